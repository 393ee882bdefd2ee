// RenderBuffers: engine-ready vertex and index buffers kept in step with a HalfEdgeMesh (the C ABI's
// hedge_render_buffers, hedge/render/render_buffers.h).
//
// Each face owns fixed triangle slots in the index buffer and each render vertex (a mesh vertex
// per distinct set of corner attributes: seams split vertices) a fixed vertex slot. Sync() rewrites
// only what the edits since the last sync touched and reports the rewritten ranges; copy those
// ranges into arrays you keep (CopyDirtyVertices / CopyDirtyIndices) and upload them with a start
// and a count. Freed slots stay as holes (degenerate triangles, unreferenced vertices) until
// Compact(). Edits between BeginTransaction() and CommitTransaction() are synced once, at commit.
//
// Sizes. The buffers grow inside a capacity the library keeps (Counts.VertexCapacity and
// IndexCapacity); Resized says they grew beyond it (or were rebuilt). Counts grow inside it without
// Resized (the new slots are then among the dirty ranges). So allocate your arrays (and GPU
// buffers) at the capacities; after a Resized or Full result, reallocate and copy everything;
// otherwise copy the dirty ranges. UpdateVertexMirror and UpdateIndexMirror do exactly that.
// After Compact(), copy everything. A consumer that uploads later than it syncs, or not after every
// sync, keeps a RenderChangeLog (CreateChangeLog()): every sync merges its ranges into it.
//
// Errors follow HalfEdgeMesh: a failed status throws HedgeException; a RenderBuffers that was
// disposed, or whose mesh was (which disposes them too), throws ObjectDisposedException. The partial copies read the library's buffers in place
// (no copy of the whole buffer, no managed allocation).
using System;
using System.Collections.Generic;
using System.Runtime.InteropServices;

namespace Hedge
{
    /// <summary>Vertex and index buffers that follow the edits of a <see cref="HalfEdgeMesh"/>.</summary>
    public sealed partial class RenderBuffers : IDisposable
    {

        readonly RenderHandle handle;
        readonly IntPtr liveId;
        // Keeps the mesh (and so the native render object) alive as long as these buffers are reachable.
        readonly HalfEdgeMesh mesh;
        readonly RenderOptions options;
        readonly VertexLayout layout;
        // Scratch for the dirty ranges of the partial copies; grows, never shrinks.
        SlotRange[] ranges = new SlotRange[16];

        internal RenderBuffers(HalfEdgeMesh mesh, RenderOptions options)
        {
            if (mesh == null) throw new ArgumentNullException("mesh");
            IntPtr render;
            Status.Check(Native.hedge_render_buffers_create(mesh.Id, ref options, out render));
            liveId = render;
            handle = new RenderHandle(render, mesh.PendingRenders);
            this.mesh = mesh;
            this.options = options;
            Status.Check(Native.hedge_render_buffers_layout(id, out layout));
        }

        // The native id for a call: every call goes through here, so buffers disposed themselves or with
        // their mesh throw ObjectDisposedException (naming the type) before they reach the library.
        IntPtr id
        {
            get
            {
                ThrowIfDisposed();
                return liveId;
            }
        }

        void ThrowIfDisposed()
        {
            if (handle.IsClosed) throw new ObjectDisposedException("RenderBuffers");
            if (mesh.IsDisposed)
                throw new ObjectDisposedException("RenderBuffers", "Their mesh was disposed, which disposed them too.");
        }

        /// <summary>The mesh these buffers follow.</summary>
        public HalfEdgeMesh Mesh { get { return mesh; } }
        public RenderOptions Options { get { return options; } }
        /// <summary>Where each attribute sits in a vertex (fixed for the life of the buffers).</summary>
        public VertexLayout Layout
        {
            get
            {
                ThrowIfDisposed();
                return layout;
            }
        }
        /// <summary>The SafeHandle that owns the native render object.</summary>
        public SafeHandle Handle { get { return handle; } }
        /// <summary>True after <see cref="Dispose"/> or the mesh's; every later call (but Dispose, IsDisposed,
        /// Mesh, Options and Handle) throws ObjectDisposedException.</summary>
        public bool IsDisposed { get { return handle.IsClosed || mesh.IsDisposed; } }

