// More of the UnityEngine stand-in: Vector4, Mesh.tangents and Mesh.uv2, and the rules Unity documents
// for SetVertexBufferParams, checked on every call: at most four streams (0 to 3), no attribute twice,
// Float32 with 1 to 4 components, and the attributes of one stream listed in the order of
// VertexAttribute, the order Unity lays them out in a vertex of the stream. ReadAttribute reads one
// attribute of one vertex back from the uploaded streams by that rule, so a test sees what a shader
// would read. It says nothing about Unity itself.
using System;

namespace UnityEngine
{
    public struct Vector4
    {
        public float x, y, z, w;
        public Vector4(float x, float y, float z, float w) { this.x = x; this.y = y; this.z = z; this.w = w; }
    }

    public sealed partial class Mesh
    {
        public Vector4[] tangents { get; set; }
        public Vector2[] uv2 { get; set; }

        // Throws unless the descriptors follow Unity's rules; called by SetVertexBufferParams.
        static void CheckDescriptors(Rendering.VertexAttributeDescriptor[] attributes)
        {
            var last = new int[4];
            for (int s = 0; s < 4; ++s) last[s] = -1;
            var seen = new bool[16];
            foreach (var a in attributes)
            {
                if (a.stream < 0 || a.stream > 3)
                    throw new ArgumentException("stream " + a.stream + " of " + a.attribute + ": Unity has streams 0 to 3");
                if (a.dimension < 1 || a.dimension > 4)
                    throw new ArgumentException("dimension " + a.dimension + " of " + a.attribute);
                if (seen[(int)a.attribute]) throw new ArgumentException(a.attribute + " given twice");
                seen[(int)a.attribute] = true;
                if ((int)a.attribute <= last[a.stream])
                    throw new ArgumentException(a.attribute + " after " + (Rendering.VertexAttribute)last[a.stream] +
                                                " in stream " + a.stream + ": not in VertexAttribute order");
                last[a.stream] = (int)a.attribute;
            }
            if (!seen[(int)Rendering.VertexAttribute.Position]) throw new ArgumentException("no Position attribute");
        }

        /// <summary>Vertex v's value of an attribute, read from its stream as Unity lays the stream out
        /// (attributes in VertexAttribute order, each vertex the sum of their dimensions); null when the
        /// attribute is not in the layout.</summary>
        public float[] ReadAttribute(Rendering.VertexAttribute attribute, int v)
        {
            int stream = -1, dimension = 0;
            foreach (var a in Attributes)
                if (a.attribute == attribute) { stream = a.stream; dimension = a.dimension; }
            if (stream < 0) return null;
            int offset = 0, stride = 0;
            foreach (var a in Attributes)
            {
                if (a.stream != stream) continue;
                stride += a.dimension;
                if (a.attribute < attribute) offset += a.dimension;
            }
            var data = (float[])Streams[stream];
            var value = new float[dimension];
            Array.Copy(data, v * stride + offset, value, 0, dimension);
            return value;
        }

        /// <summary>The streams the layout uses.</summary>
        public int StreamCount
        {
            get
            {
                int n = 0;
                for (int s = 0; s < 4; ++s)
                    if (Streams != null && Streams[s] != null) ++n;
                return n;
            }
        }
    }
}
