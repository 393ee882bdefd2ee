/* The C ABI's render buffers (src/capi/render.cpp). */
#include "capi_test.h"

/* ---------------------------------------------------------------------------------------------- */
/* Render buffers                                                                                 */
/* ---------------------------------------------------------------------------------------------- */

/* An engine quad of two triangles: 6 engine vertices, 4 positions, a UV seam at corner (1, 1). */
static const float kQuadPositions[] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 0, 0, 1, 1, 0, 0, 1, 0};
static const float kQuadTexcoords[] = {0, 0, 1, 0, 1, 1, 0, 0, 0.5f, 0.5f, 0, 1};
static const float kQuadColors[] = {1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1};
static const uint32_t kQuadTriangles[] = {0, 1, 2, 3, 4, 5};

/* Every live triangle of the index buffer is one of the mesh's faces (same corners, same order up
 * to rotation), checked through the render vertex source map. */
static void check_triangles_match(const hedge_mesh* mesh, const hedge_render_buffers* render) {
  hedge_counts mc = counts_of(mesh);
  hedge_buffer_counts rc;
  CHECK_OK(hedge_render_buffers_counts(render, &rc));
  const uint32_t* indices = NULL;
  uint64_t n_indices = 0;
  CHECK_OK(hedge_render_buffers_index_data(render, &indices, &n_indices));
  CHECK(n_indices == rc.index_count);
  uint32_t* source = malloc(sizeof(uint32_t) * (rc.vertex_slots + 1));
  uint32_t n_source = 0;
  CHECK(source != NULL);
  CHECK_OK(hedge_render_buffers_vertex_source(render, source, rc.vertex_slots + 1, &n_source));
  CHECK(n_source == rc.vertex_slots);
  uint32_t live_triangles = 0;
  for (uint32_t f = 0; f < mc.face_slots; ++f) {
    int32_t deleted = 1;
    CHECK_OK(hedge_face_is_deleted(mesh, f, &deleted));
    if (deleted) continue;
    uint32_t first = INVALID, count = 0, corners[8], loop[8], n = 0;
    CHECK_OK(hedge_render_buffers_face_triangles(render, f, &first, &count));
    CHECK(count == 1);
    ++live_triangles;
    CHECK_OK(hedge_face_vertices(mesh, f, corners, 8, &n));
    CHECK_OK(hedge_face_halfedges(mesh, f, loop, 8, &n));
    const uint32_t* t = indices + 3 * first;
    uint32_t mapped[3];
    for (int k = 0; k < 3; ++k) {
      CHECK(t[k] < rc.vertex_slots);
      mapped[k] = source[t[k]];
    }
    CHECK(face_is(mesh, f, mapped, 3));
    /* The corner render vertices are those of the triangle. */
    for (uint32_t k = 0; k < 3; ++k) {
      uint32_t rv = INVALID;
      CHECK_OK(hedge_render_buffers_corner_vertex(render, loop[k], &rv));
      CHECK(rv == t[0] || rv == t[1] || rv == t[2]);
      CHECK(source[rv] == corners[k]);
    }
  }
  CHECK(live_triangles == rc.triangles);
  free(source);
}

