/* Tests of hedge_mesh_fracture() through the mesh's picking tree (src/capi/algorithms.cpp and
 * picking.cpp), compiled as C11: strikes in a row on one mesh, whose tree each strike keeps up to
 * date, give the same shards as the same strikes on a twin mesh whose tree is freed before each
 * strike (so each strike builds a fresh one); a strike where an earlier one removed the faces finds
 * no surface there; open shards weigh as thin shells; a break radius in model units, a relative thickness,
 * the inner faces' submesh and the principal moments and axes. The rest of hedge_mesh_fracture() is tested in
 * algorithms_test.c.
 * Each CHECK reports file:line and exits non-zero on failure. */
#include "capi_test.h"

int g_checks = 0;

enum { kMaxShards = 64 };

/* The two meshes have the same counts and the same positions in the same slots. */
static void check_same_mesh(const hedge_mesh* a, const hedge_mesh* b) {
  const hedge_counts ca = counts_of(a), cb = counts_of(b);
  CHECK(same_counts(ca, cb));
  const uint64_t n = 3 * (uint64_t)ca.vertex_slots;
  float* pa = malloc(sizeof(float) * (n + 1));
  float* pb = malloc(sizeof(float) * (n + 1));
  CHECK(pa != NULL && pb != NULL);
  uint64_t na = 0, nb = 0;
  CHECK_OK(hedge_mesh_copy_positions(a, pa, n, &na));
  CHECK_OK(hedge_mesh_copy_positions(b, pb, n, &nb));
  CHECK(na == n && nb == n && memcmp(pa, pb, sizeof(float) * n) == 0);
  free(pa);
  free(pb);
}

/* Strikes `cached` (its tree kept from earlier calls) and `fresh` (its tree freed first) at the same
 * point with the same seed: the same shards, the same remaining meshes. Returns the shard count. */
static uint32_t strike_both(hedge_mesh* cached, hedge_mesh* fresh, float x, float y, uint64_t seed) {
  hedge_fracture_options o;
  CHECK_OK(hedge_fracture_options_default(HEDGE_FRACTURE_GLASS, &o));
  o.seed = seed;
  hedge_fracture_shard a[kMaxShards], b[kMaxShards];
  uint32_t na = 0, nb = 0;
  CHECK_OK(hedge_mesh_fracture(cached, x, y, 0, &o, a, kMaxShards, &na));
  CHECK_OK(hedge_mesh_bvh_release(fresh));
  CHECK_OK(hedge_mesh_fracture(fresh, x, y, 0, &o, b, kMaxShards, &nb));
  CHECK(na > 0 && na == nb);
  for (uint32_t i = 0; i < na && i < nb; ++i) {
    CHECK(a[i].area == b[i].area && a[i].area > 0);
    /* Open shards weigh as thin shells by default: a mass and a positive-definite inertia. */
    CHECK(a[i].closed == 0 && a[i].mass > 0 && a[i].mass == b[i].mass && a[i].principal_moments[0] > 0);
    CHECK(a[i].centroid[0] == b[i].centroid[0] && a[i].centroid[1] == b[i].centroid[1]);
    check_same_mesh(a[i].mesh, b[i].mesh);
    CHECK_VALID(a[i].mesh);
    CHECK((a[i].hull == NULL) == (b[i].hull == NULL));
    CHECK_OK(hedge_mesh_destroy(a[i].mesh));
    CHECK_OK(hedge_mesh_destroy(b[i].mesh));
    if (a[i].hull != NULL) CHECK_OK(hedge_mesh_destroy(a[i].hull));
    if (b[i].hull != NULL) CHECK_OK(hedge_mesh_destroy(b[i].hull));
  }
  check_same_mesh(cached, fresh);
  CHECK_VALID(cached);
  CHECK_VALID(fresh);
  return na;
}

/* Straight down onto the plate at (x, y): whether the picking tree finds a face, and which. */
static int32_t pick_down(hedge_mesh* mesh, float x, float y, uint32_t* out_face) {
  const float origin[3] = {x, y, 1}, down[3] = {0, 0, -1};
  hedge_surface_hit hit;
  int32_t found = -1;
  CHECK_OK(hedge_mesh_raycast(mesh, origin, down, INFINITY, &hit, &found));
  if (found) *out_face = hit.face;
  return found;
}

