/* The C ABI's local operations and region edits (src/capi/operations.cpp). */
#include "capi_test.h"

/* ---------------------------------------------------------------------------------------------- */
/* Boundaries and the local operations on an open pyramid                                         */
/* ---------------------------------------------------------------------------------------------- */

/* The first live half-edge (or edge, face, vertex) for which the predicate says yes. */
typedef hedge_status (*predicate_fn)(const hedge_mesh*, uint32_t, int32_t*);
typedef hedge_status (*deleted_fn)(const hedge_mesh*, uint32_t, int32_t*);

static uint32_t find_allowed(const hedge_mesh* mesh, uint32_t slots, predicate_fn can,
                             deleted_fn is_deleted) {
  for (uint32_t i = 0; i < slots; ++i) {
    int32_t deleted = 1, ok = 0;
    CHECK_OK(is_deleted(mesh, i, &deleted));
    if (deleted) {
      CHECK_STATUS(can(mesh, i, &ok), HEDGE_ERROR_BAD_HANDLE);
      continue;
    }
    CHECK_OK(can(mesh, i, &ok));
    if (ok) return i;
  }
  return INVALID;
}

void test_pyramid_operations(void) {
  hedge_mesh* mesh = make_mesh(kPyramidPositions, 5, kPyramidTriangles, 12, NULL, 0);
  hedge_counts c = counts_of(mesh);
  CHECK(c.vertices == 5 && c.edges == 8 && c.faces == 4 && c.halfedges == 16);

  /* Boundary queries. */
  int32_t boundary = -1;
  for (uint32_t v = 0; v < 4; ++v) {
    uint32_t h = 0, ring[8], faces[8], n = 0, n_faces = 0;
    CHECK_OK(hedge_vertex_is_boundary(mesh, v, &boundary));
    CHECK(boundary == 1);
    CHECK_OK(hedge_vertex_halfedge(mesh, v, &h));
    CHECK_OK(hedge_halfedge_is_boundary(mesh, h, &boundary));
    CHECK(boundary == 1);
    uint32_t face = 0;
    CHECK_OK(hedge_halfedge_face(mesh, h, &face));
    CHECK(face == INVALID);
    CHECK_OK(hedge_vertex_vertices(mesh, v, ring, 8, &n));
    CHECK(n == 3 && contains(ring, n, 4) && contains(ring, n, (v + 1) % 4) && contains(ring, n, (v + 3) % 4));
    CHECK_OK(hedge_vertex_faces(mesh, v, faces, 8, &n_faces));
    CHECK(n_faces == 2);
    /* prev of a boundary half-edge walks the boundary loop */
    uint32_t prev = 0;
    CHECK_OK(hedge_halfedge_prev(mesh, h, &prev));
    CHECK(next_of(mesh, prev) == h);
    CHECK_OK(hedge_halfedge_is_boundary(mesh, prev, &boundary));
    CHECK(boundary == 1);
  }
  CHECK_OK(hedge_vertex_is_boundary(mesh, 4, &boundary));
  CHECK(boundary == 0);
  for (uint32_t f = 0; f < 4; ++f) {
    CHECK_OK(hedge_face_is_boundary(mesh, f, &boundary));
    CHECK(boundary == 1);
  }
  uint32_t base = 0, apex_edge = 0;
  CHECK_OK(hedge_mesh_find_halfedge(mesh, 1, 0, &base)); /* the base edge outside face 0 */
  CHECK(base != INVALID);
  CHECK_OK(hedge_halfedge_is_boundary(mesh, base, &boundary));
  CHECK(boundary == 1);
  CHECK_OK(hedge_edge_is_boundary(mesh, base >> 1, &boundary));
  CHECK(boundary == 1);
  CHECK_OK(hedge_mesh_find_halfedge(mesh, 0, 4, &apex_edge));
  CHECK_OK(hedge_edge_is_boundary(mesh, apex_edge >> 1, &boundary));
  CHECK(boundary == 0);
  uint32_t none = 0;
  CHECK_OK(hedge_mesh_find_halfedge(mesh, 0, 2, &none));
  CHECK(none == INVALID);

  /* fill_hole: predicate, too small a buffer (nothing changed), then the fill. */
  int32_t ok = -1;
  CHECK_OK(hedge_can_fill_hole(mesh, base, &ok));
  CHECK(ok == 1);
  CHECK_OK(hedge_can_fill_hole(mesh, apex_edge, &ok));
  CHECK(ok == 0);
  uint32_t filled[4] = {0}, n_filled = 0;
  CHECK_STATUS(hedge_fill_hole(mesh, apex_edge, filled, 4, &n_filled), HEDGE_ERROR_REFUSED);
  CHECK_STATUS(hedge_fill_hole(mesh, base, filled, 1, &n_filled), HEDGE_ERROR_BUFFER_TOO_SMALL);
  CHECK(n_filled == 2);
  CHECK(same_counts(counts_of(mesh), c));
  CHECK_OK(hedge_fill_hole(mesh, base, filled, 4, &n_filled));
  CHECK(n_filled == 2 && filled[0] != filled[1] && filled[0] >= 4 && filled[1] >= 4);
  c = counts_of(mesh);
  CHECK(c.faces == 6 && c.edges == 9 && c.vertices == 5);
  CHECK_OK(hedge_halfedge_is_boundary(mesh, base, &boundary));
  CHECK(boundary == 0);
  CHECK_OK(hedge_can_fill_hole(mesh, base, &ok));
  CHECK(ok == 0);
  CHECK_VALID(mesh);

  /* split_edge at the middle of edge 0. */
  uint32_t h0 = 0, a = 0, b = 0, mid = 0;
  CHECK_OK(hedge_edge_halfedge(mesh, 0, 0, &h0));
  a = from_vertex(mesh, h0);
  b = to_vertex(mesh, h0);
  float pa[3], pb[3], pm[3];
  get_position(mesh, a, pa);
  get_position(mesh, b, pb);
  CHECK_OK(hedge_can_split_edge(mesh, 0, &ok));
  CHECK(ok == 1);
  CHECK_STATUS(hedge_split_edge(mesh, 0, NAN, 0, 0, &mid), HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK(same_counts(counts_of(mesh), c));
  CHECK_OK(hedge_split_edge(mesh, 0, (pa[0] + pb[0]) / 2, (pa[1] + pb[1]) / 2, (pa[2] + pb[2]) / 2, &mid));
  CHECK(mid == 5);
  get_position(mesh, mid, pm);
  CHECK(pm[0] == (pa[0] + pb[0]) / 2 && pm[1] == (pa[1] + pb[1]) / 2 && pm[2] == (pa[2] + pb[2]) / 2);
  CHECK(from_vertex(mesh, h0) == a && to_vertex(mesh, h0) == mid);
  uint32_t found = 0;
  CHECK_OK(hedge_mesh_find_halfedge(mesh, mid, b, &found));
  CHECK(found != INVALID);
  c = counts_of(mesh);
  CHECK(c.vertices == 6 && c.faces == 8 && c.edges == 12); /* two triangles split in two */
  CHECK_VALID(mesh);

  /* split_face at a face's centroid. */
  uint32_t corners[3], n = 0, centre = 0, valence = 0;
  CHECK_OK(hedge_can_split_face(mesh, 1, &ok));
  CHECK(ok == 1);
  CHECK_OK(hedge_face_vertices(mesh, 1, corners, 3, &n));
  float centroid[3] = {0, 0, 0};
  for (uint32_t i = 0; i < 3; ++i) {
    float p[3];
    get_position(mesh, corners[i], p);
    for (int k = 0; k < 3; ++k) centroid[k] += p[k] / 3;
  }
  CHECK_OK(hedge_split_face(mesh, 1, centroid[0], centroid[1], centroid[2], &centre));
  CHECK_OK(hedge_vertex_valence(mesh, centre, &valence));
  CHECK(valence == 3);
  {
    uint32_t ring[8], n_ring = 0;
    CHECK_OK(hedge_vertex_vertices(mesh, centre, ring, 8, &n_ring));
    CHECK(n_ring == 3);
    for (uint32_t i = 0; i < 3; ++i) CHECK(contains(ring, 3, corners[i]));
  }
  c = counts_of(mesh);
  CHECK(c.vertices == 7 && c.faces == 10);
  CHECK_VALID(mesh);

  /* flip: the edge turns to join the two opposite corners. */
  const uint32_t e_flip = find_allowed(mesh, c.edge_slots, hedge_can_flip, hedge_edge_is_deleted);
  CHECK(e_flip != INVALID);
  const uint32_t tip0 = to_vertex(mesh, next_of(mesh, 2 * e_flip));
  const uint32_t tip1 = to_vertex(mesh, next_of(mesh, 2 * e_flip + 1));
  CHECK_OK(hedge_flip(mesh, e_flip));
  {
    const uint32_t u = from_vertex(mesh, 2 * e_flip), w = to_vertex(mesh, 2 * e_flip);
    CHECK((u == tip0 && w == tip1) || (u == tip1 && w == tip0));
  }
  CHECK(same_counts(counts_of(mesh), c));
  CHECK_VALID(mesh);

  /* collapse: the from-vertex goes, the to-vertex survives. */
  const uint32_t h_collapse =
      find_allowed(mesh, c.halfedge_slots, hedge_can_collapse, hedge_halfedge_is_deleted);
  CHECK(h_collapse != INVALID);
  const uint32_t gone = from_vertex(mesh, h_collapse), kept = to_vertex(mesh, h_collapse);
  uint32_t survivor = 0;
  CHECK_OK(hedge_collapse(mesh, h_collapse, &survivor));
  CHECK(survivor == kept);
  int32_t deleted = 0;
  CHECK_OK(hedge_vertex_is_deleted(mesh, gone, &deleted));
  CHECK(deleted == 1);
  uint32_t unused = 0;
  CHECK_STATUS(hedge_vertex_halfedge(mesh, gone, &unused), HEDGE_ERROR_BAD_HANDLE);
  CHECK_ERROR_HAS("deleted");
  CHECK_STATUS(hedge_halfedge_twin(mesh, h_collapse, &unused), HEDGE_ERROR_BAD_HANDLE);
  CHECK_STATUS(hedge_collapse(mesh, h_collapse, &unused), HEDGE_ERROR_BAD_HANDLE);
  {
    const hedge_counts after = counts_of(mesh);
    CHECK(after.vertices == c.vertices - 1 && after.edges == c.edges - 3 && after.faces == c.faces - 2);
    CHECK(after.vertex_slots == c.vertex_slots);
    c = after;
  }
  CHECK_VALID(mesh);

  /* remove_face, remove_vertex. */
  const uint32_t f_remove = find_allowed(mesh, c.face_slots, hedge_can_remove_face, hedge_face_is_deleted);
  CHECK(f_remove != INVALID);
  CHECK_OK(hedge_remove_face(mesh, f_remove));
  CHECK_OK(hedge_face_is_deleted(mesh, f_remove, &deleted));
  CHECK(deleted == 1);
  CHECK_STATUS(hedge_remove_face(mesh, f_remove), HEDGE_ERROR_BAD_HANDLE);
  CHECK(counts_of(mesh).faces == c.faces - 1);
  CHECK_VALID(mesh);
  c = counts_of(mesh);
  const uint32_t v_remove =
      find_allowed(mesh, c.vertex_slots, hedge_can_remove_vertex, hedge_vertex_is_deleted);
  CHECK(v_remove != INVALID);
  CHECK_OK(hedge_can_remove_vertex(mesh, v_remove, &ok));
  CHECK(ok == 1);
  uint32_t v_face_list[16], v_faces = 0;
  CHECK_OK(hedge_vertex_faces(mesh, v_remove, v_face_list, 16, &v_faces));
  CHECK(v_faces > 0);
  CHECK_OK(hedge_remove_vertex(mesh, v_remove));
  CHECK_OK(hedge_vertex_is_deleted(mesh, v_remove, &deleted));
  CHECK(deleted == 1);
  CHECK(counts_of(mesh).faces == c.faces - v_faces);
  CHECK_VALID(mesh);

  /* split_all_faces: too small a buffer changes nothing. */
  c = counts_of(mesh);
  uint32_t added[64], n_added = 0;
  CHECK_STATUS(hedge_mesh_split_all_faces(mesh, added, c.faces - 1, &n_added), HEDGE_ERROR_BUFFER_TOO_SMALL);
  CHECK(n_added == c.faces);
  CHECK(same_counts(counts_of(mesh), c));
  CHECK_OK(hedge_mesh_split_all_faces(mesh, added, 64, &n_added));
  CHECK(n_added == c.faces);
  {
    const hedge_counts after = counts_of(mesh);
    CHECK(after.vertices == c.vertices + c.faces && after.faces == 3 * c.faces);
    for (uint32_t i = 0; i < n_added; ++i) {
      CHECK(added[i] >= c.vertex_slots);
      CHECK_OK(hedge_vertex_valence(mesh, added[i], &valence));
      CHECK(valence == 3);
    }
    c = after;
  }
  CHECK_VALID(mesh);
  CHECK_OK(hedge_mesh_split_all_faces(mesh, NULL, 0, &n_added));
  CHECK(n_added == c.faces);
  CHECK_VALID(mesh);

  /* garbage_collection with maps copied out. */
  c = counts_of(mesh);
  CHECK(c.vertex_slots > c.vertices && c.face_slots > c.faces);
  uint32_t* vmap = malloc(sizeof(uint32_t) * c.vertex_slots);
  uint32_t* hmap = malloc(sizeof(uint32_t) * c.halfedge_slots);
  uint32_t* emap = malloc(sizeof(uint32_t) * c.edge_slots);
  uint32_t* fmap = malloc(sizeof(uint32_t) * c.face_slots);
  CHECK(vmap && hmap && emap && fmap);
  float* before = malloc(sizeof(float) * 3 * c.vertex_slots);
  CHECK(before != NULL);
  copy_positions(mesh, before, 3 * (uint64_t)c.vertex_slots);
  CHECK_STATUS(hedge_mesh_garbage_collection(mesh, vmap, c.vertex_slots - 1, NULL, 0, NULL, 0, NULL, 0),
               HEDGE_ERROR_BUFFER_TOO_SMALL);
  CHECK_ERROR_HAS("vertex_map");
  CHECK(same_counts(counts_of(mesh), c));
  CHECK_OK(hedge_mesh_garbage_collection(mesh, vmap, c.vertex_slots, hmap, c.halfedge_slots, emap,
                                         c.edge_slots, fmap, c.face_slots));
  {
    const hedge_counts after = counts_of(mesh);
    CHECK(after.vertices == c.vertices && after.faces == c.faces && after.edges == c.edges);
    CHECK(after.vertex_slots == c.vertices && after.face_slots == c.faces && after.edge_slots == c.edges);
    uint32_t live = 0;
    for (uint32_t v = 0; v < c.vertex_slots; ++v) {
      if (vmap[v] == INVALID) continue;
      CHECK(vmap[v] == live); /* order kept */
      float p[3];
      get_position(mesh, vmap[v], p);
      CHECK(p[0] == before[3 * v] && p[1] == before[3 * v + 1] && p[2] == before[3 * v + 2]);
      ++live;
    }
    CHECK(live == c.vertices);
    uint32_t live_faces = 0, live_edges = 0, live_halfedges = 0;
    for (uint32_t f = 0; f < c.face_slots; ++f) live_faces += fmap[f] != INVALID;
    for (uint32_t e = 0; e < c.edge_slots; ++e) live_edges += emap[e] != INVALID;
    for (uint32_t h = 0; h < c.halfedge_slots; ++h) live_halfedges += hmap[h] != INVALID;
    CHECK(live_faces == c.faces && live_edges == c.edges && live_halfedges == c.halfedges);
  }
  free(vmap);
  free(hmap);
  free(emap);
  free(fmap);
  free(before);
  CHECK_VALID(mesh);
  CHECK_OK(hedge_mesh_destroy(mesh));
}

/* ---------------------------------------------------------------------------------------------- */
/* Polygons: cutting faces, adding faces, detaching faces                                         */
/* ---------------------------------------------------------------------------------------------- */

/* A face added with texcoords per corner and a submesh: the texcoords reach the render buffers' corners;
 * bad attributes fail before the mesh changes. */
static void add_face_with_attributes(void) {
  hedge_mesh* grid = make_mesh(kGridPositions, 9, kGridQuads, 16, kGridSizes, 4);
  CHECK_OK(hedge_remove_face(grid, 3)); /* quad 4 5 8 7; vertex 8 goes with it */
  const uint32_t triangle[] = {4, 5, 7};
  const float uv[] = {0.25f, 0.5f, 0.75f, 0.5f, 0.25f, 1.0f};
  const float nan_uv[] = {0, 0, NAN, 0, 1, 1};
  uint32_t face = 1234;
  const hedge_counts before = counts_of(grid);
  CHECK_STATUS(hedge_add_face_with_attributes(grid, triangle, 3, nan_uv, -1, &face),
               HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK_ERROR_HAS("texcoord 1 is not finite");
  CHECK_STATUS(hedge_add_face_with_attributes(grid, triangle, 3, uv, 65536, &face),
               HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK_ERROR_HAS("submesh 65536 is not in [0, 65535]");
  const uint32_t reversed[] = {7, 5, 4};
  CHECK_STATUS(hedge_add_face_with_attributes(grid, reversed, 3, uv, 1, &face), HEDGE_ERROR_REFUSED);
  CHECK(hedge_last_refusal_code() != HEDGE_REFUSAL_NONE);
  CHECK_STATUS(hedge_add_face_with_attributes(grid, NULL, 3, uv, 1, &face), HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK_STATUS(hedge_add_face_with_attributes(grid, triangle, 3, uv, 1, NULL), HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK(face == 1234);
  CHECK(same_counts(counts_of(grid), before));

  CHECK_OK(hedge_add_face_with_attributes(grid, triangle, 3, uv, 2, &face));
  CHECK(face_is(grid, face, triangle, 3));
  CHECK_VALID(grid);
  hedge_render_buffers_options options;
  CHECK_OK(hedge_render_buffers_options_default(&options));
  options.interleaved = 0;
  hedge_render_buffers* render = NULL;
  CHECK_OK(hedge_render_buffers_create(grid, &options, &render));
  const float* texcoords = NULL;
  uint64_t floats = 0;
  CHECK_OK(hedge_render_buffers_vertex_data(render, HEDGE_STREAM_TEXCOORDS, &texcoords, &floats));
  CHECK(texcoords != NULL);
  uint32_t loop[3], n = 0;
  CHECK_OK(hedge_face_halfedges(grid, face, loop, 3, &n));
  CHECK(n == 3);
  for (uint32_t i = 0; i < 3; ++i) {
    uint32_t corner = 0, rv = 0;
    const uint32_t v = to_vertex(grid, loop[i]);
    while (triangle[corner] != v) ++corner;
    CHECK_OK(hedge_render_buffers_corner_vertex(render, loop[i], &rv));
    CHECK(2 * (uint64_t)rv + 1 < floats);
    CHECK(texcoords[2 * rv] == uv[2 * corner] && texcoords[2 * rv + 1] == uv[2 * corner + 1]);
  }
  CHECK_OK(hedge_render_buffers_destroy(render));
  CHECK_VALID(grid);
  CHECK_OK(hedge_mesh_destroy(grid));
}

void test_grid_operations(void) {
  hedge_mesh* grid = make_mesh(kGridPositions, 9, kGridQuads, 16, kGridSizes, 4);
  hedge_counts c = counts_of(grid);
  CHECK(c.vertices == 9 && c.faces == 4 && c.edges == 12);
  for (uint32_t f = 0; f < 4; ++f) {
    uint32_t valence = 0;
    CHECK_OK(hedge_face_valence(grid, f, &valence));
    CHECK(valence == 4);
    CHECK(face_is(grid, f, kGridQuads + 4 * f, 4));
  }
  uint32_t valence = 0;
  CHECK_OK(hedge_vertex_valence(grid, 4, &valence));
  CHECK(valence == 4);

  /* Cut quad 0 along a diagonal. */
  uint32_t loop[4], n = 0, cut = 0;
  int32_t ok = -1;
  CHECK_OK(hedge_face_halfedges(grid, 0, loop, 4, &n));
  CHECK(n == 4);
  CHECK_OK(hedge_can_cut_face(grid, loop[0], loop[1], &ok));
  CHECK(ok == 0);
  CHECK_STATUS(hedge_cut_face(grid, loop[0], loop[1], &cut), HEDGE_ERROR_REFUSED);
  CHECK(same_counts(counts_of(grid), c));
  CHECK_OK(hedge_can_cut_face(grid, loop[0], loop[2], &ok));
  CHECK(ok == 1);
  const uint32_t d0 = to_vertex(grid, loop[0]), d1 = to_vertex(grid, loop[2]);
  CHECK_OK(hedge_cut_face(grid, loop[0], loop[2], &cut));
  CHECK(from_vertex(grid, cut) == d0 && to_vertex(grid, cut) == d1);
  c = counts_of(grid);
  CHECK(c.faces == 5 && c.edges == 13);
  CHECK_OK(hedge_face_valence(grid, 0, &valence));
  CHECK(valence == 3);
  CHECK_VALID(grid);

  /* Remove quad 3 (corner face) and add it back. */
  CHECK_OK(hedge_can_remove_face(grid, 3, &ok));
  CHECK(ok == 1);
  CHECK_OK(hedge_remove_face(grid, 3));
  CHECK(counts_of(grid).faces == 4);
  int32_t deleted = 0;
  CHECK_OK(hedge_vertex_is_deleted(grid, 8, &deleted)); /* the corner vertex went with the face */
  CHECK(deleted == 1);
  CHECK_VALID(grid);
  const uint32_t corner_gone[] = {4, 5, 8, 7};
  CHECK_STATUS(hedge_can_add_face(grid, corner_gone, 4, &ok), HEDGE_ERROR_BAD_HANDLE);
  const uint32_t repeated[] = {4, 5, 4};
  CHECK_OK(hedge_can_add_face(grid, repeated, 3, &ok));
  CHECK(ok == 0);
  uint32_t face = 0;
  CHECK_STATUS(hedge_add_face(grid, repeated, 3, &face), HEDGE_ERROR_REFUSED);
  const uint32_t inside_out[] = {4, 7, 5}; /* would run against its neighbours' orientation */
  CHECK_OK(hedge_can_add_face(grid, inside_out, 3, &ok));
  CHECK(ok == 0);
  CHECK_STATUS(hedge_add_face(grid, inside_out, 3, &face), HEDGE_ERROR_REFUSED);
  const uint32_t triangle[] = {4, 5, 7};
  CHECK_OK(hedge_can_add_face(grid, triangle, 3, &ok));
  CHECK(ok == 1);
  CHECK_OK(hedge_add_face(grid, triangle, 3, &face));
  CHECK(face_is(grid, face, triangle, 3));
  CHECK(counts_of(grid).faces == 5);
  CHECK_STATUS(hedge_add_face(grid, NULL, 3, &face), HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK_VALID(grid);

  /* Detach faces 1 and 2 (two quads that meet at vertex 4 only) with the vertex origins. */
  c = counts_of(grid);
  const uint32_t detach[] = {1, 2, 1};
  uint32_t origin[16], n_origin = 0;
  hedge_mesh* piece = NULL;
  CHECK_STATUS(hedge_detach_faces(grid, detach, 3, origin, 7, &n_origin, &piece),
               HEDGE_ERROR_BUFFER_TOO_SMALL);
  CHECK(n_origin == 8 && piece == NULL);
  CHECK(same_counts(counts_of(grid), c));
  CHECK_OK(hedge_detach_faces(grid, detach, 3, origin, 16, &n_origin, &piece));
  CHECK(piece != NULL);
  const hedge_counts pc = counts_of(piece);
  CHECK(pc.faces == 2 && pc.vertices == n_origin);
  CHECK(n_origin == 8); /* the vertex shared only at a corner is split in the piece */
  for (uint32_t v = 0; v < n_origin; ++v) {
    float p[3];
    CHECK(origin[v] < c.vertex_slots);
    get_position(piece, v, p);
    CHECK(p[0] == kGridPositions[3 * origin[v]] && p[1] == kGridPositions[3 * origin[v] + 1]);
  }
  CHECK(counts_of(grid).faces == c.faces - 2);
  CHECK_VALID(grid);
  CHECK_VALID(piece);
  /* Detaching nothing gives an empty mesh. */
  hedge_mesh* empty = NULL;
  CHECK_OK(hedge_detach_faces(grid, NULL, 0, NULL, 0, NULL, &empty));
  CHECK(counts_of(empty).faces == 0 && counts_of(empty).vertices == 0);
  CHECK_STATUS(hedge_detach_faces(grid, detach, 1, NULL, 0, NULL, &empty),
               HEDGE_ERROR_BAD_HANDLE); /* deleted */
  CHECK_OK(hedge_mesh_destroy(empty));
  CHECK_OK(hedge_mesh_destroy(piece));
  CHECK_OK(hedge_mesh_destroy(grid));
  add_face_with_attributes();
}
