// The WebAssembly binding of hedge (embind). bindings/wasm/hedge.js wraps it into the public JS API;
// this file is its native half and is not meant to be called directly.
//
// Errors. No exception crosses into JavaScript: every bound function runs its body in guarded(),
// which catches the C++ exception, records its kind and message in the error slot and returns a
// placeholder. The JS layer reads the slot's flag straight from wasm memory after each call and
// throws a JS Error with the message. A JS exception thrown through wasm frames would skip their
// destructors and leave the stack pointer lowered, so the binding never does that.
//
// Objects. A Mesh holds its SurfaceMesh (and the FaceBvh used for picking) through a shared state,
// which each Render shares too: disposing a Mesh before its Render leaves the Render working.
#include <emscripten/bind.h>
#include <emscripten/val.h>
#include <malloc.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <new>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "hedge/algorithms/decimate.h"
#include "hedge/algorithms/fracture.h"
#include "hedge/algorithms/locate.h"
#include "hedge/algorithms/smooth.h"
#include "hedge/algorithms/subdivide.h"
#include "hedge/core/build.h"
#include "hedge/core/export.h"
#include "hedge/core/operations.h"
#include "hedge/core/surface_mesh.h"
#include "hedge/error.h"
#include "hedge/io/io.h"
#include "hedge/render/render_sync.h"

