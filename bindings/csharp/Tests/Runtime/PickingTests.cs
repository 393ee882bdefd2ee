// Picking (Raycast, TryGetClosestPoint, TryGetFaceContainingPoint) and the render-triangle-to-face
// map (FaceOfTriangle), after edits as well, without managed allocation per query.
using System;
using System.IO;
using System.Runtime.InteropServices;

namespace Hedge.Tests
{
    public static class PickingTests
    {
        // An n x n grid of unit squares in the plane z = 0, two triangles each, read from an OBJ file.
        static HalfEdgeMesh Grid(int n)
        {
            var text = new System.Text.StringBuilder();
            for (int y = 0; y <= n; ++y)
                for (int x = 0; x <= n; ++x) text.Append("v ").Append(x).Append(' ').Append(y).Append(" 0\n");
            for (int y = 0; y < n; ++y)
                for (int x = 0; x < n; ++x)
                {
                    int a = y * (n + 1) + x + 1, b = a + 1, c = a + n + 2, d = a + n + 1;
                    text.Append("f ").Append(a).Append(' ').Append(b).Append(' ').Append(c).Append('\n');
                    text.Append("f ").Append(a).Append(' ').Append(c).Append(' ').Append(d).Append('\n');
                }
            string path = Context.Scratch("picking_grid_" + n + ".obj");
            File.WriteAllText(path, text.ToString());
            return HalfEdgeMesh.Read(path);
        }

        // True if (x, y) is inside or on the triangle face f (a face of the z = 0 grid).
        static bool FaceHas(HalfEdgeMesh mesh, Face f, float x, float y)
        {
            var c = new Vertex[3];
            Check.Equal(3, mesh.GetFaceVertices(f, c));
            Vec3 a = mesh.GetPosition(c[0]), b = mesh.GetPosition(c[1]), d = mesh.GetPosition(c[2]);
            double e0 = Cross(a, b, x, y), e1 = Cross(b, d, x, y), e2 = Cross(d, a, x, y);
            const double eps = 1e-6;
            return (e0 >= -eps && e1 >= -eps && e2 >= -eps) || (e0 <= eps && e1 <= eps && e2 <= eps);
        }

        static double Cross(Vec3 a, Vec3 b, float x, float y)
        {
            return (double)(b.X - a.X) * (y - a.Y) - (double)(b.Y - a.Y) * (x - a.X);
        }

        [Test]
        static void Raycast()
        {
            Check.Equal(48, Marshal.SizeOf(typeof(SurfaceHit)), "hedge_surface_hit is 48 bytes");
            using (HalfEdgeMesh mesh = Grid(3))
            {
                SurfaceHit hit;
                Check.True(mesh.Raycast(new Vec3(2.25f, 0.5f, 4), new Vec3(0, 0, -2), out hit));
                Check.Near(2, hit.T, 1e-6, "t in units of the direction's length");
                Check.Near(4, hit.Distance, 1e-6, "distance in the mesh's units");
                Check.Equal(new Vec3(2.25f, 0.5f, 0), hit.Point);
                Check.True(FaceHas(mesh, hit.Face, 2.25f, 0.5f), "the hit face holds the point");
                Check.Near(1, hit.Barycentric.X + hit.Barycentric.Y + hit.Barycentric.Z, 1e-6);
                Vec3 p0 = mesh.GetPosition(hit.Corner0), p1 = mesh.GetPosition(hit.Corner1),
                     p2 = mesh.GetPosition(hit.Corner2);
                Vec3 w = hit.Barycentric;
                Check.Near(2.25, w.X * p0.X + w.Y * p1.X + w.Z * p2.X, 1e-5, "barycentric x");
                Check.Near(0.5, w.X * p0.Y + w.Y * p1.Y + w.Z * p2.Y, 1e-5, "barycentric y");
                // Misses: too short, pointing away, beside the grid.
                Check.False(mesh.Raycast(new Vec3(2.25f, 0.5f, 4), new Vec3(0, 0, -1), out hit, 3.5f));
                Check.False(hit.Face.IsValid, "a miss leaves no face");
                Check.False(mesh.Raycast(new Vec3(2.25f, 0.5f, 4), new Vec3(0, 0, 1), out hit));
                Check.False(mesh.Raycast(new Vec3(5, 0.5f, 4), new Vec3(0, 0, -1), out hit));
                // From below: two-sided.
                Check.True(mesh.Raycast(new Vec3(1.5f, 1.5f, -1), new Vec3(0, 0, 1), out hit));
                Check.True(FaceHas(mesh, hit.Face, 1.5f, 1.5f));
            }
        }

