// HalfEdgeMesh.AddFace with Unity's Vector2 texture coordinates, passed to the native library pinned
// as they are (two floats each), as the float[] overload does.
using System;
using System.Runtime.InteropServices;
using UnityEngine;

namespace Hedge.Unity
{
    /// <summary>Face attributes in Unity's types.</summary>
    public static class UnityAttributes
    {
        /// <summary><see cref="HalfEdgeMesh.AddFace(Vertex[], int, float[], int)"/> with one Vector2 per corner
        /// (null: none) and all of corners.</summary>
        public static Face AddFace(this HalfEdgeMesh mesh, Vertex[] corners, Vector2[] uv, int submesh = -1)
        {
            if (mesh == null) throw new ArgumentNullException("mesh");
            if (corners == null) throw new ArgumentNullException("corners");
            if (uv != null && uv.Length < corners.Length)
                throw new ArgumentException("holds " + uv.Length + " texcoords, " + corners.Length + " needed (one per corner)",
                                            "uv");
            HalfEdgeMesh.CheckSubmesh(submesh);
            uint f;
            int status = hedge_add_face_with_attributes(mesh.Id, corners, (uint)corners.Length, uv, submesh, out f);
            return mesh.AddedFace(status, f);
        }

        [DllImport(Native.Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        static extern int hedge_add_face_with_attributes(IntPtr mesh, [In] Vertex[] vertices, uint count,
                                                         [In] Vector2[] texcoords, int submesh, out uint face);
    }
}
