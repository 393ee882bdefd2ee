// Building from arrays: welding, repair, the strict policy, maps and argument errors.
using System;

namespace Hedge.Tests
{
    public static class BuildTests
    {
        // A unit quad as two triangles with their own copies of the shared corners: 6 input vertices.
        static readonly float[] SplitQuad = { 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 0, 0, 1, 1, 0, 0, 1, 0 };
        static readonly int[] SplitQuadTriangles = { 0, 1, 2, 3, 4, 5 };

        [Test]
        static void Welding()
        {
            BuildOptions options = BuildOptions.Default;
            BuildReport report;
            using (HalfEdgeMesh apart = HalfEdgeMesh.FromTriangles(SplitQuad, SplitQuadTriangles, options, out report))
            {
                Check.Equal(6, apart.VertexCount, "no welding: two separate triangles");
                Check.Equal(6, apart.EdgeCount);
                Check.Equal(0, report.WeldedVertices);
                Check.Equal(0, report.Repairs);
                Check.Valid(apart);
            }

            options.Weld = Weld.Exact;
            var vertexMap = new Vertex[6];
            var faceMap = new Face[2];
            using (HalfEdgeMesh welded = HalfEdgeMesh.Build(SplitQuad, SplitQuadTriangles, null, options, out report,
                                                            vertexMap, faceMap))
            {
                Check.Equal(2, report.WeldedVertices);
                Check.Equal(4, welded.VertexCount);
                Check.Equal(5, welded.EdgeCount, "the diagonal is shared");
                Check.Equal(2, welded.FaceCount);
                Check.Equal(vertexMap[0], vertexMap[3], "input 3 welded onto input 0");
                Check.Equal(vertexMap[2], vertexMap[4], "input 4 welded onto input 2");
                Check.True(vertexMap[1] != vertexMap[5]);
                for (int i = 0; i < 6; ++i)
                    Check.Equal(new Vec3(SplitQuad[3 * i], SplitQuad[3 * i + 1], SplitQuad[3 * i + 2]),
                                welded.GetPosition(vertexMap[i]), "vertex map of input " + i);
                Check.Equal(new Face(0), faceMap[0]);
                Check.Equal(new Face(1), faceMap[1]);
                HalfEdge diagonal = welded.FindHalfEdge(vertexMap[0], vertexMap[2]);
                Check.True(diagonal.IsValid && !welded.IsBoundary(diagonal.Edge), "an interior diagonal");
                Check.Valid(welded);
            }

            // Epsilon welding merges near positions too.
            var near = (float[])SplitQuad.Clone();
            near[9] = 1e-7f; // input 3 is 1e-7 away from input 0
            options.Weld = Weld.Epsilon;
            options.WeldEpsilon = 1e-5;
            using (HalfEdgeMesh welded = HalfEdgeMesh.FromTriangles(near, SplitQuadTriangles, options, out report))
            {
                Check.Equal(4, welded.VertexCount);
                Check.Equal(2, report.WeldedVertices);
                Check.Valid(welded);
            }
            options.Weld = Weld.Exact;
            using (HalfEdgeMesh exact = HalfEdgeMesh.FromTriangles(near, SplitQuadTriangles, options, out report))
            {
                // Exact welding keeps the near copy apart and merges only input 4 into input 2: the two
                // triangles then touch at a single vertex, which repair splits again.
                Check.Equal(1, report.WeldedVertices);
                Check.Equal(1, report.NonManifoldVertices);
                Check.Equal(1, report.DuplicatedVertices);
                Check.Equal(6, exact.VertexCount);
                Check.Equal(6, exact.EdgeCount, "no shared edge");
                Check.Valid(exact);
            }
        }

