// Zero-copy uploads: the library's own vertex and index buffers, wrapped in NativeArrays
// (NativeArrayUnsafeUtility.ConvertExistingDataToNativeArray over the native pointers), feed
// Mesh.SetVertexBufferData and Mesh.SetIndexBufferData range by range. No managed array holds a
// copy of the mesh, and a partial upload allocates nothing.
//
// Layout: the buffers must use the separate layout of RenderOptions.Unity (Unity orders attributes
// inside one stream differently from hedge's interleaved vertex, so interleaved buffers are
// refused). Vertex stream 0 holds the positions, then the other attributes as UnityStreams.cs says:
// one stream each, or, with tangents and lightmap UVs too, normals with tangents and texcoords with
// lightmap UVs sharing a stream (Unity takes four). A stream of one attribute is uploaded from the
// library's memory as it is; a shared one is interleaved, range by range, into a NativeArray the
// uploader keeps (native memory, not managed), then uploaded. One submesh per submesh of the buffers, each a contiguous index range with its first
// vertex, vertex count and bounds (UploadSubmeshes, after every upload). Indices are 16-bit when every render vertex
// slot the GPU buffer can hold fits (at most 65536 slots): those are converted range by range into a
// NativeArray<ushort> the uploader keeps (native memory, not managed); otherwise the 32-bit native
// index buffer is uploaded as it is.
//
// Never stale: the uploader keeps a change log of the buffers (RenderChangeLog), which every sync,
// commit, rebuild and compaction fills, whoever calls it. An upload sends what the log gathered since
// the last upload, from the buffers' current data, so a script that syncs the buffers itself (to
// map a triangle to its face, say) does not leave the Unity mesh behind.
//
// Bounds: a full upload sets them from every position; a partial one grows them by the rewritten
// vertices only (O(what changed)). They never shrink between full uploads: a conservative box.
using System;
using Unity.Collections;
using Unity.Collections.LowLevel.Unsafe;
using UnityEngine;
using UnityEngine.Rendering;

namespace Hedge.Unity
{
    /// <summary>Uploads a <see cref="RenderBuffers"/> to a Unity Mesh without managed copies.</summary>
    public sealed class NativeMeshUploader : IDisposable
    {
        const MeshUpdateFlags PartialFlags = MeshUpdateFlags.DontValidateIndices | MeshUpdateFlags.DontRecalculateBounds |
                                             MeshUpdateFlags.DontNotifyMeshUsers;
        const MeshUpdateFlags FullFlags = MeshUpdateFlags.DontRecalculateBounds;

        readonly RenderBuffers buffers;
        readonly Mesh mesh;
        readonly RenderChangeLog log;
        UnityStreams streams;
        // Per Unity stream that interleaves several attributes: its staging buffer, gpuVertices x stride floats.
        readonly NativeArray<float>[] staging = new NativeArray<float>[UnityStreams.MaxStreams];
        int gpuVertices, gpuIndices, indexCount;
        IndexFormat indexFormat = IndexFormat.UInt32;
        NativeArray<ushort> indices16;
        bool disposed;
#if ENABLE_UNITY_COLLECTIONS_CHECKS
        AtomicSafetyHandle safety = AtomicSafetyHandle.Create();
#endif

        /// <summary>Uploads buffers to mesh; call <see cref="UploadAll"/> (or <see cref="Upload"/>) to send data.</summary>
        /// <exception cref="ArgumentException">The buffers use the interleaved layout.</exception>
        public NativeMeshUploader(RenderBuffers buffers, Mesh mesh)
        {
            if (buffers == null) throw new ArgumentNullException("buffers");
            if (mesh == null) throw new ArgumentNullException("mesh");
            if (buffers.Layout.Interleaved)
                throw new ArgumentException("interleaved buffers: use the separate layout (RenderOptions.Unity)", "buffers");
            this.buffers = buffers;
            this.mesh = mesh;
            log = buffers.CreateChangeLog();
        }

        public RenderBuffers Buffers { get { return buffers; } }
        public Mesh Mesh { get { return mesh; } }
        /// <summary>The index format of the last full upload: UInt16 while the render vertices fit.</summary>
        public IndexFormat IndexFormat { get { return indexFormat; } }

        /// <summary>The ranges rewritten since the last upload, by any sync of the buffers.</summary>
        public RenderChangeLog Pending { get { return log; } }

        /// <summary>Syncs the buffers, then uploads everything rewritten since the last upload
        /// (<see cref="Upload(SyncResult)"/>).</summary>
        /// <returns>True if only ranges were uploaded; false if everything was (or nothing changed).</returns>
        public bool Upload()
        {
            ThrowIfDisposed();
            buffers.Sync();
            return UploadPending();
        }

