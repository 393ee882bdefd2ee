// libFuzzer target for the CLI's fracture material files (tools/hedge/material_json.cpp). Bad text
// must be refused with the exceptions the parser documents (hedge::IoError for text that is not
// JSON, hedge::InvalidInputError for a bad field); any other exception escapes and is reported.
// A material the parser accepts must be one the library takes: fracture() checks its options,
// material included, before anything else, so on a mesh without faces a valid material gets the
// error about the mesh and an invalid one the error naming its field.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#include "hedge/algorithms/fracture.h"
#include "hedge/error.h"
#include "material_json.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace hedge;
  FractureOptions options;
  try {
    options.material =
        cli::parse_material_json(std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.json");
  } catch (const IoError&) {
    return 0;
  } catch (const InvalidInputError&) {
    return 0;
  }
  SurfaceMesh empty;
  try {
    fracture(empty, Vec3{0, 0, 0}, options);
  } catch (const InvalidInputError& e) {
    if (std::string_view(e.what()) == "fracture: the mesh has no face") return 0;
    std::fprintf(stderr, "fuzz_material: the parser accepted a material the library refuses: %s\n", e.what());
    std::abort();
  }
  std::fprintf(stderr, "fuzz_material: fracture() accepted a mesh without faces\n");
  std::abort();
}
