// Handles, struct layouts, adjacency queries, circulators, predicates and local edits.
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

        // A unit cube of 12 triangles: area, volume, box, face normals, vertex normals along the diagonals,
        // and corner normals with a crease that render buffers turn into 24 vertices (hard edges).
        [Test]
        static void GeometryAndNormals()
        {
            float[] positions = { 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1 };
            int[] triangles = { 0, 3, 2, 0, 2, 1, 4, 5, 6, 4, 6, 7, 0, 1, 5, 0, 5, 4,
                                 1, 2, 6, 1, 6, 5, 2, 3, 7, 2, 7, 6, 3, 0, 4, 3, 4, 7 };
            using (var cube = HalfEdgeMesh.FromTriangles(positions, triangles))
            {
                MeshGeometry g = cube.Geometry;
                Check.True(Math.Abs(g.Area - 6) < 1e-9, "area " + g.Area);
                Check.True(Math.Abs(g.Volume - 1) < 1e-9, "volume " + g.Volume);
                Check.True(g.Closed && !g.Empty, "closed");
                Check.Equal(new Vec3(1, 1, 1), g.BoxMax);
                Check.True(Math.Abs(cube.FaceArea(new Face(0)) - 0.5) < 1e-9, "a triangle of a unit square");
                Check.Equal(new Vec3(0, 0, -1), cube.FaceNormal(new Face(0)));

                Check.Throws(HedgeStatus.InvalidArgument, () => cube.CopyVertexNormals(new float[24]));
                cube.ComputeVertexNormals(NormalWeighting.Angle);
                float[] vn = new float[cube.CopyVertexNormals(null)];
                Check.Equal(24, cube.CopyVertexNormals(vn));
                float d = 1 / (float)Math.Sqrt(3);
                for (int v = 0; v < 8; ++v)
                    for (int a = 0; a < 3; ++a)
                        Check.True(Math.Abs(vn[3 * v + a] - (positions[3 * v + a] > 0.5f ? d : -d)) < 1e-6, "diagonal at " + v);

                Check.Throws(HedgeStatus.InvalidArgument, () => cube.ComputeCornerNormals(-5));
                cube.ComputeCornerNormals(30);
                float[] cn = new float[cube.CopyCornerNormals(null)];
                cube.CopyCornerNormals(cn);
                for (int h = 0; h < 36; ++h)
                {
                    Vec3 fn = cube.FaceNormal(cube.GetFace(new HalfEdge(h)));
                    Check.True(Math.Abs(cn[3 * h] - fn.X) + Math.Abs(cn[3 * h + 1] - fn.Y) + Math.Abs(cn[3 * h + 2] - fn.Z) < 1e-6,
                               "corner " + h + " takes its face's normal");
                }
                RenderOptions options = RenderOptions.Default;
                options.Normals = NormalSource.Attribute;
                using (RenderBuffers buffers = cube.CreateRenderBuffers(options))
                {
                    Check.Equal(24, buffers.Counts.Vertices, "hard edges split the cube's corners");
                }
                Check.Valid(cube, "after the normals");
            }
        }

        // The grid against a copy raised by 0.5: every point is 0.5 from the other; a mesh without faces is refused.
        [Test]
        static void HausdorffDistanceOfARaisedCopy()
        {
            float[] raised = (float[])Meshes.GridPositions.Clone();
            for (int v = 0; v < raised.Length / 3; ++v) raised[3 * v + 2] += 0.5f;
            BuildReport report;
            using (var grid = Meshes.Grid())
            using (var copy = HalfEdgeMesh.FromPolygons(raised, Meshes.GridQuads, Meshes.GridSizes, BuildOptions.Default,
                                                        out report))
            using (var points = HalfEdgeMesh.FromTriangles(raised, new int[0]))
            {
                double mean;
                Check.Near(0.5, grid.HausdorffDistance(copy, out mean, 1000), 1e-7, "distance");
                Check.Near(0.5, mean, 1e-7, "mean");
                Check.Near(0, grid.HausdorffDistance(grid, out mean), 1e-7, "to itself");
                Check.Throws(HedgeStatus.InvalidArgument, () => grid.HausdorffDistance(points, out mean));
            }
        }

        // Loop subdivision of a tetrahedron: 4 -> 16 -> 64 faces, still closed and valid; its render buffers
        // rebuild at the next sync; quads are refused unchanged.
        [Test]
        static void SubdivisionRefinesAndRenderBuffersFollow()
        {
            float[] positions = { 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1 };
            int[] triangles = { 0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3 };
            using (var tet = HalfEdgeMesh.FromTriangles(positions, triangles))
            using (RenderBuffers buffers = tet.CreateRenderBuffers())
            {
                double before = tet.Geometry.Volume;
                tet.Subdivide(Subdivision.Loop, 2);
                Check.Equal(64, tet.FaceCount);
                Check.True(tet.Geometry.Closed && tet.Geometry.Volume < before, "smaller, still closed");
                buffers.Sync();
                Check.Equal(64, buffers.Counts.Triangles, "the buffers follow");
                Check.Throws(HedgeStatus.InvalidArgument, () => tet.Subdivide(Subdivision.Midpoint, 20));
                var map = new Vertex[tet.Counts.VertexSlots];
                tet.Reorder(Ordering.Spatial, vertexMap: map);
                Check.Equal((int)tet.Counts.VertexSlots, map.Select(v => v.Index).Distinct().Count(), "a permutation");
                double spatial = tet.CacheMissRatio();
                tet.Reorder(Ordering.VertexCache);
                Check.True(tet.CacheMissRatio() < spatial, "the vertex-cache order loads fewer vertices per triangle");
                buffers.Sync();
                Check.Equal(64, buffers.Counts.Triangles, "the buffers follow the renumbering");
                Check.Valid(tet, "after subdividing");
            }
            float[] grid = { 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0 };
            BuildReport report;
            using (var quad = HalfEdgeMesh.FromPolygons(grid, new int[] { 0, 1, 2, 3 }, new int[] { 4 }, BuildOptions.Default, out report))
            {
                Check.Throws(HedgeStatus.InvalidArgument, () => quad.Subdivide(Subdivision.Loop));
                Check.Equal(1, quad.FaceCount);
                quad.Subdivide(Subdivision.CatmullClark, 2);
                Check.Equal(16, quad.FaceCount, "Catmull-Clark takes quads");
                Check.Valid(quad, "after Catmull-Clark");
                Check.Throws(HedgeStatus.InvalidArgument, () => quad.Subdivide(Subdivision.Sqrt3));
                quad.Subdivide(Subdivision.SplitFaces);
                Check.Equal(64, quad.FaceCount, "each quad fans into 4 triangles");
                quad.Subdivide(Subdivision.Sqrt3);
                Check.Equal(192, quad.FaceCount, "sqrt(3) triples the triangles");
                Check.Valid(quad, "after sqrt(3)");
            }
        }

        // A loop-subdivided tetrahedron (130 vertices) decimated to 20: the counts come back, the mesh stays valid and
        // closed, the render buffers follow the renumbering; quads and bad options are refused.
        [Test]
        static void DecimationReachesItsTarget()
        {
            float[] positions = { 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1 };
            int[] triangles = { 0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3 };
            using (var mesh = HalfEdgeMesh.FromTriangles(positions, triangles))
            using (RenderBuffers buffers = mesh.CreateRenderBuffers())
            {
                mesh.Subdivide(Subdivision.Loop, 3);
                DecimateOptions o = DecimateOptions.Default;
                Check.True(o.KeepSeams && !o.KeepBoundary && double.IsInfinity(o.MaxError), "defaults");
                o.TargetVertices = 20;
                DecimateResult r = mesh.Decimate(o);
                Check.Equal(20ul, r.Vertices);
                Check.Equal((ulong)mesh.FaceCount, r.Faces);
                Check.Equal(36ul, r.Faces, "a closed genus-0 mesh: F = 2V - 4");
                Check.True(r.Collapses == 110 && r.MaxError > 0, "collapses " + r.Collapses + ", error " + r.MaxError);
                Check.Equal(DecimateStop.TargetReached, r.Stop);
                Check.True(mesh.Geometry.Closed, "still closed");
                buffers.Sync();
                Check.Equal(36, buffers.Counts.Triangles, "the buffers follow");
                o.MaxNormalChangeDegrees = 0;
                Check.Throws(HedgeStatus.InvalidArgument, () => mesh.Decimate(o));
                Check.Equal(36, mesh.FaceCount);
                Check.Valid(mesh, "after decimating");
            }
            // A normal limit of 1 degree held to the end stops short of the target, counting its refusals;
            // relaxed (the default) the run goes further.
            ulong strict = 0;
            foreach (bool relax in new[] { false, true })
                using (var mesh = HalfEdgeMesh.FromTriangles(positions, triangles))
                {
                    mesh.Subdivide(Subdivision.Loop, 2);
                    DecimateOptions o = DecimateOptions.Default;
                    Check.True(o.RelaxNormalChange, "relaxed by default");
                    o.TargetVertices = 4;
                    o.MaxNormalChangeDegrees = 1;
                    o.RelaxNormalChange = relax;
                    DecimateResult r = mesh.Decimate(o);
                    if (!relax)
                    {
                        Check.Equal(DecimateStop.NoLegalCollapse, r.Stop);
                        Check.True(r.RefusedNormal > 0 && r.Vertices > 4, "refused " + r.RefusedNormal);
                        strict = r.Collapses;
                    }
                    else
                        Check.True(r.Collapses > strict, "relaxed: " + r.Collapses + " collapses, held: " + strict);
                    Check.Valid(mesh, "after decimating");
                }
            float[] grid = { 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0 };
            BuildReport report;
            using (var quad = HalfEdgeMesh.FromPolygons(grid, new int[] { 0, 1, 2, 3 }, new int[] { 4 }, BuildOptions.Default, out report))
            {
                DecimateOptions o = DecimateOptions.Default;
                o.TargetFaces = 1;
                Check.Throws(HedgeStatus.InvalidArgument, () => quad.Decimate(o));
                Check.Equal(1, quad.FaceCount);
            }
        }

        // The original's demo on a 24 x 24 plate: glass breaks into many shards whose areas add up, each a valid mesh
        // with a hull and, by default, a closed solid with mass (a plate's open shards had none, so a game could not
        // use them); with a set thickness each is a solid that thick; the same seed repeats; a miss is refused.
        [Test]
        static void SimulateBreakingGivesShardsForRigidBodies()
        {
            Check.Equal(488, Marshal.SizeOf(typeof(FractureOptions)), "hedge_fracture_options");
            Check.Equal(388, (int)Marshal.OffsetOf(typeof(FractureOptions), "Units"), "units");
            Check.Equal(472, (int)Marshal.OffsetOf(typeof(FractureOptions), "Radius"), "radius");
            Check.Equal(480, (int)Marshal.OffsetOf(typeof(FractureOptions), "ShellThickness"), "shell_thickness");
            Check.Equal(24, Marshal.SizeOf(typeof(FractureRing)), "hedge_fracture_ring");
            Check.Equal(264, Marshal.SizeOf(typeof(NativeFractureShard)), "hedge_fracture_shard");
            using (var plate = Meshes.Plate(24))
            using (RenderBuffers buffers = plate.CreateRenderBuffers())
            {
                double before = plate.Geometry.Area;
                FractureShard[] shards = plate.SimulateBreaking(new Vec3(12.2f, 11.9f, 0), FracturePreset.Glass, 5);
                Check.True(shards.Length >= 20 && shards.Length <= 40, "shards: " + shards.Length);
                double area = plate.Geometry.Area;
                foreach (FractureShard s in shards)
                {
                    Check.Valid(s.Mesh, "a shard");
                    area += s.Area;
                    Check.True(s.Hull != null && s.HullDimension == 4, "a solid hull");
                    Check.True(s.Closed && s.Mass > 0 && s.Volume > 0, "a solid with mass by default");
                    Check.True(s.PrincipalMoments[0] > 0, "a usable inertia");
                    s.Dispose();
                }
                Check.True(Math.Abs(area - before) < 1e-5 * before, "areas add up: " + area + " vs " + before);
                Check.Valid(plate, "the rest");
                buffers.Sync();
                Check.Equal(plate.FaceCount, buffers.Counts.Triangles, "the buffers follow");
                Check.Throws(HedgeStatus.InvalidArgument, () => plate.SimulateBreaking(new Vec3(12, 12, 5), FracturePreset.Stone, 1));
            }
            double[] areas = new double[2];
            for (int run = 0; run < 2; ++run)
                using (var plate = Meshes.Plate(24))
                {
                    FractureOptions o = FractureOptions.Preset(FracturePreset.Wood);
                    Check.True(o.GrainStretch == 3 && o.Hulls && o.RingCount == 3, "the wood preset");
                    o.Thickness = 0.2;
                    o.Density = 3;
                    o.Seed = 77;
                    FractureShard[] shards = o.TotalPoints == 18 ? plate.Fracture(new Vec3(12.5f, 12.4f, 0), o) : null;
                    Check.True(shards != null && shards.Length >= 8, "wood shards");
                    foreach (FractureShard s in shards)
                    {
                        Check.True(s.Closed && s.Volume > 0 && Math.Abs(s.Mass - 3 * s.Volume) < 1e-9 * s.Mass, "a solid");
                        Check.True(s.Inertia.Length == 9 && s.Inertia[0] > 0 && s.HullDimension == 4, "inertia and a solid hull");
                        areas[run] += s.Area;
                        s.Dispose();
                    }
                }
            Check.True(areas[0] == areas[1], "the same seed breaks the same way");
        }

        // A 2 x 2 grid of quads with its middle vertex lifted: every method but cotangent (quads) pulls it down,
        // the boundary stays, and a mask keeps it where it is.
        [Test]
        static void SmoothingPullsALiftedVertexDown()
        {
            float[] positions = { 0, 0, 0, 1, 0, 0, 2, 0, 0, 0, 1, 0, 1, 1, 1, 2, 1, 0, 0, 2, 0, 1, 2, 0, 2, 2, 0 };
            int[] quads = { 0, 1, 4, 3, 1, 2, 5, 4, 3, 4, 7, 6, 4, 5, 8, 7 };
            int[] sizes = { 4, 4, 4, 4 };
            BuildReport report;
            using (var mesh = HalfEdgeMesh.FromPolygons(positions, quads, sizes, BuildOptions.Default, out report))
            {
                SmoothOptions o = SmoothOptions.Default;
                Check.Equal(10, o.Iterations);
                Check.True(o.FixBoundary, "boundary fixed by default");
                var mask = new byte[9];
                mesh.Smooth(o, mask);
                Check.True(mesh.GetPosition(new Vertex(4)).Z == 1f, "masked out");
                o.Method = SmoothMethod.Cotangent;
                Check.Throws(HedgeStatus.InvalidArgument, () => mesh.Smooth(o));
                o.Method = SmoothMethod.Taubin;
                mesh.Smooth(o);
                Check.True(mesh.GetPosition(new Vertex(4)).Z < 0.5f, "pulled down: " + mesh.GetPosition(new Vertex(4)).Z);
                Check.True(mesh.GetPosition(new Vertex(0)) == new Vec3(0, 0, 0), "the boundary stays");
                Check.Valid(mesh, "after smoothing");
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
