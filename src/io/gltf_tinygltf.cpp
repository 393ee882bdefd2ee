// tinygltf's implementation, compiled from Debian's header once for the glTF reader and writer
// (gltf_internal.h says under which namespace and configuration).
#include <fstream>  // tinygltf's file writers use it even under TINYGLTF_NO_FS

#define TINYGLTF_IMPLEMENTATION
#include "gltf_internal.h"