        [Test]
        static void RepairAndStrict()
        {
            // Three triangles on the edge 0-1 (non-manifold), one degenerate triangle (2, 2, 5) and a
            // neighbour of the first across the edge 1-2.
            float[] positions = { 0, 0, 0, 1, 0, 0, 0.5f, 1, 0, 0.5f, -1, 0, 0.5f, 0, 1, 1.5f, 1, 0 };
            int[] triangles = { 0, 1, 2, 1, 0, 3, 0, 1, 4, 2, 2, 5, 2, 1, 5 };
            BuildOptions options = BuildOptions.Default;
            BuildReport report;
            var faceMap = new Face[5];
            using (HalfEdgeMesh mesh = HalfEdgeMesh.Build(positions, triangles, null, options, out report, null, faceMap))
            {
                Check.True(report.NonManifoldEdges >= 1, "the edge 0-1 is cut apart: " + report.NonManifoldEdges);
                Check.Equal(1, report.DegenerateFaces);
                Check.Equal(Face.Invalid, faceMap[3], "the degenerate triangle was dropped");
                Check.True(report.Repairs >= 2, "repairs: " + report.Repairs);
                Check.Equal(4, mesh.FaceCount);
                for (int i = 0; i < 5; ++i)
                    if (i != 3) Check.True(faceMap[i].IsValid, "face " + i + " kept");
                Check.Valid(mesh, "a repaired mesh is valid");
            }

            options.Policy = TopologyPolicy.Strict;
            HedgeException e = Check.Throws(HedgeStatus.Topology,
                                            () => HalfEdgeMesh.FromTriangles(positions, triangles, options, out report));
            Check.Equal("HEDGE_ERROR_TOPOLOGY", e.StatusName);

            // Polygons: a strict build of clean quads works.
            using (HalfEdgeMesh grid = HalfEdgeMesh.FromPolygons(Meshes.GridPositions, Meshes.GridQuads,
                                                                 Meshes.GridSizes, options, out report))
            {
                Check.Equal(4, grid.FaceCount);
                Check.Equal(0, report.Repairs);
                Check.Valid(grid);
            }
        }

        [Test]
        static void InvalidInput()
        {
            BuildReport report;
            BuildOptions options = BuildOptions.Default;
            // Errors the library reports.
            var nan = (float[])Meshes.TetPositions.Clone();
            nan[4] = float.NaN;
            Check.Throws(HedgeStatus.InvalidArgument, () => HalfEdgeMesh.FromTriangles(nan, Meshes.TetTriangles));
            Check.Throws(HedgeStatus.InvalidArgument,
                         () => HalfEdgeMesh.FromTriangles(Meshes.TetPositions, new int[] { 0, 1, 9 }), "index 9 of 4");
            Check.Throws(HedgeStatus.InvalidArgument,
                         () => HalfEdgeMesh.FromTriangles(Meshes.TetPositions, new int[] { 0, 1, 2, 3 }), "not triangles");
            Check.Throws(HedgeStatus.InvalidArgument,
                         () => HalfEdgeMesh.FromPolygons(Meshes.GridPositions, Meshes.GridQuads, new int[] { 4, 4, 4 },
                                                         options, out report), "face sizes do not add up");
            options.Policy = (TopologyPolicy)7;
            Check.Throws(HedgeStatus.InvalidArgument,
                         () => HalfEdgeMesh.FromTriangles(Meshes.TetPositions, Meshes.TetTriangles, options, out report),
                         "an unknown policy");
            // Errors the binding catches before calling (they would read or write past an array).
            Check.ThrowsType<ArgumentException>(() => HalfEdgeMesh.FromTriangles(new float[] { 0, 0 }, new int[0]));
            Check.ThrowsType<ArgumentNullException>(() => HalfEdgeMesh.FromTriangles(null, new int[0]));
            Check.ThrowsType<ArgumentException>(() => HalfEdgeMesh.Build(Meshes.TetPositions, Meshes.TetTriangles,
                                                                         null, BuildOptions.Default, out report,
                                                                         new Vertex[3], null), "vertex map too short");
            Check.ThrowsType<ArgumentException>(() => HalfEdgeMesh.FromEngineMesh(Meshes.TetPositions,
                                                                                  Meshes.TetTriangles, null,
                                                                                  new float[7], null,
                                                                                  EngineImportOptions.Default,
                                                                                  out report), "texcoords too short");
            // An empty mesh is fine.
            using (HalfEdgeMesh empty = HalfEdgeMesh.FromTriangles(new float[0], new int[0]))
            {
                Check.Equal(0, empty.VertexCount);
                Check.Valid(empty);
            }
        }
    }
}
