// Engine meshes with every vertex stream the library keeps: positions, normals, texcoords, colours,
// tangents (xyz and the handedness w), a second texcoord channel (lightmap UVs) and a submesh per
// triangle, through one C call (hedge_mesh_from_engine_streams) that takes a struct of optional
// streams. The arrays are pinned for the call, never copied, whatever their element type (float[]
// here; Unity's Vector3[], Vector4[], Vector2[] and Color[] in the Unity assembly).
using System;
using System.Runtime.InteropServices;

namespace Hedge
{
    /// <summary>An engine mesh's arrays for <see cref="HalfEdgeMesh.FromEngineMesh(EngineStreams,
    /// EngineImportOptions)"/>: Positions and Triangles are required, every other stream is optional
    /// (null). Each per-vertex stream has one entry per engine vertex: 3 floats for positions and
    /// normals, 2 for texcoords, 4 for colours (r, g, b, a), 4 for tangents (x, y, z and the handedness
    /// w, +1 or -1, as Unity's <c>Mesh.tangents</c>), 2 for the second texcoord channel (lightmap UVs,
    /// Unity's <c>uv2</c>).</summary>
    public sealed class EngineStreams
    {
        public float[] Positions;
        /// <summary>Three engine-vertex indices per triangle.</summary>
        public int[] Triangles;
        public float[] Normals;
        public float[] Texcoords;
        public float[] Colors;
        /// <summary>Kept per corner ("h:tangent"), imported, not computed: render buffers whose normals
        /// follow the geometry make each corner's tangent perpendicular to its recomputed normal again,
        /// the handedness kept.</summary>
        public float[] Tangents;
        /// <summary>The second texcoord channel (lightmap UVs), kept per corner ("h:texcoord1").</summary>
        public float[] Texcoords1;
        /// <summary>One submesh (material) id in [0, HalfEdgeMesh.MaxSubmesh] per triangle.</summary>
        public int[] TriangleSubmeshes;

        public EngineStreams() { }

        public EngineStreams(float[] positions, int[] triangles)
        {
            Positions = positions;
            Triangles = triangles;
        }
    }

    public sealed partial class HalfEdgeMesh
    {
        /// <summary>Builds a mesh from an engine's arrays with every stream that is not null kept per corner
        /// (per face for the submeshes): render buffers of the mesh then have tangent and lightmap-UV streams
        /// (<see cref="VertexStream.Tangents"/>, <see cref="VertexStream.Texcoords1"/>) that follow its
        /// edits.</summary>
        /// <exception cref="ArgumentException">A null required array, a stream whose length is not its
        /// floats per vertex times the vertex count, a negative index, or not one submesh per
        /// triangle.</exception>
        /// <exception cref="HedgeException">InvalidArgument for a non-finite value, an index out of range or a
        /// submesh id outside [0, MaxSubmesh] (the message names the stream and the vertex or
        /// triangle).</exception>
        public static HalfEdgeMesh FromEngineMesh(EngineStreams streams, EngineImportOptions options,
                                                  out BuildReport report)
        {
            if (streams == null) throw new ArgumentNullException("streams");
            uint n = CheckEngineArrays(streams.Positions, streams.Normals, streams.Texcoords, streams.Colors);
            CheckStream(streams.Tangents, 4, n, "Tangents");
            CheckStream(streams.Texcoords1, 2, n, "Texcoords1");
            return FromEngineArrays((int)n, streams.Positions, streams.Triangles, streams.Normals, streams.Texcoords,
                                    streams.Colors, streams.Tangents, streams.Texcoords1, streams.TriangleSubmeshes,
                                    options, out report);
        }

        /// <summary>As above, without the report.</summary>
        public static HalfEdgeMesh FromEngineMesh(EngineStreams streams, EngineImportOptions options)
        {
            BuildReport report;
            return FromEngineMesh(streams, options, out report);
        }

        static void CheckStream(float[] stream, int components, uint n, string name)
        {
            if (stream != null && stream.Length != (long)components * n)
                throw new ArgumentException("length " + stream.Length + ", " + (long)components * n + " expected (" +
                                            components + " per vertex)", name);
        }

        // The one path to hedge_mesh_from_engine_streams: each array (of floats or of blittable structs
        // of floats) holds vertexCount entries of its stream, as the caller checked; null for absent
        // streams. The arrays are pinned for the call only.
        internal static HalfEdgeMesh FromEngineArrays(int vertexCount, Array positions, int[] triangles, Array normals,
                                                      Array texcoords, Array colors, Array tangents, Array texcoords1,
                                                      int[] triangleSubmeshes, EngineImportOptions options,
                                                      out BuildReport report)
        {
            if (positions == null) throw new ArgumentNullException("positions");
            CheckNotNegative(triangles, "triangles", "a vertex index");
            if (triangleSubmeshes != null && triangleSubmeshes.Length != triangles.Length / 3)
                throw new ArgumentException("length " + triangleSubmeshes.Length + ", " + triangles.Length / 3 +
                                            " expected (one per triangle)", "triangleSubmeshes");
            var pins = new GCHandle[8];
            try
            {
                var s = new Native.EngineStreamsData();
                s.VertexCount = (uint)vertexCount;
                s.IndexCount = (uint)triangles.Length;
                s.Positions = Pin(pins, 0, positions);
                s.Indices = Pin(pins, 1, triangles);
                s.Normals = Pin(pins, 2, normals);
                s.Texcoords = Pin(pins, 3, texcoords);
                s.Colors = Pin(pins, 4, colors);
                s.Tangents = Pin(pins, 5, tangents);
                s.Texcoords1 = Pin(pins, 6, texcoords1);
                s.TriangleSubmeshes = Pin(pins, 7, triangleSubmeshes);
                IntPtr mesh;
                int status = Native.hedge_mesh_from_engine_streams(ref s, ref options, out report, out mesh);
                return Created(status, mesh);
            }
            finally
            {
                for (int i = 0; i < pins.Length; ++i)
                    if (pins[i].IsAllocated) pins[i].Free();
            }
        }

        // Pins an array for the call and gives its address; null (and an empty array, which has no
        // element to point at) give NULL, which the library takes for an absent or empty stream.
        static IntPtr Pin(GCHandle[] pins, int i, Array array)
        {
            if (array == null) return IntPtr.Zero;
            pins[i] = GCHandle.Alloc(array, GCHandleType.Pinned);
            return array.Length > 0 ? pins[i].AddrOfPinnedObject() : IntPtr.Zero;
        }
    }

    internal static partial class Native
    {
        // hedge_engine_streams: two counts, then eight pointers (88 bytes on 64-bit systems).
        [StructLayout(LayoutKind.Sequential)]
        internal struct EngineStreamsData
        {
            internal uint VertexCount;
            internal uint IndexCount;
            internal IntPtr Positions;
            internal IntPtr Indices;
            internal IntPtr Normals;
            internal IntPtr Texcoords;
            internal IntPtr Colors;
            internal IntPtr Tangents;
            internal IntPtr Texcoords1;
            internal IntPtr TriangleSubmeshes;
        }

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_mesh_from_engine_streams(ref EngineStreamsData streams,
                                                                  ref EngineImportOptions options,
                                                                  out BuildReport report, out IntPtr mesh);
    }
}
