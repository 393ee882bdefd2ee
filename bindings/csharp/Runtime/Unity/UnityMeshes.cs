// Unity's own array types in and out of a HalfEdgeMesh without managed copies: Vector3[], Vector2[],
// Color[] and int[] go to the native library pinned, as the float[] overloads do (all are
// blittable: three, two and four floats). Also Vector3 overloads of the picking and edit calls.
using System;
using System.Runtime.InteropServices;
using UnityEngine;

namespace Hedge.Unity
{
    /// <summary>HalfEdgeMesh calls in Unity's types.</summary>
    public static partial class UnityMeshes
    {
        /// <summary>Builds a mesh from a Unity Mesh's arrays (mesh.vertices, mesh.triangles, mesh.normals,
        /// mesh.uv, mesh.colors) with <see cref="EngineImportOptions.Unity"/>: positions welded for the
        /// topology, normals, texcoords and colours kept per corner (seams stay seams). Every face is in
        /// submesh 0: for a mesh of several submeshes (materials), use <see cref="FromMesh(Mesh)"/>, which
        /// keeps each triangle's.</summary>
        /// <param name="vertices">One position per Unity vertex.</param>
        /// <param name="triangles">Three vertex indices per triangle (the Unity winding).</param>
        /// <param name="normals">Optional (null or empty): one per vertex.</param>
        /// <param name="uv">Optional (null or empty): one per vertex.</param>
        /// <param name="colors">Optional (null or empty): one per vertex.</param>
        public static HalfEdgeMesh FromUnityMesh(Vector3[] vertices, int[] triangles, Vector3[] normals = null,
                                                 Vector2[] uv = null, Color[] colors = null)
        {
            BuildReport report;
            return FromUnityMesh(vertices, triangles, normals, uv, colors, EngineImportOptions.Unity, out report);
        }

        /// <summary>As above, with the options and the report of what was welded and repaired.</summary>
        public static HalfEdgeMesh FromUnityMesh(Vector3[] vertices, int[] triangles, Vector3[] normals, Vector2[] uv,
                                                 Color[] colors, EngineImportOptions options, out BuildReport report)
        {
            return FromUnityArrays(vertices, triangles, normals, uv, colors, null, null, null, options, out report);
        }

        /// <summary>As above, with tangents (mesh.tangents: xyz and the handedness w) and lightmap UVs
        /// (mesh.uv2), each kept per corner when given (null or empty: none). Render buffers of the mesh then
        /// have tangent and lightmap-UV streams, which the component and <see cref="NativeMeshUploader"/>
        /// upload as VertexAttribute.Tangent and TexCoord1. Tangents are kept as imported, not computed:
        /// where normals follow the geometry, each recomputed normal's tangent is made perpendicular to it
        /// again.</summary>
        public static HalfEdgeMesh FromUnityMesh(Vector3[] vertices, int[] triangles, Vector3[] normals, Vector2[] uv,
                                                 Color[] colors, Vector4[] tangents, Vector2[] uv2,
                                                 EngineImportOptions options, out BuildReport report)
        {
            return FromUnityArrays(vertices, triangles, normals, uv, colors, tangents, uv2, null, options, out report);
        }

        // Every Unity import goes here: the arrays are pinned as they are (Vector3, Vector2, Vector4 and Color
        // are blittable floats), absent or empty ones passed as none.
        internal static HalfEdgeMesh FromUnityArrays(Vector3[] vertices, int[] triangles, Vector3[] normals,
                                                     Vector2[] uv, Color[] colors, Vector4[] tangents, Vector2[] uv2,
                                                     int[] triangleSubmeshes, EngineImportOptions options,
                                                     out BuildReport report)
        {
            if (vertices == null) throw new ArgumentNullException("vertices");
            if (triangles == null) throw new ArgumentNullException("triangles");
            int n = vertices.Length;
            return HalfEdgeMesh.FromEngineArrays(n, vertices, triangles, Optional(normals, n, "normals"),
                                                 Optional(uv, n, "uv"), Optional(colors, n, "colors"),
                                                 Optional(tangents, n, "tangents"), Optional(uv2, n, "uv2"),
                                                 triangleSubmeshes, options, out report);
        }

        /// <summary>Builds a mesh from a Unity Mesh (its vertices, the triangles of every submesh, normals, uv,
        /// colors, tangents and uv2) with <see cref="EngineImportOptions.Unity"/>, as <see
        /// cref="FromUnityMesh(Vector3[], int[], Vector3[], Vector2[], Color[])"/>, keeping each triangle's
        /// submesh (material) as its face's ("f:submesh"; <see cref="UnitySubmeshes.ReadTriangles"/>).</summary>
        /// <exception cref="ArgumentException">The mesh is not readable (its model was imported without
        /// Read/Write): Unity gives scripts no vertices then.</exception>
        public static HalfEdgeMesh FromMesh(Mesh source)
        {
            BuildReport report;
            return FromMesh(source, EngineImportOptions.Unity, out report);
        }

