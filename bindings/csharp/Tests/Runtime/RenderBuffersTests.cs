// Render buffers: layout, buffer contents against the mesh, dirty ranges after edits, transactions,
// holes and compaction, and the promise of no managed allocation on the hot paths.
using System;

namespace Hedge.Tests
{
    public static class RenderBuffersTests
    {
        /// <summary>Every live triangle of the index buffer is a face of the mesh (corners in order, up to
        /// rotation, through the render-vertex source map), and the render vertices carry their mesh
        /// vertex's position.</summary>
        public static void CheckBuffersMatchMesh(HalfEdgeMesh mesh, RenderBuffers buffers)
        {
            BufferCounts counts = buffers.Counts;
            VertexLayout layout = buffers.Layout;
            var indices = new int[counts.IndexCount];
            Check.Equal((int)counts.IndexCount, buffers.CopyIndices(indices));
            var source = new Vertex[counts.VertexSlots];
            Check.Equal((int)counts.VertexSlots, buffers.CopyVertexSource(source));
            var vertices = new float[buffers.CopyVertices(null)];
            buffers.CopyVertices(vertices);
            int k = buffers.Components(VertexStream.Vertices);
            float sign = buffers.Options.FlipX ? -1 : 1;
            for (int r = 0; r < source.Length; ++r)
            {
                if (!source[r].IsValid) continue;
                Vec3 p = mesh.GetPosition(source[r]);
                Check.Equal(new Vec3(sign * p.X, p.Y, p.Z),
                            new Vec3(vertices[r * k + layout.Position], vertices[r * k + layout.Position + 1],
                                     vertices[r * k + layout.Position + 2]), "position of render vertex " + r);
            }
            MeshCounts mc = mesh.Counts;
            var corners = new Vertex[64];
            var loop = new HalfEdge[64];
            var triangle = new Vertex[3];
            int live = 0;
            for (int f = 0; f < mc.FaceSlots; ++f)
            {
                var face = new Face(f);
                if (mesh.IsDeleted(face)) continue;
                int n = mesh.GetFaceVertices(face, corners);
                mesh.GetFaceHalfEdges(face, loop);
                SlotRange slots = buffers.GetFaceTriangles(face);
                Check.Equal((int)(n - 2), slots.Count, "an n-gon owns n - 2 triangles");
                live += (int)slots.Count;
                if (n != 3) continue;
                for (int c = 0; c < 3; ++c)
                {
                    int rv = indices[3 * slots.First + c];
                    Check.True(rv < counts.VertexSlots);
                    triangle[c] = source[rv];
                }
                if (buffers.Options.Winding == Winding.Clockwise)
                {
                    Vertex t = triangle[1];
                    triangle[1] = triangle[2];
                    triangle[2] = t;
                }
                Check.Equal(Meshes.Show(Meshes.Rotated(corners, 3)), Meshes.Show(Meshes.Rotated(triangle, 3)),
                            "triangle of face " + f);
                for (int c = 0; c < 3; ++c)
                    Check.Equal(corners[c], source[buffers.GetRenderVertex(loop[c])], "corner render vertex");
            }
            Check.Equal(counts.Triangles, (int)live);
        }

        /// <summary>A mirror of the vertex stream and the index buffer that receives only the dirty ranges.</summary>
        sealed class Mirror
        {
            public float[] Vertices;
            public int[] Indices;
            readonly RenderBuffers buffers;

            public Mirror(RenderBuffers buffers)
            {
                this.buffers = buffers;
                Reload();
            }

            public void Reload()
            {
                Vertices = new float[buffers.CopyVertices(null)];
                buffers.CopyVertices(Vertices);
                Indices = new int[buffers.CopyIndices((int[])null)];
                buffers.CopyIndices(Indices);
            }

