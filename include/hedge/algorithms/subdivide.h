// Subdivision: Loop's scheme and the midpoint split refine triangle meshes 1-to-4 (every edge gets a
// vertex at its middle); Catmull-Clark refines any polygon mesh into quads; sqrt3 and split-faces
// put a vertex at every face's centroid and fan the face into triangles about it.
//
//  - loop: Loop's scheme. New vertices are placed by Loop's masks (3/8, 3/8, 1/8, 1/8 on an
//    interior edge), old vertices move toward their neighbours (Loop's beta); boundaries follow
//    the cubic B-spline rules (1/8, 3/4, 1/8; edge midpoints), so a boundary curve is refined on
//    its own. Edges marked in the edge property "e:crease" (std::uint8_t, nonzero) are kept sharp
//    the same way: a vertex on two crease edges is a crease vertex, on three or more a corner that
//    stays where it is.
//  - midpoint: linear; the old vertices stay, the new ones sit at the edge midpoints. The shape
//    does not change.
//  - catmull_clark: for any polygons. A face of n corners becomes n quads around a new face point
//    (its centroid); edge points average the edge's ends and the two face points; old vertices move
//    by (Q + 2R + (n - 3) S) / n. Boundaries and "e:crease" edges follow the cubic B-spline curve
//    rules, as in Loop's scheme. After one step every face is a quad.
//  - sqrt3: Kobbelt's sqrt(3) scheme, for triangle meshes. Every face gets its centroid as a new
//    vertex, every old edge is flipped so that it joins the centroids of its two faces, and old
//    vertices move by (1 - a) p + a (mean of the n neighbours), a = (4 - 2 cos(2 pi / n)) / 9. A
//    closed mesh goes from V, E, F to V + F, E + 3F, 3F; two steps make each edge three (a triadic
//    split). Boundaries follow Kobbelt's rule, as OpenMesh's and CGAL's sqrt(3) do: the first,
//    third, ... step of a call neither flips nor splits boundary edges and leaves boundary vertices
//    where they are; the second, fourth, ... splits each boundary edge a -> b in three, with points
//    (z + 16a + 10b) / 27 and (10a + 16b + w) / 27 (z before a, w after b along the boundary), and
//    moves boundary vertices to (4 prev + 19 p + 4 next) / 27 (the ternary cubic B-spline), so two
//    steps split the boundary as they split the interior and boundary faces stay well shaped. The
//    parity counts within one call: subdivide(m, sqrt3, 2) is not two calls of one step (those
//    never split the boundary). "e:crease" edges are never flipped nor split, and a vertex on two
//    or more sharp edges (crease or boundary) stays where it is, but for a boundary vertex whose
//    two boundary edges are split; a vertex on one crease edge is smoothed as an interior one. A
//    boundary edge marked "e:crease" is kept like any crease: mark a whole boundary so to keep the
//    boundary polygon exactly (a patch that must still fit a hole in an unrefined mesh). An even
//    step adds one vertex and one edge per split boundary edge to the counts above (its face
//    gets the two points instead of a centroid).
//  - split_faces: the 1-to-n split of every face of n corners at its centroid (no flip, nothing
//    moves): the original's SplitAllFaces. Any polygons; gives triangles.
//
// The refined mesh is built in one pass by index arithmetic rather than by local operations: with
// V vertices, E edges and F faces, old vertex v keeps index v, the vertex of edge e is V + e, the
// halves of edge e are edges 2e and 2e + 1, the three inner edges of face f are 2E + 3f + {0, 1, 2},
// and face f becomes faces 4f + {0, 1, 2} (its corners) and 4f + 3 (its middle). Children sit next
// to their parents, so the order keeps the input's locality. Catmull-Clark adds face f's point as
// vertex V + E + f and numbers its quads and inner edges face by face: the quad at the k-th corner of
// face f (counted from halfedge(f)) is face D + k, D the sum of the degrees of the faces before f.
//
// sqrt3 and split_faces: old vertices, edges and half-edges keep their index (old edges flipped),
// face f's centroid is vertex V + f, and with the faces' corners numbered face by face
// (q = 3f + k for triangles), corner q gets the spoke edge E + q and the new face q. So again
// children sit next to their parents. In an even sqrt3 step a boundary face f (a, b, m) with a split
// edge takes, instead of a centroid, the point near a as vertex V + f, and the j-th such face (in
// face order) the point near b as vertex V + F + j and the edge from it to b as edge E + C + j (C
// the face corners).
//
// Properties follow: vertex properties of new vertices are the average of the edge's ends (the
// positions by the scheme); corner properties (texture coordinates) are copied at old corners and
// averaged along each face's own edges, so UV seams stay seams; edge properties go to both halves
// (inner edges get the default); face properties go to the four children. In sqrt3 and
// split_faces the centroid averages its face's vertex and corner properties, corners at old
// vertices keep their face's value, old edges keep theirs and spokes get the default, and the
// children take their face's properties. A sqrt3 flip across a UV seam cannot keep the seam: the
// new triangle takes each side's centroid value and the first face's value at the old vertex. The
// two points of a split boundary edge take 2/3 and 1/3 of its ends' vertex and corner values, and
// its three pieces keep its edge properties.
// Deleted elements are
// collected first (in a copy: the input's garbage stays until the result replaces it). The change
// log records a reset: every index changed.
//
// Each step builds the refined mesh in storage of its own and reads the one before; the mesh given
// takes the result only at the end, in a step that cannot fail. So if an allocation fails
// (std::bad_alloc) at any point, in any step, the mesh is left exactly as it was: same counts,
// links, deletion flags, positions and property values. Its property arrays stay the same objects,
// so handles to them stay valid, and see the refined mesh afterwards.
// Threads: each step splits its passes over the elements between up to min(8, max_threads())
// threads (core/threads.h), the calling thread one of them, when a pass has at least 32768
// elements per thread; set_max_threads(1) keeps it on the calling thread. The result does not
// depend on the number of threads, and every thread is joined before subdivide() returns.
#pragma once

