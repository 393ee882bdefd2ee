// Subdivision: Loop's scheme and the midpoint split refine triangle meshes 1-to-4 (every edge gets a
// vertex at its middle); Catmull-Clark refines any polygon mesh into quads.
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
//
// The refined mesh is built in one pass by index arithmetic rather than by local operations: with
// V vertices, E edges and F faces, old vertex v keeps index v, the vertex of edge e is V + e, the
// halves of edge e are edges 2e and 2e + 1, the three inner edges of face f are 2E + 3f + {0, 1, 2},
// and face f becomes faces 4f + {0, 1, 2} (its corners) and 4f + 3 (its middle). Children sit next
// to their parents, so the order keeps the input's locality. Catmull-Clark adds face f's point as
// vertex V + E + f and numbers its quads and inner edges after the faces' half-edges, in order.
//
// Properties follow: vertex properties of new vertices are the average of the edge's ends (the
// positions by the scheme); corner properties (texture coordinates) are copied at old corners and
// averaged along each face's own edges, so UV seams stay seams; edge properties go to both halves
// (inner edges get the default); face properties go to the four children. Deleted elements are
// collected first. The change log records a reset: every index changed.
#pragma once

#include "hedge/core/surface_mesh.h"

namespace hedge {

enum class Subdivision { loop, midpoint, catmull_clark };

//! Refines every face, `steps` times. Cost per step: O(V + E + F) time; the output has four times the
//! faces (Loop, midpoint) or as many quads as the input had face corners (Catmull-Clark). An empty
//! mesh stays empty.
//! \throw InvalidInputError, with the mesh unchanged, if a face is not a triangle for Loop's or the
//!   midpoint scheme (the message names it), if steps is negative, or if the result would exceed
//!   2^31 half-edges.
void subdivide(SurfaceMesh& mesh, Subdivision scheme, int steps = 1);

}  // namespace hedge