            /// <summary>Applies the last sync's ranges (or reloads after a resize); returns whether it did
            /// a partial update.</summary>
            public bool Apply(SyncResult result)
            {
                BufferCounts counts = buffers.Counts;
                if (result.Resized || Vertices.Length < counts.VertexSlots * buffers.Components(VertexStream.Vertices) ||
                    Indices.Length < counts.IndexCount)
                {
                    Reload();
                    return false;
                }
                buffers.CopyDirtyVertices(VertexStream.Vertices, Vertices);
                buffers.CopyDirtyIndices(Indices);
                return true;
            }

            public void CheckEqualsBuffers(string what)
            {
                var vertices = new float[buffers.CopyVertices(null)];
                buffers.CopyVertices(vertices);
                var indices = new int[buffers.CopyIndices((int[])null)];
                buffers.CopyIndices(indices);
                Check.Same(vertices, Vertices, vertices.Length, "vertex mirror " + what);
                Check.Same(indices, Indices, indices.Length, "index mirror " + what);
            }
        }

        /// <summary>The layout is in one interleaved stream or in streams of their own, with this stride and
        /// these offsets (in floats; -1: the buffers do not carry it).</summary>
        static void CheckLayout(VertexLayout layout, bool interleaved, int stride, int position, int normal, int texcoord,
                                int color)
        {
            Check.Equal(interleaved, layout.Interleaved, "interleaved");
            Check.Equal(stride, layout.Stride, "stride");
            Check.Equal(position, layout.Position, "position offset");
            Check.Equal(normal, layout.Normal, "normal offset");
            Check.Equal(texcoord, layout.Texcoord, "texcoord offset");
            Check.Equal(color, layout.Color, "color offset");
        }

        // The render normal of the corner entered by h (interleaved layout).
        static Vec3 RenderNormal(RenderBuffers buffers, HalfEdge h)
        {
            var v = new float[buffers.CopyVertices(null)];
            buffers.CopyVertices(v);
            VertexLayout layout = buffers.Layout;
            long at = (long)buffers.GetRenderVertex(h) * layout.Stride + layout.Normal;
            return new Vec3(v[at], v[at + 1], v[at + 2]);
        }

        // Imported normals follow a moved vertex by default (Automatic): its render normal becomes the
        // area-weighted normal of its faces, as ComputeVertexNormals gives it. With Attribute they stay.
        [Test]
        static void ImportedNormalsFollowOrStay()
        {
            foreach (NormalSource source in new[] { NormalSource.Automatic, NormalSource.Attribute })
                using (HalfEdgeMesh mesh = SeamTests.UvGrid(4))
                {
                    RenderOptions options = RenderOptions.Default;
                    Check.Equal(NormalSource.Automatic, options.Normals, "the default");
                    options.Normals = source;
                    using (RenderBuffers buffers = mesh.CreateRenderBuffers(options))
                    {
                        Vertex v = new Vertex(6), neighbour = new Vertex(7);  // (1, 1) and (2, 1)
                        HalfEdge corner = mesh.FindHalfEdge(neighbour, v), other = mesh.FindHalfEdge(v, neighbour);
                        Check.Equal(new Vec3(0, 0, 1), RenderNormal(buffers, corner), "imported");
                        mesh.SetPosition(v, 1, 1, 0.5f);
                        buffers.Sync();
                        CheckBuffersMatchMesh(mesh, buffers);
                        Vec3 n = RenderNormal(buffers, corner), m = RenderNormal(buffers, other);
                        if (source == NormalSource.Attribute)
                        {
                            Check.Equal(new Vec3(0, 0, 1), n, "kept at the moved vertex");
                            Check.Equal(new Vec3(0, 0, 1), m, "kept at its neighbour");
                        }
                        else
                        {
                            mesh.ComputeVertexNormals(NormalWeighting.Area);
                            var expected = new float[mesh.CopyVertexNormals(null)];
                            mesh.CopyVertexNormals(expected);
                            int i = (int)v.Index, j = (int)neighbour.Index;
                            Check.True(Math.Abs(n.X - expected[3 * i]) < 1e-5f && Math.Abs(n.Y - expected[3 * i + 1]) < 1e-5f &&
                                       Math.Abs(n.Z - expected[3 * i + 2]) < 1e-5f, "recomputed at the moved vertex: " + n);
                            Check.True(Math.Abs(m.X) + Math.Abs(m.Y) > 0.05f, "the neighbour tilted: " + m);
                            Check.True(Math.Abs(m.X - expected[3 * j]) < 1e-5f && Math.Abs(m.Y - expected[3 * j + 1]) < 1e-5f &&
                                       Math.Abs(m.Z - expected[3 * j + 2]) < 1e-5f, "recomputed at its neighbour: " + m);
                        }
                        Check.Valid(mesh);
                    }
                }
        }