namespace {

using emscripten::val;
using namespace hedge;

// ---- Errors ------------------------------------------------------------------------------------

//! Kinds of error, as the JS layer names them (HedgeError.kind).
enum ErrorKind : std::int32_t {
  kNoError = 0,
  kInvalidArgument = 1,  // hedge::InvalidInputError, or a bad argument of the binding
  kIo = 2,               // hedge::IoError: a malformed or unreadable file
  kTopology = 3,         // hedge::TopologyError
  kRefused = 4,          // a local operation its predicate refuses; the message says why
  kOutOfMemory = 5,      // std::bad_alloc
  kInternal = 6,         // anything else: a bug
};

//! Read by the JS layer through HEAP32 at errorSlotAddress(): [pending, kind].
struct ErrorSlot {
  std::int32_t pending = 0;
  std::int32_t kind = kNoError;
};
ErrorSlot g_error;
std::string g_error_message;

//! A local operation refused by its predicate; the message says why.
class Refused : public Error {
 public:
  using Error::Error;
};

void set_error(ErrorKind kind, const char* message) {
  g_error.pending = 1;
  g_error.kind = kind;
  g_error_message = message;
}

//! Runs body(); on an exception records it in the error slot and returns a placeholder
//! (undefined for a val, a default value otherwise), which the JS layer discards.
template <typename Body>
auto guarded(Body&& body) -> decltype(body()) {
  using R = decltype(body());
  try {
    return body();
  } catch (const Refused& e) {
    set_error(kRefused, e.what());
  } catch (const IoError& e) {
    set_error(kIo, e.what());
  } catch (const TopologyError& e) {
    set_error(kTopology, e.what());
  } catch (const InvalidInputError& e) {
    set_error(kInvalidArgument, e.what());
  } catch (const Error& e) {
    set_error(kInvalidArgument, e.what());
  } catch (const std::bad_alloc&) {
    set_error(kOutOfMemory, "out of memory (the wasm heap could not grow)");
  } catch (const std::exception& e) {
    set_error(kInternal, e.what());
  } catch (...) {
    set_error(kInternal, "unknown C++ exception");
  }
  if constexpr (std::is_void_v<R>) {
    return;
  } else if constexpr (std::is_same_v<R, val>) {
    return val::undefined();
  } else {
    return R{};
  }
}

//! The message of the recorded error, clearing the slot.
std::string take_error_message() {
  std::string message = std::move(g_error_message);
  g_error_message.clear();
  g_error = ErrorSlot{};
  return message;
}

// ---- Small conversions ------------------------------------------------------------------------

//! An element index for JS: -1 for "none".
double js_index(Index i) { return i == kInvalidIndex ? -1.0 : double(i); }

template <typename Handle>
val js_index_array(const std::vector<Handle>& handles) {
  val out = val::array();
  for (std::size_t i = 0; i < handles.size(); ++i) out.set(i, js_index(handles[i].idx()));
  return out;
}

val js_vec3(const Vec3& p) {
  val out = val::array();
  out.set(0, p.x);
  out.set(1, p.y);
  out.set(2, p.z);
  return out;
}

//! A finite point from a JS [x, y, z] array. \throw InvalidInputError naming `what` otherwise.
Vec3 point_from_js(const val& p, const std::string& what) {
  if (!p.isArray() || p["length"].as<unsigned>() != 3)
    throw InvalidInputError(what + ": expected an array [x, y, z]");
  const Vec3 out{float(p[0].as<double>()), float(p[1].as<double>()), float(p[2].as<double>())};
  if (!std::isfinite(out.x) || !std::isfinite(out.y) || !std::isfinite(out.z))
    throw InvalidInputError(what + ": the point is not finite");
  return out;
}

//! Copies a JS typed array (or array) of numbers into `out` (resized to `count` elements of T).
template <typename T>
void copy_from_js(const val& source, std::vector<T>& out, std::size_t count) {
  out.resize(count);
  if (count == 0) return;
  val view{emscripten::typed_memory_view(count, out.data())};
  view.call<void>("set", source);
}

std::uint32_t js_length(const val& array, const char* what) {
  if (array.isUndefined() || array.isNull()) return 0;
  const val length = array["length"];
  if (!length.isNumber()) throw InvalidInputError(std::string(what) + ": expected a typed array");
  return length.as<std::uint32_t>();
}

val js_vec3d(const Vec3d& p) {
  val out = val::array();
  out.set(0, p.x);
  out.set(1, p.y);
  out.set(2, p.z);
  return out;
}

//! Copies of native arrays as JS typed arrays.
val js_doubles(const double* data, std::size_t n) {
  return val::global("Float64Array").new_(val(emscripten::typed_memory_view(n, data)));
}
val js_floats(const float* data, std::size_t n) {
  return val::global("Float32Array").new_(val(emscripten::typed_memory_view(n, data)));
}
val js_uints(const std::uint32_t* data, std::size_t n) {
  return val::global("Uint32Array").new_(val(emscripten::typed_memory_view(n, data)));
}

//! A fracture material from the object the JS layer made of a custom material (see
//! WasmMesh::fracture); fracture() checks the values.
FractureMaterial material_from_js(const val& m) {
  FractureMaterial out;
  out.name = m["name"].as<std::string>();
  std::vector<double> rings;
  copy_from_js(m["rings"], rings, js_length(m["rings"], "material.rings"));
  if (rings.size() % 3 != 0) throw InvalidInputError("material.rings: expected 3 numbers per ring");
  for (std::size_t i = 0; i < rings.size(); i += 3) {
    const double points = rings[i];
    if (!(points >= 0 && points <= 100000 && std::floor(points) == points))
      throw InvalidInputError("material '" + out.name + "' rings[" + std::to_string(i / 3) +
                              "].points must be a whole number in [0, 100000]");
    out.rings.push_back(FractureRing{unsigned(points), rings[i + 1], rings[i + 2]});
  }
  const val grain = m["grain"];
  out.grain = Vec3{float(grain[0].as<double>()), float(grain[1].as<double>()), float(grain[2].as<double>())};
  out.grain_stretch = m["grainStretch"].as<double>();
  out.refine_edge = m["refineEdge"].as<double>();
  out.absolute = m["absolute"].as<bool>();
  return out;
}

//! Numbers per shard in the packed result of WasmMesh::fracture.
constexpr std::size_t kShardScalars = 7 + 6 * 3 + 9;

// ---- The shared state of a mesh ---------------------------------------------------------------

struct MeshState {
  SurfaceMesh mesh;
  //! Built on the first pick; follows the mesh's change log afterwards. Declared after the mesh,
  //! so it is destroyed (and detached from the log) first.
  std::unique_ptr<FaceBvh> bvh;
  BuildReport report;
};

std::string element_name(const char* kind, std::uint32_t index) {
  return std::string(kind) + " " + std::to_string(index);
}

const char* none_if_missing(std::size_t slots) { return slots == 0 ? " (the mesh has none)" : ""; }

Vertex live_vertex(const SurfaceMesh& m, std::uint32_t v) {
  if (!m.is_live(Vertex(v)))
    throw InvalidInputError(element_name("vertex", v) + " is not a live vertex of the mesh (vertex slots: " +
                            std::to_string(m.vertex_slots()) + ")" + none_if_missing(m.vertex_slots()));
  return Vertex(v);
}
Halfedge live_halfedge(const SurfaceMesh& m, std::uint32_t h) {
  if (!m.is_live(Halfedge(h)))
    throw InvalidInputError(element_name("half-edge", h) +
                            " is not a live half-edge of the mesh (half-edge slots: " +
                            std::to_string(m.halfedge_slots()) + ")" + none_if_missing(m.halfedge_slots()));
  return Halfedge(h);
}
Edge live_edge(const SurfaceMesh& m, std::uint32_t e) {
  if (!m.is_live(Edge(e)))
    throw InvalidInputError(element_name("edge", e) + " is not a live edge of the mesh (edge slots: " +
                            std::to_string(m.edge_slots()) + ")" + none_if_missing(m.edge_slots()));
  return Edge(e);
}
Face live_face(const SurfaceMesh& m, std::uint32_t f) {
  if (!m.is_live(Face(f)))
    throw InvalidInputError(element_name("face", f) + " is not a live face of the mesh (face slots: " +
                            std::to_string(m.face_slots()) + ")" + none_if_missing(m.face_slots()));
  return Face(f);
}

// ---- Why a local operation is refused ----------------------------------------------------------
// The predicates of core/operations.h decide; these only explain a refusal in words, checking the
// conditions the predicates document, in order. "" means allowed.

std::string why_not_flip(const SurfaceMesh& m, Edge e) {
  if (!m.is_live(e)) return element_name("edge", e.idx()) + " is not a live edge";
  if (can_flip(m, e)) return {};
  const std::string name = element_name("edge", e.idx());
  if (m.is_boundary(e)) return name + " is on the boundary: a flip needs a face on both sides";
  const Halfedge h0 = SurfaceMesh::halfedge(e, 0), h1 = SurfaceMesh::halfedge(e, 1);
  if (m.valence(m.face(h0)) != 3 || m.valence(m.face(h1)) != 3)
    return "a face of " + name + " is not a triangle: a flip turns an edge between two triangles";
  const Vertex c = m.to_vertex(m.next(h0)), d = m.to_vertex(m.next(h1));
  if (c == d) return "the two triangles of " + name + " share their tip, " + element_name("vertex", c.idx());
  if (const Edge cd = m.find_edge(c, d); cd.is_valid())
    return "the tips of " + name + ", " + element_name("vertex", c.idx()) + " and " +
           element_name("vertex", d.idx()) + ", are already joined by " + element_name("edge", cd.idx());
  for (const Vertex v : m.vertices(e))
    if (!m.is_boundary(v) && m.valence(v) == 3)
      return element_name("vertex", v.idx()) + ", an end of " + name +
             ", is an interior vertex of valence 3: the flip would leave it with 2";
  return "flipping " + name + " would break the mesh";
}

std::string why_not_collapse(const SurfaceMesh& m, Halfedge h) {
  if (!m.is_live(h)) return element_name("half-edge", h.idx()) + " is not a live half-edge";
  if (can_collapse(m, h)) return {};
  const std::string name = element_name("half-edge", h.idx());
  const Vertex a = m.from_vertex(h), b = m.to_vertex(h);
  // The tips of the triangles on either side, which the two ends may share.
  std::vector<Vertex> tips;
  for (const Halfedge s : {h, SurfaceMesh::twin(h)})
    if (!m.is_boundary(s) && m.valence(m.face(s)) == 3) tips.push_back(m.to_vertex(m.next(s)));
  for (const Vertex n : m.vertices(a)) {
    if (n == b || std::find(tips.begin(), tips.end(), n) != tips.end()) continue;
    if (m.find_edge(n, b).is_valid())
      return "the ends of " + name + " (" + element_name("vertex", a.idx()) + " and " +
             element_name("vertex", b.idx()) + ") share the neighbour " + element_name("vertex", n.idx()) +
             " outside the triangles on the edge: collapsing would pinch the surface (the link condition)";
  }
  if (!m.is_boundary(SurfaceMesh::edge(h)) && m.is_boundary(a) && m.is_boundary(b))
    return name +
           " crosses the interior between two boundary vertices: collapsing would join the boundaries there";
  for (const Vertex t : tips)
    if (!m.is_boundary(t) && m.valence(t) <= 3)
      return element_name("vertex", t.idx()) + ", a tip of a triangle on " + name +
             ", is an interior vertex of valence 3: the collapse would leave it with 2";
  return "collapsing " + name +
         " would leave a degenerate or non-manifold surface (an end or a tip would be left "
         "with too few edges, or a boundary would close up)";
}

//! Runs body(), which rewrites the whole mesh (subdivision, decimation, garbage collection), so that
//! it either succeeds or leaves the mesh as it was: a copy is kept and put back if body() throws.
//! The library's algorithms check their input before they change anything, but running out of wasm
//! memory halfway through a step (a subdivision past what 2 GB holds) would leave a broken mesh.
//! Costs a copy of the mesh (time and memory), small next to what these algorithms allocate.
template <typename Body>
auto with_rollback(SurfaceMesh& mesh, Body&& body) -> decltype(body()) {
  SurfaceMesh backup = mesh;  // throws before anything changed if memory is short already
  try {
    return body();
  } catch (...) {
    mesh = std::move(backup);  // noexcept; the change log records a reset for its consumers
    throw;
  }
}

// ---- Picking results ---------------------------------------------------------------------------

//! Filled by Mesh::pick and read by the JS layer as a Float64Array at pickScratchAddress():
//! [face, t, px, py, pz, halfedge, edge, vertex, edgeDistance, vertexDistance, c0, c1, c2, b0, b1, b2].
double g_pick[16];

double distance_to_segment(const Vec3d& p, const Vec3d& a, const Vec3d& b) {
  const Vec3d ab = b - a;
  const double len2 = dot(ab, ab);
  double t = len2 > 0 ? dot(p - a, ab) / len2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  return norm(p - (a + ab * t));
}

Vec3d as_double(const Vec3& p) { return {double(p.x), double(p.y), double(p.z)}; }

// ---- Mesh --------------------------------------------------------------------------------------

TopologyPolicy policy_from(int policy) {
  if (policy == 0) return TopologyPolicy::strict;
  if (policy == 1) return TopologyPolicy::repair;
  throw InvalidInputError("unknown topology policy " + std::to_string(policy) + " (0 strict, 1 repair)");
}

Weld weld_from(int weld) {
  switch (weld) {
    case 0:
      return Weld::none;
    case 1:
      return Weld::exact;
    case 2:
      return Weld::epsilon;
    default:
      throw InvalidInputError("unknown weld mode " + std::to_string(weld) + " (0 none, 1 exact, 2 epsilon)");
  }
}

Subdivision scheme_from(const std::string& name) {
  if (name == "loop") return Subdivision::loop;
  if (name == "midpoint") return Subdivision::midpoint;
  if (name == "catmull-clark" || name == "catmull_clark") return Subdivision::catmull_clark;
  if (name == "sqrt3") return Subdivision::sqrt3;
  if (name == "split-faces" || name == "split_faces") return Subdivision::split_faces;
  throw InvalidInputError("unknown subdivision scheme '" + name +
                          "' (loop, midpoint, catmull-clark, sqrt3, split-faces)");
}

SmoothMethod method_from(const std::string& name) {
  if (name == "uniform") return SmoothMethod::uniform;
  if (name == "taubin") return SmoothMethod::taubin;
  if (name == "cotangent") return SmoothMethod::cotangent;
  if (name == "implicit") return SmoothMethod::implicit;
  throw InvalidInputError("unknown smoothing method '" + name + "' (uniform, taubin, cotangent, implicit)");
}

val report_to_js(const BuildReport& r) {
  val out = val::object();
  out.set("weldedVertices", double(r.welded_vertices));
  out.set("degenerateFaces", double(r.degenerate_faces));
  out.set("repeatedCorners", double(r.repeated_corners));
  out.set("reorientedFaces", double(r.reoriented_faces));
  out.set("nonManifoldEdges", double(r.non_manifold_edges));
  out.set("nonManifoldVertices", double(r.non_manifold_vertices));
  out.set("duplicatedVertices", double(r.duplicated_vertices));
  out.set("isolatedVertices", double(r.isolated_vertices));
  out.set("repairs", double(r.repairs()));
  val warnings = val::array();
  for (std::size_t i = 0; i < r.warnings.size(); ++i) warnings.set(i, r.warnings[i]);
  out.set("warnings", warnings);
  return out;
}

//! {halfedges, vertices (their targets), edges, faces} of a list of half-edges; the faces are those
//! of the twins (across) or of the half-edges themselves, -1 for none.
val halfedge_lists(const SurfaceMesh& m, const std::vector<Halfedge>& hs, bool faces_across) {
  std::vector<Vertex> vs;
  std::vector<Edge> es;
  std::vector<Face> fs;
  for (const Halfedge h : hs) {
    vs.push_back(m.to_vertex(h));
    es.push_back(SurfaceMesh::edge(h));
    fs.push_back(m.face(faces_across ? SurfaceMesh::twin(h) : h));
  }
  val out = val::object();
  out.set("halfedges", js_index_array(hs));
  out.set("vertices", js_index_array(vs));
  out.set("edges", js_index_array(es));
  out.set("faces", js_index_array(fs));
  return out;
}

class WasmMesh {
 public:
  WasmMesh() : s_(std::make_shared<MeshState>()) {}
  explicit WasmMesh(std::shared_ptr<MeshState> state) : s_(std::move(state)) {}