        internal IntPtr Id { get { return id; } }

        /// <summary>Destroys the native render object (the mesh stays). Call it on the mesh's thread. A
        /// RenderBuffers that is not disposed is destroyed on the mesh's thread after the garbage collector
        /// finds it (see <see cref="RenderHandle"/>).</summary>
        public void Dispose() { handle.DisposeNow(); }

        /// <summary>Buffer sizes (slot counts include free slots).</summary>
        public BufferCounts Counts
        {
            get
            {
                BufferCounts counts;
                Status.Check(Native.hedge_render_buffers_counts(id, out counts));
                if (counts.IndexCount < 0 || counts.IndexCapacity < 0) throw Status.TooLarge("index-buffer entries");
                return counts;
            }
        }

        /// <summary>Floats per vertex in a stream: the stride for interleaved vertices, else 3, 3, 2, 4, 4 or 2.</summary>
        public int Components(VertexStream stream)
        {
            switch (stream)
            {
                case VertexStream.Vertices: return layout.Interleaved ? (int)layout.Stride : 3;
                case VertexStream.Normals: return 3;
                case VertexStream.Texcoords: return 2;
                case VertexStream.Colors: return 4;
                case VertexStream.Tangents: return 4;
                case VertexStream.Texcoords1: return 2;
                default: throw new ArgumentOutOfRangeException("stream", stream, "not a VertexStream");
            }
        }

        // =========================================================================================
        // Updates
        // =========================================================================================

        /// <summary>Brings the buffers in step with the edits since the last sync. Inside a transaction it
        /// does nothing (an empty result).</summary>
        public SyncResult Sync()
        {
            mesh.PendingRenders.Drain();
            return Record(Status.Checked(Native.hedge_render_buffers_sync(id, out SyncResult result), result));
        }

        /// <summary>Opens a transaction of these buffers: edits are gathered until the matching commit
        /// (transactions nest). Other RenderBuffers of the same mesh keep syncing as usual.</summary>
        public void BeginTransaction() { Status.Check(Native.hedge_render_buffers_begin(id)); }

        /// <summary>Closes the transaction; the outermost commit syncs once. Without an open transaction:
        /// HedgeException(InvalidArgument).</summary>
        public SyncResult CommitTransaction()
        {
            mesh.PendingRenders.Drain();
            return Record(Status.Checked(Native.hedge_render_buffers_commit(id, out SyncResult result), result));
        }

        /// <summary>Rebuilds every buffer from scratch, a full export (slots restart in face order, so it
        /// also compacts).</summary>
        public SyncResult Rebuild()
        {
            mesh.PendingRenders.Drain();
            return Record(Status.Checked(Native.hedge_render_buffers_rebuild(id, out SyncResult result), result));
        }

        /// <summary>The result of the last sync, commit or rebuild.</summary>
        public SyncResult LastResult
        {
            get { return Status.Checked(Native.hedge_render_buffers_last_result(id, out SyncResult result), result); }
        }

        /// <summary>The render-vertex slot ranges the last sync, commit or rebuild rewrote, sorted, merged and
        /// disjoint (the same ranges apply to every stream). Null asks for the count only.</summary>
        public int GetDirtyVertexRanges(SlotRange[] result)
        {
            uint count;
            int status = Native.hedge_render_buffers_dirty_vertex_ranges(id, result, Status.Capacity(result), out count);
            return Status.Filled(status, result == null, count);
        }

        /// <summary>The index-buffer ranges (in indices, not triangles) the last sync, commit or rebuild
        /// rewrote, sorted, merged and disjoint. Null asks for the count only.</summary>
        public int GetDirtyIndexRanges(SlotRange[] result)
        {
            uint count;
            int status = Native.hedge_render_buffers_dirty_index_ranges(id, result, Status.Capacity(result), out count);
            return Status.Filled(status, result == null, count);
        }

