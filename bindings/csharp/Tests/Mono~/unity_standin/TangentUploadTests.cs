// Tangents and lightmap UVs (uv2) through the Unity glue, against the UnityEngine stand-in: both
// uploaders (NativeMeshUploader and HalfEdgeMeshBehaviour) describe at most four streams with the
// attributes of each in VertexAttribute order, and after edits (a move whose normals follow, splits,
// a collapse) every attribute a shader reads from the uploaded streams, by Unity's layout rule,
// equals the render buffers', with tangents perpendicular to the uploaded normals. Uploads stay
// partial and allocate nothing. It says nothing about Unity itself.
using System;
using Hedge.Unity;
using UnityEngine;
using UnityEngine.Rendering;

namespace Hedge.Tests
{
    public static class TangentUploadTests
    {
        // A flat n x n grid at z = 0 in Unity's winding (normals -z), with uv, tangents along +x, uv2, and
        // colours when asked.
        static UnityEngine.Mesh Grid(int n, bool colors)
        {
            var m = new UnityEngine.Mesh();
            m.name = "tangent grid";
            int count = (n + 1) * (n + 1);
            var v = new Vector3[count];
            var normals = new Vector3[count];
            var uv = new Vector2[count];
            var uv2 = new Vector2[count];
            var tangents = new Vector4[count];
            var c = new Color[count];
            for (int y = 0; y <= n; ++y)
                for (int x = 0; x <= n; ++x)
                {
                    int i = y * (n + 1) + x;
                    v[i] = new Vector3(x, y, 0);
                    normals[i] = new Vector3(0, 0, -1);
                    uv[i] = new Vector2((float)x / n, (float)y / n);
                    uv2[i] = new Vector2(0.5f + 0.5f * x / n, 0.5f * y / n);
                    tangents[i] = new Vector4(1, 0, 0, -1);
                    c[i] = new Color(x / (float)n, 0, 1, 1);
                }
            int[] t = StandinMeshes.GridTriangles(n);
            m.vertices = v;
            m.normals = normals;
            m.uv = uv;
            m.uv2 = uv2;
            m.tangents = tangents;
            if (colors) m.colors = c;
            m.triangles = t;
            return m;
        }

        static readonly VertexAttribute[] Attributes = { VertexAttribute.Position, VertexAttribute.Normal,
                                                         VertexAttribute.Tangent, VertexAttribute.Color,
                                                         VertexAttribute.TexCoord0, VertexAttribute.TexCoord1 };
        static readonly VertexStream[] Sources = { VertexStream.Vertices, VertexStream.Normals, VertexStream.Tangents,
                                                   VertexStream.Colors, VertexStream.Texcoords, VertexStream.Texcoords1 };

