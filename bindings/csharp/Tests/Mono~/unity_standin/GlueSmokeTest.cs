// Runs the Unity glue (Runtime/Unity/HalfEdgeMeshBehaviour.cs) against the UnityEngine stand-in:
//   mono HedgeUnityGlue.exe
// It checks that what the component uploads into the (stand-in) Mesh equals the render buffers after
// building, after single edits, after a transaction and after growth. It says nothing about Unity
// itself: the stand-in only follows Unity's documented signatures.
using System;
using System.Reflection;
using Hedge.Unity;
using UnityEngine;
using UnityEngine.Rendering;

namespace Hedge.Tests
{
    public static class GlueSmokeTest
    {
        public static int Main(string[] args)
        {
            var runner = new Runner();
            runner.AddTests(typeof(GlueSmokeTest).Assembly);
            return runner.Run(args.Length > 0 ? args[0] : null) > 0 ? 1 : 0;
        }

        // An open pyramid as a Unity Mesh holds it (taken as it is: no conversion), a seam at the apex
        // (two texcoords), and colours.
        static UnityEngine.Mesh SourceMesh()
        {
            var m = new UnityEngine.Mesh();
            m.name = "pyramid";
            m.vertices = new[]
            {
                new Vector3(0, 0, 0), new Vector3(-1, 0, 0), new Vector3(-1, 1, 0), new Vector3(0, 1, 0),
                new Vector3(-0.5f, 0.5f, 1), new Vector3(-0.5f, 0.5f, 1),
            };
            m.normals = new[]
            {
                new Vector3(0, 0, -1), new Vector3(0, 0, -1), new Vector3(0, 0, -1), new Vector3(0, 0, -1),
                new Vector3(0, 0, 1), new Vector3(0, 0, 1),
            };
            m.uv = new[]
            {
                new Vector2(0, 0), new Vector2(1, 0), new Vector2(1, 1), new Vector2(0, 1),
                new Vector2(0.5f, 0.5f), new Vector2(0.25f, 0.75f),
            };
            m.colors = new[]
            {
                new Color(1, 0, 0, 1), new Color(0, 1, 0, 1), new Color(0, 0, 1, 1), new Color(1, 1, 0, 1),
                new Color(1, 1, 1, 1), new Color(1, 1, 1, 1),
            };
            // Counter-clockwise (0, 1, 4), (1, 2, 4), (2, 3, 5), (3, 0, 5) in hedge's axes, reversed.
            m.triangles = new[] { 0, 4, 1, 1, 4, 2, 2, 5, 3, 3, 5, 0 };
            return m;
        }

        // The stand-in mesh's buffers hold exactly the render buffers (their first Counts entries).
        static void CheckUploaded(HalfEdgeMeshBehaviour b, string what)
        {
            UnityEngine.Mesh mesh = b.RenderedMesh;
            RenderBuffers buffers = b.Buffers;
            BufferCounts counts = buffers.Counts;
            // Streams in VertexAttribute order: Position, Normal, Color, TexCoord0.
            var streams = new[] { VertexStream.Vertices, VertexStream.Normals, VertexStream.Colors, VertexStream.Texcoords };
            var attributes = new[] { VertexAttribute.Position, VertexAttribute.Normal, VertexAttribute.Color,
                                     VertexAttribute.TexCoord0 };
            Check.Equal(4, mesh.Attributes.Length, "four attributes");
            for (int s = 0; s < 4; ++s)
            {
                VertexAttributeDescriptor d = mesh.Attributes[s];
                Check.Equal(attributes[s], d.attribute);
                Check.Equal(s, d.stream, "one stream per attribute");
                var expected = new float[buffers.CopyStream(streams[s], null)];
                buffers.CopyStream(streams[s], expected);
                Check.Equal((int)counts.VertexSlots * d.dimension, expected.Length);
                var uploaded = (float[])mesh.Streams[s];
                Check.True(uploaded.Length >= expected.Length, "the GPU stream holds the buffer");
                Check.Same(expected, uploaded, expected.Length, streams[s] + " " + what);
            }
            var indices = new int[counts.IndexCount];
            buffers.CopyIndices(indices);
            Check.Equal(IndexFormat.UInt32, mesh.IndexFormatUsed);
            Check.Same(indices, (int[])mesh.IndexBuffer, indices.Length, "indices " + what);
            Check.Equal((int)counts.IndexCount, mesh.SubMesh.indexCount, "the submesh covers the index buffer");
            Check.Equal(0, mesh.SubMesh.indexStart);
        }

        static void CheckBounds(Bounds b, Vector3 min, Vector3 max, string what)
        {
            Check.True(Math.Abs(b.min.x - min.x) < 1e-6f && Math.Abs(b.min.y - min.y) < 1e-6f &&
                       Math.Abs(b.min.z - min.z) < 1e-6f, "bounds min " + what);
            Check.True(Math.Abs(b.max.x - max.x) < 1e-6f && Math.Abs(b.max.y - max.y) < 1e-6f &&
                       Math.Abs(b.max.z - max.z) < 1e-6f, "bounds max " + what);
        }

