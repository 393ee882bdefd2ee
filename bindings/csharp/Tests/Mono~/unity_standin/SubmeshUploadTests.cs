// Submeshes (materials) through the Unity glue, against the UnityEngine stand-in: a source mesh of
// two materials keeps them as face submeshes, and both uploaders (NativeMeshUploader and
// HalfEdgeMeshBehaviour) give the Unity mesh one SubMeshDescriptor per submesh whose index range
// holds exactly that submesh's faces, with first vertex, vertex count and bounds, after edits,
// subdivision and decimation. It says nothing about Unity itself.
using System;
using Hedge.Unity;
using UnityEngine;
using UnityEngine.Rendering;

namespace Hedge.Tests
{
    public static class SubmeshUploadTests
    {
        // An n x n grid of unit squares at z = 0: the left half of the columns in submesh 0, the right half
        // in submesh 1, set with SetTriangles per submesh as a multi-material model is.
        static UnityEngine.Mesh TwoMaterialGrid(int n)
        {
            var m = new UnityEngine.Mesh();
            m.name = "two materials";
            Vector3[] v = StandinMeshes.GridPositions(n);
            var left = new System.Collections.Generic.List<int>();
            var right = new System.Collections.Generic.List<int>();
            for (int y = 0; y < n; ++y)
                for (int x = 0; x < n; ++x)
                    (2 * x < n ? left : right).AddRange(StandinMeshes.SquareTriangles(n, x, y));
            m.vertices = v;
            m.subMeshCount = 2;
            m.SetTriangles(left.ToArray(), 0);
            m.SetTriangles(right.ToArray(), 1);
            return m;
        }

        // Every submesh descriptor equals the buffers' range, holds only faces of its submesh (and every
        // live triangle lies in one), its indices lie in its vertex range, its bounds hold its positions.
        static void CheckSubmeshes(UnityEngine.Mesh rendered, HalfEdgeMesh mesh, RenderBuffers buffers, string what)
        {
            int count = buffers.SubmeshCount;
            Check.Equal(count, rendered.subMeshCount, "subMeshCount " + what);
            var p = (float[])rendered.Streams[0];
            int live = 0;
            for (int i = 0; i < count; ++i)
            {
                SubMeshDescriptor d = rendered.GetSubMesh(i);
                SubmeshRange r = buffers.GetSubmesh(i);
                Check.Equal((int)r.IndexStart, d.indexStart, "indexStart of " + i + " " + what);
                Check.Equal((int)r.IndexCount, d.indexCount, "indexCount of " + i + " " + what);
                Check.Equal((int)r.FirstVertex, d.firstVertex, "firstVertex of " + i + " " + what);
                Check.Equal((int)r.VertexCount, d.vertexCount, "vertexCount of " + i + " " + what);
                Check.True((rendered.GetSubMeshFlags(i) & MeshUpdateFlags.DontRecalculateBounds) != 0,
                           "bounds given, not recalculated " + what);
                Vector3 lo = d.bounds.min, hi = d.bounds.max;
                const float eps = 1e-5f;
                for (int k = d.indexStart; k < d.indexStart + d.indexCount; ++k)
                {
                    int v = Convert.ToInt32(rendered.IndexBuffer.GetValue(k));
                    Check.True(v >= d.firstVertex && v < d.firstVertex + d.vertexCount,
                               "index " + k + " in the vertex range of submesh " + i + " " + what);
                    Face f = buffers.FaceOfTriangle(k / 3);
                    if (!f.IsValid || mesh.IsDeleted(f)) continue;
                    if (k % 3 == 0)
                    {
                        ++live;
                        Check.Equal(i, mesh.GetSubmesh(f), "triangle " + k / 3 + "'s face in submesh " + i + " " + what);
                    }
                    Check.True(p[3 * v] >= lo.x - eps && p[3 * v] <= hi.x + eps && p[3 * v + 1] >= lo.y - eps &&
                               p[3 * v + 1] <= hi.y + eps && p[3 * v + 2] >= lo.z - eps && p[3 * v + 2] <= hi.z + eps,
                               "bounds of submesh " + i + " hold render vertex " + v + " " + what);
                }
            }
            Check.Equal((int)buffers.Counts.Triangles, live, "every live triangle in its submesh " + what);
            Check.Valid(mesh);
        }

        // The face on either side of the edge a-b that is not the outside.
        static Face FaceAt(HalfEdgeMesh mesh, int a, int b)
        {
            HalfEdge h = mesh.FindHalfEdge(new Vertex(a), new Vertex(b));
            if (!h.IsValid || mesh.IsBoundary(h)) h = mesh.FindHalfEdge(new Vertex(b), new Vertex(a));
            return mesh.GetFace(h);
        }

