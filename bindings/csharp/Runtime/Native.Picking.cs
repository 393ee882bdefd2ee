// P/Invoke declarations of the C ABI's picking functions and render-triangle-to-face map
// (include/hedge/c_api.h), blittable as the others in Native.cs. Element indices travel as int or as
// the one-index handle structs: the same 32 bits as the C uint32_t.
using System;
using System.Runtime.InteropServices;

namespace Hedge
{
    internal static partial class Native
    {
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_mesh_bvh_update(IntPtr mesh, out ulong bytes);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_mesh_bvh_release(IntPtr mesh);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_mesh_raycast(IntPtr mesh, ref Vec3 origin, ref Vec3 direction, float tMax,
            out SurfaceHit hit, out int found);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_mesh_closest_point(IntPtr mesh, ref Vec3 point, float maxDistance,
            out SurfaceHit hit, out int found);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_mesh_face_containing_point(IntPtr mesh, ref Vec3 point, float tolerance,
            out SurfaceHit hit, out int found);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_mesh_face_containing_point_2d(IntPtr mesh, float u, float v, int plane,
            out SurfaceHit hit, out int found);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_render_buffers_triangle_face(IntPtr render, int triangle, out Face face);
    }
}