        /// <summary>Uploads everything the buffers rewrote since the last upload, whoever synced them: the
        /// gathered dirty ranges, or everything when a sync since then grew or rebuilt the buffers (Resized,
        /// Full: after Compact, garbage collection, subdivision). The result (of the caller's sync) is not
        /// needed: every sync, commit and rebuild of the buffers already reached the uploader's change log.</summary>
        /// <returns>True if only ranges were uploaded; false if everything was (or nothing changed).</returns>
        public bool Upload(SyncResult result) { return UploadPending(); }

        bool UploadPending()
        {
            ThrowIfDisposed();
            if (log.IsEmpty) return false;
            BufferCounts counts = buffers.Counts;
            if (log.Everything || counts.VertexSlots > gpuVertices || counts.IndexCount > gpuIndices)
            {
                UploadAll();
                return false;
            }
            if (log.VertexRangeCount > 0)
            {
                for (int s = 0; s < streams.Count; ++s) UploadVertexRanges(s);
                GrowBounds();
            }
            if (log.IndexRangeCount > 0) UploadIndexRanges();
            indexCount = (int)counts.IndexCount;
            UploadSubmeshes(PartialFlags);
            log.Clear();
            return true;
        }

        /// <summary>(Re)allocates the mesh's buffers at the library's capacities, chooses the index format
        /// and uploads everything.</summary>
        public void UploadAll()
        {
            ThrowIfDisposed();
            log.Clear();
            BufferCounts counts = buffers.Counts;
            VertexLayout layout = buffers.Layout;
            gpuVertices = (int)Math.Max(counts.VertexCapacity, counts.VertexSlots);
            gpuIndices = (int)Math.Max(counts.IndexCapacity, counts.IndexCount);
            indexCount = (int)counts.IndexCount;
            streams = UnityStreams.Describe(layout);
            mesh.SetVertexBufferParams(gpuVertices, streams.Attributes);
            for (int s = 0; s < streams.Count; ++s) UploadWholeStream(s, (int)counts.VertexSlots);

            indexFormat = gpuVertices <= 65536 ? IndexFormat.UInt16 : IndexFormat.UInt32;
            mesh.SetIndexBufferParams(gpuIndices, indexFormat);
            if (indexFormat == IndexFormat.UInt16)
            {
                if (!indices16.IsCreated || indices16.Length < gpuIndices)
                {
                    if (indices16.IsCreated) indices16.Dispose();
                    indices16 = new NativeArray<ushort>(gpuIndices, Allocator.Persistent, NativeArrayOptions.ClearMemory);
                }
                UploadIndices16(0, indexCount, FullFlags);
            }
            else if (indexCount > 0)
            {
                int count;
                NativeArray<uint> data = Wrap<uint>(buffers.GetIndexPointer(out count), count);
                mesh.SetIndexBufferData(data, 0, 0, indexCount, FullFlags);
            }
            UploadSubmeshes(FullFlags);
            SetBoundsFromAll((int)counts.VertexSlots);
        }

        // One SubMeshDescriptor per submesh of the buffers (materials), with the first vertex, vertex count
        // and bounds that DontRecalculateBounds needs given. O(submeshes).
        void UploadSubmeshes(MeshUpdateFlags flags) { UnitySubmeshes.SetSubmeshes(mesh, buffers, flags); }

        void UploadWholeStream(int s, int vertexSlots)
        {
            if (streams.Staged(s))
            {
                int stride = streams.Stride(s);
                long needed = (long)gpuVertices * stride;
                if (!staging[s].IsCreated || staging[s].Length < needed)
                {
                    if (staging[s].IsCreated) staging[s].Dispose();
                    staging[s] = new NativeArray<float>(checked((int)needed), Allocator.Persistent,
                                                        NativeArrayOptions.ClearMemory);
                }
                if (vertexSlots == 0) return;
                Interleave(s, 0, vertexSlots);
                mesh.SetVertexBufferData(staging[s], 0, 0, vertexSlots * stride, s, FullFlags);
                return;
            }
            int floats;
            IntPtr p = buffers.GetStreamPointer(streams.Members(s)[0], out floats);
            if (floats == 0) return;
            mesh.SetVertexBufferData(Wrap<float>(p, floats), 0, 0, floats, s, FullFlags);
        }

        void UploadVertexRanges(int s)
        {
            int k = streams.Stride(s);
            NativeArray<float> data;
            if (streams.Staged(s))
            {
                data = staging[s];
            }
            else
            {
                int floats;
                data = Wrap<float>(buffers.GetStreamPointer(streams.Members(s)[0], out floats), floats);
            }
            for (int i = 0, n = log.VertexRangeCount; i < n; ++i)
            {
                SlotRange r = log.VertexRange(i);
                if (streams.Staged(s)) Interleave(s, r.First, r.Count);
                mesh.SetVertexBufferData(data, r.First * k, r.First * k, r.Count * k, s, PartialFlags);
            }
        }