        [Test]
        static void ClosestPointAndFaceContainingPoint()
        {
            using (HalfEdgeMesh mesh = Grid(2))
            {
                SurfaceHit hit;
                Check.True(mesh.TryGetClosestPoint(new Vec3(3, 1, 2), out hit));
                Check.Equal(new Vec3(2, 1, 0), hit.Point);
                Check.Near(Math.Sqrt(5), hit.Distance, 1e-5);
                Check.False(mesh.TryGetClosestPoint(new Vec3(3, 1, 2), out hit, 2f), "sqrt(5) is beyond 2");

                Face face;
                Check.True(mesh.TryGetFaceContainingPoint(new Vec3(0.75f, 1.25f, 0.00005f), out face));
                Check.True(FaceHas(mesh, face, 0.75f, 1.25f));
                Check.False(mesh.TryGetFaceContainingPoint(new Vec3(0.75f, 1.25f, 0.1f), out face));
                Check.False(face.IsValid);
                Check.True(mesh.TryGetFaceContainingPoint(new Vec3(0.75f, 1.25f, 0.1f), out face, 0.2f));

                Check.True(mesh.TryGetFaceContainingPoint(1.5f, 0.25f, ProjectionPlane.XY, out face, out hit));
                Check.True(FaceHas(mesh, face, 1.5f, 0.25f));
                Check.Equal(face, hit.Face);
                Check.Equal(new Vec3(1.5f, 0.25f, 0), hit.Point);
                Check.False(mesh.TryGetFaceContainingPoint(-0.5f, 0.25f, ProjectionPlane.XY, out face));
                Check.False(mesh.TryGetFaceContainingPoint(1, 0, ProjectionPlane.XZ, out face), "edge-on in xz");
            }
        }

        [Test]
        static void QueriesFollowEdits()
        {
            using (HalfEdgeMesh mesh = Grid(2))
            {
                Check.True(mesh.UpdatePickingTree() > 0, "the tree holds memory");
                SurfaceHit hit;
                // Lift the centre vertex (1, 1): a ray through it sees the new height.
                Vertex centre = Vertex.Invalid;
                Check.True(mesh.TryGetClosestPoint(new Vec3(1, 1, 0), out hit));
                foreach (Vertex c in new[] { hit.Corner0, hit.Corner1, hit.Corner2 })
                    if (mesh.GetPosition(c) == new Vec3(1, 1, 0)) centre = c;
                Check.True(centre.IsValid);
                mesh.SetPosition(centre, 1, 1, 2);
                Check.True(mesh.Raycast(new Vec3(1, 1, 10), new Vec3(0, 0, -1), out hit));
                Check.Near(2, hit.Point.Z, 1e-5, "the moved vertex is seen");
                mesh.SetPosition(centre, 1, 1, 0);
                // Split an edge of the centre: the new vertex's faces are found.
                HalfEdge[] around = new HalfEdge[8];
                mesh.GetVertexHalfEdges(centre, around);
                Vertex other = mesh.ToVertex(around[0]);
                Vec3 a = mesh.GetPosition(centre), b = mesh.GetPosition(other);
                var mid = new Vec3(0.5f * (a.X + b.X), 0.5f * (a.Y + b.Y), 0);
                Vertex v = mesh.SplitEdge(around[0].Edge, mid);
                Check.True(v.IsValid);
                Check.True(mesh.Raycast(new Vec3(mid.X, mid.Y, 1), new Vec3(0, 0, -1), out hit));
                Check.True(hit.Corner0 == v || hit.Corner1 == v || hit.Corner2 == v, "a face of the new vertex");
                // Garbage collection renumbers everything: the tree is rebuilt.
                mesh.GarbageCollection();
                Check.True(mesh.Raycast(new Vec3(0.3f, 1.6f, 1), new Vec3(0, 0, -1), out hit));
                Check.True(FaceHas(mesh, hit.Face, 0.3f, 1.6f));
                mesh.ReleasePickingTree();
                Check.True(mesh.TryGetClosestPoint(new Vec3(0.3f, 1.6f, 1), out hit), "built again after a release");
                Check.Valid(mesh);
            }
        }

