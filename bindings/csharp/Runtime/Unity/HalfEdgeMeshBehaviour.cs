// Unity glue: a component that turns its MeshFilter's mesh into a HalfEdgeMesh, lets scripts edit
// it, and uploads only the rewritten ranges to a Unity Mesh with SetVertexBufferData /
// SetIndexBufferData (start and count). Vertex stream 0 holds the positions, then normals, tangents,
// colours, texcoords and lightmap UVs as present, one stream each, or with normals and tangents, and
// texcoords and lightmap UVs, sharing a stream when Unity's four would not do (UnityStreams.cs); one
// submesh per submesh (material) of the
// source, each a contiguous index range that follows the edits. The GPU buffers are allocated at
// the library's capacities, so that growth from edits rarely reallocates them. Uploads follow a
// change log of the buffers (RenderChangeLog), not the result of the component's own sync, so
// syncs, commits and rebuilds that scripts make themselves are uploaded too.
using System;
using UnityEngine;
using UnityEngine.Rendering;

namespace Hedge.Unity
{
    [RequireComponent(typeof(MeshFilter))]
    public sealed class HalfEdgeMeshBehaviour : MonoBehaviour
    {
        /// <summary>Keep Mesh.bounds around the mesh. A full upload (building, growth, Compact()) computes them
        /// over the render vertices; a partial upload only grows them by the vertices it rewrote, so the cost
        /// follows the edit. After vertices move inward the bounds may stay larger than the mesh (never
        /// smaller): call <see cref="TightenBounds"/> when culling needs them tight. Turn it off to set
        /// Mesh.bounds yourself.</summary>
        public bool recalculateBounds = true;

        /// <summary>Keep the source mesh's normals as they are, even where vertices move
        /// (<see cref="NormalSource.Attribute"/>). By default (false) normals follow the geometry: each upload
        /// recomputes the normals about what the edits touched (<see cref="NormalSource.Automatic"/>). Read when
        /// the mesh is built (Awake or <see cref="Build"/>).</summary>
        public bool keepImportedNormals = false;

        const MeshUpdateFlags PartialFlags = MeshUpdateFlags.DontValidateIndices |
                                             MeshUpdateFlags.DontRecalculateBounds;

        Mesh mesh;
        float[] positions;
        // Per Unity stream, its data as uploaded (stream 0 is positions).
        readonly float[][] streamData = new float[UnityStreams.MaxStreams][];
        int[] indices;
        RenderChangeLog pending;
        UnityStreams streams;
        int gpuVertices, indexCount;
        Vector3 boundsMin, boundsMax;

        /// <summary>The editable mesh. Edit it, then let LateUpdate (or <see cref="Upload"/>) upload the change.</summary>
        public HalfEdgeMesh HalfEdgeMesh { get; private set; }
        /// <summary>The render buffers that follow <see cref="HalfEdgeMesh"/> in Unity's conventions.</summary>
        public RenderBuffers Buffers { get; private set; }
        /// <summary>What building from the source mesh welded and repaired.</summary>
        public BuildReport Report { get; private set; }
        /// <summary>The Unity mesh the component renders (it replaces the MeshFilter's shared mesh).</summary>
        public Mesh RenderedMesh { get { return mesh; } }

        void Awake()
        {
            MeshFilter filter = GetComponent<MeshFilter>();
            if (filter.sharedMesh != null) Build(filter.sharedMesh);
        }

        void LateUpdate() { Upload(); }

        void OnDestroy() { Release(); }

        /// <summary>Builds the half-edge mesh from a Unity mesh (positions welded; UV seams, normals, colours,
        /// tangents and lightmap UVs (uv2) kept per corner; one submesh per submesh) and renders it through
        /// this component's MeshFilter.</summary>
        public void Build(Mesh source)
        {
            BuildReport report;  // built before Release(): a source that cannot be built changes nothing
            HalfEdgeMesh built = UnityMeshes.FromMesh(source, EngineImportOptions.Unity, out report);
            Release();
            HalfEdgeMesh = built;
            Report = report;
            RenderOptions renderOptions = RenderOptions.Unity;
            if (keepImportedNormals) renderOptions.Normals = NormalSource.Attribute;
            Buffers = HalfEdgeMesh.CreateRenderBuffers(renderOptions);
            pending = Buffers.CreateChangeLog();
            mesh = new Mesh();
            mesh.name = source.name + " (hedge)";
            mesh.MarkDynamic();
            GetComponent<MeshFilter>().sharedMesh = mesh;
            UploadAll();
        }

