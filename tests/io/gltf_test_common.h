// What the glTF test files (gltf_read_test.cpp, gltf_write_test.cpp, gltf_guard_test.cpp) share:
// the readers and writers, JSON to build and inspect files with, and the filesystem.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>

#include "hedge/error.h"
#include "hedge/io/io.h"

namespace hedge::gltf_test {

namespace fs = std::filesystem;
using json = nlohmann::json;

}  // namespace hedge::gltf_test
