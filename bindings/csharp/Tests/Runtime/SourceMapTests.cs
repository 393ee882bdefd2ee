// The map back to the engine mesh: FromEngineMesh welds and renumbers vertices, and the source
// indices say which engine (Unity) vertex each hedge vertex and corner came from, so user data
// keyed by the engine's vertex index is found again, also after edits and garbage collection.
using System;

namespace Hedge.Tests
{
    public static class SourceMapTests
    {
        // A 2 x 1 strip of quads (6 positions) with a UV seam along x = 1: the right quad's corners at
        // x = 1 are engine vertices 0 and 1, duplicates listed first, so welding must renumber.
        static readonly float[] Positions = { 1, 0, 0, 1, 1, 0,  // 0, 1: seam copies (right side)
                                              0, 0, 0, 1, 0, 0, 2, 0, 0, 0, 1, 0, 1, 1, 0, 2, 1, 0 };
        static readonly float[] Texcoords = { 0.5f, 0, 0.5f, 1, 0, 0, 0.4f, 0, 1, 0, 0, 1, 0.4f, 1, 1, 1 };
        //   left quad: 2 3 6 5, right quad: 0 4 7 1
        static readonly int[] Triangles = { 2, 3, 6, 2, 6, 5, 0, 4, 7, 0, 7, 1 };

        static Vec3 EnginePosition(int i) { return new Vec3(Positions[3 * i], Positions[3 * i + 1], Positions[3 * i + 2]); }

        static Vertex VertexAt(HalfEdgeMesh mesh, Vec3 p)
        {
            for (int v = 0; v < mesh.Counts.VertexSlots; ++v)
                if (!mesh.IsDeleted(new Vertex(v)) && mesh.GetPosition(new Vertex(v)) == p) return new Vertex(v);
            throw new InvalidOperationException("no vertex at " + p);
        }

        [Test]
        static void EngineIndicesOfVerticesAndCorners()
        {
            BuildReport report;
            using (HalfEdgeMesh mesh = HalfEdgeMesh.FromEngineMesh(Positions, Triangles, null, Texcoords, null,
                                                                    EngineImportOptions.Unity, out report))
            {
                Check.Equal(6, mesh.VertexCount);
                Check.Equal(2, report.WeldedVertices);
                var perVertex = new int[mesh.CopyVertexSourceIndices(null)];
                Check.Equal(mesh.Counts.VertexSlots, perVertex.Length);
                mesh.CopyVertexSourceIndices(perVertex);
                var seen = new bool[8];
                for (int v = 0; v < perVertex.Length; ++v)
                {
                    int s = perVertex[v];
                    Check.True(s >= 0 && s < 8, "vertex " + v + " has a source");
                    Check.Equal(EnginePosition(s), mesh.GetPosition(new Vertex(v)), "vertex " + v + "'s source");
                    seen[s] = true;
                }
                // The welded seam vertices name their first engine vertex: 0 and 1, not 3 and 6.
                Check.True(seen[0] && seen[1] && !seen[3] && !seen[6], "the first engine index of a welded vertex");

                var perCorner = new int[mesh.CopyCornerSourceIndices(null)];
                Check.Equal(2 * mesh.Counts.EdgeSlots, perCorner.Length);
                mesh.CopyCornerSourceIndices(perCorner);
                var corners = new HalfEdge[8];
                bool seamSplit = false;
                for (int f = 0; f < mesh.Counts.FaceSlots; ++f)
                    for (int i = 0, n = mesh.GetFaceHalfEdges(new Face(f), corners); i < n; ++i)
                    {
                        int s = perCorner[corners[i].Index];
                        Vertex v = mesh.ToVertex(corners[i]);
                        Check.Equal(EnginePosition(s), mesh.GetPosition(v), "corner " + corners[i].Index);
                        seamSplit |= s == 3 || s == 6;
                    }
                Check.True(seamSplit, "the left quad's corners at the seam name engine vertices 3 and 6");
                for (int h = 0; h < perCorner.Length; ++h)
                    if (mesh.IsBoundary(new HalfEdge(h))) Check.Equal(-1, perCorner[h], "boundary half-edge " + h);
                Check.Valid(mesh);
            }
        }

        // User data keyed by the engine's vertex index (a weight per Unity vertex) found again after a
        // split, a collapse and garbage collection; a vertex the edits made has no source (-1).
        [Test]
        static void UserDataSurvivesEdits()
        {
            var weight = new float[8];
            for (int i = 0; i < 8; ++i) weight[i] = 10 * EnginePosition(i).X + EnginePosition(i).Y;
            BuildReport report;
            using (HalfEdgeMesh mesh = HalfEdgeMesh.FromEngineMesh(Positions, Triangles, null, Texcoords, null,
                                                                    EngineImportOptions.Unity, out report))
            {
                Vertex a = VertexAt(mesh, new Vec3(0, 0, 0)), b = VertexAt(mesh, new Vec3(0, 1, 0));
                Vertex added = mesh.SplitEdge(mesh.FindHalfEdge(a, b).Edge, 0, 0.5f, 0);
                Check.True(added.IsValid);
                Check.Equal(a, mesh.Collapse(mesh.FindHalfEdge(added, a)), "collapsed back into (0, 0, 0)");
                Face left = mesh.GetFace(mesh.FindHalfEdge(a, VertexAt(mesh, new Vec3(1, 0, 0))));
                Vertex extra = mesh.SplitFace(left, 0.6f, 0.3f, 0);
                Check.True(extra.IsValid);
                var map = new Vertex[mesh.Counts.VertexSlots];
                mesh.GarbageCollection(map);
                Vertex moved = map[extra.Index];
                var source = new int[mesh.Counts.VertexSlots];
                mesh.CopyVertexSourceIndices(source);
                int found = 0;
                for (int v = 0; v < source.Length; ++v)
                {
                    if (v == moved.Index)
                    {
                        Check.Equal(-1, source[v], "the vertex a split made has no engine vertex");
                        continue;
                    }
                    Vec3 p = mesh.GetPosition(new Vertex(v));
                    Check.True(source[v] >= 0, "vertex " + v + " kept its source");
                    Check.Equal(10 * p.X + p.Y, weight[source[v]], "the weight of vertex " + v);
                    ++found;
                }
                Check.Equal(6, found);
                Check.Valid(mesh);
            }
        }
    }
}
