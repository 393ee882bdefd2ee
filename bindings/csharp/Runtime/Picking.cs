// Picking: the first face a ray hits, the nearest point of the surface, and the face under a point
// (hedge/algorithms/locate.h through the C ABI's hedge_mesh_raycast and its neighbours).
//
// The native mesh owns a bounding volume hierarchy over its faces. The first query builds it
// (O(n log n), about 45 bytes a face); every later query first takes in the edits made since the
// previous one (a few microseconds per changed face, nothing when nothing changed), then answers in
// O(log n) expected time. Call UpdatePickingTree() after loading or after a batch of edits to pay
// for that up front, and ReleasePickingTree() to free it. Queries allocate no managed memory.
//
// A query that finds nothing returns false; a coordinate that is NaN or infinite, or a limit out
// of range, throws HedgeException(InvalidArgument) with the library's message.
using System;
using System.Runtime.InteropServices;

#pragma warning disable 0649

namespace Hedge
{
    /// <summary>Where a picking query met the surface (the C ABI's hedge_surface_hit, 48 bytes). It is
    /// named apart from UnityEngine.RaycastHit so that scripts using both namespaces compile.</summary>
    [StructLayout(LayoutKind.Sequential)]
    public struct SurfaceHit
    {
        /// <summary>The face found.</summary>
        public Face Face;
        /// <summary>The corners of the triangle of the face the point is in (a polygon face is a fan
        /// from its first corner, Corner0).</summary>
        public Vertex Corner0, Corner1, Corner2;
        /// <summary>The point on the surface.</summary>
        public Vec3 Point;
        /// <summary>The weights of Corner0, Corner1 and Corner2 (each in [0, 1], summing to 1).</summary>
        public Vec3 Barycentric;
        /// <summary>Raycast: Point = origin + T x direction (in units of the direction's length); 0 for the
        /// other queries.</summary>
        public float T;
        /// <summary>From the query's origin or point to <see cref="Point"/>, in the mesh's units.</summary>
        public float Distance;

        /// <summary>No hit: every handle invalid, every number 0 (what a query that finds nothing gives).</summary>
        public static SurfaceHit None { get { return none; } }

        static readonly SurfaceHit none = new SurfaceHit
        {
            Face = Face.Invalid, Corner0 = Vertex.Invalid, Corner1 = Vertex.Invalid, Corner2 = Vertex.Invalid,
        };

        public override string ToString()
        {
            return Face + " at " + Point + ", distance " +
                   Distance.ToString("R", System.Globalization.CultureInfo.InvariantCulture);
        }
    }

    /// <summary>The coordinate plane of <see cref="HalfEdgeMesh.TryGetFaceContainingPoint(float, float,
    /// ProjectionPlane, out Face)"/>: the two coordinates kept.</summary>
    public enum ProjectionPlane
    {
        /// <summary>(x, y): z is dropped.</summary>
        XY = 0,
        /// <summary>(x, z): y is dropped, the ground plane of y-up engines such as Unity.</summary>
        XZ = 1,
        /// <summary>(y, z): x is dropped.</summary>
        YZ = 2,
    }

    public sealed partial class HalfEdgeMesh
    {
        /// <summary>The first face hit by the ray origin + t x direction, 0 &lt;= t &lt;= maxT. Watertight (a
        /// ray through a shared edge or vertex hits one of its faces) and two-sided.</summary>
        /// <param name="origin">Finite.</param>
        /// <param name="direction">Finite and not zero; need not be unit length.</param>
        /// <param name="hit">The hit, or <see cref="SurfaceHit.None"/> when it returns false.</param>
        /// <param name="maxT">&gt;= 0; infinity (the default) for an unbounded ray.</param>
        /// <returns>True if a face was hit.</returns>
        public bool Raycast(Vec3 origin, Vec3 direction, out SurfaceHit hit, float maxT = float.PositiveInfinity)
        {
            int found;
            Status.Check(Native.hedge_mesh_raycast(id, ref origin, ref direction, maxT, out hit, out found));
            if (found == 0) hit = SurfaceHit.None;
            return found != 0;
        }

        /// <summary>The nearest point of the surface to a point, no farther than maxDistance.</summary>
        /// <param name="point">Finite.</param>
        /// <param name="hit">The nearest point with its face; <see cref="SurfaceHit.None"/> when it returns false.</param>
        /// <param name="maxDistance">&gt;= 0; infinity (the default) for no limit. A limit makes the search
        /// cheaper.</param>
        public bool TryGetClosestPoint(Vec3 point, out SurfaceHit hit, float maxDistance = float.PositiveInfinity)
        {
            int found;
            Status.Check(Native.hedge_mesh_closest_point(id, ref point, maxDistance, out hit, out found));
            if (found == 0) hit = SurfaceHit.None;
            return found != 0;
        }

