// P/Invoke declarations of the C ABI (include/hedge/c_api.h), one per C function.
//
// Marshalling is blittable only: handles are IntPtr, element indices uint (or the one-uint handle
// structs), booleans int, buffers float[] / uint[] / int[] / arrays of sequential structs, paths a
// NUL-terminated UTF-8 byte[]. Nothing is converted or copied by the marshaller, so a call costs
// no managed allocation.
using System;
using System.Runtime.InteropServices;

namespace Hedge
{
    internal static partial class Native
    {
        // "hedge_c" is resolved to libhedge_c.so (Linux), hedge_c.dll (Windows) and
        // libhedge_c.dylib (macOS) by Mono, .NET and Unity. Platforms that link native code into
        // the player statically (iOS, WebGL) name it "__Internal": define HEDGE_INTERNAL_LIB to build
        // for a static library elsewhere.
#if HEDGE_INTERNAL_LIB || UNITY_IOS || UNITY_WEBGL
        internal const string Library = "__Internal";
#else
        internal const string Library = "hedge_c";
#endif

        // ---- Status, errors, version ----
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern IntPtr hedge_last_error();
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern IntPtr hedge_last_refusal();
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern IntPtr hedge_status_string(int code);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_version(out int major, out int minor, out int patch);

        // ---- Creation and destruction ----
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_build_options_default(out BuildOptions options);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_mesh_create(float[] positions, uint vertexCount, uint[] indices,
            uint indexCount, uint[] faceSizes, uint faceCount, ref BuildOptions options, out BuildReport report,
            [Out] Vertex[] vertexMap, [Out] Face[] faceMap, out IntPtr mesh);
        // The same function with int[] indices and face sizes (the binding's public type; same bits).
        [DllImport(Library, EntryPoint = "hedge_mesh_create", CallingConvention = CallingConvention.Cdecl,
            ExactSpelling = true)]
        internal static extern int hedge_mesh_create_int(float[] positions, uint vertexCount, int[] indices,
            uint indexCount, int[] faceSizes, uint faceCount, ref BuildOptions options, out BuildReport report,
            [Out] Vertex[] vertexMap, [Out] Face[] faceMap, out IntPtr mesh);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_mesh_destroy(IntPtr mesh);

        // ---- Counts and positions ----
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_mesh_counts(IntPtr mesh, out MeshCounts counts);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_vertex_position(IntPtr mesh, uint vertex, out Vec3 xyz);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_set_vertex_position(IntPtr mesh, uint vertex, float x, float y, float z);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_mesh_copy_positions(IntPtr mesh, [Out] float[] buffer, ulong capacity,
            out ulong count);

        // ---- Reordering ----
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_mesh_reorder(IntPtr mesh, int ordering, uint cacheSize, [Out] Vertex[] vertexMap,
            uint vertexCapacity, [Out] HalfEdge[] halfEdgeMap, uint halfEdgeCapacity, [Out] Edge[] edgeMap, uint edgeCapacity,
            [Out] Face[] faceMap, uint faceCapacity);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_mesh_cache_miss_ratio(IntPtr mesh, uint cacheSize, out double ratio);

        // ---- Subdivision ----
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_mesh_subdivide(IntPtr mesh, int scheme, int steps);

        // ---- Decimation ----
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_decimate_options_default(out DecimateOptions options);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_mesh_decimate(IntPtr mesh, ref DecimateOptions options, out DecimateResult result);

        // ---- Fracture ----
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_fracture_options_default(int preset, out FractureOptions options);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_mesh_fracture(IntPtr mesh, float x, float y, float z, ref FractureOptions options,
                                                       [Out] NativeFractureShard[] shards, uint capacity, out uint count);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_fracture_options_at_radius(ref FractureOptions options, double radius);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_mesh_copy_face_submeshes(IntPtr mesh, [Out] int[] buffer, ulong capacity,
                                                                  out ulong count);

        // ---- Smoothing ----
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_smooth_options_default(out SmoothOptions options);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_mesh_smooth(IntPtr mesh, ref SmoothOptions options, byte[] mask, uint maskCount);

        // ---- Geometry and normals ----
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_mesh_geometry(IntPtr mesh, out MeshGeometry geometry);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_face_normal(IntPtr mesh, uint face, out Vec3 xyz);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_face_area(IntPtr mesh, uint face, out double area);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_mesh_compute_vertex_normals(IntPtr mesh, int weighting);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_mesh_compute_corner_normals(IntPtr mesh, double creaseDegrees, int weighting);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_mesh_copy_vertex_normals(IntPtr mesh, [Out] float[] buffer, ulong capacity,
            out ulong count);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_mesh_copy_corner_normals(IntPtr mesh, [Out] float[] buffer, ulong capacity,
            out ulong count);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_mesh_hausdorff(IntPtr a, IntPtr b, ulong samples, ulong seed, out double distance,
            out double mean);

