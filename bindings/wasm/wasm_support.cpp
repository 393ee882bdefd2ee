#include "wasm_support.h"

#include <string_view>

#include "hedge/error.h"

namespace hedge::wasm {

ErrorSlot g_error;

namespace {
std::string g_error_message;
std::string g_refusal;
}  // namespace

void record_failure() noexcept {
  const binding::Failure f = binding::current_failure();
  g_error.pending = 1;
  g_error.status = f.status;
  try {
    g_error_message = f.status == HEDGE_ERROR_OUT_OF_MEMORY && std::string_view(f.message) == "out of memory"
                          ? "out of memory (the wasm heap could not grow)"
                          : f.message;
    g_refusal = f.refusal;
  } catch (...) {
    g_error.status = HEDGE_ERROR_OUT_OF_MEMORY;
    g_error_message.clear();
  }
}

std::string take_error_message() {
  std::string message = std::move(g_error_message);
  g_error_message.clear();
  g_error = ErrorSlot{};
  return message;
}

std::string take_refusal() {
  std::string refusal = std::move(g_refusal);
  g_refusal.clear();
  return refusal;
}

double js_index(Index i) { return i == kInvalidIndex ? -1.0 : double(i); }

namespace {
template <typename V>
val js_array3(const V& p) {
  val out = val::array();
  out.set(0, p.x);
  out.set(1, p.y);
  out.set(2, p.z);
  return out;
}
}  // namespace

val js_vec3(const Vec3& p) { return js_array3(p); }
val js_vec3d(const Vec3d& p) { return js_array3(p); }

namespace {
Vec3 vec3_from_js(const val& p, const std::string& what) {
  if (!p.isArray() || p["length"].as<unsigned>() != 3)
    throw InvalidInputError(what + ": expected an array [x, y, z]");
  return Vec3{float(p[0].as<double>()), float(p[1].as<double>()), float(p[2].as<double>())};
}
}  // namespace

Vec3 point_from_js(const val& p, const std::string& what) {
  const Vec3 out = vec3_from_js(p, what);
  if (!is_finite(out)) throw InvalidInputError(what + ": the point is not finite");
  return out;
}

std::optional<Vec3> optional_vec3_from_js(const val& p, const std::string& what) {
  if (p.isUndefined() || p.isNull()) return std::nullopt;
  return vec3_from_js(p, what);
}

std::uint32_t js_length(const val& array, const char* what) {
  if (array.isUndefined() || array.isNull()) return 0;
  const val length = array["length"];
  if (!length.isNumber()) throw InvalidInputError(std::string(what) + ": expected a typed array");
  return length.as<std::uint32_t>();
}

val js_doubles(const double* data, std::size_t n) {
  return val::global("Float64Array").new_(val(emscripten::typed_memory_view(n, data)));
}
val js_floats(const float* data, std::size_t n) {
  return val::global("Float32Array").new_(val(emscripten::typed_memory_view(n, data)));
}
val js_uints(const std::uint32_t* data, std::size_t n) {
  return val::global("Uint32Array").new_(val(emscripten::typed_memory_view(n, data)));
}

}  // namespace hedge::wasm