        /// <summary>The face a point on the surface lies on: the nearest face, if the point is within tolerance
        /// of it (an impact point from a physics engine, a point on a plate in any orientation).</summary>
        /// <param name="point">Finite.</param>
        /// <param name="face">The face; <see cref="Hedge.Face.Invalid"/> when it returns false.</param>
        /// <param name="tolerance">&gt;= 0 and finite, in the mesh's units.</param>
        public bool TryGetFaceContainingPoint(Vec3 point, out Face face, float tolerance = 1e-4f)
        {
            SurfaceHit hit;
            int found;
            Status.Check(Native.hedge_mesh_face_containing_point(id, ref point, tolerance, out hit, out found));
            face = found != 0 ? hit.Face : Face.Invalid;
            return found != 0;
        }

        /// <summary>2D plates and height fields: the face whose projection onto a coordinate plane contains
        /// (u, v), boundary included.</summary>
        /// <param name="u">The first kept coordinate (x for XY and XZ, y for YZ).</param>
        /// <param name="v">The second kept coordinate (y for XY, z for XZ and YZ).</param>
        /// <param name="plane">The plane projected onto.</param>
        /// <param name="face">The face; <see cref="Hedge.Face.Invalid"/> when it returns false.</param>
        public bool TryGetFaceContainingPoint(float u, float v, ProjectionPlane plane, out Face face)
        {
            SurfaceHit hit;
            return TryGetFaceContainingPoint(u, v, plane, out face, out hit);
        }

        /// <summary>As above, also giving the point of the face that projects onto (u, v): the dropped
        /// coordinate interpolated, so this samples a height field.</summary>
        public bool TryGetFaceContainingPoint(float u, float v, ProjectionPlane plane, out Face face, out SurfaceHit hit)
        {
            int found;
            Status.Check(Native.hedge_mesh_face_containing_point_2d(id, u, v, (int)plane, out hit, out found));
            if (found == 0) hit = SurfaceHit.None;
            face = found != 0 ? hit.Face : Face.Invalid;
            return found != 0;
        }

        /// <summary>Builds the picking tree now, or takes in the edits since the last query, so that the next
        /// query does not pay for it.</summary>
        /// <returns>Heap bytes the tree holds.</returns>
        public long UpdatePickingTree()
        {
            ulong bytes;
            Status.Check(Native.hedge_mesh_bvh_update(id, out bytes));
            return (long)bytes;
        }

        /// <summary>Frees the picking tree; the next query builds it again.</summary>
        public void ReleasePickingTree() { Status.Check(Native.hedge_mesh_bvh_release(id)); }
    }

    public sealed partial class RenderBuffers
    {
        /// <summary>The face that owns a triangle of the index buffer (indices 3 x triangleIndex on), as of
        /// the last sync: what Unity's RaycastHit.triangleIndex names on a MeshCollider of the uploaded
        /// mesh. <see cref="Face.Invalid"/> for a free triangle slot and for a face deleted since that
        /// sync. O(1).</summary>
        /// <exception cref="ArgumentOutOfRangeException">triangleIndex is negative.</exception>
        /// <exception cref="HedgeException">BadHandle: triangleIndex is not below IndexCount / 3.</exception>
        public Face FaceOfTriangle(int triangleIndex)
        {
            if (triangleIndex < 0)
                throw new ArgumentOutOfRangeException("triangleIndex", triangleIndex, "a triangle index is >= 0");
            return Status.Checked(Native.hedge_render_buffers_triangle_face(id, triangleIndex, out Face face), face);
        }

        /// <summary>The library's own vertex stream, read in place: valid until the next Sync, commit,
        /// Rebuild or Compact of these buffers, or until they or their mesh are disposed. Read-only. For
        /// zero-copy uploads (the Unity glue wraps it in a NativeArray).</summary>
        /// <param name="stream">The stream.</param>
        /// <param name="floatCount">Floats in the stream (0, with IntPtr.Zero, for an absent stream).</param>
        public IntPtr GetStreamPointer(VertexStream stream, out int floatCount)
        {
            IntPtr data;
            ulong count;
            Status.Check(Native.hedge_render_buffers_vertex_data(id, (int)stream, out data, out count));
            floatCount = checked((int)count);
            return data;
        }

        /// <summary>The library's own index buffer (32-bit indices, 3 per triangle slot), read in place; valid
        /// as <see cref="GetStreamPointer"/>.</summary>
        /// <param name="indexCount">Indices in the buffer.</param>
        public IntPtr GetIndexPointer(out int indexCount)
        {
            IntPtr data;
            ulong count;
            Status.Check(Native.hedge_render_buffers_index_data(id, out data, out count));
            indexCount = checked((int)count);
            return data;
        }
    }
}