        /// <summary>Removes the free slots by packing the live slots in their current order; upload both buffers again
        /// afterwards. Outside a transaction it syncs pending edits first. Each map is optional (null): old
        /// render-vertex slot -> new slot, old triangle slot -> new triangle slot (freed slots map to -1);
        /// they must hold the vertex count and index count / 3 of <see cref="Counts"/> after that sync.</summary>
        public void Compact(int[] vertexMap = null, int[] triangleMap = null)
        {
            uint vertexCount, triangleCount;
            Status.Check(Native.hedge_render_buffers_compact_int(id, vertexMap, Status.Capacity(vertexMap), out vertexCount,
                                                         triangleMap, Status.Capacity(triangleMap), out triangleCount));
            for (int i = 0; i < changeLogs.Count; ++i) changeLogs[i].MarkEverything();
        }

        // =========================================================================================
        // Change logs: what every sync rewrote, for consumers that upload later (RenderChangeLog.cs)
        // =========================================================================================

        readonly List<RenderChangeLog> changeLogs = new List<RenderChangeLog>();

        /// <summary>A log of every range the buffers rewrite from now on, by any sync, commit, rebuild or
        /// compaction, until it is cleared: what an uploader must send, whoever synced. Dispose it to stop
        /// recording.</summary>
        public RenderChangeLog CreateChangeLog()
        {
            ThrowIfDisposed();
            var log = new RenderChangeLog(this);
            changeLogs.Add(log);
            return log;
        }

        internal void RemoveChangeLog(RenderChangeLog log) { changeLogs.Remove(log); }

        // Adds a result's dirty ranges to every change log (or marks them everything).
        SyncResult Record(SyncResult result)
        {
            if (changeLogs.Count == 0 || result.IsEmpty) return result;
            if (result.Full || result.Resized)
            {
                for (int i = 0; i < changeLogs.Count; ++i) changeLogs[i].MarkEverything();
                return result;
            }
            int n = LoadRanges(true);
            for (int i = 0; i < changeLogs.Count; ++i) changeLogs[i].Record(true, ranges, n);
            n = LoadRanges(false);
            for (int i = 0; i < changeLogs.Count; ++i) changeLogs[i].Record(false, ranges, n);
            return result;
        }

        // =========================================================================================
        // Whole buffers into caller arrays. Each returns the entries needed; null asks for that only.
        // =========================================================================================

        /// <summary>Copies a vertex stream (<see cref="VertexStream.Vertices"/>: the interleaved vertices, or
        /// the positions of a separate layout).</summary>
        /// <returns>Floats in the stream (0 for a stream the layout does not have).</returns>
        public int CopyStream(VertexStream stream, float[] buffer)
        {
            ulong count;
            int status = Native.hedge_render_buffers_copy_vertex_data(id, (int)stream, buffer,
                                                              buffer != null ? (ulong)buffer.Length : 0, out count);
            return Status.Filled(status, buffer == null, count);
        }

        /// <summary>Copies the <see cref="VertexStream.Vertices"/> stream.</summary>
        public int CopyVertices(float[] buffer) { return CopyStream(VertexStream.Vertices, buffer); }

        /// <summary>Copies the index buffer (3 entries per triangle slot) into an int array (Unity's
        /// Mesh.triangles type).</summary>
        public int CopyIndices(int[] buffer)
        {
            ulong count;
            int status = Native.hedge_render_buffers_copy_index_data_int(id, buffer, buffer != null ? (ulong)buffer.Length : 0,
                                                                 out count);
            return Status.Filled(status, buffer == null, count);
        }

        // =========================================================================================
        // Partial copies: the dirty ranges, or any range, into arrays the caller keeps
        // =========================================================================================

        /// <summary>Copies render vertices [firstVertex, firstVertex + vertexCount) of a stream into the same
        /// place of destination (float firstVertex x components on).</summary>
        public void CopyVertexRange(VertexStream stream, int firstVertex, int vertexCount, float[] destination)
        {
            if (destination == null) throw new ArgumentNullException("destination");
            if (firstVertex < 0) throw new ArgumentOutOfRangeException("firstVertex");
            if (vertexCount < 0) throw new ArgumentOutOfRangeException("vertexCount");
            int components = Components(stream);
            if (vertexCount == 0) return;
            ulong floats;
            IntPtr data = StreamData(stream, out floats);
            CopyFloats(data, floats, (long)firstVertex * components, (long)vertexCount * components, destination);
            GC.KeepAlive(this);
        }

