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

        /// <summary>Builds a HalfEdgeMesh from a Unity mesh of several submeshes: positions welded, normals, uv
        /// and colours kept per corner, and each triangle's submesh kept as its face's submesh
        /// (<see cref="UnityMeshes.FromMesh(Mesh, EngineImportOptions, out BuildReport)"/> calls it).</summary>
        internal static HalfEdgeMesh FromMesh(Mesh source, int[] triangles, int[] submeshes, EngineImportOptions options,
                                              out BuildReport report)
        {
            Vector3[] v = source.vertices;
            return HalfEdgeMesh.FromEngineMesh(Floats(v, v.Length), triangles, Floats(source.normals, v.Length),
                                               Floats(source.uv, v.Length), Floats(source.colors, v.Length), submeshes,
                                               options, out report);
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

        // Unity's empty arrays (an absent attribute) and null become null; others become floats.
        static float[] Floats(Vector3[] a, int n)
        {
            if (a == null || a.Length == 0) return null;
            if (a.Length != n) throw new ArgumentException("length " + a.Length + ", " + n + " expected (one per vertex)");
            var f = new float[3 * n];
            for (int i = 0; i < n; ++i) { f[3 * i] = a[i].x; f[3 * i + 1] = a[i].y; f[3 * i + 2] = a[i].z; }
            return f;
        }

        static float[] Floats(Vector2[] a, int n)
        {
            if (a == null || a.Length == 0) return null;
            if (a.Length != n) throw new ArgumentException("length " + a.Length + ", " + n + " expected (one per vertex)");
            var f = new float[2 * n];
            for (int i = 0; i < n; ++i) { f[2 * i] = a[i].x; f[2 * i + 1] = a[i].y; }
            return f;
        }

        static float[] Floats(Color[] a, int n)
        {
            if (a == null || a.Length == 0) return null;
            if (a.Length != n) throw new ArgumentException("length " + a.Length + ", " + n + " expected (one per vertex)");
            var f = new float[4 * n];
            for (int i = 0; i < n; ++i) { f[4 * i] = a[i].r; f[4 * i + 1] = a[i].g; f[4 * i + 2] = a[i].b; f[4 * i + 3] = a[i].a; }
            return f;
        }
    }
}