        [Test]
        static void BuffersMatchMesh()
        {
            using (HalfEdgeMesh mesh = Meshes.Pyramid())
            using (RenderBuffers buffers = mesh.CreateRenderBuffers())
            {
                // Position and computed normal in one stream; the pyramid has no texcoords or colours.
                CheckLayout(buffers.Layout, true, 6, 0, 3, -1, -1);
                BufferCounts counts = buffers.Counts;
                Check.Equal(5, counts.VertexSlots);
                Check.Equal(5, counts.Vertices);
                Check.Equal(0, counts.SeamSplits);
                Check.Equal(12, counts.IndexCount);
                Check.Equal(4, counts.Triangles);
                Check.Equal(5ul * 6 * 4 + 12 * 4, counts.BufferBytes);
                SyncResult first = buffers.LastResult;
                Check.True(first.Full && first.Resized, "the first build is a full one");
                Check.Equal(30, buffers.CopyVertices(null));
                Check.Equal(0, buffers.CopyStream(VertexStream.Normals, null), "no separate streams when interleaved");
                var uints = new int[12];
                var ints = new int[12];
                buffers.CopyIndices(uints);
                buffers.CopyIndices(ints);
                for (int i = 0; i < 12; ++i) Check.Equal((int)uints[i], ints[i]);
                // The apex normal points up; base corners' normals point outwards and up.
                var v = new float[30];
                buffers.CopyVertices(v);
                var source = new Vertex[5];
                buffers.CopyVertexSource(source);
                for (int r = 0; r < 5; ++r)
                {
                    float nx = v[6 * r + 3], ny = v[6 * r + 4], nz = v[6 * r + 5];
                    Check.Near(1, Math.Sqrt(nx * nx + ny * ny + nz * nz), 1e-5, "unit normal");
                    if (source[r] == new Vertex(4)) Check.Near(1, nz, 1e-5, "the apex normal is +z");
                    else Check.True(nz > 0, "base normals lean up");
                }
                // The partial copy of a range agrees with the full copy.
                var part = new float[30];
                buffers.CopyVertexRange(VertexStream.Vertices, 2, 2, part);
                for (int i = 0; i < 30; ++i) Check.Equal(i >= 12 && i < 24 ? v[i] : 0f, part[i], "float " + i);
                var partIndices = new int[12];
                buffers.CopyIndexRange(3, 6, partIndices);
                for (int i = 0; i < 12; ++i) Check.Equal(i >= 3 && i < 9 ? ints[i] : 0, partIndices[i]);
                Check.ThrowsType<ArgumentOutOfRangeException>(() => buffers.CopyVertexRange(VertexStream.Vertices, 4, 2, part));
                CheckBuffersMatchMesh(mesh, buffers);
                Check.Valid(mesh);
            }
        }