  //! positions: 3 floats per vertex; indices: the corners of the faces; face_sizes: corners per
  //! face, or empty/undefined for triangles.
  static WasmMesh from_buffers(val positions, val indices, val face_sizes, int policy, int weld) {
    return guarded([&] {
      IndexedMesh in;
      const std::uint32_t n_floats = js_length(positions, "positions");
      if (n_floats % 3 != 0)
        throw InvalidInputError("positions: " + std::to_string(n_floats) + " floats is not 3 per vertex");
      in.positions.resize(n_floats / 3);
      if (n_floats > 0) {
        val view{emscripten::typed_memory_view(n_floats, &in.positions[0].x)};
        view.call<void>("set", positions);
      }
      copy_from_js(indices, in.indices, js_length(indices, "indices"));
      copy_from_js(face_sizes, in.face_sizes, js_length(face_sizes, "faceSizes"));
      BuildOptions options;
      options.policy = policy_from(policy);
      options.weld = weld_from(weld);
      auto state = std::make_shared<MeshState>();
      state->mesh = build(in, options, &state->report);
      return WasmMesh(std::move(state));
    });
  }

  //! A file's bytes, read by hedge's reader for the format of `name`'s extension, then built with
  //! the file defaults (repair policy, exact welding for STL), as read_mesh() does.
  static WasmMesh from_file(const std::string& bytes, const std::string& name) {
    return guarded([&] {
      const FileFormat format = format_from_path(name);
      const IndexedMesh in = read_indexed(std::string_view(bytes), format, name);
      auto state = std::make_shared<MeshState>();
      state->mesh = build(in, default_build_options(format), &state->report);
      for (const ReadWarning& w : in.warnings) state->report.warnings.push_back(w.text());
      return WasmMesh(std::move(state));
    });
  }

