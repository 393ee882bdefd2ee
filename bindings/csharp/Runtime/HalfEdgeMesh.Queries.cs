// HalfEdgeMesh's queries: adjacency, circulators into caller arrays and the edit predicates. Each
// is one native call whose status is checked and whose result is converted to the binding's types
// by the helpers below; none allocates.
using System;

namespace Hedge
{
    public sealed partial class HalfEdgeMesh
    {
        // Call, check, convert: the result of a native query whose status is OK, or the exception.
        static HalfEdge HalfEdgeOf(int status, uint raw) { return new HalfEdge(Status.Checked(status, raw)); }
        static Vertex VertexOf(int status, uint raw) { return new Vertex(Status.Checked(status, raw)); }
        static Face FaceOf(int status, uint raw) { return new Face(Status.Checked(status, raw)); }
        static Edge EdgeOf(int status, uint raw) { return new Edge(Status.Checked(status, raw)); }
        static bool IsSet(int status, int flag) { return Status.Checked(status, flag) != 0; }

        // A predicate's answer; a "no" also sets LastRefusalCode to why that edit would be refused, a "yes"
        // clears it, so the reason read after a predicate is always this edit's.
        bool Allowed(int status, int ok)
        {
            Status.Check(status);
            LastRefusalCode = ok != 0 ? RefusalCode.None : (RefusalCode)Native.hedge_last_refusal_code();
            return ok != 0;
        }
        // The count of a copy into a caller array; a null array asks for the count only.
        static int Filled(int status, Array result, ulong count) { return Status.Filled(status, result == null, count); }

        // =========================================================================================
        // Adjacency (O(1) unless noted)
        // =========================================================================================

        /// <summary>The opposite half-edge (checked against the mesh: a dead half-edge throws).</summary>
        public HalfEdge Twin(HalfEdge h) { return HalfEdgeOf(Native.hedge_halfedge_twin(id, h.Raw, out uint r), r); }

        /// <summary>The next half-edge in the face or boundary loop.</summary>
        public HalfEdge Next(HalfEdge h) { return HalfEdgeOf(Native.hedge_halfedge_next(id, h.Raw, out uint r), r); }

        /// <summary>The previous half-edge in the face or boundary loop. O(face degree), O(valence) on a boundary.</summary>
        public HalfEdge Prev(HalfEdge h) { return HalfEdgeOf(Native.hedge_halfedge_prev(id, h.Raw, out uint r), r); }

        /// <summary>The vertex the half-edge points to.</summary>
        public Vertex ToVertex(HalfEdge h) { return VertexOf(Native.hedge_halfedge_to_vertex(id, h.Raw, out uint r), r); }

        /// <summary>The vertex the half-edge starts at.</summary>
        public Vertex FromVertex(HalfEdge h)
        {
            return VertexOf(Native.hedge_halfedge_from_vertex(id, h.Raw, out uint r), r);
        }

        /// <summary>The face of the half-edge; <see cref="Face.Invalid"/> for a boundary half-edge.</summary>
        public Face GetFace(HalfEdge h) { return FaceOf(Native.hedge_halfedge_face(id, h.Raw, out uint r), r); }

        /// <summary>The edge of the half-edge.</summary>
        public Edge GetEdge(HalfEdge h) { return EdgeOf(Native.hedge_halfedge_edge(id, h.Raw, out uint r), r); }

        /// <summary>One outgoing half-edge of the vertex (a boundary one if the vertex is on a boundary);
        /// <see cref="HalfEdge.Invalid"/> for an isolated vertex.</summary>
        public HalfEdge GetHalfEdge(Vertex v) { return HalfEdgeOf(Native.hedge_vertex_halfedge(id, v.Raw, out uint r), r); }

        /// <summary>The face's half-edge: its corners start at this half-edge's target.</summary>
        public HalfEdge GetHalfEdge(Face f) { return HalfEdgeOf(Native.hedge_face_halfedge(id, f.Raw, out uint r), r); }

        /// <summary>Half-edge i (0 or 1) of the edge.</summary>
        public HalfEdge GetHalfEdge(Edge e, int i)
        {
            if (i < 0) throw new ArgumentOutOfRangeException("i", i, "a half-edge of an edge is 0 or 1");
            return HalfEdgeOf(Native.hedge_edge_halfedge(id, e.Raw, (uint)i, out uint r), r);
        }

        /// <summary>True if the vertex is on a boundary or isolated.</summary>
        public bool IsBoundary(Vertex v) { return IsSet(Native.hedge_vertex_is_boundary(id, v.Raw, out int r), r); }

        /// <summary>True if the half-edge has no face.</summary>
        public bool IsBoundary(HalfEdge h) { return IsSet(Native.hedge_halfedge_is_boundary(id, h.Raw, out int r), r); }

        /// <summary>True if either half-edge of the edge has no face.</summary>
        public bool IsBoundary(Edge e) { return IsSet(Native.hedge_edge_is_boundary(id, e.Raw, out int r), r); }

        /// <summary>True if any edge of the face is on a boundary. O(face degree).</summary>
        public bool IsBoundary(Face f) { return IsSet(Native.hedge_face_is_boundary(id, f.Raw, out int r), r); }

        /// <summary>Number of edges at the vertex. O(valence).</summary>
        public int Valence(Vertex v) { return (int)Status.Checked(Native.hedge_vertex_valence(id, v.Raw, out uint r), r); }

        /// <summary>Number of corners of the face. O(face degree).</summary>
        public int Valence(Face f) { return (int)Status.Checked(Native.hedge_face_valence(id, f.Raw, out uint r), r); }

