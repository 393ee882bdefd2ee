// The zero-copy path of the Unity glue (NativeMeshUploader, UnityMeshes) and the click-to-split
// sample, run against the UnityEngine stand-in: what reaches the (stand-in) Mesh equals the render
// buffers, through NativeArrays over the library's memory, with 16-bit indices while they fit.
// It says nothing about Unity itself.
using System;
using System.Reflection;
using Hedge.Unity;
using Unity.Collections;
using Unity.Collections.LowLevel.Unsafe;
using UnityEngine;
using UnityEngine.Rendering;

namespace Hedge.Tests
{
    public static class NativeUploadTests
    {
        // A flat n x n grid of unit squares at z = 0 as Unity arrays, with texcoords.
        static UnityEngine.Mesh Grid(int n)
        {
            UnityEngine.Mesh m = StandinMeshes.Grid(n, "grid");
            Vector3[] v = m.vertices;
            var uv = new Vector2[v.Length];
            for (int i = 0; i < v.Length; ++i) uv[i] = new Vector2(v[i].x / n, v[i].y / n);
            m.uv = uv;
            return m;
        }

        [Test]
        static void UnityArraysInAndOut()
        {
            UnityEngine.Mesh source = Grid(3);
            using (HalfEdgeMesh mesh = UnityMeshes.FromUnityMesh(source.vertices, source.triangles, null, source.uv, null))
            {
                Check.Equal(16, mesh.VertexCount);
                Check.Equal(18, mesh.FaceCount);
                Check.Equal(16, mesh.CopyPositions((Vector3[])null), "the size query");
                var positions = new Vector3[16];
                Check.Equal(16, mesh.CopyPositions(positions));
                var expected = new float[3 * 16];
                mesh.CopyPositions(expected);
                for (int i = 0; i < 16; ++i)
                    Check.Equal(new Vec3(expected[3 * i], expected[3 * i + 1], expected[3 * i + 2]), positions[i].ToVec3());
                Check.Throws(HedgeStatus.BufferTooSmall, () => mesh.CopyPositions(new Vector3[15]));
                // Empty attribute arrays (what Unity returns for absent ones) mean none.
                using (HalfEdgeMesh again = UnityMeshes.FromUnityMesh(source.vertices, source.triangles, new Vector3[0],
                                                                      new Vector2[0], new Color[0]))
                    Check.Equal(18, again.FaceCount);
                Check.ThrowsType<ArgumentException>(() => UnityMeshes.FromUnityMesh(source.vertices, source.triangles,
                                                                                     new Vector3[3]));
                BuildReport report;
                Check.Throws(HedgeStatus.InvalidArgument,
                             () => UnityMeshes.FromUnityMesh(source.vertices, new[] { 0, 1, 99 }, null, null, null,
                                                             EngineImportOptions.Unity, out report));
                // Vector3 overloads of the picking calls, in the mesh's own space.
                SurfaceHit hit;
                Check.True(mesh.Raycast(new Vector3(1.5f, 2.5f, -3), new Vector3(0, 0, 1), out hit));
                Check.Equal(new Vec3(1.5f, 2.5f, 0), hit.Point);
                Face face;
                Check.True(mesh.TryGetFaceContainingPoint(new Vector3(1.5f, 2.5f, 0), out face));
                Check.Equal(hit.Face, face);
                Check.Valid(mesh);
            }
        }

        // The stand-in mesh holds exactly the render buffers, as 16- or 32-bit indices.
        static void CheckUploaded(NativeMeshUploader u, string what)
        {
            RenderBuffers buffers = u.Buffers;
            UnityEngine.Mesh mesh = u.Mesh;
            BufferCounts counts = buffers.Counts;
            VertexLayout layout = buffers.Layout;
            int present = 1 + (layout.HasNormals ? 1 : 0) + (layout.HasTexcoords ? 1 : 0) + (layout.HasColors ? 1 : 0);
            Check.Equal(present, mesh.Attributes.Length, "one attribute per stream present");
            foreach (VertexAttributeDescriptor d in mesh.Attributes)
            {
                VertexStream stream = d.attribute == VertexAttribute.Position ? VertexStream.Vertices
                                      : d.attribute == VertexAttribute.Normal ? VertexStream.Normals
                                      : d.attribute == VertexAttribute.TexCoord0 ? VertexStream.Texcoords
                                      : VertexStream.Colors;
                var expected = new float[buffers.CopyStream(stream, null)];
                buffers.CopyStream(stream, expected);
                Check.True(expected.Length > 0, stream + " is present");
                Check.Same(expected, (float[])mesh.Streams[d.stream], expected.Length, stream + " " + what);
            }
            var indices = new int[counts.IndexCount];
            buffers.CopyIndices(indices);
            var uploaded = new int[indices.Length];
            for (int i = 0; i < indices.Length; ++i) uploaded[i] = Convert.ToInt32(mesh.IndexBuffer.GetValue(i));
            Check.Same(indices, uploaded, indices.Length, "indices " + what);
            Check.Equal((int)counts.IndexCount, mesh.SubMesh.indexCount, "the submesh covers the index buffer");
            // Bounds hold every live position.
            var p = new float[buffers.CopyStream(VertexStream.Vertices, null)];
            buffers.CopyStream(VertexStream.Vertices, p);
            var source = new Vertex[counts.VertexSlots];
            buffers.CopyVertexSource(source);
            Vector3 lo = mesh.bounds.min, hi = mesh.bounds.max;
            for (int v = 0; v < source.Length; ++v)
            {
                if (!source[v].IsValid) continue;
                Check.True(p[3 * v] >= lo.x && p[3 * v] <= hi.x && p[3 * v + 1] >= lo.y && p[3 * v + 1] <= hi.y &&
                           p[3 * v + 2] >= lo.z && p[3 * v + 2] <= hi.z, "bounds hold render vertex " + v + " " + what);
            }
        }

