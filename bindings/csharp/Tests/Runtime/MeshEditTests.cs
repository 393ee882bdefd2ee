// Local edits from C#: refusals and their reasons, collapses, splits, flips and cuts on small meshes,
// polygons and diagonals, detaching faces and garbage collection.
using System;

namespace Hedge.Tests
{
    public static class MeshEditTests
    {
        // A refused edit returns false / an invalid handle, throws nothing, and LastRefusal says why; the next
        // edit that is done clears it.
        [Test]
        static void RefusalsCarryTheirReason()
        {
            using (HalfEdgeMesh mesh = Meshes.Tet())
            {
                Check.Equal(null, mesh.LastRefusal, "nothing refused yet");
                Check.Equal(Vertex.Invalid, mesh.Collapse(new HalfEdge(0)));
                string why = mesh.LastRefusal;
                Check.Equal("a tip of its triangles would be left with too few edges", why, "the library's reason");
                Check.False(mesh.Flip(new Edge(1)));
                Check.Equal("an end is an interior vertex of valence 3 (the flip would leave it with 2)",
                            mesh.LastRefusal);
                Check.True(mesh.SplitEdge(new Edge(0), 0.5f, 0, 0).IsValid);
                Check.Equal(null, mesh.LastRefusal, "cleared by an edit that was done");
                Check.Valid(mesh);
            }
            // A seam vertex pulled off its seam: the reason names the seam.
            using (HalfEdgeMesh mesh = SeamTests.UvGrid(4, 2))
            {
                Vertex onSeam = new Vertex(12), off = new Vertex(13);  // (2, 2) and (3, 2)
                Check.Equal(new Vec3(2, 2, 0), mesh.GetPosition(onSeam));
                HalfEdge h = mesh.FindHalfEdge(onSeam, off);
                Check.False(mesh.CanCollapse(h));
                Check.Equal(Vertex.Invalid, mesh.Collapse(h));
                Check.True(mesh.LastRefusal.Contains("it would pull a seam vertex off its seam"), mesh.LastRefusal);
                Check.Equal(onSeam, mesh.Collapse(mesh.FindHalfEdge(off, onSeam)), "an off-seam vertex onto the seam");
                Check.Equal(null, mesh.LastRefusal);
                Check.Valid(mesh);
            }
        }

        [Test]
        static void TetrahedronCollapseRefused()
        {
            using (HalfEdgeMesh mesh = Meshes.Tet())
            {
                var before = new float[12];
                mesh.CopyPositions(before);
                MeshCounts counts = mesh.Counts;
                for (int i = 0; i < 12; ++i)
                {
                    var h = new HalfEdge(i);
                    Check.False(mesh.CanCollapse(h), "every tetrahedron edge is refused: " + h);
                    Check.Equal(Vertex.Invalid, mesh.Collapse(h), "refused, not thrown: " + h);
                }
                for (int e = 0; e < 6; ++e)
                {
                    Check.False(mesh.CanFlip(new Edge(e)), "valence-3 ends");
                    Check.False(mesh.Flip(new Edge(e)));
                }
                // Removing a face would leave a vertex with two fans? No: it leaves a valid open mesh.
                Check.True(mesh.CanRemoveFace(new Face(0)));
                Check.False(mesh.CanFillHole(new HalfEdge(0)), "not a boundary half-edge");
                Check.Equal(0, mesh.FillHole(new HalfEdge(0)), "refused fill makes no face");

                MeshCounts after = mesh.Counts;
                Check.True(counts.Equals(after), "counts unchanged: " + after);
                var now = new float[12];
                Check.Equal(12, mesh.CopyPositions(now));
                Check.Same(before, now, 12, "positions unchanged");
                Check.Valid(mesh);
            }
        }