        /// <summary>As above, with the options and the report of what was welded and repaired.</summary>
        public static HalfEdgeMesh FromMesh(Mesh source, EngineImportOptions options, out BuildReport report)
        {
            CheckReadable(source);
            int[] submeshes;
            int[] triangles = UnitySubmeshes.ReadTriangles(source, out submeshes);
            return FromUnityArrays(source.vertices, triangles, source.normals, source.uv, source.colors,
                                   source.tangents, source.uv2, submeshes, options, out report);
        }

        /// <summary>Throws unless a script can read the mesh's arrays.</summary>
        /// <exception cref="ArgumentException">Read/Write is off in the model's import settings.</exception>
        public static void CheckReadable(Mesh source)
        {
            if (source == null) throw new ArgumentNullException("source");
            if (!source.isReadable)
                throw new ArgumentException("mesh '" + source.name + "' is not readable, so Unity gives scripts no " +
                                            "vertices: enable Read/Write in the model's import settings (Inspector > " +
                                            "Model > Read/Write) or pass a mesh made by a script", "source");
        }

        // Unity returns empty arrays for absent attributes; those mean "none" here.
        static T[] Optional<T>(T[] array, int vertexCount, string name)
        {
            if (array == null || array.Length == 0) return null;
            if (array.Length != vertexCount)
                throw new ArgumentException("length " + array.Length + ", " + vertexCount + " expected (one per vertex)",
                                            name);
            return array;
        }

        /// <summary>Copies the position of every vertex slot (deleted ones with stale data) into buffer.</summary>
        /// <returns>The vertex slots (the length needed); with a null buffer, only that.</returns>
        /// <exception cref="HedgeException">BufferTooSmall if buffer holds fewer; nothing is written.</exception>
        public static int CopyPositions(this HalfEdgeMesh mesh, Vector3[] buffer)
        {
            if (mesh == null) throw new ArgumentNullException("mesh");
            ulong floats;
            int status = hedge_mesh_copy_positions(mesh.Id, buffer, buffer != null ? 3UL * (ulong)buffer.Length : 0,
                                                   out floats);
            return Status.Filled(status, buffer == null, floats / 3);
        }

        public static Vector3 ToVector3(this Vec3 p) { return new Vector3(p.X, p.Y, p.Z); }
        public static Vec3 ToVec3(this Vector3 p) { return new Vec3(p.x, p.y, p.z); }

        /// <summary>The position of a live vertex.</summary>
        public static Vector3 GetPositionVector(this HalfEdgeMesh mesh, Vertex v) { return mesh.GetPosition(v).ToVector3(); }

        /// <summary><see cref="HalfEdgeMesh.SetPosition(Vertex, Vec3)"/> with a Vector3.</summary>
        public static void SetPosition(this HalfEdgeMesh mesh, Vertex v, Vector3 p) { mesh.SetPosition(v, p.ToVec3()); }

        /// <summary><see cref="HalfEdgeMesh.SplitEdge(Edge, Vec3)"/> with a Vector3.</summary>
        public static Vertex SplitEdge(this HalfEdgeMesh mesh, Edge e, Vector3 p) { return mesh.SplitEdge(e, p.ToVec3()); }

        /// <summary><see cref="HalfEdgeMesh.Raycast"/> with Vector3s, in the mesh's own (local) space.</summary>
        public static bool Raycast(this HalfEdgeMesh mesh, Vector3 origin, Vector3 direction, out SurfaceHit hit,
                                   float maxT = float.PositiveInfinity)
        {
            return mesh.Raycast(origin.ToVec3(), direction.ToVec3(), out hit, maxT);
        }

        /// <summary><see cref="HalfEdgeMesh.TryGetClosestPoint"/> with a Vector3.</summary>
        public static bool TryGetClosestPoint(this HalfEdgeMesh mesh, Vector3 point, out SurfaceHit hit,
                                              float maxDistance = float.PositiveInfinity)
        {
            return mesh.TryGetClosestPoint(point.ToVec3(), out hit, maxDistance);
        }

        /// <summary><see cref="HalfEdgeMesh.TryGetFaceContainingPoint(Vec3, out Face, float)"/> with a Vector3:
        /// the face a point on the surface (a physics hit point in local space) lies on.</summary>
        public static bool TryGetFaceContainingPoint(this HalfEdgeMesh mesh, Vector3 point, out Face face,
                                                     float tolerance = 1e-4f)
        {
            return mesh.TryGetFaceContainingPoint(point.ToVec3(), out face, tolerance);
        }

        [DllImport(Native.Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        static extern int hedge_mesh_copy_positions(IntPtr mesh, [Out] Vector3[] buffer, ulong capacity, out ulong count);
    }
}