  WasmMesh clone() const {
    return guarded([&] {
      auto state = std::make_shared<MeshState>();
      state->mesh = s_->mesh;
      return WasmMesh(std::move(state));
    });
  }

  std::shared_ptr<MeshState> state() const { return s_; }

  val build_report() const {
    return guarded([&] { return report_to_js(s_->report); });
  }

  // ---- Queries ----

  val counts() const {
    return guarded([&] {
      const SurfaceMesh& m = s_->mesh;
      val out = val::object();
      out.set("vertices", double(m.n_vertices()));
      out.set("edges", double(m.n_edges()));
      out.set("halfedges", double(m.n_halfedges()));
      out.set("faces", double(m.n_faces()));
      out.set("vertexSlots", double(m.vertex_slots()));
      out.set("halfedgeSlots", double(m.halfedge_slots()));
      out.set("edgeSlots", double(m.edge_slots()));
      out.set("faceSlots", double(m.face_slots()));
      return out;
    });
  }

  val validate() const {
    return guarded([&] {
      const std::vector<std::string> messages = s_->mesh.validate();
      val out = val::array();
      for (std::size_t i = 0; i < messages.size(); ++i) out.set(i, messages[i]);
      return out;
    });
  }

  bool is_triangle_mesh() const {
    return guarded([&] { return s_->mesh.is_triangle_mesh(); });
  }

  //! A view of the position array (3 floats per vertex slot, deleted slots included); no copy.
  val positions_view() const {
    return guarded([&] {
      const auto& p = s_->mesh.positions().vector();
      return val(emscripten::typed_memory_view(p.size() * 3, p.empty() ? nullptr : &p[0].x));
    });
  }

  val position(std::uint32_t v) const {
    return guarded([&] { return js_vec3(s_->mesh.position(live_vertex(s_->mesh, v))); });
  }

  void set_position(std::uint32_t v, val p) {
    guarded([&] {
      const Vertex vh = live_vertex(s_->mesh, v);
      s_->mesh.set_position(vh, point_from_js(p, "setPosition of " + element_name("vertex", v)));
    });
  }

  //! The records of half-edge h, as the half-edge article draws them.
  val halfedge(std::uint32_t h) const {
    return guarded([&] {
      const SurfaceMesh& m = s_->mesh;
      const Halfedge hh = live_halfedge(m, h);
      val out = val::object();
      out.set("halfedge", double(h));
      out.set("origin", js_index(m.from_vertex(hh).idx()));
      out.set("target", js_index(m.to_vertex(hh).idx()));
      out.set("twin", js_index(SurfaceMesh::twin(hh).idx()));
      out.set("face", js_index(m.face(hh).idx()));
      out.set("next", js_index(m.next(hh).idx()));
      out.set("prev", js_index(m.prev(hh).idx()));
      out.set("edge", js_index(SurfaceMesh::edge(hh).idx()));
      out.set("boundary", m.is_boundary(hh));
      return out;
    });
  }

  val vertex(std::uint32_t v) const {
    return guarded([&] {
      const SurfaceMesh& m = s_->mesh;
      const Vertex vh = live_vertex(m, v);
      val out = val::object();
      out.set("vertex", double(v));
      out.set("halfedge", js_index(m.halfedge(vh).idx()));
      out.set("position", js_vec3(m.position(vh)));
      out.set("valence", double(m.valence(vh)));
      out.set("boundary", m.is_boundary(vh));
      out.set("isolated", m.is_isolated(vh));
      return out;
    });
  }

  val edge(std::uint32_t e) const {
    return guarded([&] {
      const SurfaceMesh& m = s_->mesh;
      const Edge eh = live_edge(m, e);
      val out = val::object();
      out.set("edge", double(e));
      out.set("halfedges", js_index_array(std::vector<Halfedge>{SurfaceMesh::halfedge(eh, 0),
                                                                SurfaceMesh::halfedge(eh, 1)}));
      out.set("vertices", js_index_array(std::vector<Vertex>{m.vertex(eh, 0), m.vertex(eh, 1)}));
      out.set("faces", js_index_array(std::vector<Face>{m.face(eh, 0), m.face(eh, 1)}));
      out.set("boundary", m.is_boundary(eh));
      return out;
    });
  }

  //! f's half-edges in order: {face, halfedge, halfedges, vertices (their targets), edges, faces
  //! (across each edge, -1 on the boundary), boundary}.
  val face(std::uint32_t f) const {
    return guarded([&] {
      const SurfaceMesh& m = s_->mesh;
      const Face fh = live_face(m, f);
      std::vector<Halfedge> hs;
      for (const Halfedge h : m.halfedges(fh)) hs.push_back(h);
      val out = halfedge_lists(m, hs, true);
      out.set("face", double(f));
      out.set("halfedge", js_index(m.halfedge(fh).idx()));
      out.set("boundary", m.is_boundary(fh));
      return out;
    });
  }

  //! The one-ring of v, clockwise: outgoing half-edges, neighbours, edges, and the face of each
  //! outgoing half-edge (-1 across a boundary gap).
  val one_ring(std::uint32_t v) const {
    return guarded([&] {
      const SurfaceMesh& m = s_->mesh;
      const Vertex vh = live_vertex(m, v);
      std::vector<Halfedge> hs;
      if (!m.is_isolated(vh))
        for (const Halfedge h : m.halfedges(vh)) hs.push_back(h);
      val out = halfedge_lists(m, hs, false);
      out.set("vertex", double(v));
      return out;
    });
  }

