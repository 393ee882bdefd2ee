/* Tests of the C ABI (include/hedge/c_api.h), compiled as C11. Every function of the header is
 * called at least once, with its error paths; tests/capi/check_coverage.cmake checks that.
 * Each CHECK reports file:line and exits non-zero on failure. */
#include "hedge/c_api.h"

#include <math.h>
#include <stdatomic.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <threads.h>

static int g_checks = 0;

#define CHECK(cond)                                                                                 \
  do {                                                                                              \
    ++g_checks;                                                                                     \
    if (!(cond)) {                                                                                  \
      fprintf(stderr, "%s:%d: CHECK failed: %s\n  last error: \"%s\"\n", __FILE__, __LINE__, #cond, \
              hedge_last_error());                                                                  \
      exit(1);                                                                                      \
    }                                                                                               \
  } while (0)

/* A call that must return `expected`. */
#define CHECK_STATUS(call, expected)                                                                    \
  do {                                                                                                  \
    const hedge_status status_ = (call);                                                                \
    ++g_checks;                                                                                         \
    if (status_ != (expected)) {                                                                        \
      fprintf(stderr, "%s:%d: %s returned %s, expected %s\n  last error: \"%s\"\n", __FILE__, __LINE__, \
              #call, hedge_status_string(status_), hedge_status_string(expected), hedge_last_error());  \
      exit(1);                                                                                          \
    }                                                                                                   \
  } while (0)

#define CHECK_OK(call) CHECK_STATUS(call, HEDGE_OK)

/* The message of the last failure contains `text`. */
#define CHECK_ERROR_HAS(text) CHECK(strstr(hedge_last_error(), (text)) != NULL)

#define INVALID HEDGE_INVALID_INDEX

/* ---------------------------------------------------------------------------------------------- */
/* Helpers                                                                                        */
/* ---------------------------------------------------------------------------------------------- */

static hedge_counts counts_of(const hedge_mesh* mesh) {
  hedge_counts c;
  memset(&c, 0xAB, sizeof c);
  CHECK_OK(hedge_mesh_counts(mesh, &c));
  return c;
}

static int same_counts(hedge_counts a, hedge_counts b) { return memcmp(&a, &b, sizeof a) == 0; }

/* validate() reports no problem: the count is 0, the report is "", problem 0 does not exist. */
static void check_valid_at(hedge_mesh* mesh, const char* file, int line) {
  uint32_t problems = 12345;
  char text[4096];
  uint32_t size = 0;
  if (hedge_mesh_validate(mesh, &problems) != HEDGE_OK || problems != 0) {
    fprintf(stderr, "%s:%d: mesh is not valid (%u problems): %s\n", file, line, (unsigned)problems,
            hedge_last_error());
    if (hedge_mesh_validation_report(mesh, text, sizeof text, &size) == HEDGE_OK)
      fprintf(stderr, "%s\n", text);
    exit(1);
  }
  ++g_checks;
  CHECK_OK(hedge_mesh_validation_report(mesh, text, sizeof text, &size));
  CHECK(size == 1 && text[0] == '\0');
  CHECK_STATUS(hedge_mesh_validation_problem(mesh, 0, text, sizeof text, &size),
               HEDGE_ERROR_INVALID_ARGUMENT);
}
#define CHECK_VALID(mesh) check_valid_at((mesh), __FILE__, __LINE__)

static void get_position(const hedge_mesh* mesh, uint32_t v, float out[3]) {
  CHECK_OK(hedge_mesh_get_position(mesh, v, out));
}

static uint32_t to_vertex(const hedge_mesh* mesh, uint32_t h) {
  uint32_t v = 0;
  CHECK_OK(hedge_halfedge_to_vertex(mesh, h, &v));
  return v;
}

static uint32_t from_vertex(const hedge_mesh* mesh, uint32_t h) {
  uint32_t v = 0;
  CHECK_OK(hedge_halfedge_from_vertex(mesh, h, &v));
  return v;
}

static uint32_t next_of(const hedge_mesh* mesh, uint32_t h) {
  uint32_t n = 0;
  CHECK_OK(hedge_halfedge_next(mesh, h, &n));
  return n;
}

static int contains(const uint32_t* a, uint32_t n, uint32_t x) {
  for (uint32_t i = 0; i < n; ++i)
    if (a[i] == x) return 1;
  return 0;
}

/* The corners of `face` equal `expected` (n corners) up to a rotation. */
static int face_is(const hedge_mesh* mesh, uint32_t face, const uint32_t* expected, uint32_t n) {
  uint32_t corners[16];
  uint32_t count = 0;
  CHECK_OK(hedge_face_vertices(mesh, face, corners, 16, &count));
  if (count != n) return 0;
  for (uint32_t shift = 0; shift < n; ++shift) {
    uint32_t i = 0;
    while (i < n && corners[(i + shift) % n] == expected[i]) ++i;
    if (i == n) return 1;
  }
  return 0;
}

static void copy_positions(const hedge_mesh* mesh, float* out, uint64_t capacity) {
  uint64_t count = 0;
  CHECK_OK(hedge_mesh_copy_positions(mesh, out, capacity, &count));
}

static void write_text(const char* path, const char* text) {
  FILE* f = fopen(path, "wb");
  CHECK(f != NULL);
  CHECK(fputs(text, f) >= 0);
  CHECK(fclose(f) == 0);
}

/* A tetrahedron, outward counter-clockwise faces. */
static const float kTetPositions[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
static const uint32_t kTetTriangles[] = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};

/* A square pyramid without its base: 4 triangles about apex 4, one boundary loop of 4 edges. */
static const float kPyramidPositions[] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0.5f, 0.5f, 1};
static const uint32_t kPyramidTriangles[] = {0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4};

/* A 3 x 3 grid of vertices (row-major, z = 0) in 2 x 2 quads. */
static const float kGridPositions[] = {0, 0, 0, 1, 0, 0, 2, 0, 0, 0, 1, 0, 1, 1,
                                       0, 2, 1, 0, 0, 2, 0, 1, 2, 0, 2, 2, 0};
static const uint32_t kGridQuads[] = {0, 1, 4, 3, 1, 2, 5, 4, 3, 4, 7, 6, 4, 5, 8, 7};
static const uint32_t kGridSizes[] = {4, 4, 4, 4};

static hedge_mesh* make_mesh(const float* positions, uint32_t nv, const uint32_t* indices, uint32_t ni,
                             const uint32_t* sizes, uint32_t nf) {
  hedge_mesh* mesh = NULL;
  CHECK_OK(hedge_mesh_create(positions, nv, indices, ni, sizes, nf, NULL, NULL, NULL, NULL, &mesh));
  CHECK(mesh != NULL);
  return mesh;
}

/* ---------------------------------------------------------------------------------------------- */
/* Status codes, errors, version                                                                  */
/* ---------------------------------------------------------------------------------------------- */

static void test_basics(void) {
  int32_t major = -1, minor = -1, patch = -1;
  CHECK_OK(hedge_version(&major, &minor, &patch));
  CHECK(major == HEDGE_TEST_VERSION_MAJOR && minor == HEDGE_TEST_VERSION_MINOR &&
        patch == HEDGE_TEST_VERSION_PATCH);
  CHECK(strcmp(hedge_last_error(), "") == 0);
  CHECK_STATUS(hedge_version(NULL, &minor, &patch), HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK_ERROR_HAS("out_major");
  /* A success clears the message. */
  CHECK_OK(hedge_version(&major, &minor, &patch));
  CHECK(strcmp(hedge_last_error(), "") == 0);

  CHECK(strcmp(hedge_status_string(HEDGE_OK), "HEDGE_OK") == 0);
  CHECK(strcmp(hedge_status_string(HEDGE_ERROR_INVALID_ARGUMENT), "HEDGE_ERROR_INVALID_ARGUMENT") == 0);
  CHECK(strcmp(hedge_status_string(HEDGE_ERROR_BAD_HANDLE), "HEDGE_ERROR_BAD_HANDLE") == 0);
  CHECK(strcmp(hedge_status_string(HEDGE_ERROR_REFUSED), "HEDGE_ERROR_REFUSED") == 0);
  CHECK(strcmp(hedge_status_string(HEDGE_ERROR_IO), "HEDGE_ERROR_IO") == 0);
  CHECK(strcmp(hedge_status_string(HEDGE_ERROR_TOPOLOGY), "HEDGE_ERROR_TOPOLOGY") == 0);
  CHECK(strcmp(hedge_status_string(HEDGE_ERROR_OUT_OF_MEMORY), "HEDGE_ERROR_OUT_OF_MEMORY") == 0);
  CHECK(strcmp(hedge_status_string(HEDGE_ERROR_BUFFER_TOO_SMALL), "HEDGE_ERROR_BUFFER_TOO_SMALL") == 0);
  CHECK(strcmp(hedge_status_string(HEDGE_ERROR_INTERNAL), "HEDGE_ERROR_INTERNAL") == 0);
  CHECK(strcmp(hedge_status_string(HEDGE_ERROR_BUSY), "HEDGE_ERROR_BUSY") == 0);
  CHECK(strcmp(hedge_status_string(42), "HEDGE_ERROR_UNKNOWN") == 0);

  /* All codes are distinct. */
  const hedge_status codes[] = {HEDGE_OK,
                                HEDGE_ERROR_INVALID_ARGUMENT,
                                HEDGE_ERROR_BAD_HANDLE,
                                HEDGE_ERROR_REFUSED,
                                HEDGE_ERROR_IO,
                                HEDGE_ERROR_TOPOLOGY,
                                HEDGE_ERROR_OUT_OF_MEMORY,
                                HEDGE_ERROR_BUFFER_TOO_SMALL,
                                HEDGE_ERROR_INTERNAL,
                                HEDGE_ERROR_BUSY};
  for (size_t i = 0; i < sizeof codes / sizeof codes[0]; ++i)
    for (size_t j = i + 1; j < sizeof codes / sizeof codes[0]; ++j) CHECK(codes[i] != codes[j]);

  /* Struct layouts documented in the header. */
  CHECK(sizeof(hedge_build_options) == 16);
  CHECK(sizeof(hedge_build_report) == 36);
  CHECK(sizeof(hedge_counts) == 32);
  CHECK(sizeof(hedge_render_options) == 24);
  CHECK(sizeof(hedge_vertex_layout) == 24);
  CHECK(sizeof(hedge_range) == 8);
  CHECK(sizeof(hedge_sync_result) == 40);
  CHECK(sizeof(hedge_buffer_counts) == 40);
  CHECK(sizeof(hedge_engine_import_options) == 24);
}

/* ---------------------------------------------------------------------------------------------- */
/* Creation, queries and the refused collapse of a tetrahedron                                    */
/* ---------------------------------------------------------------------------------------------- */

static void test_tetrahedron(void) {
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
    CHECK_OK(hedge_mesh_set_position(tet, 3, 0.25f, 0.5f, 2));
    get_position(tet, 3, p);
    CHECK(p[0] == 0.25f && p[1] == 0.5f && p[2] == 2);
    CHECK_STATUS(hedge_mesh_set_position(tet, 3, NAN, 0, 0), HEDGE_ERROR_INVALID_ARGUMENT);
    CHECK_STATUS(hedge_mesh_set_position(tet, 3, 0, INFINITY, 0), HEDGE_ERROR_INVALID_ARGUMENT);
    CHECK_ERROR_HAS("not finite");
    get_position(tet, 3, p);
    CHECK(p[0] == 0.25f && p[1] == 0.5f && p[2] == 2);
    CHECK_OK(hedge_mesh_set_position(tet, 3, 0, 0, 1));

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
    CHECK_OK(hedge_can_flip(tet, 0, &(int32_t){0}));
    CHECK(strcmp(hedge_last_refusal(), "") == 0); /* cleared by a call that was not refused */
    copy_positions(tet, after, 12);
    CHECK(memcmp(before, after, sizeof before) == 0);
    for (uint32_t f = 0; f < 4; ++f) CHECK(face_is(tet, f, kTetTriangles + 3 * f, 3));
    CHECK_VALID(tet);
  }
  CHECK_OK(hedge_mesh_destroy(tet));
}

/* ---------------------------------------------------------------------------------------------- */
/* Handles: NULL, destroyed, never created, of the wrong kind                                     */
/* ---------------------------------------------------------------------------------------------- */

