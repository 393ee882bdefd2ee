#include "material_json.h"

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <limits>
#include <nlohmann/json.hpp>

#include "hedge/error.h"

namespace hedge::cli {

namespace {

using nlohmann::json;

[[noreturn]] void bad_field(const std::string& path, const std::string& field, const std::string& what) {
  throw InvalidInputError(path + ": material field '" + field + "' " + what);
}

// A material is an object of rings, each an object: three levels. Deeper text is refused while it
// is read, before the parser has built the levels below (a file of 10^6 nested arrays took 40
// times its size before).
constexpr int kMaxMaterialDepth = 8;

double number_field(const json& j, const std::string& path, const std::string& field) {
  if (!j.is_number()) bad_field(path, field, "must be a number");
  return j.get<double>();
}

}  // namespace

FractureMaterial parse_material_json(std::string_view text, const std::string& path) {
  if (text.size() > kMaterialMaxBytes)
    throw IoError(path, 0, -1,
                  "a material is at most " + std::to_string(kMaterialMaxBytes) +
                      " bytes of JSON; this one has " + std::to_string(text.size()));
  const auto depth_limit = [&path](int depth, json::parse_event_t event, json&) {
    if ((event == json::parse_event_t::object_start || event == json::parse_event_t::array_start) &&
        depth >= kMaxMaterialDepth)
      throw IoError(
          path, 0, -1,
          "not a material: JSON nested deeper than " + std::to_string(kMaxMaterialDepth) + " levels");
    return true;
  };
  json j;
  try {
    j = json::parse(text, depth_limit);
  } catch (const json::parse_error& e) {
    throw IoError(path, 0, static_cast<std::int64_t>(e.byte), std::string("not valid JSON: ") + e.what());
  } catch (const json::exception& e) {  // a number beyond a double's range ("1e400"): out_of_range
    throw IoError(path, 0, -1, std::string("not valid JSON: ") + e.what());
  }
  if (!j.is_object()) throw InvalidInputError(path + ": a material is a JSON object");
  static const char* const known[] = {"name",        "rings", "grain", "grain_stretch",
                                      "refine_edge", "units", "radius"};
  for (const auto& item : j.items()) {
    bool ok = false;
    for (const char* k : known) ok |= item.key() == k;
    if (item.key() == "absolute")
      bad_field(path, "absolute",
                "was replaced by units and radius (absolute true: \"units\": \"model\" and the "
                "spacings summed as \"radius\"; false: \"units\": \"edge_lengths\")");
    if (!ok)
      bad_field(path, item.key(),
                "is unknown (fields: name, rings, grain, grain_stretch, refine_edge, units, radius)");
  }
  FractureMaterial m;
  m.name = std::filesystem::path(path).stem().string();
  if (j.contains("name")) {
    if (!j["name"].is_string()) bad_field(path, "name", "must be a string");
    m.name = j["name"].get<std::string>();
  }
  if (!j.contains("rings")) bad_field(path, "rings", "is missing");
  if (!j["rings"].is_array()) bad_field(path, "rings", "must be an array of rings");
  for (std::size_t i = 0; i < j["rings"].size(); ++i) {
    const json& r = j["rings"][i];
    const std::string at = "rings[" + std::to_string(i) + "]";
    if (!r.is_object()) bad_field(path, at, "must be an object {points, spacing, jitter}");
    for (const auto& item : r.items())
      if (item.key() != "points" && item.key() != "spacing" && item.key() != "jitter")
        bad_field(path, at + "." + item.key(), "is unknown (fields: points, spacing, jitter)");
    FractureRing ring;
    if (!r.contains("points") || !r["points"].is_number_unsigned())
      bad_field(path, at + ".points", "must be a whole number >= 0");
    if (r["points"].get<std::uint64_t>() > 100000) bad_field(path, at + ".points", "must be at most 100000");
    ring.points = r["points"].get<unsigned>();
    if (!r.contains("spacing")) bad_field(path, at + ".spacing", "is missing");
    ring.spacing = number_field(r["spacing"], path, at + ".spacing");
    if (!(ring.spacing > 0)) bad_field(path, at + ".spacing", "must be positive");
    if (r.contains("jitter")) ring.jitter = number_field(r["jitter"], path, at + ".jitter");
    if (!(ring.jitter >= 0 && ring.jitter <= 1)) bad_field(path, at + ".jitter", "must be in [0, 1]");
    m.rings.push_back(ring);
  }
  if (j.contains("grain")) {
    const json& g = j["grain"];
    if (!g.is_array() || g.size() != 3) bad_field(path, "grain", "must be an array of three numbers");
    for (std::size_t i = 0; i < 3; ++i) {
      const double v = number_field(g[i], path, "grain");
      // Converting a double beyond float's range to float is undefined behaviour.
      if (!(std::fabs(v) <= std::numeric_limits<float>::max()))
        bad_field(path, "grain", "must hold numbers within single precision (at most 3.4e38 in magnitude)");
      m.grain[i] = static_cast<float>(v);
    }
  }
  if (j.contains("grain_stretch")) {
    m.grain_stretch = number_field(j["grain_stretch"], path, "grain_stretch");
    if (!(m.grain_stretch >= 1)) bad_field(path, "grain_stretch", "must be at least 1");
  }
  // As fracture() requires: a grain to stretch along (its float components, which may have
  // underflowed to zero).
  if (m.grain_stretch > 1 && m.grain == Vec3{})
    bad_field(path, "grain", "must not be zero when grain_stretch is above 1");
  if (j.contains("refine_edge")) {
    m.refine_edge = number_field(j["refine_edge"], path, "refine_edge");
    if (!(m.refine_edge > 0)) bad_field(path, "refine_edge", "must be positive");
  }
  if (j.contains("units")) {
    static const FractureUnits all[] = {FractureUnits::edge_lengths, FractureUnits::model,
                                        FractureUnits::diagonal_fraction};
    bool found = false;
    for (FractureUnits u : all)
      if (j["units"].is_string() && j["units"].get<std::string>() == fracture_units_name(u)) {
        m.units = u;
        found = true;
      }
    if (!found) bad_field(path, "units", "must be \"diagonal_fraction\", \"model\" or \"edge_lengths\"");
  }
  if (j.contains("radius")) {
    m.radius = number_field(j["radius"], path, "radius");
    if (!(m.radius > 0)) bad_field(path, "radius", "must be positive");
  }
  return m;
}

}  // namespace hedge::cli
