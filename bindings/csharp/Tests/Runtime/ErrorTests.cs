// Error paths (disposed objects, dead elements, malformed files) and files, and finalization.
using System;
using System.IO;
using System.Runtime.InteropServices;
using System.Text;

namespace Hedge.Tests
{
    public static class ErrorTests
    {
        // One mesh, one thread at a time: a call that overlaps another thread's call on the same mesh throws
        // HedgeException(Busy) at once, and the mesh is intact afterwards.
        [Test]
        static void SecondThreadIsRefusedNotHung()
        {
            using (HalfEdgeMesh mesh = Meshes.Tet())
            {
                mesh.Subdivide(Subdivision.Midpoint, 6);
                int busy = 0, editorErrors = 0;
                var editor = new System.Threading.Thread(() =>
                {
                    for (int round = 0; round < 3; ++round)
                    {
                        for (;;)
                        {
                            try { mesh.Subdivide(Subdivision.Midpoint, 1); break; }
                            catch (HedgeException e) { if (e.Status != HedgeStatus.Busy) { ++editorErrors; break; } }
                        }
                    }
                });
                editor.Start();
                string message = null;
                while (editor.IsAlive)
                {
                    try { var c = mesh.Counts; }
                    catch (HedgeException e)
                    {
                        Check.Equal(HedgeStatus.Busy, e.Status);
                        message = e.Message;
                        ++busy;
                    }
                }
                editor.Join();
                Check.Equal(0, editorErrors);
                Check.True(busy > 0, "the calls collided");
                Check.Contains(message, "another thread", "the library's message");
                Check.Equal(4 * 4096 * 64, mesh.FaceCount, "every subdivision ran once");
                Check.Valid(mesh, "after the collisions");
            }
        }

        // Every call on a disposed mesh throws ObjectDisposedException naming the type, before it reaches
        // the library: queries, edits (not a refusal), picking, files, render buffers.
        [Test]
        static void DisposedMesh()
        {
            HalfEdgeMesh mesh = Meshes.Tet();
            HalfEdgeMesh other = Meshes.Tet();
            Check.Valid(mesh);
            Check.False(mesh.IsDisposed);
            mesh.Dispose();
            Check.True(mesh.IsDisposed);
            ObjectDisposedException e = Check.ThrowsType<ObjectDisposedException>(() => { var c = mesh.Counts; });
            Check.Equal("HalfEdgeMesh", e.ObjectName);
            Check.ThrowsType<ObjectDisposedException>(() => mesh.Twin(new HalfEdge(0)));
            Check.ThrowsType<ObjectDisposedException>(() => mesh.Collapse(new HalfEdge(0)), "disposed, not refused");
            Check.ThrowsType<ObjectDisposedException>(() => { string r = mesh.LastRefusal; }, "no refusal to read");
            Check.ThrowsType<ObjectDisposedException>(() => mesh.CanFlip(new Edge(0)));
            Check.ThrowsType<ObjectDisposedException>(() => mesh.GetFaceVertices(new Face(0), new Vertex[3]));
            Check.ThrowsType<ObjectDisposedException>(() => mesh.Validate());
            Check.ThrowsType<ObjectDisposedException>(() => mesh.CreateRenderBuffers());
            Check.ThrowsType<ObjectDisposedException>(() => mesh.Write(Context.Scratch("never.obj")));
            Check.ThrowsType<ObjectDisposedException>(() => mesh.SetPosition(new Vertex(0), 1, 2, 3));
            Check.ThrowsType<ObjectDisposedException>(() => mesh.GarbageCollection());
            Check.ThrowsType<ObjectDisposedException>(() => { var g = mesh.Geometry; });
            SurfaceHit hit;
            Check.ThrowsType<ObjectDisposedException>(() => mesh.Raycast(new Vec3(0, 0, 5), new Vec3(0, 0, -1), out hit));
            Check.ThrowsType<ObjectDisposedException>(() => mesh.UpdatePickingTree());
            double mean;
            Check.ThrowsType<ObjectDisposedException>(() => other.HausdorffDistance(mesh, out mean), "the other mesh");
            Check.ThrowsType<ObjectDisposedException>(() => mesh.HausdorffDistance(other, out mean));
            mesh.Dispose(); // a second Dispose is harmless
            Check.Equal("HalfEdgeMesh (disposed)", mesh.ToString());
            Check.Valid(other);
            other.Dispose();
        }

