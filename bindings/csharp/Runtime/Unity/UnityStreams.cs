// The Unity vertex streams of a RenderBuffers in the separate layout, shared by the component and
// the zero-copy uploader: stream 0 the positions, then normals, texcoords and colours each on the
// next stream, as present; all Float32.
using UnityEngine.Rendering;

namespace Hedge.Unity
{
    internal static class UnityStreams
    {
        /// <summary>The attribute descriptors for SetVertexBufferParams, and the stream of each optional
        /// attribute (-1 when absent).</summary>
        internal static VertexAttributeDescriptor[] Describe(VertexLayout layout, out int normalStream,
                                                             out int texcoordStream, out int colorStream)
        {
            int streams = 1;
            normalStream = layout.HasNormals ? streams++ : -1;
            texcoordStream = layout.HasTexcoords ? streams++ : -1;
            colorStream = layout.HasColors ? streams++ : -1;
            var attributes = new VertexAttributeDescriptor[streams];
            attributes[0] = new VertexAttributeDescriptor(VertexAttribute.Position, VertexAttributeFormat.Float32, 3, 0);
            if (normalStream >= 0)
                attributes[normalStream] = new VertexAttributeDescriptor(VertexAttribute.Normal,
                                                                         VertexAttributeFormat.Float32, 3, normalStream);
            if (texcoordStream >= 0)
                attributes[texcoordStream] = new VertexAttributeDescriptor(VertexAttribute.TexCoord0,
                                                                           VertexAttributeFormat.Float32, 2, texcoordStream);
            if (colorStream >= 0)
                attributes[colorStream] = new VertexAttributeDescriptor(VertexAttribute.Color,
                                                                        VertexAttributeFormat.Float32, 4, colorStream);
            return attributes;
        }
    }
}