static void test_bad_handles(void) {
  hedge_counts c;
  uint32_t out = 0;
  CHECK_STATUS(hedge_mesh_counts(NULL, &c), HEDGE_ERROR_BAD_HANDLE);
  CHECK_ERROR_HAS("NULL");
  CHECK_STATUS(hedge_mesh_destroy(NULL), HEDGE_ERROR_BAD_HANDLE);
  CHECK_STATUS(hedge_render_destroy(NULL), HEDGE_ERROR_BAD_HANDLE);
  CHECK_STATUS(hedge_render_sync(NULL, NULL), HEDGE_ERROR_BAD_HANDLE);

  hedge_mesh* mesh = make_mesh(kTetPositions, 4, kTetTriangles, 12, NULL, 0);
  CHECK_OK(hedge_mesh_counts(mesh, &c));
  CHECK(c.faces == 4);
  CHECK_OK(hedge_mesh_destroy(mesh));
  CHECK_STATUS(hedge_mesh_counts(mesh, &c), HEDGE_ERROR_BAD_HANDLE);
  CHECK_ERROR_HAS("not a live mesh");
  CHECK_STATUS(hedge_halfedge_twin(mesh, 0, &out), HEDGE_ERROR_BAD_HANDLE);
  CHECK_STATUS(hedge_split_all_faces(mesh, NULL, 0, &out), HEDGE_ERROR_BAD_HANDLE);
  CHECK_STATUS(hedge_mesh_destroy(mesh), HEDGE_ERROR_BAD_HANDLE);

  /* A value that was never a handle. */
  hedge_mesh* garbage = (hedge_mesh*)(uintptr_t)0x5a5a5a50u;
  CHECK_STATUS(hedge_mesh_counts(garbage, &c), HEDGE_ERROR_BAD_HANDLE);
  CHECK_STATUS(hedge_mesh_destroy(garbage), HEDGE_ERROR_BAD_HANDLE);

  /* A new mesh never gets the destroyed one's handle. */
  hedge_mesh* again = make_mesh(kTetPositions, 4, kTetTriangles, 12, NULL, 0);
  CHECK(again != mesh);
  CHECK_STATUS(hedge_mesh_counts(mesh, &c), HEDGE_ERROR_BAD_HANDLE);

  /* A render handle is not a mesh handle, nor the reverse. */
  hedge_render* render = NULL;
  CHECK_OK(hedge_render_create(again, NULL, &render));
  CHECK_STATUS(hedge_mesh_counts((const hedge_mesh*)render, &c), HEDGE_ERROR_BAD_HANDLE);
  CHECK_STATUS(hedge_render_sync((hedge_render*)again, NULL), HEDGE_ERROR_BAD_HANDLE);
  CHECK_OK(hedge_render_destroy(render));
  CHECK_STATUS(hedge_render_destroy(render), HEDGE_ERROR_BAD_HANDLE);
  CHECK_STATUS(hedge_render_sync(render, NULL), HEDGE_ERROR_BAD_HANDLE);
  CHECK_OK(hedge_mesh_destroy(again));
}

/* ---------------------------------------------------------------------------------------------- */
/* Input checks and the repair policy                                                             */
/* ---------------------------------------------------------------------------------------------- */