  //! Casts a ray against the faces (a FaceBvh, built on the first call and updated from the change
  //! log afterwards). Returns the hit face or -1, and fills g_pick (see there).
  double pick(double ox, double oy, double oz, double dx, double dy, double dz) {
    return guarded([&]() -> double {
      FaceBvh& bvh = ready_bvh();
      const std::optional<RayHit> hit =
          bvh.first_hit(Vec3{float(ox), float(oy), float(oz)}, Vec3{float(dx), float(dy), float(dz)});
      if (!hit) return -1.0;
      const SurfaceMesh& m = s_->mesh;
      const Vec3d p = as_double(hit->point);
      Halfedge best_h;
      double best_h_d = std::numeric_limits<double>::infinity();
      Vertex best_v;
      double best_v_d = std::numeric_limits<double>::infinity();
      for (const Halfedge h : m.halfedges(hit->face)) {
        const Vec3d a = as_double(m.position(m.from_vertex(h))), b = as_double(m.position(m.to_vertex(h)));
        const double dh = distance_to_segment(p, a, b);
        if (dh < best_h_d) best_h_d = dh, best_h = h;
        const double dv = norm(p - b);
        if (dv < best_v_d) best_v_d = dv, best_v = m.to_vertex(h);
      }
      const double values[16] = {double(hit->face.idx()),
                                 hit->t,
                                 p.x,
                                 p.y,
                                 p.z,
                                 double(best_h.idx()),
                                 double(SurfaceMesh::edge(best_h).idx()),
                                 double(best_v.idx()),
                                 best_h_d,
                                 best_v_d,
                                 double(hit->corners[0].idx()),
                                 double(hit->corners[1].idx()),
                                 double(hit->corners[2].idx()),
                                 hit->barycentric[0],
                                 hit->barycentric[1],
                                 hit->barycentric[2]};
      std::copy(values, values + 16, g_pick);
      return double(hit->face.idx());
    });
  }

  //! Casts n rays (6 floats each: origin, direction) and writes each hit face, or -1, into `out`
  //! (an Int32Array of n entries). Returns the number of hits.
  std::uint32_t pick_many(val rays, val out) {
    return guarded([&]() -> std::uint32_t {
      std::vector<float> r;
      const std::uint32_t n_floats = js_length(rays, "rays");
      if (n_floats % 6 != 0)
        throw InvalidInputError("rays: " + std::to_string(n_floats) + " floats is not 6 per ray");
      const std::uint32_t n = n_floats / 6;
      if (js_length(out, "out") != n)
        throw InvalidInputError("out: expected " + std::to_string(n) + " entries, one per ray");
      copy_from_js(rays, r, n_floats);
      FaceBvh& bvh = ready_bvh();
      std::vector<std::int32_t> faces(n);
      std::uint32_t hits = 0;
      for (std::uint32_t i = 0; i < n; ++i) {
        const float* q = &r[6 * std::size_t(i)];
        const auto hit = bvh.first_hit(Vec3{q[0], q[1], q[2]}, Vec3{q[3], q[4], q[5]});
        faces[i] = hit ? std::int32_t(hit->face.idx()) : -1;
        hits += hit ? 1 : 0;
      }
      if (n > 0) out.call<void>("set", val(emscripten::typed_memory_view(faces.size(), faces.data())));
      return hits;
    });
  }

  // ---- Local operations ----

  //! "" if the operation is allowed on the element, else why not. op: splitEdge, flip, collapse
  //! (element: a half-edge), splitFace.
  std::string why_not(const std::string& op, std::uint32_t element) const {
    return guarded([&]() -> std::string {
      const SurfaceMesh& m = s_->mesh;
      if (op == "splitEdge")
        return can_split_edge(m, Edge(element)) ? "" : element_name("edge", element) + " is not a live edge";
      if (op == "flip")
        return m.is_valid(Edge(element)) ? why_not_flip(m, Edge(element))
                                         : element_name("edge", element) + " is not a live edge";
      if (op == "collapse")
        return m.is_valid(Halfedge(element))
                   ? why_not_collapse(m, Halfedge(element))
                   : element_name("half-edge", element) + " is not a live half-edge";
      if (op == "splitFace")
        return can_split_face(m, Face(element)) ? "" : element_name("face", element) + " is not a live face";
      throw InvalidInputError("unknown operation '" + op + "' (splitEdge, flip, collapse, splitFace)");
    });
  }

  //! Splits e at `point` ([x, y, z]; undefined: the midpoint). Returns the new vertex.
  double split_edge(std::uint32_t e, val point) {
    return guarded([&]() -> double {
      SurfaceMesh& m = s_->mesh;
      if (!can_split_edge(m, Edge(e)) || !m.is_valid(Edge(e)))
        throw Refused("split of " + element_name("edge", e) + " refused: " + element_name("edge", e) +
                      " is not a live edge");
      const Edge eh(e);
      const Vec3 p = point.isUndefined() || point.isNull()
                         ? (m.position(m.vertex(eh, 0)) + m.position(m.vertex(eh, 1))) * 0.5f
                         : point_from_js(point, "splitEdge of " + element_name("edge", e));
      const Vertex v = hedge::split_edge(m, eh, p);
      if (!v.is_valid()) throw Refused("split of " + element_name("edge", e) + " refused");
      return double(v.idx());
    });
  }

  double flip(std::uint32_t e) {
    return guarded([&]() -> double {
      SurfaceMesh& m = s_->mesh;
      if (!m.is_valid(Edge(e)) || !can_flip(m, Edge(e)))
        throw Refused("flip of " + element_name("edge", e) + " refused: " +
                      (m.is_valid(Edge(e)) ? why_not_flip(m, Edge(e))
                                           : element_name("edge", e) + " is not a live edge"));
      const Edge out = hedge::flip(m, Edge(e));
      if (!out.is_valid()) throw Refused("flip of " + element_name("edge", e) + " refused");
      return double(out.idx());
    });
  }