        // ---- Adjacency ----
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_halfedge_twin(IntPtr mesh, uint halfedge, out uint result);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_halfedge_next(IntPtr mesh, uint halfedge, out uint result);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_halfedge_prev(IntPtr mesh, uint halfedge, out uint result);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_halfedge_to_vertex(IntPtr mesh, uint halfedge, out uint result);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_halfedge_from_vertex(IntPtr mesh, uint halfedge, out uint result);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_halfedge_face(IntPtr mesh, uint halfedge, out uint result);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_halfedge_edge(IntPtr mesh, uint halfedge, out uint result);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_vertex_halfedge(IntPtr mesh, uint vertex, out uint result);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_face_halfedge(IntPtr mesh, uint face, out uint result);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_edge_halfedge(IntPtr mesh, uint edge, uint i, out uint result);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_vertex_is_boundary(IntPtr mesh, uint vertex, out int result);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_halfedge_is_boundary(IntPtr mesh, uint halfedge, out int result);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_edge_is_boundary(IntPtr mesh, uint edge, out int result);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_face_is_boundary(IntPtr mesh, uint face, out int result);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_vertex_valence(IntPtr mesh, uint vertex, out uint result);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_face_valence(IntPtr mesh, uint face, out uint result);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_mesh_find_halfedge(IntPtr mesh, uint from, uint to, out uint result);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_vertex_is_deleted(IntPtr mesh, uint vertex, out int result);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_halfedge_is_deleted(IntPtr mesh, uint halfedge, out int result);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_edge_is_deleted(IntPtr mesh, uint edge, out int result);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_face_is_deleted(IntPtr mesh, uint face, out int result);

        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_vertex_halfedges(IntPtr mesh, uint vertex, [Out] HalfEdge[] buffer,
            uint capacity, out uint count);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_vertex_vertices(IntPtr mesh, uint vertex, [Out] Vertex[] buffer,
            uint capacity, out uint count);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_vertex_faces(IntPtr mesh, uint vertex, [Out] Face[] buffer,
            uint capacity, out uint count);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_face_vertices(IntPtr mesh, uint face, [Out] Vertex[] buffer,
            uint capacity, out uint count);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_face_halfedges(IntPtr mesh, uint face, [Out] HalfEdge[] buffer,
            uint capacity, out uint count);

        // ---- Local operations ----
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_can_split_edge(IntPtr mesh, uint edge, out int ok);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_split_edge(IntPtr mesh, uint edge, float x, float y, float z,
            out uint vertex);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_can_collapse(IntPtr mesh, uint halfedge, out int ok);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_collapse(IntPtr mesh, uint halfedge, out uint vertex);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_can_flip(IntPtr mesh, uint edge, out int ok);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_flip(IntPtr mesh, uint edge);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_can_split_face(IntPtr mesh, uint face, out int ok);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_split_face(IntPtr mesh, uint face, float x, float y, float z,
            out uint vertex);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_can_cut_face(IntPtr mesh, uint halfedge0, uint halfedge1,
            out int ok);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_cut_face(IntPtr mesh, uint halfedge0, uint halfedge1,
            out uint halfedge);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_mesh_split_all_faces(IntPtr mesh, [Out] Vertex[] buffer, uint capacity,
            out uint count);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_can_add_face(IntPtr mesh, [In] Vertex[] vertices, uint count, out int ok);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_add_face(IntPtr mesh, [In] Vertex[] vertices, uint count, out uint face);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_can_remove_face(IntPtr mesh, uint face, out int ok);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_remove_face(IntPtr mesh, uint face);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_can_remove_vertex(IntPtr mesh, uint vertex, out int ok);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_remove_vertex(IntPtr mesh, uint vertex);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_can_fill_hole(IntPtr mesh, uint halfedge, out int ok);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_fill_hole(IntPtr mesh, uint halfedge, [Out] Face[] buffer, uint capacity,
            out uint count);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_detach_faces(IntPtr mesh, [In] Face[] faces, uint count,
            [Out] Vertex[] vertexOrigin, uint originCapacity, out uint originCount, out IntPtr newMesh);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_mesh_garbage_collection(IntPtr mesh, [Out] Vertex[] vertexMap,
            uint vertexCapacity, [Out] HalfEdge[] halfedgeMap, uint halfedgeCapacity, [Out] Edge[] edgeMap,
            uint edgeCapacity, [Out] Face[] faceMap, uint faceCapacity);