        [Test]
        static void UploadsFromNativeMemory()
        {
            UnityEngine.Mesh source = Grid(4);
            int liveBefore = NativeArray<ushort>.LiveAllocations;
            using (HalfEdgeMesh mesh = UnityMeshes.FromUnityMesh(source.vertices, source.triangles, null, source.uv, null))
            using (RenderBuffers buffers = mesh.CreateRenderBuffers(RenderOptions.Unity))
            {
                var rendered = new UnityEngine.Mesh();
                using (var u = new NativeMeshUploader(buffers, rendered))
                {
                    int wrapped = NativeArrayUnsafeUtility.WrappedArrays;
                    u.UploadAll();
                    Check.True(NativeArrayUnsafeUtility.WrappedArrays > wrapped, "the native buffers were wrapped, not copied");
                    Check.Equal(IndexFormat.UInt16, u.IndexFormat, "25 vertices fit 16-bit indices");
                    Check.Equal(IndexFormat.UInt16, rendered.IndexFormatUsed);
                    Check.True(rendered.NativeVertexUploads > 0 && rendered.NativeIndexUploads > 0);
                    CheckUploaded(u, "after the first upload");

                    // A move outside the box: a partial upload, from NativeArrays, and the bounds grow.
                    SurfaceHit hit;
                    Check.True(mesh.Raycast(new Vector3(2, 2, -1), new Vector3(0, 0, 1), out hit));
                    Vertex v = hit.Corner0;
                    rendered.VertexUploads = rendered.IndexUploads = 0;
                    mesh.SetPosition(v, new Vector3(2, 2, 5));
                    Check.True(u.Upload(buffers.Sync()), "a partial upload");
                    Check.True(rendered.VertexUploads > 0 && rendered.VertexUploads < 3 * 25, "only the dirty ranges");
                    Check.Equal(0, rendered.IndexUploads);
                    Check.Near(5, rendered.bounds.max.z, 1e-6, "the bounds grew by the moved vertex");
                    CheckUploaded(u, "after a move");

                    // Splits and a collapse: index ranges in 16 bits.
                    for (int i = 0; i < 6; ++i)
                    {
                        Check.True(mesh.Raycast(new Vector3(0.3f + 0.6f * i, 1.2f, -1), new Vector3(0, 0, 1), out hit));
                        Vector3 a = mesh.GetPositionVector(hit.Corner0), b = mesh.GetPositionVector(hit.Corner1);
                        HalfEdge h = mesh.FindHalfEdge(hit.Corner0, hit.Corner1);
                        Check.True(mesh.SplitEdge(h.Edge, 0.5f * (a + b)).IsValid);
                    }
                    rendered.IndexUploads = 0;
                    u.Upload(buffers.Sync());
                    Check.True(rendered.IndexUploads > 0);
                    CheckUploaded(u, "after splits");
                    Check.True(mesh.Raycast(new Vector3(3.3f, 3.3f, -1), new Vector3(0, 0, 1), out hit));
                    HalfEdge c = mesh.FindHalfEdge(hit.Corner0, hit.Corner1);
                    Check.True(mesh.CanCollapse(c) && mesh.Collapse(c).IsValid);
                    u.Upload(buffers.Sync());
                    CheckUploaded(u, "after a collapse");

                    // Compact() moves every slot: the next upload sends everything.
                    buffers.Compact();
                    u.Upload(buffers.Sync());
                    CheckUploaded(u, "after Compact()");

                    // A partial upload allocates no managed memory.
                    long sink = 0;
                    for (int round = 0; round < 2; ++round)
                    {
                        long before = GC.GetAllocatedBytesForCurrentThread();
                        for (int i = 0; i < 50; ++i)
                        {
                            mesh.SetPosition(v, new Vector3(2, 2, 5 + 0.01f * i));
                            sink += u.Upload(buffers.Sync()) ? 1 : 0;
                        }
                        long allocated = GC.GetAllocatedBytesForCurrentThread() - before;
                        if (round == 1) Check.Equal(0L, allocated, "managed bytes allocated by 50 partial uploads");
                    }
                    Check.True(sink > 0);
                    CheckUploaded(u, "after the moves");
                    Check.Valid(mesh);
                }
                Check.ThrowsType<ArgumentException>(() => new NativeMeshUploader(mesh.CreateRenderBuffers(), rendered));
            }
            Check.Equal(liveBefore, NativeArray<ushort>.LiveAllocations, "the 16-bit scratch was freed");
        }