        [Test]
        static void DirtyRangesAndTransactions()
        {
            using (HalfEdgeMesh mesh = Meshes.Pyramid())
            using (RenderBuffers buffers = mesh.CreateRenderBuffers())
            {
                var mirror = new Mirror(buffers);
                var source = new Vertex[5];
                buffers.CopyVertexSource(source);
                int apexSlot = Array.IndexOf(source, new Vertex(4));

                // Move the apex: its render vertex (and the normals around it) are rewritten, no index.
                mesh.SetPosition(new Vertex(4), 0.5f, 0.5f, 2);
                SyncResult moved = buffers.Sync();
                Check.False(moved.Full || moved.Resized);
                Check.True(moved.VertexRangeCount >= 1);
                Check.Equal(0, moved.IndexRangeCount, "moving a vertex rewrites no index");
                var ranges = new SlotRange[8];
                int n = buffers.GetDirtyVertexRanges(ranges);
                Check.Equal((int)moved.VertexRangeCount, n);
                Check.Equal(n, buffers.GetDirtyVertexRanges(null));
                bool covered = false;
                for (int i = 0; i < n; ++i)
                    if (apexSlot >= ranges[i].First && apexSlot < ranges[i].First + ranges[i].Count) covered = true;
                Check.True(covered, "the apex's render vertex is in a dirty range");
                Check.Throws(HedgeStatus.BufferTooSmall, () => buffers.GetDirtyVertexRanges(new SlotRange[0]));
                Check.True(mirror.Apply(moved));
                Check.Equal(2f, mirror.Vertices[6 * apexSlot + 2], "the mirror holds the new apex height");
                mirror.CheckEqualsBuffers("after moving the apex");

                // Nothing changed since: an empty sync.
                SyncResult idle = buffers.Sync();
                Check.True(idle.IsEmpty && !idle.Full);
                Check.Equal(0, buffers.GetDirtyIndexRanges(null));

                // A transaction: nothing is synced until the commit.
                buffers.BeginTransaction();
                Vertex c = mesh.SplitFace(new Face(0), 0.5f, 0.2f, 0.6f);
                HalfEdge h12 = mesh.FindHalfEdge(new Vertex(1), new Vertex(2));
                Vertex m = mesh.SplitHalfEdge(h12, 1, 0.5f, 0);
                Check.True(c.IsValid && m.IsValid);
                Check.True(buffers.Sync().IsEmpty, "inside a transaction, Sync does nothing");
                buffers.BeginTransaction(); // transactions nest
                mesh.SetPosition(c, 0.5f, 0.25f, 0.6f);
                Check.True(buffers.CommitTransaction().IsEmpty, "the inner commit does not sync");
                SyncResult committed = buffers.CommitTransaction();
                Check.True(committed.IndexRangeCount >= 1 && committed.VertexRangeCount >= 1);
                Check.True(committed.FacesSynced >= 5, "faces synced: " + committed.FacesSynced);
                BufferCounts counts = buffers.Counts;
                Check.Equal(7, counts.Triangles, "4 + 2 (split face) + 1 (split edge on a boundary)");
                Check.Equal(7, counts.Vertices);
                mirror.Apply(committed);
                mirror.CheckEqualsBuffers("after the transaction");
                CheckBuffersMatchMesh(mesh, buffers);
                Check.Throws(HedgeStatus.InvalidArgument, () => buffers.CommitTransaction(), "no open transaction");

                // A flip rewrites the indices of its two triangles only. (A spoke of the split face cannot
                // be flipped: its tips are already joined.)
                Check.False(mesh.CanFlip(mesh.FindHalfEdge(c, new Vertex(4))));
                HalfEdge h04 = mesh.FindHalfEdge(new Vertex(0), new Vertex(4));
                Check.True(mesh.Flip(h04));
                Check.True(mesh.FindHalfEdge(c, new Vertex(3)).IsValid, "0-4 turned into c-3");
                SyncResult flipped = buffers.Sync();
                Check.Equal(2, flipped.FacesSynced);
                Check.True(flipped.IndexRangeCount >= 1 && flipped.IndexRangeCount <= 2);
                Check.Equal(2ul * 3 * 4, flipped.IndexBytes, "two triangles' indices");
                Check.True(mirror.Apply(flipped));
                mirror.CheckEqualsBuffers("after a flip");
                CheckBuffersMatchMesh(mesh, buffers);
                Check.Valid(mesh);
            }
        }