        /// <summary>Copies index-buffer entries [first, first + count) into the same place of destination.</summary>
        public void CopyIndexRange(int first, int count, int[] destination)
        {
            if (destination == null) throw new ArgumentNullException("destination");
            if (first < 0) throw new ArgumentOutOfRangeException("first");
            if (count < 0) throw new ArgumentOutOfRangeException("count");
            ulong entries;
            IntPtr data = IndexData(out entries);
            CopyInts(data, entries, first, count, destination);
            GC.KeepAlive(this);
        }

        /// <summary>Copies the vertex ranges the last sync rewrote, of one stream, into a mirror of that stream
        /// (an array of at least Counts.VertexSlots x <see cref="Components"/> floats that holds the stream as of
        /// the previous sync). Afterwards the mirror equals the stream.</summary>
        /// <returns>The number of render vertices copied.</returns>
        public int CopyDirtyVertices(VertexStream stream, float[] mirror)
        {
            if (mirror == null) throw new ArgumentNullException("mirror");
            int components = Components(stream);
            int n = LoadRanges(true);
            if (n == 0) return 0;
            ulong floats;
            IntPtr data = StreamData(stream, out floats);
            int copied = 0;
            for (int i = 0; i < n; ++i)
            {
                SlotRange r = ranges[i];
                CopyFloats(data, floats, (long)r.First * components, (long)r.Count * components, mirror);
                copied += (int)r.Count;
            }
            GC.KeepAlive(this);
            return copied;
        }

        /// <summary>Copies the index ranges the last sync rewrote into a mirror of the index buffer (at least
        /// Counts.IndexCount entries, holding the buffer as of the previous sync).</summary>
        /// <returns>The number of indices copied.</returns>
        public int CopyDirtyIndices(int[] mirror)
        {
            if (mirror == null) throw new ArgumentNullException("mirror");
            int n = LoadRanges(false);
            if (n == 0) return 0;
            ulong entries;
            IntPtr data = IndexData(out entries);
            int copied = 0;
            for (int i = 0; i < n; ++i)
            {
                SlotRange r = ranges[i];
                CopyInts(data, entries, r.First, r.Count, mirror);
                copied += (int)r.Count;
            }
            GC.KeepAlive(this);
            return copied;
        }

        /// <summary>Brings an array that mirrors a vertex stream up to date after a sync, commit or rebuild: if
        /// the stream outgrew it, or after a Resized or Full result, it grows the array (to the capacity) and
        /// copies the whole stream; otherwise it copies the dirty ranges only. Allocates only when it grows.
        /// (After <see cref="Compact"/>, copy the whole stream with <see cref="CopyStream"/>.)</summary>
        /// <param name="stream">The stream the array mirrors.</param>
        /// <param name="mirror">The array; null makes a new one (at the capacity, and copies everything).</param>
        /// <returns>True if only the dirty ranges were copied (upload those); false if everything was copied
        /// (reallocate and upload everything).</returns>
        public bool UpdateVertexMirror(VertexStream stream, ref float[] mirror)
        {
            SyncResult result = LastResult;
            BufferCounts counts = Counts;
            long needed = (long)counts.VertexSlots * Components(stream);
            long capacity = (long)counts.VertexCapacity * Components(stream);
            bool grew = Grow(ref mirror, needed, capacity);
            if (mirror == null || grew || result.Resized || result.Full)
            {
                if (mirror == null) mirror = Allocate<float>(needed, capacity);
                CopyStream(stream, mirror);
                return false;
            }
            CopyDirtyVertices(stream, mirror);
            return true;
        }

        /// <summary>As <see cref="UpdateVertexMirror"/>, for an array that mirrors the index buffer.</summary>
        public bool UpdateIndexMirror(ref int[] mirror)
        {
            SyncResult result = LastResult;
            BufferCounts counts = Counts;
            bool grew = Grow(ref mirror, counts.IndexCount, counts.IndexCapacity);
            if (mirror == null || grew || result.Resized || result.Full)
            {
                if (mirror == null) mirror = Allocate<int>(counts.IndexCount, counts.IndexCapacity);
                CopyIndices(mirror);
                return false;
            }
            CopyDirtyIndices(mirror);
            return true;
        }

