// Handles, struct layouts, adjacency queries and circulators, the Unity quad and the original project's names.
using System;
using System.Collections.Generic;
using System.Linq;
using System.Runtime.InteropServices;

namespace Hedge.Tests
{
    public static class MeshTests
    {
        // The original project's quad as a Unity Mesh holds it: with the Unity options the mesh holds Unity's
        // own coordinates, a vertex set to (1, 0.5, 0) lands at (1, 0.5, 0) in the buffers, computed normals
        // point to -z as Unity's RecalculateNormals gives, and the triangles come back in the same winding.
        [Test]
        static void UnityQuadKeepsTheUsersCoordinates()
        {
            float[] p = { 0, 0, 0, 0, 1, 0, 1, 0, 0, 1, 1, 0 };
            int[] triangles = { 0, 1, 2, 2, 1, 3 };
            BuildReport report;
            using (var mesh = HalfEdgeMesh.FromEngineMesh(p, triangles, null, null, null, EngineImportOptions.Unity, out report))
            {
                for (int i = 0; i < 4; ++i)
                {
                    Vec3 q = mesh.GetPosition(new Vertex((int)i));
                    Check.True(q.X == p[3 * i] && q.Y == p[3 * i + 1] && q.Z == p[3 * i + 2], "vertex " + i + " bit for bit");
                }
                mesh.SetPosition(new Vertex(2), 1, 0.5f, 0);
                using (RenderBuffers unity = mesh.GenerateUnityMesh())
                {
                    var positions = new float[3 * unity.Counts.VertexSlots];
                    var normals = new float[3 * unity.Counts.VertexSlots];
                    var indices = new int[unity.Counts.IndexCount];
                    unity.CopyStream(VertexStream.Vertices, positions);
                    unity.CopyStream(VertexStream.Normals, normals);
                    unity.CopyIndices(indices);
                    Check.Equal(6, indices.Length);
                    float[] want = { 0, 0, 0, 0, 1, 0, 1, 0.5f, 0, 1, 0.5f, 0, 0, 1, 0, 1, 1, 0 };
                    for (int c = 0; c < 6; ++c)
                    {
                        int r = indices[c];
                        Check.True(positions[3 * r] == want[3 * c] && positions[3 * r + 1] == want[3 * c + 1] &&
                                   positions[3 * r + 2] == want[3 * c + 2], "corner " + c + " in the user's axes and winding");
                        Check.True(normals[3 * r] == 0 && normals[3 * r + 1] == 0 && normals[3 * r + 2] < -0.99f,
                                   "computed normals point to -z, as in Unity");
                    }
                }
                Check.Valid(mesh, "the Unity quad");
            }
        }

        // The original project's names do exactly what the names they stand for do: the same edits on two
        // copies of one mesh give the same results.
        [Test]
        static void OriginalNamesForward()
        {
            float[] positions = { 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0.5f, 0.5f, 1 };
            int[] triangles = { 0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4 };
            using (var a = HalfEdgeMesh.FromTriangles(positions, triangles))
            using (var b = HalfEdgeMesh.FromTriangles(positions, triangles))
            {
                HalfEdge h01 = a.FindHalfEdge(new Vertex(0), new Vertex(1));
                Vertex ma = a.SplitHalfEdge(h01, 0.5f, 0, 0);
                Vertex mb = b.SplitEdge(h01.Edge, 0.5f, 0, 0);
                Check.Equal(mb, ma, "SplitHalfEdge is SplitEdge");
                Check.Equal(new Vertex(5), ma);
                Check.Equal(b.Counts.ToString(), a.Counts.ToString());
                HalfEdge hm0 = a.FindHalfEdge(ma, new Vertex(0));
                Check.Equal(b.Collapse(hm0), a.EdgeCollapse(hm0), "EdgeCollapse is Collapse");
                Check.Equal(b.Counts.ToString(), a.Counts.ToString());
                Check.Equal(4, a.FaceCount);
                using (RenderBuffers unity = a.GenerateUnityMesh())
                {
                    Check.True(!unity.Options.FlipX && unity.Options.Winding == Winding.CounterClockwise && !unity.Options.Interleaved,
                               "GenerateUnityMesh keeps Unity's coordinates and triangles, one stream per attribute");
                }
                Check.Valid(a, "after the original's names");
                Check.Valid(b, "after hedge's names");
            }
        }