/* The centroid of a live face. */
static void face_centroid(const hedge_mesh* mesh, uint32_t f, float out[2]) {
  uint32_t corners[8], n = 0;
  CHECK_OK(hedge_face_vertices(mesh, f, corners, 8, &n));
  CHECK(n >= 3);
  double x = 0, y = 0;
  for (uint32_t i = 0; i < n; ++i) {
    float p[3];
    CHECK_OK(hedge_vertex_position(mesh, corners[i], p));
    x += p[0], y += p[1];
  }
  out[0] = (float)(x / n), out[1] = (float)(y / n);
}

static void test_strikes_in_a_row(void) {
  hedge_mesh* cached = make_plate(40);
  hedge_mesh* fresh = make_plate(40);
  uint64_t bytes = 0;
  CHECK_OK(hedge_mesh_bvh_update(cached, &bytes));
  CHECK(bytes > 0);

  /* The first strike: the tree built above locates it. */
  CHECK(strike_both(cached, fresh, 20.3f, 19.6f, 5) >= 20);

  /* Where the first strike broke the plate: no surface, for picking and for a second strike,
   * which is refused with the mesh unchanged. */
  uint32_t face = HEDGE_INVALID_INDEX;
  CHECK(pick_down(cached, 20.3f, 19.6f, &face) == 0);
  const hedge_counts before = counts_of(cached);
  hedge_fracture_shard shards[kMaxShards];
  uint32_t count = 0;
  CHECK_STATUS(hedge_mesh_fracture(cached, 20.3f, 19.6f, 0, NULL, shards, kMaxShards, &count),
               HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK_ERROR_HAS("tolerance");
  const hedge_counts after = counts_of(cached);
  CHECK(same_counts(before, after));

  /* At the rim of the hole: the remaining face nearest to the first impact (found face by face),
   * which the first strike cut or refined. The updated tree finds it, and a strike there breaks
   * what remains as a fresh tree does. */
  uint32_t rim = HEDGE_INVALID_INDEX;
  float at[2] = {0, 0};
  double nearest = INFINITY;
  for (uint32_t f = 0; f < after.face_slots; ++f) {
    int32_t deleted = 1;
    CHECK_OK(hedge_face_is_deleted(cached, f, &deleted));
    if (deleted) continue;
    float c[2];
    face_centroid(cached, f, c);
    const double d = hypot(c[0] - 20.3, c[1] - 19.6);
    if (d < nearest) nearest = d, rim = f, at[0] = c[0], at[1] = c[1];
  }
  CHECK(rim != HEDGE_INVALID_INDEX && nearest > 2);
  const float first_impact[3] = {20.3f, 19.6f, 0};
  hedge_surface_hit hit;
  int32_t found = 0;
  CHECK_OK(hedge_mesh_closest_point(cached, first_impact, INFINITY, &hit, &found));
  CHECK(found == 1 && hit.distance > 1);
  CHECK(pick_down(cached, at[0], at[1], &face) == 1 && face == rim);
  CHECK(strike_both(cached, fresh, at[0], at[1], 6) > 0);

  /* Far from both holes, where the plate is whole. */
  CHECK(strike_both(cached, fresh, 8.4f, 31.7f, 7) >= 20);
  CHECK(pick_down(cached, 8.4f, 31.7f, &face) == 0 && pick_down(cached, 35.5f, 5.5f, &face) == 1);

  CHECK_OK(hedge_mesh_destroy(cached));
  CHECK_OK(hedge_mesh_destroy(fresh));
}

/* The break radius in model units, a thickness relative to it, the inner faces' submesh and the
 * principal frame of each shard's inertia. */
static void test_radius_thickness_inner_faces_and_principal_frame(void) {
  hedge_fracture_options o;
  CHECK_OK(hedge_fracture_options_default(HEDGE_FRACTURE_GLASS, &o));
  const double refine = o.refine_edge;
  /* Refused radii leave the options as they were. */
  CHECK_STATUS(hedge_fracture_options_at_radius(&o, 0), HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK_ERROR_HAS("radius");
  CHECK_STATUS(hedge_fracture_options_at_radius(&o, NAN), HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK_STATUS(hedge_fracture_options_at_radius(NULL, 1), HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK(o.units == HEDGE_FRACTURE_UNITS_DIAGONAL_FRACTION && o.rings[0].spacing == 1.0 &&
        o.refine_edge == refine);
  CHECK(o.inner_submesh == -1 && o.relative_thickness == 0);
  CHECK_OK(hedge_fracture_options_at_radius(&o, 3.5));
  double sum = 0;
  for (uint32_t i = 0; i < o.ring_count; ++i) sum += o.rings[i].spacing;
  CHECK(o.units == HEDGE_FRACTURE_UNITS_MODEL && o.radius == 3.5 && fabs(sum - 3.5) < 1e-12 &&
        fabs(o.refine_edge - refine * 0.5) < 1e-12);

  for (int explicit_inner = 0; explicit_inner < 2; ++explicit_inner) {
    hedge_mesh* plate = make_plate(30);
    o.relative_thickness = 0.05;
    o.inner_submesh = explicit_inner ? 4 : -1;
    o.seed = 3;
    hedge_fracture_shard shards[kMaxShards];
    uint32_t count = 0;
    CHECK_OK(hedge_mesh_fracture(plate, 15.2f, 14.9f, 0, &o, shards, kMaxShards, &count));
    CHECK(count >= 20);
    const int32_t inner = explicit_inner ? 4 : 1;
    for (uint32_t i = 0; i < count; ++i) {
      const hedge_fracture_shard* s = &shards[i];
      /* 5% of the 3.5 radius: the solid of a flat shard is its area that thick. */
      CHECK(s->closed == 1 && fabs(s->volume - 0.175 * s->area) < 1e-4 * s->area);
      /* The principal frame: right-handed, and R diag(moments) R^T is the inertia tensor. */
      const double* a = s->principal_axes;
      const double det = a[0] * (a[4] * a[8] - a[5] * a[7]) - a[1] * (a[3] * a[8] - a[5] * a[6]) +
                         a[2] * (a[3] * a[7] - a[4] * a[6]);
      CHECK(fabs(det - 1) < 1e-9);
      CHECK(s->principal_moments[0] > 0 && s->principal_moments[0] <= s->principal_moments[1] &&
            s->principal_moments[1] <= s->principal_moments[2]);
      double largest = 0, worst = 0;
      for (int r = 0; r < 9; ++r) largest = fmax(largest, fabs(s->inertia[r]));
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) {
          double t = 0;
          for (int k = 0; k < 3; ++k) t += s->principal_moments[k] * a[3 * k + r] * a[3 * k + c];
          worst = fmax(worst, fabs(t - s->inertia[3 * r + c]));
        }
      CHECK(worst <= 1e-9 * largest);
      /* The faces the solid added carry the inner submesh, the broken faces 0. */
      uint64_t n = 0;
      CHECK_STATUS(hedge_mesh_copy_face_submeshes(s->mesh, NULL, 0, &n), HEDGE_ERROR_BUFFER_TOO_SMALL);
      int32_t* submesh = malloc(sizeof(int32_t) * (n + 1));
      CHECK(submesh != NULL);
      CHECK_OK(hedge_mesh_copy_face_submeshes(s->mesh, submesh, n, &n));
      uint64_t front = 0, added = 0;
      for (uint64_t f = 0; f < n; ++f) {
        CHECK(submesh[f] == 0 || submesh[f] == inner);
        front += submesh[f] == 0, added += submesh[f] == inner;
      }
      CHECK(front > 0 && added > front);
      free(submesh);
      CHECK_VALID(s->mesh);
      CHECK_OK(hedge_mesh_destroy(s->mesh));
      CHECK_OK(hedge_mesh_destroy(s->hull));
    }
    /* The plate itself has no submesh: every slot reads 0. */
    uint64_t n = 0;
    int32_t first[4] = {7, 7, 7, 7};
    CHECK_STATUS(hedge_mesh_copy_face_submeshes(plate, first, 4, &n), HEDGE_ERROR_BUFFER_TOO_SMALL);
    CHECK(n == counts_of(plate).face_slots);
    CHECK_VALID(plate);
    CHECK_OK(hedge_mesh_destroy(plate));
  }
}

int main(void) {
  test_strikes_in_a_row();
  test_radius_thickness_inner_faces_and_principal_frame();
  printf("fracture_test: %d checks passed\n", g_checks);
  return 0;
}