        /// <summary>The half-edge from one vertex to another, or <see cref="HalfEdge.Invalid"/> when no edge
        /// joins them. O(valence).</summary>
        public HalfEdge FindHalfEdge(Vertex from, Vertex to)
        {
            return HalfEdgeOf(Native.hedge_mesh_find_halfedge(id, from.Raw, to.Raw, out uint r), r);
        }

        // Deletion flags: these accept deleted elements (only an index out of range throws).
        public bool IsDeleted(Vertex v) { return IsSet(Native.hedge_vertex_is_deleted(id, v.Raw, out int r), r); }

        public bool IsDeleted(HalfEdge h) { return IsSet(Native.hedge_halfedge_is_deleted(id, h.Raw, out int r), r); }

        public bool IsDeleted(Edge e) { return IsSet(Native.hedge_edge_is_deleted(id, e.Raw, out int r), r); }

        public bool IsDeleted(Face f) { return IsSet(Native.hedge_face_is_deleted(id, f.Raw, out int r), r); }

        // =========================================================================================
        // Circulators into caller arrays. The one-ring of a vertex is clockwise, starting at
        // GetHalfEdge(v) (at the boundary gap for a boundary vertex); an isolated vertex has an empty
        // one-ring. Each returns the count; null asks for the count only.
        // =========================================================================================

        /// <summary>Outgoing half-edges of the vertex.</summary>
        public int GetVertexHalfEdges(Vertex v, HalfEdge[] result)
        {
            return Filled(Native.hedge_vertex_halfedges(id, v.Raw, result, Status.Capacity(result), out uint n), result, n);
        }

        /// <summary>Neighbour vertices (the targets of the outgoing half-edges, same order).</summary>
        public int GetVertexNeighbours(Vertex v, Vertex[] result)
        {
            return Filled(Native.hedge_vertex_vertices(id, v.Raw, result, Status.Capacity(result), out uint n), result, n);
        }

        /// <summary>Faces around the vertex (boundary gaps skipped).</summary>
        public int GetVertexFaces(Vertex v, Face[] result)
        {
            return Filled(Native.hedge_vertex_faces(id, v.Raw, result, Status.Capacity(result), out uint n), result, n);
        }

        /// <summary>Corners of the face in order (counter-clockwise), starting at the target of GetHalfEdge(f).</summary>
        public int GetFaceVertices(Face f, Vertex[] result)
        {
            return Filled(Native.hedge_face_vertices(id, f.Raw, result, Status.Capacity(result), out uint n), result, n);
        }

        /// <summary>Half-edges of the face in order, starting at GetHalfEdge(f); the i-th enters the i-th
        /// corner of <see cref="GetFaceVertices"/>.</summary>
        public int GetFaceHalfEdges(Face f, HalfEdge[] result)
        {
            return Filled(Native.hedge_face_halfedges(id, f.Raw, result, Status.Capacity(result), out uint n), result, n);
        }

        // =========================================================================================
        // Predicates. True if the edit of the same name would be carried out.
        // =========================================================================================

        public bool CanSplitEdge(Edge e) { return Allowed(Native.hedge_can_split_edge(id, e.Raw, out int ok), ok); }

        /// <summary>True if collapsing h keeps the mesh a valid manifold (link condition, no valence
        /// below 3 left, no tetrahedron collapsed, ...). O(valence).</summary>
        public bool CanCollapse(HalfEdge h) { return Allowed(Native.hedge_can_collapse(id, h.Raw, out int ok), ok); }

        /// <summary>True if the edge is interior between two triangles and can be turned. O(valence).</summary>
        public bool CanFlip(Edge e) { return Allowed(Native.hedge_can_flip(id, e.Raw, out int ok), ok); }

        public bool CanFlip(HalfEdge h) { return CanFlip(h.Edge); }

        public bool CanSplitFace(Face f) { return Allowed(Native.hedge_can_split_face(id, f.Raw, out int ok), ok); }

        /// <summary>True if the face of h0 and h1 can be cut along a new edge from the target of h0 to the
        /// target of h1: both in the same live face, the targets not adjacent in it and not joined yet.</summary>
        public bool CanCutFace(HalfEdge h0, HalfEdge h1)
        {
            return Allowed(Native.hedge_can_cut_face(id, h0.Raw, h1.Raw, out int ok), ok);
        }

        /// <summary>True if a face with the first count corners (counter-clockwise) can be added while every
        /// vertex and edge stays manifold.</summary>
        public bool CanAddFace(Vertex[] corners, int count)
        {
            CheckSpan(corners, count, "corners");
            return Allowed(Native.hedge_can_add_face(id, corners, (uint)count, out int ok), ok);
        }

        public bool CanAddFace(Vertex[] corners) { return CanAddFace(corners, LengthOf(corners)); }

        public bool CanAddFace(Vertex a, Vertex b, Vertex c) { return CanAddFace(Triangle(a, b, c), 3); }

        public bool CanRemoveFace(Face f) { return Allowed(Native.hedge_can_remove_face(id, f.Raw, out int ok), ok); }

        public bool CanRemoveVertex(Vertex v) { return Allowed(Native.hedge_can_remove_vertex(id, v.Raw, out int ok), ok); }

        /// <summary>True if h is a boundary half-edge whose loop has at least 3 edges.</summary>
        public bool CanFillHole(HalfEdge h) { return Allowed(Native.hedge_can_fill_hole(id, h.Raw, out int ok), ok); }
    }
}
