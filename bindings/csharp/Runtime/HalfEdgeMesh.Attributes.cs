// Faces added with their attributes: texture coordinates per corner (the corner property
// "h:texcoord") and a submesh, the material slot an engine draws the face with (the face property
// "f:submesh", 0 by default), which follow the face through later edits, subdivision, decimation,
// detaching and fracture.
using System;
using System.Runtime.InteropServices;

namespace Hedge
{
    public sealed partial class HalfEdgeMesh
    {
        // The largest submesh a face takes (the C ABI's limit).

        /// <summary>Adds a face with the first count corners (counter-clockwise), their texture coordinates and
        /// its submesh. Everything is checked before the mesh changes.</summary>
        /// <param name="corners">The corners; the first count are used.</param>
        /// <param name="count">How many corners.</param>
        /// <param name="texcoords">Optional (null): u, v per corner, in the corners' order (at least 2 x count
        /// floats; the first 2 x count are used). The mesh's corner texcoords are added, (0, 0) at every other
        /// corner, if it has none.</param>
        /// <param name="submesh">The face's submesh (material slot) in [0, 65535]; -1 leaves the default, 0.</param>
        /// <returns>The new face, or <see cref="Face.Invalid"/> if <see cref="CanAddFace(Vertex[], int)"/> refuses
        /// (<see cref="LastRefusalCode"/> says why).</returns>
        /// <exception cref="ArgumentException">texcoords holds fewer than 2 x count floats; submesh is out of range
        /// (ArgumentOutOfRangeException).</exception>
        /// <exception cref="HedgeException">InvalidArgument: a texcoord is not finite, or the mesh keeps its
        /// texcoords per vertex; BadHandle: a corner is not a live vertex.</exception>
        public Face AddFace(Vertex[] corners, int count, float[] texcoords, int submesh)
        {
            CheckSpan(corners, count, "corners");
            if (texcoords != null && texcoords.Length < 2L * count)
                throw new ArgumentException("holds " + texcoords.Length + " floats, " + 2L * count +
                                            " needed (u, v per corner)", "texcoords");
            CheckSubmesh(submesh);
            uint f;
            int status = Native.hedge_add_face_with_attributes(id, corners, (uint)count, texcoords, submesh, out f);
            return AddedFace(status, f);
        }

        /// <summary>Adds a triangle with its texture coordinates (null: none) and submesh (-1: the default);
        /// see <see cref="AddFace(Vertex[], int, float[], int)"/>.</summary>
        public Face AddFace(Vertex a, Vertex b, Vertex c, float[] texcoords, int submesh)
        {
            return AddFace(Triangle(a, b, c), 3, texcoords, submesh);
        }

        // The result of an add_face call: the face, or Invalid if refused (LastRefusalCode says why).
        internal Face AddedFace(int status, uint f) { return WasRefused(status) ? Face.Invalid : new Face(f); }

        internal static void CheckSubmesh(int submesh)
        {
            if (submesh < -1 || submesh > MaxSubmesh)
                throw new ArgumentOutOfRangeException("submesh", submesh,
                                                      "a face's submesh is in [0, " + MaxSubmesh + "] (-1: the default)");
        }
    }

    internal static partial class Native
    {
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_add_face_with_attributes(IntPtr mesh, [In] Vertex[] vertices, uint count,
                                                                  [In] float[] texcoords, int submesh, out uint face);
    }
}