        // The descriptor follows Unity's rules (the stand-in checks them when it is set), uses at most four
        // streams, and every attribute of every render vertex in use reads back as the buffers hold it;
        // tangents are unit, perpendicular to the uploaded normals, handedness kept.
        static void CheckUploaded(UnityEngine.Mesh rendered, RenderBuffers buffers, int expectedStreams, string what)
        {
            Check.True(rendered.StreamCount <= 4, "at most four streams " + what);
            Check.Equal(expectedStreams, rendered.StreamCount, "streams " + what);
            BufferCounts counts = buffers.Counts;
            var indices = new int[counts.IndexCount];
            buffers.CopyIndices(indices);
            var used = new bool[counts.VertexSlots];
            for (int i = 0; i + 2 < indices.Length; i += 3)
                if (indices[i] != indices[i + 1])
                    used[indices[i]] = used[indices[i + 1]] = used[indices[i + 2]] = true;
            for (int a = 0; a < Attributes.Length; ++a)
            {
                int k = buffers.Components(Sources[a]);
                var expected = new float[buffers.CopyStream(Sources[a], null)];
                buffers.CopyStream(Sources[a], expected);
                bool present = expected.Length > 0;
                Check.Equal(present, rendered.ReadAttribute(Attributes[a], 0) != null, Attributes[a] + " described " + what);
                if (!present) continue;
                for (int r = 0; r < counts.VertexSlots; ++r)
                {
                    float[] value = rendered.ReadAttribute(Attributes[a], r);
                    for (int c = 0; c < k; ++c)
                        if (value[c] != expected[r * k + c])
                            Check.Equal(expected[r * k + c], value[c], Attributes[a] + "[" + c + "] of vertex " + r + " " + what);
                }
            }
            int checkedFrames = 0;
            for (int r = 0; r < counts.VertexSlots; ++r)
            {
                if (!used[r]) continue;
                float[] n = rendered.ReadAttribute(VertexAttribute.Normal, r);
                float[] t = rendered.ReadAttribute(VertexAttribute.Tangent, r);
                var tv = new Vec3(t[0], t[1], t[2]);
                Check.Near(0, Vec3.Dot(new Vec3(n[0], n[1], n[2]), tv), 1e-5, "tangent . normal of vertex " + r + " " + what);
                Check.Near(1, tv.Length, 1e-4, "|tangent| of vertex " + r + " " + what);
                Check.Equal(-1f, t[3], "handedness of vertex " + r + " " + what);
                ++checkedFrames;
            }
            Check.True(checkedFrames > 0);
        }

        // Moves a vertex (its normals and their tangents follow), splits two edges and collapses one, calling
        // upload after each; returns the vertex moved.
        static Vertex Edit(HalfEdgeMesh mesh, Action upload, UnityEngine.Mesh rendered, RenderBuffers buffers,
                           int streams)
        {
            SurfaceHit hit;
            Check.True(mesh.Raycast(new Vector3(2, 2, -1), new Vector3(0, 0, 1), out hit));
            Vertex v = hit.Corner0;
            mesh.SetPosition(v, mesh.GetPositionVector(v) + new Vector3(0, 0, 0.7f));
            rendered.VertexUploads = 0;
            upload();
            Check.True(rendered.VertexUploads > 0, "the move was uploaded");
            CheckUploaded(rendered, buffers, streams, "after a move");
            for (int i = 0; i < 2; ++i)
            {
                Check.True(mesh.Raycast(new Vector3(0.3f + 1.6f * i, 1.2f, -1), new Vector3(0, 0, 1), out hit));
                Vector3 a = mesh.GetPositionVector(hit.Corner0), b = mesh.GetPositionVector(hit.Corner1);
                Check.True(mesh.SplitEdge(mesh.FindHalfEdge(hit.Corner0, hit.Corner1).Edge, 0.5f * (a + b)).IsValid);
            }
            upload();
            CheckUploaded(rendered, buffers, streams, "after splits");
            Check.True(mesh.Raycast(new Vector3(3.3f, 3.3f, -1), new Vector3(0, 0, 1), out hit));
            HalfEdge c = mesh.FindHalfEdge(hit.Corner0, hit.Corner1);
            Check.True(mesh.CanCollapse(c) && mesh.Collapse(c).IsValid);
            upload();
            CheckUploaded(rendered, buffers, streams, "after a collapse");
            return v;
        }

