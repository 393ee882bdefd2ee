// The component and the uploader never go stale: a script that syncs the render buffers itself
// (Sync(), Rebuild(), CommitTransaction()) used to leave the Unity mesh behind, because the upload
// followed only the result of its own sync. Every sync now reaches each uploader's change log.
using System;
using System.Reflection;
using Hedge.Unity;
using UnityEngine;
using UnityEngine.Rendering;

namespace Hedge.Tests
{
    public static class StaleUploadTests
    {
        // A flat n x n grid of unit squares at z = 0, in Unity's winding.
        static UnityEngine.Mesh Grid(int n) { return StandinMeshes.Grid(n, "grid"); }

        // The stand-in mesh holds the positions and indices of the render buffers.
        static void CheckCurrent(RenderBuffers buffers, UnityEngine.Mesh mesh, string what)
        {
            BufferCounts counts = buffers.Counts;
            var expected = new float[buffers.CopyStream(VertexStream.Vertices, null)];
            buffers.CopyStream(VertexStream.Vertices, expected);
            Check.Same(expected, (float[])mesh.Streams[0], expected.Length, "positions " + what);
            var indices = new int[counts.IndexCount];
            buffers.CopyIndices(indices);
            var uploaded = new int[indices.Length];
            for (int i = 0; i < indices.Length; ++i) uploaded[i] = Convert.ToInt32(mesh.IndexBuffer.GetValue(i));
            Check.Same(indices, uploaded, indices.Length, "indices " + what);
            Check.Equal(counts.IndexCount, mesh.SubMesh.indexCount, "the submesh " + what);
        }

        // What a script does to the buffers behind the uploader's back, after an edit it made.
        static readonly string[] Calls = { "Sync", "Rebuild", "CommitTransaction" };

        static void EditAndSyncBehindTheBack(HalfEdgeMesh mesh, RenderBuffers buffers, string call, float z)
        {
            if (call == "CommitTransaction") buffers.BeginTransaction();
            mesh.SetPosition(new Vertex(6), 1, 1, z);
            SurfaceHit hit;
            Check.True(mesh.Raycast(new Vec3(2.5f, 2.5f, -5), new Vec3(0, 0, 1), out hit));
            Check.True(mesh.SplitFace(hit.Face, hit.Point).IsValid);
            if (call == "Sync") Check.False(buffers.Sync().IsEmpty, "the script's sync found the edits");
            else if (call == "Rebuild") Check.True(buffers.Rebuild().Full);
            else Check.False(buffers.CommitTransaction().IsEmpty, "the script's commit synced the edits");
        }

        [Test]
        static void ComponentSeesSyncsItDidNotMake()
        {
            foreach (string call in Calls)
            {
                var go = new GameObject();
                go.AddComponent<MeshFilter>().sharedMesh = Grid(4);
                HalfEdgeMeshBehaviour b = go.AddComponent<HalfEdgeMeshBehaviour>();
                CheckCurrent(b.Buffers, b.RenderedMesh, "after building");
                EditAndSyncBehindTheBack(b.HalfEdgeMesh, b.Buffers, call, 3);
                b.Upload();  // LateUpdate
                CheckCurrent(b.Buffers, b.RenderedMesh, "after a script's " + call + "()");
                Check.Near(3, b.RenderedMesh.bounds.max.z, 1e-6, "the bounds after a script's " + call + "()");
                // And again, after the component's own upload.
                EditAndSyncBehindTheBack(b.HalfEdgeMesh, b.Buffers, call, 4);
                b.Upload();
                CheckCurrent(b.Buffers, b.RenderedMesh, "after a second " + call + "()");
                Check.Valid(b.HalfEdgeMesh);
                typeof(HalfEdgeMeshBehaviour).GetMethod("OnDestroy", BindingFlags.Instance | BindingFlags.NonPublic)
                                             .Invoke(b, null);
            }
        }