        /// <summary>Opens a transaction: edits until <see cref="EndEdit"/> are synced and uploaded once.</summary>
        /// <exception cref="InvalidOperationException">No mesh is built (before Awake or Build, or after
        /// OnDestroy).</exception>
        public void BeginEdit() { Built("BeginEdit").BeginTransaction(); }

        /// <summary>Closes the transaction and uploads what it changed.</summary>
        /// <exception cref="InvalidOperationException">No mesh is built.</exception>
        public void EndEdit()
        {
            Built("EndEdit").CommitTransaction();
            UploadPending();
        }

        // The buffers of the built mesh, for a call that needs one: a clear error instead of a null reference.
        RenderBuffers Built(string call)
        {
            if (Buffers == null)
                throw new InvalidOperationException(call + ": the component has no mesh (it is built in Awake or by " +
                                                    "Build(mesh), and released in OnDestroy)");
            return Buffers;
        }

        /// <summary>Syncs the edits made since the last upload and uploads everything rewritten since then, by
        /// this sync or by any other sync, commit or rebuild of <see cref="Buffers"/> (LateUpdate does this
        /// every frame). Inside a transaction it syncs nothing, and uploads what earlier syncs rewrote.</summary>
        public void Upload()
        {
            if (Buffers == null) return;
            Buffers.Sync();
            UploadPending();
        }

        void UploadPending()
        {
            if (pending.IsEmpty) return;
            BufferCounts counts = Buffers.Counts;
            // Everything changed (a rebuild, Compact(), garbage collection, growth): upload everything, as
            // ranges may not cover what moved.
            if (pending.Everything || counts.VertexSlots > gpuVertices || counts.IndexCount > indices.Length)
            {
                UploadAll();
                return;
            }
            int vertexRanges = pending.VertexRangeCount;
            if (vertexRanges > 0)
                for (int s = 0; s < streams.Count; ++s) UploadStream(s);
            for (int i = 0, n = pending.IndexRangeCount; i < n; ++i)
            {
                SlotRange r = pending.IndexRange(i);
                Buffers.CopyIndexRange(r.First, r.Count, indices);
                mesh.SetIndexBufferData(indices, r.First, r.First, r.Count, PartialFlags);
            }
            indexCount = (int)counts.IndexCount;
            UploadSubmeshes(PartialFlags);
            if (recalculateBounds && vertexRanges > 0) GrowBounds();
            pending.Clear();
        }

        /// <summary>Sets Mesh.bounds to the exact box of the render vertices in use: a pass over all of them.</summary>
        public void TightenBounds()
        {
            if (Buffers == null) return;
            boundsMin = new Vector3(float.PositiveInfinity, float.PositiveInfinity, float.PositiveInfinity);
            boundsMax = new Vector3(float.NegativeInfinity, float.NegativeInfinity, float.NegativeInfinity);
            BufferCounts counts = Buffers.Counts;
            int n = counts.VertexSlots;
            if (counts.Vertices == counts.VertexSlots)
                for (int v = 0; v < n; ++v) Encapsulate(v);
            else  // free slots hold stale positions: only the render vertices of triangles count
                for (int i = 0; i < indexCount; ++i) Encapsulate(indices[i]);
            SetBounds();
        }

        // Grows the bounds by the positions of the pending vertex ranges.
        void GrowBounds()
        {
            Vector3 min = boundsMin, max = boundsMax;
            for (int i = 0, n = pending.VertexRangeCount; i < n; ++i)
                for (int v = pending.VertexRange(i).First, end = v + pending.VertexRange(i).Count; v < end; ++v)
                    Encapsulate(v);
            if (min.x != boundsMin.x || min.y != boundsMin.y || min.z != boundsMin.z || max.x != boundsMax.x ||
                max.y != boundsMax.y || max.z != boundsMax.z)
                SetBounds();
        }

