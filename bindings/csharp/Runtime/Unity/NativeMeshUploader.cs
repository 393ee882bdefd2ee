// Zero-copy uploads: the library's own vertex and index buffers, wrapped in NativeArrays
// (NativeArrayUnsafeUtility.ConvertExistingDataToNativeArray over the native pointers), feed
// Mesh.SetVertexBufferData and Mesh.SetIndexBufferData range by range. No managed array holds a
// copy of the mesh, and a partial upload allocates nothing.
//
// Layout: the buffers must use the separate layout of RenderOptions.Unity: vertex stream 0 holds the
// positions, then normals, texcoords and colours each on the next stream, as present (Unity orders
// attributes inside one stream differently from hedge's interleaved vertex, so interleaved buffers
// are refused). One submesh per submesh of the buffers, each a contiguous index range with its first
// vertex, vertex count and bounds (UploadSubmeshes, after every upload). Indices are 16-bit when every render vertex
// slot the GPU buffer can hold fits (at most 65536 slots): those are converted range by range into a
// NativeArray<ushort> the uploader keeps (native memory, not managed); otherwise the 32-bit native
// index buffer is uploaded as it is.
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
        SlotRange[] ranges = new SlotRange[16];
        int normalStream = -1, texcoordStream = -1, colorStream = -1;
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
        }

        public RenderBuffers Buffers { get { return buffers; } }
        public Mesh Mesh { get { return mesh; } }
        /// <summary>The index format of the last full upload: UInt16 while the render vertices fit.</summary>
        public IndexFormat IndexFormat { get { return indexFormat; } }

        /// <summary>Uploads what a sync, commit or rebuild rewrote: the dirty ranges, or everything when the
        /// result says the buffers grew or were rebuilt (Resized, Full: after Compact, garbage collection,
        /// subdivision).</summary>
        /// <returns>True if only ranges were uploaded; false if everything was (or nothing changed).</returns>
        public bool Upload(SyncResult result)
        {
            if (result.IsEmpty) return false;
            BufferCounts counts = buffers.Counts;
            if (result.Resized || result.Full || counts.VertexSlots > gpuVertices || counts.IndexCount > gpuIndices)
            {
                UploadAll();
                return false;
            }
            if (result.VertexRangeCount > 0)
            {
                int n = LoadRanges(true);
                UploadVertexRanges(VertexStream.Vertices, 0, n);
                if (normalStream >= 0) UploadVertexRanges(VertexStream.Normals, normalStream, n);
                if (texcoordStream >= 0) UploadVertexRanges(VertexStream.Texcoords, texcoordStream, n);
                if (colorStream >= 0) UploadVertexRanges(VertexStream.Colors, colorStream, n);
                GrowBounds(n);
            }
            if (result.IndexRangeCount > 0)
            {
                int n = LoadRanges(false);
                UploadIndexRanges(n);
                indexCount = (int)counts.IndexCount;
            }
            UploadSubmeshes(PartialFlags);
            return true;
        }

        /// <summary>(Re)allocates the mesh's buffers at the library's capacities, chooses the index format
        /// and uploads everything.</summary>
        public void UploadAll()
        {
            BufferCounts counts = buffers.Counts;
            VertexLayout layout = buffers.Layout;
            gpuVertices = (int)Math.Max(counts.VertexCapacity, counts.VertexSlots);
            gpuIndices = (int)Math.Max(counts.IndexCapacity, counts.IndexCount);
            indexCount = (int)counts.IndexCount;
            VertexAttributeDescriptor[] attributes = UnityStreams.Describe(layout, out normalStream, out texcoordStream,
                                                                           out colorStream);
            mesh.SetVertexBufferParams(gpuVertices, attributes);
            UploadWholeStream(VertexStream.Vertices, 0);
            if (normalStream >= 0) UploadWholeStream(VertexStream.Normals, normalStream);
            if (texcoordStream >= 0) UploadWholeStream(VertexStream.Texcoords, texcoordStream);
            if (colorStream >= 0) UploadWholeStream(VertexStream.Colors, colorStream);

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

        void UploadWholeStream(VertexStream stream, int unityStream)
        {
            int floats;
            IntPtr p = buffers.GetStreamPointer(stream, out floats);
            if (floats == 0) return;
            mesh.SetVertexBufferData(Wrap<float>(p, floats), 0, 0, floats, unityStream, FullFlags);
        }

        void UploadVertexRanges(VertexStream stream, int unityStream, int rangeCount)
        {
            int floats;
            IntPtr p = buffers.GetStreamPointer(stream, out floats);
            NativeArray<float> data = Wrap<float>(p, floats);
            int k = buffers.Components(stream);
            for (int i = 0; i < rangeCount; ++i)
            {
                int first = (int)ranges[i].First * k;
                mesh.SetVertexBufferData(data, first, first, (int)ranges[i].Count * k, unityStream, PartialFlags);
            }
        }

        void UploadIndexRanges(int rangeCount)
        {
            if (indexFormat == IndexFormat.UInt16)
            {
                for (int i = 0; i < rangeCount; ++i)
                    UploadIndices16((int)ranges[i].First, (int)ranges[i].Count, PartialFlags);
                return;
            }
            int count;
            NativeArray<uint> data = Wrap<uint>(buffers.GetIndexPointer(out count), count);
            for (int i = 0; i < rangeCount; ++i)
                mesh.SetIndexBufferData(data, (int)ranges[i].First, (int)ranges[i].First, (int)ranges[i].Count, PartialFlags);
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

        unsafe void GrowBounds(int rangeCount)
        {
            int floats;
            float* p = (float*)buffers.GetStreamPointer(VertexStream.Vertices, out floats);
            Bounds b = mesh.bounds;
            Vector3 lo = b.min, hi = b.max;
            for (int i = 0; i < rangeCount; ++i)
                for (int v = (int)ranges[i].First; v < (int)(ranges[i].First + ranges[i].Count); ++v)
                    Include(ref lo, ref hi, p + 3 * v);
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

        int LoadRanges(bool vertices)
        {
            int n = vertices ? buffers.GetDirtyVertexRanges(null) : buffers.GetDirtyIndexRanges(null);
            if (n > ranges.Length) ranges = new SlotRange[Math.Max(n, 2 * ranges.Length)];
            return vertices ? buffers.GetDirtyVertexRanges(ranges) : buffers.GetDirtyIndexRanges(ranges);
        }

        /// <summary>Frees the 16-bit index scratch (the Mesh and the buffers stay).</summary>
        public void Dispose()
        {
            if (disposed) return;
            disposed = true;
            if (indices16.IsCreated) indices16.Dispose();
#if ENABLE_UNITY_COLLECTIONS_CHECKS
            AtomicSafetyHandle.Release(safety);
#endif
        }
    }
}