static void test_create_errors(void) {
  hedge_mesh* mesh = NULL;
  hedge_build_options options;
  CHECK_OK(hedge_build_options_default(&options));

  CHECK_STATUS(hedge_mesh_create(kTetPositions, 4, kTetTriangles, 12, NULL, 0, NULL, NULL, NULL, NULL, NULL),
               HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK_STATUS(hedge_mesh_create(NULL, 4, kTetTriangles, 12, NULL, 0, NULL, NULL, NULL, NULL, &mesh),
               HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK_ERROR_HAS("positions");
  CHECK_STATUS(hedge_mesh_create(kTetPositions, 4, kTetTriangles, 11, NULL, 0, NULL, NULL, NULL, NULL, &mesh),
               HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK_STATUS(hedge_mesh_create(kTetPositions, 4, kTetTriangles, 12, NULL, 3, NULL, NULL, NULL, NULL, &mesh),
               HEDGE_ERROR_INVALID_ARGUMENT);
  /* face sizes that do not add up */
  const uint32_t sizes[] = {3, 3, 3, 4};
  CHECK_STATUS(
      hedge_mesh_create(kTetPositions, 4, kTetTriangles, 12, sizes, 4, NULL, NULL, NULL, NULL, &mesh),
      HEDGE_ERROR_INVALID_ARGUMENT);
  /* an index out of range */
  const uint32_t bad_index[] = {0, 1, 7};
  CHECK_STATUS(hedge_mesh_create(kTetPositions, 4, bad_index, 3, NULL, 0, NULL, NULL, NULL, NULL, &mesh),
               HEDGE_ERROR_INVALID_ARGUMENT);
  /* a NaN coordinate */
  float nan_positions[12];
  memcpy(nan_positions, kTetPositions, sizeof nan_positions);
  nan_positions[4] = NAN;
  CHECK_STATUS(hedge_mesh_create(nan_positions, 4, kTetTriangles, 12, NULL, 0, NULL, NULL, NULL, NULL, &mesh),
               HEDGE_ERROR_INVALID_ARGUMENT);
  /* bad enum values */
  options.weld = 7;
  CHECK_STATUS(
      hedge_mesh_create(kTetPositions, 4, kTetTriangles, 12, NULL, 0, &options, NULL, NULL, NULL, &mesh),
      HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK_ERROR_HAS("weld");
  CHECK(mesh == NULL);

  /* Three triangles on one edge: strict refuses with a topology error, repair cuts the edge. */
  const float fin_positions[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1};
  const uint32_t fin[] = {0, 1, 2, 1, 0, 3, 0, 1, 4};
  hedge_build_options strict = options;
  strict.policy = HEDGE_POLICY_STRICT;
  strict.weld = HEDGE_WELD_NONE;
  CHECK_STATUS(hedge_mesh_create(fin_positions, 5, fin, 9, NULL, 0, &strict, NULL, NULL, NULL, &mesh),
               HEDGE_ERROR_TOPOLOGY);
  CHECK(strlen(hedge_last_error()) > 0);
  CHECK(mesh == NULL);
  hedge_build_report report;
  uint32_t face_map[3] = {9, 9, 9};
  hedge_build_options repair = strict;
  repair.policy = HEDGE_POLICY_REPAIR;
  CHECK_OK(hedge_mesh_create(fin_positions, 5, fin, 9, NULL, 0, &repair, &report, NULL, face_map, &mesh));
  CHECK(report.non_manifold_edges >= 1 && report.repairs >= 1);
  CHECK(counts_of(mesh).faces == 3);
  CHECK(face_map[0] != INVALID && face_map[1] != INVALID && face_map[2] != INVALID);
  CHECK_VALID(mesh);
  CHECK_OK(hedge_mesh_destroy(mesh));

  /* Exact welding of a triangle soup: two triangles of a square, six input vertices. */
  const float soup[] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 0, 0, 1, 1, 0, 0, 1, 0};
  const uint32_t soup_triangles[] = {0, 1, 2, 3, 4, 5};
  hedge_build_options weld = repair;
  weld.weld = HEDGE_WELD_EXACT;
  uint32_t vertex_map[6];
  CHECK_OK(hedge_mesh_create(soup, 6, soup_triangles, 6, NULL, 0, &weld, &report, vertex_map, NULL, &mesh));
  CHECK(report.welded_vertices == 2);
  CHECK(vertex_map[3] == vertex_map[0] && vertex_map[4] == vertex_map[2]);
  CHECK(vertex_map[0] != vertex_map[1] && vertex_map[5] != vertex_map[0]);
  const hedge_counts c = counts_of(mesh);
  CHECK(c.vertices == 4 && c.faces == 2 && c.edges == 5);
  CHECK_VALID(mesh);
  CHECK_OK(hedge_mesh_destroy(mesh));

  /* An empty mesh is fine. */
  CHECK_OK(hedge_mesh_create(NULL, 0, NULL, 0, NULL, 0, NULL, NULL, NULL, NULL, &mesh));
  CHECK(counts_of(mesh).vertices == 0);
  CHECK_VALID(mesh);
  CHECK_OK(hedge_mesh_destroy(mesh));
}

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

static void test_pyramid_operations(void) {
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
  CHECK_STATUS(hedge_split_all_faces(mesh, added, c.faces - 1, &n_added), HEDGE_ERROR_BUFFER_TOO_SMALL);
  CHECK(n_added == c.faces);
  CHECK(same_counts(counts_of(mesh), c));
  CHECK_OK(hedge_split_all_faces(mesh, added, 64, &n_added));
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
  CHECK_OK(hedge_split_all_faces(mesh, NULL, 0, &n_added));
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

static void test_grid_operations(void) {
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
}

/* ---------------------------------------------------------------------------------------------- */
/* Files                                                                                          */
/* ---------------------------------------------------------------------------------------------- */

static void test_files(void) {
  hedge_mesh* spot = NULL;
  hedge_build_report report;
  CHECK_OK(hedge_mesh_read(HEDGE_DATA_DIR "/spot_control_mesh.obj", NULL, &report, &spot));
  const hedge_counts c = counts_of(spot);
  CHECK(c.vertices == 188 && c.faces == 180 && c.edges == 366);
  CHECK((int64_t)c.vertices - c.edges + c.faces == 2); /* a sphere */
  CHECK(report.repairs == 0);
  CHECK_VALID(spot);

  /* Write binary PLY, read it back. */
  const char* ply = HEDGE_TEST_OUTPUT_DIR "/c_api_test_spot.ply";
  CHECK_OK(hedge_mesh_write(spot, ply, 1, 0));
  hedge_mesh* back = NULL;
  hedge_build_options strict;
  CHECK_OK(hedge_build_options_default(&strict));
  strict.policy = HEDGE_POLICY_STRICT;
  CHECK_OK(hedge_mesh_read(ply, &strict, NULL, &back));
  CHECK(same_counts(counts_of(back), c));
  float p[3], q[3];
  get_position(spot, 17, p);
  get_position(back, 17, q);
  CHECK(p[0] == q[0] && p[1] == q[1] && p[2] == q[2]);
  CHECK_OK(hedge_mesh_destroy(back));
  /* ASCII OBJ with 3 significant digits: positions rounded. */
  const char* obj = HEDGE_TEST_OUTPUT_DIR "/c_api_test_spot.obj";
  CHECK_OK(hedge_mesh_write(spot, obj, 0, 3));
  CHECK_OK(hedge_mesh_read(obj, NULL, NULL, &back));
  CHECK(same_counts(counts_of(back), c));
  CHECK_OK(hedge_mesh_destroy(back));
  CHECK_STATUS(hedge_mesh_write(spot, obj, 2, 0), HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK_STATUS(hedge_mesh_write(spot, NULL, 1, 0), HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK_STATUS(hedge_mesh_write(spot, HEDGE_TEST_OUTPUT_DIR "/spot.unknown", 1, 0), HEDGE_ERROR_IO);
  CHECK_STATUS(hedge_mesh_write(NULL, obj, 1, 0), HEDGE_ERROR_BAD_HANDLE);
  CHECK_OK(hedge_mesh_destroy(spot));

  /* A malformed OBJ: the error names the file and line 4. */
  const char* broken = HEDGE_TEST_OUTPUT_DIR "/c_api_test_broken.obj";
  write_text(broken, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 x\n");
  hedge_mesh* bad = NULL;
  CHECK_STATUS(hedge_mesh_read(broken, NULL, NULL, &bad), HEDGE_ERROR_IO);
  CHECK(bad == NULL);
  CHECK_ERROR_HAS("c_api_test_broken.obj:4:");
  CHECK_STATUS(hedge_mesh_read(HEDGE_TEST_OUTPUT_DIR "/does_not_exist.obj", NULL, NULL, &bad),
               HEDGE_ERROR_IO);
  CHECK_ERROR_HAS("does_not_exist.obj");
  CHECK_STATUS(hedge_mesh_read(NULL, NULL, NULL, &bad), HEDGE_ERROR_INVALID_ARGUMENT);
  remove(broken);
  remove(ply);
  remove(obj);
}

/* Hostile files: a glTF reads no file outside its folder, deep JSON and huge asks are refused. */
static const char* kTriangleGltfHead =
    "{\"asset\":{\"version\":\"2.0\"},\"scenes\":[{\"nodes\":[0]}],\"nodes\":[{\"mesh\":0}],"
    "\"meshes\":[{\"primitives\":[{\"attributes\":{\"POSITION\":0}}]}],"
    "\"accessors\":[{\"bufferView\":0,\"componentType\":5126,\"count\":3,\"type\":\"VEC3\"}],"
    "\"bufferViews\":[{\"buffer\":0,\"byteLength\":36}],";
/* The triangle's 36 bytes of positions (0,0,0 1,0,0 0,1,0), base64. */
#define TRIANGLE_BASE64 "AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"

static void write_gltf_with_buffer(const char* path, const char* buffer_json) {
  char text[2048];
  snprintf(text, sizeof text, "%s\"buffers\":[%s]}", kTriangleGltfHead, buffer_json);
  write_text(path, text);
}

static void test_hostile_files(void) {
  CHECK(sizeof(hedge_read_options) == 16);
  hedge_read_options read;
  CHECK_OK(hedge_read_options_default(&read));
  CHECK(read.external_buffers == 1 && read.reserved == 0 && read.max_memory == 0);
  CHECK_STATUS(hedge_read_options_default(NULL), HEDGE_ERROR_INVALID_ARGUMENT);

  const char* path = HEDGE_TEST_OUTPUT_DIR "/c_api_hostile.gltf";
  hedge_mesh* mesh = NULL;
  /* Embedded: read, by path and from memory. */
  write_gltf_with_buffer(
      path, "{\"byteLength\":36,\"uri\":\"data:application/octet-stream;base64," TRIANGLE_BASE64 "\"}");
  CHECK_OK(hedge_mesh_read_with(path, NULL, &read, NULL, &mesh));
  CHECK(counts_of(mesh).faces == 1);
  CHECK_VALID(mesh);
  CHECK_OK(hedge_mesh_destroy(mesh));
  char text[4096];
  FILE* f = fopen(path, "rb");
  CHECK(f != NULL);
  const size_t size = fread(text, 1, sizeof text, f);
  fclose(f);
  mesh = NULL;
  CHECK_OK(hedge_mesh_read_memory(text, size, "upload.gltf", NULL, NULL, NULL, &mesh));
  CHECK(counts_of(mesh).faces == 1);
  CHECK_OK(hedge_mesh_destroy(mesh));
  /* A budget smaller than the file needs; the message says how to raise it. */
  read.max_memory = 100;
  mesh = NULL;
  CHECK_STATUS(hedge_mesh_read_memory(text, size, "upload.gltf", NULL, &read, NULL, &mesh), HEDGE_ERROR_IO);
  CHECK(mesh == NULL);
  CHECK_ERROR_HAS("upload.gltf: its JSON");
  CHECK_ERROR_HAS("more than the read budget of 100 bytes");
  CHECK_ERROR_HAS("max_memory");
  read.max_memory = 0;
  read.reserved = 7;
  CHECK_STATUS(hedge_mesh_read_memory(text, size, "upload.gltf", NULL, &read, NULL, &mesh),
               HEDGE_ERROR_INVALID_ARGUMENT);
  read.reserved = 0;
  read.external_buffers = 2;
  CHECK_STATUS(hedge_mesh_read_with(path, NULL, &read, NULL, &mesh), HEDGE_ERROR_INVALID_ARGUMENT);
  read.external_buffers = 1;
  CHECK_STATUS(hedge_mesh_read_memory(NULL, 10, "upload.gltf", NULL, NULL, NULL, &mesh),
               HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK_STATUS(hedge_mesh_read_memory(text, size, NULL, NULL, NULL, NULL, &mesh),
               HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK_STATUS(hedge_mesh_read_memory(text, size, "upload.txt", NULL, NULL, NULL, &mesh), HEDGE_ERROR_IO);
  CHECK_OK(
      hedge_mesh_read_memory("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", 32, "t.obj", NULL, NULL, NULL, &mesh));
  CHECK(counts_of(mesh).faces == 1);
  CHECK_OK(hedge_mesh_destroy(mesh));

  /* A buffer outside the file's folder, by path or by a climb: refused, nothing of it quoted. */
  mesh = NULL;
  write_gltf_with_buffer(path, "{\"byteLength\":1221,\"uri\":\"../../../../../../../../../../etc/passwd\"}");
  CHECK_STATUS(hedge_mesh_read(path, NULL, NULL, &mesh), HEDGE_ERROR_IO);
  CHECK(mesh == NULL);
  CHECK_ERROR_HAS(
      "buffer 0: uri '../../../../../../../../../../etc/passwd' does not name a regular file inside");
  CHECK(strstr(hedge_last_error(), "root") == NULL);
  write_gltf_with_buffer(path, "{\"byteLength\":1221,\"uri\":\"/etc/passwd\"}");
  CHECK_STATUS(hedge_mesh_read_with(path, NULL, NULL, NULL, &mesh), HEDGE_ERROR_IO);
  CHECK_ERROR_HAS("uri is an absolute path");
  write_gltf_with_buffer(path, "{\"byteLength\":5,\"uri\":\"data:text/plain,hello\"}");
  CHECK_STATUS(hedge_mesh_read(path, NULL, NULL, &mesh), HEDGE_ERROR_IO);
  CHECK_ERROR_HAS("a data URI must be base64 application/octet-stream or application/gltf-buffer");
  /* A buffer beside the file: read by path; from memory only when the caller turns it on. */
  const char* bin = HEDGE_TEST_OUTPUT_DIR "/c_api_hostile.bin";
  static const float kPositions[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  f = fopen(bin, "wb");
  CHECK(f != NULL && fwrite(kPositions, sizeof kPositions, 1, f) == 1);
  fclose(f);
  write_gltf_with_buffer(path, "{\"byteLength\":36,\"uri\":\"c_api_hostile.bin\"}");
  CHECK_OK(hedge_mesh_read(path, NULL, NULL, &mesh));
  CHECK(counts_of(mesh).faces == 1);
  CHECK_OK(hedge_mesh_destroy(mesh));
  f = fopen(path, "rb");
  const size_t external_size = fread(text, 1, sizeof text, f);
  fclose(f);
  mesh = NULL;
  CHECK_STATUS(hedge_mesh_read_memory(text, external_size, path, NULL, NULL, NULL, &mesh), HEDGE_ERROR_IO);
  CHECK_ERROR_HAS("reading external buffers is turned off");
  CHECK_OK(hedge_mesh_read_memory(text, external_size, path, NULL, &read, NULL, &mesh));
  CHECK(counts_of(mesh).faces == 1);
  CHECK_OK(hedge_mesh_destroy(mesh));
  read.external_buffers = 0;
  CHECK_STATUS(hedge_mesh_read_with(path, NULL, &read, NULL, &mesh), HEDGE_ERROR_IO);
  CHECK_ERROR_HAS("turned off");

  /* 17,000 nested arrays in extras crashed the parser's recursion: now an I/O error. */
  enum { kDepth = 17000 };
  char* deep = malloc(2 * kDepth + 64);
  CHECK(deep != NULL);
  strcpy(deep, "{\"extras\":");
  size_t n = strlen(deep);
  for (int i = 0; i < kDepth; ++i) deep[n++] = '[';
  for (int i = 0; i < kDepth; ++i) deep[n++] = ']';
  strcpy(deep + n, "}");
  mesh = NULL;
  CHECK_STATUS(hedge_mesh_read_memory(deep, strlen(deep), "deep.gltf", NULL, NULL, NULL, &mesh),
               HEDGE_ERROR_IO);
  CHECK_ERROR_HAS("deep.gltf: malformed glTF: JSON nested deeper than 64 levels");
  free(deep);
  remove(path);
  remove(bin);
}

/* ---------------------------------------------------------------------------------------------- */
/* Validation text                                                                                */
/* ---------------------------------------------------------------------------------------------- */

static void test_validation_text(void) {
  hedge_mesh* mesh = make_mesh(kTetPositions, 4, kTetTriangles, 12, NULL, 0);
  uint32_t problems = 99, size = 0;
  char text[8] = "xxxxxxx";
  /* Before any validation there are no problems recorded. */
  CHECK_OK(hedge_mesh_validation_report(mesh, text, sizeof text, &size));
  CHECK(size == 1 && text[0] == '\0');
  CHECK_OK(hedge_mesh_validate(mesh, &problems));
  CHECK(problems == 0);
  CHECK_STATUS(hedge_mesh_validation_problem(mesh, 0, text, sizeof text, &size),
               HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK_ERROR_HAS("problem 0");
  CHECK_STATUS(hedge_mesh_validate(mesh, NULL), HEDGE_ERROR_INVALID_ARGUMENT);
  /* An empty report in a zero-capacity buffer is too small: it needs the NUL. */
  CHECK_STATUS(hedge_mesh_validation_report(mesh, NULL, 0, &size), HEDGE_ERROR_BUFFER_TOO_SMALL);
  CHECK(size == 1);
  CHECK_OK(hedge_mesh_destroy(mesh));
}

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
static void check_triangles_match(const hedge_mesh* mesh, const hedge_render* render) {
  hedge_counts mc = counts_of(mesh);
  hedge_buffer_counts rc;
  CHECK_OK(hedge_render_counts(render, &rc));
  const uint32_t* indices = NULL;
  uint64_t n_indices = 0;
  CHECK_OK(hedge_render_index_data(render, &indices, &n_indices));
  CHECK(n_indices == rc.index_count);
  uint32_t* source = malloc(sizeof(uint32_t) * (rc.vertex_slots + 1));
  uint32_t n_source = 0;
  CHECK(source != NULL);
  CHECK_OK(hedge_render_vertex_source(render, source, rc.vertex_slots + 1, &n_source));
  CHECK(n_source == rc.vertex_slots);
  uint32_t live_triangles = 0;
  for (uint32_t f = 0; f < mc.face_slots; ++f) {
    int32_t deleted = 1;
    CHECK_OK(hedge_face_is_deleted(mesh, f, &deleted));
    if (deleted) continue;
    uint32_t first = INVALID, count = 0, corners[8], loop[8], n = 0;
    CHECK_OK(hedge_render_face_triangles(render, f, &first, &count));
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
      CHECK_OK(hedge_render_corner_vertex(render, loop[k], &rv));
      CHECK(rv == t[0] || rv == t[1] || rv == t[2]);
      CHECK(source[rv] == corners[k]);
    }
  }
  CHECK(live_triangles == rc.triangles);
  free(source);
}

static void test_render(void) {
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

  hedge_render_options options;
  memset(&options, 0xFF, sizeof options);
  CHECK_OK(hedge_render_options_default(&options));
  CHECK(options.normals == HEDGE_NORMALS_AUTOMATIC && options.texcoords == 1 && options.colors == 1);
  CHECK(options.interleaved == 1 && options.winding == HEDGE_WINDING_CCW && options.flip_x == 0);
  hedge_render* render = NULL;
  {
    hedge_render_options wrong = options;
    wrong.normals = 9;
    CHECK_STATUS(hedge_render_create(mesh, &wrong, &render), HEDGE_ERROR_INVALID_ARGUMENT);
    CHECK(render == NULL);
    CHECK_STATUS(hedge_render_create(NULL, &options, &render), HEDGE_ERROR_BAD_HANDLE);
  }
  CHECK_OK(hedge_render_create(mesh, &options, &render));

  /* Layout: position, computed normal, texcoord, colour. */
  hedge_vertex_layout layout;
  CHECK_OK(hedge_render_layout(render, &layout));
  CHECK(layout.interleaved == 1 && layout.stride == 12);
  CHECK(layout.position == 0 && layout.normal == 3 && layout.texcoord == 6 && layout.color == 8);

  hedge_buffer_counts rc;
  CHECK_OK(hedge_render_counts(render, &rc));
  CHECK(rc.vertex_slots == 5 && rc.vertices == 5 && rc.seam_splits == 1);
  CHECK(rc.free_triangle_slots == 0);
  CHECK(rc.vertex_capacity >= rc.vertex_slots && rc.index_capacity >= rc.index_count);
  CHECK(rc.index_count == 6 && rc.triangles == 2 && rc.free_triangle_slots == 0);
  CHECK(rc.buffer_bytes == (uint64_t)rc.vertex_slots * layout.stride * 4 + (uint64_t)rc.index_count * 4);

  /* The first build is a full one. */
  hedge_sync_result result;
  CHECK_OK(hedge_render_last_result(render, &result));
  CHECK(result.full == 1 && result.resized == 1);

  /* Vertex data: pointer and copy agree; every engine (position, texcoord) pair is present. */
  const float* data = NULL;
  uint64_t n_data = 0;
  CHECK_OK(hedge_render_vertex_data(render, HEDGE_STREAM_VERTICES, &data, &n_data));
  CHECK(data != NULL && n_data == (uint64_t)rc.vertex_slots * layout.stride);
  float copied[256];
  uint64_t n_copied = 0;
  CHECK_STATUS(hedge_render_copy_vertex_data(render, HEDGE_STREAM_VERTICES, copied, n_data - 1, &n_copied),
               HEDGE_ERROR_BUFFER_TOO_SMALL);
  CHECK(n_copied == n_data);
  CHECK_OK(hedge_render_copy_vertex_data(render, HEDGE_STREAM_VERTICES, copied, 256, &n_copied));
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
  CHECK_OK(hedge_render_vertex_data(render, HEDGE_STREAM_NORMALS, &data, &n_data));
  CHECK(data == NULL && n_data == 0);
  CHECK_STATUS(hedge_render_vertex_data(render, 7, &data, &n_data), HEDGE_ERROR_INVALID_ARGUMENT);

  /* Index data. */
  const uint32_t* indices = NULL;
  uint64_t n_indices = 0;
  uint32_t index_copy[64];
  CHECK_OK(hedge_render_index_data(render, &indices, &n_indices));
  CHECK(n_indices == 6);
  CHECK_STATUS(hedge_render_copy_index_data(render, index_copy, 5, &n_indices), HEDGE_ERROR_BUFFER_TOO_SMALL);
  CHECK(n_indices == 6);
  CHECK_OK(hedge_render_copy_index_data(render, index_copy, 64, &n_indices));
  CHECK(n_indices == 6 && memcmp(index_copy, indices, 6 * sizeof(uint32_t)) == 0);
  check_triangles_match(mesh, render);

  /* Move a vertex: the sync rewrites its render vertices only. */
  uint32_t source[16], n_source = 0;
  CHECK_OK(hedge_render_vertex_source(render, source, 16, &n_source));
  CHECK(n_source == 5);
  CHECK_STATUS(hedge_render_vertex_source(render, source, 4, &n_source), HEDGE_ERROR_BUFFER_TOO_SMALL);
  CHECK_OK(hedge_mesh_set_position(mesh, 1, 1, 0, 0.5f));
  CHECK_OK(hedge_render_sync(render, &result));
  CHECK(result.full == 0 && result.resized == 0 && result.vertex_range_count >= 1);
  CHECK(result.vertex_bytes > 0);
  {
    hedge_range ranges[16];
    uint32_t n_ranges = 0;
    CHECK_STATUS(hedge_render_dirty_vertex_ranges(render, ranges, 0, &n_ranges),
                 HEDGE_ERROR_BUFFER_TOO_SMALL);
    CHECK(n_ranges == result.vertex_range_count);
    CHECK_OK(hedge_render_dirty_vertex_ranges(render, ranges, 16, &n_ranges));
    CHECK(n_ranges == result.vertex_range_count);
    int covered = 0;
    for (uint32_t r = 0; r < n_source; ++r) {
      if (source[r] != 1) continue;
      for (uint32_t i = 0; i < n_ranges; ++i)
        if (r >= ranges[i].first && r < ranges[i].first + ranges[i].count) covered = 1;
    }
    CHECK(covered);
    CHECK_OK(hedge_render_dirty_index_ranges(render, ranges, 16, &n_ranges));
    CHECK(n_ranges == result.index_range_count);
    CHECK_OK(hedge_render_vertex_data(render, HEDGE_STREAM_VERTICES, &data, &n_data));
    for (uint32_t r = 0; r < n_source; ++r)
      if (source[r] == 1) CHECK(data[r * layout.stride + 2] == 0.5f);
  }
  /* Nothing changed since: an empty sync. */
  CHECK_OK(hedge_render_sync(render, &result));
  CHECK(result.vertex_range_count == 0 && result.index_range_count == 0 && result.full == 0);

  /* A transaction: the edits appear at commit. */
  CHECK_STATUS(hedge_render_commit(render, &result), HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK_OK(hedge_render_begin(render));
  uint32_t diagonal = 0, mid = 0;
  CHECK_OK(hedge_mesh_find_halfedge(mesh, 0, 2, &diagonal));
  CHECK(diagonal != INVALID);
  CHECK_OK(hedge_split_edge(mesh, diagonal >> 1, 0.5f, 0.5f, 0, &mid));
  CHECK_OK(hedge_render_sync(render, &result)); /* inside the transaction: nothing */
  CHECK(result.vertex_range_count == 0 && result.index_range_count == 0);
  CHECK_OK(hedge_render_commit(render, &result));
  CHECK(result.faces_synced >= 4 && result.index_range_count >= 1);
  CHECK_OK(hedge_render_counts(render, &rc));
  CHECK(rc.triangles == 4);
  CHECK_VALID(mesh);
  check_triangles_match(mesh, render);

  /* Remove a face: its triangle becomes a hole until compact(). */
  CHECK_OK(hedge_remove_face(mesh, 0));
  CHECK_OK(hedge_render_sync(render, NULL));
  CHECK_OK(hedge_render_counts(render, &rc));
  CHECK(rc.triangles == 3 && rc.index_count == 12);
  CHECK_VALID(mesh);
  check_triangles_match(mesh, render);
  {
    uint32_t vmap[32], tmap[32], nv = 0, nt = 0;
    CHECK_STATUS(hedge_render_compact(render, vmap, 32, &nv, tmap, 1, &nt), HEDGE_ERROR_BUFFER_TOO_SMALL);
    CHECK(nv == rc.vertex_slots && nt == 4);
    CHECK_OK(hedge_render_compact(render, vmap, 32, &nv, tmap, 32, &nt));
    uint32_t freed = 0;
    for (uint32_t t = 0; t < nt; ++t) freed += tmap[t] == INVALID;
    CHECK(freed == 1);
    hedge_buffer_counts after;
    CHECK_OK(hedge_render_counts(render, &after));
    CHECK(after.index_count == 9 && after.triangles == 3 && after.vertex_slots == after.vertices);
    check_triangles_match(mesh, render);
    CHECK_OK(hedge_render_compact(render, NULL, 0, NULL, NULL, 0, NULL));
  }

  /* Rebuild and garbage collection: full syncs. */
  CHECK_OK(hedge_render_rebuild(render, &result));
  CHECK(result.full == 1);
  CHECK_OK(hedge_mesh_garbage_collection(mesh, NULL, 0, NULL, 0, NULL, 0, NULL, 0));
  CHECK_OK(hedge_render_sync(render, &result));
  CHECK(result.full == 1);
  CHECK_VALID(mesh);
  check_triangles_match(mesh, render);
  {
    uint32_t rv = 0, first = 0, count = 0;
    CHECK_STATUS(hedge_render_corner_vertex(render, 999, &rv), HEDGE_ERROR_BAD_HANDLE);
    CHECK_STATUS(hedge_render_face_triangles(render, 999, &first, &count), HEDGE_ERROR_BAD_HANDLE);
  }

  /* A second render object: separate streams, x flipped, clockwise. */
  hedge_render_options separate = options;
  separate.interleaved = 0;
  separate.flip_x = 1;
  separate.winding = HEDGE_WINDING_CW;
  separate.normals = HEDGE_NORMALS_COMPUTED;
  hedge_render* render2 = NULL;
  CHECK_OK(hedge_render_create(mesh, &separate, &render2));
  CHECK_OK(hedge_render_layout(render2, &layout));
  CHECK(layout.interleaved == 0 && layout.position == 0 && layout.normal == 0 && layout.stride == 12);
  hedge_buffer_counts rc2;
  CHECK_OK(hedge_render_counts(render2, &rc2));
  const float* positions = NULL;
  const float* normals = NULL;
  uint64_t n_positions = 0, n_normals = 0;
  CHECK_OK(hedge_render_vertex_data(render2, HEDGE_STREAM_VERTICES, &positions, &n_positions));
  CHECK_OK(hedge_render_vertex_data(render2, HEDGE_STREAM_NORMALS, &normals, &n_normals));
  CHECK(n_positions == 3 * (uint64_t)rc2.vertex_slots && n_normals == 3 * (uint64_t)rc2.vertex_slots);
  CHECK_OK(hedge_render_vertex_source(render2, source, 16, &n_source));
  for (uint32_t r = 0; r < n_source; ++r) {
    float p[3];
    get_position(mesh, source[r], p);
    CHECK(positions[3 * r] == -p[0] && positions[3 * r + 1] == p[1] && positions[3 * r + 2] == p[2]);
  }
  float texcoords[64], colors[128];
  uint64_t n_tex = 0, n_col = 0;
  CHECK_OK(hedge_render_copy_vertex_data(render2, HEDGE_STREAM_TEXCOORDS, texcoords, 64, &n_tex));
  CHECK_OK(hedge_render_copy_vertex_data(render2, HEDGE_STREAM_COLORS, colors, 128, &n_col));
  CHECK(n_tex == 2 * (uint64_t)rc2.vertex_slots && n_col == 4 * (uint64_t)rc2.vertex_slots);
  CHECK(colors[0] == 1 && colors[1] == 0 && colors[3] == 1);

  /* Destroying the mesh destroys its render objects: their handles are then bad. */
  CHECK_OK(hedge_render_destroy(render2));
  CHECK_OK(hedge_mesh_destroy(mesh));
  CHECK_STATUS(hedge_render_sync(render, &result), HEDGE_ERROR_BAD_HANDLE);
  CHECK_STATUS(hedge_render_counts(render, &rc), HEDGE_ERROR_BAD_HANDLE);
  CHECK_STATUS(hedge_render_vertex_data(render, HEDGE_STREAM_VERTICES, &data, &n_data),
               HEDGE_ERROR_BAD_HANDLE);
  CHECK_STATUS(hedge_render_begin(render), HEDGE_ERROR_BAD_HANDLE);
  CHECK_STATUS(hedge_render_destroy(render), HEDGE_ERROR_BAD_HANDLE);
  CHECK_STATUS(hedge_render_destroy(render2), HEDGE_ERROR_BAD_HANDLE);
}

/* A render object left open inside a transaction, then its mesh destroyed: no crash, no leak. */
static void test_render_lifetime(void) {
  hedge_mesh* mesh = make_mesh(kPyramidPositions, 5, kPyramidTriangles, 12, NULL, 0);
  hedge_render* a = NULL;
  hedge_render* b = NULL;
  CHECK_OK(hedge_render_create(mesh, NULL, &a));
  CHECK_OK(hedge_render_create(mesh, NULL, &b));
  CHECK_OK(hedge_render_begin(a));
  uint32_t v = 0;
  CHECK_OK(hedge_split_face(mesh, 0, 0.5f, 0.25f, 0.3f, &v));
  CHECK_OK(hedge_render_sync(b, NULL));
  hedge_buffer_counts rc;
  CHECK_OK(hedge_render_counts(b, &rc));
  CHECK(rc.triangles == 6);
  CHECK_OK(hedge_mesh_destroy(mesh));
  CHECK_STATUS(hedge_render_commit(a, NULL), HEDGE_ERROR_BAD_HANDLE);
  CHECK_STATUS(hedge_render_sync(b, NULL), HEDGE_ERROR_BAD_HANDLE);
  CHECK_STATUS(hedge_split_face(mesh, 0, 0.5f, 0.25f, 0.3f, &v), HEDGE_ERROR_BAD_HANDLE);
}

/* Every function has an error path: each one taking a handle refuses NULL and destroyed handles,
 * and each one without a handle refuses a NULL out parameter. */
static void test_every_function_error_path(void) {
  hedge_mesh* dead_mesh = make_mesh(kTetPositions, 4, kTetTriangles, 12, NULL, 0);
  hedge_render* dead_render = NULL;
  CHECK_OK(hedge_render_create(dead_mesh, NULL, &dead_render));
  CHECK_OK(hedge_mesh_destroy(dead_mesh)); /* destroys dead_render too */

  uint32_t u = 0, buffer[16];
  int32_t i = 0;
  uint64_t u64 = 0;
  float f[16];
  char text[16];
  const float* fp = NULL;
  const uint32_t* up = NULL;
  hedge_mesh* out_mesh = NULL;
  hedge_counts counts;
  hedge_sync_result result;
  hedge_range ranges[4];
  hedge_buffer_counts buffer_counts;
  hedge_vertex_layout layout;
  const uint32_t tri[] = {0, 1, 2};

  hedge_mesh* const meshes[] = {NULL, dead_mesh};
  hedge_render* const renders[] = {NULL, dead_render};
  for (int k = 0; k < 2; ++k) {
    hedge_mesh* m = meshes[k];
    hedge_render* r = renders[k];
#define BAD(call) CHECK_STATUS(call, HEDGE_ERROR_BAD_HANDLE)
    BAD(hedge_mesh_counts(m, &counts));
    BAD(hedge_mesh_fracture(m, 0, 0, 0, NULL, NULL, 0, &u));
    BAD(hedge_mesh_get_position(m, 0, f));
    BAD(hedge_mesh_set_position(m, 0, 0, 0, 0));
    BAD(hedge_mesh_copy_positions(m, f, 16, &u64));
    BAD(hedge_halfedge_twin(m, 0, &u));
    BAD(hedge_halfedge_next(m, 0, &u));
    BAD(hedge_halfedge_prev(m, 0, &u));
    BAD(hedge_halfedge_to_vertex(m, 0, &u));
    BAD(hedge_halfedge_from_vertex(m, 0, &u));
    BAD(hedge_halfedge_face(m, 0, &u));
    BAD(hedge_halfedge_edge(m, 0, &u));
    BAD(hedge_vertex_halfedge(m, 0, &u));
    BAD(hedge_face_halfedge(m, 0, &u));
    BAD(hedge_edge_halfedge(m, 0, 0, &u));
    BAD(hedge_vertex_is_boundary(m, 0, &i));
    BAD(hedge_halfedge_is_boundary(m, 0, &i));
    BAD(hedge_edge_is_boundary(m, 0, &i));
    BAD(hedge_face_is_boundary(m, 0, &i));
    BAD(hedge_vertex_valence(m, 0, &u));
    BAD(hedge_face_valence(m, 0, &u));
    BAD(hedge_mesh_find_halfedge(m, 0, 1, &u));
    BAD(hedge_vertex_is_deleted(m, 0, &i));
    BAD(hedge_halfedge_is_deleted(m, 0, &i));
    BAD(hedge_edge_is_deleted(m, 0, &i));
    BAD(hedge_face_is_deleted(m, 0, &i));
    BAD(hedge_vertex_halfedges(m, 0, buffer, 16, &u));
    BAD(hedge_vertex_vertices(m, 0, buffer, 16, &u));
    BAD(hedge_vertex_faces(m, 0, buffer, 16, &u));
    BAD(hedge_face_vertices(m, 0, buffer, 16, &u));
    BAD(hedge_face_halfedges(m, 0, buffer, 16, &u));
    BAD(hedge_can_split_edge(m, 0, &i));
    BAD(hedge_split_edge(m, 0, 0, 0, 0, &u));
    BAD(hedge_can_collapse(m, 0, &i));
    BAD(hedge_collapse(m, 0, &u));
    BAD(hedge_can_flip(m, 0, &i));
    BAD(hedge_flip(m, 0));
    BAD(hedge_can_split_face(m, 0, &i));
    BAD(hedge_split_face(m, 0, 0, 0, 0, &u));
    BAD(hedge_can_cut_face(m, 0, 4, &i));
    BAD(hedge_cut_face(m, 0, 4, &u));
    BAD(hedge_split_all_faces(m, buffer, 16, &u));
    BAD(hedge_can_add_face(m, tri, 3, &i));
    BAD(hedge_add_face(m, tri, 3, &u));
    BAD(hedge_can_remove_face(m, 0, &i));
    BAD(hedge_remove_face(m, 0));
    BAD(hedge_can_remove_vertex(m, 0, &i));
    BAD(hedge_remove_vertex(m, 0));
    BAD(hedge_can_fill_hole(m, 0, &i));
    BAD(hedge_fill_hole(m, 0, buffer, 16, &u));
    BAD(hedge_detach_faces(m, tri, 1, NULL, 0, NULL, &out_mesh));
    BAD(hedge_mesh_garbage_collection(m, NULL, 0, NULL, 0, NULL, 0, NULL, 0));
    BAD(hedge_mesh_write(m, HEDGE_TEST_OUTPUT_DIR "/never_written.obj", 0, 0));
    BAD(hedge_mesh_validate(m, &u));
    BAD(hedge_mesh_validation_problem(m, 0, text, 16, &u));
    BAD(hedge_mesh_validation_report(m, text, 16, &u));
    BAD(hedge_mesh_destroy(m));
    BAD(hedge_render_create(m, NULL, &r));
    BAD(hedge_render_sync(r, &result));
    BAD(hedge_render_begin(r));
    BAD(hedge_render_commit(r, &result));
    BAD(hedge_render_rebuild(r, &result));
    BAD(hedge_render_last_result(r, &result));
    BAD(hedge_render_dirty_vertex_ranges(r, ranges, 4, &u));
    BAD(hedge_render_dirty_index_ranges(r, ranges, 4, &u));
    BAD(hedge_render_compact(r, NULL, 0, NULL, NULL, 0, NULL));
    BAD(hedge_render_counts(r, &buffer_counts));
    BAD(hedge_render_layout(r, &layout));
    BAD(hedge_render_vertex_data(r, HEDGE_STREAM_VERTICES, &fp, &u64));
    BAD(hedge_render_copy_vertex_data(r, HEDGE_STREAM_VERTICES, f, 16, &u64));
    BAD(hedge_render_index_data(r, &up, &u64));
    BAD(hedge_render_copy_index_data(r, buffer, 16, &u64));
    BAD(hedge_render_vertex_source(r, buffer, 16, &u));
    BAD(hedge_render_corner_vertex(r, 0, &u));
    BAD(hedge_render_face_triangles(r, 0, &u, &u));
    BAD(hedge_render_triangle_face(r, 0, &u));
    BAD(hedge_render_destroy(r));
#undef BAD
  }
  CHECK(out_mesh == NULL);

#define NULL_OUT(call) CHECK_STATUS(call, HEDGE_ERROR_INVALID_ARGUMENT)
  NULL_OUT(hedge_version(&i, &i, NULL));
  NULL_OUT(hedge_build_options_default(NULL));
  NULL_OUT(hedge_render_options_default(NULL));
  NULL_OUT(hedge_engine_import_options_default(NULL));
  NULL_OUT(hedge_mesh_create(kTetPositions, 4, kTetTriangles, 12, NULL, 0, NULL, NULL, NULL, NULL, NULL));
  NULL_OUT(hedge_mesh_read(HEDGE_DATA_DIR "/tet.obj", NULL, NULL, NULL));
  NULL_OUT(
      hedge_mesh_from_engine_mesh(kTetPositions, 4, kTetTriangles, 12, NULL, NULL, NULL, NULL, NULL, NULL));
#undef NULL_OUT
  /* hedge_last_error and hedge_status_string cannot fail. */
  CHECK(hedge_last_error() != NULL);
  CHECK(strcmp(hedge_status_string(-100), "HEDGE_ERROR_UNKNOWN") == 0);
}

/* ---------------------------------------------------------------------------------------------- */
/* Geometry and normals                                                                           */
/* ---------------------------------------------------------------------------------------------- */

/* The unit cube as 6 quads, outward counter-clockwise. */
static const float kCubePositions[] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0,
                                       0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1};
static const uint32_t kCubeQuads[] = {0, 3, 2, 1, 4, 5, 6, 7, 0, 1, 5, 4, 1, 2, 6, 5, 2, 3, 7, 6, 3, 0, 4, 7};
static const uint32_t kCubeSizes[] = {4, 4, 4, 4, 4, 4};

static int near(double a, double b, double eps) { return fabs(a - b) <= eps; }

static void test_geometry(void) {
  hedge_mesh* cube = make_mesh(kCubePositions, 8, kCubeQuads, 24, kCubeSizes, 6);
  hedge_geometry g;
  memset(&g, 0xFF, sizeof g);
  CHECK(sizeof g == 48);
  CHECK_OK(hedge_mesh_geometry(cube, &g));
  CHECK(near(g.area, 6, 1e-12) && near(g.volume, 1, 1e-12) && g.closed == 1 && g.empty == 0);
  for (int a = 0; a < 3; ++a) CHECK(g.box_min[a] == 0 && g.box_max[a] == 1);
  double area = 0;
  float n[3] = {0, 0, 0};
  CHECK_OK(hedge_face_area(cube, 0, &area));
  CHECK(near(area, 1, 1e-12));
  CHECK_OK(hedge_face_normal(cube, 0, n)); /* the bottom face, z = 0 */
  CHECK(near(n[0], 0, 1e-7) && near(n[1], 0, 1e-7) && near(n[2], -1, 1e-7));
  CHECK_STATUS(hedge_face_normal(cube, 99, n), HEDGE_ERROR_BAD_HANDLE);
  CHECK_STATUS(hedge_face_area(cube, 0, NULL), HEDGE_ERROR_INVALID_ARGUMENT);

  /* Vertex normals: the outward diagonals. Copying before computing is refused. */
  float normals[3 * 24];
  uint64_t count = 0;
  CHECK_STATUS(hedge_mesh_copy_vertex_normals(cube, normals, 24, &count), HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK_ERROR_HAS("compute them first");
  CHECK_STATUS(hedge_mesh_compute_vertex_normals(cube, 7), HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK_OK(hedge_mesh_compute_vertex_normals(cube, HEDGE_WEIGHTING_ANGLE));
  CHECK_STATUS(hedge_mesh_copy_vertex_normals(cube, normals, 23, &count), HEDGE_ERROR_BUFFER_TOO_SMALL);
  CHECK(count == 24);
  CHECK_OK(hedge_mesh_copy_vertex_normals(cube, normals, 24, &count));
  for (uint32_t v = 0; v < 8; ++v)
    for (int a = 0; a < 3; ++a) {
      const double want = (kCubePositions[3 * v + a] > 0.5f ? 1 : -1) / sqrt(3.0);
      CHECK(near(normals[3 * v + a], want, 1e-6));
    }

  /* Corner normals with a 30-degree crease: every corner takes its face's normal. */
  CHECK_STATUS(hedge_mesh_compute_corner_normals(cube, 200, HEDGE_WEIGHTING_ANGLE),
               HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK_STATUS(hedge_mesh_copy_corner_normals(cube, normals, 72, &count), HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK_OK(hedge_mesh_compute_corner_normals(cube, 30, HEDGE_WEIGHTING_AREA));
  CHECK_OK(hedge_mesh_copy_corner_normals(cube, normals, 72, &count));
  CHECK(count == 72);
  for (uint32_t h = 0; h < 24; ++h) {
    uint32_t face = 0;
    float fn[3];
    CHECK_OK(hedge_halfedge_face(cube, h, &face));
    CHECK_OK(hedge_face_normal(cube, face, fn));
    for (int a = 0; a < 3; ++a) CHECK(near(normals[3 * h + a], fn[a], 1e-6));
  }

  /* Render buffers made afterwards with attribute normals split the cube's corners: 24 vertices. */
  hedge_render_options ro;
  CHECK_OK(hedge_render_options_default(&ro));
  ro.normals = HEDGE_NORMALS_ATTRIBUTE;
  hedge_render* render = NULL;
  CHECK_OK(hedge_render_create(cube, &ro, &render));
  hedge_buffer_counts bc;
  CHECK_OK(hedge_render_counts(render, &bc));
  CHECK(bc.vertices == 24);
  CHECK_OK(hedge_render_destroy(render));

  /* Raising a corner of the top face: by default (AUTOMATIC) the corner normals follow the geometry;
   * ATTRIBUTE keeps them as they were. */
  {
    uint32_t top = INVALID; /* the corner of vertex 6 (1, 1, 1) in the top face (normal +z) */
    for (uint32_t h = 0; h < 24; ++h) {
      uint32_t v = INVALID;
      CHECK_OK(hedge_halfedge_to_vertex(cube, h, &v));
      if (v == 6 && normals[3 * h + 2] > 0.5f) top = h;
    }
    CHECK(top != INVALID);
    hedge_render_options follow;
    CHECK_OK(hedge_render_options_default(&follow));
    hedge_render *kept = NULL, *followed = NULL;
    CHECK_OK(hedge_render_create(cube, &ro, &kept));
    CHECK_OK(hedge_render_create(cube, &follow, &followed));
    CHECK_OK(hedge_mesh_set_position(cube, 6, 1, 1, 1.5f));
    hedge_render* both[2] = {kept, followed};
    float n[2][3];
    for (int i = 0; i < 2; ++i) {
      CHECK_OK(hedge_render_sync(both[i], NULL));
      hedge_vertex_layout layout;
      CHECK_OK(hedge_render_layout(both[i], &layout));
      uint32_t rv = INVALID;
      CHECK_OK(hedge_render_corner_vertex(both[i], top, &rv));
      const float* data = NULL;
      uint64_t floats = 0;
      CHECK_OK(hedge_render_vertex_data(both[i], HEDGE_STREAM_VERTICES, &data, &floats));
      CHECK((uint64_t)(rv + 1) * layout.stride <= floats && layout.normal >= 0);
      for (int a = 0; a < 3; ++a) n[i][a] = data[(uint64_t)rv * layout.stride + (uint32_t)layout.normal + a];
    }
    CHECK(n[0][0] == 0 && n[0][1] == 0 && n[0][2] == 1); /* kept */
    CHECK(n[1][2] < 0.99f && n[1][2] > 0.5f);            /* tilted by the raised corner */
    CHECK(near(n[1][0] * n[1][0] + n[1][1] * n[1][1] + n[1][2] * n[1][2], 1, 1e-6));
    CHECK_OK(hedge_render_destroy(kept));
    CHECK_OK(hedge_render_destroy(followed));
  }

  /* An open mesh has no volume: NaN. */
  hedge_mesh* pyramid = make_mesh(kPyramidPositions, 5, kPyramidTriangles, 12, NULL, 0);
  CHECK_OK(hedge_mesh_geometry(pyramid, &g));
  CHECK(g.closed == 0 && isnan(g.volume) && g.area > 0);
  CHECK_STATUS(hedge_mesh_geometry(pyramid, NULL), HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK_OK(hedge_mesh_destroy(pyramid));
  CHECK_OK(hedge_mesh_destroy(cube));
}

/* The cube against a copy raised by 0.25: its bottom face is 0.25 from the copy, and nothing is farther. */
static void test_hausdorff(void) {
  float raised[24];
  memcpy(raised, kCubePositions, sizeof raised);
  for (int v = 0; v < 8; ++v) raised[3 * v + 2] += 0.25f;
  hedge_mesh* cube = make_mesh(kCubePositions, 8, kCubeQuads, 24, kCubeSizes, 6);
  hedge_mesh* copy = make_mesh(raised, 8, kCubeQuads, 24, kCubeSizes, 6);
  hedge_mesh* points = make_mesh(kCubePositions, 8, NULL, 0, NULL, 0);
  double distance = -1, mean = -1;
  CHECK_OK(hedge_mesh_hausdorff(cube, copy, 1000, 1, &distance, &mean));
  CHECK(near(distance, 0.25, 1e-7) && mean > 0 && mean < 0.25);
  CHECK_OK(hedge_mesh_hausdorff(cube, cube, 1000, 1, &distance, NULL));
  CHECK(distance >= 0 && distance < 1e-7);
  CHECK_STATUS(hedge_mesh_hausdorff(cube, copy, 1000, 1, NULL, &mean), HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK_STATUS(hedge_mesh_hausdorff(cube, points, 1000, 1, &distance, &mean), HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK_ERROR_HAS("no faces");
  CHECK_OK(hedge_mesh_destroy(points));
  CHECK_OK(hedge_mesh_destroy(copy));
  CHECK_OK(hedge_mesh_destroy(cube));
}

static void test_smooth(void) {
  hedge_smooth_options o;
  memset(&o, 0xFF, sizeof o);
  CHECK(sizeof o == 32);
  CHECK_OK(hedge_smooth_options_default(&o));
  CHECK(o.method == HEDGE_SMOOTH_UNIFORM && o.iterations == 10 && o.lambda == 0.5 && o.fix_boundary == 1);
  /* The grid with its middle vertex (4) lifted: smoothing pulls it down, the boundary stays. */
  float lifted[27];
  memcpy(lifted, kGridPositions, sizeof lifted);
  lifted[3 * 4 + 2] = 1;
  hedge_mesh* grid = make_mesh(lifted, 9, kGridQuads, 16, kGridSizes, 4);
  float p[3];
  CHECK_OK(hedge_mesh_smooth(grid, NULL, NULL, 0));
  CHECK_OK(hedge_mesh_get_position(grid, 4, p));
  CHECK(p[2] < 0.01f && p[2] >= 0);
  CHECK_OK(hedge_mesh_get_position(grid, 0, p));
  CHECK(p[0] == 0 && p[1] == 0 && p[2] == 0);
  /* A mask that excludes vertex 4: nothing moves. */
  hedge_mesh* again = make_mesh(lifted, 9, kGridQuads, 16, kGridSizes, 4);
  uint8_t mask[9] = {1, 1, 1, 1, 0, 1, 1, 1, 1};
  CHECK_OK(hedge_mesh_smooth(again, NULL, mask, 9));
  CHECK_OK(hedge_mesh_get_position(again, 4, p));
  CHECK(p[2] == 1);
  CHECK_STATUS(hedge_mesh_smooth(again, NULL, mask, 8), HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK_STATUS(hedge_mesh_smooth(again, NULL, NULL, 9), HEDGE_ERROR_INVALID_ARGUMENT);
  /* Cotangent weights on quads, a bad method, a bad lambda: refused, nothing moves. */
  o.method = HEDGE_SMOOTH_COTANGENT;
  CHECK_STATUS(hedge_mesh_smooth(again, &o, NULL, 0), HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK_ERROR_HAS("triangles");
  o.method = 9;
  CHECK_STATUS(hedge_mesh_smooth(again, &o, NULL, 0), HEDGE_ERROR_INVALID_ARGUMENT);
  o.method = HEDGE_SMOOTH_TAUBIN;
  o.lambda = 3;
  CHECK_STATUS(hedge_mesh_smooth(again, &o, NULL, 0), HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK_OK(hedge_mesh_get_position(again, 4, p));
  CHECK(p[2] == 1);
  o.lambda = 0.5;
  CHECK_OK(hedge_mesh_smooth(again, &o, NULL, 0));
  /* Implicit steps need triangles: the pyramid's apex comes down. */
  {
    hedge_mesh* pyramid = make_mesh(kPyramidPositions, 5, kPyramidTriangles, 12, NULL, 0);
    hedge_smooth_options imp;
    CHECK_OK(hedge_smooth_options_default(&imp));
    imp.method = HEDGE_SMOOTH_IMPLICIT;
    imp.iterations = 1;
    imp.lambda = 10;
    CHECK_OK(hedge_mesh_smooth(pyramid, &imp, NULL, 0));
    CHECK_OK(hedge_mesh_get_position(pyramid, 4, p));
    CHECK(p[2] < 0.5f && p[2] >= 0);
    CHECK_OK(hedge_mesh_destroy(pyramid));
  }
  CHECK_OK(hedge_mesh_get_position(again, 4, p));
  CHECK(p[2] < 1);
  CHECK_STATUS(hedge_smooth_options_default(NULL), HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK_OK(hedge_mesh_destroy(again));
  CHECK_OK(hedge_mesh_destroy(grid));
}

static void test_decimate(void) {
  hedge_decimate_options o;
  memset(&o, 0xFF, sizeof o);
  CHECK(sizeof o == 72 && sizeof(hedge_decimate_result) == 32);
  CHECK_OK(hedge_decimate_options_default(&o));
  CHECK(o.target_vertices == 0 && o.target_faces == 0 && isinf(o.max_error) && o.boundary_weight == 1 &&
        o.max_normal_change_degrees == 60 && o.keep_boundary == 0 && o.keep_seams == 1);
  /* A 9 x 9 height field z = x^2 / 20, triangulated: 81 vertices, 128 triangles. */
  float positions[81 * 3];
  uint32_t triangles[128 * 3], n = 0;
  for (uint32_t j = 0; j < 9; ++j)
    for (uint32_t i = 0; i < 9; ++i) {
      float* p = positions + 3 * (9 * j + i);
      p[0] = (float)i, p[1] = (float)j, p[2] = (float)(i * i) / 20;
    }
  for (uint32_t j = 0; j < 8; ++j)
    for (uint32_t i = 0; i < 8; ++i) {
      const uint32_t a = 9 * j + i, b = a + 1, c = a + 10, d = a + 9;
      const uint32_t quad[6] = {a, b, c, a, c, d};
      memcpy(triangles + n, quad, sizeof quad);
      n += 6;
    }
  hedge_mesh* field = make_mesh(positions, 81, triangles, n, NULL, 0);
  o.target_vertices = 20;
  hedge_decimate_result r;
  CHECK_OK(hedge_mesh_decimate(field, &o, &r));
  hedge_counts c = counts_of(field);
  CHECK(r.vertices == c.vertices && r.faces == c.faces && c.vertices <= 20 && c.vertices >= 18);
  CHECK(r.collapses == 81 - c.vertices && r.max_error > 0 && r.max_error < 1);
  CHECK(c.vertex_slots == c.vertices); /* garbage collected */
  uint32_t problems = 1;
  CHECK_OK(hedge_mesh_validate(field, &problems));
  CHECK(problems == 0);
  /* Bad options and booleans: refused, nothing changes. */
  o.target_vertices = 10;
  o.max_normal_change_degrees = 0;
  CHECK_STATUS(hedge_mesh_decimate(field, &o, NULL), HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK_ERROR_HAS("max_normal_change_degrees");
  o.max_normal_change_degrees = 60;
  o.keep_seams = 2;
  CHECK_STATUS(hedge_mesh_decimate(field, &o, NULL), HEDGE_ERROR_INVALID_ARGUMENT);
  o.keep_seams = 1;
  o.max_error = -1;
  CHECK_STATUS(hedge_mesh_decimate(field, &o, NULL), HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK(counts_of(field).vertices == c.vertices);
  /* The defaults (NULL): no target, no error limit: as far as the collapses are legal. */
  hedge_mesh* fresh = make_mesh(positions, 81, triangles, n, NULL, 0);
  CHECK_OK(hedge_mesh_decimate(fresh, NULL, &r));
  CHECK(r.vertices < 20 && r.vertices >= 3 && r.faces >= 1 && r.vertices == counts_of(fresh).vertices);
  CHECK_OK(hedge_mesh_validate(fresh, &problems));
  CHECK(problems == 0);
  CHECK_OK(hedge_mesh_destroy(fresh));
  /* Quads are refused, unchanged. */
  hedge_mesh* grid = make_mesh(kGridPositions, 9, kGridQuads, 16, kGridSizes, 4);
  CHECK_STATUS(hedge_mesh_decimate(grid, NULL, NULL), HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK_ERROR_HAS("triangles");
  CHECK(counts_of(grid).faces == 4);
  CHECK_STATUS(hedge_decimate_options_default(NULL), HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK_OK(hedge_mesh_destroy(grid));
  CHECK_OK(hedge_mesh_destroy(field));
}

/* A plate of n x n quads, each two triangles, in z = 0: (n + 1)^2 vertices. */
static hedge_mesh* make_plate(uint32_t n) {
  float* positions = malloc(sizeof(float) * 3 * (n + 1) * (n + 1));
  uint32_t* triangles = malloc(sizeof(uint32_t) * 6 * n * n);
  uint32_t k = 0;
  for (uint32_t j = 0; j <= n; ++j)
    for (uint32_t i = 0; i <= n; ++i) {
      float* p = positions + 3 * ((n + 1) * j + i);
      p[0] = (float)i, p[1] = (float)j, p[2] = 0;
    }
  for (uint32_t j = 0; j < n; ++j)
    for (uint32_t i = 0; i < n; ++i) {
      const uint32_t a = (n + 1) * j + i, b = a + 1, c = a + n + 2, d = a + n + 1;
      const uint32_t quad[6] = {a, b, c, a, c, d};
      memcpy(triangles + k, quad, sizeof quad);
      k += 6;
    }
  hedge_mesh* plate = make_mesh(positions, (n + 1) * (n + 1), triangles, k, NULL, 0);
  free(positions);
  free(triangles);
  return plate;
}

static void test_fracture(void) {
  CHECK(sizeof(hedge_fracture_ring) == 24 && sizeof(hedge_fracture_options) == 464 &&
        sizeof(hedge_fracture_shard) == 168);
  hedge_fracture_options o;
  CHECK_OK(hedge_fracture_options_default(HEDGE_FRACTURE_GLASS, &o));
  CHECK(o.ring_count == 4 && o.rings[0].points == 4 && o.rings[3].points == 16 && o.density == 1 &&
        o.hulls == 1 && o.thickness == 0 && o.absolute == 0);
  CHECK_OK(hedge_fracture_options_default(HEDGE_FRACTURE_WOOD, &o));
  CHECK(o.grain[0] == 1 && o.grain_stretch == 3);
  CHECK_STATUS(hedge_fracture_options_default(7, &o), HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK_ERROR_HAS("preset");
  CHECK_STATUS(hedge_fracture_options_default(HEDGE_FRACTURE_ICE, NULL), HEDGE_ERROR_INVALID_ARGUMENT);

  hedge_mesh* plate = make_plate(30);
  hedge_geometry before;
  CHECK_OK(hedge_mesh_geometry(plate, &before));
  const uint32_t faces_before = (uint32_t)counts_of(plate).faces;
  hedge_fracture_shard shards[40];
  uint32_t count = 0;
  /* Too small a buffer: the bound is given and nothing changes. */
  CHECK_STATUS(hedge_mesh_fracture(plate, 15.2f, 14.9f, 0, NULL, shards, 10, &count),
               HEDGE_ERROR_BUFFER_TOO_SMALL);
  CHECK(count == 40 && counts_of(plate).faces == faces_before);
  /* Off the plate, NaN, bad booleans and ring counts: refused, nothing changes. */
  CHECK_STATUS(hedge_mesh_fracture(plate, 15, 15, 3, NULL, shards, 40, &count), HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK_ERROR_HAS("tolerance");
  CHECK_STATUS(hedge_mesh_fracture(plate, NAN, 15, 0, NULL, shards, 40, &count),
               HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK_OK(hedge_fracture_options_default(HEDGE_FRACTURE_GLASS, &o));
  o.hulls = 2;
  CHECK_STATUS(hedge_mesh_fracture(plate, 15, 15, 0, &o, shards, 40, &count), HEDGE_ERROR_INVALID_ARGUMENT);
  o.hulls = 1;
  o.ring_count = HEDGE_FRACTURE_MAX_RINGS + 1;
  CHECK_STATUS(hedge_mesh_fracture(plate, 15, 15, 0, &o, shards, 40, &count), HEDGE_ERROR_INVALID_ARGUMENT);
  o.ring_count = 4;
  o.rings[1].spacing = -1;
  CHECK_STATUS(hedge_mesh_fracture(plate, 15, 15, 0, &o, shards, 40, &count), HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK_ERROR_HAS("rings[1].spacing");
  /* Points past the library's limits: an illegal option (not an internal error), checked before the
   * capacity, and nothing changes. */
  CHECK_OK(hedge_fracture_options_default(HEDGE_FRACTURE_GLASS, &o));
  o.ring_count = 2;
  o.rings[0].points = 0xFFFFFFFFu;
  o.rings[1].points = 0xFFFFFFFFu;
  CHECK_STATUS(hedge_mesh_fracture(plate, 15, 15, 0, &o, shards, 40, &count), HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK_ERROR_HAS("rings[0].points");
  o.ring_count = 1;
  CHECK_STATUS(hedge_mesh_fracture(plate, 15, 15, 0, &o, shards, 40, &count), HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK_ERROR_HAS("rings[0].points");
  o.ring_count = 2;
  o.rings[0].points = 6000;
  o.rings[1].points = 6000;
  CHECK_STATUS(hedge_mesh_fracture(plate, 15, 15, 0, &o, shards, 40, &count), HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK_ERROR_HAS("10000");
  CHECK_OK(hedge_fracture_options_default(HEDGE_FRACTURE_GLASS, &o));
  o.thickness = 1e30;
  CHECK_STATUS(hedge_mesh_fracture(plate, 15, 15, 0, &o, shards, 40, &count), HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK_ERROR_HAS("diagonal");
  CHECK_STATUS(hedge_mesh_fracture(plate, 15, 15, 0, NULL, shards, 40, NULL), HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK(counts_of(plate).faces == faces_before);

  /* Glass with thickness: closed shards with mass, hulls, areas adding up. */
  CHECK_OK(hedge_fracture_options_default(HEDGE_FRACTURE_GLASS, &o));
  o.thickness = 0.25;
  o.density = 2;
  o.seed = 9;
  CHECK_OK(hedge_mesh_fracture(plate, 15.2f, 14.9f, 0, &o, shards, 40, &count));
  CHECK(count >= 20 && count <= 40);
  hedge_geometry after;
  CHECK_OK(hedge_mesh_geometry(plate, &after));
  double area = after.area;
  uint32_t problems = 1;
  for (uint32_t i = 0; i < count; ++i) {
    const hedge_fracture_shard* s = &shards[i];
    area += s->area;
    CHECK(s->closed == 1 && s->volume > 0 && fabs(s->volume - 0.25 * s->area) < 1e-4 * s->area);
    CHECK(fabs(s->mass - 2 * s->volume) < 1e-9 * s->mass && s->inertia[0] > 0 && s->inertia[4] > 0);
    CHECK(fabs(s->centroid[2]) < 1e-9 && fabs(s->centre_of_mass[2] + 0.125) < 1e-4);
    CHECK(s->mesh != NULL && s->hull != NULL && s->hull_dimension == 4);
    CHECK_OK(hedge_mesh_validate(s->mesh, &problems));
    CHECK(problems == 0);
    hedge_geometry g;
    CHECK_OK(hedge_mesh_geometry(s->hull, &g));
    CHECK(g.closed == 1 && g.volume >= s->volume * (1 - 1e-6));
  }
  CHECK(fabs(area - before.area) < 1e-5 * before.area);
  CHECK_OK(hedge_mesh_validate(plate, &problems));
  CHECK(problems == 0);

  /* The same seed on a fresh plate: the same shards. */
  hedge_mesh* again = make_plate(30);
  hedge_fracture_shard twin[40];
  uint32_t twin_count = 0;
  CHECK_OK(hedge_mesh_fracture(again, 15.2f, 14.9f, 0, &o, twin, 40, &twin_count));
  CHECK(twin_count == count);
  for (uint32_t i = 0; i < count && i < twin_count; ++i) {
    CHECK(twin[i].area == shards[i].area && twin[i].centroid[0] == shards[i].centroid[0] &&
          counts_of(twin[i].mesh).faces == counts_of(shards[i].mesh).faces);
    CHECK_OK(hedge_mesh_destroy(twin[i].mesh));
    CHECK_OK(hedge_mesh_destroy(twin[i].hull));
  }
  for (uint32_t i = 0; i < count; ++i) {
    CHECK_OK(hedge_mesh_destroy(shards[i].mesh));
    CHECK_OK(hedge_mesh_destroy(shards[i].hull));
  }
  /* No break points: no shard, nothing changes. */
  o.ring_count = 0;
  CHECK_OK(hedge_mesh_fracture(again, 5.5f, 5.5f, 0, &o, NULL, 0, &count));
  CHECK(count == 0);
  CHECK_OK(hedge_mesh_destroy(again));
  CHECK_OK(hedge_mesh_destroy(plate));
}

static void test_subdivide(void) {
  hedge_mesh* tet = make_mesh(kTetPositions, 4, kTetTriangles, 12, NULL, 0);
  CHECK_OK(hedge_mesh_subdivide(tet, HEDGE_SUBDIVISION_LOOP, 2));
  hedge_counts c = counts_of(tet);
  CHECK(c.faces == 64 && c.vertices == 34 && c.edges == 96);
  uint32_t problems = 1;
  CHECK_OK(hedge_mesh_validate(tet, &problems));
  CHECK(problems == 0);
  CHECK_STATUS(hedge_mesh_subdivide(tet, 5, 1), HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK_STATUS(hedge_mesh_subdivide(tet, HEDGE_SUBDIVISION_MIDPOINT, 13), HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK_STATUS(hedge_mesh_subdivide(tet, HEDGE_SUBDIVISION_MIDPOINT, 12), HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK_ERROR_HAS("2^31");
  CHECK(counts_of(tet).faces == 64);
  /* Quads are refused, unchanged. */
  hedge_mesh* grid = make_mesh(kGridPositions, 9, kGridQuads, 16, kGridSizes, 4);
  CHECK_STATUS(hedge_mesh_subdivide(grid, HEDGE_SUBDIVISION_LOOP, 1), HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK_ERROR_HAS("face 0 has 4 corners");
  CHECK(counts_of(grid).faces == 4);
  CHECK_OK(hedge_mesh_subdivide(grid, HEDGE_SUBDIVISION_CATMULL_CLARK, 1));
  CHECK(counts_of(grid).faces == 16 && counts_of(grid).vertices == 25);
  CHECK_STATUS(hedge_mesh_subdivide(grid, HEDGE_SUBDIVISION_SPLIT_FACES + 1, 1),
               HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK_OK(hedge_mesh_subdivide(grid, HEDGE_SUBDIVISION_SPLIT_FACES, 1)); /* quads fan into 4 triangles */
  CHECK(counts_of(grid).faces == 64 && counts_of(grid).vertices == 41);
  CHECK_OK(hedge_mesh_subdivide(grid, HEDGE_SUBDIVISION_SQRT3, 2));
  CHECK(counts_of(grid).faces == 9 * 64 && counts_of(grid).vertices == 41 + 64 + 192);
  CHECK_OK(hedge_mesh_validate(grid, &problems));
  CHECK(problems == 0);
  /* A render object of the mesh rebuilds at its next sync: 64 triangles. */
  hedge_render* render = NULL;
  CHECK_OK(hedge_render_create(tet, NULL, &render));
  CHECK_OK(hedge_mesh_subdivide(tet, HEDGE_SUBDIVISION_MIDPOINT, 1));
  hedge_sync_result sync;
  CHECK_OK(hedge_render_sync(render, &sync));
  hedge_buffer_counts bc;
  CHECK_OK(hedge_render_counts(render, &bc));
  CHECK(bc.triangles == 256);
  CHECK_OK(hedge_render_destroy(render));
  /* Reordering: a permutation of the elements, the mesh still valid, with the same counts. */
  const hedge_counts before = counts_of(tet);
  uint32_t vmap[512], fmap[1024];
  CHECK_STATUS(hedge_mesh_reorder(tet, HEDGE_ORDERING_SPATIAL, 0, vmap, 3, NULL, 0, NULL, 0, NULL, 0),
               HEDGE_ERROR_BUFFER_TOO_SMALL);
  CHECK_STATUS(hedge_mesh_reorder(tet, 7, 0, NULL, 0, NULL, 0, NULL, 0, NULL, 0),
               HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK(same_counts(counts_of(tet), before));
  CHECK_OK(hedge_mesh_reorder(tet, HEDGE_ORDERING_SPATIAL, 0, vmap, 512, NULL, 0, NULL, 0, fmap, 1024));
  CHECK(same_counts(counts_of(tet), before));
  /* The vertex-cache order draws with fewer vertex loads per triangle than the spatial one. */
  double spatial_acmr = 0, cache_acmr = 0;
  CHECK_OK(hedge_mesh_cache_miss_ratio(tet, 16, &spatial_acmr));
  CHECK_OK(hedge_mesh_reorder(tet, HEDGE_ORDERING_VERTEX_CACHE, 16, NULL, 0, NULL, 0, NULL, 0, NULL, 0));
  CHECK_OK(hedge_mesh_cache_miss_ratio(tet, 16, &cache_acmr));
  CHECK(cache_acmr < spatial_acmr && cache_acmr > 0.4);
  CHECK_STATUS(hedge_mesh_cache_miss_ratio(tet, 16, NULL), HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK(same_counts(counts_of(tet), before));
  CHECK_OK(hedge_mesh_reorder(tet, HEDGE_ORDERING_SPATIAL, 0, vmap, 512, NULL, 0, NULL, 0, fmap, 1024));
  {
    uint8_t seen[512] = {0};
    for (uint32_t v = 0; v < before.vertex_slots; ++v) {
      CHECK(vmap[v] < before.vertices && !seen[vmap[v]]);
      seen[vmap[v]] = 1;
    }
  }
  CHECK_OK(hedge_mesh_validate(tet, &problems));
  CHECK(problems == 0);
  CHECK_OK(hedge_mesh_destroy(grid));
  CHECK_OK(hedge_mesh_destroy(tet));
}

/* ---------------------------------------------------------------------------------------------- */
/* Threads: one mesh, one thread at a time; a second thread's overlapping call fails, never hangs   */
/* ---------------------------------------------------------------------------------------------- */

typedef struct {
  hedge_mesh* mesh;
  hedge_render* render;
  atomic_int working; /* 1 while the first thread is inside its long call */
  atomic_int done;
  int busy_seen, ok_seen, other_seen;
} shared_mesh;

/* The editing thread: its calls collide with the other thread's too, and are retried when busy. */
static int long_edits(void* arg) {
  shared_mesh* s = (shared_mesh*)arg;
  int failed = 0;
  for (int round = 0; round < 3 && !failed; ++round) {
    hedge_status st;
    do {
      atomic_store(&s->working, 1);
      /* Long work on one mesh: the other thread gets many chances to collide with it. */
      st = hedge_mesh_subdivide(s->mesh, HEDGE_SUBDIVISION_MIDPOINT, 1);
      atomic_store(&s->working, 0);
      if (st == HEDGE_ERROR_BUSY) thrd_yield();
    } while (st == HEDGE_ERROR_BUSY);
    if (st != HEDGE_OK) failed = 1;
    hedge_sync_result r;
    do {
      st = hedge_render_sync(s->render, &r);
    } while (st == HEDGE_ERROR_BUSY);
    if (st != HEDGE_OK) failed = 1;
  }
  atomic_store(&s->done, 1);
  return failed;
}

static void test_threads(void) {
  hedge_mesh* mesh = make_mesh(kGridPositions, 9, kGridQuads, 16, kGridSizes, 4);
  uint32_t added = 0;
  CHECK_OK(hedge_split_all_faces(mesh, NULL, 0, &added)); /* triangles, for the midpoint scheme */
  CHECK_OK(hedge_mesh_subdivide(mesh, HEDGE_SUBDIVISION_MIDPOINT, 5));
  hedge_render* render = NULL;
  CHECK_OK(hedge_render_create(mesh, NULL, &render));
  shared_mesh s = {mesh, render, 0, 0, 0, 0, 0};
  thrd_t editor;
  CHECK(thrd_create(&editor, long_edits, &s) == thrd_success);
  /* This thread reads and edits the same mesh meanwhile: every call either runs alone (OK) or
   * fails at once with HEDGE_ERROR_BUSY; none hangs and none corrupts the mesh. */
  while (!atomic_load(&s.done)) {
    for (int i = 0; i < 3; ++i) {
      hedge_counts c;
      hedge_sync_result r;
      const hedge_status st = i == 0   ? hedge_mesh_counts(mesh, &c)
                              : i == 1 ? hedge_mesh_set_position(mesh, 0, 0.f, 0.f, 0.f)
                                       : hedge_render_sync(render, &r);
      if (st == HEDGE_ERROR_BUSY) {
        ++s.busy_seen;
        CHECK(strstr(hedge_last_error(), "another thread") != NULL);
      } else if (st == HEDGE_OK) {
        ++s.ok_seen;
      } else {
        ++s.other_seen;
      }
    }
    if (atomic_load(&s.working) == 0) thrd_yield();
  }
  int editor_failed = 1;
  CHECK(thrd_join(editor, &editor_failed) == thrd_success);
  CHECK(editor_failed == 0);
  CHECK(s.busy_seen > 0); /* the calls did collide */
  CHECK(s.other_seen == 0);
  CHECK_VALID(mesh);
  /* Free again: this thread's calls succeed. */
  hedge_counts c;
  CHECK_OK(hedge_mesh_counts(mesh, &c));
  CHECK_OK(hedge_render_destroy(render));
  CHECK_OK(hedge_mesh_destroy(mesh));
}

/* ---------------------------------------------------------------------------------------------- */
/* Picking and the render-triangle-to-face map                                                    */
/* ---------------------------------------------------------------------------------------------- */

/* The 2 x 2 quad grid, triangulated: 8 triangles in the plane z = 0, x and y in [0, 2]. */
static hedge_mesh* make_triangle_grid(void) {
  uint32_t tris[24];
  for (int q = 0; q < 4; ++q) {
    const uint32_t* c = kGridQuads + 4 * q;
    const uint32_t t[6] = {c[0], c[1], c[2], c[0], c[2], c[3]};
    memcpy(tris + 6 * q, t, sizeof t);
  }
  return make_mesh(kGridPositions, 9, tris, 24, NULL, 0);
}

/* The face of the grid whose triangle contains (x, y), by brute force over its corners. */
static int face_has_point(const hedge_mesh* mesh, uint32_t face, float x, float y) {
  uint32_t c[3], n = 0;
  CHECK_OK(hedge_face_vertices(mesh, face, c, 3, &n));
  float p[3][3];
  for (int i = 0; i < 3; ++i) get_position(mesh, c[i], p[i]);
  float lo[2] = {p[0][0], p[0][1]}, hi[2] = {p[0][0], p[0][1]};
  for (int i = 1; i < 3; ++i)
    for (int k = 0; k < 2; ++k) {
      lo[k] = fminf(lo[k], p[i][k]);
      hi[k] = fmaxf(hi[k], p[i][k]);
    }
  return x >= lo[0] && x <= hi[0] && y >= lo[1] && y <= hi[1];
}

static void test_picking(void) {
  hedge_mesh* mesh = make_triangle_grid();
  hedge_surface_hit hit;
  int32_t found = -1;
  uint64_t bytes = 0;
  CHECK(sizeof(hedge_surface_hit) == 48);

  /* A ray straight down onto (0.25, 1.5). */
  const float origin[3] = {0.25f, 1.5f, 5}, down[3] = {0, 0, -2};
  CHECK_OK(hedge_mesh_raycast(mesh, origin, down, INFINITY, &hit, &found));
  CHECK(found == 1);
  CHECK(fabsf(hit.t - 2.5f) < 1e-6f);        /* in units of the direction's length 2 */
  CHECK(fabsf(hit.distance - 5.0f) < 1e-6f); /* in the mesh's units */
  CHECK(fabsf(hit.point[0] - 0.25f) < 1e-6f && fabsf(hit.point[1] - 1.5f) < 1e-6f && hit.point[2] == 0);
  CHECK(face_has_point(mesh, hit.face, 0.25f, 1.5f));
  CHECK(fabsf(hit.barycentric[0] + hit.barycentric[1] + hit.barycentric[2] - 1) < 1e-6f);
  {
    float p[3] = {0, 0, 0}, q[3];
    for (int i = 0; i < 3; ++i) {
      get_position(mesh, hit.corners[i], q);
      for (int k = 0; k < 3; ++k) p[k] += hit.barycentric[i] * q[k];
    }
    CHECK(fabsf(p[0] - 0.25f) < 1e-5f && fabsf(p[1] - 1.5f) < 1e-5f);
  }
  /* Too short, and pointing away: no hit, and *out_hit is left alone. */
  hedge_surface_hit untouched;
  memset(&untouched, 0x5A, sizeof untouched);
  hit = untouched;
  CHECK_OK(hedge_mesh_raycast(mesh, origin, down, 2.0f, &hit, &found));
  CHECK(found == 0 && memcmp(&hit, &untouched, sizeof hit) == 0);
  const float up[3] = {0, 0, 1};
  CHECK_OK(hedge_mesh_raycast(mesh, origin, up, INFINITY, &hit, &found));
  CHECK(found == 0);

  /* The nearest point to a point above the grid, outside it. */
  const float above[3] = {3, 1, 2};
  CHECK_OK(hedge_mesh_closest_point(mesh, above, INFINITY, &hit, &found));
  CHECK(found == 1);
  CHECK(fabsf(hit.point[0] - 2) < 1e-6f && fabsf(hit.point[1] - 1) < 1e-6f && hit.point[2] == 0);
  CHECK(fabsf(hit.distance - sqrtf(5)) < 1e-5f && hit.t == 0);
  CHECK_OK(hedge_mesh_closest_point(mesh, above, 2.0f, &hit, &found)); /* sqrt(5) > 2 */
  CHECK(found == 0);

  /* A point on the surface within a tolerance, and not. */
  const float on[3] = {1.5f, 0.5f, 0.001f}, off[3] = {1.5f, 0.5f, 0.5f};
  CHECK_OK(hedge_mesh_face_containing_point(mesh, on, 0.01f, &hit, &found));
  CHECK(found == 1 && face_has_point(mesh, hit.face, 1.5f, 0.5f));
  CHECK(fabsf(hit.distance - 0.001f) < 1e-6f);
  CHECK_OK(hedge_mesh_face_containing_point(mesh, off, 0.01f, &hit, &found));
  CHECK(found == 0);

  /* The 2D variant: the grid lies in xy. In xz it is seen edge-on and contains nothing. */
  CHECK_OK(hedge_mesh_face_containing_point_2d(mesh, 1.75f, 1.25f, HEDGE_PLANE_XY, &hit, &found));
  CHECK(found == 1 && face_has_point(mesh, hit.face, 1.75f, 1.25f) && hit.distance == 0);
  CHECK_OK(hedge_mesh_face_containing_point_2d(mesh, 2.5f, 1.25f, HEDGE_PLANE_XY, &hit, &found));
  CHECK(found == 0);
  CHECK_OK(hedge_mesh_face_containing_point_2d(mesh, 1.0f, 0.0f, HEDGE_PLANE_XZ, &hit, &found));
  CHECK(found == 0);
  CHECK_OK(hedge_mesh_face_containing_point_2d(mesh, 1.0f, 0.0f, HEDGE_PLANE_YZ, &hit, &found));
  CHECK(found == 0);

  /* Edits are seen by the next query: lift vertex 4 (the centre) and a ray through it finds it. */
  CHECK_OK(hedge_mesh_bvh_update(mesh, &bytes));
  CHECK(bytes > 0);
  CHECK_OK(hedge_mesh_set_position(mesh, 4, 1, 1, 3));
  const float centre[3] = {1, 1, 10};
  CHECK_OK(hedge_mesh_raycast(mesh, centre, down, INFINITY, &hit, &found));
  CHECK(found == 1 && fabsf(hit.point[2] - 3) < 1e-5f);
  CHECK_OK(hedge_mesh_set_position(mesh, 4, 1, 1, 0));
  /* A split adds faces: the new vertex's faces are found. */
  uint32_t h = INVALID, e = INVALID, v = INVALID;
  CHECK_OK(hedge_mesh_find_halfedge(mesh, 0, 1, &h));
  CHECK(h != INVALID);
  CHECK_OK(hedge_halfedge_edge(mesh, h, &e));
  CHECK_OK(hedge_split_edge(mesh, e, 0.5f, 0, 0, &v));
  const float near_new[3] = {0.5f, 0.05f, 1};
  CHECK_OK(hedge_mesh_raycast(mesh, near_new, down, INFINITY, &hit, &found));
  CHECK(found == 1);
  CHECK(hit.corners[0] == v || hit.corners[1] == v || hit.corners[2] == v);
  CHECK_VALID(mesh);
  /* Garbage collection renumbers: the tree is rebuilt, answers name the new indices. */
  CHECK_OK(hedge_mesh_garbage_collection(mesh, NULL, 0, NULL, 0, NULL, 0, NULL, 0));
  CHECK_OK(hedge_mesh_raycast(mesh, origin, down, INFINITY, &hit, &found));
  CHECK(found == 1 && face_has_point(mesh, hit.face, 0.25f, 1.5f));
  CHECK_OK(hedge_mesh_bvh_release(mesh));
  CHECK_OK(hedge_mesh_bvh_release(mesh)); /* no tree: nothing to do */
  CHECK_OK(hedge_mesh_raycast(mesh, origin, down, INFINITY, &hit, &found));
  CHECK(found == 1);

  /* Bad input: a clear error naming what, and nothing found. */
  const float nan3[3] = {NAN, 0, 0}, zero[3] = {0, 0, 0};
  CHECK_STATUS(hedge_mesh_raycast(mesh, nan3, down, INFINITY, &hit, &found), HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK_ERROR_HAS("origin");
  CHECK_STATUS(hedge_mesh_raycast(mesh, origin, zero, INFINITY, &hit, &found), HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK_ERROR_HAS("direction is zero");
  CHECK_STATUS(hedge_mesh_raycast(mesh, origin, down, -1, &hit, &found), HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK_ERROR_HAS("t_max");
  CHECK_STATUS(hedge_mesh_raycast(mesh, NULL, down, 1, &hit, &found), HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK_STATUS(hedge_mesh_raycast(mesh, origin, down, 1, NULL, &found), HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK_STATUS(hedge_mesh_raycast(mesh, origin, down, 1, &hit, NULL), HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK_STATUS(hedge_mesh_closest_point(mesh, above, NAN, &hit, &found), HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK_ERROR_HAS("max_distance");
  CHECK_STATUS(hedge_mesh_face_containing_point(mesh, on, INFINITY, &hit, &found),
               HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK_ERROR_HAS("tolerance");
  CHECK_STATUS(hedge_mesh_face_containing_point_2d(mesh, 0, 0, 7, &hit, &found),
               HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK_ERROR_HAS("HEDGE_PLANE_");
  CHECK_STATUS(hedge_mesh_face_containing_point_2d(mesh, INFINITY, 0, HEDGE_PLANE_XY, &hit, &found),
               HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK_STATUS(hedge_mesh_bvh_update(NULL, NULL), HEDGE_ERROR_BAD_HANDLE);
  CHECK_STATUS(hedge_mesh_bvh_release(NULL), HEDGE_ERROR_BAD_HANDLE);
  CHECK_STATUS(hedge_mesh_closest_point(NULL, above, 1, &hit, &found), HEDGE_ERROR_BAD_HANDLE);
  CHECK_VALID(mesh);
  CHECK_OK(hedge_mesh_destroy(mesh));

  /* A mesh with no face yet: nothing is found, and a face added later is. */
  hedge_mesh* empty = make_mesh(kGridPositions, 9, NULL, 0, NULL, 0);
  CHECK_OK(hedge_mesh_raycast(empty, origin, down, INFINITY, &hit, &found));
  CHECK(found == 0);
  const uint32_t corners[3] = {3, 4, 6}; /* (0, 1), (1, 1), (0, 2): under (0.25, 1.5) */
  uint32_t face = INVALID;
  CHECK_OK(hedge_add_face(empty, corners, 3, &face));
  CHECK_OK(hedge_mesh_raycast(empty, origin, down, INFINITY, &hit, &found));
  CHECK(found == 1 && hit.face == face);
  CHECK_VALID(empty);
  CHECK_OK(hedge_mesh_destroy(empty));
}

/* Every live triangle slot names the face that owns it, after a split, a collapse and compaction. */
static void check_triangle_faces(const hedge_mesh* mesh, const hedge_render* render) {
  hedge_buffer_counts bc;
  CHECK_OK(hedge_render_counts(render, &bc));
  hedge_counts c = counts_of(mesh);
  uint32_t named = 0;
  for (uint32_t t = 0; t < bc.index_count / 3; ++t) {
    uint32_t f = 12345, first = 0, count = 0;
    CHECK_OK(hedge_render_triangle_face(render, t, &f));
    if (f == INVALID) continue;
    ++named;
    CHECK_OK(hedge_render_face_triangles(render, f, &first, &count));
    CHECK(t >= first && t < first + count);
  }
  CHECK(named == c.faces);
  uint32_t f = 0;
  CHECK_STATUS(hedge_render_triangle_face(render, bc.index_count / 3, &f), HEDGE_ERROR_BAD_HANDLE);
  CHECK_ERROR_HAS("triangle");
  CHECK_STATUS(hedge_render_triangle_face(render, 0, NULL), HEDGE_ERROR_INVALID_ARGUMENT);
}

static void test_triangle_faces(void) {
  hedge_mesh* mesh = make_triangle_grid();
  hedge_render* render = NULL;
  CHECK_OK(hedge_render_create(mesh, NULL, &render));
  check_triangle_faces(mesh, render);
  /* Split the edge 1-4: the new vertex's four faces each own their triangle. */
  uint32_t h = INVALID, e = INVALID, v = INVALID, faces[8], n = 0;
  CHECK_OK(hedge_mesh_find_halfedge(mesh, 1, 4, &h));
  CHECK_OK(hedge_halfedge_edge(mesh, h, &e));
  CHECK_OK(hedge_split_edge(mesh, e, 1, 0.5f, 0, &v));
  CHECK_OK(hedge_render_sync(render, NULL));
  CHECK_OK(hedge_vertex_faces(mesh, v, faces, 8, &n));
  CHECK(n == 4);
  for (uint32_t i = 0; i < n; ++i) {
    uint32_t first = 0, count = 0, f = INVALID;
    CHECK_OK(hedge_render_face_triangles(render, faces[i], &first, &count));
    CHECK(count == 1);
    CHECK_OK(hedge_render_triangle_face(render, first, &f));
    CHECK(f == faces[i]);
  }
  check_triangle_faces(mesh, render);
  /* Collapse the new vertex away. Before the next sync, the slots of the faces it deleted name no
   * face (the buffers still hold them), and after the sync they are free. */
  uint32_t old_first[4], count = 0, f = 0;
  for (uint32_t i = 0; i < 4; ++i)
    CHECK_OK(hedge_render_face_triangles(render, faces[i], &old_first[i], &count));
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
    CHECK_OK(hedge_render_triangle_face(render, old_first[i], &f));
    CHECK(f == INVALID);
  }
  CHECK(dead_faces == 2);
  CHECK_OK(hedge_render_sync(render, NULL));
  check_triangle_faces(mesh, render);
  /* Compaction moves the triangles; the map follows. */
  CHECK_OK(hedge_render_compact(render, NULL, 0, NULL, NULL, 0, NULL));
  check_triangle_faces(mesh, render);
  CHECK_VALID(mesh);
  CHECK_OK(hedge_mesh_destroy(mesh));
}

int main(void) {
  test_basics();
  test_tetrahedron();
  test_bad_handles();
  test_create_errors();
  test_pyramid_operations();
  test_grid_operations();
  test_files();
  test_hostile_files();
  test_validation_text();
  test_render();
  test_render_lifetime();
  test_geometry();
  test_hausdorff();
  test_smooth();
  test_decimate();
  test_fracture();
  test_subdivide();
  test_picking();
  test_triangle_faces();
  test_every_function_error_path();
  test_threads();
  printf("c_api_test: %d checks passed\n", g_checks);
  return 0;
}