        [Test]
        static void HolesCompactRebuild()
        {
            using (HalfEdgeMesh mesh = Meshes.Pyramid())
            using (RenderBuffers buffers = mesh.CreateRenderBuffers())
            {
                var mirror = new Mirror(buffers);
                SlotRange slots = buffers.GetFaceTriangles(new Face(1));
                Check.True(mesh.RemoveFace(new Face(1)));
                SyncResult removed = buffers.Sync();
                Check.True(mirror.Apply(removed));
                mirror.CheckEqualsBuffers("after removing a face");
                BufferCounts counts = buffers.Counts;
                Check.Equal(3, counts.Triangles);
                Check.Equal(12, counts.IndexCount, "the freed triangle stays as a hole");
                int t = 3 * (int)slots.First;
                Check.True(mirror.Indices[t] == mirror.Indices[t + 1] && mirror.Indices[t + 1] == mirror.Indices[t + 2],
                           "a freed triangle is degenerate");
                Check.Throws(HedgeStatus.BadHandle, () => buffers.GetFaceTriangles(new Face(1)), "a removed face");
                CheckBuffersMatchMesh(mesh, buffers);

                var vertexMap = new int[counts.VertexSlots];
                var triangleMap = new int[counts.IndexCount / 3];
                Check.Throws(HedgeStatus.BufferTooSmall, () => buffers.Compact(vertexMap, new int[1]));
                buffers.Compact(vertexMap, triangleMap);
                Check.Equal(-1, triangleMap[slots.First], "the hole maps to nothing");
                BufferCounts packed = buffers.Counts;
                Check.Equal(9, packed.IndexCount);
                Check.Equal(packed.Vertices, packed.VertexSlots);
                CheckBuffersMatchMesh(mesh, buffers);

                SyncResult rebuilt = buffers.Rebuild();
                Check.True(rebuilt.Full);
                CheckBuffersMatchMesh(mesh, buffers);

                // Garbage collection moves indices: the next sync is a full one.
                mesh.GarbageCollection();
                SyncResult afterGc = buffers.Sync();
                Check.True(afterGc.Full);
                mirror.Apply(afterGc);
                mirror.CheckEqualsBuffers("after garbage collection");
                CheckBuffersMatchMesh(mesh, buffers);
                Check.Valid(mesh);
            }
        }

        [Test]
        static void UnityConventions()
        {
            using (HalfEdgeMesh mesh = Meshes.Pyramid())
            using (RenderBuffers buffers = mesh.GenerateUnityMesh())
            {
                // Each attribute at 0 of its own stream; the stride counts a whole vertex over all streams.
                CheckLayout(buffers.Layout, false, 6, 0, 0, -1, -1);
                Check.Equal(3, buffers.Components(VertexStream.Vertices));
                Check.Equal(15, buffers.CopyStream(VertexStream.Vertices, null));
                Check.Equal(15, buffers.CopyStream(VertexStream.Normals, null));
                Check.Equal(0, buffers.CopyStream(VertexStream.Texcoords, null), "no texcoords in the mesh");
                CheckBuffersMatchMesh(mesh, buffers); // the mesh's own coordinates and winding

                var normals = new float[15];
                buffers.CopyStream(VertexStream.Normals, normals);
                var source = new Vertex[5];
                buffers.CopyVertexSource(source);
                int apex = Array.IndexOf(source, new Vertex(4));
                Check.Near(1, normals[3 * apex + 2], 1e-5, "the apex normal is +z");
                int corner1 = Array.IndexOf(source, new Vertex(1)); // at x = 1: its normal leans to +x
                Check.True(normals[3 * corner1] > 0, "normal x as computed in the mesh's axes (no mirroring for Unity)");

                // Per-stream mirrors take the same dirty ranges.
                var positions = new float[15];
                buffers.CopyStream(VertexStream.Vertices, positions);
                mesh.SetPosition(new Vertex(1), 1.5f, 0, 0);
                buffers.Sync();
                Check.True(buffers.CopyDirtyVertices(VertexStream.Vertices, positions) >= 1);
                Check.True(buffers.CopyDirtyVertices(VertexStream.Normals, normals) >= 1);
                Check.Equal(1.5f, positions[3 * corner1], "the user's x in the mirror");
                var fresh = new float[15];
                buffers.CopyStream(VertexStream.Normals, fresh);
                Check.Same(fresh, normals, 15, "normal mirror");
                Check.ThrowsType<InvalidOperationException>(() => buffers.CopyDirtyVertices(VertexStream.Texcoords,
                                                                                            new float[10]));
                Check.Valid(mesh);
            }
        }

