/* Tests of the thread setting of the C ABI (hedge_set_max_threads, hedge_max_threads), compiled as
 * C11: the value round-trips, 0 restores the default, a NULL out pointer is refused, and a
 * subdivision gives the same positions on one thread as on two. */
#include "capi_test.h"

int g_checks = 0;

enum { kSide = 200 }; /* quads per side: 40000 quads, enough for two threads per subdivision pass */

/* A wavy grid of quads, subdivided once by Catmull-Clark; returns its positions (3 floats a slot). */
static float* subdivided_grid(uint64_t* out_count) {
  const uint32_t n = kSide + 1;
  float* positions = malloc(sizeof(float) * 3 * n * n);
  uint32_t* indices = malloc(sizeof(uint32_t) * 4 * kSide * kSide);
  uint32_t* sizes = malloc(sizeof(uint32_t) * kSide * kSide);
  CHECK(positions && indices && sizes);
  for (uint32_t y = 0; y < n; ++y)
    for (uint32_t x = 0; x < n; ++x) {
      float* p = positions + 3 * (y * n + x);
      p[0] = (float)x;
      p[1] = (float)y;
      p[2] = (float)((x * 7 + y * 13) % 5) * 0.25f;
    }
  for (uint32_t y = 0; y < kSide; ++y)
    for (uint32_t x = 0; x < kSide; ++x) {
      uint32_t* q = indices + 4 * (y * kSide + x);
      q[0] = y * n + x;
      q[1] = y * n + x + 1;
      q[2] = (y + 1) * n + x + 1;
      q[3] = (y + 1) * n + x;
      sizes[y * kSide + x] = 4;
    }
  hedge_mesh* mesh = make_mesh(positions, n * n, indices, 4 * kSide * kSide, sizes, kSide * kSide);
  CHECK_OK(hedge_mesh_subdivide(mesh, HEDGE_SUBDIVISION_CATMULL_CLARK, 1));
  CHECK_VALID(mesh);
  uint64_t count = 0;
  CHECK_STATUS(hedge_mesh_copy_positions(mesh, NULL, 0, &count), HEDGE_ERROR_BUFFER_TOO_SMALL);
  float* out = malloc(sizeof(float) * count);
  CHECK(out != NULL);
  CHECK_OK(hedge_mesh_copy_positions(mesh, out, count, &count));
  CHECK_OK(hedge_mesh_destroy(mesh));
  free(positions);
  free(indices);
  free(sizes);
  *out_count = count;
  return out;
}

int main(void) {
  uint32_t n = 0;
  CHECK_OK(hedge_max_threads(&n));
  CHECK(n >= 1);
  const uint32_t cores = n;

  CHECK_OK(hedge_set_max_threads(1));
  CHECK(hedge_max_threads(&n) == HEDGE_OK && n == 1);
  uint64_t one_count = 0;
  float* one = subdivided_grid(&one_count);

  CHECK_OK(hedge_set_max_threads(2));
  CHECK(hedge_max_threads(&n) == HEDGE_OK && n == 2);
  uint64_t two_count = 0;
  float* two = subdivided_grid(&two_count);
  CHECK(one_count == two_count);
  CHECK(memcmp(one, two, sizeof(float) * one_count) == 0);
  free(one);
  free(two);

  CHECK_OK(hedge_set_max_threads(0));
  CHECK(hedge_max_threads(&n) == HEDGE_OK && n == cores);

  CHECK_STATUS(hedge_max_threads(NULL), HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK_ERROR_HAS("out_n");
  CHECK(hedge_max_threads(&n) == HEDGE_OK && hedge_last_error()[0] == '\0');

  printf("threads_test: %d checks passed\n", g_checks);
  return 0;
}
