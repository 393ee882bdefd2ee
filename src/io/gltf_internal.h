// glTF's private header: tinygltf's declarations, under a namespace of hedge's own. The
// implementation is compiled once, in gltf_tinygltf.cpp; gltf_read.cpp and gltf_write.cpp use it.
//
// The namespace keeps a program that links hedge's archive and another copy of tinygltf free of
// duplicate and interposed symbols. Images are not decoded (a mesh reader has no use for them, and a
// decoder is attack surface for untrusted files), and the only files tinygltf may open are the
// external buffers gltf_guard.h approved. Every file that includes tiny_gltf.h does so through this
// header, so that all of them see the same configuration.
#pragma once

#define tinygltf hedge_tinygltf
#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE
#define TINYGLTF_NO_FS
#include <tiny_gltf.h>
#undef tinygltf

namespace hedge {
namespace tg = ::hedge_tinygltf;
}  // namespace hedge