        // Replaces an array too small for `needed` entries by one of the library's capacity (its contents
        // are copied in full by the caller). A null array stays null (the caller makes it). True if it grew.
        static bool Grow<T>(ref T[] array, long needed, long capacity)
        {
            if (array == null || array.Length >= needed) return false;
            array = Allocate<T>(needed, capacity);
            return true;
        }

        static T[] Allocate<T>(long needed, long capacity)
        {
            return new T[Math.Min(int.MaxValue, Math.Max(needed, capacity))];
        }

        // Reads the dirty vertex or index ranges into the scratch array, growing it if needed.
        int LoadRanges(bool vertices)
        {
            for (;;)
            {
                uint count;
                int status = vertices
                                 ? Native.hedge_render_buffers_dirty_vertex_ranges(id, ranges, (uint)ranges.Length, out count)
                                 : Native.hedge_render_buffers_dirty_index_ranges(id, ranges, (uint)ranges.Length, out count);
                if (status == Status.BufferTooSmall)
                {
                    ranges = new SlotRange[Math.Max((int)count, 2 * ranges.Length)];
                    continue;
                }
                Status.Check(status);
                return (int)count;
            }
        }

        IntPtr StreamData(VertexStream stream, out ulong floats)
        {
            IntPtr data;
            Status.Check(Native.hedge_render_buffers_vertex_data(id, (int)stream, out data, out floats));
            if (data == IntPtr.Zero || floats == 0)
                throw new InvalidOperationException("the " + stream + " stream is empty in this layout");
            return data;
        }

        IntPtr IndexData(out ulong entries)
        {
            IntPtr data;
            Status.Check(Native.hedge_render_buffers_index_data(id, out data, out entries));
            return data;
        }

        static void CopyFloats(IntPtr data, ulong available, long first, long count, float[] destination)
        {
            if (!CheckCopy(available, first, count, destination, "floats", "the stream's ")) return;
            Marshal.Copy(new IntPtr(data.ToInt64() + first * sizeof(float)), destination, (int)first, (int)count);
        }

        static void CopyInts(IntPtr data, ulong available, long first, long count, int[] destination)
        {
            if (!CheckCopy(available, first, count, destination, "indices", "the index buffer's ")) return;
            Marshal.Copy(new IntPtr(data.ToInt64() + first * sizeof(int)), destination, (int)first, (int)count);
        }

        // Checks a copy of entries [first, first + count) of a native buffer of `available` entries into
        // the same place of destination; false when there is nothing to copy.
        static bool CheckCopy(ulong available, long first, long count, Array destination, string entries,
                              string source)
        {
            if (count == 0) return false;
            if ((ulong)(first + count) > available)
                throw new ArgumentOutOfRangeException("count", entries + " [" + first + ", " + (first + count) +
                                                               ") beyond " + source + available);
            if (first + count > destination.Length)
                throw new ArgumentException("holds " + destination.Length + " " + entries + ", " + (first + count) +
                                            " needed: reallocate it after a resize", "destination");
            return true;
        }

        // =========================================================================================
        // Maps between render slots and mesh elements (as of the last sync)
        // =========================================================================================

        /// <summary>Render vertex slot -> mesh vertex (<see cref="Vertex.Invalid"/> for a free slot), one entry
        /// per slot. Null asks for the count only.</summary>
        public int CopyVertexSource(Vertex[] result)
        {
            uint count;
            int status = Native.hedge_render_buffers_vertex_source(id, result, Status.Capacity(result), out count);
            return Status.Filled(status, result == null, count);
        }

        /// <summary>The render vertex of the corner the half-edge enters; -1 for a boundary half-edge.</summary>
        public int GetRenderVertex(HalfEdge corner)
        {
            uint rv;
            Status.Check(Native.hedge_render_buffers_corner_vertex(id, corner.Raw, out rv));
            return unchecked((int)rv);
        }

        /// <summary>The triangle slots of a face: triangles [First, First + Count) of the index buffer (indices
        /// 3 x First on); Count 0 if it has none.</summary>
        public SlotRange GetFaceTriangles(Face f)
        {
            uint first, count;
            Status.Check(Native.hedge_render_buffers_face_triangles(id, f.Raw, out first, out count));
            return new SlotRange((int)first, (int)count);
        }
    }
}