        // Render buffers disposed themselves, or with their mesh, throw ObjectDisposedException naming the type.
        [Test]
        static void DisposedRenderBuffers()
        {
            HalfEdgeMesh mesh = Meshes.Pyramid();
            RenderBuffers a = mesh.CreateRenderBuffers();
            RenderBuffers b = mesh.CreateRenderBuffers();
            a.Dispose();
            Check.True(a.IsDisposed);
            ObjectDisposedException e = Check.ThrowsType<ObjectDisposedException>(() => a.Sync());
            Check.Equal("RenderBuffers", e.ObjectName);
            Check.ThrowsType<ObjectDisposedException>(() => { var l = a.Layout; });
            Check.ThrowsType<ObjectDisposedException>(() => a.FaceOfTriangle(0));
            Check.Equal(5, b.Counts.VertexSlots, "the other render object lives on");
            b.BeginTransaction();
            Check.True(mesh.SplitFace(new Face(0), 0.5f, 0.2f, 0.5f).IsValid);
            Check.Valid(mesh);
            mesh.Dispose(); // destroys b with the mesh, even inside its transaction
            Check.True(b.IsDisposed, "disposed with its mesh");
            e = Check.ThrowsType<ObjectDisposedException>(() => b.CommitTransaction());
            Check.Equal("RenderBuffers", e.ObjectName);
            Check.Contains(e.Message, "mesh was disposed");
            Check.ThrowsType<ObjectDisposedException>(() => { var c = b.Counts; });
            Check.ThrowsType<ObjectDisposedException>(() => b.CopyDirtyVertices(VertexStream.Vertices, new float[64]));
            Check.ThrowsType<ObjectDisposedException>(() => { int n; b.GetStreamPointer(VertexStream.Vertices, out n); });
            b.Dispose(); // already gone with its mesh: nothing to release, no exception
            Check.True(b.IsDisposed);
        }

        [Test]
        static void DeadAndOutOfRangeElements()
        {
            using (HalfEdgeMesh mesh = Meshes.Pyramid())
            {
                Check.Throws(HedgeStatus.BadHandle, () => mesh.Twin(new HalfEdge(16)), "16 half-edges: 0..15");
                Check.Throws(HedgeStatus.BadHandle, () => mesh.GetPosition(Vertex.Invalid));
                Check.Throws(HedgeStatus.BadHandle, () => mesh.Flip(Edge.Invalid));
                Check.Throws(HedgeStatus.BadHandle, () => mesh.IsDeleted(new Face(4)), "only in range is accepted");
                Check.Throws(HedgeStatus.InvalidArgument, () => mesh.GetHalfEdge(new Edge(0), 2));
                Check.Throws(HedgeStatus.InvalidArgument, () => mesh.SplitFace(new Face(0), float.PositiveInfinity, 0, 0));
                Check.Throws(HedgeStatus.InvalidArgument, () => mesh.Write(Context.Scratch("x.ply"), false, 40));
                Check.True(mesh.RemoveFace(new Face(0)));
                Check.True(mesh.IsDeleted(new Face(0)));
                Check.Throws(HedgeStatus.BadHandle, () => mesh.GetFaceVertices(new Face(0), new Vertex[3]), "deleted");
                Check.Throws(HedgeStatus.BadHandle, () => mesh.SplitFace(new Face(0), 0, 0, 0), "deleted");
                Check.Valid(mesh);
            }
        }