        [Test]
        static void NoAllocationOnHotPaths()
        {
            using (HalfEdgeMesh mesh = Meshes.Pyramid())
            using (RenderBuffers buffers = mesh.CreateRenderBuffers())
            {
                var mirror = new Mirror(buffers);
                var ring = new Vertex[16];
                var loop = new HalfEdge[16];
                var ranges = new SlotRange[16];
                // Grow the buffers first, so that the measured syncs do not resize them.
                mesh.SplitAllFaces();
                mirror.Apply(buffers.Sync());
                float[] vertexMirror = null;
                int[] indexMirror = null;
                buffers.UpdateVertexMirror(VertexStream.Vertices, ref vertexMirror);
                buffers.UpdateIndexMirror(ref indexMirror);
                long sink = 0;
                for (int round = 0; round < 2; ++round) // round 0 warms up (JIT), round 1 is measured
                {
                    long before = GC.GetAllocatedBytesForCurrentThread();
                    for (int i = 0; i < 200; ++i)
                    {
                        var h = new HalfEdge((int)(i % 24));
                        sink += mesh.Twin(h).Index + mesh.Next(h).Index + mesh.Prev(h).Index;
                        sink += mesh.ToVertex(h).Index + mesh.GetFace(h).Index + (mesh.IsBoundary(h) ? 1 : 0);
                        sink += mesh.GetFaceVertices(new Face((int)(i % 12)), ring);
                        sink += mesh.GetFaceHalfEdges(new Face((int)(i % 12)), loop);
                        sink += mesh.GetVertexNeighbours(new Vertex(4), ring);
                        sink += mesh.CanCollapse(h) ? 1 : 0;
                        sink += mesh.CanFlip(h.Edge) ? 1 : 0;
                        Vec3 p = mesh.GetPosition(new Vertex(4));
                        mesh.SetPosition(new Vertex(4), p.X, p.Y, p.Z + 0.001f);
                        SyncResult result = buffers.Sync();
                        sink += buffers.GetDirtyVertexRanges(ranges);
                        sink += buffers.CopyDirtyVertices(VertexStream.Vertices, mirror.Vertices);
                        sink += buffers.CopyDirtyIndices(mirror.Indices);
                        sink += buffers.UpdateVertexMirror(VertexStream.Vertices, ref vertexMirror) ? 1 : 0;
                        sink += buffers.UpdateIndexMirror(ref indexMirror) ? 1 : 0;
                        sink += (long)result.VertexBytes;
                    }
                    long allocated = GC.GetAllocatedBytesForCurrentThread() - before;
                    if (round == 1) Check.Equal(0L, allocated, "bytes allocated by 200 rounds of queries, edits and syncs");
                }
                Check.True(sink > 0);
                mirror.CheckEqualsBuffers("after the measured rounds");
                Check.Same(mirror.Vertices, vertexMirror, mirror.Vertices.Length, "UpdateVertexMirror's array");
                Check.Same(mirror.Indices, indexMirror, mirror.Indices.Length, "UpdateIndexMirror's array");
                Check.Valid(mesh);
            }
        }
    }
}