        [Test]
        static void NativeUploaderSendsTangentsAndUv2()
        {
            // Five attributes besides positions share streams: (normal, tangent), colour, (uv, uv2). Without
            // colours, four: (normal, tangent), (uv, uv2).
            for (int variant = 0; variant < 2; ++variant)
            {
                bool colors = variant == 0;
                int streams = colors ? 4 : 3;
                UnityEngine.Mesh source = Grid(4, colors);
                BuildReport report;
                using (HalfEdgeMesh mesh = UnityMeshes.FromMesh(source, EngineImportOptions.Unity, out report))
                using (RenderBuffers buffers = mesh.CreateRenderBuffers(RenderOptions.Unity))
                using (var u = new NativeMeshUploader(buffers, new UnityEngine.Mesh()))
                {
                    Check.True(buffers.Layout.HasTangents && buffers.Layout.HasTexcoords1, "tangents and uv2 imported");
                    u.UploadAll();
                    UnityEngine.Mesh rendered = u.Mesh;
                    CheckUploaded(rendered, buffers, streams, "after the first upload");
                    Vertex moved = Edit(mesh, () => Check.True(u.Upload(), "partial"), rendered, buffers, streams);
                    Check.True(u.Pending.IsEmpty, "everything pending was uploaded");

                    // A script's own sync is seen through the change log; partial uploads allocate nothing.
                    mesh.SetPosition(moved, new Vector3(2, 2, 0.2f));
                    buffers.Sync();
                    Check.False(u.Pending.IsEmpty, "the script's sync is pending");
                    Check.True(u.Upload());
                    CheckUploaded(rendered, buffers, streams, "after a script's sync");
                    for (int round = 0; round < 2; ++round)
                    {
                        long before = GC.GetAllocatedBytesForCurrentThread();
                        for (int i = 0; i < 50; ++i)
                        {
                            mesh.SetPosition(moved, new Vector3(2, 2, 0.01f * i));
                            u.Upload();
                        }
                        long allocated = GC.GetAllocatedBytesForCurrentThread() - before;
                        if (round == 1) Check.Equal(0L, allocated, "managed bytes allocated by 50 partial uploads");
                    }
                    CheckUploaded(rendered, buffers, streams, "after the moves");
                    Check.Valid(mesh);
                }
            }
        }

        [Test]
        static void ComponentSendsTangentsAndUv2()
        {
            var go = new GameObject();
            MeshFilter filter = go.AddComponent<MeshFilter>();
            filter.sharedMesh = Grid(4, true);
            HalfEdgeMeshBehaviour b = go.AddComponent<HalfEdgeMeshBehaviour>();
            Check.True(b.Buffers.Layout.HasTangents && b.Buffers.Layout.HasTexcoords1, "tangents and uv2 imported");
            CheckUploaded(b.RenderedMesh, b.Buffers, 4, "after Awake");
            Vertex moved = Edit(b.HalfEdgeMesh, b.Upload, b.RenderedMesh, b.Buffers, 4);
            for (int round = 0; round < 2; ++round)
            {
                long before = GC.GetAllocatedBytesForCurrentThread();
                for (int i = 0; i < 50; ++i)
                {
                    b.HalfEdgeMesh.SetPosition(moved, new Vector3(2, 2, 0.01f * i));
                    b.Upload();
                }
                long allocated = GC.GetAllocatedBytesForCurrentThread() - before;
                if (round == 1) Check.Equal(0L, allocated, "managed bytes allocated by 50 uploads of the component");
            }
            CheckUploaded(b.RenderedMesh, b.Buffers, 4, "after the moves");
            Check.Valid(b.HalfEdgeMesh);
            UnityEngine.Object.Destroy(b.RenderedMesh);
        }

        [Test]
        static void DescriptorRulesAreChecked()
        {
            // The stand-in refuses what Unity's rules forbid, so the checks above can fail.
            var m = new UnityEngine.Mesh();
            Check.ThrowsType<ArgumentException>(() => m.SetVertexBufferParams(
                4, new VertexAttributeDescriptor(VertexAttribute.Position, VertexAttributeFormat.Float32, 3, 0),
                new VertexAttributeDescriptor(VertexAttribute.TexCoord0, VertexAttributeFormat.Float32, 2, 1),
                new VertexAttributeDescriptor(VertexAttribute.Tangent, VertexAttributeFormat.Float32, 4, 1)));
            Check.ThrowsType<ArgumentException>(() => m.SetVertexBufferParams(
                4, new VertexAttributeDescriptor(VertexAttribute.Position, VertexAttributeFormat.Float32, 3, 0),
                new VertexAttributeDescriptor(VertexAttribute.Normal, VertexAttributeFormat.Float32, 3, 4)));
        }
    }
}
