/* The C ABI of hedge: a flat, exception-free interface for C and for P/Invoke (C#).
 *
 * Conventions
 *  - Every function returns a status code (hedge_status: HEDGE_OK = 0, errors negative), except
 *    hedge_last_error(), hedge_last_refusal(), hedge_last_refusal_code(), hedge_refusal_text(),
 *    hedge_refusal_name() and hedge_status_string(), which cannot fail. Results
 *    are written through out parameters, which are never NULL unless documented as optional; on an
 *    error the out parameters are left unchanged unless documented otherwise.
 *  - No C++ exception ever crosses this interface. After a call that failed, hedge_last_error()
 *    gives the message on the calling thread (an I/O error names the file and the line or byte
 *    offset). Every other call that succeeds clears the message to the empty string (the six
 *    functions that cannot fail leave it as it is). The status codes are the one list of error kinds of
 *    every binding: the JS API's HedgeError.kind and the C# binding's HedgeStatus name them one to
 *    one.
 *  - Objects are opaque handles: hedge_mesh* and hedge_render_buffers*. A handle is not an address: it is
 *    an id checked against a registry of live objects on every call, so NULL, a destroyed handle or
 *    a value that was never a handle yields HEDGE_ERROR_BAD_HANDLE instead of undefined behaviour.
 *    Ids are never reused within a process, so a destroyed handle never aliases a later object.
 *  - Elements (vertices, half-edges, edges, faces) are uint32_t indices; HEDGE_INVALID_INDEX
 *    (0xFFFFFFFF) means "none" (the face of a boundary half-edge, an isolated vertex's half-edge).
 *    An element argument that is out of range or deleted yields HEDGE_ERROR_BAD_HANDLE, except in
 *    the hedge_*_is_deleted queries, which accept deleted elements. Half-edges come in pairs:
 *    half-edge h belongs to edge h >> 1, and its twin is h ^ 1.
 *  - Booleans are int32_t: 0 false, 1 true.
 *  - Caller buffers: a function that fills a buffer takes the buffer, its capacity in elements (in
 *    bytes for text, counting the terminating NUL) and an out-count. The out-count always receives
 *    the size needed. When it exceeds the capacity, the function writes nothing into the buffer,
 *    returns HEDGE_ERROR_BUFFER_TOO_SMALL and, for an edit, leaves the mesh unchanged. The buffer
 *    may be NULL when the capacity is 0, so (NULL, 0) asks for the size.
 *  - Structs hold only int32_t, uint32_t, uint64_t, float and double fields at their natural
 *    alignment (the layout of a C# [StructLayout(LayoutKind.Sequential)] struct); the byte offsets
 *    are given with each.
 *  - Threads: every function may be called from any thread, and different objects may be used
 *    concurrently. One mesh (with its render objects) takes calls from one thread at a time: a call
 *    that overlaps another thread's call on the same mesh fails at once with HEDGE_ERROR_BUSY and
 *    changes nothing (one atomic compare-and-swap per call checks it). Destroying an object while
 *    another thread uses it fails the same way.
 *  - Strings are UTF-8, NUL-terminated; paths too.
 *
 * Render objects refer to their mesh: hedge_mesh_destroy() also destroys every render object made
 * for that mesh, whose handles then yield HEDGE_ERROR_BAD_HANDLE.
 */
#ifndef HEDGE_C_API_H
#define HEDGE_C_API_H

#include <stddef.h>
#include <stdint.h>

#if defined(_WIN32)
#if defined(HEDGE_C_BUILDING)
#define HEDGE_API __declspec(dllexport)
#else
#define HEDGE_API __declspec(dllimport)
#endif
#elif defined(__GNUC__) || defined(__clang__)
#define HEDGE_API __attribute__((visibility("default")))
#else
#define HEDGE_API
#endif

