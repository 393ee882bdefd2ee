// Engine meshes with tangents and lightmap UVs (Runtime/EngineStreams.cs): the import, the two new
// vertex streams of render buffers, their mirrors after edits, and the errors of bad streams.
using System;
using System.Runtime.InteropServices;

namespace Hedge.Tests
{
    public static class EngineStreamsTests
    {
        /// <summary>A 3 x 3 grid of quads in the plane z = 0 (16 engine vertices, 18 triangles), with
        /// normals +z, tangents +x (handedness +1), texcoords and lightmap UVs that differ.</summary>
        public static EngineStreams Grid()
        {
            const int n = 4;
            var s = new EngineStreams(new float[3 * n * n], new int[6 * (n - 1) * (n - 1)]);
            s.Normals = new float[3 * n * n];
            s.Texcoords = new float[2 * n * n];
            s.Tangents = new float[4 * n * n];
            s.Texcoords1 = new float[2 * n * n];
            for (int y = 0; y < n; ++y)
                for (int x = 0; x < n; ++x)
                {
                    int v = y * n + x;
                    s.Positions[3 * v] = x;
                    s.Positions[3 * v + 1] = y;
                    s.Normals[3 * v + 2] = 1;
                    s.Texcoords[2 * v] = x / 3f;
                    s.Texcoords[2 * v + 1] = y / 3f;
                    s.Tangents[4 * v] = 1;
                    s.Tangents[4 * v + 3] = 1;
                    s.Texcoords1[2 * v] = 0.5f + x / 6f;
                    s.Texcoords1[2 * v + 1] = y / 6f;
                }
            int t = 0;
            for (int y = 0; y + 1 < n; ++y)
                for (int x = 0; x + 1 < n; ++x)
                {
                    int a = y * n + x, b = a + 1, c = a + n + 1, d = a + n;
                    int[] quad = { a, b, c, a, c, d };
                    foreach (int i in quad) s.Triangles[t++] = i;
                }
            return s;
        }

        [Test]
        static void LayoutAndStreams()
        {
            Check.Equal(8 + 8 * IntPtr.Size, Marshal.SizeOf(typeof(Native.EngineStreamsData)), "hedge_engine_streams");
            using (var mesh = HalfEdgeMesh.FromEngineMesh(Grid(), EngineImportOptions.Unity))
            {
                using (var whole = mesh.CreateRenderBuffers())
                {
                    VertexLayout l = whole.Layout;
                    Check.True(l.Interleaved && l.HasTangents && l.HasTexcoords1);
                    Check.Equal(8, l.Tangent, "after position, normal and texcoord (no colours)");
                    Check.Equal(12, l.Texcoord1);
                    Check.Equal(14, l.Stride);
                }
                using (var buffers = mesh.CreateRenderBuffers(RenderOptions.Unity))
                {
                    VertexLayout l = buffers.Layout;
                    Check.True(!l.Interleaved && l.Tangent == 0 && l.Texcoord1 == 0);
                    Check.Equal(4, buffers.Components(VertexStream.Tangents));
                    Check.Equal(2, buffers.Components(VertexStream.Texcoords1));
                    int slots = buffers.Counts.VertexSlots;
                    Check.Equal(16, slots, "no seams: one render vertex per engine vertex");
                    var tangents = new float[4 * slots];
                    var uv2 = new float[2 * slots];
                    Check.Equal(4 * slots, buffers.CopyStream(VertexStream.Tangents, tangents));
                    Check.Equal(2 * slots, buffers.CopyStream(VertexStream.Texcoords1, uv2));
                    var source = new Vertex[slots];
                    buffers.CopyVertexSource(source);
                    var engine = new int[mesh.Counts.VertexSlots];
                    mesh.CopyVertexSourceIndices(engine);
                    EngineStreams s = Grid();
                    for (int r = 0; r < slots; ++r)
                    {
                        int e = engine[source[r].Index];
                        Check.Equal(s.Texcoords1[2 * e], uv2[2 * r], "uv2.x of render vertex " + r);
                        Check.Equal(s.Texcoords1[2 * e + 1], uv2[2 * r + 1], "uv2.y of render vertex " + r);
                        Check.Equal(1f, tangents[4 * r], "tangent x");
                        Check.Equal(1f, tangents[4 * r + 3], "handedness");
                    }
                }
            }
            // Without tangents or a second channel, neither stream exists.
            EngineStreams plain = Grid();
            plain.Tangents = null;
            plain.Texcoords1 = null;
            using (var mesh = HalfEdgeMesh.FromEngineMesh(plain, EngineImportOptions.Unity))
            using (var buffers = mesh.CreateRenderBuffers(RenderOptions.Unity))
            {
                Check.False(buffers.Layout.HasTangents || buffers.Layout.HasTexcoords1);
                Check.Equal(0, buffers.CopyStream(VertexStream.Tangents, new float[4]));
            }
        }