        [Test]
        static void NativeUploaderGivesOneRangePerSubmesh()
        {
            UnityEngine.Mesh source = TwoMaterialGrid(4);
            BuildReport report;
            using (HalfEdgeMesh mesh = UnityMeshes.FromMesh(source, EngineImportOptions.Unity, out report))
            using (RenderBuffers buffers = mesh.CreateRenderBuffers(RenderOptions.Unity))
            {
                Check.Equal(0, mesh.GetSubmesh(FaceAt(mesh, 0, 6)));
                Check.Equal(1, mesh.GetSubmesh(FaceAt(mesh, 3, 9)));
                var rendered = new UnityEngine.Mesh();
                using (var u = new NativeMeshUploader(buffers, rendered))
                {
                    u.UploadAll();
                    CheckSubmeshes(rendered, mesh, buffers, "after the first upload");
                    Check.True(rendered.GetSubMesh(0).bounds.max.x <= 2.0001f, "submesh 0 is the left half");
                    Check.True(rendered.GetSubMesh(1).bounds.min.x >= 1.9999f, "submesh 1 is the right half");

                    Vertex mid = mesh.SplitEdge(mesh.GetEdge(mesh.FindHalfEdge(new Vertex(6), new Vertex(7))), 1.5f, 1, 0);
                    Check.True(u.Upload(buffers.Sync()), "a split is a partial upload");
                    CheckSubmeshes(rendered, mesh, buffers, "after a split");
                    HalfEdge h = mesh.FindHalfEdge(new Vertex(12), new Vertex(13));
                    Check.True(mesh.CanCollapse(h));
                    mesh.Collapse(h);
                    Check.True(u.Upload(buffers.Sync()), "a collapse is a partial upload");
                    CheckSubmeshes(rendered, mesh, buffers, "after a collapse");
                    mesh.SetPosition(mid, 1.5f, 1, 3);
                    u.Upload(buffers.Sync());
                    CheckSubmeshes(rendered, mesh, buffers, "after a move");
                    Check.True(rendered.GetSubMesh(0).bounds.max.z >= 2.9999f, "the moved vertex is in submesh 0's box");
                    mesh.SetSubmesh(FaceAt(mesh, 0, 6), 1);
                    u.Upload(buffers.Sync());
                    CheckSubmeshes(rendered, mesh, buffers, "after a face changed material");
                    Check.Throws(HedgeStatus.InvalidArgument, () => mesh.SetSubmesh(FaceAt(mesh, 0, 1), -1));
                    Check.Equal(1, mesh.GetSubmesh(FaceAt(mesh, 0, 1)), "a refused id changes nothing (the face set to 1 above)");

                    mesh.Subdivide(Subdivision.Loop);
                    u.Upload(buffers.Sync());
                    CheckSubmeshes(rendered, mesh, buffers, "after subdivision");
                    DecimateOptions o = DecimateOptions.Default;
                    o.TargetFaces = (ulong)mesh.FaceCount / 3;
                    mesh.Decimate(o);
                    u.Upload(buffers.Sync());
                    CheckSubmeshes(rendered, mesh, buffers, "after decimation");
                    Check.Equal(2, rendered.subMeshCount);
                }
            }
        }

        [Test]
        static void BehaviourKeepsTheSourceMaterials()
        {
            var go = new GameObject();
            go.AddComponent<MeshFilter>().sharedMesh = TwoMaterialGrid(4);
            HalfEdgeMeshBehaviour b = go.AddComponent<HalfEdgeMeshBehaviour>();  // Awake builds
            CheckSubmeshes(b.RenderedMesh, b.HalfEdgeMesh, b.Buffers, "after building");
            HalfEdgeMesh m = b.HalfEdgeMesh;
            m.SplitEdge(m.GetEdge(m.FindHalfEdge(new Vertex(7), new Vertex(8))), 2.5f, 1, 0);
            b.Upload();
            CheckSubmeshes(b.RenderedMesh, m, b.Buffers, "after a split");
            HalfEdge h = m.FindHalfEdge(new Vertex(17), new Vertex(18));
            Check.True(m.CanCollapse(h));
            m.Collapse(h);
            b.Upload();
            CheckSubmeshes(b.RenderedMesh, m, b.Buffers, "after a collapse");
        }

        [Test]
        static void ReadTrianglesConcatenatesTheSubmeshes()
        {
            UnityEngine.Mesh source = TwoMaterialGrid(2);
            int[] ids;
            int[] t = UnitySubmeshes.ReadTriangles(source, out ids);
            Check.Equal(24, t.Length);
            Check.Equal(8, ids.Length);
            Check.Equal(0, ids[0]);
            Check.Equal(1, ids[7]);
            UnityEngine.Mesh single = new UnityEngine.Mesh();
            single.vertices = source.vertices;
            single.triangles = source.triangles;
            Check.Equal(24, UnitySubmeshes.ReadTriangles(single, out ids).Length);
            Check.True(ids == null, "one submesh: no ids");
        }
    }
}
