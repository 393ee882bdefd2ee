#include "camera.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "hedge/error.h"

namespace hedge::picture {

std::optional<View> parse_view(const std::string& name) {
  static const std::pair<const char*, View> kNames[] = {
      {"front", View::front}, {"back", View::back},     {"left", View::left}, {"right", View::right},
      {"top", View::top},     {"bottom", View::bottom}, {"iso", View::iso}};
  for (const auto& [n, v] : kNames)
    if (name == n) return v;
  return std::nullopt;
}

const char* view_names() { return "front|back|left|right|top|bottom|iso"; }

namespace {
double length(const Vec3d& v) { return std::sqrt(dot(v, v)); }
}  // namespace

Camera frame(const SurfaceMesh& mesh, View view, double aspect) {
  Vec3d lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
  std::size_t n = 0;
  for (Vertex v : mesh.vertices()) {
    const Vec3d p = to_double(mesh.position(v));
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      throw InvalidInputError("vertex " + std::to_string(v.idx()) + " has a position that is not finite");
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], p[a]);
      hi[a] = std::max(hi[a], p[a]);
    }
    ++n;
  }
  if (n == 0) throw InvalidInputError("nothing to frame: the mesh has no vertices");
  const Vec3d centre = (lo + hi) * 0.5;
  double radius = 0.5 * length(hi - lo);
  if (!(radius > 0)) radius = 1;
  Vec3d dir{0, 0, 1}, up{0, 1, 0};
  switch (view) {
    case View::front:
      dir = {0, 0, 1};
      break;
    case View::back:
      dir = {0, 0, -1};
      break;
    case View::left:
      dir = {-1, 0, 0};
      break;
    case View::right:
      dir = {1, 0, 0};
      break;
    case View::top:
      dir = {0, 1, 0}, up = {0, 0, -1};
      break;
    case View::bottom:
      dir = {0, -1, 0}, up = {0, 0, 1};
      break;
    case View::iso:
      dir = normalize(Vec3d{1, 0.8, 1.2});
      break;
  }
  // Fit the picture to the mesh's extent across the view (a 6% margin), measured in the camera's
  // own axes, so that long or flat meshes fill it too.
  const Vec3d forward = dir * -1.0;
  const Vec3d right = normalize(cross(forward, up));
  const Vec3d upv = cross(right, forward);
  double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300, z1 = -1e300;
  for (Vertex v : mesh.vertices()) {
    const Vec3d d = to_double(mesh.position(v)) - centre;
    x0 = std::min(x0, dot(d, right)), x1 = std::max(x1, dot(d, right));
    y0 = std::min(y0, dot(d, upv)), y1 = std::max(y1, dot(d, upv));
    z1 = std::max(z1, dot(d, dir));
  }
  const double floor = 1e-3 * radius;  // a mesh seen edge-on still gets a picture
  const double hx = std::max(0.5 * (x1 - x0), floor) * 1.06, hy = std::max(0.5 * (y1 - y0), floor) * 1.06;
  Camera c;
  c.fov_degrees = 30;
  c.up = upv;
  c.target = centre + right * (0.5 * (x0 + x1)) + upv * (0.5 * (y0 + y1));
  const double t = std::tan(c.fov_degrees * std::numbers::pi / 360);
  const double distance = z1 + std::max(hx / (t * aspect), hy / t);
  c.eye = c.target + dir * distance;
  c.ortho_height = 2 * std::max(hy, hx / aspect);
  return c;
}

Projection::Projection(const Camera& camera, int width, int height) {
  eye_ = camera.eye;
  const Vec3d f = camera.target - camera.eye;
  const double fl = length(f);
  if (!(fl > 0) || !std::isfinite(fl)) throw InvalidInputError("camera: the eye and the target must differ");
  forward_ = f * (1 / fl);
  const Vec3d r = cross(forward_, camera.up);
  const double rl = length(r);
  if (!(rl > 1e-9 * length(camera.up)) || !std::isfinite(rl))
    throw InvalidInputError("camera: the up direction must not be parallel to the view direction");
  right_ = r * (1 / rl);
  up_ = cross(right_, forward_);
  if (!(camera.fov_degrees >= 0 && camera.fov_degrees <= 179))
    throw InvalidInputError("camera: the field of view must be in [0, 179] degrees");
  ortho_ = camera.fov_degrees == 0;
  if (ortho_) {
    if (!(camera.ortho_height > 0) || !std::isfinite(camera.ortho_height))
      throw InvalidInputError("camera: the orthographic height must be positive");
    scale_ = height / camera.ortho_height;
  } else {
    scale_ = 0.5 * height / std::tan(camera.fov_degrees * std::numbers::pi / 360);
  }
  cx_ = 0.5 * width;
  cy_ = 0.5 * height;
}

Projection::Point Projection::operator()(const Vec3d& p) const {
  const Vec3d d = p - eye_;
  const double z = dot(d, forward_);
  const double s = ortho_ ? scale_ : scale_ / z;
  return {cx_ + dot(d, right_) * s, cy_ - dot(d, up_) * s, z};
}

Vec3d Projection::toward_eye(const Vec3d& p) const {
  if (ortho_) return forward_ * -1.0;
  return normalize(eye_ - p);
}

}  // namespace hedge::picture
