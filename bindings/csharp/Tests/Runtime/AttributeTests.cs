// Faces added with texture coordinates per corner and a submesh (HalfEdgeMesh.Attributes.cs).
using System;

namespace Hedge.Tests
{
    public static class AttributeTests
    {
        // The pyramid with its face 0 (corners 0 1 4) removed, and those corners.
        static HalfEdgeMesh Opened(out Vertex[] corners)
        {
            HalfEdgeMesh mesh = Meshes.Pyramid();
            corners = new Vertex[3];
            Check.Equal(3, mesh.GetFaceVertices(new Face(0), corners));
            Check.True(mesh.RemoveFace(new Face(0)));
            return mesh;
        }

        // The texcoord of each corner of face f as the render buffers give it, in the order of corners.
        static float[] CornerTexcoords(HalfEdgeMesh mesh, Face f, Vertex[] corners)
        {
            RenderOptions options = RenderOptions.Default;
            options.Interleaved = false;
            using (RenderBuffers buffers = mesh.CreateRenderBuffers(options))
            {
                var uv = new float[buffers.CopyStream(VertexStream.Texcoords, null)];
                buffers.CopyStream(VertexStream.Texcoords, uv);
                var result = new float[2 * corners.Length];
                var loop = new HalfEdge[8];
                int n = mesh.GetFaceHalfEdges(f, loop);
                for (int i = 0; i < n; ++i)
                {
                    int corner = Array.IndexOf(corners, mesh.ToVertex(loop[i]));
                    int rv = buffers.GetRenderVertex(loop[i]);
                    result[2 * corner] = uv[2 * rv];
                    result[2 * corner + 1] = uv[2 * rv + 1];
                }
                return result;
            }
        }

        [Test]
        static void TexcoordsReachTheCorners()
        {
            Vertex[] corners;
            using (HalfEdgeMesh mesh = Opened(out corners))
            {
                float[] uv = { 0.25f, 0.5f, 0.75f, 0.5f, 0.5f, 1, 99, 99 };  // a longer array: the first 6 used
                Face f = mesh.AddFace(corners, 3, uv, 4);
                Check.True(f.IsValid);
                Check.Equal(RefusalCode.None, mesh.LastRefusalCode);
                Check.Same(new[] { 0.25f, 0.5f, 0.75f, 0.5f, 0.5f, 1 }, CornerTexcoords(mesh, f, corners), 6,
                           "the texcoords of the new corners");
                Check.Valid(mesh);
            }
            using (HalfEdgeMesh mesh = Opened(out corners))
            {
                Face f = mesh.AddFace(corners[0], corners[1], corners[2], null, 2);
                Check.True(f.IsValid, "a submesh without texcoords");
                Check.Valid(mesh);
            }
        }

        [Test]
        static void BadAttributesChangeNothing()
        {
            Vertex[] corners;
            using (HalfEdgeMesh mesh = Opened(out corners))
            {
                MeshCounts before = mesh.Counts;
                float[] uv = { 0, 0, 1, 0, 1, 1 };
                Check.ThrowsType<ArgumentException>(() => mesh.AddFace(corners, 3, new float[5], 0), "5 floats, 6 needed");
                var range = Check.ThrowsType<ArgumentOutOfRangeException>(() => mesh.AddFace(corners, 3, uv, 65536));
                Check.Contains(range.Message, "[0, 65535]");
                Check.ThrowsType<ArgumentOutOfRangeException>(() => mesh.AddFace(corners, 3, uv, -2));
                HedgeException e = Check.Throws(HedgeStatus.InvalidArgument,
                                                () => mesh.AddFace(corners, 3, new[] { 0, 0, float.NaN, 0, 1, 1 }, 0));
                Check.Contains(e.Message, "texcoord 1 is not finite");
                var reversed = new[] { corners[2], corners[1], corners[0] };
                Check.Equal(Face.Invalid, mesh.AddFace(reversed, 3, uv, 1), "refused");
                Check.True(mesh.LastRefusalCode != RefusalCode.None, "the refusal's code");
                Check.Equal(before, mesh.Counts);
                Check.Valid(mesh);
            }
        }
    }
}
