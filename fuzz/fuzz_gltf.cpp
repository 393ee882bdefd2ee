// libFuzzer target for the glTF reader (.gltf JSON and .glb binary alike: the reader tells them apart
// by their first bytes).
#include "fuzz_common.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace hedge;
  IndexedMesh mesh;
  try {
    mesh = read_gltf(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz");
  } catch (const Error&) {
    return 0;  // rejecting bad input with hedge's exception is the expected outcome
  }
  fuzz::check_invariants(mesh);
  // What the reader accepted, both writers must reproduce. A mesh without faces is written as a file
  // without meshes (glTF has no place for vertices alone), so only meshes with faces are compared.
  if (mesh.indices.empty()) return 0;
  for (const FileFormat format : {FileFormat::gltf, FileFormat::glb}) {
    const IndexedMesh back = read_gltf(write_indexed(mesh, format), "fuzz round trip");
    fuzz::require(fuzz::same_geometry(mesh, back));
  }
  return 0;
}