        // The normal uploaded for the corner of vertex v entered by h.
        static Vec3 UploadedNormal(HalfEdgeMeshBehaviour b, HalfEdge h)
        {
            var n = (float[])b.RenderedMesh.Streams[1];
            int rv = b.Buffers.GetRenderVertex(h);
            return new Vec3(n[3 * rv], n[3 * rv + 1], n[3 * rv + 2]);
        }

        // Lifting a base corner of the pyramid tilts its normal by default; with keepImportedNormals the
        // imported (0, 0, -1) stays.
        [Test]
        static void NormalsFollowOrStay()
        {
            foreach (bool keep in new[] { false, true })
            {
                var go = new GameObject();
                go.AddComponent<MeshFilter>().sharedMesh = SourceMesh();
                HalfEdgeMeshBehaviour b = go.AddComponent<HalfEdgeMeshBehaviour>();
                b.keepImportedNormals = keep;
                b.Build(SourceMesh());
                HalfEdgeMesh m = b.HalfEdgeMesh;
                HalfEdge corner = m.FindHalfEdge(new Vertex(1), new Vertex(0));  // enters vertex 0
                Check.Equal(new Vec3(0, 0, -1), UploadedNormal(b, corner), "imported");
                m.SetPosition(new Vertex(0), 0, 0, -1);
                b.Upload();
                CheckUploaded(b, "after a move, keep " + keep);
                Vec3 n = UploadedNormal(b, corner);
                if (keep) Check.Equal(new Vec3(0, 0, -1), n, "kept");
                else Check.True(Math.Abs(n.X) + Math.Abs(n.Y) > 0.1f && n.Z > -0.999f, "recomputed: " + n);
                Check.Valid(m);
            }
        }

        // Edits on a component whose mesh was released (after OnDestroy): a clear error, not a null reference.
        [Test]
        static void EditsAfterReleaseAreAClearError()
        {
            var go = new GameObject();
            go.AddComponent<MeshFilter>().sharedMesh = SourceMesh();
            HalfEdgeMeshBehaviour b = go.AddComponent<HalfEdgeMeshBehaviour>();
            b.BeginEdit();
            Check.True(b.HalfEdgeMesh.SplitFace(new Face(0), 0.4f, 0.3f, 0.2f).IsValid);
            b.EndEdit();
            Check.Valid(b.HalfEdgeMesh);
            typeof(HalfEdgeMeshBehaviour).GetMethod("OnDestroy", BindingFlags.Instance | BindingFlags.NonPublic)
                .Invoke(b, null);
            var e = Check.ThrowsType<InvalidOperationException>(() => b.BeginEdit(), "after OnDestroy");
            Check.True(e.Message.Contains("BeginEdit") && e.Message.Contains("no mesh"), e.Message);
            Check.ThrowsType<InvalidOperationException>(() => b.EndEdit(), "after OnDestroy");
            b.Upload();  // LateUpdate's call: nothing to upload, no error
        }