        [Test]
        static void UploaderSeesSyncsItDidNotMake()
        {
            foreach (string call in Calls)
            {
                UnityEngine.Mesh source = Grid(4);
                using (HalfEdgeMesh mesh = UnityMeshes.FromUnityMesh(source.vertices, source.triangles))
                using (RenderBuffers buffers = mesh.CreateRenderBuffers(RenderOptions.Unity))
                using (var u = new NativeMeshUploader(buffers, new UnityEngine.Mesh()))
                {
                    u.UploadAll();
                    EditAndSyncBehindTheBack(mesh, buffers, call, 3);
                    u.Upload(buffers.Sync());
                    CheckCurrent(buffers, u.Mesh, "after a script's " + call + "()");
                    Check.Near(3, u.Mesh.bounds.max.z, 1e-6, "the bounds after a script's " + call + "()");
                    Check.Valid(mesh);
                }
            }
        }

        // Two syncs behind the back with different ranges: both reach the next upload, as ranges (not a
        // whole upload), and a partial upload still allocates nothing.
        [Test]
        static void MissedSyncsAccumulateAsRanges()
        {
            UnityEngine.Mesh source = Grid(8);
            using (HalfEdgeMesh mesh = UnityMeshes.FromUnityMesh(source.vertices, source.triangles))
            using (RenderBuffers buffers = mesh.CreateRenderBuffers(RenderOptions.Unity))
            using (var u = new NativeMeshUploader(buffers, new UnityEngine.Mesh()))
            {
                u.UploadAll();
                UnityEngine.Mesh rendered = u.Mesh;
                rendered.VertexUploads = rendered.IndexUploads = 0;
                mesh.SetPosition(new Vertex(0), 0, 0, 1);
                buffers.Sync();
                mesh.SetPosition(new Vertex(80), 8, 8, 2);
                buffers.Sync();
                Check.True(u.Upload(buffers.Sync()), "uploaded as ranges");
                Check.True(rendered.VertexUploads > 0 && rendered.VertexUploads < 3 * 81, "only the two moves' ranges");
                CheckCurrent(buffers, rendered, "after two missed syncs");
                Check.Near(2, rendered.bounds.max.z, 1e-6, "the bounds");

                long sink = 0;
                for (int round = 0; round < 2; ++round)
                {
                    long before = GC.GetAllocatedBytesForCurrentThread();
                    for (int i = 0; i < 50; ++i)
                    {
                        mesh.SetPosition(new Vertex(0), 0, 0, 1.5f + 0.01f * i);
                        buffers.Sync();
                        mesh.SetPosition(new Vertex(80), 8, 8, 2.5f + 0.01f * i);
                        sink += u.Upload() ? 1 : 0;
                    }
                    long allocated = GC.GetAllocatedBytesForCurrentThread() - before;
                    if (round == 1) Check.Equal(0L, allocated, "managed bytes allocated by 50 uploads after missed syncs");
                }
                Check.Equal(100L, sink);
                CheckCurrent(buffers, rendered, "after the moves");
                Check.Valid(mesh);
            }
        }

        // A model imported without Read/Write gives scripts empty arrays: building from it is an error that
        // names the fix, not an empty mesh.
        [Test]
        static void UnreadableMeshNamesTheFix()
        {
            UnityEngine.Mesh source = Grid(2);
            source.name = "rock";
            source.isReadable = false;
            var go = new GameObject();
            go.AddComponent<MeshFilter>();
            HalfEdgeMeshBehaviour b = go.AddComponent<HalfEdgeMeshBehaviour>();
            ArgumentException e = Check.ThrowsType<ArgumentException>(() => b.Build(source));
            Check.True(e.Message.Contains("rock") && e.Message.Contains("Read/Write"), e.Message);
            Check.True(b.HalfEdgeMesh == null && b.RenderedMesh == null, "nothing half-built");
            e = Check.ThrowsType<ArgumentException>(() => UnityMeshes.FromMesh(source));
            Check.True(e.Message.Contains("Read/Write"), e.Message);
            // A readable mesh builds.
            b.Build(Grid(2));
            Check.Equal(9, b.HalfEdgeMesh.VertexCount);
            using (HalfEdgeMesh m = UnityMeshes.FromMesh(Grid(2))) Check.Equal(8, m.FaceCount);
        }
    }
}
