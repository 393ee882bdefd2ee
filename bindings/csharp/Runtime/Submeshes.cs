// Submeshes (materials): a face's submesh is the face property "f:submesh" of the native mesh (0
// without it), kept through edits, subdivision, decimation and fracture. RenderBuffers group the
// index buffer by submesh: each submesh is one contiguous index range, with spare room (degenerate
// triangles) so that edits stay local; a range that runs out of room makes the sync a full rebuild
// (SyncResult.Full), which lays the ranges out again.
using System;
using System.Runtime.InteropServices;

namespace Hedge
{
    /// <summary>One submesh's part of the render buffers, as of the last sync: what Unity's
    /// SubMeshDescriptor needs. Laid out as the C ABI's hedge_submesh_range (40 bytes).</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct SubmeshRange
    {
        /// <summary>First entry of the index buffer.</summary>
        public uint IndexStart;
        /// <summary>Index entries, spare and free (degenerate) triangles included.</summary>
        public uint IndexCount;
        /// <summary>Every index entry of the range lies in [FirstVertex, FirstVertex + VertexCount).</summary>
        public uint FirstVertex;
        public uint VertexCount;
        /// <summary>The box of the positions its live triangles use, as in the vertex buffer (both zero
        /// without live triangles).</summary>
        public Vec3 Min;
        public Vec3 Max;
    }

    public sealed partial class HalfEdgeMesh
    {
        /// <summary>The largest submesh id a face may have.</summary>
        public const int MaxSubmesh = 65535;

        /// <summary><see cref="FromEngineMesh(float[], int[], float[], float[], float[], EngineImportOptions, out BuildReport)"/>
        /// with one submesh (material) per triangle, kept as each face's submesh. An engine mesh of several
        /// submeshes passes its triangles submesh after submesh (Unity: GetIndices(0), GetIndices(1), ...)
        /// with their ids.</summary>
        /// <param name="triangleSubmeshes">Null (every face in submesh 0) or one id in [0, MaxSubmesh] per
        /// triangle.</param>
        /// <exception cref="ArgumentException">triangleSubmeshes has not one entry per triangle.</exception>
        /// <exception cref="HedgeException">InvalidArgument for an id outside [0, MaxSubmesh] (the message
        /// names the triangle).</exception>
        public static HalfEdgeMesh FromEngineMesh(float[] positions, int[] triangles, float[] normals,
                                                  float[] texcoords, float[] colors, int[] triangleSubmeshes,
                                                  EngineImportOptions options, out BuildReport report)
        {
            if (triangleSubmeshes == null)
                return FromEngineMesh(positions, triangles, normals, texcoords, colors, options, out report);
            uint n = CheckEngineArrays(positions, normals, texcoords, colors);
            CheckNotNegative(triangles, "triangles", "a vertex index");
            if (triangleSubmeshes.Length != triangles.Length / 3)
                throw new ArgumentException("length " + triangleSubmeshes.Length + ", " + triangles.Length / 3 +
                                            " expected (one per triangle)", "triangleSubmeshes");
            IntPtr mesh;
            int status = Native.hedge_mesh_from_engine_mesh_with_submeshes(positions, n, triangles,
                                                                           (uint)triangles.Length, normals, texcoords,
                                                                           colors, triangleSubmeshes, ref options,
                                                                           out report, out mesh);
            return Created(status, mesh);
        }

        /// <summary>The submesh (material) of a live face: 0 when no face has been given one.</summary>
        public int GetSubmesh(Face f)
        {
            return Status.Checked(Native.hedge_face_submesh(id, f.Raw, out int submesh), submesh);
        }

        /// <summary>Moves a live face into a submesh, in [0, MaxSubmesh]; render buffers move its triangles
        /// into that submesh's index range at their next sync.</summary>
        /// <exception cref="HedgeException">InvalidArgument for a submesh outside [0, MaxSubmesh]; nothing
        /// changes.</exception>
        public void SetSubmesh(Face f, int submesh) { Status.Check(Native.hedge_set_face_submesh(id, f.Raw, submesh)); }
    }

    public sealed partial class RenderBuffers
    {
        /// <summary>Submeshes: 1 + the largest face submesh at the last full build (at least 1).</summary>
        public int SubmeshCount
        {
            get { return (int)Status.Checked(Native.hedge_render_buffers_submesh_count(id, out uint count), count); }
        }

        /// <summary>Submesh i's index range, vertex range and bounds, as of the last sync. O(its index
        /// entries).</summary>
        /// <exception cref="ArgumentOutOfRangeException">i is negative.</exception>
        /// <exception cref="HedgeException">BadHandle: i is not below SubmeshCount.</exception>
        public SubmeshRange GetSubmesh(int i)
        {
            if (i < 0) throw new ArgumentOutOfRangeException("i", i, "a submesh index is >= 0");
            return Status.Checked(Native.hedge_render_buffers_submesh(id, (uint)i, out SubmeshRange r), r);
        }
    }

    internal static partial class Native
    {
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_render_buffers_submesh_count(IntPtr render, out uint count);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_render_buffers_submesh(IntPtr render, uint submesh, out SubmeshRange range);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_face_submesh(IntPtr mesh, uint face, out int submesh);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_set_face_submesh(IntPtr mesh, uint face, int submesh);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_mesh_from_engine_mesh_with_submeshes(float[] positions, uint vertexCount,
            int[] indices, uint indexCount, float[] normals, float[] texcoords, float[] colors, int[] triangleSubmeshes,
            ref EngineImportOptions options, out BuildReport report, out IntPtr mesh);
    }
}