#ifdef __cplusplus
extern "C" {
#endif

/* ============================================================================================ */
/* Status codes, errors, version                                                                */
/* ============================================================================================ */

/** A status code: one of the HEDGE_OK / HEDGE_ERROR_* values (int32_t, so it is the same size in
 *  every language). */
typedef int32_t hedge_status;

enum {
  /** Success. */
  HEDGE_OK = 0,
  /** An argument is invalid: a NULL pointer, a NaN or infinite coordinate, a size mismatch, an
   *  index into the input arrays out of range, an unknown enum value. */
  HEDGE_ERROR_INVALID_ARGUMENT = -1,
  /** A mesh or render handle is NULL, destroyed or was never a handle; or an element index is out
   *  of range or names a deleted element. */
  HEDGE_ERROR_BAD_HANDLE = -2,
  /** The operation is illegal here (its predicate says no). Nothing was changed. */
  HEDGE_ERROR_REFUSED = -3,
  /** A file could not be read or written, or is malformed. The message names the file and the line
   *  (text formats) or byte offset (binary formats). */
  HEDGE_ERROR_IO = -4,
  /** The input cannot be represented as a half-edge mesh under the strict policy. */
  HEDGE_ERROR_TOPOLOGY = -5,
  /** Memory ran out. The object is unchanged if the operation had not started changing it. */
  HEDGE_ERROR_OUT_OF_MEMORY = -6,
  /** A caller buffer is too small; the out-count gives the size needed. Nothing was changed. */
  HEDGE_ERROR_BUFFER_TOO_SMALL = -7,
  /** An unexpected internal failure (a bug); the message says what. */
  HEDGE_ERROR_INTERNAL = -8,
  /** The mesh (or the mesh of a render object) is in a call on another thread. A mesh and its
   *  render objects take calls from one thread at a time; overlapping calls from a second thread
   *  fail at once with this status instead of corrupting the mesh or hanging. Nothing was changed. */
  HEDGE_ERROR_BUSY = -9
};

/** The invalid element index. */
#define HEDGE_INVALID_INDEX 0xFFFFFFFFu

/** The message of the last failed call on this thread; "" after a call that succeeded. The pointer
 *  stays valid until the next hedge_* call on this thread. Never NULL. */
HEDGE_API const char* hedge_last_error(void);

/** Why the last call on this thread was refused (HEDGE_ERROR_REFUSED): the library's refusal in a
 *  few words ("the edge is on the boundary (a flip needs a triangle on both sides)"), the same text
 *  in every binding; hedge_last_error() says more ("flip of edge 3 refused: ...; nothing was
 *  changed"). After a predicate (hedge_can_*) that answered 0: why that edit would be refused.
 *  "" after any other call. Static storage; never NULL. */
HEDGE_API const char* hedge_last_refusal(void);

/** A refusal's stable code: why an edit was refused, as a number to check without comparing text
 *  (the library's one table of refusals, hedge/core/refusal.h). A code keeps its value in every
 *  later release; new refusals take new values. The C# binding names them RefusalCode. */
typedef int32_t hedge_refusal;

enum {
  /** Not refused. */
  HEDGE_REFUSAL_NONE = 0,
  /** the edge is not live */
  HEDGE_REFUSAL_EDGE_NOT_LIVE = 1,
  /** the half-edge is not live */
  HEDGE_REFUSAL_HALFEDGE_NOT_LIVE = 2,
  /** the face is not live */
  HEDGE_REFUSAL_FACE_NOT_LIVE = 3,
  /** the vertex is not live */
  HEDGE_REFUSAL_VERTEX_NOT_LIVE = 4,
  /** it would join the two sides of a seam at the surviving vertex */
  HEDGE_REFUSAL_COLLAPSE_JOINS_SEAM_SIDES = 5,
  /** it would pull a seam vertex off its seam */
  HEDGE_REFUSAL_COLLAPSE_PULLS_SEAM_VERTEX = 6,
  /** it would shorten a seam that ends at the merged vertex */
  HEDGE_REFUSAL_COLLAPSE_SHORTENS_SEAM = 7,
  /** the edge has the same face on both sides */
  HEDGE_REFUSAL_COLLAPSE_SAME_FACE_BOTH_SIDES = 8,
  /** an interior edge joins two boundary vertices (the surface would pinch) */
  HEDGE_REFUSAL_COLLAPSE_PINCHES_BOUNDARY = 9,
  /** a second edge joins its ends */
  HEDGE_REFUSAL_COLLAPSE_SECOND_EDGE = 10,
  /** its ends share a neighbour besides the tips of its triangles (the link condition) */
  HEDGE_REFUSAL_COLLAPSE_LINK_CONDITION = 11,
  /** a triangle on the edge has the boundary on both other sides (an edge would dangle) */
  HEDGE_REFUSAL_COLLAPSE_DANGLING_EDGE = 12,
  /** a tip of its triangles would be left with too few edges */
  HEDGE_REFUSAL_COLLAPSE_TIP_TOO_FEW_EDGES = 13,
  /** the surviving vertex would be left with too few edges */
  HEDGE_REFUSAL_COLLAPSE_SURVIVOR_TOO_FEW_EDGES = 14,
  /** the two triangles on the edge share their tip */
  HEDGE_REFUSAL_FLIP_TIPS_SHARED = 15,
  /** an end is an interior vertex of valence 3 (the flip would leave it with 2) */
  HEDGE_REFUSAL_FLIP_VALENCE_THREE = 16,
  /** the tips of its triangles are already joined by an edge */
  HEDGE_REFUSAL_FLIP_TIPS_JOINED = 17,
  /** the edge is on the boundary (a flip needs a triangle on both sides) */
  HEDGE_REFUSAL_FLIP_BOUNDARY_EDGE = 18,
  /** a face on the edge is not a triangle */
  HEDGE_REFUSAL_FLIP_NOT_TRIANGLE = 19,
  /** a half-edge is not live */
  HEDGE_REFUSAL_CUT_HALFEDGE_NOT_LIVE = 20,
  /** the two half-edges are the same */
  HEDGE_REFUSAL_CUT_SAME_HALFEDGE = 21,
  /** the half-edges are on a boundary, not in a face */
  HEDGE_REFUSAL_CUT_ON_BOUNDARY = 22,
  /** the half-edges are in different faces */
  HEDGE_REFUSAL_CUT_DIFFERENT_FACES = 23,
  /** their targets are neighbours in the face (the cut would double an edge) */
  HEDGE_REFUSAL_CUT_NEIGHBOUR_TARGETS = 24,
  /** an edge already joins their targets */
  HEDGE_REFUSAL_CUT_TARGETS_JOINED = 25,
  /** a face needs at least 3 corners */
  HEDGE_REFUSAL_ADD_FACE_TOO_FEW_CORNERS = 26,
  /** a corner is not a live vertex */
  HEDGE_REFUSAL_ADD_FACE_CORNER_NOT_LIVE = 27,
  /** a corner is repeated */
  HEDGE_REFUSAL_ADD_FACE_CORNER_REPEATED = 28,
  /** an edge of the face already has a face on that side */
  HEDGE_REFUSAL_ADD_FACE_EDGE_TAKEN = 29,
  /** a corner is an interior vertex (its fan of faces is closed) */
  HEDGE_REFUSAL_ADD_FACE_INTERIOR_CORNER = 30,
  /** the face would meet a corner's faces at the vertex only (a second gap in its fan) */
  HEDGE_REFUSAL_ADD_FACE_SECOND_GAP = 31,
  /** a corner would be left with two gaps in its fan of faces (pinched) */
  HEDGE_REFUSAL_REMOVE_FACE_PINCHES = 32,
  /** a corner of its faces would be left with two gaps in its fan of faces (pinched) */
  HEDGE_REFUSAL_REMOVE_VERTEX_PINCHES = 33,
  /** the half-edge is not on a boundary (it has a face) */
  HEDGE_REFUSAL_FILL_HOLE_NOT_BOUNDARY = 34,
  /** its boundary loop is damaged (it never closes) */
  HEDGE_REFUSAL_FILL_HOLE_LOOP_DAMAGED = 35,
  /** its boundary loop has fewer than 3 edges (no room for a face) */
  HEDGE_REFUSAL_FILL_HOLE_LOOP_TOO_SHORT = 36,
  /** How many codes there are (one past the largest). */
  HEDGE_REFUSAL_COUNT = 37
};

/** The code of hedge_last_refusal(): why the last call on this thread was refused (or why the edit
 *  a predicate answered 0 for would be), as a number; HEDGE_REFUSAL_NONE after any other call.
 *  Cannot fail; allocates nothing. */
HEDGE_API hedge_refusal hedge_last_refusal_code(void);

/** A refusal's text, as hedge_last_refusal() gives it ("" for HEDGE_REFUSAL_NONE and for a value
 *  that is not a code). Static storage; never NULL. */
HEDGE_API const char* hedge_refusal_text(hedge_refusal code);

/** A refusal's constant name ("HEDGE_REFUSAL_FLIP_BOUNDARY_EDGE"), or "HEDGE_REFUSAL_UNKNOWN" for a
 *  value that is not a code. Static storage; never NULL. */
HEDGE_API const char* hedge_refusal_name(hedge_refusal code);

/** A short constant name for a status code ("HEDGE_OK", "HEDGE_ERROR_REFUSED", ...), or
 *  "HEDGE_ERROR_UNKNOWN" for a value that is not a status code. Never NULL; static storage. */
HEDGE_API const char* hedge_status_string(hedge_status code);

/** The library version (major.minor.patch). */
HEDGE_API hedge_status hedge_version(int32_t* out_major, int32_t* out_minor, int32_t* out_patch);

/* ============================================================================================ */
/* Meshes: creation and destruction                                                             */
/* ============================================================================================ */

typedef struct hedge_mesh hedge_mesh;
typedef struct hedge_render_buffers hedge_render_buffers;

/** Topology policy (hedge::TopologyPolicy). */
enum {
  /** Refuse input a half-edge mesh cannot hold: HEDGE_ERROR_TOPOLOGY. */
  HEDGE_POLICY_STRICT = 0,
  /** Split non-manifold edges and vertices, re-orient faces, drop degenerate faces; every repair is
   *  counted in the build report. */
  HEDGE_POLICY_REPAIR = 1
};

/** Vertex welding (hedge::Weld). */
enum {
  HEDGE_WELD_NONE = 0,   /**< keep the input's vertices */
  HEDGE_WELD_EXACT = 1,  /**< merge bit-identical positions (+0 == -0) */
  HEDGE_WELD_EPSILON = 2 /**< merge positions closer than weld_epsilon x bounding-box diagonal */
};

/** Triangle winding (hedge::Winding). */
enum {
  HEDGE_WINDING_CCW = 0,
  HEDGE_WINDING_CW = 1 /**< Unity, Direct3D */
};

/** Build options. Layout (16 bytes): policy @0, weld @4, weld_epsilon @8. */
typedef struct hedge_build_options {
  int32_t policy;      /**< HEDGE_POLICY_* */
  int32_t weld;        /**< HEDGE_WELD_* */
  double weld_epsilon; /**< relative to the bounding-box diagonal; used with HEDGE_WELD_EPSILON */
} hedge_build_options;

/** What building did; all zero for clean input. Layout (36 bytes): nine uint32_t in this order. */
typedef struct hedge_build_report {
  uint32_t welded_vertices;       /**< input vertices merged into another by welding */
  uint32_t degenerate_faces;      /**< faces dropped: fewer than 3 distinct corners */
  uint32_t repeated_corners;      /**< consecutive repeated corners removed from kept faces */
  uint32_t reoriented_faces;      /**< faces whose winding was reversed */
  uint32_t non_manifold_edges;    /**< input edges cut apart */
  uint32_t non_manifold_vertices; /**< vertices whose faces formed several fans */
  uint32_t duplicated_vertices;   /**< vertices added to split them */
  uint32_t isolated_vertices;     /**< vertices no face uses (kept; not a repair) */
  uint32_t repairs;               /**< total repairs (welding and isolated vertices excluded) */
} hedge_build_report;

/** Fills *out_options with the defaults of the C ABI: HEDGE_POLICY_REPAIR, HEDGE_WELD_NONE,
 *  weld_epsilon 1e-6. (Note: the C++ default policy is strict; the C ABI's is repair.) */
HEDGE_API hedge_status hedge_build_options_default(hedge_build_options* out_options);

/** Builds a mesh from index buffers.
 *  \param positions     3 floats (x, y, z) per vertex, vertex_count vertices; finite.
 *  \param indices       the corners of all faces, face after face (index_count entries), each an
 *                       index into positions.
 *  \param face_sizes    the number of corners of each face (face_count entries), summing to
 *                       index_count; NULL for triangles (then face_count must be 0 or
 *                       index_count / 3, and index_count a multiple of 3).
 *  \param options       NULL for hedge_build_options_default().
 *  \param out_report    optional (NULL): what was repaired.
 *  \param out_vertex_map optional (NULL), vertex_count entries: input vertex -> mesh vertex
 *                       (after welding; a split vertex maps to its first copy).
 *  \param out_face_map  optional (NULL), one entry per input face (face_count, or index_count / 3
 *                       for triangles): input face -> mesh face, HEDGE_INVALID_INDEX if dropped.
 *  \param out_mesh      receives the new mesh; destroy it with hedge_mesh_destroy().
 *  \return HEDGE_ERROR_INVALID_ARGUMENT for a NaN coordinate, an index out of range or a size
 *          mismatch; HEDGE_ERROR_TOPOLOGY for non-manifold input under HEDGE_POLICY_STRICT. */
HEDGE_API hedge_status hedge_mesh_create(const float* positions, uint32_t vertex_count,
                                         const uint32_t* indices, uint32_t index_count,
                                         const uint32_t* face_sizes, uint32_t face_count,
                                         const hedge_build_options* options, hedge_build_report* out_report,
                                         uint32_t* out_vertex_map, uint32_t* out_face_map,
                                         hedge_mesh** out_mesh);

/** Destroys a mesh and every render object made for it. NULL or a destroyed handle:
 *  HEDGE_ERROR_BAD_HANDLE. */
HEDGE_API hedge_status hedge_mesh_destroy(hedge_mesh* mesh);

/* ============================================================================================ */
/* Counts and positions                                                                         */
/* ============================================================================================ */

/** Element counts. Live counts skip deleted elements; slot counts include them (element indices
 *  run from 0 to the slot count - 1 until hedge_mesh_garbage_collection()).
 *  Layout (32 bytes): eight uint32_t in this order. */
typedef struct hedge_counts {
  uint32_t vertices;
  uint32_t halfedges;
  uint32_t edges;
  uint32_t faces;
  uint32_t vertex_slots;
  uint32_t halfedge_slots;
  uint32_t edge_slots;
  uint32_t face_slots;
} hedge_counts;

HEDGE_API hedge_status hedge_mesh_counts(const hedge_mesh* mesh, hedge_counts* out_counts);

/** out_xyz receives 3 floats. */
HEDGE_API hedge_status hedge_vertex_position(const hedge_mesh* mesh, uint32_t vertex, float* out_xyz);
/** Moves a vertex (render objects see it at their next sync). NaN or infinity:
 *  HEDGE_ERROR_INVALID_ARGUMENT. */
HEDGE_API hedge_status hedge_set_vertex_position(hedge_mesh* mesh, uint32_t vertex, float x, float y,
                                                 float z);
/** Copies the positions of every vertex slot (deleted ones included, with stale data): 3 floats a
 *  slot, so the size needed (*out_count, in floats) is 3 x vertex_slots. */
HEDGE_API hedge_status hedge_mesh_copy_positions(const hedge_mesh* mesh, float* buffer, uint64_t capacity,
                                                 uint64_t* out_count);

/* ============================================================================================ */
/* Adjacency. O(1) unless noted.                                                                */
/* ============================================================================================ */

HEDGE_API hedge_status hedge_halfedge_twin(const hedge_mesh* mesh, uint32_t halfedge, uint32_t* out_halfedge);
/** The next half-edge in the face or boundary loop. */
HEDGE_API hedge_status hedge_halfedge_next(const hedge_mesh* mesh, uint32_t halfedge, uint32_t* out_halfedge);
/** The previous half-edge in the face or boundary loop: O(face degree), O(valence) on a boundary. */
HEDGE_API hedge_status hedge_halfedge_prev(const hedge_mesh* mesh, uint32_t halfedge, uint32_t* out_halfedge);
/** The vertex the half-edge points to. */
HEDGE_API hedge_status hedge_halfedge_to_vertex(const hedge_mesh* mesh, uint32_t halfedge,
                                                uint32_t* out_vertex);
/** The vertex the half-edge starts at. */
HEDGE_API hedge_status hedge_halfedge_from_vertex(const hedge_mesh* mesh, uint32_t halfedge,
                                                  uint32_t* out_vertex);
/** The face of the half-edge; HEDGE_INVALID_INDEX for a boundary half-edge. */
HEDGE_API hedge_status hedge_halfedge_face(const hedge_mesh* mesh, uint32_t halfedge, uint32_t* out_face);
/** The edge of the half-edge (halfedge >> 1). */
HEDGE_API hedge_status hedge_halfedge_edge(const hedge_mesh* mesh, uint32_t halfedge, uint32_t* out_edge);
/** One outgoing half-edge of the vertex (a boundary one if the vertex is on a boundary);
 *  HEDGE_INVALID_INDEX for an isolated vertex. */
HEDGE_API hedge_status hedge_vertex_halfedge(const hedge_mesh* mesh, uint32_t vertex, uint32_t* out_halfedge);
/** The face's half-edge: the face's corners start at its target vertex. */
HEDGE_API hedge_status hedge_face_halfedge(const hedge_mesh* mesh, uint32_t face, uint32_t* out_halfedge);
/** Half-edge i (0 or 1, else HEDGE_ERROR_INVALID_ARGUMENT) of the edge: edge * 2 + i. */
HEDGE_API hedge_status hedge_edge_halfedge(const hedge_mesh* mesh, uint32_t edge, uint32_t i,
                                           uint32_t* out_halfedge);

/** True if the vertex is on a boundary or isolated. */
HEDGE_API hedge_status hedge_vertex_is_boundary(const hedge_mesh* mesh, uint32_t vertex,
                                                int32_t* out_boundary);
/** True if the half-edge has no face. */
HEDGE_API hedge_status hedge_halfedge_is_boundary(const hedge_mesh* mesh, uint32_t halfedge,
                                                  int32_t* out_boundary);
/** True if either half-edge of the edge has no face. */
HEDGE_API hedge_status hedge_edge_is_boundary(const hedge_mesh* mesh, uint32_t edge, int32_t* out_boundary);
/** True if any edge of the face is on a boundary. O(face degree). */
HEDGE_API hedge_status hedge_face_is_boundary(const hedge_mesh* mesh, uint32_t face, int32_t* out_boundary);

/** Number of edges at the vertex. O(valence). */
HEDGE_API hedge_status hedge_vertex_valence(const hedge_mesh* mesh, uint32_t vertex, uint32_t* out_valence);
/** Number of corners of the face. O(face degree). */
HEDGE_API hedge_status hedge_face_valence(const hedge_mesh* mesh, uint32_t face, uint32_t* out_valence);
/** The half-edge from vertex `from` to vertex `to`, or HEDGE_INVALID_INDEX (with HEDGE_OK) when no
 *  edge joins them. O(valence). */
HEDGE_API hedge_status hedge_mesh_find_halfedge(const hedge_mesh* mesh, uint32_t from, uint32_t to,
                                                uint32_t* out_halfedge);

/** Deletion flags. These accept deleted elements (only an index out of range is a bad handle). */
HEDGE_API hedge_status hedge_vertex_is_deleted(const hedge_mesh* mesh, uint32_t vertex, int32_t* out_deleted);
HEDGE_API hedge_status hedge_halfedge_is_deleted(const hedge_mesh* mesh, uint32_t halfedge,
                                                 int32_t* out_deleted);
HEDGE_API hedge_status hedge_edge_is_deleted(const hedge_mesh* mesh, uint32_t edge, int32_t* out_deleted);
HEDGE_API hedge_status hedge_face_is_deleted(const hedge_mesh* mesh, uint32_t face, int32_t* out_deleted);

/* One-rings and face loops, into caller buffers (see "Caller buffers" above). The one-ring of a
 * vertex is clockwise, starting at hedge_vertex_halfedge() (at the boundary gap for a boundary
 * vertex); an isolated vertex has an empty one-ring. O(valence) or O(face degree). */

/** Outgoing half-edges of the vertex. */
HEDGE_API hedge_status hedge_vertex_halfedges(const hedge_mesh* mesh, uint32_t vertex, uint32_t* buffer,
                                              uint32_t capacity, uint32_t* out_count);
/** Neighbour vertices (the targets of the outgoing half-edges, same order). */
HEDGE_API hedge_status hedge_vertex_vertices(const hedge_mesh* mesh, uint32_t vertex, uint32_t* buffer,
                                             uint32_t capacity, uint32_t* out_count);
/** Incident faces (boundary gaps skipped). */
HEDGE_API hedge_status hedge_vertex_faces(const hedge_mesh* mesh, uint32_t vertex, uint32_t* buffer,
                                          uint32_t capacity, uint32_t* out_count);
/** Corners of the face in order (counter-clockwise for a CCW face), starting at the target of
 *  hedge_face_halfedge(). */
HEDGE_API hedge_status hedge_face_vertices(const hedge_mesh* mesh, uint32_t face, uint32_t* buffer,
                                           uint32_t capacity, uint32_t* out_count);
/** Half-edges of the face in order, starting at hedge_face_halfedge(); the i-th enters the i-th
 *  corner of hedge_face_vertices(). */
HEDGE_API hedge_status hedge_face_halfedges(const hedge_mesh* mesh, uint32_t face, uint32_t* buffer,
                                            uint32_t capacity, uint32_t* out_count);

/* ============================================================================================ */
/* Local operations (hedge/core/operations.h) and the edits of whole regions beside them        */
/* (hedge/algorithms/: fill_hole.h, split_all_faces.h, detach_faces.h)                          */
/* ============================================================================================ */
/* Each edit has a predicate hedge_can_*(..., int32_t* out_ok). An edit its predicate refuses
 * returns HEDGE_ERROR_REFUSED and leaves the mesh exactly as it was; hedge_last_refusal() then says
 * why. Element handles are checked before the predicate (HEDGE_ERROR_BAD_HANDLE). Deleted elements are left
 * in their slots (flagged) until hedge_mesh_garbage_collection(). Render objects of the mesh see every edit
 * at their next sync. Points are finite x, y, z (else HEDGE_ERROR_INVALID_ARGUMENT). */

/** True if the edge can be split (it is live). O(1). */
HEDGE_API hedge_status hedge_can_split_edge(const hedge_mesh* mesh, uint32_t edge, int32_t* out_ok);
/** Inserts a vertex at (x, y, z) on the edge; triangles on either side are split in two.
 *  Half-edge 2 x edge then runs from the edge's first vertex to the new vertex.
 *  \param out_vertex the new vertex. */
HEDGE_API hedge_status hedge_split_edge(hedge_mesh* mesh, uint32_t edge, float x, float y, float z,
                                        uint32_t* out_vertex);

/** True if collapsing the half-edge keeps the mesh a valid manifold (link condition, no valence
 *  below 3 left, no tetrahedron collapsed, ...). O(valence). */
HEDGE_API hedge_status hedge_can_collapse(const hedge_mesh* mesh, uint32_t halfedge, int32_t* out_ok);
/** Merges the half-edge's from-vertex into its to-vertex, which survives and keeps its position.
 *  \param out_vertex the surviving vertex. */
HEDGE_API hedge_status hedge_collapse(hedge_mesh* mesh, uint32_t halfedge, uint32_t* out_vertex);

/** True if the edge is interior between two triangles and can be turned. O(valence). */
HEDGE_API hedge_status hedge_can_flip(const hedge_mesh* mesh, uint32_t edge, int32_t* out_ok);
/** Turns the edge to join the two opposite corners of its triangles (the edge keeps its index). */
HEDGE_API hedge_status hedge_flip(hedge_mesh* mesh, uint32_t edge);

/** True if the face can be split at a point (it is live). O(1). */
HEDGE_API hedge_status hedge_can_split_face(const hedge_mesh* mesh, uint32_t face, int32_t* out_ok);
/** Inserts a vertex at (x, y, z) into the face and joins it to every corner (an n-gon becomes n
 *  triangles). \param out_vertex the new vertex. */
HEDGE_API hedge_status hedge_split_face(hedge_mesh* mesh, uint32_t face, float x, float y, float z,
                                        uint32_t* out_vertex);

/** True if the face of halfedge0 and halfedge1 can be cut along a new edge from the target of
 *  halfedge0 to the target of halfedge1: both in the same live face, targets not adjacent in it and
 *  not joined by an edge yet. */
HEDGE_API hedge_status hedge_can_cut_face(const hedge_mesh* mesh, uint32_t halfedge0, uint32_t halfedge1,
                                          int32_t* out_ok);
/** Cuts the face in two along that new edge (a diagonal; no vertex is added).
 *  \param out_halfedge the new half-edge from the target of halfedge0 to the target of halfedge1. */
HEDGE_API hedge_status hedge_cut_face(hedge_mesh* mesh, uint32_t halfedge0, uint32_t halfedge1,
                                      uint32_t* out_halfedge);

/** Splits every live face at its centroid. Never refused.
 *  \param buffer optional (NULL): receives the new vertices, one per face, in face order.
 *  \param capacity entries in buffer; when buffer is not NULL it must be at least the number of
 *         live faces (else HEDGE_ERROR_BUFFER_TOO_SMALL and nothing is changed).
 *  \param out_count the number of new vertices (the number of live faces). */
HEDGE_API hedge_status hedge_mesh_split_all_faces(hedge_mesh* mesh, uint32_t* buffer, uint32_t capacity,
                                                  uint32_t* out_count);

/** True if a face with these corners (count vertices, counter-clockwise) can be added while every
 *  vertex and edge stays manifold. O(count x valence). */
HEDGE_API hedge_status hedge_can_add_face(const hedge_mesh* mesh, const uint32_t* vertices, uint32_t count,
                                          int32_t* out_ok);
/** Adds the face. \param out_face the new face. */
HEDGE_API hedge_status hedge_add_face(hedge_mesh* mesh, const uint32_t* vertices, uint32_t count,
                                      uint32_t* out_face);
/** Adds the face with its attributes: texture coordinates per corner and a submesh (the material
 *  slot an engine draws it with). Everything is checked before the mesh changes; a bad attribute is
 *  HEDGE_ERROR_INVALID_ARGUMENT, a refused face HEDGE_ERROR_REFUSED, and either leaves the mesh as
 *  it was.
 *  \param texcoords optional (NULL): u, v per corner (2 x count floats, finite), written into the
 *         corner property "h:texcoord", which is added ((0, 0) at every other corner) when the mesh
 *         has none. A mesh that keeps texcoords per vertex ("v:texcoord") takes none.
 *  \param submesh the face's submesh in [0, 65535], written into the face property "f:submesh"
 *         (added, 0 for every other face, when the mesh has none); -1 leaves the default, 0.
 *  \param out_face the new face. */
HEDGE_API hedge_status hedge_add_face_with_attributes(hedge_mesh* mesh, const uint32_t* vertices,
                                                      uint32_t count, const float* texcoords, int32_t submesh,
                                                      uint32_t* out_face);

/** True if removing the face leaves every vertex manifold. O(face degree). */
HEDGE_API hedge_status hedge_can_remove_face(const hedge_mesh* mesh, uint32_t face, int32_t* out_ok);
/** Removes the face; edges and vertices it leaves unused are removed too. */
HEDGE_API hedge_status hedge_remove_face(hedge_mesh* mesh, uint32_t face);

/** True if removing the vertex with its faces leaves every other vertex manifold. O(valence^2). */
HEDGE_API hedge_status hedge_can_remove_vertex(const hedge_mesh* mesh, uint32_t vertex, int32_t* out_ok);
/** Removes the vertex, its faces and whatever they leave unused. */
HEDGE_API hedge_status hedge_remove_vertex(hedge_mesh* mesh, uint32_t vertex);

/** True if the half-edge is a boundary half-edge whose loop has at least 3 edges. O(loop length). */
HEDGE_API hedge_status hedge_can_fill_hole(const hedge_mesh* mesh, uint32_t halfedge, int32_t* out_ok);
/** Fills the boundary loop of the half-edge with triangles (shortest diagonals first; a rest that
 *  cannot be cut stays one polygon). O(loop length^2).
 *  \param buffer optional (NULL): receives the new faces.
 *  \param capacity when buffer is not NULL it must be at least the loop length - 2, the most faces
 *         a fill can make (else HEDGE_ERROR_BUFFER_TOO_SMALL with *out_count = loop length - 2,
 *         and nothing is changed).
 *  \param out_count the number of new faces. */
HEDGE_API hedge_status hedge_fill_hole(hedge_mesh* mesh, uint32_t halfedge, uint32_t* buffer,
                                       uint32_t capacity, uint32_t* out_count);

/** Moves the faces out of the mesh into a new mesh with all their properties; vertices the removal
 *  leaves pinched are split so both meshes stay manifold. Repeated faces are ignored.
 *  \param faces the faces to detach (live faces), count of them (0 gives an empty new mesh).
 *  \param out_vertex_origin optional (NULL): receives new-mesh vertex -> source-mesh vertex.
 *  \param origin_capacity when out_vertex_origin is not NULL it must be at least the total number of
 *         corners of the (distinct) faces, an upper bound of the new mesh's vertices (else
 *         HEDGE_ERROR_BUFFER_TOO_SMALL with *out_origin_count = that bound, nothing changed).
 *  \param out_origin_count optional (NULL) when out_vertex_origin is NULL: the number of vertices
 *         of the new mesh.
 *  \param out_mesh the new mesh; destroy it with hedge_mesh_destroy(). */
HEDGE_API hedge_status hedge_detach_faces(hedge_mesh* mesh, const uint32_t* faces, uint32_t count,
                                          uint32_t* out_vertex_origin, uint32_t origin_capacity,
                                          uint32_t* out_origin_count, hedge_mesh** out_mesh);

/** Removes deleted elements and compacts every array; element indices change. Each map is
 *  optional (NULL) and receives old index -> new index (HEDGE_INVALID_INDEX for a removed element);
 *  its capacity must be at least the slot count of its kind before the call (hedge_mesh_counts():
 *  vertex_slots, halfedge_slots, edge_slots, face_slots), else HEDGE_ERROR_BUFFER_TOO_SMALL and
 *  nothing is changed; after HEDGE_ERROR_OUT_OF_MEMORY too. Render objects of the mesh rebuild at
 *  their next sync. O(#elements). */
HEDGE_API hedge_status hedge_mesh_garbage_collection(hedge_mesh* mesh, uint32_t* vertex_map,
                                                     uint32_t vertex_capacity, uint32_t* halfedge_map,
                                                     uint32_t halfedge_capacity, uint32_t* edge_map,
                                                     uint32_t edge_capacity, uint32_t* face_map,
                                                     uint32_t face_capacity);

/* ============================================================================================ */
/* Geometry and normals (hedge/algorithms/geometry.h, normals.h)                                */
/* ============================================================================================ */

/** Measures of the whole mesh. Layout (48 bytes): area @0, volume @8 (double), closed @16, empty @20
 *  (int32_t), box_min @24, box_max @36 (3 floats each). */
typedef struct hedge_geometry {
  double area;      /**< the sum of the live faces' areas */
  double volume;    /**< signed enclosed volume (positive for outward faces); NaN when not closed */
  int32_t closed;   /**< 1 if the mesh has no boundary half-edge */
  int32_t empty;    /**< 1 if the mesh has no vertex (then the box is zero) */
  float box_min[3]; /**< the axis-aligned bounding box of the live vertices */
  float box_max[3];
} hedge_geometry;

HEDGE_API hedge_status hedge_mesh_geometry(const hedge_mesh* mesh, hedge_geometry* out_geometry);
/** The unit normal of a live face (Newell's; zero for a degenerate face). out_xyz receives 3 floats. */
HEDGE_API hedge_status hedge_face_normal(const hedge_mesh* mesh, uint32_t face, float* out_xyz);
HEDGE_API hedge_status hedge_face_area(const hedge_mesh* mesh, uint32_t face, double* out_area);

/** How the faces around a vertex are weighted in its normal. */
typedef enum hedge_normal_weighting {
  HEDGE_WEIGHTING_AREA = 0,   /**< by face area */
  HEDGE_WEIGHTING_ANGLE = 1,  /**< by the face's angle at the vertex: independent of the tessellation */
  HEDGE_WEIGHTING_UNIFORM = 2 /**< every face alike */
} hedge_normal_weighting;

/** Computes unit vertex normals into the mesh's vertex normals ("v:normal"), which render objects
 *  made afterwards with HEDGE_NORMALS_ATTRIBUTE (or AUTOMATIC) use. Render objects that exist see
 *  the change at their next sync if they read attribute normals. */
HEDGE_API hedge_status hedge_mesh_compute_vertex_normals(hedge_mesh* mesh, int32_t weighting);
/** Computes corner normals ("h:normal"): around each vertex, the faces between boundary gaps and
 *  edges sharper than crease_degrees (0..180) share one normal; 0 gives flat shading, 180 smooth.
 *  Render objects made afterwards with HEDGE_NORMALS_ATTRIBUTE split their vertices along the
 *  creases. A crease angle outside 0..180 or NaN: HEDGE_ERROR_INVALID_ARGUMENT. */
HEDGE_API hedge_status hedge_mesh_compute_corner_normals(hedge_mesh* mesh, double crease_degrees,
                                                         int32_t weighting);
/** Copies the vertex normals, 3 floats per vertex slot (*out_count floats, 3 x vertex_slots).
 *  Without computed or loaded vertex normals: HEDGE_ERROR_INVALID_ARGUMENT. */
HEDGE_API hedge_status hedge_mesh_copy_vertex_normals(const hedge_mesh* mesh, float* buffer,
                                                      uint64_t capacity, uint64_t* out_count);
/** Copies the corner normals, 3 floats per half-edge slot, for the corner of the half-edge's face at
 *  its target vertex (zero on boundary half-edges); *out_count floats, 3 x halfedge_slots. Without
 *  corner normals: HEDGE_ERROR_INVALID_ARGUMENT. */
HEDGE_API hedge_status hedge_mesh_copy_corner_normals(const hedge_mesh* mesh, float* buffer,
                                                      uint64_t capacity, uint64_t* out_count);
/** The sampled symmetric Hausdorff distance between the surfaces of a and b
 *  (hedge/algorithms/distance.h): each surface's vertices plus `samples` seeded, area-proportional
 *  points on its faces, each measured exactly against the other surface; O((V + samples) log F).
 *  out_mean (optional, NULL) gets the mean distance over all points. A mesh without faces or with a
 *  non-finite position: HEDGE_ERROR_INVALID_ARGUMENT. */
HEDGE_API hedge_status hedge_mesh_hausdorff(const hedge_mesh* a, const hedge_mesh* b, uint64_t samples,
                                            uint64_t seed, double* out_distance, double* out_mean);

/* ============================================================================================ */
/* Smoothing (hedge/algorithms/smooth.h)                                                        */
/* ============================================================================================ */

typedef enum hedge_smooth_method {
  HEDGE_SMOOTH_UNIFORM = 0,   /**< the average of the neighbours */
  HEDGE_SMOOTH_TAUBIN = 1,    /**< lambda|mu steps: removes noise without shrinking */
  HEDGE_SMOOTH_COTANGENT = 2, /**< cotangent weights (triangle meshes only) */
  HEDGE_SMOOTH_IMPLICIT = 3   /**< backward Euler steps of the cotangent flow; lambda is the time step */
} hedge_smooth_method;

/** Layout (32 bytes): method @0, iterations @4 (int32_t), lambda @8, mu @16 (double), fix_boundary
 *  @24, reserved @28 (int32_t). */
typedef struct hedge_smooth_options {
  int32_t method;       /**< HEDGE_SMOOTH_* */
  int32_t iterations;   /**< 0..100000 */
  double lambda;        /**< the step toward the average, in (0, 1]; implicit: the time step (> 0) */
  double mu;            /**< Taubin's inflating step, in [-1, -lambda) */
  int32_t fix_boundary; /**< 1: boundary vertices stay; 0: they move along the boundary */
  int32_t reserved;     /**< 0 */
} hedge_smooth_options;

/** Fills *out_options with the defaults: uniform, 10 iterations, lambda 0.5, mu -0.53, boundary fixed. */
HEDGE_API hedge_status hedge_smooth_options_default(hedge_smooth_options* out_options);
/** Smooths the positions of the live vertices (render objects see the moves at their next sync).
 *  \param options NULL for the defaults.
 *  \param mask optional (NULL with mask_count 0): one byte per vertex slot; only vertices with a
 *         nonzero byte move.
 *  Options out of range, a mask of another size, or cotangent weights on a mesh with a face that is
 *  not a triangle: HEDGE_ERROR_INVALID_ARGUMENT, and the mesh is unchanged. */
HEDGE_API hedge_status hedge_mesh_smooth(hedge_mesh* mesh, const hedge_smooth_options* options,
                                         const uint8_t* mask, uint32_t mask_count);

/* ============================================================================================ */
/* Decimation (hedge/algorithms/decimate.h)                                                     */
/* ============================================================================================ */

/** Layout (80 bytes): target_vertices @0, target_faces @8 (uint64_t), max_error @16,
 *  boundary_weight @24, feature_angle_degrees @32, feature_weight @40, attribute_weight @48,
 *  max_normal_change_degrees @56 (double), keep_boundary @64, keep_seams @68,
 *  relax_normal_change @72, reserved @76 (int32_t). */
typedef struct hedge_decimate_options {
  uint64_t target_vertices; /**< stop at this many vertices (0: no vertex target) */
  uint64_t target_faces;    /**< stop at this many faces (0: no face target) */
  double
      max_error; /**< stop before a collapse that moves the surface farther (model units); INFINITY: none */
  double boundary_weight;           /**< weight of the planes that keep open boundaries in place (0: none) */
  double feature_angle_degrees;     /**< edges with a larger dihedral angle (or "e:crease") are features; 180:
                                       crease edges only */
  double feature_weight;            /**< weight of the planes that keep feature edges (0: none) */
  double attribute_weight;          /**< > 0: texture distortion ("h:texcoord") enters the error */
  double max_normal_change_degrees; /**< refuse collapses that turn a face more than this, in (0, 180] */
  int32_t keep_boundary;            /**< 1: boundary vertices never move and are never removed */
  int32_t keep_seams;               /**< 1: UV seams are not collapsed across or broken */
  int32_t relax_normal_change; /**< 1: should max_normal_change_degrees (below 90) alone stop the run short
                                  of its target, it is raised to 90 for the rest; 0: it holds to the end */
  int32_t reserved;            /**< 0 */
} hedge_decimate_options;

/** Why hedge_mesh_decimate() stopped (hedge_decimate_result.stop; DecimateStop in order). */
typedef enum hedge_decimate_stop {
  HEDGE_DECIMATE_TARGET_REACHED = 0, /**< the vertex and face targets are met */
  HEDGE_DECIMATE_ERROR_BOUND = 1,    /**< every collapse left would exceed max_error */
  HEDGE_DECIMATE_NO_LEGAL_COLLAPSE =
      2 /**< each collapse left is refused by a check (counted), or none is left */
} hedge_decimate_stop;

/** Layout (64 bytes): vertices @0, faces @8, collapses @16 (uint64_t), max_error @24 (double),
 *  stop @32, reserved @36 (int32_t), refused_topology @40, refused_normal @48, refused_shape @56
 *  (uint64_t). */
typedef struct hedge_decimate_result {
  uint64_t vertices;         /**< live vertices left */
  uint64_t faces;            /**< live faces left */
  uint64_t collapses;        /**< edge collapses done */
  double max_error;          /**< the largest error (a distance) of a collapse done, 0 if none */
  int32_t stop;              /**< hedge_decimate_stop: why it stopped */
  int32_t reserved;          /**< 0 */
  uint64_t refused_topology; /**< collapse attempts refused by the link condition (an edge retried in a
                                later pass counts again) */
  uint64_t refused_normal;   /**< ... because a face would turn too far, turn over or lose its area */
  uint64_t refused_shape;    /**< ... because a new face would be a sliver */
} hedge_decimate_result;

/** Fills *out_options with the defaults: no target, no error limit (INFINITY), boundary weight 1,
 *  feature angle 60 and weight 1, no attribute weight, normal change 60 degrees relaxed to 90 when
 *  it alone stops the run, boundary free, seams kept. */
HEDGE_API hedge_status hedge_decimate_options_default(hedge_decimate_options* out_options);
/** Decimates a triangle mesh by quadric-ranked edge collapses until both targets that are nonzero
 *  are met, the next collapse's error would exceed max_error, or no legal collapse is left (see
 *  hedge/algorithms/decimate.h). Garbage is collected at the end, so every index may change, as after
 *  hedge_mesh_garbage_collection(); render objects of the mesh rebuild at their next sync.
 *  \param options NULL for the defaults (which have no target: as much as the error limit allows).
 *  \param out_result optional (NULL).
 *  A face that is not a triangle, a position that is not finite, a non-manifold vertex, or options
 *  out of range: HEDGE_ERROR_INVALID_ARGUMENT, and the mesh is unchanged; so it is after
 *  HEDGE_ERROR_OUT_OF_MEMORY, however far the collapses had gone. */
HEDGE_API hedge_status hedge_mesh_decimate(hedge_mesh* mesh, const hedge_decimate_options* options,
                                           hedge_decimate_result* out_result);

/* ============================================================================================ */
/* Fracture (hedge/algorithms/fracture.h; docs/fracture.md)                                     */
/* ============================================================================================ */

typedef enum hedge_fracture_preset {
  HEDGE_FRACTURE_GLASS = 0, /**< many small shards (40 break points) */
  HEDGE_FRACTURE_STONE = 1, /**< few large chunks (7) */
  HEDGE_FRACTURE_WOOD = 2,  /**< splinters along the grain, x by default (18) */
  HEDGE_FRACTURE_ICE = 3    /**< 26 break points */
} hedge_fracture_preset;

/** The units of hedge_fracture_options.radius (hedge::FractureUnits). */
typedef enum hedge_fracture_units {
  HEDGE_FRACTURE_UNITS_EDGE_LENGTHS = 0,     /**< mean edge lengths of the impact face */
  HEDGE_FRACTURE_UNITS_MODEL = 1,            /**< model units */
  HEDGE_FRACTURE_UNITS_DIAGONAL_FRACTION = 2 /**< a fraction of the mesh's bounding-box diagonal */
} hedge_fracture_units;

/** Most rings a hedge_fracture_options holds. */
#define HEDGE_FRACTURE_MAX_RINGS 16

/** One ring of break points. Layout (24 bytes): spacing @0, jitter @8 (double), points @16,
 *  reserved @20 (uint32_t). */
typedef struct hedge_fracture_ring {
  double spacing;    /**< distance from the previous ring (the first: from the impact), > 0, in
                          proportion only: the spacings are scaled so that the outer ring lies at
                          the radius */
  double jitter;     /**< in [0, 1]: how far points stray from even angles and the ring's radius */
  uint32_t points;   /**< break points on the ring, at most 100000 (10000 in all rings) */
  uint32_t reserved; /**< 0 */
} hedge_fracture_ring;

/** Layout (488 bytes): rings @0 (16 x 24), ring_count @384 (uint32_t), units @388 (int32_t),
 *  grain @392 (3 floats), reserved @404 (uint32_t), grain_stretch @408, refine_edge @416 (double),
 *  seed @424 (uint64_t), thickness @432, density @440, tolerance @448 (double), hulls @456,
 *  inner_submesh @460 (int32_t), relative_thickness @464, radius @472, shell_thickness @480
 *  (double). units took the place of the former absolute (0: edge lengths, 1: model units, as
 *  absolute meant). */
typedef struct hedge_fracture_options {
  hedge_fracture_ring rings[HEDGE_FRACTURE_MAX_RINGS]; /**< the material's rings, innermost first */
  uint32_t ring_count;                                 /**< rings used, 0..HEDGE_FRACTURE_MAX_RINGS */
  int32_t units;         /**< hedge_fracture_units of radius; the presets: diagonal fraction */
  float grain[3];        /**< grain direction, nonzero when grain_stretch > 1 */
  uint32_t reserved;     /**< 0 */
  double grain_stretch;  /**< >= 1: cells this many times longer along the grain */
  double refine_edge;    /**< longest edge left in the broken area (units of the spacings), > 0 */
  uint64_t seed;         /**< seed of the break points */
  double thickness;      /**< > 0: each shard extruded into a closed solid this thick */
  double density;        /**< mass per unit volume, > 0 */
  double tolerance;      /**< largest distance from the impact to the surface; 0: 1e-3 of the nearest face's
                            longest edge */
  int32_t hulls;         /**< 1: compute each shard's convex hull */
  int32_t inner_submesh; /**< with a thickness, the face property "f:submesh" of the faces the solid
                            adds (back, side walls); -1: one more than the mesh's largest, or 1 */
  double relative_thickness; /**< in [0, 1]; > 0 (thickness 0): the thickness as this fraction of
                                the break radius in model units */
  double radius;             /**< the break radius (the outer ring's) in units, > 0; the presets:
                                0.13 (glass), 0.14 (stone), 0.11 (wood, ice) of the diagonal */
  double shell_thickness;    /**< >= 0: an open shard's mass properties are those of a thin shell
                                this thick (model units); 0: 0.05 of the break radius in model units */
} hedge_fracture_options;

/** One shard. Layout (264 bytes): mesh @0, hull @8 (handles), centroid @16 (3 doubles), area @40,
 *  volume @48, mass @56 (double), centre_of_mass @64 (3 doubles), inertia @88 (9 doubles,
 *  row-major, about the centre of mass), closed @160, hull_dimension @164 (int32_t),
 *  principal_moments @168 (3 doubles), principal_axes @192 (9 doubles). */
typedef struct hedge_fracture_shard {
  hedge_mesh* mesh;            /**< the shard, a new mesh; destroy it with hedge_mesh_destroy() */
  hedge_mesh* hull;            /**< its convex hull, a new mesh, or NULL (hulls off, or no volume) */
  double centroid[3];          /**< area-weighted centroid of the broken faces */
  double area;                 /**< area of the broken faces */
  double volume;               /**< volume when closed; when open, of the thin shell (area x the shell
                                  thickness, see hedge_fracture_options.shell_thickness) */
  double mass;                 /**< at the density, of the solid when closed, of the shell when open;
                                  0 only for a shard without area (skip it) */
  double centre_of_mass[3];    /**< of the solid or the shell */
  double inertia[9];           /**< inertia tensor about the centre of mass, of the solid or shell */
  int32_t closed;              /**< 1: the shard's mesh has no boundary */
  int32_t hull_dimension;      /**< 0 empty, 1 point, 2 segment, 3 flat (a thin prism), 4 solid */
  double principal_moments[3]; /**< the eigenvalues of inertia, ascending (0 with mass 0) */
  double principal_axes[9];    /**< row i: the unit axis of principal_moments[i]; a right-handed frame
                                  (row 2 = row 0 x row 1), so the matrix whose columns they are is a
                                  rotation R with inertia = R diag(moments) R^T; 0 with mass 0 */
} hedge_fracture_shard;

/** Fills *out_options with a preset (hedge_fracture_preset): its rings, its break radius as a
 *  fraction of the mesh's bounding-box diagonal (units HEDGE_FRACTURE_UNITS_DIAGONAL_FRACTION),
 *  seed 0, no thickness, density 1, shell_thickness 0 (automatic), tolerance 0 (automatic), hulls
 *  on and inner_submesh -1 (automatic). An unknown preset:
 *  HEDGE_ERROR_INVALID_ARGUMENT. */
HEDGE_API hedge_status hedge_fracture_options_default(int32_t preset, hedge_fracture_options* out_options);
/** Puts the material of *options into model units with its outer ring radius model units from the
 *  impact (fracture_material_at_radius): units HEDGE_FRACTURE_UNITS_MODEL, radius = radius, and
 *  every used ring's spacing and refine_edge scaled by radius / (the spacings summed), so they read
 *  in model units too. A radius that is not finite and positive, no ring, or a spacing that is not
 *  finite and positive: HEDGE_ERROR_INVALID_ARGUMENT naming it, *options unchanged. */
HEDGE_API hedge_status hedge_fracture_options_at_radius(hedge_fracture_options* options, double radius);
/** Breaks the mesh at the impact (x, y, z) into shards (see hedge/algorithms/fracture.h): the
 *  broken faces leave the mesh, each shard is a new mesh with its properties, its area, centroid,
 *  mass properties when closed and its convex hull. The mesh's render objects update at their next
 *  sync. The same mesh, impact, options and seed give the same shards, bit for bit.
 *  \param options NULL for the glass preset.
 *  \param out_shards receives the shards, in the order of their break points.
 *  \param capacity at least the options' total break points (the most shards there can be), else
 *         HEDGE_ERROR_BUFFER_TOO_SMALL with *out_count = that number, and nothing is changed.
 *  \param out_count the number of shards.
 *  No face within the tolerance, a non-finite impact, a single face with no neighbour at the impact,
 *  or options out of range: HEDGE_ERROR_INVALID_ARGUMENT naming what, and the mesh is unchanged.
 *  Options out of range include more than 100000 points on a ring, more than 10000 break points
 *  in all rings, and a thickness beyond 10 times the diagonal of the mesh's bounding box (the
 *  limits of fracture.h); they are checked before the capacity.
 *  The impact is located through the mesh's picking tree (see Picking below), built by the first
 *  strike or picking call if there is none and kept up to date across strikes, so a strike costs
 *  the broken area, whatever the size of the mesh: only the first one on a mesh pays for the tree,
 *  O(n log n) for n faces (call hedge_mesh_bvh_update() after loading to pay it then). The tree
 *  stays valid after the strike for the next strike and the picking calls. */
HEDGE_API hedge_status hedge_mesh_fracture(hedge_mesh* mesh, float x, float y, float z,
                                           const hedge_fracture_options* options,
                                           hedge_fracture_shard* out_shards, uint32_t capacity,
                                           uint32_t* out_count);
/** Copies each face slot's submesh, the face property "f:submesh" (int32_t), deleted slots
 *  included: 0 for every slot when the mesh has no such property (or one of another type). A
 *  shard with a thickness has it, its back and side walls at the options' inner_submesh.
 *  *out_count receives face_slots; a buffer smaller: HEDGE_ERROR_BUFFER_TOO_SMALL. */
HEDGE_API hedge_status hedge_mesh_copy_face_submeshes(const hedge_mesh* mesh, int32_t* buffer,
                                                      uint64_t capacity, uint64_t* out_count);

/* ============================================================================================ */
/* Solid fracture (hedge/algorithms/fracture_solid.h; docs/fracture.md)                         */
/* ============================================================================================ */

/** The result of a solid fracture: its pieces and bonds, read through the hedge_solid_fracture_*
 *  calls below; destroy it with hedge_solid_fracture_destroy(). */
typedef struct hedge_solid_fracture hedge_solid_fracture;

/** Names the remaining object (the struck mesh) as the end b of a bond. */
#define HEDGE_SOLID_REMAINING 0xFFFFFFFFu

/** Layout (440 bytes): rings @0 (16 x hedge_fracture_ring, 24 bytes each), ring_count @384
 *  (uint32_t), hulls @388 (int32_t), radius @392, radius_fraction @400 (double), seed @408
 *  (uint64_t), density @416, tolerance @424 (double), inner_submesh @432 (int32_t), reserved @436
 *  (uint32_t). */
typedef struct hedge_solid_fracture_options {
  hedge_fracture_ring rings[HEDGE_FRACTURE_MAX_RINGS]; /**< the material's rings, innermost first; their
                                                          spacings are scaled so the outer ring lies at
                                                          the break radius */
  uint32_t ring_count;                                 /**< rings used, 1..HEDGE_FRACTURE_MAX_RINGS */
  int32_t hulls;                                       /**< 1: compute each piece's convex hull */
  double radius;          /**< the break radius in model units; 0: radius_fraction of the diagonal of the
                             mesh's bounding box */
  double radius_fraction; /**< used when radius is 0; in (0, 10] */
  uint64_t seed;          /**< seed of the break points */
  double density;         /**< mass per unit volume, > 0 */
  double tolerance;       /**< largest distance from the impact to the surface; 0: 1e-3 of the nearest
                             face's longest edge */
  int32_t inner_submesh;  /**< "f:submesh" of the cap faces; -1: one more than the mesh's largest, or 1 */
  uint32_t reserved;      /**< 0 */
} hedge_solid_fracture_options;

/** One piece. Layout (240 bytes): mesh @0, hull @8 (handles), volume @16, cap_area @24, mass @32
 *  (double), centre_of_mass @40 (3 doubles), inertia @64 (9 doubles, row-major, about the centre
 *  of mass), principal_moments @136 (3 doubles), principal_axes @160 (9 doubles), hull_dimension
 *  @232 (int32_t), reserved @236 (uint32_t). */
typedef struct hedge_solid_piece {
  hedge_mesh* mesh;            /**< the closed piece, its caps marked in "f:inner" and "f:submesh" */
  hedge_mesh* hull;            /**< its convex hull, or NULL (hulls off) */
  double volume;               /**< enclosed volume, positive */
  double cap_area;             /**< area of the cap (inner) faces */
  double mass;                 /**< at the options' density */
  double centre_of_mass[3];    /**< uniform density */
  double inertia[9];           /**< inertia tensor about the centre of mass */
  double principal_moments[3]; /**< the eigenvalues of inertia, ascending */
  double principal_axes[9];    /**< row i: the unit axis of principal_moments[i], a right-handed frame */
  int32_t hull_dimension;      /**< 0 empty, 1 point, 2 segment, 3 flat, 4 solid */
  uint32_t reserved;           /**< 0 */
} hedge_solid_piece;

/** Two pieces that touch, or a piece and the remaining object (b = HEDGE_SOLID_REMAINING), sharing
 *  `area` of cap. a < b. Layout (16 bytes): a @0, b @4 (uint32_t), area @8 (double). */
typedef struct hedge_solid_bond {
  uint32_t a;  /**< index of a piece */
  uint32_t b;  /**< index of a piece, or HEDGE_SOLID_REMAINING */
  double area; /**< shared cap area */
} hedge_solid_bond;

/** What a strike did. Layout (48 bytes): piece_count @0, bond_count @4, impact_face @8, reserved
 *  @12 (uint32_t), impact_point @16 (3 doubles), radius @40 (double). */
typedef struct hedge_solid_fracture_summary {
  uint32_t piece_count;   /**< pieces, in the order of their break points */
  uint32_t bond_count;    /**< bonds, sorted by (a, b) */
  uint32_t impact_face;   /**< the face the impact was located on, before the strike */
  uint32_t reserved;      /**< 0 */
  double impact_point[3]; /**< the impact moved onto the surface */
  double radius;          /**< the break radius used, in model units */
} hedge_solid_fracture_summary;

/** Fills *out_options with a preset's rings (hedge_fracture_preset), radius 0 and radius_fraction
 *  0.25 (a quarter of the bounding box's diagonal), seed 0, density 1, tolerance 0 (automatic),
 *  hulls on and inner_submesh -1 (automatic). An unknown preset: HEDGE_ERROR_INVALID_ARGUMENT. */
HEDGE_API hedge_status hedge_solid_fracture_options_default(int32_t preset,
                                                            hedge_solid_fracture_options* out_options);
/** Why a strike cannot be a solid fracture, as a code to check without comparing text
 *  (hedge_solid_fracture_refusal_code(); hedge::SolidRefusal in order). A code keeps its value in
 *  every later release; new refusals take new values. The C# binding names them SolidRefusal, the
 *  JS and Python APIs by the lower-case names ("open", "non_manifold", ...).
 *
 *  "auto", one rule in every binding and the CLI: a strike refused for the shape of the input,
 *  HEDGE_SOLID_REFUSAL_OPEN or HEDGE_SOLID_REFUSAL_NON_MANIFOLD, falls back to surface fracture
 *  (hedge_mesh_fracture(), which breaks such meshes); any other refusal is reported as an error. */
typedef int32_t hedge_solid_refusal;

enum {
  HEDGE_SOLID_REFUSAL_NONE = 0,         /**< not refused */
  HEDGE_SOLID_REFUSAL_OPEN = 1,         /**< the mesh is open (anywhere, or near the impact) */
  HEDGE_SOLID_REFUSAL_NON_MANIFOLD = 2, /**< a vertex near the impact joins several fans of faces */
  HEDGE_SOLID_REFUSAL_BAD_OPTION = 3,   /**< an illegal option or material */
  HEDGE_SOLID_REFUSAL_BAD_IMPACT = 4,   /**< the impact is not finite */
  HEDGE_SOLID_REFUSAL_OFF_SURFACE = 5,  /**< no face within the tolerance of the impact */
  HEDGE_SOLID_REFUSAL_NO_FACE = 6,      /**< the mesh has no face */
  HEDGE_SOLID_REFUSAL_BAD_RADIUS = 7,   /**< the break radius is not positive (a mesh of zero size) */
  HEDGE_SOLID_REFUSAL_FOREIGN_TREE = 8, /**< (C++ only: a FaceBvh of another mesh) */
  /** How many codes there are (one past the largest). */
  HEDGE_SOLID_REFUSAL_COUNT = 9
};

/** Why the mesh cannot be solid-fractured at the impact (x, y, z) with these options (NULL: the
 *  stone preset), as a text with its NUL, or "" when it can: a non-finite impact, no face within
 *  the tolerance, a mesh open anywhere or non-manifold near the impact, or an illegal option. It
 *  checks through the mesh's picking tree, which keeps whether the mesh is closed until the mesh
 *  changes, and changes nothing. hedge_solid_fracture_refusal_code() gives the same refusal as a
 *  code, for "auto" (see hedge_solid_refusal). *out_size receives the bytes needed; a smaller
 *  buffer: HEDGE_ERROR_BUFFER_TOO_SMALL. */
HEDGE_API hedge_status hedge_solid_fracture_refusal(hedge_mesh* mesh, float x, float y, float z,
                                                    const hedge_solid_fracture_options* options, char* buffer,
                                                    uint32_t capacity, uint32_t* out_size);
/** The code of hedge_solid_fracture_refusal()'s answer for the same arguments:
 *  HEDGE_SOLID_REFUSAL_NONE when the strike can be made. "auto" strikes with hedge_mesh_fracture()
 *  for HEDGE_SOLID_REFUSAL_OPEN and _NON_MANIFOLD, and reports any other code as an error. */
HEDGE_API hedge_status hedge_solid_fracture_refusal_code(hedge_mesh* mesh, float x, float y, float z,
                                                         const hedge_solid_fracture_options* options,
                                                         hedge_solid_refusal* out_code);
/** Breaks the closed mesh at the impact (x, y, z) into closed pieces (see
 *  hedge/algorithms/fracture_solid.h): the mesh becomes the remaining object, closed, its new cap
 *  faces marked inner. The pieces, their mass properties, hulls and bonds are in *out_result, even
 *  when there are none (no cell held part of the object, the mesh unchanged). Each piece's mesh
 *  and hull are new meshes that belong to the caller from this call on: destroy them with
 *  hedge_mesh_destroy(), before or after the result. The same mesh, impact, options and seed give
 *  the same pieces, bit for bit. The impact is located, and the region found, through the mesh's
 *  picking tree, kept up to date for the next strike (as hedge_mesh_fracture()).
 *  \param options NULL for the stone preset.
 *  What hedge_solid_fracture_refusal() names, or a strike whose pieces could not be made closed:
 *  HEDGE_ERROR_INVALID_ARGUMENT with the reason, the mesh unchanged and *out_result NULL. */
HEDGE_API hedge_status hedge_mesh_fracture_solid(hedge_mesh* mesh, float x, float y, float z,
                                                 const hedge_solid_fracture_options* options,
                                                 hedge_solid_fracture** out_result);
/** Counts, impact and radius of a strike. */
HEDGE_API hedge_status hedge_solid_fracture_get_summary(const hedge_solid_fracture* result,
                                                        hedge_solid_fracture_summary* out_summary);
/** Copies the pieces (the same mesh handles on every call). *out_count receives piece_count; a
 *  smaller buffer: HEDGE_ERROR_BUFFER_TOO_SMALL. */
HEDGE_API hedge_status hedge_solid_fracture_copy_pieces(const hedge_solid_fracture* result,
                                                        hedge_solid_piece* buffer, uint32_t capacity,
                                                        uint32_t* out_count);
/** Copies the bonds, sorted by (a, b). *out_count receives bond_count; a smaller buffer:
 *  HEDGE_ERROR_BUFFER_TOO_SMALL. */
HEDGE_API hedge_status hedge_solid_fracture_copy_bonds(const hedge_solid_fracture* result,
                                                       hedge_solid_bond* buffer, uint32_t capacity,
                                                       uint32_t* out_count);
/** Frees the result (not the pieces' meshes, which are the caller's). */
HEDGE_API hedge_status hedge_solid_fracture_destroy(hedge_solid_fracture* result);

/* ============================================================================================ */
/* Subdivision (hedge/algorithms/subdivide.h)                                                   */
/* ============================================================================================ */

typedef enum hedge_subdivision {
  HEDGE_SUBDIVISION_LOOP = 0,          /**< Loop's scheme: smooth, triangle meshes */
  HEDGE_SUBDIVISION_MIDPOINT = 1,      /**< 1-to-4 at the edge midpoints: the shape is kept */
  HEDGE_SUBDIVISION_CATMULL_CLARK = 2, /**< Catmull-Clark: any polygons, gives quads */
  HEDGE_SUBDIVISION_SQRT3 = 3,         /**< Kobbelt's sqrt(3): smooth 1-to-3 with flips, triangle meshes */
  HEDGE_SUBDIVISION_SPLIT_FACES = 4    /**< each face fanned about its centroid: any polygons, shape kept */
} hedge_subdivision;

/** Subdivides steps times (0..12): Loop and midpoint refine triangles 1-to-4, Catmull-Clark turns
 *  a face of n corners into n quads (Catmull-Clark's face points are vertex_slots + edge_slots + f),
 *  sqrt3 and split-faces turn a face of n corners into n triangles about its centroid, vertex
 *  vertex_slots + f. Every index changes, as after garbage
 *  collection: old vertex v keeps index v, the vertex of edge e is vertex_slots + e. Render objects
 *  of the mesh rebuild at their next sync. A face that is not a triangle (Loop, midpoint, sqrt3), or a
 *  result beyond 2^31 half-edges: HEDGE_ERROR_INVALID_ARGUMENT, and the mesh is unchanged. */
HEDGE_API hedge_status hedge_mesh_subdivide(hedge_mesh* mesh, int32_t scheme, int32_t steps);

/* ============================================================================================ */
/* Mirroring (hedge/algorithms/mirror.h)                                                        */
/* ============================================================================================ */

/** Mirrors the mesh in the plane x = 0 and reverses every face, so that faces keep facing out: x
 *  of positions and normals negated, each face's corners reversed with their attributes (texcoords
 *  unchanged). The rule of Unity's model importers (OBJ, FBX): a file read and then mirrored is what
 *  Unity's importer gives; mirrored again before writing, it gives the file's own space back (the
 *  call is its own inverse, bit for bit). Indices are kept; render objects of the mesh rebuild at
 *  their next sync. */
HEDGE_API hedge_status hedge_mesh_mirror_x(hedge_mesh* mesh);

/* ============================================================================================ */
/* Reordering (hedge/algorithms/reorder.h)                                                      */
/* ============================================================================================ */

typedef enum hedge_ordering {
  HEDGE_ORDERING_SPATIAL = 0,     /**< Morton curve: traversals read memory in order */
  HEDGE_ORDERING_VERTEX_CACHE = 1 /**< faces for a GPU vertex cache, vertices by first use */
} hedge_ordering;

/** Renumbers the elements in the given order (hedge_ordering), so that traversals or a GPU's
 *  vertex cache read memory in order; garbage is collected at the same time. cache_size is the
 *  vertex cache's size for HEDGE_ORDERING_VERTEX_CACHE (16 to 32; 0 means 16). The old-to-new maps
 *  are written as by hedge_mesh_garbage_collection() (each map optional, NULL). Render objects of
 *  the mesh rebuild at their next sync. An unknown ordering: HEDGE_ERROR_INVALID_ARGUMENT, and the
 *  mesh is unchanged; so it is after HEDGE_ERROR_OUT_OF_MEMORY. */
HEDGE_API hedge_status hedge_mesh_reorder(hedge_mesh* mesh, int32_t ordering, uint32_t cache_size,
                                          uint32_t* vertex_map, uint32_t vertex_capacity,
                                          uint32_t* halfedge_map, uint32_t halfedge_capacity,
                                          uint32_t* edge_map, uint32_t edge_capacity, uint32_t* face_map,
                                          uint32_t face_capacity);

/** The average cache miss ratio of drawing the faces in index order through a FIFO vertex cache of
 *  cache_size entries (0 means 16): vertex loads per triangle, 0.5 (best) to 3 (worst). */
HEDGE_API hedge_status hedge_mesh_cache_miss_ratio(const hedge_mesh* mesh, uint32_t cache_size,
                                                   double* out_ratio);

/* ============================================================================================ */
/* Files (hedge/io/io.h): OBJ, OFF, PLY, STL, glTF (.gltf, .glb), chosen by the extension       */
/* ============================================================================================ */

/** What a reader may do for a file from a stranger (hedge::ReadOptions). Layout (16 bytes):
 *  external_buffers at 0, reserved at 4, max_memory at 8. */
typedef struct hedge_read_options {
  /** glTF buffers in separate files: 1 reads them, only from the .gltf's folder and below (after
   *  `..` and symbolic links are resolved) and only regular files of the declared byteLength; 0
   *  refuses any such buffer (HEDGE_ERROR_IO). */
  int32_t external_buffers;
  int32_t reserved; /**< 0 */
  /** The most bytes a glTF reader may allocate for what the file describes, checked before it
   *  allocates; 0 for the default: 64 times the input's size plus 64 MiB. */
  uint64_t max_memory;
} hedge_read_options;

/** Fills *out_options with the defaults for reading a file by its path: external_buffers 1,
 *  max_memory 0 (the default budget). Bytes read from memory default to external_buffers 0. */
HEDGE_API hedge_status hedge_read_options_default(hedge_read_options* out_options);

/** Reads and builds a mesh.
 *  \param options NULL for the format's defaults (repair policy; exact welding for STL and glTF).
 *  \param out_report optional (NULL).
 *  \return HEDGE_ERROR_IO for an unreadable or malformed file or an unknown extension; the message
 *          is "path:line: what was expected" (text) or "path (byte N): ..." (binary). */
HEDGE_API hedge_status hedge_mesh_read(const char* path, const hedge_build_options* options,
                                       hedge_build_report* out_report, hedge_mesh** out_mesh);
/** hedge_mesh_read() with read options: read_options NULL for hedge_read_options_default(). A file
 *  over the memory budget or with a refused external buffer: HEDGE_ERROR_IO, the message naming
 *  the limit (and how to raise it) or the buffer. */
HEDGE_API hedge_status hedge_mesh_read_with(const char* path, const hedge_build_options* options,
                                            const hedge_read_options* read_options,
                                            hedge_build_report* out_report, hedge_mesh** out_mesh);
/** Reads and builds a mesh from a file's bytes in memory (an upload, an asset bundle).
 *  \param name the file's name: its extension chooses the format (.obj, .off, .ply, .stl, .gltf,
 *         .glb), and messages start with it; with external buffers on, they are looked up in its
 *         folder.
 *  \param read_options NULL for external_buffers 0 and the default memory budget.
 *  Otherwise as hedge_mesh_read_with(). */
HEDGE_API hedge_status hedge_mesh_read_memory(const void* bytes, uint64_t size, const char* name,
                                              const hedge_build_options* options,
                                              const hedge_read_options* read_options,
                                              hedge_build_report* out_report, hedge_mesh** out_mesh);
/** Writes the live faces to a file atomically (a failed write leaves the target as it was).
 *  \param binary PLY and STL: 1 binary (little endian), 0 ASCII; ignored for OBJ, OFF and glTF
 *         (.glb is binary, .gltf JSON).
 *  \param precision significant digits of ASCII coordinates; 0 for the default (9, exact round
 *         trip of every float). */
HEDGE_API hedge_status hedge_mesh_write(const hedge_mesh* mesh, const char* path, int32_t binary,
                                        int32_t precision);

/* ============================================================================================ */
/* Validation                                                                                   */
/* ============================================================================================ */

/** Checks every invariant of the mesh and keeps the list of problems in the mesh object for the
 *  two functions below. \param out_problem_count 0 when the mesh is valid. O(#elements). */
HEDGE_API hedge_status hedge_mesh_validate(hedge_mesh* mesh, uint32_t* out_problem_count);
/** The text of problem `index` (< the count) of the last hedge_mesh_validate() on this mesh, into
 *  a caller buffer; *out_size receives the bytes needed including the NUL. An index out of range:
 *  HEDGE_ERROR_INVALID_ARGUMENT. */
HEDGE_API hedge_status hedge_mesh_validation_problem(const hedge_mesh* mesh, uint32_t index, char* buffer,
                                                     uint32_t capacity, uint32_t* out_size);
/** All problems of the last hedge_mesh_validate(), joined with newlines (no trailing newline; "" when
 *  valid), into a caller buffer; *out_size receives the bytes needed including the NUL. */
HEDGE_API hedge_status hedge_mesh_validation_report(const hedge_mesh* mesh, char* buffer, uint32_t capacity,
                                                    uint32_t* out_size);

/* ============================================================================================ */
/* Picking (hedge/algorithms/locate.h): rays, nearest points, the face under a point            */
/* ============================================================================================ */
/* The mesh handle owns a bounding volume hierarchy over its live faces (hedge::FaceBvh), made by
 * the first picking call (or hedge_mesh_fracture(), which locates its impacts through the same
 * tree): O(n log n) for n faces, about 45 bytes a face. Each later picking call
 * first takes in the edits made since the previous one from the mesh's change log (FaceBvh::update:
 * a few microseconds per changed face, nothing when nothing changed; after garbage collection or
 * another renumbering it rebuilds), then answers in O(log n) expected time. While the tree exists
 * the change log keeps what was edited since the last picking call (a few bytes per edited element);
 * hedge_mesh_bvh_release() frees both. Faces are located through triangles: a polygon face through
 * the fan from its first corner, exact for convex planar polygons. Positions are floats; the
 * queries compute in double. Ties go to the smallest face index. Every query below returns HEDGE_OK
 * with *out_found 0 (and *out_hit unchanged) when nothing is found. */

/** Where a query met the surface. Layout (48 bytes): face @0, corners @4 (3 uint32_t), point @16
 *  (3 floats), barycentric @28 (3 floats), t @40, distance @44 (float). */
typedef struct hedge_surface_hit {
  uint32_t face;        /**< the face found */
  uint32_t corners[3];  /**< the fan triangle of the face the point is in; corners[0] is the face's
                             first corner, the target of hedge_face_halfedge() */
  float point[3];       /**< the point on the surface: sum of barycentric[i] x position(corners[i]) */
  float barycentric[3]; /**< weights of corners[0..2], each in [0, 1], summing to 1 */
  float t;              /**< hedge_mesh_raycast: point = origin + t x direction; 0 for the others */
  float distance;       /**< from the query's origin or point to `point` */
} hedge_surface_hit;

/** The coordinate plane of hedge_mesh_face_containing_point_2d (hedge::ProjectionPlane): the two
 *  coordinates kept; the third is dropped. */
enum {
  HEDGE_PLANE_XY = 0, /**< (x, y): drop z */
  HEDGE_PLANE_XZ = 1, /**< (x, z): drop y, the ground plane of y-up engines (Unity) */
  HEDGE_PLANE_YZ = 2  /**< (y, z): drop x */
};

/** Builds the picking tree now, or brings it up to date with the edits since the last picking
 *  call, so that the next query does not pay for it (call it after loading, or once after a batch
 *  of edits). \param out_bytes optional (NULL): heap bytes the tree holds. */
HEDGE_API hedge_status hedge_mesh_bvh_update(hedge_mesh* mesh, uint64_t* out_bytes);
/** Frees the picking tree (the next picking call or fracture builds it again). No tree: does
 *  nothing. */
HEDGE_API hedge_status hedge_mesh_bvh_release(hedge_mesh* mesh);

/** The first face hit by the ray origin + t x direction, 0 <= t <= t_max: watertight (a ray through
 *  a shared edge or vertex hits one of its faces) and two-sided (back faces are hit too).
 *  \param origin    3 floats, finite.
 *  \param direction 3 floats, finite and not zero; need not be unit length (t is in its units).
 *  \param t_max     >= 0; INFINITY for an unbounded ray.
 *
eturn HEDGE_ERROR_INVALID_ARGUMENT for a non-finite origin or direction, a zero direction, a
 *          NaN or negative t_max. */
HEDGE_API hedge_status hedge_mesh_raycast(hedge_mesh* mesh, const float* origin, const float* direction,
                                          float t_max, hedge_surface_hit* out_hit, int32_t* out_found);
/** The nearest point of the surface to a point, within max_distance of it.
 *  \param point        3 floats, finite.
 *  \param max_distance >= 0; INFINITY for no limit (a limit also makes the search cheaper).
 *
eturn HEDGE_ERROR_INVALID_ARGUMENT for a non-finite point or a NaN or negative max_distance. */
HEDGE_API hedge_status hedge_mesh_closest_point(hedge_mesh* mesh, const float* point, float max_distance,
                                                hedge_surface_hit* out_hit, int32_t* out_found);
/** The face a point on the surface lies on: the nearest face, if the point is within tolerance of it
 *  (an impact point reported by a physics engine, a point on a plate in any orientation).
 *  \param tolerance >= 0 and finite, in the mesh's units.
 *
eturn HEDGE_ERROR_INVALID_ARGUMENT for a non-finite point or a bad tolerance. */
HEDGE_API hedge_status hedge_mesh_face_containing_point(hedge_mesh* mesh, const float* point, float tolerance,
                                                        hedge_surface_hit* out_hit, int32_t* out_found);
/** 2D plates and height fields: the face whose projection onto a coordinate plane contains (u, v),
 *  boundary included; `point` is the point of that face that projects onto (u, v) (the dropped
 *  coordinate interpolated), `distance` 0. Faces seen edge-on contain nothing.
 *  \param plane HEDGE_PLANE_*: (u, v) are (x, y), (x, z) or (y, z).
 *
eturn HEDGE_ERROR_INVALID_ARGUMENT for a non-finite u or v or an unknown plane. */
HEDGE_API hedge_status hedge_mesh_face_containing_point_2d(hedge_mesh* mesh, float u, float v, int32_t plane,
                                                           hedge_surface_hit* out_hit, int32_t* out_found);

/* ============================================================================================ */
/* Render buffers (hedge/render/render_buffers.h)                                               */
/* ============================================================================================ */
/* A render object keeps engine-ready vertex and index buffers in step with its mesh: each face
 * owns fixed triangle slots, each render vertex (a mesh vertex per distinct set of corner
 * attributes: seams split vertices) a fixed vertex slot; hedge_render_buffers_sync() rewrites only what
 * the edits since the last sync touched and reports the rewritten ranges. Freed slots stay as
 * holes (degenerate triangles, unreferenced vertices) until hedge_render_buffers_compact(). */

/** Normal source (hedge::NormalSource). */
enum {
  HEDGE_NORMALS_NONE = 0, /**< no normal stream */
  /** the mesh's corner or vertex normals as they are, never recomputed (imported normals kept);
   *  none if it has none */
  HEDGE_NORMALS_ATTRIBUTE = 1,
  HEDGE_NORMALS_COMPUTED = 2, /**< area-weighted smooth vertex normals */
  /** the default: the mesh's normals if it has some, following the geometry (each sync recomputes
   *  the normals about what the edits touched into the mesh's normals, creases kept); computed
   *  normals otherwise */
  HEDGE_NORMALS_AUTOMATIC = 3
};

/** Vertex streams for hedge_render_buffers_vertex_data() and hedge_render_buffers_copy_vertex_data(). */
enum {
  /** Interleaved layout: every vertex, stride floats each. Separate layout: the positions. */
  HEDGE_STREAM_VERTICES = 0,
  HEDGE_STREAM_NORMALS = 1,   /**< separate layout only (3 floats a vertex); else empty */
  HEDGE_STREAM_TEXCOORDS = 2, /**< separate layout only (2 floats a vertex); else empty */
  HEDGE_STREAM_COLORS = 3,    /**< separate layout only (4 floats a vertex); else empty */
  /** separate layout only (4 floats a vertex: xyz and the handedness w); else empty */
  HEDGE_STREAM_TANGENTS = 4,
  HEDGE_STREAM_TEXCOORDS1 = 5 /**< separate layout only (2 floats a vertex: lightmap UVs); else empty */
};

/** Render options (hedge::RenderOptions). Layout (24 bytes): six int32_t in this order. */
typedef struct hedge_render_buffers_options {
  int32_t normals;     /**< HEDGE_NORMALS_* */
  int32_t texcoords;   /**< 1: texcoords from the mesh's corner or vertex texcoords when present */
  int32_t colors;      /**< 1: colours from the mesh's corner or vertex colours when present */
  int32_t interleaved; /**< 1: one buffer of whole vertices; 0: one buffer per stream */
  int32_t winding;     /**< HEDGE_WINDING_*: of the triangles in the index buffer */
  int32_t flip_x;      /**< 1: negate x of positions and normals (mirrored data; Unity needs none) */
} hedge_render_buffers_options;

/** Where each attribute sits in a vertex, in floats; an absent attribute has offset -1.
 *  Interleaved: all in the HEDGE_STREAM_VERTICES buffer, stride floats a vertex, in the order
 *  position, normal, texcoord, color, tangent, texcoord1. Separate: each in its own stream, tightly
 *  packed (3, 3, 2, 4, 4 and 2 floats a vertex), a present attribute has offset 0, and stride still
 *  counts the floats of one whole vertex over all streams. Tangents ("h:tangent": xyz and the
 *  handedness w) and the second texcoord channel ("h:texcoord1", lightmap UVs) are present when the
 *  mesh has them (hedge_mesh_from_engine_streams()). Layout (32 bytes): stride @0 (uint32_t),
 *  position @4, normal @8, texcoord @12, color @16, interleaved @20, tangent @24, texcoord1 @28
 *  (int32_t). */
typedef struct hedge_vertex_layout {
  uint32_t stride;
  int32_t position;
  int32_t normal;
  int32_t texcoord;
  int32_t color;
  int32_t interleaved;
  int32_t tangent;
  int32_t texcoord1;
} hedge_vertex_layout;

/** A run of slots [first, first + count). Layout (8 bytes): first @0, count @4. */
typedef struct hedge_range {
  uint32_t first;
  uint32_t count;
} hedge_range;

/** What a sync (or commit, or rebuild) rewrote. The ranges themselves:
 *  hedge_render_buffers_dirty_vertex_ranges() and hedge_render_buffers_dirty_index_ranges().
 *  Layout (40 bytes): vertex_bytes @0, index_bytes @8 (uint64_t), vertex_range_count @16,
 *  index_range_count @20, faces_synced @24, vertices_synced @28 (uint32_t), resized @32,
 *  full @36 (int32_t). */
typedef struct hedge_sync_result {
  uint64_t vertex_bytes;       /**< bytes in the vertex ranges, all streams */
  uint64_t index_bytes;        /**< bytes in the index ranges */
  uint32_t vertex_range_count; /**< rewritten render-vertex ranges */
  uint32_t index_range_count;  /**< rewritten index-buffer ranges (in indices, not triangles) */
  uint32_t faces_synced;
  uint32_t vertices_synced;
  int32_t resized; /**< 1: the buffers grew or were rebuilt: reallocate GPU buffers, upload all */
  int32_t full;    /**< 1: everything was rebuilt (first sync, garbage collection, rebuild) */
} hedge_sync_result;

/** Buffer sizes. *_slots count storage slots, free ones included; vertices and triangles count the
 *  slots in use (the vocabulary of hedge_counts). Layout (40 bytes): vertex_slots @0, index_count @4,
 *  vertices @8, triangles @12, seam_splits @16, free_triangle_slots @20 (uint32_t), buffer_bytes
 *  @24 (uint64_t), vertex_capacity @32, index_capacity @36 (uint32_t). Allocate GPU buffers at the
 *  capacities: the buffers grow inside them without a reallocation, and a sync whose result has
 *  `resized` set grew beyond them. */
typedef struct hedge_buffer_counts {
  uint32_t vertex_slots;        /**< render vertex slots: the vertex buffer's length in vertices */
  uint32_t index_count;         /**< the index buffer's length in indices (3 per triangle slot) */
  uint32_t vertices;            /**< render vertex slots in use */
  uint32_t triangles;           /**< triangle slots in use */
  uint32_t seam_splits;         /**< render vertices beyond one per used mesh vertex */
  uint32_t free_triangle_slots; /**< degenerate triangle slots waiting for reuse or compaction */
  uint64_t buffer_bytes;        /**< bytes of the whole vertex and index buffers */
  uint32_t vertex_capacity;     /**< render vertex slots to allocate (>= vertex_slots) */
  uint32_t index_capacity;      /**< index-buffer entries to allocate (>= index_count) */
} hedge_buffer_counts;

/** Fills *out_options with the defaults: HEDGE_NORMALS_AUTOMATIC, texcoords 1, colors 1,
 *  interleaved 1, HEDGE_WINDING_CCW, flip_x 0. */
HEDGE_API hedge_status hedge_render_buffers_options_default(hedge_render_buffers_options* out_options);

/** Makes a render object for the mesh and builds its buffers (a full export).
 *  \param options NULL for hedge_render_buffers_options_default(). */
HEDGE_API hedge_status hedge_render_buffers_create(hedge_mesh* mesh,
                                                   const hedge_render_buffers_options* options,
                                                   hedge_render_buffers** out_render);
/** Destroys a render object (the mesh stays). */
HEDGE_API hedge_status hedge_render_buffers_destroy(hedge_render_buffers* render);

/** Brings the buffers in step with the edits since the last sync. Inside a transaction it does
 *  nothing (an empty result). \param out_result optional (NULL). */
HEDGE_API hedge_status hedge_render_buffers_sync(hedge_render_buffers* render, hedge_sync_result* out_result);
/** Opens a transaction: edits are gathered until the matching commit (transactions nest). The
 *  transaction is this render object's own: other render objects of the mesh keep syncing. */
HEDGE_API hedge_status hedge_render_buffers_begin(hedge_render_buffers* render);
/** Closes the transaction; the outermost commit syncs once. No open transaction:
 *  HEDGE_ERROR_INVALID_ARGUMENT. \param out_result optional (NULL). */
HEDGE_API hedge_status hedge_render_buffers_commit(hedge_render_buffers* render,
                                                   hedge_sync_result* out_result);
/** Rebuilds every buffer from scratch (slots restart in face order, so it also compacts).
 *  \param out_result optional (NULL). */
HEDGE_API hedge_status hedge_render_buffers_rebuild(hedge_render_buffers* render,
                                                    hedge_sync_result* out_result);
/** The result of the last sync, commit or rebuild. */
HEDGE_API hedge_status hedge_render_buffers_last_result(const hedge_render_buffers* render,
                                                        hedge_sync_result* out_result);
/** The render-vertex slot ranges the last sync, commit or rebuild rewrote, sorted, merged and
 *  disjoint (the same ranges apply to every stream of a separate layout). */
HEDGE_API hedge_status hedge_render_buffers_dirty_vertex_ranges(const hedge_render_buffers* render,
                                                                hedge_range* buffer, uint32_t capacity,
                                                                uint32_t* out_count);
/** The index-buffer ranges (in entries, not triangles) the last sync, commit or rebuild rewrote,
 *  sorted, merged and disjoint. */
HEDGE_API hedge_status hedge_render_buffers_dirty_index_ranges(const hedge_render_buffers* render,
                                                               hedge_range* buffer, uint32_t capacity,
                                                               uint32_t* out_count);
/** Removes the free slots by packing the live render vertices and triangles in their current
 *  order (live slots keep their relative order); re-upload both buffers afterwards. Outside a
 *  transaction it first syncs pending edits, as hedge_render_buffers_sync() does. Each map is optional
 * (NULL): old render-vertex slot -> new slot, and old triangle slot -> new triangle slot; freed slots map to
 * HEDGE_INVALID_INDEX. The sizes needed are the vertex_slots and index_count / 3 of
 * hedge_render_buffers_counts() after that sync, and are written to *out_vertex_count and *out_triangle_count
 * (each optional, NULL); a map too small gives HEDGE_ERROR_BUFFER_TOO_SMALL and nothing is compacted (the
 * sync may have happened). */
HEDGE_API hedge_status hedge_render_buffers_compact(hedge_render_buffers* render, uint32_t* vertex_map,
                                                    uint32_t vertex_capacity, uint32_t* out_vertex_count,
                                                    uint32_t* triangle_map, uint32_t triangle_capacity,
                                                    uint32_t* out_triangle_count);

HEDGE_API hedge_status hedge_render_buffers_counts(const hedge_render_buffers* render,
                                                   hedge_buffer_counts* out_counts);
HEDGE_API hedge_status hedge_render_buffers_layout(const hedge_render_buffers* render,
                                                   hedge_vertex_layout* out_layout);

/** A pointer to a vertex stream (HEDGE_STREAM_*) and its size in floats (0, with a NULL pointer,
 *  for an empty stream). The pointer is valid until the next sync, commit, rebuild or compact of
 *  this render object, or its destruction (or its mesh's). Read-only. */
HEDGE_API hedge_status hedge_render_buffers_vertex_data(const hedge_render_buffers* render, int32_t stream,
                                                        const float** out_data, uint64_t* out_count);
/** Copies a vertex stream into a caller buffer (capacity and *out_count in floats). */
HEDGE_API hedge_status hedge_render_buffers_copy_vertex_data(const hedge_render_buffers* render,
                                                             int32_t stream, float* buffer, uint64_t capacity,
                                                             uint64_t* out_count);
/** A pointer to the index buffer (3 entries per triangle slot) and its size in entries; valid as for
 *  hedge_render_buffers_vertex_data(). */
HEDGE_API hedge_status hedge_render_buffers_index_data(const hedge_render_buffers* render,
                                                       const uint32_t** out_data, uint64_t* out_count);
/** Copies the index buffer into a caller buffer (capacity and *out_count in entries). */
HEDGE_API hedge_status hedge_render_buffers_copy_index_data(const hedge_render_buffers* render,
                                                            uint32_t* buffer, uint64_t capacity,
                                                            uint64_t* out_count);
/** Render vertex slot -> mesh vertex (HEDGE_INVALID_INDEX for a free slot), vertex_slots entries. */
HEDGE_API hedge_status hedge_render_buffers_vertex_source(const hedge_render_buffers* render,
                                                          uint32_t* buffer, uint32_t capacity,
                                                          uint32_t* out_count);
/** The render vertex of the corner that the half-edge enters (HEDGE_INVALID_INDEX for a boundary
 *  half-edge), as of the last sync. */
HEDGE_API hedge_status hedge_render_buffers_corner_vertex(const hedge_render_buffers* render,
                                                          uint32_t halfedge, uint32_t* out_render_vertex);
/** The triangle slots of a face, as of the last sync: triangles [*out_first, *out_first +
 *  *out_count) of the index buffer (*out_count 0 if it has none). */
HEDGE_API hedge_status hedge_render_buffers_face_triangles(const hedge_render_buffers* render, uint32_t face,
                                                           uint32_t* out_first, uint32_t* out_count);
/** The face that owns triangle slot `triangle` of the index buffer (entries 3 x triangle to
 *  3 x triangle + 2), as of the last sync: the inverse of hedge_render_buffers_face_triangles(). This is what
 *  an engine's own ray hit gives back (Unity's RaycastHit.triangleIndex on a MeshCollider of the
 *  uploaded mesh). *out_face is HEDGE_INVALID_INDEX (with HEDGE_OK) for a free slot and for a face
 *  deleted by an edit since that sync. O(1). A triangle out of range (>= index_count / 3):
 *  HEDGE_ERROR_BAD_HANDLE. */
HEDGE_API hedge_status hedge_render_buffers_triangle_face(const hedge_render_buffers* render,
                                                          uint32_t triangle, uint32_t* out_face);

/* Submeshes (materials). A face's submesh is its "f:submesh" property (0 without it); the index
 * buffer holds one contiguous range per submesh, in submesh order, each but the last with spare
 * room (degenerate triangles) so that edits stay local. */

/** One submesh's part of the buffers (hedge::SubmeshRange), as of the last sync: what an engine's
 *  submesh descriptor needs. Layout (40 bytes): index_start @0, index_count @4, first_vertex @8,
 *  vertex_count @12 (uint32_t), min @16, max @28 (3 floats each). */
typedef struct hedge_submesh_range {
  uint32_t index_start; /**< first entry of the index buffer */
  uint32_t index_count; /**< entries, spare and free (degenerate) triangles included */
  uint32_t
      first_vertex; /**< every index entry of the range lies in [first_vertex, first_vertex + vertex_count) */
  uint32_t vertex_count;
  float min[3]; /**< the box of the positions its live triangles use, as in the vertex buffer */
  float max[3]; /**< (both 0 without live triangles) */
} hedge_submesh_range;

/** *out_count receives the number of submeshes: 1 + the largest face submesh at the last full build
 *  (a sync that meets a larger one rebuilds). At least 1. */
HEDGE_API hedge_status hedge_render_buffers_submesh_count(const hedge_render_buffers* render,
                                                          uint32_t* out_count);
/** Fills *out_range with submesh `submesh`'s index range, vertex range and bounds. O(its index
 *  entries). A submesh >= the count: HEDGE_ERROR_BAD_HANDLE. */
HEDGE_API hedge_status hedge_render_buffers_submesh(const hedge_render_buffers* render, uint32_t submesh,
                                                    hedge_submesh_range* out_range);
/** *out_submesh receives face `face`'s submesh (0 when the mesh has no "f:submesh"). */
HEDGE_API hedge_status hedge_face_submesh(const hedge_mesh* mesh, uint32_t face, int32_t* out_submesh);
/** Sets face `face`'s submesh, in [0, 65535] (else HEDGE_ERROR_INVALID_ARGUMENT, nothing changed),
 *  adding "f:submesh" (0 for every other face) when the mesh has none. Render buffers move the
 *  face's triangles into that submesh's range at their next sync. */
HEDGE_API hedge_status hedge_set_face_submesh(hedge_mesh* mesh, uint32_t face, int32_t submesh);

/* ============================================================================================ */
/* Engine-mesh import (hedge/render/engine_mesh.h)                                              */
/* ============================================================================================ */

/** Import options for engine meshes (hedge::EngineImportOptions). Layout (24 bytes): weld @0,
 *  policy @4 (int32_t), weld_epsilon @8 (double), winding @16, flip_x @20 (int32_t). */
typedef struct hedge_engine_import_options {
  int32_t weld;        /**< HEDGE_WELD_*: positions welded into one topological vertex */
  int32_t policy;      /**< HEDGE_POLICY_* */
  double weld_epsilon; /**< relative to the bounding-box diagonal, with HEDGE_WELD_EPSILON */
  int32_t winding;     /**< HEDGE_WINDING_*: the triangle winding to convert from (Unity: none, CCW) */
  int32_t flip_x;      /**< 1: negate x of positions and normals (mirrored data; Unity needs none) */
} hedge_engine_import_options;

/** Fills *out_options with the defaults: HEDGE_WELD_EXACT, HEDGE_POLICY_REPAIR, weld_epsilon 1e-6,
 *  HEDGE_WINDING_CCW, flip_x 0. */
HEDGE_API hedge_status hedge_engine_import_options_default(hedge_engine_import_options* out_options);

/** Builds a mesh from an engine's arrays (a Unity Mesh, a glTF primitive): positions welded for the
 *  topology, normals, texcoords and colours kept per corner, so that a render object with the same
 *  winding and flip_x reproduces the engine's triangles and attributes.
 *  \param positions 3 floats per vertex (vertex_count vertices).
 *  \param indices   3 per triangle (index_count, a multiple of 3).
 *  \param normals   optional (NULL): 3 floats per vertex.
 *  \param texcoords optional (NULL): 2 floats per vertex.
 *  \param colors    optional (NULL): 4 floats (r, g, b, a) per vertex.
 *  \param options   NULL for hedge_engine_import_options_default().
 *  \param out_report optional (NULL). */
HEDGE_API hedge_status hedge_mesh_from_engine_mesh(const float* positions, uint32_t vertex_count,
                                                   const uint32_t* indices, uint32_t index_count,
                                                   const float* normals, const float* texcoords,
                                                   const float* colors,
                                                   const hedge_engine_import_options* options,
                                                   hedge_build_report* out_report, hedge_mesh** out_mesh);

/** The map back to the engine's vertex indices (hedge/render/engine_mesh.h kVertexSource,
 *  kCornerSource): which engine vertex each vertex and corner of a mesh made by
 *  hedge_mesh_from_engine_mesh() came from, so that data keyed by the engine's vertex index (a Unity
 *  mesh's) is found again. Per vertex slot: the first (smallest) engine vertex welded into it (a
 *  seam welds several). Per half-edge slot: the engine vertex of the corner it enters (that
 *  vertex in that half-edge's face). -1 for boundary half-edges, deleted elements and what later edits
 *  made; the values follow their elements through edits and garbage collection.
 *  \param buffer   optional (NULL asks for the count): vertex_slots (2 x edge_slots) int32 values.
 *  \param out_count the values needed.
 *  A mesh not made from engine arrays: HEDGE_ERROR_INVALID_ARGUMENT. */
HEDGE_API hedge_status hedge_mesh_vertex_source_indices(const hedge_mesh* mesh, int32_t* buffer,
                                                        uint64_t capacity, uint64_t* out_count);
HEDGE_API hedge_status hedge_mesh_corner_source_indices(const hedge_mesh* mesh, int32_t* buffer,
                                                        uint64_t capacity, uint64_t* out_count);

/** hedge_mesh_from_engine_mesh() with one submesh (material) per triangle: triangle_submeshes holds
 *  index_count / 3 ids in [0, 65535] (NULL: every face in submesh 0, as hedge_mesh_from_engine_mesh()),
 *  kept as the face property "f:submesh" through edits, subdivision, decimation and fracture. An
 *  engine mesh of several submeshes passes its triangles submesh after submesh with their ids. */
HEDGE_API hedge_status hedge_mesh_from_engine_mesh_with_submeshes(
    const float* positions, uint32_t vertex_count, const uint32_t* indices, uint32_t index_count,
    const float* normals, const float* texcoords, const float* colors, const int32_t* triangle_submeshes,
    const hedge_engine_import_options* options, hedge_build_report* out_report, hedge_mesh** out_mesh);

/** An engine mesh's arrays for hedge_mesh_from_engine_streams(): every stream but positions and
 *  indices is optional (NULL), so that a new stream adds a field instead of a parameter. Fill it
 *  with zeros (`hedge_engine_streams s = {0};`), then set what you have. Layout (88 bytes on 64-bit
 *  systems, 48 on 32-bit ones): vertex_count @0, index_count @4 (uint32_t), then the pointers in
 *  this order from @8, each one pointer wide. */
typedef struct hedge_engine_streams {
  uint32_t vertex_count;   /**< engine vertices: every per-vertex stream has this many entries */
  uint32_t index_count;    /**< entries of indices, a multiple of 3 */
  const float* positions;  /**< required: 3 floats a vertex */
  const uint32_t* indices; /**< required: 3 a triangle, each < vertex_count */
  const float* normals;    /**< optional: 3 floats a vertex, kept per corner as "h:normal" */
  const float* texcoords;  /**< optional: 2 floats a vertex ("h:texcoord") */
  const float* colors;     /**< optional: 4 floats (r, g, b, a) a vertex ("h:color") */
  /** optional: 4 floats a vertex, xyz and the handedness w (+1 or -1; Unity's Mesh.tangents), kept
   *  per corner as "h:tangent", imported, not computed: render buffers whose normals follow the
   *  geometry make each corner's tangent perpendicular to its recomputed normal again, w kept */
  const float* tangents;
  /** optional: 2 floats a vertex, a second texcoord channel (lightmap UVs, Unity's uv2), kept per
   *  corner as "h:texcoord1" */
  const float* texcoords1;
  /** optional: index_count / 3 submesh (material) ids in [0, 65535], one a triangle ("f:submesh") */
  const int32_t* triangle_submeshes;
} hedge_engine_streams;

/** Builds a mesh from an engine's arrays, as hedge_mesh_from_engine_mesh() does, with every stream
 *  of `streams` that is not NULL kept per corner (per face for triangle_submeshes). Render buffers
 *  of the mesh then have tangent and texcoord1 streams (hedge_vertex_layout, HEDGE_STREAM_TANGENTS,
 *  HEDGE_STREAM_TEXCOORDS1) that follow its edits. A non-finite value, an index out of range or a
 *  submesh id outside [0, 65535] is HEDGE_ERROR_INVALID_ARGUMENT naming the stream and the entry;
 *  no mesh is made then.
 *  \param options   NULL for hedge_engine_import_options_default().
 *  \param out_report optional (NULL). */
HEDGE_API hedge_status hedge_mesh_from_engine_streams(const hedge_engine_streams* streams,
                                                      const hedge_engine_import_options* options,
                                                      hedge_build_report* out_report, hedge_mesh** out_mesh);

/* ============================================================================================ */
/* Threads (hedge/core/threads.h)                                                               */
/* ============================================================================================ */

/** Sets how many threads one call may run on, the calling thread included, for the whole process:
 *  1 starts no worker thread at all (every call runs on the calling thread, as inside a game's
 *  frame); 0 restores the default, every core the process may run on. Only subdivision and the
 *  Hausdorff distance use worker threads, joined before they return; their results do not depend on
 *  the count. Any thread may call it at any time; a call already running keeps its count. */
HEDGE_API hedge_status hedge_set_max_threads(uint32_t n);
/** *out_n receives the number of threads a call may run on now (at least 1): the value set, or the
 *  number of usable cores when 0 was set or nothing was. */
HEDGE_API hedge_status hedge_max_threads(uint32_t* out_n);

/* ============================================================================================ */
/* Deprecated names (kept for one release)                                                      */
/* ============================================================================================ */

/* The names of the previous release, as aliases of the current ones (docs/names.md, "C function
 * names"): code written against them still compiles, and the next release removes them. They are
 * macros, so the library exports only the current names. */
#define hedge_render hedge_render_buffers
#define hedge_render_options hedge_render_buffers_options
#define hedge_render_begin hedge_render_buffers_begin
#define hedge_render_commit hedge_render_buffers_commit
#define hedge_render_compact hedge_render_buffers_compact
#define hedge_render_copy_index_data hedge_render_buffers_copy_index_data
#define hedge_render_copy_vertex_data hedge_render_buffers_copy_vertex_data
#define hedge_render_corner_vertex hedge_render_buffers_corner_vertex
#define hedge_render_counts hedge_render_buffers_counts
#define hedge_render_create hedge_render_buffers_create
#define hedge_render_destroy hedge_render_buffers_destroy
#define hedge_render_dirty_index_ranges hedge_render_buffers_dirty_index_ranges
#define hedge_render_dirty_vertex_ranges hedge_render_buffers_dirty_vertex_ranges
#define hedge_render_face_triangles hedge_render_buffers_face_triangles
#define hedge_render_index_data hedge_render_buffers_index_data
#define hedge_render_last_result hedge_render_buffers_last_result
#define hedge_render_layout hedge_render_buffers_layout
#define hedge_render_options_default hedge_render_buffers_options_default
#define hedge_render_rebuild hedge_render_buffers_rebuild
#define hedge_render_sync hedge_render_buffers_sync
#define hedge_render_triangle_face hedge_render_buffers_triangle_face
#define hedge_render_vertex_data hedge_render_buffers_vertex_data
#define hedge_render_vertex_source hedge_render_buffers_vertex_source
#define hedge_split_all_faces hedge_mesh_split_all_faces
#define hedge_mesh_get_position hedge_vertex_position
#define hedge_mesh_set_position hedge_set_vertex_position
/* End of deprecated names */

#ifdef __cplusplus
} /* extern "C" */
#endif

#endif /* HEDGE_C_API_H */