        // Indices and counts are int, as Unity's APIs take them: "none" is -1 (never 4294967295), and a
        // negative input is an ArgumentException that says what and where.
        [Test]
        static void IntIndicesAndNegativeInputs()
        {
            Check.Equal(-1, Vertex.Invalid.Index);
            Check.Equal(-1, HalfEdge.Invalid.Index);
            Check.Equal(-1, Edge.Invalid.Index);
            Check.Equal(-1, Face.Invalid.Index);
            Check.Equal(-1, Vertex.InvalidIndex);
            var e = Check.ThrowsType<ArgumentOutOfRangeException>(() => new Vertex(-1), "Invalid names no vertex");
            Check.Contains(e.Message, "0 or more");
            Check.ThrowsType<ArgumentOutOfRangeException>(() => new HalfEdge(-2));
            Check.ThrowsType<ArgumentOutOfRangeException>(() => new Edge(-3));
            Check.ThrowsType<ArgumentOutOfRangeException>(() => new Face(int.MinValue));
            Check.ThrowsType<ArgumentOutOfRangeException>(() => new SlotRange(-1, 3));
            float[] p = { 0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0 };
            var bad = Check.ThrowsType<ArgumentOutOfRangeException>(
                () => HalfEdgeMesh.FromTriangles(p, new[] { 0, 1, 2, 2, 1, -3 }));
            Check.Contains(bad.Message, "triangles[5] is -3: a vertex index is 0 or more");
            BuildReport report;
            Check.ThrowsType<ArgumentOutOfRangeException>(
                () => HalfEdgeMesh.FromPolygons(p, new[] { 0, 1, 3, 2 }, new[] { -4 }, BuildOptions.Default, out report));
            Check.ThrowsType<ArgumentOutOfRangeException>(
                () => HalfEdgeMesh.FromEngineMesh(p, new[] { 0, 1, -2 }, null, null, null, EngineImportOptions.Unity,
                                                  out report));
            using (HalfEdgeMesh mesh = HalfEdgeMesh.FromTriangles(p, new[] { 0, 1, 2, 2, 1, 3 }))
            using (RenderBuffers buffers = mesh.CreateRenderBuffers())
            {
                MeshCounts c = mesh.Counts;
                int vertices = c.Vertices, faces = c.Faces;  // int, no cast
                Check.Equal(4, vertices);
                Check.Equal(2, faces);
                HalfEdge boundary = mesh.FindHalfEdge(new Vertex(1), new Vertex(0));
                Check.True(mesh.IsBoundary(boundary));
                Check.Equal(Face.Invalid, mesh.GetFace(boundary), "the face of a boundary half-edge");
                Check.Equal(-1, mesh.GetFace(boundary).Index);
                Check.Equal(-1, buffers.GetRenderVertex(boundary), "no render vertex: -1");
                Check.ThrowsType<ArgumentOutOfRangeException>(() => mesh.GetHalfEdge(new Edge(0), -1));
                Check.ThrowsType<ArgumentOutOfRangeException>(() => mesh.CacheMissRatio(-1));
                int[] triangles = new int[buffers.CopyIndices(null)];
                buffers.CopyIndices(triangles);  // Unity's Mesh.triangles type
                Check.Equal(6, triangles.Length);
                Check.Valid(mesh);
            }
        }