void test_render(void) {
  hedge_engine_import_options import;
  memset(&import, 0xFF, sizeof import);
  CHECK_OK(hedge_engine_import_options_default(&import));
  CHECK(import.weld == HEDGE_WELD_EXACT && import.policy == HEDGE_POLICY_REPAIR &&
        import.weld_epsilon == 1e-6);
  CHECK(import.winding == HEDGE_WINDING_CCW && import.flip_x == 0);

  hedge_mesh* mesh = NULL;
  hedge_build_report report;
  CHECK_OK(hedge_mesh_from_engine_mesh(kQuadPositions, 6, kQuadTriangles, 6, NULL, kQuadTexcoords,
                                       kQuadColors, &import, &report, &mesh));
  CHECK(report.welded_vertices == 2);
  hedge_counts c = counts_of(mesh);
  CHECK(c.vertices == 4 && c.faces == 2 && c.edges == 5);
  CHECK_VALID(mesh);

  /* Engine input errors. */
  {
    hedge_mesh* bad = NULL;
    const uint32_t out_of_range[] = {0, 1, 6};
    CHECK_STATUS(
        hedge_mesh_from_engine_mesh(kQuadPositions, 6, out_of_range, 3, NULL, NULL, NULL, NULL, NULL, &bad),
        HEDGE_ERROR_INVALID_ARGUMENT);
    CHECK_STATUS(
        hedge_mesh_from_engine_mesh(kQuadPositions, 6, kQuadTriangles, 5, NULL, NULL, NULL, NULL, NULL, &bad),
        HEDGE_ERROR_INVALID_ARGUMENT);
    float nan_uv[12];
    memcpy(nan_uv, kQuadTexcoords, sizeof nan_uv);
    nan_uv[3] = NAN;
    CHECK_STATUS(hedge_mesh_from_engine_mesh(kQuadPositions, 6, kQuadTriangles, 6, NULL, nan_uv, NULL, NULL,
                                             NULL, &bad),
                 HEDGE_ERROR_INVALID_ARGUMENT);
    CHECK_STATUS(hedge_mesh_from_engine_mesh(NULL, 6, kQuadTriangles, 6, NULL, NULL, NULL, NULL, NULL, &bad),
                 HEDGE_ERROR_INVALID_ARGUMENT);
    CHECK(bad == NULL);
  }

  hedge_render_buffers_options options;
  memset(&options, 0xFF, sizeof options);
  CHECK_OK(hedge_render_buffers_options_default(&options));
  CHECK(options.normals == HEDGE_NORMALS_AUTOMATIC && options.texcoords == 1 && options.colors == 1);
  CHECK(options.interleaved == 1 && options.winding == HEDGE_WINDING_CCW && options.flip_x == 0);
  hedge_render_buffers* render = NULL;
  {
    hedge_render_buffers_options wrong = options;
    wrong.normals = 9;
    CHECK_STATUS(hedge_render_buffers_create(mesh, &wrong, &render), HEDGE_ERROR_INVALID_ARGUMENT);
    CHECK(render == NULL);
    CHECK_STATUS(hedge_render_buffers_create(NULL, &options, &render), HEDGE_ERROR_BAD_HANDLE);
  }
  CHECK_OK(hedge_render_buffers_create(mesh, &options, &render));

  /* Layout: position, computed normal, texcoord, colour. */
  hedge_vertex_layout layout;
  CHECK_OK(hedge_render_buffers_layout(render, &layout));
  CHECK(layout.interleaved == 1 && layout.stride == 12);
  CHECK(layout.position == 0 && layout.normal == 3 && layout.texcoord == 6 && layout.color == 8);

  hedge_buffer_counts rc;
  CHECK_OK(hedge_render_buffers_counts(render, &rc));
  CHECK(rc.vertex_slots == 5 && rc.vertices == 5 && rc.seam_splits == 1);
  CHECK(rc.free_triangle_slots == 0);
  CHECK(rc.vertex_capacity >= rc.vertex_slots && rc.index_capacity >= rc.index_count);
  CHECK(rc.index_count == 6 && rc.triangles == 2 && rc.free_triangle_slots == 0);
  CHECK(rc.buffer_bytes == (uint64_t)rc.vertex_slots * layout.stride * 4 + (uint64_t)rc.index_count * 4);

  /* The first build is a full one. */
  hedge_sync_result result;
  CHECK_OK(hedge_render_buffers_last_result(render, &result));
  CHECK(result.full == 1 && result.resized == 1);

  /* Vertex data: pointer and copy agree; every engine (position, texcoord) pair is present. */
  const float* data = NULL;
  uint64_t n_data = 0;
  CHECK_OK(hedge_render_buffers_vertex_data(render, HEDGE_STREAM_VERTICES, &data, &n_data));
  CHECK(data != NULL && n_data == (uint64_t)rc.vertex_slots * layout.stride);
  float copied[256];
  uint64_t n_copied = 0;
  CHECK_STATUS(
      hedge_render_buffers_copy_vertex_data(render, HEDGE_STREAM_VERTICES, copied, n_data - 1, &n_copied),
      HEDGE_ERROR_BUFFER_TOO_SMALL);
  CHECK(n_copied == n_data);
  CHECK_OK(hedge_render_buffers_copy_vertex_data(render, HEDGE_STREAM_VERTICES, copied, 256, &n_copied));
  CHECK(n_copied == n_data && memcmp(copied, data, sizeof(float) * n_data) == 0);
  for (uint32_t i = 0; i < 6; ++i) {
    int found = 0;
    for (uint32_t r = 0; r < rc.vertex_slots; ++r) {
      const float* v = data + r * layout.stride;
      if (v[0] == kQuadPositions[3 * i] && v[1] == kQuadPositions[3 * i + 1] &&
          v[2] == kQuadPositions[3 * i + 2] && v[6] == kQuadTexcoords[2 * i] &&
          v[7] == kQuadTexcoords[2 * i + 1] && v[8] == 1 && v[9] == 0 && v[10] == 0 && v[11] == 1)
        found = 1;
    }
    CHECK(found);
  }
  for (uint32_t r = 0; r < rc.vertex_slots; ++r) { /* the flat quad's computed normals are +z */
    const float* v = data + r * layout.stride;
    CHECK(fabsf(v[3]) < 1e-6f && fabsf(v[4]) < 1e-6f && fabsf(v[5] - 1) < 1e-6f);
  }
  /* Separate streams are empty in an interleaved layout. */
  CHECK_OK(hedge_render_buffers_vertex_data(render, HEDGE_STREAM_NORMALS, &data, &n_data));
  CHECK(data == NULL && n_data == 0);
  CHECK_STATUS(hedge_render_buffers_vertex_data(render, 7, &data, &n_data), HEDGE_ERROR_INVALID_ARGUMENT);

  /* Index data. */
  const uint32_t* indices = NULL;
  uint64_t n_indices = 0;
  uint32_t index_copy[64];
  CHECK_OK(hedge_render_buffers_index_data(render, &indices, &n_indices));
  CHECK(n_indices == 6);
  CHECK_STATUS(hedge_render_buffers_copy_index_data(render, index_copy, 5, &n_indices),
               HEDGE_ERROR_BUFFER_TOO_SMALL);
  CHECK(n_indices == 6);
  CHECK_OK(hedge_render_buffers_copy_index_data(render, index_copy, 64, &n_indices));
  CHECK(n_indices == 6 && memcmp(index_copy, indices, 6 * sizeof(uint32_t)) == 0);
  check_triangles_match(mesh, render);

  /* Move a vertex: the sync rewrites its render vertices only. */
  uint32_t source[16], n_source = 0;
  CHECK_OK(hedge_render_buffers_vertex_source(render, source, 16, &n_source));
  CHECK(n_source == 5);
  CHECK_STATUS(hedge_render_buffers_vertex_source(render, source, 4, &n_source),
               HEDGE_ERROR_BUFFER_TOO_SMALL);
  CHECK_OK(hedge_set_vertex_position(mesh, 1, 1, 0, 0.5f));
  CHECK_OK(hedge_render_buffers_sync(render, &result));
  CHECK(result.full == 0 && result.resized == 0 && result.vertex_range_count >= 1);
  CHECK(result.vertex_bytes > 0);
  {
    hedge_range ranges[16];
    uint32_t n_ranges = 0;
    CHECK_STATUS(hedge_render_buffers_dirty_vertex_ranges(render, ranges, 0, &n_ranges),
                 HEDGE_ERROR_BUFFER_TOO_SMALL);
    CHECK(n_ranges == result.vertex_range_count);
    CHECK_OK(hedge_render_buffers_dirty_vertex_ranges(render, ranges, 16, &n_ranges));
    CHECK(n_ranges == result.vertex_range_count);
    int covered = 0;
    for (uint32_t r = 0; r < n_source; ++r) {
      if (source[r] != 1) continue;
      for (uint32_t i = 0; i < n_ranges; ++i)
        if (r >= ranges[i].first && r < ranges[i].first + ranges[i].count) covered = 1;
    }
    CHECK(covered);
    CHECK_OK(hedge_render_buffers_dirty_index_ranges(render, ranges, 16, &n_ranges));
    CHECK(n_ranges == result.index_range_count);
    CHECK_OK(hedge_render_buffers_vertex_data(render, HEDGE_STREAM_VERTICES, &data, &n_data));
    for (uint32_t r = 0; r < n_source; ++r)
      if (source[r] == 1) CHECK(data[r * layout.stride + 2] == 0.5f);
  }
  /* Nothing changed since: an empty sync. */
  CHECK_OK(hedge_render_buffers_sync(render, &result));
  CHECK(result.vertex_range_count == 0 && result.index_range_count == 0 && result.full == 0);

  /* A transaction: the edits appear at commit. */
  CHECK_STATUS(hedge_render_buffers_commit(render, &result), HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK_OK(hedge_render_buffers_begin(render));
  uint32_t diagonal = 0, mid = 0;
  CHECK_OK(hedge_mesh_find_halfedge(mesh, 0, 2, &diagonal));
  CHECK(diagonal != INVALID);
  CHECK_OK(hedge_split_edge(mesh, diagonal >> 1, 0.5f, 0.5f, 0, &mid));
  CHECK_OK(hedge_render_buffers_sync(render, &result)); /* inside the transaction: nothing */
  CHECK(result.vertex_range_count == 0 && result.index_range_count == 0);
  CHECK_OK(hedge_render_buffers_commit(render, &result));
  CHECK(result.faces_synced >= 4 && result.index_range_count >= 1);
  CHECK_OK(hedge_render_buffers_counts(render, &rc));
  CHECK(rc.triangles == 4);
  CHECK_VALID(mesh);
  check_triangles_match(mesh, render);

  /* Remove a face: its triangle becomes a hole until compact(). */
  CHECK_OK(hedge_remove_face(mesh, 0));
  CHECK_OK(hedge_render_buffers_sync(render, NULL));
  CHECK_OK(hedge_render_buffers_counts(render, &rc));
  CHECK(rc.triangles == 3 && rc.index_count == 12);
  CHECK_VALID(mesh);
  check_triangles_match(mesh, render);
  {
    uint32_t vmap[32], tmap[32], nv = 0, nt = 0;
    CHECK_STATUS(hedge_render_buffers_compact(render, vmap, 32, &nv, tmap, 1, &nt),
                 HEDGE_ERROR_BUFFER_TOO_SMALL);
    CHECK(nv == rc.vertex_slots && nt == 4);
    CHECK_OK(hedge_render_buffers_compact(render, vmap, 32, &nv, tmap, 32, &nt));
    uint32_t freed = 0;
    for (uint32_t t = 0; t < nt; ++t) freed += tmap[t] == INVALID;
    CHECK(freed == 1);
    hedge_buffer_counts after;
    CHECK_OK(hedge_render_buffers_counts(render, &after));
    CHECK(after.index_count == 9 && after.triangles == 3 && after.vertex_slots == after.vertices);
    check_triangles_match(mesh, render);
    CHECK_OK(hedge_render_buffers_compact(render, NULL, 0, NULL, NULL, 0, NULL));
  }

  /* Rebuild and garbage collection: full syncs. */
  CHECK_OK(hedge_render_buffers_rebuild(render, &result));
  CHECK(result.full == 1);
  CHECK_OK(hedge_mesh_garbage_collection(mesh, NULL, 0, NULL, 0, NULL, 0, NULL, 0));
  CHECK_OK(hedge_render_buffers_sync(render, &result));
  CHECK(result.full == 1);
  CHECK_VALID(mesh);
  check_triangles_match(mesh, render);
  {
    uint32_t rv = 0, first = 0, count = 0;
    CHECK_STATUS(hedge_render_buffers_corner_vertex(render, 999, &rv), HEDGE_ERROR_BAD_HANDLE);
    CHECK_STATUS(hedge_render_buffers_face_triangles(render, 999, &first, &count), HEDGE_ERROR_BAD_HANDLE);
  }

  /* A second render object: separate streams, x flipped, clockwise. */
  hedge_render_buffers_options separate = options;
  separate.interleaved = 0;
  separate.flip_x = 1;
  separate.winding = HEDGE_WINDING_CW;
  separate.normals = HEDGE_NORMALS_COMPUTED;
  hedge_render_buffers* render2 = NULL;
  CHECK_OK(hedge_render_buffers_create(mesh, &separate, &render2));
  CHECK_OK(hedge_render_buffers_layout(render2, &layout));
  CHECK(layout.interleaved == 0 && layout.position == 0 && layout.normal == 0 && layout.stride == 12);
  hedge_buffer_counts rc2;
  CHECK_OK(hedge_render_buffers_counts(render2, &rc2));
  const float* positions = NULL;
  const float* normals = NULL;
  uint64_t n_positions = 0, n_normals = 0;
  CHECK_OK(hedge_render_buffers_vertex_data(render2, HEDGE_STREAM_VERTICES, &positions, &n_positions));
  CHECK_OK(hedge_render_buffers_vertex_data(render2, HEDGE_STREAM_NORMALS, &normals, &n_normals));
  CHECK(n_positions == 3 * (uint64_t)rc2.vertex_slots && n_normals == 3 * (uint64_t)rc2.vertex_slots);
  CHECK_OK(hedge_render_buffers_vertex_source(render2, source, 16, &n_source));
  for (uint32_t r = 0; r < n_source; ++r) {
    float p[3];
    get_position(mesh, source[r], p);
    CHECK(positions[3 * r] == -p[0] && positions[3 * r + 1] == p[1] && positions[3 * r + 2] == p[2]);
  }
  float texcoords[64], colors[128];
  uint64_t n_tex = 0, n_col = 0;
  CHECK_OK(hedge_render_buffers_copy_vertex_data(render2, HEDGE_STREAM_TEXCOORDS, texcoords, 64, &n_tex));
  CHECK_OK(hedge_render_buffers_copy_vertex_data(render2, HEDGE_STREAM_COLORS, colors, 128, &n_col));
  CHECK(n_tex == 2 * (uint64_t)rc2.vertex_slots && n_col == 4 * (uint64_t)rc2.vertex_slots);
  CHECK(colors[0] == 1 && colors[1] == 0 && colors[3] == 1);

  /* Destroying the mesh destroys its render objects: their handles are then bad. */
  CHECK_OK(hedge_render_buffers_destroy(render2));
  CHECK_OK(hedge_mesh_destroy(mesh));
  CHECK_STATUS(hedge_render_buffers_sync(render, &result), HEDGE_ERROR_BAD_HANDLE);
  CHECK_STATUS(hedge_render_buffers_counts(render, &rc), HEDGE_ERROR_BAD_HANDLE);
  CHECK_STATUS(hedge_render_buffers_vertex_data(render, HEDGE_STREAM_VERTICES, &data, &n_data),
               HEDGE_ERROR_BAD_HANDLE);
  CHECK_STATUS(hedge_render_buffers_begin(render), HEDGE_ERROR_BAD_HANDLE);
  CHECK_STATUS(hedge_render_buffers_destroy(render), HEDGE_ERROR_BAD_HANDLE);
  CHECK_STATUS(hedge_render_buffers_destroy(render2), HEDGE_ERROR_BAD_HANDLE);
}

/* A render object left open inside a transaction, then its mesh destroyed: no crash, no leak. */
void test_render_lifetime(void) {
  hedge_mesh* mesh = make_mesh(kPyramidPositions, 5, kPyramidTriangles, 12, NULL, 0);
  hedge_render_buffers* a = NULL;
  hedge_render_buffers* b = NULL;
  CHECK_OK(hedge_render_buffers_create(mesh, NULL, &a));
  CHECK_OK(hedge_render_buffers_create(mesh, NULL, &b));
  CHECK_OK(hedge_render_buffers_begin(a));
  uint32_t v = 0;
  CHECK_OK(hedge_split_face(mesh, 0, 0.5f, 0.25f, 0.3f, &v));
  CHECK_OK(hedge_render_buffers_sync(b, NULL));
  hedge_buffer_counts rc;
  CHECK_OK(hedge_render_buffers_counts(b, &rc));
  CHECK(rc.triangles == 6);
  CHECK_OK(hedge_mesh_destroy(mesh));
  CHECK_STATUS(hedge_render_buffers_commit(a, NULL), HEDGE_ERROR_BAD_HANDLE);
  CHECK_STATUS(hedge_render_buffers_sync(b, NULL), HEDGE_ERROR_BAD_HANDLE);
  CHECK_STATUS(hedge_split_face(mesh, 0, 0.5f, 0.25f, 0.3f, &v), HEDGE_ERROR_BAD_HANDLE);
}

/* Every live triangle slot names the face that owns it, after a split, a collapse and compaction. */
static void check_triangle_faces(const hedge_mesh* mesh, const hedge_render_buffers* render) {
  hedge_buffer_counts bc;
  CHECK_OK(hedge_render_buffers_counts(render, &bc));
  hedge_counts c = counts_of(mesh);
  uint32_t named = 0;
  for (uint32_t t = 0; t < bc.index_count / 3; ++t) {
    uint32_t f = 12345, first = 0, count = 0;
    CHECK_OK(hedge_render_buffers_triangle_face(render, t, &f));
    if (f == INVALID) continue;
    ++named;
    CHECK_OK(hedge_render_buffers_face_triangles(render, f, &first, &count));
    CHECK(t >= first && t < first + count);
  }
  CHECK(named == c.faces);
  uint32_t f = 0;
  CHECK_STATUS(hedge_render_buffers_triangle_face(render, bc.index_count / 3, &f), HEDGE_ERROR_BAD_HANDLE);
  CHECK_ERROR_HAS("triangle");
  CHECK_STATUS(hedge_render_buffers_triangle_face(render, 0, NULL), HEDGE_ERROR_INVALID_ARGUMENT);
}

void test_triangle_faces(void) {
  hedge_mesh* mesh = make_triangle_grid();
  hedge_render_buffers* render = NULL;
  CHECK_OK(hedge_render_buffers_create(mesh, NULL, &render));
  check_triangle_faces(mesh, render);
  /* Split the edge 1-4: the new vertex's four faces each own their triangle. */
  uint32_t h = INVALID, e = INVALID, v = INVALID, faces[8], n = 0;
  CHECK_OK(hedge_mesh_find_halfedge(mesh, 1, 4, &h));
  CHECK_OK(hedge_halfedge_edge(mesh, h, &e));
  CHECK_OK(hedge_split_edge(mesh, e, 1, 0.5f, 0, &v));
  CHECK_OK(hedge_render_buffers_sync(render, NULL));
  CHECK_OK(hedge_vertex_faces(mesh, v, faces, 8, &n));
  CHECK(n == 4);
  for (uint32_t i = 0; i < n; ++i) {
    uint32_t first = 0, count = 0, f = INVALID;
    CHECK_OK(hedge_render_buffers_face_triangles(render, faces[i], &first, &count));
    CHECK(count == 1);
    CHECK_OK(hedge_render_buffers_triangle_face(render, first, &f));
    CHECK(f == faces[i]);
  }
  check_triangle_faces(mesh, render);
  /* Collapse the new vertex away. Before the next sync, the slots of the faces it deleted name no
   * face (the buffers still hold them), and after the sync they are free. */
  uint32_t old_first[4], count = 0, f = 0;
  for (uint32_t i = 0; i < 4; ++i)
    CHECK_OK(hedge_render_buffers_face_triangles(render, faces[i], &old_first[i], &count));
  uint32_t out_h[8], survivor = INVALID;
  CHECK_OK(hedge_vertex_halfedges(mesh, v, out_h, 8, &n));
  int32_t ok = 0;
  uint32_t k = 0;
  for (; k < n; ++k) {
    CHECK_OK(hedge_can_collapse(mesh, out_h[k], &ok));
    if (ok) break;
  }
  CHECK(k < n);
  CHECK_OK(hedge_collapse(mesh, out_h[k], &survivor));
  int dead_faces = 0;
  for (uint32_t i = 0; i < 4; ++i) {
    int32_t dead = 0;
    CHECK_OK(hedge_face_is_deleted(mesh, faces[i], &dead));
    if (!dead) continue;
    ++dead_faces;
    CHECK_OK(hedge_render_buffers_triangle_face(render, old_first[i], &f));
    CHECK(f == INVALID);
  }
  CHECK(dead_faces == 2);
  CHECK_OK(hedge_render_buffers_sync(render, NULL));
  check_triangle_faces(mesh, render);
  /* Compaction moves the triangles; the map follows. */
  CHECK_OK(hedge_render_buffers_compact(render, NULL, 0, NULL, NULL, 0, NULL));
  check_triangle_faces(mesh, render);
  CHECK_VALID(mesh);
  CHECK_OK(hedge_mesh_destroy(mesh));
}

/* The map back to the engine arrays: the quad's 6 engine vertices weld into 4, each vertex names
 * the first engine vertex welded into it, each corner its own; a mesh not made from engine arrays
 * has no map. */
void test_engine_sources(void) {
  hedge_mesh* mesh = NULL;
  CHECK_OK(hedge_mesh_from_engine_mesh(kQuadPositions, 6, kQuadTriangles, 6, NULL, kQuadTexcoords, NULL, NULL,
                                       NULL, &mesh));
  uint64_t n = 0;
  CHECK_STATUS(hedge_mesh_vertex_source_indices(mesh, NULL, 0, &n), HEDGE_ERROR_BUFFER_TOO_SMALL);
  CHECK(n == counts_of(mesh).vertex_slots);
  int32_t vs[8], cs[32];
  CHECK_STATUS(hedge_mesh_vertex_source_indices(mesh, vs, n - 1, &n), HEDGE_ERROR_BUFFER_TOO_SMALL);
  CHECK_OK(hedge_mesh_vertex_source_indices(mesh, vs, 8, &n));
  for (uint64_t v = 0; v < n; ++v) {
    float p[3];
    get_position(mesh, (uint32_t)v, p);
    CHECK(vs[v] >= 0 && vs[v] < 6);
    CHECK(kQuadPositions[3 * vs[v]] == p[0] && kQuadPositions[3 * vs[v] + 1] == p[1]);
  }
  CHECK_OK(hedge_mesh_corner_source_indices(mesh, cs, 32, &n));
  CHECK(n == 2 * counts_of(mesh).edge_slots);
  uint32_t corners = 0;
  for (uint64_t h = 0; h < n; ++h) {
    int32_t boundary = 0;
    CHECK_OK(hedge_halfedge_is_boundary(mesh, (uint32_t)h, &boundary));
    if (boundary) {
      CHECK(cs[h] == -1);
      continue;
    }
    float p[3];
    get_position(mesh, to_vertex(mesh, (uint32_t)h), p);
    CHECK(cs[h] >= 0 && cs[h] < 6 && kQuadPositions[3 * cs[h]] == p[0] &&
          kQuadPositions[3 * cs[h] + 1] == p[1]);
    ++corners;
  }
  CHECK(corners == 6);
  CHECK_OK(hedge_mesh_destroy(mesh));
  hedge_mesh* plain = make_mesh(kPyramidPositions, 5, kPyramidTriangles, 12, NULL, 0);
  CHECK_STATUS(hedge_mesh_vertex_source_indices(plain, vs, 8, &n), HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK_ERROR_HAS("hedge_mesh_from_engine_mesh");
  CHECK_STATUS(hedge_mesh_corner_source_indices(plain, cs, 32, &n), HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK_STATUS(hedge_mesh_corner_source_indices(plain, cs, 32, NULL), HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK_OK(hedge_mesh_destroy(plain));
}

/* Submeshes: an engine quad of two materials keeps one index range per material through a split and
 * a move of a face to the other material; bad ids are refused with nothing changed. */
static void check_submeshes(const hedge_mesh* mesh, const hedge_render_buffers* render, uint32_t expected) {
  uint32_t count = 0;
  CHECK_OK(hedge_render_buffers_submesh_count(render, &count));
  CHECK(count == expected);
  hedge_buffer_counts bc;
  CHECK_OK(hedge_render_buffers_counts(render, &bc));
  uint32_t end = 0;
  for (uint32_t s = 0; s < count; ++s) {
    hedge_submesh_range r;
    CHECK_OK(hedge_render_buffers_submesh(render, s, &r));
    CHECK(r.index_start == end);
    end = r.index_start + r.index_count;
    for (uint32_t t = r.index_start / 3; t < end / 3; ++t) {
      uint32_t f = INVALID;
      int32_t sub = -1;
      CHECK_OK(hedge_render_buffers_triangle_face(render, t, &f));
      if (f == INVALID) continue;
      CHECK_OK(hedge_face_submesh(mesh, f, &sub));
      CHECK(sub == (int32_t)s);
    }
    CHECK(r.min[0] <= r.max[0] && r.min[1] <= r.max[1]);
  }
  CHECK(end == bc.index_count);
  hedge_submesh_range r;
  CHECK_STATUS(hedge_render_buffers_submesh(render, count, &r), HEDGE_ERROR_BAD_HANDLE);
  CHECK_ERROR_HAS("submesh");
}

void test_submeshes(void) {
  const int32_t materials[] = {1, 0};
  hedge_mesh* mesh = NULL;
  CHECK_OK(hedge_mesh_from_engine_mesh_with_submeshes(kQuadPositions, 6, kQuadTriangles, 6, NULL,
                                                      kQuadTexcoords, NULL, materials, NULL, NULL, &mesh));
  int32_t sub = -1;
  CHECK_OK(hedge_face_submesh(mesh, 0, &sub));
  CHECK(sub == 1);
  hedge_render_buffers* render = NULL;
  CHECK_OK(hedge_render_buffers_create(mesh, NULL, &render));
  check_submeshes(mesh, render, 2);
  hedge_submesh_range r;
  CHECK_OK(hedge_render_buffers_submesh(render, 1, &r));
  CHECK(r.min[0] == 0 && r.max[0] == 1 && r.max[1] == 1); /* triangle (0,0) (1,0) (1,1) */

  uint32_t v = 0;
  CHECK_OK(hedge_split_face(mesh, 0, 0.6f, 0.3f, 0, &v));
  CHECK_OK(hedge_render_buffers_sync(render, NULL));
  check_submeshes(mesh, render, 2);
  CHECK_OK(hedge_set_face_submesh(mesh, 1, 1));
  CHECK_OK(hedge_render_buffers_sync(render, NULL));
  check_submeshes(mesh, render, 2);
  CHECK_OK(hedge_set_face_submesh(mesh, 1, 3)); /* beyond the last submesh: the sync rebuilds */
  hedge_sync_result result;
  CHECK_OK(hedge_render_buffers_sync(render, &result));
  CHECK(result.full == 1);
  check_submeshes(mesh, render, 4);

  CHECK_STATUS(hedge_set_face_submesh(mesh, 1, -1), HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK_ERROR_HAS("outside [0, 65535]");
  CHECK_OK(hedge_face_submesh(mesh, 1, &sub));
  CHECK(sub == 3);
  CHECK_STATUS(hedge_face_submesh(mesh, 1, NULL), HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK_VALID(mesh);
  CHECK_OK(hedge_mesh_destroy(mesh));

  const int32_t bad[] = {0, 70000};
  mesh = NULL;
  CHECK_STATUS(hedge_mesh_from_engine_mesh_with_submeshes(kQuadPositions, 6, kQuadTriangles, 6, NULL, NULL,
                                                          NULL, bad, NULL, NULL, &mesh),
               HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK_ERROR_HAS("submesh of triangle 1 is 70000");
  CHECK(mesh == NULL);
}

/* ---------------------------------------------------------------------------------------------- */
/* Engine streams: tangents and a second texcoord channel                                         */
/* ---------------------------------------------------------------------------------------------- */

/* Per engine vertex of the quad: a tangent along +x (handedness -1 on the second triangle) and
 * lightmap UVs that differ from every other vertex's. */
static const float kQuadTangents[] = {1, 0, 0, 1,  1, 0, 0, 1,  1, 0, 0, 1,
                                      1, 0, 0, -1, 1, 0, 0, -1, 1, 0, 0, -1};
static const float kQuadTexcoords1[] = {0.1f, 0.1f, 0.2f, 0.1f, 0.2f, 0.2f,
                                        0.3f, 0.1f, 0.3f, 0.3f, 0.1f, 0.3f};
static const float kQuadNormals[] = {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1};

static hedge_engine_streams quad_streams(void) {
  hedge_engine_streams s;
  memset(&s, 0, sizeof s);
  s.vertex_count = 6;
  s.index_count = 6;
  s.positions = kQuadPositions;
  s.indices = kQuadTriangles;
  s.normals = kQuadNormals;
  s.texcoords = kQuadTexcoords;
  s.colors = kQuadColors;
  s.tangents = kQuadTangents;
  s.texcoords1 = kQuadTexcoords1;
  return s;
}

/* Every render vertex the index buffer uses has a unit tangent perpendicular to its normal, w = +-1
 * (separate layout: the normal and tangent streams). */
static void check_tangent_frames(const hedge_render_buffers* render) {
  const float *normals = NULL, *tangents = NULL;
  const uint32_t* indices = NULL;
  uint64_t n_normals = 0, n_tangents = 0, n_indices = 0;
  CHECK_OK(hedge_render_buffers_vertex_data(render, HEDGE_STREAM_NORMALS, &normals, &n_normals));
  CHECK_OK(hedge_render_buffers_vertex_data(render, HEDGE_STREAM_TANGENTS, &tangents, &n_tangents));
  CHECK_OK(hedge_render_buffers_index_data(render, &indices, &n_indices));
  CHECK(n_normals / 3 == n_tangents / 4);
  for (uint64_t i = 0; i + 2 < n_indices; i += 3) {
    if (indices[i] == indices[i + 1]) continue; /* a free slot */
    for (int k = 0; k < 3; ++k) {
      const float* n = normals + 3 * indices[i + k];
      const float* t = tangents + 4 * indices[i + k];
      CHECK(fabsf(n[0] * t[0] + n[1] * t[1] + n[2] * t[2]) < 1e-5f);
      CHECK(fabsf(t[0] * t[0] + t[1] * t[1] + t[2] * t[2] - 1) < 1e-4f);
      CHECK(t[3] == 1 || t[3] == -1);
    }
  }
}

static uint32_t vertex_at(const hedge_mesh* mesh, float x, float y) {
  hedge_counts c = counts_of(mesh);
  for (uint32_t v = 0; v < c.vertex_slots; ++v) {
    float p[3];
    CHECK_OK(hedge_vertex_position(mesh, v, p));
    if (p[0] == x && p[1] == y) return v;
  }
  CHECK(0);
  return INVALID;
}

void test_engine_streams(void) {
  hedge_engine_streams s = quad_streams();
  hedge_mesh* mesh = NULL;
  CHECK_OK(hedge_mesh_from_engine_streams(&s, NULL, NULL, &mesh));

  /* Interleaved: position, normal, texcoord, colour, tangent, texcoord1. */
  hedge_render_buffers* whole = NULL;
  CHECK_OK(hedge_render_buffers_create(mesh, NULL, &whole));
  hedge_vertex_layout layout;
  CHECK_OK(hedge_render_buffers_layout(whole, &layout));
  CHECK(layout.interleaved == 1 && layout.stride == 18 && layout.color == 8);
  CHECK(layout.tangent == 12 && layout.texcoord1 == 16);
  hedge_buffer_counts bc;
  CHECK_OK(hedge_render_buffers_counts(whole, &bc));
  const float* v = NULL;
  uint64_t n = 0;
  CHECK_OK(hedge_render_buffers_vertex_data(whole, HEDGE_STREAM_VERTICES, &v, &n));
  CHECK(n == 18ull * bc.vertex_slots);
  /* Every engine vertex is one render vertex with its own tangent and lightmap UV. */
  for (uint32_t e = 0; e < 6; ++e) {
    int found = 0;
    for (uint32_t r = 0; r < bc.vertex_slots; ++r) {
      const float* x = v + 18 * r;
      if (x[0] == kQuadPositions[3 * e] && x[1] == kQuadPositions[3 * e + 1] &&
          x[6] == kQuadTexcoords[2 * e] && x[7] == kQuadTexcoords[2 * e + 1] &&
          x[12] == kQuadTangents[4 * e] && x[15] == kQuadTangents[4 * e + 3] &&
          x[16] == kQuadTexcoords1[2 * e] && x[17] == kQuadTexcoords1[2 * e + 1])
        ++found;
    }
    CHECK(found == 1);
  }
  CHECK_OK(hedge_render_buffers_destroy(whole));

  /* Separate: streams 4 and 5, offset 0, the same dirty ranges as the other streams. */
  hedge_render_buffers_options options;
  CHECK_OK(hedge_render_buffers_options_default(&options));
  options.interleaved = 0;
  hedge_render_buffers* render = NULL;
  CHECK_OK(hedge_render_buffers_create(mesh, &options, &render));
  CHECK_OK(hedge_render_buffers_layout(render, &layout));
  CHECK(layout.interleaved == 0 && layout.stride == 18 && layout.tangent == 0 && layout.texcoord1 == 0);
  CHECK_OK(hedge_render_buffers_counts(render, &bc));
  const float* t = NULL;
  CHECK_OK(hedge_render_buffers_vertex_data(render, HEDGE_STREAM_TANGENTS, &t, &n));
  CHECK(t != NULL && n == 4ull * bc.vertex_slots);
  float copy[256];
  uint64_t n_copy = 0;
  CHECK_OK(hedge_render_buffers_copy_vertex_data(render, HEDGE_STREAM_TEXCOORDS1, copy, 256, &n_copy));
  CHECK(n_copy == 2ull * bc.vertex_slots);
  check_tangent_frames(render);

  /* Lift a corner: the normals follow, and the tangents about it are made perpendicular again. */
  const uint32_t lifted = vertex_at(mesh, 1, 1);
  CHECK_OK(hedge_set_vertex_position(mesh, lifted, 1, 1, 0.5f));
  hedge_sync_result result;
  CHECK_OK(hedge_render_buffers_sync(render, &result));
  CHECK(result.vertex_range_count > 0 && result.full == 0);
  check_tangent_frames(render);
  hedge_range ranges[16];
  uint32_t n_ranges = 0;
  CHECK_OK(hedge_render_buffers_dirty_vertex_ranges(render, ranges, 16, &n_ranges));
  CHECK_OK(hedge_render_buffers_vertex_data(render, HEDGE_STREAM_TANGENTS, &t, &n));
  int tilted = 0;
  for (uint32_t i = 0; i < n_ranges; ++i)
    for (uint32_t r = ranges[i].first; r < ranges[i].first + ranges[i].count; ++r)
      tilted |= t[4 * r + 2] != 0;
  CHECK(tilted); /* the rewritten range holds the re-orthogonalised tangents */

  /* Split an edge: the new corners get interpolated tangents and lightmap UVs. */
  uint32_t h = INVALID, e = INVALID, mid = INVALID;
  CHECK_OK(hedge_mesh_find_halfedge(mesh, vertex_at(mesh, 0, 0), vertex_at(mesh, 1, 0), &h));
  CHECK_OK(hedge_halfedge_edge(mesh, h, &e));
  CHECK_OK(hedge_split_edge(mesh, e, 0.5f, 0, 0, &mid));
  CHECK_OK(hedge_render_buffers_sync(render, &result));
  check_tangent_frames(render);
  uint32_t rv = INVALID;
  CHECK_OK(hedge_mesh_find_halfedge(mesh, vertex_at(mesh, 0, 0), mid, &h));
  CHECK_OK(hedge_render_buffers_corner_vertex(render, h, &rv));
  CHECK_OK(hedge_render_buffers_copy_vertex_data(render, HEDGE_STREAM_TEXCOORDS1, copy, 256, &n_copy));
  CHECK(fabsf(copy[2 * rv] - 0.15f) < 1e-6f && fabsf(copy[2 * rv + 1] - 0.1f) < 1e-6f);
  CHECK_VALID(mesh);
  CHECK_OK(hedge_mesh_destroy(mesh));

  /* Without tangents or a second channel (the older import), both are absent. */
  mesh = NULL;
  CHECK_OK(hedge_mesh_from_engine_mesh(kQuadPositions, 6, kQuadTriangles, 6, NULL, kQuadTexcoords, NULL, NULL,
                                       NULL, &mesh));
  CHECK_OK(hedge_render_buffers_create(mesh, &options, &render));
  CHECK_OK(hedge_render_buffers_layout(render, &layout));
  CHECK(layout.tangent == -1 && layout.texcoord1 == -1);
  CHECK_OK(hedge_render_buffers_vertex_data(render, HEDGE_STREAM_TANGENTS, &t, &n));
  CHECK(t == NULL && n == 0);
  CHECK_STATUS(hedge_render_buffers_vertex_data(render, 6, &t, &n), HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK_ERROR_HAS("not a HEDGE_STREAM_* value");
  CHECK_OK(hedge_mesh_destroy(mesh));

  /* Bad input: named, and no mesh is made. */
  float nan_tangents[24];
  memcpy(nan_tangents, kQuadTangents, sizeof nan_tangents);
  nan_tangents[4 * 2 + 1] = NAN;
  s.tangents = nan_tangents;
  mesh = NULL;
  CHECK_STATUS(hedge_mesh_from_engine_streams(&s, NULL, NULL, &mesh), HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK_ERROR_HAS("tangent of vertex 2");
  CHECK(mesh == NULL);
  CHECK_STATUS(hedge_mesh_from_engine_streams(NULL, NULL, NULL, &mesh), HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK_ERROR_HAS("streams");
  s = quad_streams();
  s.positions = NULL;
  CHECK_STATUS(hedge_mesh_from_engine_streams(&s, NULL, NULL, &mesh), HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK_ERROR_HAS("positions");
  CHECK(mesh == NULL);
}
