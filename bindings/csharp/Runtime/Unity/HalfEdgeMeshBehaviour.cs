// Unity glue: a component that turns its MeshFilter's mesh into a HalfEdgeMesh, lets scripts edit
// it, and uploads only the rewritten ranges to a Unity Mesh with SetVertexBufferData /
// SetIndexBufferData (start and count). One vertex stream per attribute: 0 positions, then normals,
// texcoords and colours on the next streams, as present; one submesh per submesh (material) of the
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
        float[] positions, normals, texcoords, colors;
        int[] indices;
        RenderChangeLog pending;
        int normalStream = -1, texcoordStream = -1, colorStream = -1;
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

        /// <summary>Builds the half-edge mesh from a Unity mesh (positions welded, UV seams, normals and colours
        /// kept per corner) and renders it through this component's MeshFilter.</summary>
        public void Build(Mesh source)
        {
            UnityMeshes.CheckReadable(source);  // before Release(): an unreadable source changes nothing
            Release();
            Vector3[] v = source.vertices;
            Vector3[] n = source.normals;
            Vector2[] uv = source.uv;
            Color[] c = source.colors;
            var p = new float[3 * v.Length];
            for (int i = 0; i < v.Length; ++i) { p[3 * i] = v[i].x; p[3 * i + 1] = v[i].y; p[3 * i + 2] = v[i].z; }
            float[] fn = null, fuv = null, fc = null;
            if (n != null && n.Length == v.Length)
            {
                fn = new float[3 * v.Length];
                for (int i = 0; i < n.Length; ++i) { fn[3 * i] = n[i].x; fn[3 * i + 1] = n[i].y; fn[3 * i + 2] = n[i].z; }
            }
            if (uv != null && uv.Length == v.Length)
            {
                fuv = new float[2 * v.Length];
                for (int i = 0; i < uv.Length; ++i) { fuv[2 * i] = uv[i].x; fuv[2 * i + 1] = uv[i].y; }
            }
            if (c != null && c.Length == v.Length)
            {
                fc = new float[4 * v.Length];
                for (int i = 0; i < c.Length; ++i)
                {
                    fc[4 * i] = c[i].r; fc[4 * i + 1] = c[i].g; fc[4 * i + 2] = c[i].b; fc[4 * i + 3] = c[i].a;
                }
            }
            BuildReport report;
            int[] submeshes;
            int[] triangles = UnitySubmeshes.ReadTriangles(source, out submeshes);
            HalfEdgeMesh = HalfEdgeMesh.FromEngineMesh(p, triangles, fn, fuv, fc, submeshes, EngineImportOptions.Unity,
                                                       out report);
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
        public void BeginEdit() { Buffers.BeginTransaction(); }

        /// <summary>Closes the transaction and uploads what it changed.</summary>
        public void EndEdit()
        {
            Buffers.CommitTransaction();
            UploadPending();
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
            {
                UploadStream(VertexStream.Vertices, positions, 0);
                if (normalStream >= 0) UploadStream(VertexStream.Normals, normals, normalStream);
                if (texcoordStream >= 0) UploadStream(VertexStream.Texcoords, texcoords, texcoordStream);
                if (colorStream >= 0) UploadStream(VertexStream.Colors, colors, colorStream);
            }
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

        // Copies the pending ranges of one stream into its array, then uploads each range.
        void UploadStream(VertexStream stream, float[] data, int unityStream)
        {
            int k = Buffers.Components(stream);
            for (int i = 0, n = pending.VertexRangeCount; i < n; ++i)
            {
                SlotRange r = pending.VertexRange(i);
                Buffers.CopyVertexRange(stream, r.First, r.Count, data);
                mesh.SetVertexBufferData(data, r.First * k, r.First * k, r.Count * k, unityStream, PartialFlags);
            }
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
            VertexAttributeDescriptor[] attributes = UnityStreams.Describe(layout, out normalStream, out texcoordStream,
                                                                           out colorStream);
            positions = new float[3 * gpuVertices];
            normals = normalStream >= 0 ? new float[3 * gpuVertices] : null;
            texcoords = texcoordStream >= 0 ? new float[2 * gpuVertices] : null;
            colors = colorStream >= 0 ? new float[4 * gpuVertices] : null;
            indices = new int[gpuIndices];

            mesh.SetVertexBufferParams(gpuVertices, attributes);
            UploadWhole(VertexStream.Vertices, positions, 0);
            if (normals != null) UploadWhole(VertexStream.Normals, normals, normalStream);
            if (texcoords != null) UploadWhole(VertexStream.Texcoords, texcoords, texcoordStream);
            if (colors != null) UploadWhole(VertexStream.Colors, colors, colorStream);
            Buffers.CopyIndices(indices);
            mesh.SetIndexBufferParams(gpuIndices, IndexFormat.UInt32);
            mesh.SetIndexBufferData(indices, 0, 0, gpuIndices, MeshUpdateFlags.DontRecalculateBounds);
            UploadSubmeshes(MeshUpdateFlags.DontRecalculateBounds);
            if (recalculateBounds) TightenBounds();
        }

        // One SubMeshDescriptor per submesh (material) of the buffers, with the first vertex, vertex count
        // and bounds that DontRecalculateBounds needs given. O(submeshes).
        void UploadSubmeshes(MeshUpdateFlags flags) { UnitySubmeshes.SetSubmeshes(mesh, Buffers, flags); }

        void UploadWhole(VertexStream stream, float[] data, int unityStream)
        {
            int floats = Buffers.CopyStream(stream, data);
            mesh.SetVertexBufferData(data, 0, 0, floats, unityStream, MeshUpdateFlags.DontRecalculateBounds);
        }

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
