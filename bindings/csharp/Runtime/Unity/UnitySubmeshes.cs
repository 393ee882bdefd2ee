// Submeshes (materials) between Unity meshes and the library: a source mesh's submeshes become each
// face's submesh (kept through edits, subdivision, decimation and fracture), and render buffers give
// one contiguous index range per submesh back, which SetSubMesh takes with its first vertex, vertex
// count and bounds (MeshUpdateFlags.DontRecalculateBounds makes Unity use them as given).
using System;
using UnityEngine;
using UnityEngine.Rendering;

namespace Hedge.Unity
{
    /// <summary>Submeshes of Unity meshes in and out of a HalfEdgeMesh.</summary>
    public static class UnitySubmeshes
    {
        /// <summary>A Unity mesh's triangles, submesh after submesh (GetIndices(0), GetIndices(1), ...), and
        /// each triangle's submesh; null ids for a mesh of one submesh (source.triangles as it is).</summary>
        /// <exception cref="ArgumentException">A submesh whose topology is not triangles.</exception>
        public static int[] ReadTriangles(Mesh source, out int[] triangleSubmeshes)
        {
            if (source == null) throw new ArgumentNullException("source");
            int count = source.subMeshCount;
            triangleSubmeshes = null;
            if (count <= 1) return source.triangles;
            var lists = new int[count][];
            int total = 0;
            for (int i = 0; i < count; ++i)
            {
                if (source.GetTopology(i) != MeshTopology.Triangles)
                    throw new ArgumentException("submesh " + i + " of " + source.name + " is " + source.GetTopology(i) +
                                                ", not triangles", "source");
                lists[i] = source.GetIndices(i);
                total += lists[i].Length;
            }
            var triangles = new int[total];
            triangleSubmeshes = new int[total / 3];
            int at = 0;
            for (int i = 0; i < count; ++i)
            {
                Array.Copy(lists[i], 0, triangles, at, lists[i].Length);
                for (int t = at / 3; t < (at + lists[i].Length) / 3; ++t) triangleSubmeshes[t] = i;
                at += lists[i].Length;
            }
            return triangles;
        }

        /// <summary>Sets mesh.subMeshCount to the buffers' submeshes and each SubMeshDescriptor: index start and
        /// count, first vertex, vertex count and bounds, as of the buffers' last sync. O(submeshes).</summary>
        public static void SetSubmeshes(Mesh mesh, RenderBuffers buffers, MeshUpdateFlags flags)
        {
            if (mesh == null) throw new ArgumentNullException("mesh");
            if (buffers == null) throw new ArgumentNullException("buffers");
            int n = buffers.SubmeshCount;
            if (mesh.subMeshCount != n) mesh.subMeshCount = n;
            for (int i = 0; i < n; ++i)
            {
                SubmeshRange r = buffers.GetSubmesh(i);
                var d = new SubMeshDescriptor((int)r.IndexStart, (int)r.IndexCount, MeshTopology.Triangles);
                d.firstVertex = (int)r.FirstVertex;
                d.vertexCount = (int)r.VertexCount;
                var b = new Bounds();
                b.SetMinMax(r.Min.ToVector3(), r.Max.ToVector3());
                d.bounds = b;
                mesh.SetSubMesh(i, d, flags);
            }
        }
    }
}
