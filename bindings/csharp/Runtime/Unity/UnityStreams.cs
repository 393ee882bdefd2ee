// The Unity vertex streams of a RenderBuffers in the separate layout, shared by the component and
// the zero-copy uploader. Unity takes at most four vertex streams, and lays the attributes of one
// stream out in the order of VertexAttribute (Position, Normal, Tangent, Color, TexCoord0, TexCoord1,
// ...), whatever their order in the descriptor array. The library has up to six streams (positions,
// normals, texcoords, colours, tangents, lightmap UVs), so:
//   - stream 0 holds the positions;
//   - with at most three other attributes, each has a stream of its own, in VertexAttribute order
//     (normals, tangents, colours, texcoords, lightmap UVs, as present);
//   - with four or five, normals and tangents share a stream (the tangent frame), and so do texcoords
//     and lightmap UVs (both UV sets); colours keep their own. That is at most four streams.
// A stream of one attribute is the library's own stream, uploaded as it is (zero-copy in the
// uploader). A shared stream is interleaved per vertex, in VertexAttribute order, into a staging
// buffer kept between uploads: only the dirty ranges, with no allocation per upload. The descriptor
// array lists the streams in order and, in each, the attributes in VertexAttribute order, so the
// array is in VertexAttribute order as a whole too. All attributes are Float32.
using System;
using UnityEngine.Rendering;

namespace Hedge.Unity
{
    internal sealed class UnityStreams
    {
        internal const int MaxStreams = 4;

        // Per Unity stream: the library streams it holds, in VertexAttribute order, and its floats per vertex.
        readonly VertexStream[][] members = new VertexStream[MaxStreams][];
        readonly int[] strides = new int[MaxStreams];

        /// <summary>The descriptors for SetVertexBufferParams.</summary>
        internal VertexAttributeDescriptor[] Attributes { get; private set; }
        /// <summary>The Unity streams in use (1 to 4).</summary>
        internal int Count { get; private set; }

        /// <summary>The library streams Unity stream s holds, in VertexAttribute order.</summary>
        internal VertexStream[] Members(int s) { return members[s]; }
        /// <summary>Floats per vertex in Unity stream s.</summary>
        internal int Stride(int s) { return strides[s]; }
        /// <summary>True when Unity stream s interleaves several library streams (uploaded from a staging
        /// buffer); false when it is one library stream as it is.</summary>
        internal bool Staged(int s) { return members[s].Length > 1; }

        internal static UnityStreams Describe(VertexLayout layout)
        {
            // The optional attributes present, in VertexAttribute order.
            var attributes = new VertexAttribute[5];
            var sources = new VertexStream[5];
            int n = 0;
            if (layout.HasNormals) { attributes[n] = VertexAttribute.Normal; sources[n++] = VertexStream.Normals; }
            if (layout.HasTangents) { attributes[n] = VertexAttribute.Tangent; sources[n++] = VertexStream.Tangents; }
            if (layout.HasColors) { attributes[n] = VertexAttribute.Color; sources[n++] = VertexStream.Colors; }
            if (layout.HasTexcoords) { attributes[n] = VertexAttribute.TexCoord0; sources[n++] = VertexStream.Texcoords; }
            if (layout.HasTexcoords1)
            {
                attributes[n] = VertexAttribute.TexCoord1;
                sources[n++] = VertexStream.Texcoords1;
            }
            bool share = n > MaxStreams - 1;

            var plan = new UnityStreams();
            var descriptors = new VertexAttributeDescriptor[n + 1];
            descriptors[0] = new VertexAttributeDescriptor(VertexAttribute.Position, VertexAttributeFormat.Float32, 3, 0);
            plan.members[0] = new[] { VertexStream.Vertices };
            plan.strides[0] = 3;
            int stream = 0;
            for (int i = 0; i < n; ++i)
            {
                // A tangent joins the normals' stream, lightmap UVs the texcoords' one, when streams are short.
                bool joins = share && i > 0 &&
                             ((attributes[i] == VertexAttribute.Tangent && attributes[i - 1] == VertexAttribute.Normal) ||
                              (attributes[i] == VertexAttribute.TexCoord1 && attributes[i - 1] == VertexAttribute.TexCoord0));
                if (!joins)
                {
                    ++stream;
                    plan.members[stream] = new VertexStream[0];
                }
                VertexStream[] old = plan.members[stream];
                var grown = new VertexStream[old.Length + 1];
                Array.Copy(old, grown, old.Length);
                grown[old.Length] = sources[i];
                plan.members[stream] = grown;
                int dimension = Dimension(sources[i]);
                plan.strides[stream] += dimension;
                descriptors[i + 1] = new VertexAttributeDescriptor(attributes[i], VertexAttributeFormat.Float32, dimension,
                                                                   stream);
            }
            plan.Count = stream + 1;
            plan.Attributes = descriptors;
            return plan;
        }

        static int Dimension(VertexStream s)
        {
            if (s == VertexStream.Texcoords || s == VertexStream.Texcoords1) return 2;
            if (s == VertexStream.Colors || s == VertexStream.Tangents) return 4;
            return 3;
        }

        /// <summary>Interleaves render vertices [first, first + count) of Unity stream s from the library's
        /// streams into target (Stride(s) floats a vertex, at the vertex's own place). No allocation.</summary>
        internal unsafe void Interleave(RenderBuffers buffers, int s, float* target, long targetFloats, int first,
                                        int count)
        {
            int stride = strides[s];
            if ((long)(first + count) * stride > targetFloats)
                throw new InvalidOperationException("vertex range beyond the staging buffer");
            int offset = 0;
            foreach (VertexStream m in members[s])
            {
                int k = Dimension(m);
                int floats;
                float* source = (float*)buffers.GetStreamPointer(m, out floats);
                if ((long)(first + count) * k > floats)
                    throw new InvalidOperationException("vertex range beyond the library's " + m + " stream");
                for (int v = first; v < first + count; ++v)
                {
                    float* from = source + (long)v * k;
                    float* to = target + (long)v * stride + offset;
                    for (int c = 0; c < k; ++c) to[c] = from[c];
                }
                offset += k;
            }
        }
    }
}