        // ---- Files ----
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_mesh_read([In] byte[] path, ref BuildOptions options,
            out BuildReport report, out IntPtr mesh);
        // The same function with options NULL: the format's own defaults (exact welding for STL).
        [DllImport(Library, EntryPoint = "hedge_mesh_read", CallingConvention = CallingConvention.Cdecl,
            ExactSpelling = true)]
        internal static extern int hedge_mesh_read_defaults([In] byte[] path, IntPtr optionsNull,
            out BuildReport report, out IntPtr mesh);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_read_options_default(out ReadOptions options);
        // hedge_mesh_read_with and hedge_mesh_read_memory with build options NULL (the format's defaults).
        [DllImport(Library, EntryPoint = "hedge_mesh_read_with", CallingConvention = CallingConvention.Cdecl,
            ExactSpelling = true)]
        internal static extern int hedge_mesh_read_with_defaults([In] byte[] path, IntPtr optionsNull,
            ref ReadOptions readOptions, out BuildReport report, out IntPtr mesh);
        [DllImport(Library, EntryPoint = "hedge_mesh_read_memory", CallingConvention = CallingConvention.Cdecl,
            ExactSpelling = true)]
        internal static extern int hedge_mesh_read_memory_defaults([In] byte[] bytes, ulong size, [In] byte[] name,
            IntPtr optionsNull, ref ReadOptions readOptions, out BuildReport report, out IntPtr mesh);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_mesh_write(IntPtr mesh, [In] byte[] path, int binary, int precision);

        // ---- Validation ----
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_mesh_validate(IntPtr mesh, out uint problemCount);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_mesh_validation_problem(IntPtr mesh, uint index, [Out] byte[] buffer,
            uint capacity, out uint size);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_mesh_validation_report(IntPtr mesh, [Out] byte[] buffer, uint capacity,
            out uint size);

        // ---- Render buffers ----
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_render_buffers_options_default(out RenderOptions options);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_render_buffers_create(IntPtr mesh, ref RenderOptions options, out IntPtr render);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_render_buffers_destroy(IntPtr render);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_render_buffers_sync(IntPtr render, out SyncResult result);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_render_buffers_begin(IntPtr render);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_render_buffers_commit(IntPtr render, out SyncResult result);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_render_buffers_rebuild(IntPtr render, out SyncResult result);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_render_buffers_last_result(IntPtr render, out SyncResult result);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_render_buffers_dirty_vertex_ranges(IntPtr render, [Out] SlotRange[] buffer,
            uint capacity, out uint count);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_render_buffers_dirty_index_ranges(IntPtr render, [Out] SlotRange[] buffer,
            uint capacity, out uint count);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_render_buffers_compact(IntPtr render, [Out] uint[] vertexMap, uint vertexCapacity,
            out uint vertexCount, [Out] uint[] triangleMap, uint triangleCapacity, out uint triangleCount);
        // The same function with int[] maps (freed slots: -1, the same bits as 0xFFFFFFFF).
        [DllImport(Library, EntryPoint = "hedge_render_buffers_compact", CallingConvention = CallingConvention.Cdecl,
            ExactSpelling = true)]
        internal static extern int hedge_render_buffers_compact_int(IntPtr render, [Out] int[] vertexMap, uint vertexCapacity,
            out uint vertexCount, [Out] int[] triangleMap, uint triangleCapacity, out uint triangleCount);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_render_buffers_counts(IntPtr render, out BufferCounts counts);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_render_buffers_layout(IntPtr render, out VertexLayout layout);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_render_buffers_vertex_data(IntPtr render, int stream, out IntPtr data,
            out ulong count);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_render_buffers_copy_vertex_data(IntPtr render, int stream, [Out] float[] buffer,
            ulong capacity, out ulong count);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_render_buffers_index_data(IntPtr render, out IntPtr data, out ulong count);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_render_buffers_copy_index_data(IntPtr render, [Out] uint[] buffer, ulong capacity,
            out ulong count);
        // The same function into an int[] (Unity's Mesh.triangles type): same bits for indices < 2^31.
        [DllImport(Library, EntryPoint = "hedge_render_buffers_copy_index_data", CallingConvention = CallingConvention.Cdecl,
            ExactSpelling = true)]
        internal static extern int hedge_render_buffers_copy_index_data_int(IntPtr render, [Out] int[] buffer,
            ulong capacity, out ulong count);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_render_buffers_vertex_source(IntPtr render, [Out] Vertex[] buffer, uint capacity,
            out uint count);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_render_buffers_corner_vertex(IntPtr render, uint halfedge, out uint renderVertex);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_render_buffers_face_triangles(IntPtr render, uint face, out uint first,
            out uint count);

        // ---- Engine meshes ----
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_engine_import_options_default(out EngineImportOptions options);
        [DllImport(Library, CallingConvention = CallingConvention.Cdecl, ExactSpelling = true)]
        internal static extern int hedge_mesh_from_engine_mesh(float[] positions, uint vertexCount, uint[] indices,
            uint indexCount, float[] normals, float[] texcoords, float[] colors, ref EngineImportOptions options,
            out BuildReport report, out IntPtr mesh);
        // The same function with int[] indices (Unity's Mesh.triangles).
        [DllImport(Library, EntryPoint = "hedge_mesh_from_engine_mesh", CallingConvention = CallingConvention.Cdecl,
            ExactSpelling = true)]
        internal static extern int hedge_mesh_from_engine_mesh_int(float[] positions, uint vertexCount, int[] indices,
            uint indexCount, float[] normals, float[] texcoords, float[] colors, ref EngineImportOptions options,
            out BuildReport report, out IntPtr mesh);
    }
}
