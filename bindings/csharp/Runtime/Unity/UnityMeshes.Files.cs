// Model files in Unity's space. The rule, stated once: Unity's model importers (OBJ, FBX) turn a
// file's right-handed coordinates into Unity's left-handed ones by negating x of positions and
// normals and reversing each triangle, so that faces keep facing out; texture coordinates are kept.
// UnityMeshes.Read and FromBytes apply it after reading (HalfEdgeMesh.MirrorX), so a model read here
// lies where Unity's importer puts it, and UnityMeshes.Write applies it again before writing, so the
// file gets the file's own space back. HalfEdgeMesh.Read and Write take the file's space as it is.
using System;

namespace Hedge.Unity
{
    public static partial class UnityMeshes
    {
        /// <summary>Reads a mesh file (OBJ, OFF, PLY, STL, glTF by extension) into Unity's space, as Unity's
        /// model importer places it: x of positions and normals negated, faces reversed, texcoords kept.
        /// <see cref="HalfEdgeMesh.Read(string)"/> reads the file's own space.</summary>
        public static HalfEdgeMesh Read(string path)
        {
            return ToUnitySpace(HalfEdgeMesh.Read(path));
        }

        /// <summary>As <see cref="Read(string)"/>, with the read options and the report of the repairs.</summary>
        public static HalfEdgeMesh Read(string path, ReadOptions options, out BuildReport report)
        {
            return ToUnitySpace(HalfEdgeMesh.Read(path, options, out report));
        }

        /// <summary>Reads a file's bytes (a download, a <c>TextAsset.bytes</c>; the name's extension picks
        /// the format) into Unity's space, as <see cref="Read(string)"/>.</summary>
        public static HalfEdgeMesh FromBytes(byte[] bytes, string name)
        {
            return ToUnitySpace(HalfEdgeMesh.FromBytes(bytes, name));
        }

        /// <summary>Writes a mesh in Unity's space to a file in the file's own space (the inverse of
        /// <see cref="Read(string)"/>: a model read and written gives the file back). The mesh is mirrored for
        /// the write and mirrored back, so it ends as it was, but render buffers of it rebuild at their next
        /// sync.</summary>
        public static void Write(HalfEdgeMesh mesh, string path, bool binary = false, int precision = 0)
        {
            if (mesh == null) throw new ArgumentNullException("mesh");
            mesh.MirrorX();
            try
            {
                mesh.Write(path, binary, precision);
            }
            finally
            {
                mesh.MirrorX();
            }
        }

        static HalfEdgeMesh ToUnitySpace(HalfEdgeMesh mesh)
        {
            try
            {
                mesh.MirrorX();
                return mesh;
            }
            catch
            {
                mesh.Dispose();
                throw;
            }
        }
    }
}