        // Every render vertex the index buffer uses has a unit tangent perpendicular to its normal.
        static void CheckFrames(RenderBuffers buffers, float[] normals, float[] tangents, int[] indices, string when)
        {
            int n = buffers.Counts.IndexCount;
            for (int i = 0; i < n; i += 3)
            {
                if (indices[i] == indices[i + 1]) continue;  // a free slot
                for (int k = 0; k < 3; ++k)
                {
                    int r = indices[i + k];
                    var nr = new Vec3(normals[3 * r], normals[3 * r + 1], normals[3 * r + 2]);
                    var t = new Vec3(tangents[4 * r], tangents[4 * r + 1], tangents[4 * r + 2]);
                    Check.Near(0, Vec3.Dot(nr, t), 1e-5, when + ": tangent . normal of render vertex " + r);
                    Check.Near(1, t.Length, 1e-4, when + ": |tangent| of render vertex " + r);
                    Check.True(tangents[4 * r + 3] == 1, when + ": handedness kept");
                }
            }
        }

        static void CheckMirror(RenderBuffers buffers, VertexStream stream, ref float[] mirror, bool partial,
                                string when)
        {
            Check.Equal(partial, buffers.UpdateVertexMirror(stream, ref mirror), when + ": partial copy of " + stream);
            var whole = new float[buffers.CopyStream(stream, null)];
            buffers.CopyStream(stream, whole);
            Check.Same(whole, mirror, whole.Length, when + ": mirror of " + stream);
        }