  //! Merges from_vertex(h) into to_vertex(h), which keeps its position unless `point` is given.
  //! Returns the surviving vertex.
  double collapse(std::uint32_t h, val point) {
    return guarded([&]() -> double {
      SurfaceMesh& m = s_->mesh;
      if (!m.is_valid(Halfedge(h)) || !can_collapse(m, Halfedge(h)))
        throw Refused("collapse of " + element_name("half-edge", h) + " refused: " +
                      (m.is_valid(Halfedge(h)) ? why_not_collapse(m, Halfedge(h))
                                               : element_name("half-edge", h) + " is not a live half-edge"));
      std::optional<Vec3> p;
      if (!point.isUndefined() && !point.isNull())
        p = point_from_js(point, "collapse of " + element_name("half-edge", h));
      const Vertex v = hedge::collapse(m, Halfedge(h));
      if (!v.is_valid()) throw Refused("collapse of " + element_name("half-edge", h) + " refused");
      if (p) m.set_position(v, *p);
      return double(v.idx());
    });
  }

  //! Splits f at `point` (undefined: its centroid). Returns the new vertex.
  double split_face(std::uint32_t f, val point) {
    return guarded([&]() -> double {
      SurfaceMesh& m = s_->mesh;
      if (!m.is_valid(Face(f)) || !can_split_face(m, Face(f)))
        throw Refused("split of " + element_name("face", f) + " refused: " + element_name("face", f) +
                      " is not a live face");
      const Vec3 p = point.isUndefined() || point.isNull()
                         ? face_centroid(m, Face(f))
                         : point_from_js(point, "splitFace of " + element_name("face", f));
      const Vertex v = hedge::split_face(m, Face(f), p);
      if (!v.is_valid()) throw Refused("split of " + element_name("face", f) + " refused");
      return double(v.idx());
    });
  }

  //! Removes deleted elements; every index may change.
  void garbage_collection() {
    guarded([&] { with_rollback(s_->mesh, [&] { s_->mesh.garbage_collection(); }); });
  }

  // ---- Algorithms ----

  void subdivide(const std::string& scheme, int steps) {
    guarded([&] {
      const Subdivision s = scheme_from(scheme);
      with_rollback(s_->mesh, [&] { hedge::subdivide(s_->mesh, s, steps); });
    });
  }

  void smooth(const std::string& method, int iterations, double lambda, double mu, bool fix_boundary) {
    guarded([&] {
      SmoothOptions options;
      options.method = method_from(method);
      options.iterations = iterations;
      options.lambda = lambda;
      options.mu = mu;
      options.fix_boundary = fix_boundary;
      hedge::smooth(s_->mesh, options);
    });
  }

  //! Decimates to target_faces faces (0: none) and target_vertices vertices (0: none), stopping
  //! before a collapse whose error exceeds max_error (negative: no limit).
  val decimate(double target_faces, double target_vertices, double max_error) {
    return guarded([&] {
      if (!(target_faces >= 0) || !(target_vertices >= 0))
        throw InvalidInputError("decimate: the targets must be counts (0 or more)");
      DecimateOptions options;
      options.target_faces = std::size_t(target_faces);
      options.target_vertices = std::size_t(target_vertices);
      if (max_error >= 0) options.max_error = max_error;
      const DecimateResult r = with_rollback(s_->mesh, [&] { return hedge::decimate(s_->mesh, options); });
      val out = val::object();
      out.set("vertices", double(r.vertices));
      out.set("faces", double(r.faces));
      out.set("collapses", double(r.collapses));
      out.set("maxError", r.max_error);
      return out;
    });
  }

  //! Breaks the mesh at `impact` (fracture.h), through the picking tree (built if missing, kept up
  //! to date), so the cost is that of the broken area. `preset`: a preset's name, or "" for the
  //! material in `custom`: {name, rings (Float64Array, 3 per ring: points, spacing, jitter), grain
  //! ([x, y, z]), grainStretch, refineEdge, absolute}, whose types the JS layer has checked.
  //! Returns {shards: {count, scalars (kShardScalars per shard: faces, area, volume, closed, mass,
  //! hull dimension, hull tolerance, centroid, centre of mass, principal moments, the three
  //! principal axes, inertia (9)), meshes (NativeMesh each), hullPositions, hullIndices (each hull's
  //! indices count from its first vertex), hullVertexOffsets, hullIndexOffsets (count + 1 each)},
  //! impactFace, impactPoint, seconds: {locate, scatter, cut, detach, hulls, fracture (the whole
  //! call), pack (making this result)}}.
  //! fracture() checks everything before it edits, so a refusal leaves the mesh as it was. Running out
  //! of wasm memory halfway is not rolled back (with_rollback's copy of the mesh would cost more
  //! than the strike, whose own allocations are those of the small broken area).
  val fracture(val impact, const std::string& preset, val custom, double seed, double thickness,
               double density, double tolerance, bool hulls) {
    return guarded([&] {
      const Vec3 at = point_from_js(impact, "fracture: the impact");
      if (!(seed >= 0 && seed <= 9007199254740992.0 && std::floor(seed) == seed))
        throw InvalidInputError("fracture: the seed must be a whole number in [0, 2^53]");
      FractureOptions options;
      options.material = preset.empty() ? material_from_js(custom) : fracture_material(preset);
      options.seed = std::uint64_t(seed);
      options.thickness = thickness;
      options.density = density;
      options.tolerance = tolerance;
      options.hulls = hulls;
      FaceBvh& bvh = ready_bvh();
      const auto start = std::chrono::steady_clock::now();
      FractureResult r = hedge::fracture(s_->mesh, at, options, &bvh);
      const auto fractured = std::chrono::steady_clock::now();

      // Packed into a few typed arrays (the JS layer makes the shard objects): a val call per field
      // would cost more than the fracture itself.
      const std::size_t n = r.shards.size();
      std::vector<double> scalars;
      scalars.reserve(n * kShardScalars);
      std::vector<float> hull_positions;
      std::vector<std::uint32_t> hull_indices, hull_vertex_offsets{0}, hull_index_offsets{0};
      val meshes = val::array();
      for (std::size_t i = 0; i < n; ++i) {
        Shard& shard = r.shards[i];
        const MassProperties& mp = shard.mass;
        const double head[] = {double(shard.mesh.n_faces()), shard.area, shard.volume,
                               shard.closed ? 1.0 : 0.0,     mp.mass,    double(int(shard.hull.dimension)),
                               shard.hull.tolerance};
        scalars.insert(scalars.end(), std::begin(head), std::end(head));
        for (const Vec3d& v : {shard.centroid, mp.centre_of_mass, mp.principal_moments, mp.principal_axes[0],
                               mp.principal_axes[1], mp.principal_axes[2]})
          scalars.insert(scalars.end(), {v.x, v.y, v.z});
        scalars.insert(scalars.end(), mp.inertia.begin(), mp.inertia.end());
        const IndexedMesh h = to_indexed(shard.hull.mesh);
        for (const Vec3& p : h.positions) hull_positions.insert(hull_positions.end(), {p.x, p.y, p.z});
        hull_indices.insert(hull_indices.end(), h.indices.begin(), h.indices.end());
        hull_vertex_offsets.push_back(std::uint32_t(hull_positions.size() / 3));
        hull_index_offsets.push_back(std::uint32_t(hull_indices.size()));
        auto state = std::make_shared<MeshState>();
        state->mesh = std::move(shard.mesh);
        meshes.set(i, WasmMesh(std::move(state)));
      }
      val shards = val::object();
      shards.set("count", double(n));
      shards.set("scalars", js_doubles(scalars.data(), scalars.size()));
      shards.set("meshes", meshes);
      shards.set("hullPositions", js_floats(hull_positions.data(), hull_positions.size()));
      shards.set("hullIndices", js_uints(hull_indices.data(), hull_indices.size()));
      shards.set("hullVertexOffsets", js_uints(hull_vertex_offsets.data(), hull_vertex_offsets.size()));
      shards.set("hullIndexOffsets", js_uints(hull_index_offsets.data(), hull_index_offsets.size()));
      val seconds = val::object();
      seconds.set("locate", r.seconds.locate);
      seconds.set("scatter", r.seconds.scatter);
      seconds.set("cut", r.seconds.cut);
      seconds.set("detach", r.seconds.detach);
      seconds.set("hulls", r.seconds.hulls);
      seconds.set("fracture", std::chrono::duration<double>(fractured - start).count());
      seconds.set("pack",
                  std::chrono::duration<double>(std::chrono::steady_clock::now() - fractured).count());
      val result = val::object();
      result.set("shards", shards);
      result.set("impactFace", js_index(r.impact_face.idx()));
      result.set("impactPoint", js_vec3(r.impact_point));
      result.set("seconds", seconds);
      return result;
    });
  }