        [Test]
        static void PyramidEdits()
        {
            using (HalfEdgeMesh mesh = Meshes.Pyramid())
            {
                Check.Equal(5, mesh.VertexCount);
                Check.Equal(8, mesh.EdgeCount);
                Check.Equal(4, mesh.FaceCount);
                var apex = new Vertex(4);
                Check.False(mesh.IsBoundary(apex));
                Check.Equal(4, mesh.Valence(apex));
                for (int v = 0; v < 4; ++v) Check.True(mesh.IsBoundary(new Vertex(v)), "base corner " + v);
                HalfEdge h01 = mesh.FindHalfEdge(new Vertex(0), new Vertex(1));
                Check.False(mesh.IsBoundary(h01), "0->1 runs along face (0, 1, 4)");
                Check.True(mesh.IsBoundary(h01.Twin));
                Check.Equal(Face.Invalid, mesh.GetFace(h01.Twin));
                Check.True(mesh.IsBoundary(h01.Edge));
                Check.True(mesh.IsBoundary(mesh.GetFace(h01)));
                Check.True(mesh.IsBoundary(mesh.GetHalfEdge(new Vertex(0))), "a boundary vertex starts at the gap");
                Check.Equal(3, mesh.GetVertexNeighbours(new Vertex(0), new Vertex[4]));
                Check.Equal(2, mesh.GetVertexFaces(new Vertex(0), new Face[4]));

                // SplitHalfEdge on the boundary edge 0-1: the triangle on it becomes two.
                Vertex m = mesh.SplitHalfEdge(h01, 0.5f, 0, 0);
                Check.True(m.IsValid);
                Check.Equal(5, m.Index);
                Check.Equal(new Vec3(0.5f, 0, 0), mesh.GetPosition(m));
                Check.Equal(6, mesh.VertexCount);
                Check.Equal(10, mesh.EdgeCount);
                Check.Equal(5, mesh.FaceCount);
                Check.Equal(3, mesh.Valence(m));
                Check.True(mesh.IsBoundary(m));
                Check.Equal(new Vertex(0), mesh.FromVertex(new HalfEdge(2 * h01.Edge.Index)));
                Check.Equal(m, mesh.ToVertex(new HalfEdge(2 * h01.Edge.Index)), "2e runs from the first vertex to m");
                Check.Valid(mesh, "after SplitHalfEdge");

                // Flip: the interior edge 1-4 between (m, 1, 4) and (1, 2, 4) turns into m-2.
                HalfEdge h14 = mesh.FindHalfEdge(new Vertex(1), new Vertex(4));
                Check.True(mesh.CanFlip(h14));
                Check.True(mesh.Flip(h14));
                Check.False(mesh.FindHalfEdge(new Vertex(1), new Vertex(4)).IsValid, "1-4 is gone");
                HalfEdge hm2 = mesh.FindHalfEdge(m, new Vertex(2));
                Check.True(hm2.IsValid, "m-2 exists");
                Check.Equal(h14.Edge, hm2.Edge, "the flipped edge keeps its index");
                Check.Equal(10, mesh.EdgeCount);
                Check.Equal(2, mesh.Valence(new Vertex(1)));
                Check.Valid(mesh, "after Flip");

                // A boundary edge cannot be flipped: refused, false, nothing changed.
                Check.False(mesh.Flip(h01.Twin));
                Check.Equal(10, mesh.EdgeCount);

                // Collapse of m into 0 along the boundary: m's boundary triangle (m, 4, 0) goes.
                HalfEdge hm0 = mesh.FindHalfEdge(m, new Vertex(0));
                Check.True(mesh.CanCollapse(hm0), "m -> 0 is legal");
                Vertex survivor = mesh.Collapse(hm0);
                Check.Equal(new Vertex(0), survivor);
                Check.Equal(new Vec3(0, 0, 0), mesh.GetPosition(survivor), "the survivor keeps its position");
                Check.True(mesh.IsDeleted(m));
                Check.Throws(HedgeStatus.BadHandle, () => mesh.GetPosition(m), "a deleted vertex");
                Check.Equal(5, mesh.VertexCount);
                Check.Equal(8, mesh.EdgeCount);
                Check.Equal(4, mesh.FaceCount);
                Check.Valid(mesh, "after Collapse");

                // SplitFace at a point: 1 face becomes 3.
                Face f = mesh.GetFace(mesh.FindHalfEdge(new Vertex(2), new Vertex(3)));
                Check.True(mesh.CanSplitFace(f));
                Vertex c = mesh.SplitFace(f, 0.5f, 0.8f, 0.3f);
                Check.True(c.IsValid);
                Check.Equal(3, mesh.Valence(c));
                Check.Equal(6, mesh.FaceCount);
                Check.Equal(11, mesh.EdgeCount);
                Check.Valid(mesh, "after SplitFace");

                // SplitAllFaces: every face into three around its centroid.
                var added = new Vertex[mesh.FaceCount];
                Check.Equal(6, mesh.SplitAllFaces(added));
                for (int i = 0; i < added.Length; ++i) Check.Equal(3, mesh.Valence(added[i]));
                Check.Equal(18, mesh.FaceCount);
                Check.Equal(12, mesh.VertexCount);
                Check.Throws(HedgeStatus.BufferTooSmall, () => mesh.SplitAllFaces(new Vertex[3]), "nothing split");
                Check.Equal(18, mesh.FaceCount);
                Check.Valid(mesh, "after SplitAllFaces");

                // RemoveFace then AddFace the same corners: back to the same counts.
                Face boundaryFace = mesh.GetFace(mesh.FindHalfEdge(new Vertex(3), new Vertex(0)));
                var corners = new Vertex[3];
                Check.Equal(3, mesh.GetFaceVertices(boundaryFace, corners));
                Check.True(mesh.CanRemoveFace(boundaryFace));
                Check.True(mesh.RemoveFace(boundaryFace));
                Check.Equal(17, mesh.FaceCount);
                Check.Throws(HedgeStatus.BadHandle, () => mesh.RemoveFace(boundaryFace), "already removed");
                Check.True(mesh.CanAddFace(corners));
                Face back = mesh.AddFace(corners[0], corners[1], corners[2]);
                Check.True(back.IsValid);
                Check.Equal(18, mesh.FaceCount);
                Check.Same(Meshes.Rotated(corners, 3), Meshes.Corners(mesh, back), 3, "the new face's corners");
                Check.False(mesh.CanAddFace(corners), "the same face twice");
                Check.Equal(Face.Invalid, mesh.AddFace(corners), "refused");
                Check.Valid(mesh, "after RemoveFace and AddFace");

                // FillHole: close the base (a loop of 4 boundary edges: 2 triangles).
                HalfEdge gap = mesh.FindHalfEdge(new Vertex(0), new Vertex(1)).Twin;
                Check.True(mesh.IsBoundary(gap));
                Check.True(mesh.CanFillHole(gap));
                var filled = new Face[2];
                Check.Equal(2, mesh.FillHole(gap, filled));
                Check.True(filled[0].IsValid && filled[1].IsValid);
                Check.Equal(20, mesh.FaceCount);
                MeshCounts k = mesh.Counts;
                Check.Equal(2L, (long)k.Vertices - k.Edges + k.Faces, "a closed sphere: V - E + F = 2");
                for (int v = 0; v < 4; ++v) Check.False(mesh.IsBoundary(new Vertex(v)));
                Check.Valid(mesh, "after FillHole");

                // RemoveVertex of the apex takes its faces.
                Check.True(mesh.CanRemoveVertex(apex));
                int apexFaces = mesh.GetVertexFaces(apex, null);
                Check.True(mesh.RemoveVertex(apex));
                Check.Equal(20 - apexFaces, mesh.FaceCount);
                Check.Valid(mesh, "after RemoveVertex");
            }
        }

