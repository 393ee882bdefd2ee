// hedge.render() and Mesh._repr_png_(): the shaded picture of the hedge tool (tools/picture/,
// shaded_picture), so the same options give the same pixels as `hedge render`. The GIL is
// released while the picture is drawn.
#include <pybind11/stl.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <optional>
#include <string>

#include "binding/edits.h"
#include "binding/errors.h"
#include "binding/names.h"
#include "hedge/error.h"
#include "picture/shaded.h"
#include "py_args.h"
#include "py_support.h"

namespace hedge::python {

using picture::Image;
using picture::ShadedOptions;

namespace {

//! The camera and picture options of hedge.render(), as the CLI's `hedge render` takes them.
struct RenderArgs {
  int width = 800, height = 600;
  std::string view = "iso";
  py::object eye, target, up;
  double fov = 30;
  std::string shading = "smooth", color_by = "none";
  bool wireframe = false;
  double feature_angle = 60;
  int supersample = 2;
  std::int64_t threads = 0;
};

[[noreturn]] void invalid(const std::string& message) {
  binding::fail(HEDGE_ERROR_INVALID_ARGUMENT, message);
}

//! The value of a picture's name parser, its error prefixed with the call ("render: view 'x' ...").
template <typename Parse>
auto prefixed(Parse&& parse) {
  try {
    return parse();
  } catch (const InvalidInputError& e) {
    invalid(std::string("render: ") + e.what());
  }
}

//! The options checked as the CLI checks its command line; names and sizes are checked again by
//! the picture's own functions. Needs the GIL (eye, target and up are Python objects).
ShadedOptions shaded_options(const RenderArgs& a) {
  ShadedOptions s;
  s.width = a.width;
  s.height = a.height;
  s.view = prefixed([&] { return picture::view_named(a.view); });
  s.shading = prefixed([&] { return picture::shading_named(a.shading); });
  s.color_by = prefixed([&] { return picture::color_by_named(a.color_by); });
  s.wireframe = a.wireframe;
  if (!(a.feature_angle >= 0 && a.feature_angle <= 180))
    invalid("render: feature_angle must be in [0, 180] degrees, got " + std::to_string(a.feature_angle));
  s.feature_angle = a.feature_angle;
  if (a.supersample < 1 || a.supersample > 4)
    invalid("render: supersample must be from 1 to 4, got " + std::to_string(a.supersample));
  s.supersample = a.supersample;
  s.threads = binding::thread_count(a.threads, "render: threads");
  // Checked whatever the view, so that a bad fov is never taken quietly.
  if (!(a.fov >= 0 && a.fov <= 179))
    invalid("render: fov must be in [0, 179] degrees (0: orthographic), got " + std::to_string(a.fov));
  if (a.eye.is_none() != a.target.is_none()) invalid("render: eye and target go together");
  if (!a.eye.is_none()) {
    picture::Camera c;
    c.eye = point3d(a.eye, "render", "eye");
    c.target = point3d(a.target, "render", "target");
    if (!a.up.is_none()) c.up = point3d(a.up, "render", "up");
    c.fov_degrees = a.fov;
    s.camera = c;
  } else if (!a.up.is_none()) {
    invalid("render: up is for the camera of eye and target");
  }
  picture::check_size(a.width, a.height, "render: the picture");
  return s;
}

//! The picture of the mesh, drawn with the GIL released.
Image picture_of(const Mesh& mesh, const ShadedOptions& options) {
  const auto use = mesh.use();
  py::gil_scoped_release unlocked;
  return picture::shaded_picture(use->mesh, options);
}

bool png_path(const std::string& path) {
  if (path.size() < 4) return false;
  std::string tail = path.substr(path.size() - 4);
  std::transform(tail.begin(), tail.end(), tail.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  return tail == ".png";
}

py::object render(const Mesh& mesh, const RenderArgs& args, const py::object& path_like) {
  const ShadedOptions options = shaded_options(args);
  const std::optional<std::string> path =
      path_like.is_none() ? std::nullopt : std::optional<std::string>(fspath(path_like));
  if (path && !png_path(*path)) invalid("render: the path must end in .png, got '" + *path + "'");
  const Image image = picture_of(mesh, options);
  if (path) {
    {
      py::gil_scoped_release unlocked;
      picture::write_png(image, *path);  // atomic: a failure leaves no half-written file
    }
    return py::none();
  }
  py::array_t<std::uint8_t> out({py::ssize_t(image.height()), py::ssize_t(image.width()), py::ssize_t(3)});
  std::memcpy(out.mutable_data(), image.pixels().data(), image.pixels().size());
  return out;
}

}  // namespace

void bind_render(py::module_& m, py::class_<Mesh>& mesh) {
  m.def(
      "render",
      [](const Mesh& mesh, int width, int height, const std::string& view, const py::object& eye,
         const py::object& target, const py::object& up, double fov, const std::string& shading,
         const std::string& color_by, bool wireframe, double feature_angle, int supersample,
         std::int64_t threads, const py::object& path) {
        const RenderArgs a{width,   height,   view,      eye,           target,      up,     fov,
                           shading, color_by, wireframe, feature_angle, supersample, threads};
        return render(mesh, a, path);
      },
      py::arg("mesh"), py::arg("width") = 800, py::arg("height") = 600, py::kw_only(),
      py::arg("view") = "iso", py::arg("eye") = py::none(), py::arg("target") = py::none(),
      py::arg("up") = py::none(), py::arg("fov") = 30.0, py::arg("shading") = "smooth",
      py::arg("color_by") = "none", py::arg("wireframe") = false, py::arg("feature_angle") = 60.0,
      py::arg("supersample") = 2, py::arg("threads") = 0, py::arg("path") = py::none(),
      "The shaded picture of the mesh's faces, as `hedge render` draws it with the same options: an "
      "(height, width, 3) uint8 RGB array, or, with path (ending in .png), the picture written there "
      "as a PNG (replaced atomically; IoError if it cannot be written) and None returned.\n\n"
      "view: 'iso', 'front', 'back', 'left', 'right', 'top' or 'bottom', framing the whole mesh; or "
      "an explicit camera: eye and target (3 numbers each), up (default (0, 1, 0)) and fov (vertical, "
      "degrees; 0: orthographic). shading: 'smooth' or 'flat'. color_by: 'none', 'face', 'shard' "
      "(connected piece), 'curvature' or 'valence'. wireframe: draw every edge. feature_angle: "
      "highlight edges whose faces meet at more than this many degrees (0: none); boundary edges "
      "are red. supersample: 1..4 samples per pixel along each axis. threads: 0 for every core. "
      "InvalidArgumentError for a bad option, a mesh with no faces or a position that is not "
      "finite. Releases the GIL while drawing.");
  mesh.def(
      "_repr_png_",
      [](const Mesh& self) -> py::object {
        {
          const auto use = self.use();
          if (use->mesh.n_faces() == 0) return py::none();  // nothing to show: the text repr instead
        }
        ShadedOptions options;
        options.width = 400;
        options.height = 300;
        const Image image = picture_of(self, options);
        std::string png;
        {
          py::gil_scoped_release unlocked;
          png = picture::encode_png(image);
        }
        return py::bytes(png);
      },
      "The mesh's picture as PNG bytes (400x300, the iso view of hedge.render), so that a notebook "
      "shows the mesh; None for a mesh without faces.");
}

}  // namespace hedge::python
