// AddFace with Unity's Vector2 texcoords (Runtime/Unity/UnityAttributes.cs), against the stand-in.
using System;
using Hedge.Unity;
using UnityEngine;

namespace Hedge.Tests
{
    public static class UnityAttributesTests
    {
        [Test]
        static void AddFaceTakesVector2Texcoords()
        {
            using (HalfEdgeMesh mesh = HalfEdgeMesh.FromTriangles(new float[] { 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0 },
                                                                  new[] { 0, 1, 2 }))
            {
                var corners = new[] { new Vertex(0), new Vertex(2), new Vertex(3) };
                var uv = new[] { new Vector2(0, 0), new Vector2(1, 1), new Vector2(0, 1) };
                Check.ThrowsType<ArgumentException>(() => mesh.AddFace(corners, new Vector2[2], 0), "too few");
                Face f = mesh.AddFace(corners, uv, 3);
                Check.True(f.IsValid);
                Check.Equal(2, mesh.FaceCount);
                RenderOptions options = RenderOptions.Default;
                options.Interleaved = false;
                using (RenderBuffers buffers = mesh.CreateRenderBuffers(options))
                {
                    var texcoords = new float[buffers.CopyStream(VertexStream.Texcoords, null)];
                    buffers.CopyStream(VertexStream.Texcoords, texcoords);
                    HalfEdge into2 = mesh.FindHalfEdge(new Vertex(0), new Vertex(2));
                    Check.Equal(new Vertex(2), mesh.ToVertex(into2));
                    Check.Equal(f, mesh.GetFace(into2));
                    int rv = buffers.GetRenderVertex(into2);
                    Check.Equal(1f, texcoords[2 * rv], "u of corner 2 in the new face");
                    Check.Equal(1f, texcoords[2 * rv + 1], "v of corner 2 in the new face");
                }
                Check.Equal(Face.Invalid, mesh.AddFace(corners, uv), "the same face again: refused");
                Check.Equal(RefusalCode.AddFaceEdgeTaken, mesh.LastRefusalCode);
                Check.Valid(mesh);
            }
        }
    }
}