  //! The live mesh as index buffers (copies): {positions, indices, faceSizes (null for triangles)}.
  val to_arrays(bool triangulate) const {
    return guarded([&] {
      ExportOptions options;
      options.triangulation = triangulate ? Triangulation::ear : Triangulation::none;
      options.corner_attributes = false;
      const IndexedMesh out = to_indexed(s_->mesh, options);
      val result = val::object();
      const val f32 = val::global("Float32Array"), u32 = val::global("Uint32Array");
      result.set("positions",
                 f32.new_(val(emscripten::typed_memory_view(
                     out.positions.size() * 3, out.positions.empty() ? nullptr : &out.positions[0].x))));
      result.set("indices",
                 u32.new_(val(emscripten::typed_memory_view(out.indices.size(), out.indices.data()))));
      result.set("faceSizes", out.face_sizes.empty() ? val::null()
                                                     : u32.new_(val(emscripten::typed_memory_view(
                                                           out.face_sizes.size(), out.face_sizes.data()))));
      return result;
    });
  }

  //! The mesh written in the format of name's extension, as write_mesh() writes a file (STL
  //! triangulated by fans; PLY and STL binary). A copy (Uint8Array).
  val to_file(const std::string& name) const {
    return guarded([&] {
      const FileFormat format = format_from_path(name);
      ExportOptions options;
      if (format == FileFormat::stl) options.triangulation = Triangulation::fan;
      const std::string bytes = write_indexed(to_indexed(s_->mesh, options), format);
      return val::global("Uint8Array")
          .new_(val(emscripten::typed_memory_view(bytes.size(),
                                                  reinterpret_cast<const std::uint8_t*>(bytes.data()))));
    });
  }

  double memory_bytes() const {
    return guarded([&] { return double(s_->mesh.memory_bytes() + (s_->bvh ? s_->bvh->memory_bytes() : 0)); });
  }

 private:
  FaceBvh& ready_bvh() {
    if (!s_->bvh)
      s_->bvh = std::make_unique<FaceBvh>(s_->mesh);
    else
      s_->bvh->update();
    return *s_->bvh;
  }

  std::shared_ptr<MeshState> s_;
};

// ---- Render ------------------------------------------------------------------------------------

NormalSource normals_from(const std::string& name) {
  if (name == "none") return NormalSource::none;
  if (name == "attribute") return NormalSource::attribute;
  if (name == "computed") return NormalSource::computed;
  if (name == "auto" || name == "automatic") return NormalSource::automatic;
  throw InvalidInputError("unknown normal source '" + name + "' (none, attribute, computed, auto)");
}

val ranges_to_js(const std::vector<SlotRange>& ranges) {
  val out = val::global("Uint32Array").new_(double(ranges.size() * 2));
  if (!ranges.empty()) {
    static_assert(sizeof(SlotRange) == 8);
    out.call<void>("set", val(emscripten::typed_memory_view(
                              ranges.size() * 2, reinterpret_cast<const std::uint32_t*>(ranges.data()))));
  }
  return out;
}

val sync_result_to_js(const SyncResult& r) {
  val out = val::object();
  out.set("vertexRanges", ranges_to_js(r.vertex_ranges));
  out.set("indexRanges", ranges_to_js(r.index_ranges));
  out.set("vertexBytes", double(r.vertex_bytes));
  out.set("indexBytes", double(r.index_bytes));
  out.set("facesSynced", double(r.faces_synced));
  out.set("verticesSynced", double(r.vertices_synced));
  out.set("resized", r.resized);
  out.set("full", r.full);
  return out;
}

class WasmRender {
 public:
  WasmRender() = default;

  static WasmRender create(const WasmMesh& mesh, const std::string& normals, bool interleaved, bool texcoords,
                           bool colors) {
    return guarded([&] {
      WasmRender r;
      r.s_ = mesh.state();
      RenderOptions options;
      options.normals = normals_from(normals);
      options.interleaved = interleaved;
      options.texcoords = texcoords;
      options.colors = colors;
      r.sync_ = std::make_shared<RenderSync>(r.s_->mesh, options);
      return r;
    });
  }

  val layout() const {
    return guarded([&] {
      const VertexLayout& l = sync().layout();
      val out = val::object();
      out.set("stride", double(l.stride));
      out.set("position", double(l.position));
      out.set("normal", double(l.normal));
      out.set("texcoord", double(l.texcoord));
      out.set("color", double(l.color));
      out.set("interleaved", l.interleaved);
      return out;
    });
  }