        [Test]
        static void GridPolygonsAndDiagonals()
        {
            using (HalfEdgeMesh mesh = Meshes.Grid())
            {
                Check.Equal(9, mesh.VertexCount);
                Check.Equal(12, mesh.EdgeCount);
                Check.Equal(4, mesh.FaceCount);
                Check.Equal(4, mesh.Valence(new Face(0)));
                Check.Equal("[0, 1, 4, 3]", Meshes.Show(Meshes.Corners(mesh, new Face(0))));
                Check.Equal(4, mesh.Valence(new Vertex(4)), "the centre");
                Check.False(mesh.IsBoundary(new Vertex(4)));

                var loop = new HalfEdge[4];
                Check.Equal(4, mesh.GetFaceHalfEdges(new Face(0), loop));
                // Adjacent corners: refused.
                Check.False(mesh.CanCutFace(loop[0], loop[1]));
                Check.Equal(HalfEdge.Invalid, mesh.CutFace(loop[0], loop[1]));
                Check.Equal(4, mesh.FaceCount);
                // Opposite corners: a new diagonal.
                Check.True(mesh.CanCutFace(loop[0], loop[2]));
                HalfEdge d = mesh.CutFace(loop[0], loop[2]);
                Check.True(d.IsValid);
                Check.Equal(mesh.ToVertex(loop[0]), mesh.FromVertex(d));
                Check.Equal(mesh.ToVertex(loop[2]), mesh.ToVertex(d));
                Check.Equal(5, mesh.FaceCount);
                Check.Equal(13, mesh.EdgeCount);
                Check.Equal(3, mesh.Valence(mesh.GetFace(d)));
                Check.Equal(3, mesh.Valence(mesh.GetFace(d.Twin)));
                Check.Valid(mesh, "after the diagonal");

                // A quad split at a point: 4 triangles.
                Vertex c = mesh.SplitFace(new Face(3), 1.5f, 1.5f, 0);
                Check.Equal(4, mesh.Valence(c));
                Check.Equal(8, mesh.FaceCount);
                Check.Valid(mesh, "after SplitFace of a quad");

                // Moving a vertex.
                mesh.SetPosition(new Vertex(4), 1, 1, 0.25f);
                Check.Equal(new Vec3(1, 1, 0.25f), mesh.GetPosition(new Vertex(4)));
                Check.Throws(HedgeStatus.InvalidArgument, () => mesh.SetPosition(new Vertex(4), float.NaN, 0, 0));
                Check.Equal(new Vec3(1, 1, 0.25f), mesh.GetPosition(new Vertex(4)), "unchanged by the NaN");
                Check.Valid(mesh);
            }
        }