        [Test]
        static void BuildEditUpload()
        {
            var go = new GameObject();
            MeshFilter filter = go.AddComponent<MeshFilter>();
            UnityEngine.Mesh source = SourceMesh();
            filter.sharedMesh = source;
            HalfEdgeMeshBehaviour b = go.AddComponent<HalfEdgeMeshBehaviour>(); // Awake builds

            Check.True(b.HalfEdgeMesh != null && b.Buffers != null, "built in Awake");
            Check.True(filter.sharedMesh == b.RenderedMesh && b.RenderedMesh != source, "renders its own mesh");
            Check.True(b.RenderedMesh.Dynamic, "marked dynamic");
            Check.Equal(5, b.HalfEdgeMesh.VertexCount, "the apex copies welded");
            Check.Equal(1, b.Report.WeldedVertices);
            Check.Equal(4, b.HalfEdgeMesh.FaceCount);
            Check.Equal(new Vec3(-0.5f, 0.5f, 1), b.HalfEdgeMesh.GetPosition(new Vertex(4)), "Unity's own coordinates");
            Check.Equal(6, b.Buffers.Counts.Vertices, "the seam at the apex survives");
            CheckUploaded(b, "after building");
            CheckBounds(b.RenderedMesh.bounds, new Vector3(-1, 0, 0), new Vector3(0, 1, 1), "after building");

            // One move: a partial upload; the bounds grow by the moved vertex, no pass over all vertices.
            UnityEngine.Mesh rendered = b.RenderedMesh;
            rendered.VertexUploads = 0;
            rendered.IndexUploads = 0;
            b.HalfEdgeMesh.SetPosition(new Vertex(4), 0.5f, 0.5f, 2);
            b.Upload();
            Check.True(rendered.VertexUploads > 0, "vertex ranges uploaded");
            Check.False(b.Buffers.LastResult.Resized, "within the capacity");
            // Exactly the dirty ranges: 12 floats a vertex over the four streams. (The normals follow the
            // move, so the corners whose normals changed are rewritten too.)
            var dirty = new SlotRange[64];
            int dirtyVertices = 0, dirtyIndices = 0;
            for (int i = 0, n = b.Buffers.GetDirtyVertexRanges(dirty); i < n; ++i) dirtyVertices += (int)dirty[i].Count;
            for (int i = 0, n = b.Buffers.GetDirtyIndexRanges(dirty); i < n; ++i) dirtyIndices += (int)dirty[i].Count;
            Check.Equal(12 * dirtyVertices, rendered.VertexUploads, "only the dirty vertex ranges");
            Check.Equal(dirtyIndices, rendered.IndexUploads, "only the dirty index ranges");
            CheckUploaded(b, "after a move");
            CheckBounds(rendered.bounds, new Vector3(-1, 0, 0), new Vector3(0.5f, 1, 2), "grown by the move");
            // Moving it back inward leaves them as large (never too small) until TightenBounds().
            b.HalfEdgeMesh.SetPosition(new Vertex(4), -0.5f, 0.5f, 1);
            b.Upload();
            CheckBounds(rendered.bounds, new Vector3(-1, 0, 0), new Vector3(0.5f, 1, 2), "kept after an inward move");
            b.TightenBounds();
            CheckBounds(rendered.bounds, new Vector3(-1, 0, 0), new Vector3(0, 1, 1), "tightened");
            b.HalfEdgeMesh.SetPosition(new Vertex(4), 0.5f, 0.5f, 2);
            b.Upload();
            Check.Equal(0, rendered.BoundsRecalculations, "no RecalculateBounds over all vertices");

            // A transaction: uploaded once, at EndEdit.
            b.BeginEdit();
            Check.True(b.HalfEdgeMesh.SplitFace(new Face(0), 0.5f, 0.2f, 0.6f).IsValid);
            HalfEdge h12 = b.HalfEdgeMesh.FindHalfEdge(new Vertex(1), new Vertex(2));
            Check.True(b.HalfEdgeMesh.SplitHalfEdge(h12, 1, 0.5f, 0).IsValid);
            rendered.IndexUploads = 0;
            b.Upload(); // inside the transaction: nothing
            Check.Equal(0, rendered.IndexUploads);
            b.EndEdit();
            Check.True(rendered.IndexUploads > 0);
            Check.True(b.RenderedMesh == rendered, "no reallocation: within the capacity");
            CheckUploaded(b, "after a transaction");
            Check.Valid(b.HalfEdgeMesh);

            // Growth beyond the capacity: the buffers are reallocated and uploaded whole.
            int gpuVertices = rendered.VertexBufferCount;
            while (b.HalfEdgeMesh.VertexCount <= gpuVertices) b.HalfEdgeMesh.SplitAllFaces();
            b.Upload();
            Check.True(rendered.VertexBufferCount > gpuVertices, "reallocated: " + rendered.VertexBufferCount);
            CheckUploaded(b, "after growth");
            CheckBounds(rendered.bounds, new Vector3(-1, 0, 0), new Vector3(1, 1, 2), "after growth (a split put a vertex at x = 1)");
            Check.Valid(b.HalfEdgeMesh);

            // Removing faces leaves free slots; Compact() on the buffers moves every slot, and the next
            // upload must send everything (it used to send nothing, leaving stale indices and submesh).
            int removed = 0;
            for (int f = 0; f < b.HalfEdgeMesh.Counts.FaceSlots && removed < 5; ++f)
                if (b.HalfEdgeMesh.CanRemoveFace(new Face(f)) && b.HalfEdgeMesh.RemoveFace(new Face(f))) ++removed;
            Check.Equal(5, removed);
            b.Upload();
            Check.True(b.Buffers.Counts.FreeTriangleSlots > 0, "holes before compaction");
            b.Buffers.Compact();
            Check.Equal(0, b.Buffers.Counts.FreeTriangleSlots);
            b.Upload();
            CheckUploaded(b, "after Compact()");
            Check.Valid(b.HalfEdgeMesh);

            // OnDestroy releases the native objects and the Unity mesh.
            HalfEdgeMesh native = b.HalfEdgeMesh;
            typeof(HalfEdgeMeshBehaviour).GetMethod("OnDestroy", BindingFlags.Instance | BindingFlags.NonPublic)
                                         .Invoke(b, null);
            Check.True(native.IsDisposed);
            Check.True(UnityEngine.Object.Destroyed.Contains(rendered));
            Check.True(b.HalfEdgeMesh == null && b.Buffers == null);
        }
    }
}
