// libFuzzer target for the C ABI's file entry, hedge_mesh_read(), used as a C or C# program uses it:
// the input is written to a file, read and built through the C ABI, and a mesh it returns must be
// valid. The first byte chooses the file's extension and the build options, the rest is the file:
//   extension      byte % 6:       obj off ply stl gltf glb (fuzz/run prefixes its seeds so)
//   build options  byte / 6 % 4:   NULL (the format's defaults), strict, repair with exact welding,
//                                  repair with welding closer than 1e-6 of the diagonal
// The files go to a folder of this process under $TMPDIR (or /tmp), removed at exit.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "hedge/c_api.h"

namespace {

constexpr const char* kExtensions[] = {"obj", "off", "ply", "stl", "gltf", "glb"};
constexpr std::size_t kExtensionCount = sizeof kExtensions / sizeof kExtensions[0];

[[noreturn]] void fail(const char* what, hedge_status status) {
  std::fprintf(stderr, "fuzz_capi: %s (status %s, message '%s')\n", what, hedge_status_string(status),
               hedge_last_error());
  std::abort();
}

void remove_folder();

const std::string& folder() {
  static const std::string dir = [] {
    const char* tmp = std::getenv("TMPDIR");
    std::string pattern = std::string(tmp != nullptr && *tmp != 0 ? tmp : "/tmp") + "/hedge-fuzz-capi-XXXXXX";
    if (::mkdtemp(pattern.data()) == nullptr) {
      std::perror("fuzz_capi: mkdtemp");
      std::abort();
    }
    return pattern;
  }();
  static const bool registered = (std::atexit(remove_folder), true);
  (void)registered;
  return dir;
}

void remove_folder() {
  std::error_code ec;
  std::filesystem::remove_all(folder(), ec);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const unsigned selector = data[0];
  const std::string path = folder() + "/input." + kExtensions[selector % kExtensionCount];
  std::FILE* file = std::fopen(path.c_str(), "wb");
  if (file == nullptr || std::fwrite(data + 1, 1, size - 1, file) != size - 1 || std::fclose(file) != 0) {
    std::perror("fuzz_capi: writing the input file");
    std::abort();
  }

  hedge_build_options options;
  hedge_build_options_default(&options);
  const unsigned mode = selector / kExtensionCount % 4;
  options.policy = mode == 1 ? HEDGE_POLICY_STRICT : HEDGE_POLICY_REPAIR;
  options.weld = mode == 2 ? HEDGE_WELD_EXACT : mode == 3 ? HEDGE_WELD_EPSILON : HEDGE_WELD_NONE;
  hedge_build_report report;
  hedge_mesh* mesh = nullptr;
  const hedge_status status =
      hedge_mesh_read(path.c_str(), mode == 0 ? nullptr : &options, mode == 0 ? nullptr : &report, &mesh);
  // Each input goes to a new file: rewriting a file in place (truncation) makes some file systems
  // flush it to disk on close, which slows the target down a hundredfold.
  std::remove(path.c_str());

  if (status != HEDGE_OK) {
    // The statuses hedge_mesh_read() documents: a malformed file, topology refused under the strict
    // policy, memory running out. Anything else (an internal error, an invalid argument) is a finding.
    const bool documented = status == HEDGE_ERROR_IO || status == HEDGE_ERROR_OUT_OF_MEMORY ||
                            (status == HEDGE_ERROR_TOPOLOGY && mode == 1);
    if (!documented) fail("hedge_mesh_read returned an undocumented status", status);
    if (mesh != nullptr) fail("hedge_mesh_read failed but wrote its out parameter", status);
    if (*hedge_last_error() == 0) fail("hedge_mesh_read failed without a message", status);
    return 0;
  }
  if (mesh == nullptr) fail("hedge_mesh_read succeeded without a mesh", status);
  std::uint32_t problems = 0;
  const hedge_status valid = hedge_mesh_validate(mesh, &problems);
  if (valid != HEDGE_OK) fail("hedge_mesh_validate failed", valid);
  if (problems != 0) {
    char text[4096];
    std::uint32_t needed = 0;
    hedge_mesh_validation_report(mesh, text, sizeof text, &needed);
    std::fprintf(stderr, "fuzz_capi: the mesh read has %u problems:\n%s\n", problems,
                 needed <= sizeof text ? text : "(report too long)");
    std::abort();
  }
  const hedge_status destroyed = hedge_mesh_destroy(mesh);
  if (destroyed != HEDGE_OK) fail("hedge_mesh_destroy failed", destroyed);
  return 0;
}
