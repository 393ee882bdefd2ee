#include "diagram.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "colors.h"
#include "hedge/error.h"

namespace hedge::picture {

namespace {
// "h12" and the like (built by appending: `"h" + std::to_string(i)` trips a false -Wrestrict
// warning of g++ 12).
std::string label(char prefix, std::size_t index) {
  std::string s(1, prefix);
  s += std::to_string(index);
  return s;
}
}  // namespace

Camera diagram_camera(const SurfaceMesh& mesh, double aspect) {
  Vec3d lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
  for (Vertex v : mesh.vertices())
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], double(mesh.position(v)[a]));
      hi[a] = std::max(hi[a], double(mesh.position(v)[a]));
    }
  const Vec3d ext = hi - lo;
  const double big = std::max({ext.x, ext.y, ext.z});
  View view = View::iso;
  if (big > 0) {
    if (ext.z <= 1e-3 * big)
      view = View::front;
    else if (ext.y <= 1e-3 * big)
      view = View::top;
    else if (ext.x <= 1e-3 * big)
      view = View::right;
  }
  Camera c = frame(mesh, view, aspect);
  if (view != View::iso) {  // flat: an orthographic picture, as drawn on paper
    c.fov_degrees = 0;
    c.ortho_height *= 1.25;
  } else {  // room for the labels at the rim
    c.eye = c.target + (c.eye - c.target) * 1.15;
  }
  return c;
}

