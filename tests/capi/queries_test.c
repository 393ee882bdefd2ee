/* The C ABI's adjacency queries (src/capi/queries.cpp), on a tetrahedron with its refused edits. */
#include "capi_test.h"

/* ---------------------------------------------------------------------------------------------- */
/* Creation, queries and the refused collapse of a tetrahedron                                    */
/* ---------------------------------------------------------------------------------------------- */

void test_tetrahedron(void) {
  hedge_build_options options;
  memset(&options, 0xFF, sizeof options);
  CHECK_OK(hedge_build_options_default(&options));
  CHECK(options.policy == HEDGE_POLICY_REPAIR && options.weld == HEDGE_WELD_NONE);
  CHECK(options.weld_epsilon == 1e-6);
  CHECK_STATUS(hedge_build_options_default(NULL), HEDGE_ERROR_INVALID_ARGUMENT);

  hedge_build_report report;
  memset(&report, 0xFF, sizeof report);
  uint32_t vertex_map[4] = {9, 9, 9, 9}, face_map[4] = {9, 9, 9, 9};
  hedge_mesh* tet = NULL;
  CHECK_OK(hedge_mesh_create(kTetPositions, 4, kTetTriangles, 12, NULL, 0, &options, &report, vertex_map,
                             face_map, &tet));
  CHECK(report.repairs == 0 && report.welded_vertices == 0 && report.isolated_vertices == 0);
  CHECK(report.degenerate_faces == 0 && report.non_manifold_edges == 0 && report.reoriented_faces == 0);
  for (uint32_t i = 0; i < 4; ++i) CHECK(vertex_map[i] == i && face_map[i] == i);

  const hedge_counts c = counts_of(tet);
  CHECK(c.vertices == 4 && c.halfedges == 12 && c.edges == 6 && c.faces == 4);
  CHECK(c.vertex_slots == 4 && c.halfedge_slots == 12 && c.edge_slots == 6 && c.face_slots == 4);

  /* Faces are the input triangles. */
  for (uint32_t f = 0; f < 4; ++f) CHECK(face_is(tet, f, kTetTriangles + 3 * f, 3));

  /* Half-edge identities. */
  for (uint32_t h = 0; h < 12; ++h) {
    uint32_t twin = 0, prev = 0, face = 0, edge = 0, found = 0;
    int32_t boundary = -1, deleted = -1;
    CHECK_OK(hedge_halfedge_twin(tet, h, &twin));
    CHECK(twin == (h ^ 1u));
    CHECK_OK(hedge_halfedge_prev(tet, h, &prev));
    CHECK(next_of(tet, prev) == h);
    CHECK(next_of(tet, next_of(tet, next_of(tet, h))) == h);
    CHECK(from_vertex(tet, h) == to_vertex(tet, twin));
    CHECK(from_vertex(tet, h) != to_vertex(tet, h));
    CHECK_OK(hedge_halfedge_face(tet, h, &face));
    CHECK(face < 4);
    uint32_t loop[8], n = 0;
    CHECK_OK(hedge_face_halfedges(tet, face, loop, 8, &n));
    CHECK(n == 3 && contains(loop, n, h));
    CHECK_OK(hedge_halfedge_edge(tet, h, &edge));
    CHECK(edge == h >> 1);
    CHECK_OK(hedge_halfedge_is_boundary(tet, h, &boundary));
    CHECK(boundary == 0);
    CHECK_OK(hedge_halfedge_is_deleted(tet, h, &deleted));
    CHECK(deleted == 0);
    CHECK_OK(hedge_mesh_find_halfedge(tet, from_vertex(tet, h), to_vertex(tet, h), &found));
    CHECK(found == h);
  }
  for (uint32_t e = 0; e < 6; ++e) {
    uint32_t h0 = 0, h1 = 0;
    int32_t boundary = -1, deleted = -1;
    CHECK_OK(hedge_edge_halfedge(tet, e, 0, &h0));
    CHECK_OK(hedge_edge_halfedge(tet, e, 1, &h1));
    CHECK(h0 == 2 * e && h1 == 2 * e + 1);
    CHECK_OK(hedge_edge_is_boundary(tet, e, &boundary));
    CHECK(boundary == 0);
    CHECK_OK(hedge_edge_is_deleted(tet, e, &deleted));
    CHECK(deleted == 0);
  }
  uint32_t unused = 77;
  CHECK_STATUS(hedge_edge_halfedge(tet, 0, 2, &unused), HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK(unused == 77);

  /* One-rings: every vertex of a tetrahedron neighbours the three others. */
  for (uint32_t v = 0; v < 4; ++v) {
    uint32_t out[8], ring[8], faces[8], n_out = 0, n_ring = 0, n_faces = 0, valence = 0, h = 0;
    int32_t boundary = -1, deleted = -1;
    CHECK_OK(hedge_vertex_halfedge(tet, v, &h));
    CHECK(from_vertex(tet, h) == v);
    CHECK_OK(hedge_vertex_valence(tet, v, &valence));
    CHECK(valence == 3);
    CHECK_OK(hedge_vertex_halfedges(tet, v, out, 8, &n_out));
    CHECK_OK(hedge_vertex_vertices(tet, v, ring, 8, &n_ring));
    CHECK_OK(hedge_vertex_faces(tet, v, faces, 8, &n_faces));
    CHECK(n_out == 3 && n_ring == 3 && n_faces == 3);
    CHECK(out[0] == h);
    for (uint32_t i = 0; i < 3; ++i) {
      CHECK(from_vertex(tet, out[i]) == v && to_vertex(tet, out[i]) == ring[i]);
      CHECK(ring[i] != v && ring[i] < 4);
      CHECK(faces[i] < 4);
    }
    CHECK(ring[0] != ring[1] && ring[1] != ring[2] && ring[0] != ring[2]);
    /* The faces about v are exactly the input triangles that use v. */
    for (uint32_t f = 0; f < 4; ++f) CHECK(contains(faces, 3, f) == contains(kTetTriangles + 3 * f, 3, v));
    CHECK_OK(hedge_vertex_is_boundary(tet, v, &boundary));
    CHECK(boundary == 0);
    CHECK_OK(hedge_vertex_is_deleted(tet, v, &deleted));
    CHECK(deleted == 0);
  }
  for (uint32_t f = 0; f < 4; ++f) {
    uint32_t corners[4], loop[4], n_corners = 0, n_loop = 0, valence = 0, h = 0;
    int32_t boundary = -1, deleted = -1;
    CHECK_OK(hedge_face_halfedge(tet, f, &h));
    CHECK_OK(hedge_face_halfedges(tet, f, loop, 4, &n_loop));
    CHECK_OK(hedge_face_vertices(tet, f, corners, 4, &n_corners));
    CHECK(n_loop == 3 && n_corners == 3 && loop[0] == h);
    for (uint32_t i = 0; i < 3; ++i) {
      uint32_t face = 0;
      CHECK(to_vertex(tet, loop[i]) == corners[i]);
      CHECK_OK(hedge_halfedge_face(tet, loop[i], &face));
      CHECK(face == f);
    }
    CHECK_OK(hedge_face_valence(tet, f, &valence));
    CHECK(valence == 3);
    CHECK_OK(hedge_face_is_boundary(tet, f, &boundary));
    CHECK(boundary == 0);
    CHECK_OK(hedge_face_is_deleted(tet, f, &deleted));
    CHECK(deleted == 0);
  }

  /* Caller buffers: too small reports the size needed and writes nothing. */
  {
    uint32_t ring[2] = {555, 556}, n = 0;
    CHECK_STATUS(hedge_vertex_vertices(tet, 0, ring, 2, &n), HEDGE_ERROR_BUFFER_TOO_SMALL);
    CHECK(n == 3 && ring[0] == 555 && ring[1] == 556);
    n = 0;
    CHECK_STATUS(hedge_face_vertices(tet, 0, NULL, 0, &n), HEDGE_ERROR_BUFFER_TOO_SMALL);
    CHECK(n == 3);
    CHECK_STATUS(hedge_face_vertices(tet, 0, NULL, 5, &n), HEDGE_ERROR_INVALID_ARGUMENT);
    CHECK_STATUS(hedge_face_vertices(tet, 0, ring, 2, NULL), HEDGE_ERROR_INVALID_ARGUMENT);
  }

  /* Element handles out of range. */
  {
    uint32_t out = 0;
    int32_t flag = 0;
    CHECK_STATUS(hedge_vertex_halfedge(tet, 4, &out), HEDGE_ERROR_BAD_HANDLE);
    CHECK_ERROR_HAS("vertex 4");
    CHECK_STATUS(hedge_halfedge_next(tet, 12, &out), HEDGE_ERROR_BAD_HANDLE);
    CHECK_STATUS(hedge_face_halfedge(tet, INVALID, &out), HEDGE_ERROR_BAD_HANDLE);
    CHECK_STATUS(hedge_vertex_is_deleted(tet, 4, &flag), HEDGE_ERROR_BAD_HANDLE);
    CHECK_STATUS(hedge_halfedge_is_deleted(tet, 12, &flag), HEDGE_ERROR_BAD_HANDLE);
    CHECK_STATUS(hedge_edge_is_deleted(tet, 6, &flag), HEDGE_ERROR_BAD_HANDLE);
    CHECK_STATUS(hedge_face_is_deleted(tet, 4, &flag), HEDGE_ERROR_BAD_HANDLE);
    CHECK_STATUS(hedge_mesh_find_halfedge(tet, 0, 9, &out), HEDGE_ERROR_BAD_HANDLE);
    CHECK_STATUS(hedge_halfedge_to_vertex(tet, 0, NULL), HEDGE_ERROR_INVALID_ARGUMENT);
  }

  /* Positions. */
  {
    float p[3] = {0, 0, 0};
    get_position(tet, 3, p);
    CHECK(p[0] == 0 && p[1] == 0 && p[2] == 1);
    CHECK_OK(hedge_set_vertex_position(tet, 3, 0.25f, 0.5f, 2));
    get_position(tet, 3, p);
    CHECK(p[0] == 0.25f && p[1] == 0.5f && p[2] == 2);
    CHECK_STATUS(hedge_set_vertex_position(tet, 3, NAN, 0, 0), HEDGE_ERROR_INVALID_ARGUMENT);
    CHECK_STATUS(hedge_set_vertex_position(tet, 3, 0, INFINITY, 0), HEDGE_ERROR_INVALID_ARGUMENT);
    CHECK_ERROR_HAS("not finite");
    get_position(tet, 3, p);
    CHECK(p[0] == 0.25f && p[1] == 0.5f && p[2] == 2);
    CHECK_OK(hedge_set_vertex_position(tet, 3, 0, 0, 1));

    float all[12];
    uint64_t n = 0;
    CHECK_STATUS(hedge_mesh_copy_positions(tet, all, 11, &n), HEDGE_ERROR_BUFFER_TOO_SMALL);
    CHECK(n == 12);
    CHECK_OK(hedge_mesh_copy_positions(tet, all, 12, &n));
    CHECK(n == 12 && memcmp(all, kTetPositions, sizeof all) == 0);
  }

  /* Every collapse of a tetrahedron is refused and changes nothing; no flip is possible either. */
  {
    float before[12], after[12];
    copy_positions(tet, before, 12);
    for (uint32_t h = 0; h < 12; ++h) {
      int32_t ok = -1;
      uint32_t survivor = 1234;
      CHECK_OK(hedge_can_collapse(tet, h, &ok));
      CHECK(ok == 0);
      CHECK_STATUS(hedge_collapse(tet, h, &survivor), HEDGE_ERROR_REFUSED);
      CHECK_ERROR_HAS("refused");
      CHECK_ERROR_HAS("would be left with too few edges"); /* the reason, not only the verdict */
      CHECK(strstr(hedge_last_refusal(), "would be left with too few edges") != NULL);
      CHECK(strstr(hedge_last_error(), hedge_last_refusal()) != NULL);
      CHECK(survivor == 1234);
      CHECK(same_counts(counts_of(tet), c));
      CHECK(next_of(tet, next_of(tet, next_of(tet, h))) == h);
    }
    for (uint32_t e = 0; e < 6; ++e) {
      int32_t ok = -1;
      CHECK_OK(hedge_can_flip(tet, e, &ok));
      CHECK(ok == 0);
      CHECK_STATUS(hedge_flip(tet, e), HEDGE_ERROR_REFUSED);
      CHECK(strcmp(hedge_last_refusal(),
                   "an end is an interior vertex of valence 3 (the flip would leave it with 2)") == 0);
    }
    CHECK_OK(hedge_mesh_validate(tet, &(uint32_t){1}));
    CHECK(strcmp(hedge_last_refusal(), "") == 0); /* cleared by a call that was not refused */
    CHECK_OK(hedge_can_flip(tet, 0, &(int32_t){1}));
    CHECK(hedge_last_refusal_code() == HEDGE_REFUSAL_FLIP_VALENCE_THREE); /* a predicate's "no" says why */
    CHECK_OK(hedge_can_split_edge(tet, 0, &(int32_t){0}));
    CHECK(hedge_last_refusal_code() == HEDGE_REFUSAL_NONE); /* and its "yes" clears it */
    copy_positions(tet, after, 12);
    CHECK(memcmp(before, after, sizeof before) == 0);
    for (uint32_t f = 0; f < 4; ++f) CHECK(face_is(tet, f, kTetTriangles + 3 * f, 3));
    CHECK_VALID(tet);
  }
  CHECK_OK(hedge_mesh_destroy(tet));
}