        [Test]
        static void VersionAndLayouts()
        {
            Check.Equal(Context.ExpectedVersion, HalfEdgeMesh.LibraryVersion.ToString(3), "library version");

            // The sizes and offsets the header documents for each struct.
            Check.Equal(4, Marshal.SizeOf(typeof(Vertex)));
            Check.Equal(4, Marshal.SizeOf(typeof(HalfEdge)));
            Check.Equal(4, Marshal.SizeOf(typeof(Edge)));
            Check.Equal(4, Marshal.SizeOf(typeof(Face)));
            Check.Equal(12, Marshal.SizeOf(typeof(Vec3)));
            Check.Equal(16, Marshal.SizeOf(typeof(BuildOptions)), "hedge_build_options");
            Check.Equal(8, (int)Marshal.OffsetOf(typeof(BuildOptions), "WeldEpsilon"));
            Check.Equal(36, Marshal.SizeOf(typeof(BuildReport)), "hedge_build_report");
            Check.Equal(32, (int)Marshal.OffsetOf(typeof(BuildReport), "Repairs"));
            Check.Equal(32, Marshal.SizeOf(typeof(MeshCounts)), "hedge_counts");
            Check.Equal(48, Marshal.SizeOf(typeof(MeshGeometry)), "hedge_geometry");
            Check.Equal(32, Marshal.SizeOf(typeof(SmoothOptions)), "hedge_smooth_options");
            Check.Equal(16, (int)Marshal.OffsetOf(typeof(SmoothOptions), "Mu"));
            Check.Equal(80, Marshal.SizeOf(typeof(DecimateOptions)), "hedge_decimate_options");
            Check.Equal(56, (int)Marshal.OffsetOf(typeof(DecimateOptions), "MaxNormalChangeDegrees"));
            Check.Equal(72, (int)Marshal.OffsetOf(typeof(DecimateOptions), "relaxNormalChange"));
            Check.Equal(64, Marshal.SizeOf(typeof(DecimateResult)), "hedge_decimate_result");
            Check.Equal(32, (int)Marshal.OffsetOf(typeof(DecimateResult), "Stop"));
            Check.Equal(56, (int)Marshal.OffsetOf(typeof(DecimateResult), "RefusedShape"));
            Check.Equal(24, (int)Marshal.OffsetOf(typeof(MeshGeometry), "BoxMin"));
            Check.Equal(24, Marshal.SizeOf(typeof(RenderOptions)), "hedge_render_buffers_options");
            Check.Equal(16, (int)Marshal.OffsetOf(typeof(RenderOptions), "Winding"));
            Check.Equal(32, Marshal.SizeOf(typeof(VertexLayout)), "hedge_vertex_layout");
            Check.Equal(8, Marshal.SizeOf(typeof(SlotRange)), "hedge_range");
            Check.Equal(40, Marshal.SizeOf(typeof(SyncResult)), "hedge_sync_result");
            Check.Equal(16, (int)Marshal.OffsetOf(typeof(SyncResult), "VertexRangeCount"));
            Check.Equal(32, (int)Marshal.OffsetOf(typeof(SyncResult), "resized"));
            Check.Equal(40, Marshal.SizeOf(typeof(BufferCounts)), "hedge_buffer_counts");
            Check.Equal(24, (int)Marshal.OffsetOf(typeof(BufferCounts), "BufferBytes"));
            Check.Equal(24, Marshal.SizeOf(typeof(EngineImportOptions)), "hedge_engine_import_options");
            Check.Equal(8, (int)Marshal.OffsetOf(typeof(EngineImportOptions), "WeldEpsilon"));
            Check.Equal(16, (int)Marshal.OffsetOf(typeof(EngineImportOptions), "Winding"));

            // The defaults come from the library.
            BuildOptions b = BuildOptions.Default;
            Check.Equal(TopologyPolicy.Repair, b.Policy);
            Check.Equal(Weld.None, b.Weld);
            Check.Equal(1e-6, b.WeldEpsilon);
            RenderOptions ro = RenderOptions.Default;
            Check.Equal(NormalSource.Automatic, ro.Normals);
            Check.True(ro.Texcoords && ro.Colors && ro.Interleaved && !ro.FlipX);
            Check.Equal(Winding.CounterClockwise, ro.Winding);
            RenderOptions unity = RenderOptions.Unity;
            Check.True(!unity.FlipX && !unity.Interleaved);
            Check.Equal(Winding.CounterClockwise, unity.Winding);
            EngineImportOptions e = EngineImportOptions.Default;
            Check.Equal(Weld.Exact, e.Weld);
            Check.Equal(TopologyPolicy.Repair, e.Policy);
            Check.Equal(Winding.CounterClockwise, e.Winding);
            Check.False(e.FlipX);
            Check.False(EngineImportOptions.Unity.FlipX);
            Check.Equal(Winding.CounterClockwise, EngineImportOptions.Unity.Winding);
        }

        [Test]
        static void HandleArithmetic()
        {
            var h = new HalfEdge(5);
            Check.Equal(new HalfEdge(4), h.Twin);
            Check.Equal(new Edge(2), h.Edge);
            Check.Equal(h, new Edge(2).GetHalfEdge(1));
            Check.Equal(new HalfEdge(4), new Edge(2).GetHalfEdge(0));
            Check.False(HalfEdge.Invalid.IsValid);
            Check.Equal(HalfEdge.Invalid, HalfEdge.Invalid.Twin);
            Check.Equal(Edge.Invalid, HalfEdge.Invalid.Edge);
            Check.Equal(-1, Vertex.Invalid.Index);
            Check.True(new Vertex(3) == new Vertex(3) && new Face(1) != new Face(2));
            Check.Equal("h5", h.ToString());
            Check.ThrowsType<ArgumentOutOfRangeException>(() => new Edge(1).GetHalfEdge(2));
        }

