// Unity glue: a component that turns its MeshFilter's mesh into a HalfEdgeMesh, lets scripts edit
// it, and uploads only the rewritten ranges to a Unity Mesh with SetVertexBufferData /
// SetIndexBufferData (start and count). One vertex stream per attribute: 0 positions, then normals,
// texcoords and colours on the next streams, as present; one submesh per submesh (material) of the
// source, each a contiguous index range that follows the edits. The GPU buffers are allocated at the library's capacities, so that growth from edits
// rarely reallocates them.
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
        SlotRange[] ranges = new SlotRange[16];
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
            mesh = new Mesh();
            mesh.name = source.name + " (hedge)";
            mesh.MarkDynamic();
            GetComponent<MeshFilter>().sharedMesh = mesh;
            UploadAll();
        }

        /// <summary>Opens a transaction: edits until <see cref="EndEdit"/> are synced and uploaded once.</summary>
        public void BeginEdit() { Buffers.BeginTransaction(); }

        /// <summary>Closes the transaction and uploads what it changed.</summary>
        public void EndEdit() { UploadResult(Buffers.CommitTransaction()); }

        /// <summary>Syncs the edits made since the last upload and uploads the rewritten ranges (LateUpdate
        /// does this every frame). Does nothing inside a transaction.</summary>
        public void Upload()
        {
            if (Buffers != null) UploadResult(Buffers.Sync());
        }

        void UploadResult(SyncResult result)
        {
            if (result.IsEmpty) return;
            BufferCounts counts = Buffers.Counts;
            // A result that says everything changed (a rebuild, Compact(), garbage collection) uploads
            // everything: its ranges may not cover what moved.
            if (result.Resized || result.Full || counts.VertexSlots > gpuVertices || counts.IndexCount > indices.Length)
            {
                UploadAll();
                return;
            }
            if (result.VertexRangeCount > 0)
            {
                int n = LoadRanges(true);
                UploadStream(VertexStream.Vertices, positions, 0, n);
                if (normalStream >= 0) UploadStream(VertexStream.Normals, normals, normalStream, n);
                if (texcoordStream >= 0) UploadStream(VertexStream.Texcoords, texcoords, texcoordStream, n);
                if (colorStream >= 0) UploadStream(VertexStream.Colors, colors, colorStream, n);
            }
            if (result.IndexRangeCount > 0)
            {
                Buffers.CopyDirtyIndices(indices);
                int n = LoadRanges(false);
                for (int i = 0; i < n; ++i)
                    mesh.SetIndexBufferData(indices, (int)ranges[i].First, (int)ranges[i].First, (int)ranges[i].Count,
                                            PartialFlags);
                indexCount = (int)counts.IndexCount;
            }
            UploadSubmeshes(PartialFlags);
            if (recalculateBounds && result.VertexRangeCount > 0) GrowBounds(LoadRanges(true));
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

        // Grows the bounds by the positions of the first rangeCount dirty vertex ranges (in `ranges`).
        void GrowBounds(int rangeCount)
        {
            Vector3 min = boundsMin, max = boundsMax;
            for (int i = 0; i < rangeCount; ++i)
                for (int v = ranges[i].First, end = v + ranges[i].Count; v < end; ++v) Encapsulate(v);
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

        // Copies the dirty ranges of one stream into its array, then uploads each range.
        void UploadStream(VertexStream stream, float[] data, int unityStream, int rangeCount)
        {
            Buffers.CopyDirtyVertices(stream, data);
            int k = Buffers.Components(stream);
            for (int i = 0; i < rangeCount; ++i)
            {
                int first = (int)ranges[i].First * k;
                mesh.SetVertexBufferData(data, first, first, (int)ranges[i].Count * k, unityStream, PartialFlags);
            }
        }

        int LoadRanges(bool vertices)
        {
            int n = vertices ? Buffers.GetDirtyVertexRanges(null) : Buffers.GetDirtyIndexRanges(null);
            if (n > ranges.Length) ranges = new SlotRange[Math.Max(n, 2 * ranges.Length)];
            return vertices ? Buffers.GetDirtyVertexRanges(ranges) : Buffers.GetDirtyIndexRanges(ranges);
        }

        // (Re)allocates the Unity mesh's buffers at the library's capacities and uploads everything.
        void UploadAll()
        {
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
            if (Buffers != null) Buffers.Dispose();
            if (HalfEdgeMesh != null) HalfEdgeMesh.Dispose();
            Buffers = null;
            HalfEdgeMesh = null;
            if (mesh != null) Destroy(mesh);
            mesh = null;
        }
    }
}
