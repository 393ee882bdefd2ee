// A NativeMeshUploader whose mesh was disposed (which disposed its render buffers) throws
// ObjectDisposedException naming RenderBuffers, and a disposed uploader one naming itself, against
// the stand-in.
using System;
using Hedge.Unity;

namespace Hedge.Tests
{
    public static class DisposedUploaderTests
    {
        [Test]
        static void UploaderOfADisposedMeshThrows()
        {
            float[] p = { 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0.5f, 0.5f, 1 };  // an open pyramid
            HalfEdgeMesh mesh = HalfEdgeMesh.FromTriangles(p, new[] { 0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4 });
            RenderBuffers buffers = mesh.CreateRenderBuffers(RenderOptions.Unity);
            var uploader = new NativeMeshUploader(buffers, new UnityEngine.Mesh());
            uploader.UploadAll();
            Check.True(mesh.SplitFace(new Face(0), 0.5f, 0.2f, 0.5f).IsValid);
            Check.Valid(mesh);
            mesh.Dispose();
            var e = Check.ThrowsType<ObjectDisposedException>(() => uploader.UploadAll(), "its mesh was disposed");
            Check.Equal("RenderBuffers", e.ObjectName);
            uploader.Dispose();
            buffers.Dispose(); // already gone with its mesh: harmless
        }

        [Test]
        static void DisposedUploaderThrows()
        {
            float[] p = { 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0.5f, 0.5f, 1 };
            using (HalfEdgeMesh mesh = HalfEdgeMesh.FromTriangles(p, new[] { 0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4 }))
            using (RenderBuffers buffers = mesh.CreateRenderBuffers(RenderOptions.Unity))
            {
                var uploader = new NativeMeshUploader(buffers, new UnityEngine.Mesh());
                uploader.UploadAll();
                uploader.Dispose();
                uploader.Dispose(); // twice: harmless
                var e = Check.ThrowsType<ObjectDisposedException>(() => uploader.Upload(), "the uploader was disposed");
                Check.Equal("NativeMeshUploader", e.ObjectName);
                Check.ThrowsType<ObjectDisposedException>(() => uploader.UploadAll(), "the uploader was disposed");
                Check.Valid(mesh);
            }
        }
    }
}
