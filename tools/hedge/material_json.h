// Fracture material files (schema: docs/fracture.md): JSON text to hedge::FractureMaterial.
// Kept apart from the fracture command so that the parser can be tested and fuzzed on its own
// (fuzz/fuzz_material.cpp).
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

#include "hedge/algorithms/fracture.h"

namespace hedge::cli {

//! The largest material text read: 1,000 rings (the most a material may have) take about 80 KB.
inline constexpr std::size_t kMaterialMaxBytes = 1 << 20;

//! Parses the text of a material file. `path` names the file in messages; its stem is the
//! material's name when the file gives none.
//! \throw IoError (path, byte offset) when the text is not JSON, is larger than kMaterialMaxBytes
//!        or nests deeper than 8 levels; InvalidInputError naming the file
//!        and the field for a field that is unknown, missing, of the wrong type or out of range.
FractureMaterial parse_material_json(std::string_view text, const std::string& path);

}  // namespace hedge::cli
