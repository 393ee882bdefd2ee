/* Shared by the tests of the C ABI (include/hedge/c_api.h), compiled as C11: one test file per
 * source of src/capi/ (c_api_test.c: errors, creation, files, validation, the error path of every
 * function, threads, and main(); queries_test.c, operations_test.c, render_test.c,
 * algorithms_test.c, picking_test.c), linked into one program. Every function of the header is
 * called at least once, with its error paths; tests/capi/check_coverage.cmake checks that over all
 * of them. Each CHECK reports file:line and exits non-zero on failure.
 * The programs of their own (fracture_test.c, threads_test.c) use the same checks and helpers: each
 * defines its own g_checks, and uses none of the shared meshes or tests declared at the end. */
#pragma once

#include <math.h>
#include <stdatomic.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "hedge/c_api.h"
#include "test_threads.h"

extern int g_checks; /* counted by CHECK, defined in c_api_test.c */

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

static inline hedge_counts counts_of(const hedge_mesh* mesh) {
  hedge_counts c;
  memset(&c, 0xAB, sizeof c);
  CHECK_OK(hedge_mesh_counts(mesh, &c));
  return c;
}

static inline int same_counts(hedge_counts a, hedge_counts b) { return memcmp(&a, &b, sizeof a) == 0; }

/* validate() reports no problem: the count is 0, the report is "", problem 0 does not exist. */
static inline void check_valid_at(hedge_mesh* mesh, const char* file, int line) {
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

static inline void get_position(const hedge_mesh* mesh, uint32_t v, float out[3]) {
  CHECK_OK(hedge_vertex_position(mesh, v, out));
}

static inline uint32_t to_vertex(const hedge_mesh* mesh, uint32_t h) {
  uint32_t v = 0;
  CHECK_OK(hedge_halfedge_to_vertex(mesh, h, &v));
  return v;
}

static inline uint32_t from_vertex(const hedge_mesh* mesh, uint32_t h) {
  uint32_t v = 0;
  CHECK_OK(hedge_halfedge_from_vertex(mesh, h, &v));
  return v;
}

static inline uint32_t next_of(const hedge_mesh* mesh, uint32_t h) {
  uint32_t n = 0;
  CHECK_OK(hedge_halfedge_next(mesh, h, &n));
  return n;
}

static inline int contains(const uint32_t* a, uint32_t n, uint32_t x) {
  for (uint32_t i = 0; i < n; ++i)
    if (a[i] == x) return 1;
  return 0;
}

/* The corners of `face` equal `expected` (n corners) up to a rotation. */
static inline int face_is(const hedge_mesh* mesh, uint32_t face, const uint32_t* expected, uint32_t n) {
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

static inline void copy_positions(const hedge_mesh* mesh, float* out, uint64_t capacity) {
  uint64_t count = 0;
  CHECK_OK(hedge_mesh_copy_positions(mesh, out, capacity, &count));
}

static inline void write_text(const char* path, const char* text) {
  FILE* f = fopen(path, "wb");
  CHECK(f != NULL);
  CHECK(fputs(text, f) >= 0);
  CHECK(fclose(f) == 0);
}

/* A tetrahedron, outward counter-clockwise faces. */
extern const float kTetPositions[];
extern const uint32_t kTetTriangles[];

/* A square pyramid without its base: 4 triangles about apex 4, one boundary loop of 4 edges. */
extern const float kPyramidPositions[];
extern const uint32_t kPyramidTriangles[];

/* A 3 x 3 grid of vertices (row-major, z = 0) in 2 x 2 quads. */
extern const float kGridPositions[];
extern const uint32_t kGridQuads[];
extern const uint32_t kGridSizes[];

static inline hedge_mesh* make_mesh(const float* positions, uint32_t nv, const uint32_t* indices, uint32_t ni,
                                    const uint32_t* sizes, uint32_t nf) {
  hedge_mesh* mesh = NULL;
  CHECK_OK(hedge_mesh_create(positions, nv, indices, ni, sizes, nf, NULL, NULL, NULL, NULL, &mesh));
  CHECK(mesh != NULL);
  return mesh;
}

/* The 2 x 2 quad grid, triangulated: 8 triangles in the plane z = 0, x and y in [0, 2]. */
static inline hedge_mesh* make_triangle_grid(void) {
  uint32_t tris[24];
  for (int q = 0; q < 4; ++q) {
    const uint32_t* c = kGridQuads + 4 * q;
    const uint32_t t[6] = {c[0], c[1], c[2], c[0], c[2], c[3]};
    memcpy(tris + 6 * q, t, sizeof t);
  }
  return make_mesh(kGridPositions, 9, tris, 24, NULL, 0);
}

/* A plate of n x n quads, each two triangles, in z = 0: (n + 1)^2 vertices, x and y in [0, n]. */
static inline hedge_mesh* make_plate(uint32_t n) {
  float* positions = malloc(sizeof(float) * 3 * (n + 1) * (n + 1));
  uint32_t* triangles = malloc(sizeof(uint32_t) * 6 * n * n);
  CHECK(positions != NULL && triangles != NULL);
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

/* The tests, run in this order by main() (c_api_test.c). */
void test_basics(void);
void test_tetrahedron(void);
void test_bad_handles(void);
void test_create_errors(void);
void test_pyramid_operations(void);
void test_grid_operations(void);
void test_files(void);
void test_hostile_files(void);
void test_validation_text(void);
void test_render(void);
void test_render_lifetime(void);
void test_geometry(void);
void test_hausdorff(void);
void test_smooth(void);
void test_decimate(void);
void test_fracture(void);
void test_subdivide(void);
void test_mirror(void);
void test_engine_sources(void);
void test_picking(void);
void test_solid_fracture(void);
void test_triangle_faces(void);
void test_submeshes(void);
void test_engine_streams(void);
void test_every_function_error_path(void);
void test_threads(void);