        [Test]
        static void MirrorsFollowEdits()
        {
            using (var mesh = HalfEdgeMesh.FromEngineMesh(Grid(), EngineImportOptions.Unity))
            using (var buffers = mesh.CreateRenderBuffers(RenderOptions.Unity))
            {
                float[] normals = null, tangents = null, uv2 = null;
                int[] indices = null;
                CheckMirror(buffers, VertexStream.Normals, ref normals, false, "first copy");
                CheckMirror(buffers, VertexStream.Tangents, ref tangents, false, "first copy");
                CheckMirror(buffers, VertexStream.Texcoords1, ref uv2, false, "first copy");
                buffers.UpdateIndexMirror(ref indices);
                CheckFrames(buffers, normals, tangents, indices, "imported");

                // Lift an inner vertex: the normals about it follow, their tangents are turned with them.
                Check.Equal(new Vec3(1, 1, 0), mesh.GetPosition(new Vertex(5)), "vertices in engine order");
                mesh.SetPosition(new Vertex(5), 1, 1, 0.4f);
                buffers.Sync();
                CheckMirror(buffers, VertexStream.Normals, ref normals, true, "lift");
                CheckMirror(buffers, VertexStream.Tangents, ref tangents, true, "lift");
                CheckMirror(buffers, VertexStream.Texcoords1, ref uv2, true, "lift");
                buffers.UpdateIndexMirror(ref indices);
                CheckFrames(buffers, normals, tangents, indices, "lift");
                // (0, 1) beside it: its normal leans towards -x, so its tangent along x leaves the plane.
                Check.True(tangents[4 * buffers.GetRenderVertex(mesh.FindHalfEdge(new Vertex(5), new Vertex(4))) + 2] != 0,
                           "the neighbour's tangent turned with its normal");

                // Split the edge (1, 1)-(2, 1): the new corners get interpolated lightmap UVs and tangents.
                Edge e = mesh.FindHalfEdge(new Vertex(5), new Vertex(6)).Edge;
                Vertex mid = mesh.SplitEdge(e, 1.5f, 1, 0.2f);
                Check.True(mid.IsValid);
                buffers.Sync();
                CheckMirror(buffers, VertexStream.Tangents, ref tangents, true, "split");
                CheckMirror(buffers, VertexStream.Texcoords1, ref uv2, true, "split");
                CheckMirror(buffers, VertexStream.Normals, ref normals, true, "split");
                buffers.UpdateIndexMirror(ref indices);
                CheckFrames(buffers, normals, tangents, indices, "split");
                int rv = buffers.GetRenderVertex(mesh.FindHalfEdge(new Vertex(5), mid));
                Check.Near(0.5f + 1.5f / 6f, uv2[2 * rv], 1e-6, "uv2.x of the split's corner");
                Check.Near(1f / 6f, uv2[2 * rv + 1], 1e-6, "uv2.y of the split's corner");

                // Collapse it into (2, 1) again.
                HalfEdge h = mesh.FindHalfEdge(mid, new Vertex(6));
                Check.True(mesh.CanCollapse(h));
                Check.True(mesh.Collapse(h).IsValid);
                buffers.Sync();
                CheckMirror(buffers, VertexStream.Tangents, ref tangents, true, "collapse");
                CheckMirror(buffers, VertexStream.Texcoords1, ref uv2, true, "collapse");
                CheckMirror(buffers, VertexStream.Normals, ref normals, true, "collapse");
                buffers.UpdateIndexMirror(ref indices);
                CheckFrames(buffers, normals, tangents, indices, "collapse");

                // Keeping the mirrors allocates nothing.
                for (int round = 0; round < 2; ++round)  // round 0 warms up (JIT), round 1 is measured
                {
                    long before = GC.GetAllocatedBytesForCurrentThread();
                    for (int i = 0; i < 50; ++i)
                    {
                        mesh.SetPosition(new Vertex(10), 2, 2, 0.01f * i);
                        buffers.Sync();
                        buffers.UpdateVertexMirror(VertexStream.Tangents, ref tangents);
                        buffers.UpdateVertexMirror(VertexStream.Texcoords1, ref uv2);
                    }
                    long allocated = GC.GetAllocatedBytesForCurrentThread() - before;
                    if (round == 1) Check.Equal(0L, allocated, "bytes allocated by 50 edits and tangent/uv2 mirror updates");
                }
                Check.Valid(mesh);
            }
        }

        [Test]
        static void BadStreams()
        {
            EngineStreams s = Grid();
            s.Tangents = new float[4 * 15];
            Check.Contains(Check.ThrowsType<ArgumentException>(
                               () => HalfEdgeMesh.FromEngineMesh(s, EngineImportOptions.Unity)).Message,
                           "64 expected (4 per vertex)");
            s = Grid();
            s.Texcoords1 = new float[3];
            Check.ThrowsType<ArgumentException>(() => HalfEdgeMesh.FromEngineMesh(s, EngineImportOptions.Unity));
            s = Grid();
            s.Tangents[4 * 7 + 1] = float.NaN;
            HedgeException error = Check.Throws(HedgeStatus.InvalidArgument,
                                                () => HalfEdgeMesh.FromEngineMesh(s, EngineImportOptions.Unity));
            Check.Contains(error.Message, "tangent of vertex 7");
            s = Grid();
            s.TriangleSubmeshes = new int[17];
            Check.ThrowsType<ArgumentException>(() => HalfEdgeMesh.FromEngineMesh(s, EngineImportOptions.Unity));
            s.TriangleSubmeshes = new int[18];
            s.TriangleSubmeshes[3] = 2;
            using (var mesh = HalfEdgeMesh.FromEngineMesh(s, EngineImportOptions.Unity))
            {
                Check.Equal(2, mesh.GetSubmesh(new Face(3)));
                Check.Valid(mesh);
            }
            Check.ThrowsType<ArgumentNullException>(() => HalfEdgeMesh.FromEngineMesh(null, EngineImportOptions.Unity));
            Check.ThrowsType<ArgumentNullException>(
                () => HalfEdgeMesh.FromEngineMesh(new EngineStreams(null, new int[0]), EngineImportOptions.Unity));
        }
    }
}