  val sizes() const {
    return guarded([&] {
      const RenderSync& r = sync();
      val out = val::object();
      out.set("vertexSlots", double(r.vertex_slots()));
      out.set("triangleSlots", double(r.triangle_slots()));
      out.set("indexCount", double(r.index_count()));
      out.set("vertices", double(r.n_vertices()));
      out.set("triangles", double(r.n_triangles()));
      out.set("vertexCapacity", double(r.vertex_capacity()));
      out.set("indexCapacity", double(r.index_capacity()));
      out.set("freeTriangleSlots", double(r.free_triangle_slots()));
      out.set("bufferBytes", double(r.buffer_bytes()));
      return out;
    });
  }

  //! Views into wasm memory (no copy). stream: 0 vertices (interleaved, or positions), 1 normals,
  //! 2 texcoords, 3 colours.
  val stream_view(int stream) const {
    return guarded([&] {
      const RenderSync& r = sync();
      std::span<const float> s;
      switch (stream) {
        case 0:
          s = r.vertices();
          break;
        case 1:
          s = r.normals();
          break;
        case 2:
          s = r.texcoords();
          break;
        case 3:
          s = r.colors();
          break;
        default:
          throw InvalidInputError("unknown stream " + std::to_string(stream));
      }
      return val(emscripten::typed_memory_view(s.size(), s.data()));
    });
  }

  val indices_view() const {
    return guarded([&] {
      const auto s = sync().indices();
      return val(emscripten::typed_memory_view(s.size(), s.data()));
    });
  }

  //! Render vertex -> mesh vertex (0xFFFFFFFF for a free slot), a view.
  val vertex_source_view() const {
    return guarded([&] {
      const auto s = sync().render_vertex_source();
      static_assert(sizeof(Vertex) == sizeof(std::uint32_t));
      return val(emscripten::typed_memory_view(s.size(), reinterpret_cast<const std::uint32_t*>(s.data())));
    });
  }

  //! [first triangle slot, count] of face f.
  val face_triangles(std::uint32_t f) const {
    return guarded([&] {
      const SlotRange range = sync().triangles(live_face(s_->mesh, f));
      val out = val::array();
      out.set(0, double(range.first));
      out.set(1, double(range.count));
      return out;
    });
  }

  val do_sync() {
    return guarded([&] { return sync_result_to_js(sync().sync()); });
  }
  val rebuild() {
    return guarded([&] { return sync_result_to_js(sync().rebuild()); });
  }
  void compact() {
    guarded([&] { sync().compact(); });
  }
  void begin() {
    guarded([&] { sync().begin(); });
  }
  val commit() {
    return guarded([&] { return sync_result_to_js(sync().commit()); });
  }

 private:
  RenderSync& sync() const {
    if (!sync_) throw InvalidInputError("this render object was not created");
    return *sync_;
  }
  // The state first: members are destroyed in reverse order, so the RenderSync detaches from the
  // mesh's change log before the mesh can go.
  std::shared_ptr<MeshState> s_;
  std::shared_ptr<RenderSync> sync_;
};

// ---- Module-level functions --------------------------------------------------------------------

std::uintptr_t error_slot_address() { return reinterpret_cast<std::uintptr_t>(&g_error); }
std::uintptr_t pick_scratch_address() { return reinterpret_cast<std::uintptr_t>(&g_pick[0]); }

//! Bytes the allocator has handed out and not got back: what a leak would make grow.
double heap_bytes_in_use() {
  const struct mallinfo info = mallinfo();
  return double(info.uordblks);
}

std::string version() { return "0.1.0"; }

}  // namespace

EMSCRIPTEN_BINDINGS(hedge) {
  using namespace emscripten;
  function("errorSlotAddress", &error_slot_address);
  function("takeErrorMessage", &take_error_message);
  function("pickScratchAddress", &pick_scratch_address);
  function("heapBytesInUse", &heap_bytes_in_use);
  function("version", &version);

  class_<WasmMesh>("NativeMesh")
      .constructor<>()
      .class_function("fromBuffers", &WasmMesh::from_buffers)
      .class_function("fromFile", &WasmMesh::from_file)
      .function("clone", &WasmMesh::clone)
      .function("buildReport", &WasmMesh::build_report)
      .function("counts", &WasmMesh::counts)
      .function("validate", &WasmMesh::validate)
      .function("isTriangleMesh", &WasmMesh::is_triangle_mesh)
      .function("positionsView", &WasmMesh::positions_view)
      .function("position", &WasmMesh::position)
      .function("setPosition", &WasmMesh::set_position)
      .function("halfedge", &WasmMesh::halfedge)
      .function("vertex", &WasmMesh::vertex)
      .function("edge", &WasmMesh::edge)
      .function("face", &WasmMesh::face)
      .function("oneRing", &WasmMesh::one_ring)
      .function("pick", &WasmMesh::pick)
      .function("pickMany", &WasmMesh::pick_many)
      .function("whyNot", &WasmMesh::why_not)
      .function("splitEdge", &WasmMesh::split_edge)
      .function("flip", &WasmMesh::flip)
      .function("collapse", &WasmMesh::collapse)
      .function("splitFace", &WasmMesh::split_face)
      .function("garbageCollection", &WasmMesh::garbage_collection)
      .function("subdivide", &WasmMesh::subdivide)
      .function("smooth", &WasmMesh::smooth)
      .function("decimate", &WasmMesh::decimate)
      .function("fracture", &WasmMesh::fracture)
      .function("toArrays", &WasmMesh::to_arrays)
      .function("toFile", &WasmMesh::to_file)
      .function("memoryBytes", &WasmMesh::memory_bytes);

  class_<WasmRender>("NativeRender")
      .class_function("create", &WasmRender::create)
      .function("layout", &WasmRender::layout)
      .function("sizes", &WasmRender::sizes)
      .function("streamView", &WasmRender::stream_view)
      .function("indicesView", &WasmRender::indices_view)
      .function("vertexSourceView", &WasmRender::vertex_source_view)
      .function("faceTriangles", &WasmRender::face_triangles)
      .function("sync", &WasmRender::do_sync)
      .function("rebuild", &WasmRender::rebuild)
      .function("compact", &WasmRender::compact)
      .function("begin", &WasmRender::begin)
      .function("commit", &WasmRender::commit);
}