#include "hedge/core/progress.h"
#include "hedge/core/surface_mesh.h"

namespace hedge {

enum class Subdivision { loop, midpoint, catmull_clark, sqrt3, split_faces };

//! Refines every face, `steps` times. Cost per step: O(V + E + F) time; the output has four times the
//! faces (Loop, midpoint), as many quads as the input had face corners (Catmull-Clark) or as many
//! triangles as it had face corners (sqrt3: 3F; split_faces). An empty mesh stays empty. `progress`
//! is called with the fraction done after each step (see core/progress.h); if it throws, the steps
//! already done stay done. Memory: the input, the result and, with garbage, a compacted copy of
//! the input at once.
//! `max_memory`: a budget in bytes for the estimate of subdivide_memory(), checked before anything
//! is allocated; 0: no budget (the default), so only memory running out stops a call.
//! \throw std::bad_alloc, with the mesh unchanged (strong guarantee), if memory runs out.
//! \throw InvalidInputError, with the mesh unchanged, if a face is not a triangle for Loop's, the
//!   midpoint or the sqrt3 scheme (the message names it), if steps is negative, if the result
//!   would exceed 2^31 half-edges, or if the estimate exceeds a nonzero max_memory (the message
//!   gives both, and the most steps that fit).
//! \throw InvalidInputError naming the first vertex whose position is not finite,
//!   before anything changes (require_finite_positions()).
void subdivide(SurfaceMesh& mesh, Subdivision scheme, int steps = 1, const Progress& progress = {},
               std::size_t max_memory = 0);

//! An estimate of the most memory, in bytes, that subdivide(mesh, scheme, steps) holds at once
//! besides the mesh itself: the last two refined meshes (their connectivity, flags and every
//! property, by the counts each step makes, with a quarter for the arrays' spare capacity) and the
//! step's working arrays, plus a compacted copy of the input when it has garbage. Counts are
//! computed in floating point, so no number of steps overflows (the result saturates at SIZE_MAX).
//! O(F) for the face corners, O(1) per step; nothing is allocated. Measured against the growth of
//! the peak resident memory of the call (every scheme, 3 to 7 steps, meshes of 0.7k to 16k faces
//! with and without texture coordinates), it was 1.15 to 1.5 times the peak, never below it.
//! \throw InvalidInputError for negative steps.
std::size_t subdivide_memory(const SurfaceMesh& mesh, Subdivision scheme, int steps);

}  // namespace hedge