void draw_halfedge_diagram(const SurfaceMesh& m, const Camera& camera, Canvas& canvas,
                           const DiagramOptions& o) {
  if (m.n_faces() == 0) throw InvalidInputError("nothing to draw: the mesh has no faces");
  if (m.n_faces() > o.max_faces)
    throw InvalidInputError("the half-edge diagram is for small meshes: this one has " +
                            std::to_string(m.n_faces()) + " faces, the limit is " +
                            std::to_string(o.max_faces));
  const int legend_height = o.legend ? 28 : 0;
  const int w = canvas.width(), h = canvas.height() - legend_height;
  if (h < 16)
    throw InvalidInputError("the diagram needs a picture at least " + std::to_string(16 + legend_height) +
                            " pixels high");
  const Projection proj(camera, w, h);

  std::vector<Point2> at(m.vertex_slots());
  std::vector<double> depth(m.vertex_slots(), 0);
  for (Vertex v : m.vertices()) {
    const Vec3 p = m.position(v);
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      throw InvalidInputError("vertex " + std::to_string(v.idx()) + " has a position that is not finite");
    const Projection::Point q = proj(to_double(p));
    at[v.idx()] = {q.x, q.y};
    depth[v.idx()] = q.depth;
  }

  // Faces back to front, translucent, so that the far side of a solid shows through faintly.
  struct Item {
    Face f;
    double depth;
    Point2 centre;
    bool facing;  // toward the camera
  };
  std::vector<Item> faces;
  for (Face f : m.faces()) {
    double d = 0, cx = 0, cy = 0, area2 = 0;
    std::size_t n = 0;
    for (Halfedge g : m.halfedges(f)) {
      const Point2 a = at[m.from_vertex(g).idx()], b = at[m.to_vertex(g).idx()];
      area2 += a.x * b.y - a.y * b.x;
      d += depth[m.to_vertex(g).idx()];
      cx += b.x, cy += b.y;
      ++n;
    }
    // A face wound counter-clockwise as seen from the camera has area2 < 0 on screen (y points down).
    faces.push_back({f, d / double(n), {cx / double(n), cy / double(n)}, area2 < 0});
  }
  std::sort(faces.begin(), faces.end(),
            [](const Item& a, const Item& b) { return a.depth != b.depth ? a.depth > b.depth : a.f < b.f; });

  // Sizes from the typical edge length on screen.
  std::vector<double> lengths;
  for (Edge e : m.edges()) {
    const Point2 a = at[m.vertex(e, 0).idx()], b = at[m.vertex(e, 1).idx()];
    lengths.push_back(std::hypot(b.x - a.x, b.y - a.y));
  }
  std::nth_element(lengths.begin(), lengths.begin() + std::ptrdiff_t(lengths.size() / 2), lengths.end());
  const double typical = std::max(8.0, lengths[lengths.size() / 2]);
  const double font = std::clamp(typical * 0.11, 7.0, 15.0);
  const double stroke = std::clamp(typical * 0.012, 0.8, 2.0);
  const double head = std::clamp(typical * 0.07, 4.0, 12.0);

  const Rgb edge_color{150, 150, 150}, arrow_color{30, 60, 120}, boundary_color{205, 35, 35},
      vertex_color{20, 20, 20};
  const Rgb face_text{90, 90, 90};
  auto label_near = [&](Point2 a, Point2 b, Point2 toward, double k) {
    const Point2 mid{(a.x + b.x) / 2, (a.y + b.y) / 2};
    return Point2{mid.x + (toward.x - mid.x) * k, mid.y + (toward.y - mid.y) * k};
  };
  // An arrow for half-edge g, pulled toward `inside` (its face's centre) or pushed away from it.
  auto halfedge_arrow = [&](Halfedge g, Point2 inside, double pull, Rgb color, const char* kind) {
    Point2 a = at[m.from_vertex(g).idx()], b = at[m.to_vertex(g).idx()];
    a = {a.x + (inside.x - a.x) * pull, a.y + (inside.y - a.y) * pull};
    b = {b.x + (inside.x - b.x) * pull, b.y + (inside.y - b.y) * pull};
    const Point2 a2{a.x + (b.x - a.x) * 0.14, a.y + (b.y - a.y) * 0.14};
    const Point2 b2{b.x - (b.x - a.x) * 0.14, b.y - (b.y - a.y) * 0.14};
    canvas.arrow(a2, b2, stroke, head, color, kind);
    if (o.labels) {
      const Point2 l = label_near(a2, b2, inside, pull > 0 ? 0.22 : -0.22);
      canvas.text(l, font * 0.8, label('h', g.idx()), color);
    }
  };

  for (const Item& it : faces) {
    std::vector<Point2> poly;
    for (Vertex v : m.vertices(it.f)) poly.push_back(at[v.idx()]);
    canvas.polygon(poly, mix(categorical(it.f.idx()), Rgb{255, 255, 255}, 0.5), it.facing ? 0.8 : 0.3);
    const Rgb arrows = it.facing ? arrow_color : mix(arrow_color, Rgb{255, 255, 255}, 0.55);
    for (Halfedge g : m.halfedges(it.f))
      canvas.line(at[m.from_vertex(g).idx()], at[m.to_vertex(g).idx()], stroke, edge_color);
    for (Halfedge g : m.halfedges(it.f)) halfedge_arrow(g, it.centre, 0.2, arrows, "halfedge");
    if (o.labels)
      canvas.text(it.centre, font, label('f', it.f.idx()),
                  it.facing ? face_text : mix(face_text, Rgb{255, 255, 255}, 0.5));
  }
  // Boundary half-edges: outside, pushed away from the face on the other side.
  for (Halfedge g : m.halfedges()) {
    if (!m.is_boundary(g)) continue;
    const Face f = m.face(SurfaceMesh::twin(g));
    Point2 c{0, 0};
    std::size_t n = 0;
    for (Vertex v : m.vertices(f)) c.x += at[v.idx()].x, c.y += at[v.idx()].y, ++n;
    c = {c.x / double(n), c.y / double(n)};
    halfedge_arrow(g, c, -0.1, boundary_color, "halfedge boundary");
  }
  // Vertices, on top.
  for (Vertex v : m.vertices()) {
    canvas.disc(at[v.idx()], std::max(2.0, stroke * 2.2), vertex_color);
    if (o.labels)
      canvas.text({at[v.idx()].x + font * 0.5, at[v.idx()].y - font * 0.75}, font, label('v', v.idx()),
                  vertex_color, Anchor::start);
  }
  if (o.legend) {
    const double y = canvas.height() - legend_height / 2.0;
    canvas.text(
        {10, y}, 12,
        "arrows: half-edges, inside their face (twins run side by side, opposite ways); red: boundary "
        "half-edges",
        Rgb{60, 60, 60}, Anchor::start);
  }
}

}  // namespace hedge::picture