        unsafe void Interleave(int s, int first, int count)
        {
            streams.Interleave(buffers, s, (float*)NativeArrayUnsafeUtility.GetUnsafePtr(staging[s]), staging[s].Length,
                               first, count);
        }

        void UploadIndexRanges()
        {
            int n = log.IndexRangeCount;
            if (indexFormat == IndexFormat.UInt16)
            {
                for (int i = 0; i < n; ++i)
                    UploadIndices16(log.IndexRange(i).First, log.IndexRange(i).Count, PartialFlags);
                return;
            }
            int count;
            NativeArray<uint> data = Wrap<uint>(buffers.GetIndexPointer(out count), count);
            for (int i = 0; i < n; ++i)
            {
                SlotRange r = log.IndexRange(i);
                mesh.SetIndexBufferData(data, r.First, r.First, r.Count, PartialFlags);
            }
        }

        // Converts indices [first, first + count) to 16 bits in the uploader's native scratch, then
        // uploads them. The caller made sure every index is below 65536 (gpuVertices <= 65536).
        unsafe void UploadIndices16(int first, int count, MeshUpdateFlags flags)
        {
            if (count == 0) return;
            int available;
            uint* source = (uint*)buffers.GetIndexPointer(out available);
            if (first + count > available) throw new InvalidOperationException("index range beyond the buffer");
            ushort* target = (ushort*)NativeArrayUnsafeUtility.GetUnsafePtr(indices16);
            for (int i = first; i < first + count; ++i) target[i] = (ushort)source[i];
            mesh.SetIndexBufferData(indices16, first, first, count, flags);
        }

        unsafe void SetBoundsFromAll(int vertexSlots)
        {
            int floats;
            float* p = (float*)buffers.GetStreamPointer(VertexStream.Vertices, out floats);
            Vector3 lo = new Vector3(float.PositiveInfinity, float.PositiveInfinity, float.PositiveInfinity);
            Vector3 hi = new Vector3(float.NegativeInfinity, float.NegativeInfinity, float.NegativeInfinity);
            // Free slots keep stale positions of deleted vertices: counted too, which only makes the box larger.
            for (int v = 0; v < vertexSlots && 3 * v + 2 < floats; ++v) Include(ref lo, ref hi, p + 3 * v);
            Bounds b = new Bounds();
            if (lo.x <= hi.x) b.SetMinMax(lo, hi);
            mesh.bounds = b;
        }

        unsafe void GrowBounds()
        {
            int floats;
            float* p = (float*)buffers.GetStreamPointer(VertexStream.Vertices, out floats);
            Bounds b = mesh.bounds;
            Vector3 lo = b.min, hi = b.max;
            for (int i = 0, n = log.VertexRangeCount; i < n; ++i)
            {
                SlotRange r = log.VertexRange(i);
                for (int v = r.First; v < r.First + r.Count; ++v) Include(ref lo, ref hi, p + 3 * v);
            }
            b.SetMinMax(lo, hi);
            mesh.bounds = b;
        }

        static unsafe void Include(ref Vector3 lo, ref Vector3 hi, float* xyz)
        {
            lo.x = Math.Min(lo.x, xyz[0]); lo.y = Math.Min(lo.y, xyz[1]); lo.z = Math.Min(lo.z, xyz[2]);
            hi.x = Math.Max(hi.x, xyz[0]); hi.y = Math.Max(hi.y, xyz[1]); hi.z = Math.Max(hi.z, xyz[2]);
        }

        // A NativeArray over native memory the library owns: valid until the next sync of the buffers.
        unsafe NativeArray<T> Wrap<T>(IntPtr data, int length) where T : struct
        {
            NativeArray<T> array = NativeArrayUnsafeUtility.ConvertExistingDataToNativeArray<T>((void*)data, length,
                                                                                               Allocator.None);
#if ENABLE_UNITY_COLLECTIONS_CHECKS
            NativeArrayUnsafeUtility.SetAtomicSafetyHandle(ref array, safety);
#endif
            return array;
        }

        void ThrowIfDisposed()
        {
            if (disposed) throw new ObjectDisposedException("NativeMeshUploader");
        }

        /// <summary>Frees the 16-bit index scratch and stops the change log (the Mesh and the buffers stay).</summary>

        public void Dispose()
        {
            if (disposed) return;
            disposed = true;
            log.Dispose();
            if (indices16.IsCreated) indices16.Dispose();
            for (int s = 0; s < staging.Length; ++s)
                if (staging[s].IsCreated) staging[s].Dispose();
#if ENABLE_UNITY_COLLECTIONS_CHECKS
            AtomicSafetyHandle.Release(safety);
#endif
        }
    }
}