        [Test]
        static void BadInputThrowsAndChangesNothing()
        {
            using (HalfEdgeMesh mesh = Grid(2))
            {
                MeshCounts before = mesh.Counts;
                SurfaceHit hit;
                Face face;
                HedgeException e = Check.Throws(HedgeStatus.InvalidArgument,
                                                () => mesh.Raycast(new Vec3(float.NaN, 0, 0), new Vec3(0, 0, 1), out hit));
                Check.Contains(e.Message, "origin");
                e = Check.Throws(HedgeStatus.InvalidArgument, () => mesh.Raycast(new Vec3(0, 0, 1), new Vec3(0, 0, 0), out hit));
                Check.Contains(e.Message, "direction has zero length");
                e = Check.Throws(HedgeStatus.InvalidArgument,
                                 () => mesh.TryGetClosestPoint(new Vec3(0, 0, 1), out hit, -1));
                Check.Contains(e.Message, "max_distance");
                e = Check.Throws(HedgeStatus.InvalidArgument,
                                 () => mesh.TryGetFaceContainingPoint(new Vec3(0, 0, 0), out face, float.PositiveInfinity));
                Check.Contains(e.Message, "tolerance");
                e = Check.Throws(HedgeStatus.InvalidArgument,
                                 () => mesh.TryGetFaceContainingPoint(0, 0, (ProjectionPlane)9, out face));
                Check.Contains(e.Message, "HEDGE_PLANE_");
                Check.Equal(before, mesh.Counts);
                Check.Valid(mesh);
                mesh.Dispose();
                Check.ThrowsType<ObjectDisposedException>(() => mesh.Raycast(new Vec3(0, 0, 1), new Vec3(0, 0, -1), out hit));
            }
        }

        // Every live triangle slot names the face that owns it; free slots name none.
        static void CheckTriangleFaces(HalfEdgeMesh mesh, RenderBuffers buffers)
        {
            int triangles = (int)buffers.Counts.IndexCount / 3;
            int named = 0;
            for (int t = 0; t < triangles; ++t)
            {
                Face f = buffers.FaceOfTriangle(t);
                if (!f.IsValid) continue;
                ++named;
                SlotRange r = buffers.GetFaceTriangles(f);
                Check.True(t >= (int)r.First && t < (int)(r.First + r.Count), "triangle " + t + " is a slot of " + f);
            }
            Check.Equal(mesh.FaceCount, named, "one named triangle per live triangle face");
            Check.Throws(HedgeStatus.BadHandle, () => buffers.FaceOfTriangle(triangles));
            Check.ThrowsType<ArgumentOutOfRangeException>(() => buffers.FaceOfTriangle(-1));
        }