        [Test]
        static void TetrahedronAdjacency()
        {
            using (HalfEdgeMesh mesh = Meshes.Tet())
            {
                MeshCounts c = mesh.Counts;
                Check.Equal(4, c.Vertices);
                Check.Equal(12, c.HalfEdges);
                Check.Equal(6, c.Edges);
                Check.Equal(4, c.Faces);
                Check.Equal(4, c.VertexSlots);
                Check.Equal(4, mesh.FaceCount);
                Check.Equal(new Vec3(0, 0, 1), mesh.GetPosition(new Vertex(3)));

                for (int i = 0; i < 12; ++i)
                {
                    var h = new HalfEdge(i);
                    Check.Equal(h.Twin, mesh.Twin(h), "twin is h ^ 1");
                    Check.Equal(h.Edge, mesh.GetEdge(h), "edge is h / 2");
                    Check.Equal(h, mesh.Next(mesh.Next(mesh.Next(h))), "triangle loops close after 3");
                    Check.Equal(h, mesh.Prev(mesh.Next(h)));
                    Check.Equal(mesh.FromVertex(h), mesh.ToVertex(mesh.Twin(h)));
                    Check.Equal(mesh.ToVertex(h), mesh.FromVertex(mesh.Next(h)));
                    Check.True(mesh.GetFace(h).IsValid && !mesh.IsBoundary(h));
                    Check.Equal(mesh.GetFace(h), mesh.GetFace(mesh.Next(h)));
                }
                for (int e = 0; e < 6; ++e)
                {
                    Check.Equal(new HalfEdge(2 * e + 1), mesh.GetHalfEdge(new Edge(e), 1));
                    Check.False(mesh.IsBoundary(new Edge(e)));
                }

                // Circulators into caller arrays; the same arrays for every call.
                var ring = new Vertex[8];
                var spokes = new HalfEdge[8];
                var faces = new Face[8];
                for (int v = 0; v < 4; ++v)
                {
                    var vertex = new Vertex(v);
                    Check.Equal(3, mesh.Valence(vertex));
                    Check.False(mesh.IsBoundary(vertex));
                    Check.Equal(vertex, mesh.FromVertex(mesh.GetHalfEdge(vertex)));
                    Check.Equal(3, mesh.GetVertexNeighbours(vertex, ring));
                    Check.Equal(3, mesh.GetVertexHalfEdges(vertex, spokes));
                    Check.Equal(3, mesh.GetVertexFaces(vertex, faces));
                    for (int k = 0; k < 3; ++k)
                    {
                        Check.Equal(vertex, mesh.FromVertex(spokes[k]));
                        Check.Equal(ring[k], mesh.ToVertex(spokes[k]), "neighbours follow the outgoing half-edges");
                    }
                    var expected = new List<int> { 0, 1, 2, 3 };
                    expected.Remove(v);
                    Check.Same(expected.ToArray(), Meshes.Sorted(ring, 3), 3, "one-ring of " + v);
                }
                Check.Equal(3, mesh.GetVertexNeighbours(new Vertex(0), null), "null asks for the count");
                Check.Equal("[0, 2, 1]", Meshes.Show(Meshes.Corners(mesh, new Face(0))), "face 0 as built");
                var loop = new HalfEdge[3];
                Check.Equal(3, mesh.GetFaceHalfEdges(new Face(0), loop));
                var corners = new Vertex[3];
                mesh.GetFaceVertices(new Face(0), corners);
                for (int k = 0; k < 3; ++k) Check.Equal(corners[k], mesh.ToVertex(loop[k]));
                Check.Equal(loop[0], mesh.GetHalfEdge(new Face(0)));
                Check.Equal(3, mesh.Valence(new Face(0)));
                Check.False(mesh.IsBoundary(new Face(0)));

                HalfEdge h01 = mesh.FindHalfEdge(new Vertex(0), new Vertex(1));
                Check.True(h01.IsValid);
                Check.Equal(new Vertex(0), mesh.FromVertex(h01));
                Check.Equal(new Vertex(1), mesh.ToVertex(h01));

                // An array too small: BufferTooSmall, and nothing written.
                var small = new Vertex[] { new Vertex(77), new Vertex(77) };
                Check.Throws(HedgeStatus.BufferTooSmall, () => mesh.GetVertexNeighbours(new Vertex(0), small));
                Check.Equal(new Vertex(77), small[0], "untouched");
                Check.Valid(mesh);
            }
        }
    }
}
