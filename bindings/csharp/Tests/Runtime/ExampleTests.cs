// The example of bindings/csharp/README.md, as written there, with checks of what it computes.
using System;

namespace Hedge.Tests
{
    public static class ExampleTests
    {
        [Test]
        static void ReadmeExample()
        {
            // ---- from README.md ----
            float[] positions = { 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0.5f, 0.5f, 1 };
            int[] triangles = { 0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4 };
            using (var mesh = HalfEdgeMesh.FromTriangles(positions, triangles))
            using (var buffers = mesh.CreateRenderBuffers())         // or mesh.GenerateUnityMesh()
            {
                // Queries fill arrays you keep: no allocation per call.
                var ring = new Vertex[32];
                int n = mesh.GetVertexNeighbours(new Vertex(4), ring);  // 4: the apex's neighbours, clockwise

                // Arrays that mirror the render buffers (a whole copy the first time).
                float[] vertices = null;
                int[] indices = null;
                buffers.UpdateVertexMirror(VertexStream.Vertices, ref vertices);
                buffers.UpdateIndexMirror(ref indices);

                // Edits. A refused edit returns an invalid handle or false, and changes nothing;
                // mesh.LastRefusal then says why.
                buffers.BeginTransaction();
                HalfEdge h = mesh.FindHalfEdge(new Vertex(0), new Vertex(1));
                Vertex mid = mesh.SplitEdge(h.Edge, 0.5f, 0, 0);        // a new vertex on the edge 0-1
                Vertex kept = mesh.Collapse(mesh.FindHalfEdge(mid, new Vertex(0)));  // merged into 0 again
                bool flipped = mesh.Flip(mesh.FindHalfEdge(new Vertex(0), new Vertex(1)));  // false: boundary
                Vertex centre = mesh.SplitFace(mesh.GetFace(mesh.FindHalfEdge(new Vertex(2), new Vertex(3))),
                                               0.5f, 0.9f, 0.2f);
                mesh.SetPosition(new Vertex(4), 0.5f, 0.5f, 1.5f);
                SyncResult result = buffers.CommitTransaction();        // one sync for all the edits

                // Copy what changed into the mirrors; true: only the dirty ranges (upload those ranges),
                // false: everything (the buffers outgrew the arrays: reallocate, upload everything).
                bool partial = buffers.UpdateVertexMirror(VertexStream.Vertices, ref vertices);
                buffers.UpdateIndexMirror(ref indices);
                var ranges = new SlotRange[64];
                int dirty = buffers.GetDirtyVertexRanges(ranges);       // [First, First + Count) render vertices

                string[] problems = mesh.Validate();                    // empty: every invariant holds
                // ---- end of the example ----

                Check.Equal(4, n);
                Check.Equal(new Vertex(5), mid);
                Check.Equal(new Vertex(0), kept);
                Check.False(flipped);
                Check.True(centre.IsValid);
                Check.Equal(6, mesh.FaceCount);
                Check.False(result.Full);
                Check.True(partial, "the first copy left headroom for the new vertex");
                Check.Equal((int)result.VertexRangeCount, dirty);
                Check.True(dirty >= 1);
                Check.Equal(0, problems.Length);
                var fresh = new float[buffers.CopyVertices(null)];
                buffers.CopyVertices(fresh);
                Check.Same(fresh, vertices, fresh.Length, "the mirror");
            }
        }
    }
}
