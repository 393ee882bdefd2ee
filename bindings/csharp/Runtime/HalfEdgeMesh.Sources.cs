// The map back to an engine mesh: which engine (Unity) vertex each vertex and corner of a mesh made
// by FromEngineMesh came from.
using System;
using System.Runtime.InteropServices;

namespace Hedge
{
    public sealed partial class HalfEdgeMesh
    {
        /// <summary>For each vertex slot, the first (smallest) engine vertex index welded into it: the index in
        /// the arrays given to <see cref="FromEngineMesh(float[], int[], float[], float[], float[],
        /// EngineImportOptions, out BuildReport)"/> (a Unity mesh's vertex index). Welding renumbers vertices,
        /// and a seam welds several engine vertices into one; this finds data keyed by the engine's index
        /// again. -1 for a deleted vertex or one the edits made; the values follow their vertices through edits
        /// and <see cref="GarbageCollection"/>.</summary>
        /// <returns>The vertex slots (the length needed); with a null buffer, only that.</returns>
        /// <exception cref="HedgeException">InvalidArgument if the mesh was not made from engine arrays;
        /// BufferTooSmall if result holds fewer (nothing is written).</exception>
        public int CopyVertexSourceIndices(int[] result)
        {
            ulong count;
            int status = hedge_mesh_vertex_source_indices(id, result, result != null ? (ulong)result.Length : 0,
                                                          out count);
            return Status.Filled(status, result == null, count);
        }

        /// <summary>For each half-edge slot, the engine vertex of the corner it enters (that vertex in that
        /// half-edge's face): exact where a seam splits a vertex. -1 for boundary half-edges and corners the edits
        /// made. As <see cref="CopyVertexSourceIndices"/> otherwise.</summary>
        /// <returns>The half-edge slots (2 x edge slots); with a null buffer, only that.</returns>
        public int CopyCornerSourceIndices(int[] result)
        {
            ulong count;
            int status = hedge_mesh_corner_source_indices(id, result, result != null ? (ulong)result.Length : 0,
                                                          out count);
            return Status.Filled(status, result == null, count);
        }

        [DllImport(Native.Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        static extern int hedge_mesh_vertex_source_indices(IntPtr mesh, [Out] int[] buffer, ulong capacity,
                                                           out ulong count);
        [DllImport(Native.Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        static extern int hedge_mesh_corner_source_indices(IntPtr mesh, [Out] int[] buffer, ulong capacity,
                                                           out ulong count);
    }
}