        void Encapsulate(int v)
        {
            float x = positions[3 * v], y = positions[3 * v + 1], z = positions[3 * v + 2];
            if (x < boundsMin.x) boundsMin.x = x;
            if (y < boundsMin.y) boundsMin.y = y;
            if (z < boundsMin.z) boundsMin.z = z;
            if (x > boundsMax.x) boundsMax.x = x;
            if (y > boundsMax.y) boundsMax.y = y;
            if (z > boundsMax.z) boundsMax.z = z;
        }

        void SetBounds()
        {
            var b = new Bounds();
            if (boundsMin.x <= boundsMax.x) b.SetMinMax(boundsMin, boundsMax);
            mesh.bounds = b;
        }

        // Copies (or interleaves) the pending ranges of one Unity stream into its array, then uploads each range.
        void UploadStream(int s)
        {
            int k = streams.Stride(s);
            float[] data = streamData[s];
            for (int i = 0, n = pending.VertexRangeCount; i < n; ++i)
            {
                SlotRange r = pending.VertexRange(i);
                Fill(s, r.First, r.Count);
                mesh.SetVertexBufferData(data, r.First * k, r.First * k, r.Count * k, s, PartialFlags);
            }
        }

        // Render vertices [first, first + count) of Unity stream s from the buffers into its array.
        unsafe void Fill(int s, int first, int count)
        {
            float[] data = streamData[s];
            if (!streams.Staged(s))
            {
                Buffers.CopyVertexRange(streams.Members(s)[0], first, count, data);
                return;
            }
            fixed (float* target = data) streams.Interleave(Buffers, s, target, data.Length, first, count);
        }

        // (Re)allocates the Unity mesh's buffers at the library's capacities and uploads everything.
        void UploadAll()
        {
            pending.Clear();
            BufferCounts counts = Buffers.Counts;
            VertexLayout layout = Buffers.Layout;
            gpuVertices = (int)Math.Max(counts.VertexCapacity, counts.VertexSlots);
            indexCount = (int)counts.IndexCount;
            int gpuIndices = (int)Math.Max(counts.IndexCapacity, counts.IndexCount);
            streams = UnityStreams.Describe(layout);
            for (int s = 0; s < UnityStreams.MaxStreams; ++s)
                streamData[s] = s < streams.Count ? new float[streams.Stride(s) * gpuVertices] : null;
            positions = streamData[0];
            indices = new int[gpuIndices];

            mesh.SetVertexBufferParams(gpuVertices, streams.Attributes);
            int slots = (int)counts.VertexSlots;
            for (int s = 0; s < streams.Count; ++s)
            {
                Fill(s, 0, slots);
                mesh.SetVertexBufferData(streamData[s], 0, 0, slots * streams.Stride(s), s,
                                         MeshUpdateFlags.DontRecalculateBounds);
            }
            Buffers.CopyIndices(indices);
            mesh.SetIndexBufferParams(gpuIndices, IndexFormat.UInt32);
            mesh.SetIndexBufferData(indices, 0, 0, gpuIndices, MeshUpdateFlags.DontRecalculateBounds);
            UploadSubmeshes(MeshUpdateFlags.DontRecalculateBounds);
            if (recalculateBounds) TightenBounds();
        }

        // One SubMeshDescriptor per submesh (material) of the buffers, with the first vertex, vertex count
        // and bounds that DontRecalculateBounds needs given. O(submeshes).
        void UploadSubmeshes(MeshUpdateFlags flags) { UnitySubmeshes.SetSubmeshes(mesh, Buffers, flags); }

        void Release()
        {
            if (pending != null) pending.Dispose();
            pending = null;
            if (Buffers != null) Buffers.Dispose();
            if (HalfEdgeMesh != null) HalfEdgeMesh.Dispose();
            Buffers = null;
            HalfEdgeMesh = null;
            if (mesh != null) Destroy(mesh);
            mesh = null;
        }
    }
}