        [Test]
        static void MalformedAndMissingFiles()
        {
            string broken = Context.Scratch("broken.obj");
            File.WriteAllText(broken, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 x\n");
            HedgeException e = Check.Throws(HedgeStatus.Io, () => HalfEdgeMesh.Read(broken));
            Check.Contains(e.Message, broken + ":4:", "the message names the file and the line");
            Check.Equal("HEDGE_ERROR_IO", e.StatusName);

            string range = Context.Scratch("out_of_range.obj");
            File.WriteAllText(range, "v 0 0 0\nv 1 0 0\nv 0 1 0\n\nf 1 2 7\n");
            e = Check.Throws(HedgeStatus.Io, () => HalfEdgeMesh.Read(range));
            Check.Contains(e.Message, "out_of_range.obj:5:");

            string missing = Context.Scratch("does_not_exist.obj");
            e = Check.Throws(HedgeStatus.Io, () => HalfEdgeMesh.Read(missing));
            Check.Contains(e.Message, "does_not_exist.obj");

            using (HalfEdgeMesh mesh = Meshes.Tet())
            {
                Check.Throws(HedgeStatus.Io, () => mesh.Write(Context.Scratch("tet.unknown")), "an unknown extension");
                Check.Throws(HedgeStatus.Io, () => mesh.Write(Context.Scratch("no/such/folder/tet.obj")));
            }
            Check.ThrowsType<ArgumentNullException>(() => HalfEdgeMesh.Read(null));
            File.Delete(broken);
            File.Delete(range);
        }

        [Test]
        static void FilesRoundTrip()
        {
            BuildReport report;
            using (HalfEdgeMesh spot = HalfEdgeMesh.Read(Context.Data("spot_control_mesh.obj"), out report))
            {
                MeshCounts c = spot.Counts;
                Check.Equal(188, c.Vertices);
                Check.Equal(366, c.Edges);
                Check.Equal(180, c.Faces);
                Check.Equal(0, report.Repairs);
                Check.Valid(spot);

                // A non-ASCII file name goes through as UTF-8.
                string ply = Context.Scratch("spot \u00e9t\u00e9.ply");
                spot.Write(ply, true);
                BuildOptions strict = BuildOptions.Default;
                strict.Policy = TopologyPolicy.Strict;
                using (HalfEdgeMesh back = HalfEdgeMesh.Read(ply, strict, out report))
                {
                    Check.True(c.Equals(back.Counts), "same counts after binary PLY");
                    var a = new float[spot.CopyPositions(null)];
                    var b = new float[back.CopyPositions(null)];
                    spot.CopyPositions(a);
                    back.CopyPositions(b);
                    Check.Same(a, b, a.Length, "positions exact through binary PLY");
                    Check.Valid(back);
                }
                string obj = Context.Scratch("spot_3_digits.obj");
                spot.Write(obj, false, 3);
                using (HalfEdgeMesh back = HalfEdgeMesh.Read(obj))
                {
                    Check.True(c.Equals(back.Counts), "same counts after OBJ");
                    Vec3 exact = spot.GetPosition(new Vertex(17));
                    Vec3 rounded = back.GetPosition(new Vertex(17));
                    Check.Near(exact.X, rounded.X, 5e-3 * Math.Max(1, Math.Abs(exact.X)), "3 significant digits");
                    Check.Valid(back);
                }
                File.Delete(ply);
                File.Delete(obj);
            }
        }

        // A glTF from a stranger: its external buffers are read only beside it (never from bytes in
        // memory), and the read budget refuses what would take too much memory.
        [Test]
        static void HostileFilesAreRefused()
        {
            Check.Equal(16, Marshal.SizeOf(typeof(ReadOptions)));
            Check.True(ReadOptions.ForFiles.ExternalBuffers, "files read their buffers beside them");
            Check.True(!ReadOptions.ForBytes.ExternalBuffers, "bytes have no folder");
            Check.Equal(0UL, ReadOptions.ForFiles.MaxMemory);

            const string head =
                "{\"asset\":{\"version\":\"2.0\"},\"scenes\":[{\"nodes\":[0]}],\"nodes\":[{\"mesh\":0}]," +
                "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0}}]}]," +
                "\"accessors\":[{\"bufferView\":0,\"componentType\":5126,\"count\":3,\"type\":\"VEC3\"}]," +
                "\"bufferViews\":[{\"buffer\":0,\"byteLength\":36}],";
            string outside = Context.Scratch("outside.gltf");
            File.WriteAllText(outside, head + "\"buffers\":[{\"byteLength\":36,\"uri\":\"../../../../../../../../etc/passwd\"}]}");
            HedgeException e = Check.Throws(HedgeStatus.Io, () => HalfEdgeMesh.Read(outside));
            Check.Contains(e.Message, "does not name a regular file inside the .gltf's folder");

            // A buffer beside the file: read by path; from the same bytes in memory, refused.
            File.WriteAllBytes(Context.Scratch("beside.bin"), Convert.FromBase64String(
                "AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"));
            string beside = Context.Scratch("beside.gltf");
            File.WriteAllText(beside, head + "\"buffers\":[{\"byteLength\":36,\"uri\":\"beside.bin\"}]}");
            using (HalfEdgeMesh mesh = HalfEdgeMesh.Read(beside))
            {
                Check.Equal(1, mesh.Counts.Faces);
                Check.Valid(mesh);
            }
            byte[] bytes = File.ReadAllBytes(beside);
            e = Check.Throws(HedgeStatus.Io, () => HalfEdgeMesh.FromBytes(bytes, beside));
            Check.Contains(e.Message, "reading external buffers is turned off");
            BuildReport report;
            ReadOptions off = ReadOptions.ForFiles;
            off.ExternalBuffers = false;
            e = Check.Throws(HedgeStatus.Io, () => HalfEdgeMesh.Read(beside, off, out report));
            Check.Contains(e.Message, "turned off");

            // Embedded: read from bytes, unless the budget is smaller than the file needs.
            byte[] embedded = Encoding.UTF8.GetBytes(head + "\"buffers\":[{\"byteLength\":36,\"uri\":" +
                "\"data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA\"}]}");
            using (HalfEdgeMesh mesh = HalfEdgeMesh.FromBytes(embedded, "upload.gltf"))
            {
                Check.Equal(1, mesh.Counts.Faces);
            }
            ReadOptions tight = ReadOptions.ForBytes;
            tight.MaxMemory = 100;
            e = Check.Throws(HedgeStatus.Io, () => HalfEdgeMesh.FromBytes(embedded, "upload.gltf", tight, out report));
            Check.Contains(e.Message, "upload.gltf: its JSON would take about");
            Check.Contains(e.Message, "more than the read budget of 100 bytes");
            using (HalfEdgeMesh mesh = HalfEdgeMesh.FromBytes(Encoding.UTF8.GetBytes("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"), "t.obj"))
            {
                Check.Equal(1, mesh.Counts.Faces);
            }
            Check.ThrowsType<ArgumentNullException>(() => HalfEdgeMesh.FromBytes(null, "t.obj"));
            File.Delete(outside);
            File.Delete(beside);
            File.Delete(Context.Scratch("beside.bin"));
        }

        static void MakeGarbage()
        {
            for (int i = 0; i < 20; ++i)
            {
                HalfEdgeMesh mesh = Meshes.Pyramid();
                RenderBuffers buffers = mesh.CreateRenderBuffers();
                mesh.SplitFace(new Face(0), 0.5f, 0.2f, 0.5f);
                buffers.Sync();
                if (i % 2 == 0) mesh.Dispose(); // half of them: buffers left to the finalizer after their mesh
            }
        }

        // Render buffers of a mesh that stays alive, dropped without Dispose; returns their native ids.
        [System.Runtime.CompilerServices.MethodImpl(System.Runtime.CompilerServices.MethodImplOptions.NoInlining)]
        static IntPtr[] DropRenderBuffers(HalfEdgeMesh mesh)
        {
            var ids = new IntPtr[10];
            for (int i = 0; i < ids.Length; ++i) ids[i] = mesh.CreateRenderBuffers().Id;
            return ids;
        }

        static bool Alive(IntPtr render)
        {
            BufferCounts counts;
            return Native.hedge_render_buffers_counts(render, out counts) == 0;
        }

        [Test]
        static void FinalizersRelease()
        {
            MakeGarbage();
            GC.Collect();
            GC.WaitForPendingFinalizers();
            GC.Collect();

            // Render buffers the finalizer releases while their mesh lives on are destroyed on the mesh's
            // thread, at its next sync: never by the finalizer thread, which could race with edits.
            using (HalfEdgeMesh mesh = Meshes.Pyramid())
            using (RenderBuffers kept = mesh.CreateRenderBuffers())
            {
                IntPtr[] dropped = DropRenderBuffers(mesh);
                for (int round = 0; round < 3; ++round)
                {
                    GC.Collect();
                    GC.WaitForPendingFinalizers();
                }
                int queued = mesh.PendingRenders.Count;
                Check.True(queued >= 1, "finalized render buffers are queued: " + queued);
                int alive = 0;
                foreach (IntPtr id in dropped) alive += Alive(id) ? 1 : 0;
                Check.Equal(dropped.Length, alive, "queued, not destroyed by the finalizer");
                mesh.SplitFace(new Face(0), 0.5f, 0.2f, 0.5f);
                kept.Sync(); // the mesh's thread destroys them
                Check.Equal(0, mesh.PendingRenders.Count);
                alive = 0;
                foreach (IntPtr id in dropped) alive += Alive(id) ? 1 : 0;
                Check.Equal(dropped.Length - queued, alive, "the queued ones are gone");
                Check.Equal(6, kept.Counts.Triangles);
                Check.Valid(mesh);
            }
            // The library is still fine after finalizers destroyed meshes and render objects.
            using (HalfEdgeMesh mesh = Meshes.Tet())
            {
                Check.Equal(4, mesh.FaceCount);
                Check.Valid(mesh);
            }
        }
    }
}
