// Whole-mesh algorithms from C#: geometry and normals, Hausdorff distance, subdivision, decimation,
// surface fracture and smoothing.
using System;
using System.Linq;
using System.Runtime.InteropServices;

namespace Hedge.Tests
{
    public static class MeshAlgorithmTests
    {
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
    }
}