        [Test]
        static void FaceOfTriangleAfterSplitCollapseCompact()
        {
            using (HalfEdgeMesh mesh = Grid(3))
            using (RenderBuffers buffers = mesh.CreateRenderBuffers(RenderOptions.Unity))
            {
                CheckTriangleFaces(mesh, buffers);
                SurfaceHit hit;
                Check.True(mesh.Raycast(new Vec3(1.5f, 1.2f, 1), new Vec3(0, 0, -1), out hit));
                HalfEdge[] loop = new HalfEdge[3];
                mesh.GetFaceHalfEdges(hit.Face, loop);
                Edge e = loop[0].Edge;
                Vec3 a = mesh.GetPosition(mesh.FromVertex(loop[0])), b = mesh.GetPosition(mesh.ToVertex(loop[0]));
                Vertex v = mesh.SplitEdge(e, new Vec3(0.5f * (a.X + b.X), 0.5f * (a.Y + b.Y), 0));
                Check.True(v.IsValid);
                buffers.Sync();
                CheckTriangleFaces(mesh, buffers);
                var faces = new Face[8];
                int n = mesh.GetVertexFaces(v, faces);
                Check.Equal(4, n);
                for (int i = 0; i < n; ++i)
                    Check.Equal(faces[i], buffers.FaceOfTriangle((int)buffers.GetFaceTriangles(faces[i]).First));

                // Collapse it again: until the next sync the deleted faces' triangles name no face.
                var oldFirst = new int[n];
                for (int i = 0; i < n; ++i) oldFirst[i] = (int)buffers.GetFaceTriangles(faces[i]).First;
                var around = new HalfEdge[8];
                int k = mesh.GetVertexHalfEdges(v, around);
                Vertex survivor = Vertex.Invalid;
                for (int i = 0; i < k && !survivor.IsValid; ++i)
                    if (mesh.CanCollapse(around[i])) survivor = mesh.Collapse(around[i]);
                Check.True(survivor.IsValid);
                int dead = 0;
                for (int i = 0; i < n; ++i)
                {
                    if (!mesh.IsDeleted(faces[i])) continue;
                    ++dead;
                    Check.False(buffers.FaceOfTriangle(oldFirst[i]).IsValid, "a deleted face is not named");
                }
                Check.Equal(2, dead);
                buffers.Sync();
                CheckTriangleFaces(mesh, buffers);
                Check.True(buffers.Counts.FreeTriangleSlots > 0);
                buffers.Compact();
                Check.Equal(0, (int)buffers.Counts.FreeTriangleSlots);
                CheckTriangleFaces(mesh, buffers);
                Check.Valid(mesh);
            }
        }

        // What Unity's physics does with a MeshCollider of the uploaded mesh, done by hand: intersect
        // the ray with every triangle of the index buffer and keep the nearest. FaceOfTriangle of that
        // triangle index must be the face hedge's own Raycast finds.
        static int EngineRaycast(RenderBuffers buffers, Vec3 o, Vec3 d)
        {
            var indices = new int[buffers.CopyIndices((int[])null)];
            buffers.CopyIndices(indices);
            var vertices = new float[buffers.CopyVertices(null)];
            buffers.CopyVertices(vertices);
            int k = buffers.Components(VertexStream.Vertices), at = buffers.Layout.Position;
            if (buffers.Options.FlipX) // the engine's frame is mirrored: so is the ray
            {
                o = new Vec3(-o.X, o.Y, o.Z);
                d = new Vec3(-d.X, d.Y, d.Z);
            }
            int best = -1;
            double bestT = double.PositiveInfinity;
            for (int t = 0; 3 * t < indices.Length; ++t)
            {
                var p = new double[3][];
                for (int c = 0; c < 3; ++c)
                {
                    int i = indices[3 * t + c] * k + at;
                    p[c] = new double[] { vertices[i], vertices[i + 1], vertices[i + 2] };
                }
                double[] e1 = Sub(p[1], p[0]), e2 = Sub(p[2], p[0]);
                double[] dir = { d.X, d.Y, d.Z }, org = { o.X, o.Y, o.Z };
                double[] q = CrossD(dir, e2);
                double det = Dot(e1, q);
                if (Math.Abs(det) < 1e-12) continue; // degenerate (a free slot) or parallel
                double[] s = Sub(org, p[0]);
                double u = Dot(s, q) / det;
                double[] r = CrossD(s, e1);
                double v = Dot(dir, r) / det, tt = Dot(e2, r) / det;
                if (u < 0 || v < 0 || u + v > 1 || tt < 0 || tt >= bestT) continue;
                bestT = tt;
                best = t;
            }
            return best;
        }

        static double[] Sub(double[] a, double[] b) { return new[] { a[0] - b[0], a[1] - b[1], a[2] - b[2] }; }
        static double Dot(double[] a, double[] b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
        static double[] CrossD(double[] a, double[] b)
        {
            return new[] { a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0] };
        }

