#include "shaded.h"

#include <utility>

#include "hedge/error.h"

namespace hedge::picture {

namespace {

//! The value named `name` in `table`; \throw InvalidInputError "<what> 'name' is not one of a, b".
template <typename T, std::size_t N>
T named(const std::pair<const char*, T> (&table)[N], std::string_view name, const char* what) {
  std::string valid;
  for (const auto& [n, v] : table) {
    if (name == n) return v;
    valid += (valid.empty() ? "" : ", ") + std::string(n);
  }
  throw InvalidInputError(std::string(what) + " '" + std::string(name) + "' is not one of " + valid);
}

}  // namespace

Shading shading_named(std::string_view name) {
  static const std::pair<const char*, Shading> kNames[] = {{"flat", Shading::flat},
                                                           {"smooth", Shading::smooth}};
  return named(kNames, name, "shading");
}

ColorBy color_by_named(std::string_view name) {
  static const std::pair<const char*, ColorBy> kNames[] = {{"none", ColorBy::none},
                                                           {"face", ColorBy::face},
                                                           {"shard", ColorBy::shard},
                                                           {"curvature", ColorBy::curvature},
                                                           {"valence", ColorBy::valence}};
  return named(kNames, name, "color_by");
}

View view_named(std::string_view name) {
  if (const std::optional<View> v = parse_view(std::string(name))) return *v;
  throw InvalidInputError("view '" + std::string(name) + "' is not one of " + view_names());
}

double shaded_picture_bytes(int width, int height, int supersample) {
  return double(width) * height * supersample * supersample * (sizeof(float) + 3) + 3.0 * width * height;
}

Image shaded_picture(const SurfaceMesh& mesh, const ShadedOptions& options) {
  RenderOptions r;
  r.width = options.width;
  r.height = options.height;
  r.supersample = options.supersample;
  r.shading = options.shading;
  r.color_by = options.color_by;
  r.wireframe = options.wireframe;
  r.feature_angle = options.feature_angle;
  r.marked = options.marked;
  r.threads = options.threads;
  // The size first, so that the aspect ratio of the framing view divides by a valid height.
  check_size(options.width, options.height, "a picture");
  const Camera camera =
      options.camera ? *options.camera : frame(mesh, options.view, double(options.width) / options.height);
  return render(mesh, camera, r);
}

}  // namespace hedge::picture
