// SafeHandles owning the native objects: they destroy the object exactly once, on Dispose() or,
// if the owner forgot, after the garbage collector found it: a mesh from the finalizer thread (the
// C ABI may be called from any thread, and nothing else can be using an unreachable mesh), a render
// object on its mesh's thread (see RenderHandle).
//
// The handles of the C ABI are ids checked against a registry on every call and never reused, not
// addresses. The wrappers therefore pass the raw id to the native functions, after checking that
// the handle is not closed: a call on a disposed object throws ObjectDisposedException naming the
// wrapper's type (HalfEdgeMesh, RenderBuffers) and never reaches the library. Disposing a mesh while
// another thread is in a call on it is a misuse the library refuses (HEDGE_ERROR_BUSY): the native
// mesh then stays until the process ends, rather than being freed under the running call.
using System;
using System.Collections.Generic;
using System.Runtime.InteropServices;

namespace Hedge
{
    /// <summary>Owns a native hedge_mesh. Releasing it also destroys the mesh's render objects.</summary>
    public sealed class MeshHandle : SafeHandle
    {
        internal MeshHandle(IntPtr id) : base(IntPtr.Zero, true) { SetHandle(id); }

        public override bool IsInvalid { get { return handle == IntPtr.Zero; } }

        protected override bool ReleaseHandle()
        {
            // Cannot fail for a handle this object created; nothing to report from a finalizer anyway.
            Native.hedge_mesh_destroy(handle);
            return true;
        }
    }

    /// <summary>Owns a native hedge_render_buffers.</summary>
    /// <remarks>Destroying a render object touches its mesh (it stops following the mesh's changes), and
    /// the C ABI allows one thread at a time per mesh. So only an explicit Dispose() destroys it at once;
    /// when the finalizer releases it (a RenderBuffers nobody disposed), it is queued on its mesh and
    /// destroyed on the mesh's own thread, at the mesh's next CreateRenderBuffers, GarbageCollection, or
    /// sync of any of its RenderBuffers. (The mesh's destruction destroys it too.)</remarks>
    public sealed class RenderHandle : SafeHandle
    {
        readonly PendingRenders pending;
        volatile bool disposing;

        internal RenderHandle(IntPtr id, PendingRenders pending) : base(IntPtr.Zero, true)
        {
            this.pending = pending;
            SetHandle(id);
        }

        public override bool IsInvalid { get { return handle == IntPtr.Zero; } }

        /// <summary>Disposes on the calling thread, which must be the mesh's.</summary>
        internal void DisposeNow()
        {
            disposing = true;
            Dispose();
        }

        protected override bool ReleaseHandle()
        {
            if (disposing)
                // HEDGE_ERROR_BAD_HANDLE when the mesh was destroyed first (which destroyed this object
                // too): nothing left to release.
                Native.hedge_render_buffers_destroy(handle);
            else
                pending.Add(handle);
            return true;
        }
    }

    /// <summary>Render objects of one mesh released by the finalizer, waiting for the mesh's thread.</summary>
    internal sealed class PendingRenders
    {
        readonly object gate = new object();
        readonly List<IntPtr> ids = new List<IntPtr>();
        volatile int count;

        internal int Count { get { return count; } }

        internal void Add(IntPtr id)
        {
            lock (gate)
            {
                ids.Add(id);
                count = ids.Count;
            }
        }

        /// <summary>Destroys the queued render objects; call on the mesh's thread. Costs one volatile read
        /// when nothing is queued.</summary>
        internal void Drain()
        {
            if (count == 0) return;
            lock (gate)
            {
                foreach (IntPtr id in ids) Native.hedge_render_buffers_destroy(id);
                ids.Clear();
                count = 0;
            }
        }
    }
}