        [Test]
        static void DetachAndGarbageCollection()
        {
            using (HalfEdgeMesh mesh = Meshes.Grid())
            {
                var origin = new Vertex[8];
                using (HalfEdgeMesh piece = mesh.DetachFaces(new[] { new Face(3), new Face(3) }, 2, origin))
                {
                    Check.Equal(1, piece.FaceCount, "a repeated face counts once");
                    Check.Equal(4, piece.VertexCount);
                    Check.Equal(3, mesh.FaceCount);
                    var fromOrigin = new int[4];
                    for (int i = 0; i < 4; ++i)
                    {
                        int o = origin[i].Index;
                        fromOrigin[i] = o;
                        var expected = new Vec3(Meshes.GridPositions[3 * o], Meshes.GridPositions[3 * o + 1],
                                                Meshes.GridPositions[3 * o + 2]);
                        Check.Equal(expected, piece.GetPosition(new Vertex((int)i)),
                                    "the piece keeps the positions of its origins");
                    }
                    Array.Sort(fromOrigin);
                    Check.Equal("[4, 5, 7, 8]", Meshes.Show(fromOrigin));
                    Check.Valid(piece, "the detached piece");
                    Check.Valid(mesh, "the rest");
                }
                Check.Throws(HedgeStatus.BufferTooSmall, () => mesh.DetachFaces(new[] { new Face(0) }, 1, new Vertex[2]));
                Check.Equal(3, mesh.FaceCount, "nothing detached");

                // Deleted slots stay until garbage collection, which returns old -> new maps.
                MeshCounts before = mesh.Counts;
                Check.True(before.VertexSlots == 9 && before.Vertices == 8, before.ToString());
                var positions = new float[3 * before.VertexSlots];
                mesh.CopyPositions(positions);
                var vmap = new Vertex[before.VertexSlots];
                var hmap = new HalfEdge[before.HalfEdgeSlots];
                var emap = new Edge[before.EdgeSlots];
                var fmap = new Face[before.FaceSlots];
                Check.Throws(HedgeStatus.BufferTooSmall, () => mesh.GarbageCollection(new Vertex[3]));
                mesh.GarbageCollection(vmap, hmap, emap, fmap);
                MeshCounts after = mesh.Counts;
                Check.Equal(after.Vertices, after.VertexSlots);
                Check.Equal(after.Edges, after.EdgeSlots);
                Check.Equal(after.Faces, after.FaceSlots);
                Check.Equal(before.Vertices, after.Vertices);
                Check.Equal(Vertex.Invalid, vmap[8], "vertex 8 went with the detached face");
                for (int v = 0; v < 8; ++v)
                {
                    Check.True(vmap[v].IsValid && vmap[v].Index < after.VertexSlots);
                    Check.Equal(new Vec3(positions[3 * v], positions[3 * v + 1], positions[3 * v + 2]),
                                mesh.GetPosition(vmap[v]), "moved with its map entry");
                }
                Check.Equal(Face.Invalid, fmap[3]);
                Check.Valid(mesh, "after garbage collection");
            }
        }
    }
}
