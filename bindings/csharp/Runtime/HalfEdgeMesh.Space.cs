// Changing between a file's right-handed space and Unity's left-handed one: MirrorX().
using System;
using System.Runtime.InteropServices;

namespace Hedge
{
    public sealed partial class HalfEdgeMesh
    {
        /// <summary>Mirrors the mesh in the plane x = 0 and reverses every face, so that faces keep facing out:
        /// x of positions and normals negated, each face's corners reversed with their attributes (texcoords
        /// unchanged); indices are kept. It is Unity's rule for model files (its OBJ and FBX importers negate x
        /// and reverse the triangles): a file read and then mirrored is what Unity's importer gives, and
        /// mirrored again it is the file's own space, bit for bit. Render buffers of the mesh rebuild at their
        /// next sync. <c>Hedge.Unity.UnityMeshes.Read</c> and <c>Write</c> apply it for you.</summary>
        public void MirrorX() { Status.Check(hedge_mesh_mirror_x(id)); }

        [DllImport(Native.Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        static extern int hedge_mesh_mirror_x(IntPtr mesh);
    }
}