        [Test]
        static void EngineHitFindsTheSameFace()
        {
            using (HalfEdgeMesh mesh = Grid(4))
            using (RenderBuffers buffers = mesh.CreateRenderBuffers(RenderOptions.Unity))
            {
                var rng = new Random(13);
                int hits = 0;
                for (int round = 0; round < 40; ++round)
                {
                    // Edit a random spot: split one of its face's edges at its midpoint, or collapse it.
                    SurfaceHit at;
                    var spot = new Vec3(0.1f + 3.8f * (float)rng.NextDouble(), 0.1f + 3.8f * (float)rng.NextDouble(), 0);
                    Check.True(mesh.TryGetClosestPoint(spot, out at));
                    var loop = new HalfEdge[3];
                    Check.Equal(3, mesh.GetFaceHalfEdges(at.Face, loop));
                    HalfEdge h = loop[rng.Next(3)];
                    if (round % 3 == 2)
                    {
                        if (mesh.CanCollapse(h)) mesh.Collapse(h);
                    }
                    else
                    {
                        Vec3 a = mesh.GetPosition(mesh.FromVertex(h)), b = mesh.GetPosition(mesh.ToVertex(h));
                        mesh.SplitEdge(h.Edge, new Vec3(0.5f * (a.X + b.X), 0.5f * (a.Y + b.Y), 0));
                    }
                    buffers.Sync();
                    var o = new Vec3(0.1f + 3.8f * (float)rng.NextDouble(), 0.1f + 3.8f * (float)rng.NextDouble(), 2);
                    var d = new Vec3(0, 0, -1);
                    int triangle = EngineRaycast(buffers, o, d);
                    SurfaceHit hit;
                    // Collapses on the border can pull it in, so a ray may miss; then both must miss.
                    bool hedgeHit = mesh.Raycast(o, d, out hit);
                    Check.Equal(hedgeHit, triangle >= 0, "round " + round + ": hedge and the engine agree on a hit");
                    if (!hedgeHit) continue;
                    ++hits;
                    Face viaEngine = buffers.FaceOfTriangle(triangle);
                    Check.True(FaceHas(mesh, viaEngine, o.X, o.Y), "round " + round + ": the engine's face holds the point");
                    Check.True(FaceHas(mesh, hit.Face, o.X, o.Y), "round " + round + ": hedge's face holds the point");
                }
                Check.True(hits > 30, hits + " of 40 rays hit");
                Check.Valid(mesh);
            }
        }

        [Test]
        static void NoAllocationPerQuery()
        {
            using (HalfEdgeMesh mesh = Grid(4))
            using (RenderBuffers buffers = mesh.CreateRenderBuffers(RenderOptions.Unity))
            {
                long sink = 0;
                for (int round = 0; round < 2; ++round) // round 0 warms up (JIT), round 1 is measured
                {
                    long before = GC.GetAllocatedBytesForCurrentThread();
                    for (int i = 0; i < 200; ++i)
                    {
                        SurfaceHit hit;
                        Face face;
                        float x = 0.1f + (i % 38) * 0.1f;
                        if (mesh.Raycast(new Vec3(x, 1.3f, 1), new Vec3(0, 0, -1), out hit)) sink += hit.Face.GetHashCode();
                        if (mesh.TryGetClosestPoint(new Vec3(x, 1.3f, 1), out hit)) sink += 1;
                        if (mesh.TryGetFaceContainingPoint(new Vec3(x, 1.3f, 0), out face)) sink += 1;
                        if (mesh.TryGetFaceContainingPoint(x, 1.3f, ProjectionPlane.XY, out face)) sink += 1;
                        sink += buffers.FaceOfTriangle(i % 32).GetHashCode();
                    }
                    long allocated = GC.GetAllocatedBytesForCurrentThread() - before;
                    if (round == 1) Check.Equal(0L, allocated, "managed bytes allocated by 1000 queries");
                }
                Check.True(sink != 0);
            }
        }
    }
}
