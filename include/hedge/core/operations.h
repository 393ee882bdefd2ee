// Local topology edits on a SurfaceMesh: this header includes both halves, the edits of edges
// (core/edge_operations.h: split_edge, collapse, flip) and of faces (core/face_operations.h:
// split_face, cut_face, add_face, remove_face, remove_vertex, remove_faces), and states the
// contract they share. Include it for all of them, or the half you use.
//
// Every operation that can be illegal has a public predicate (can_*) and returns an empty result
// (an invalid handle, false, or an empty list) when refused; a refused operation leaves the mesh
// exactly as it was. Each such edit also has a refusal (*_refusal): why the edit is refused, in a
// few words, as a static string of the one table of refusals (core/refusal.h, which gives each its
// stable code), or null if it is allowed. Its can_* is exactly "the refusal is
// null", so the two cannot disagree; the bindings report the refusal as the reason. Each costs
// O(1) or O(valence) unless noted.
// Properties follow the edits:
//  - vertex properties of a new vertex are interpolated from the vertices around it (blended for
//    float-like types, taken from the nearest source otherwise; see BasePropertyArray::interpolate),
//    or by a policy of the user's set per property with Property::set_interpolator();
//  - corner (half-edge) properties such as "h:texcoord" are interpolated along a split edge and
//    copied to the corners a face is split into, so a split inside a chart gives the new vertex one
//    value and keeps the chart seamless;
//  - a collapse keeps each chart seamless, and refuses what would tear a seam (the corner rule, at
//    the top of core/edge_operations.h);
//  - face properties are copied to the faces a face is split into; edge properties are copied to
//    the two halves of a split edge.
// Deleted elements stay in storage until garbage_collection().
#pragma once

#include "hedge/core/edge_operations.h"
#include "hedge/core/face_operations.h"