        [Test]
        static void ThirtyTwoBitIndicesWhenTheVerticesDoNotFit()
        {
            UnityEngine.Mesh source = Grid(160); // 25921 vertices
            using (HalfEdgeMesh mesh = UnityMeshes.FromUnityMesh(source.vertices, source.triangles))
            {
                mesh.SplitAllFaces(); // + 51200 vertices: more than 65536
                using (RenderBuffers buffers = mesh.CreateRenderBuffers(RenderOptions.Unity))
                using (var u = new NativeMeshUploader(buffers, new UnityEngine.Mesh()))
                {
                    u.UploadAll();
                    Check.Equal(IndexFormat.UInt32, u.IndexFormat);
                    SurfaceHit hit;
                    Check.True(mesh.Raycast(new Vector3(10.2f, 20.7f, -1), new Vector3(0, 0, 1), out hit));
                    mesh.SplitFace(hit.Face, new Vec3(hit.Point.X, hit.Point.Y, 0));
                    Check.True(u.Upload(buffers.Sync()));
                    CheckUploaded(u, "32-bit, after a split");
                    Check.Valid(mesh);
                }
            }
        }

        [Test]
        static void ClickToSplitSample()
        {
            MeshCollider.All.Clear();
            var go = new GameObject();
            MeshFilter filter = go.AddComponent<MeshFilter>();
            filter.sharedMesh = Grid(4);
            MeshCollider collider = go.AddComponent<MeshCollider>();
            ClickToSplit sample = go.AddComponent<ClickToSplit>();
            Camera.main = new Camera();
            Invoke(sample, "Start");
            HalfEdgeMesh mesh = sample.HalfEdgeMesh;
            Check.True(filter.sharedMesh == sample.RenderedMesh && collider.sharedMesh == sample.RenderedMesh);
            Check.Equal(25, mesh.VertexCount);

            // A left click near the middle of the edge (1, 1)-(2, 1): it is split there.
            Click(sample, 0, 1.5f, 1.05f);
            Check.Equal(26, mesh.VertexCount, "one vertex added");
            SurfaceHit hit;
            Check.True(mesh.TryGetClosestPoint(new Vec3(1.5f, 1, 0), out hit));
            bool found = false;
            foreach (Vertex c in new[] { hit.Corner0, hit.Corner1, hit.Corner2 })
                found |= mesh.GetPosition(c) == new Vec3(1.5f, 1, 0);
            Check.True(found, "the new vertex sits where the edge was clicked");
            Check.True(collider.Cookings >= 2, "the collider was given the new mesh");
            // The collider sees the split: a click on the new triangles finds them.
            Click(sample, 0, 1.5f, 1.3f);
            Check.Equal(27, mesh.VertexCount, "a split of one of the new triangles' edges");
            Check.Valid(mesh);

            // A right click collapses the nearest edge: one vertex fewer.
            Click(sample, 1, 1.5f, 1.05f);
            Check.Equal(26, mesh.VertexCount, "one vertex collapsed");
            Check.Valid(mesh);
            // Clicking beside the mesh does nothing.
            Click(sample, 0, 7, 7);
            Check.Equal(26, mesh.VertexCount);

            // A button down with no mouse connected (the Input System's Mouse.current is null), or, for the
            // Input Manager, at the last position, beside the mesh: nothing happens.
            Input.ButtonsDown[0] = true;
            Invoke(sample, "Update");
            Input.ButtonsDown[0] = false;
            Check.Equal(26, mesh.VertexCount);

            Invoke(sample, "OnDestroy");
            Check.True(mesh.IsDisposed);
            Console.WriteLine("    the sample read the " + PointerInput.Source);
        }

        // One frame with a click, given to both input systems' stand-ins: the sample reads the one its
        // build enables (PointerInput.cs; the glue is compiled once for each).
        // A click of a mouse button at a screen point, through both input systems: what a sample's
        // Update reads (PointerInput), whichever one the build enables.
        internal static void Click(object sample, int button, float x, float y)
        {
            Input.mousePosition = new Vector3(x, y, 0);
            Input.ButtonsDown[button] = true;
            var mouse = new UnityEngine.InputSystem.Mouse();
            mouse.position.Value = new Vector2(x, y);
            (button == 0 ? mouse.leftButton : mouse.rightButton).wasPressedThisFrame = true;
            UnityEngine.InputSystem.Mouse.current = mouse;
            Invoke(sample, "Update");
            Input.ButtonsDown[button] = false;
            UnityEngine.InputSystem.Mouse.current = null;
        }

        static void Invoke(object target, string method)
        {
            target.GetType().GetMethod(method, BindingFlags.Instance | BindingFlags.NonPublic).Invoke(target, null);
        }
    }
}
