// Cameras for pictures: named views that frame a mesh, explicit cameras, and the projection from
// world space to the pixels of a picture.
#pragma once

#include <optional>
#include <string>

#include "hedge/core/surface_mesh.h"
#include "hedge/core/vec.h"

namespace hedge::picture {

//! Named views, for y-up meshes: `front` looks from +z toward -z, `top` from +y down (with -z up
//! in the picture), `iso` from the (+x, +y, +z) octant.
enum class View { front, back, left, right, top, bottom, iso };

//! The view named `name` ("front", "back", "left", "right", "top", "bottom", "iso"), if any.
std::optional<View> parse_view(const std::string& name);
const char* view_names();  //!< "front|back|left|right|top|bottom|iso", for help texts

struct Camera {
  Vec3d eye{0, 0, 1};
  Vec3d target{0, 0, 0};
  Vec3d up{0, 1, 0};
  //! Vertical field of view in degrees; 0 for an orthographic camera.
  double fov_degrees = 30;
  //! Orthographic cameras: the height of world space the picture shows.
  double ortho_height = 2;
};

//! A camera looking at the live vertices of `mesh` from `view`, with the whole mesh in the picture
//! (a margin of about 5%) for pictures of the given aspect ratio (width / height).
//! \throw InvalidInputError if the mesh has no live vertex or a position is not finite.
Camera frame(const SurfaceMesh& mesh, View view, double aspect);

//! World space to picture space: x to the right and y down, in pixels; depth is the distance in
//! front of the eye along the view direction (positive in front).
class Projection {
 public:
  //! \throw InvalidInputError if eye and target coincide, up is parallel to the view direction,
  //!   or the field of view is not in [0, 179] degrees.
  Projection(const Camera& camera, int width, int height);
  struct Point {
    double x, y, depth;
  };
  Point operator()(const Vec3d& p) const;
  //! The direction from p toward the eye (the view direction for an orthographic camera).
  Vec3d toward_eye(const Vec3d& p) const;
  bool orthographic() const { return ortho_; }

 private:
  Vec3d eye_, right_, up_, forward_;
  double scale_ = 1;  // pixels per unit of tan(angle) (perspective) or per world unit (orthographic)
  double cx_ = 0, cy_ = 0;
  bool ortho_ = false;
};

}  // namespace hedge::picture
