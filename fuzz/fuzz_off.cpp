// libFuzzer target for the OFF reader.
#include "fuzz_common.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return hedge::fuzz::run(data, size, hedge::FileFormat::off);
}
