/* Tests of solid fracture through the C ABI (src/capi/solid_fracture.cpp), compiled as C11: spot
 * struck breaks into closed, valid pieces whose volumes and the remaining object's add up to the
 * input's; the bonds are sorted, their ends legal and each piece's bonds cover its cap; the same
 * strike on a twin mesh gives the same pieces; caps carry the inner submesh; an open mesh and a NaN
 * impact are refused with the mesh unchanged; the result handle's errors.
 * Each CHECK reports file:line and exits non-zero on failure. */
#include <stddef.h>

#include "capi_test.h"

enum { kMaxPieces = 64, kMaxBonds = 512 };

static hedge_mesh* read_spot(void) {
  hedge_mesh* spot = NULL;
  CHECK_OK(hedge_mesh_read(HEDGE_DATA_DIR "/spot_triangulated.obj", NULL, NULL, &spot));
  CHECK(spot != NULL);
  return spot;
}

static hedge_geometry geometry_of(const hedge_mesh* mesh) {
  hedge_geometry g;
  CHECK_OK(hedge_mesh_geometry(mesh, &g));
  return g;
}

/* A point of spot's surface: straight down from above its centre. */
static void spot_top(hedge_mesh* spot, float out[3]) {
  const hedge_geometry g = geometry_of(spot);
  const float origin[3] = {0.5f * (g.box_min[0] + g.box_max[0]), g.box_max[1] + 1,
                           0.5f * (g.box_min[2] + g.box_max[2])};
  const float down[3] = {0, -1, 0};
  hedge_surface_hit hit;
  int32_t found = 0;
  CHECK_OK(hedge_mesh_raycast(spot, origin, down, INFINITY, &hit, &found));
  CHECK(found == 1);
  memcpy(out, hit.point, sizeof hit.point);
}

static double relative(double a, double b) { return fabs(a - b) / fmax(fabs(b), 1e-300); }

/* The stone preset at a break radius of 0.3 (spot is about 1.9 across), seed 7, caps in submesh 5. */
static hedge_solid_fracture_options stone(void) {
  hedge_solid_fracture_options o;
  CHECK_OK(hedge_solid_fracture_options_default(HEDGE_FRACTURE_STONE, &o));
  o.radius = 0.3;
  o.seed = 7;
  o.inner_submesh = 5;
  return o;
}

static void test_layout(void) {
  CHECK(sizeof(hedge_solid_fracture_options) == 440 && sizeof(hedge_solid_piece) == 240 &&
        sizeof(hedge_solid_bond) == 16 && sizeof(hedge_solid_fracture_summary) == 48);
  CHECK(offsetof(hedge_solid_fracture_options, ring_count) == 384 &&
        offsetof(hedge_solid_fracture_options, radius) == 392 &&
        offsetof(hedge_solid_fracture_options, seed) == 408 &&
        offsetof(hedge_solid_fracture_options, inner_submesh) == 432);
  CHECK(offsetof(hedge_solid_piece, volume) == 16 && offsetof(hedge_solid_piece, inertia) == 64 &&
        offsetof(hedge_solid_piece, principal_axes) == 160 &&
        offsetof(hedge_solid_piece, hull_dimension) == 232);
  CHECK(offsetof(hedge_solid_bond, area) == 8 && offsetof(hedge_solid_fracture_summary, impact_point) == 16 &&
        offsetof(hedge_solid_fracture_summary, radius) == 40);
  hedge_solid_fracture_options o;
  CHECK_OK(hedge_solid_fracture_options_default(HEDGE_FRACTURE_GLASS, &o));
  CHECK(o.ring_count == 4 && o.radius == 0 && o.radius_fraction > 0 && o.density == 1 && o.hulls == 1 &&
        o.inner_submesh == -1);
  CHECK_STATUS(hedge_solid_fracture_options_default(9, &o), HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK_ERROR_HAS("preset");
}

/* Strikes spot on top; checks every piece, the volumes and the bonds. Fills `volumes` (one per
 * piece) and returns the piece count. */
static uint32_t strike_and_check(hedge_mesh* spot, double* volumes) {
  const double before = geometry_of(spot).volume;
  float at[3];
  spot_top(spot, at);
  const hedge_solid_fracture_options o = stone();
  char why[256];
  uint32_t size = 0;
  CHECK_OK(hedge_solid_fracture_refusal(spot, at[0], at[1], at[2], &o, why, sizeof why, &size));
  CHECK(size == 1 && why[0] == '\0');
  hedge_solid_fracture* result = NULL;
  CHECK_OK(hedge_mesh_fracture_solid(spot, at[0], at[1], at[2], &o, &result));
  CHECK(result != NULL);
  hedge_solid_fracture_summary s;
  CHECK_OK(hedge_solid_fracture_get_summary(result, &s));
  CHECK(s.piece_count >= 2 && s.piece_count <= kMaxPieces && s.bond_count >= 1 && s.bond_count <= kMaxBonds);
  CHECK(s.radius == 0.3);
  CHECK(fabs(s.impact_point[1] - at[1]) < 1e-3);

  hedge_solid_piece pieces[kMaxPieces];
  hedge_solid_bond bonds[kMaxBonds];
  uint32_t n = 0, nb = 0;
  CHECK_STATUS(hedge_solid_fracture_copy_pieces(result, pieces, 1, &n), HEDGE_ERROR_BUFFER_TOO_SMALL);
  CHECK(n == s.piece_count);
  CHECK_OK(hedge_solid_fracture_copy_pieces(result, pieces, kMaxPieces, &n));
  CHECK_OK(hedge_solid_fracture_copy_bonds(result, bonds, kMaxBonds, &nb));
  CHECK(n == s.piece_count && nb == s.bond_count);

  const hedge_geometry rest = geometry_of(spot);
  CHECK(rest.closed == 1);
  CHECK_VALID(spot);
  double total = rest.volume;
  for (uint32_t i = 0; i < n; ++i) {
    const hedge_geometry g = geometry_of(pieces[i].mesh);
    CHECK(g.closed == 1);
    CHECK_VALID(pieces[i].mesh);
    CHECK(pieces[i].volume > 0 && relative(pieces[i].volume, g.volume) < 1e-9);
    CHECK(pieces[i].cap_area > 0 && pieces[i].mass > 0);
    CHECK(pieces[i].principal_moments[0] > 0 &&
          pieces[i].principal_moments[0] <= pieces[i].principal_moments[2]);
    CHECK(pieces[i].hull != NULL && pieces[i].hull_dimension == 4);
    /* The caps, and only they, are in submesh 5 (spot has no submesh of its own). */
    uint64_t slots = 0;
    CHECK_STATUS(hedge_mesh_copy_face_submeshes(pieces[i].mesh, NULL, 0, &slots),
                 HEDGE_ERROR_BUFFER_TOO_SMALL);
    int32_t* sub = malloc(sizeof(int32_t) * (slots + 1));
    CHECK(sub != NULL);
    CHECK_OK(hedge_mesh_copy_face_submeshes(pieces[i].mesh, sub, slots, &slots));
    uint64_t caps = 0;
    for (uint64_t f = 0; f < slots; ++f) {
      CHECK(sub[f] == 0 || sub[f] == 5);
      caps += sub[f] == 5;
    }
    CHECK(caps > 0);
    free(sub);
    volumes[i] = pieces[i].volume;
    total += pieces[i].volume;
  }
  CHECK(relative(total, before) < 1e-6);

  /* Bonds: sorted, a < b, ends that name pieces or the remaining object; each piece's bonds share
   * what its cap has (every cap face lies on a face between two cells, or on the broken region's
   * boundary against the remaining object). */
  double* bonded = calloc(n, sizeof(double));
  CHECK(bonded != NULL);
  for (uint32_t k = 0; k < nb; ++k) {
    const hedge_solid_bond b = bonds[k];
    CHECK(b.a < n && (b.b == HEDGE_SOLID_REMAINING || (b.b < n && b.a < b.b)) && b.area > 0);
    if (k > 0) CHECK(bonds[k - 1].a < b.a || (bonds[k - 1].a == b.a && bonds[k - 1].b < b.b));
    bonded[b.a] += b.area;
    if (b.b != HEDGE_SOLID_REMAINING) bonded[b.b] += b.area;
  }
  for (uint32_t i = 0; i < n; ++i) CHECK(relative(bonded[i], pieces[i].cap_area) < 1e-3);
  free(bonded);

  for (uint32_t i = 0; i < n; ++i) {
    CHECK_OK(hedge_mesh_destroy(pieces[i].mesh));
    CHECK_OK(hedge_mesh_destroy(pieces[i].hull));
  }
  CHECK_OK(hedge_solid_fracture_destroy(result));
  CHECK_STATUS(hedge_solid_fracture_destroy(result), HEDGE_ERROR_BAD_HANDLE);
  CHECK_STATUS(hedge_solid_fracture_get_summary(result, &s), HEDGE_ERROR_BAD_HANDLE);
  CHECK_STATUS(hedge_solid_fracture_copy_bonds(result, bonds, kMaxBonds, &nb), HEDGE_ERROR_BAD_HANDLE);
  return n;
}

static void test_spot(void) {
  hedge_mesh* a = read_spot();
  hedge_mesh* b = read_spot();
  double va[kMaxPieces], vb[kMaxPieces];
  const uint32_t na = strike_and_check(a, va);
  const uint32_t nb = strike_and_check(b, vb);
  CHECK(na == nb && memcmp(va, vb, sizeof(double) * na) == 0); /* bit for bit */
  CHECK_OK(hedge_mesh_destroy(a));
  CHECK_OK(hedge_mesh_destroy(b));
}

/* A refused strike leaves the mesh as it was: same counts, same positions. */
static void check_refused(hedge_mesh* mesh, float x, float y, float z, double radius, const char* reason,
                          hedge_solid_refusal code) {
  const hedge_counts before = counts_of(mesh);
  const uint64_t n = 3 * (uint64_t)before.vertex_slots;
  float* p0 = malloc(sizeof(float) * n);
  float* p1 = malloc(sizeof(float) * n);
  CHECK(p0 != NULL && p1 != NULL);
  copy_positions(mesh, p0, n);
  hedge_solid_fracture_options o = stone();
  o.radius = radius;
  char why[512];
  uint32_t size = 0;
  CHECK_OK(hedge_solid_fracture_refusal(mesh, x, y, z, &o, why, sizeof why, &size));
  CHECK(size > 1 && strstr(why, reason) != NULL);
  hedge_solid_refusal got = -1;
  CHECK_OK(hedge_solid_fracture_refusal_code(mesh, x, y, z, &o, &got));
  CHECK(got == code);
  hedge_solid_fracture* result = (hedge_solid_fracture*)1;
  CHECK_STATUS(hedge_mesh_fracture_solid(mesh, x, y, z, &o, &result), HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK(result == NULL);
  CHECK_ERROR_HAS(reason);
  CHECK(same_counts(before, counts_of(mesh)));
  copy_positions(mesh, p1, n);
  CHECK(memcmp(p0, p1, sizeof(float) * n) == 0);
  CHECK_VALID(mesh);
  free(p0);
  free(p1);
}

static void test_refusals(void) {
  /* The plate's boundary lies within the broken region (the check looks no farther). */
  hedge_mesh* plate = make_plate(4);
  check_refused(plate, 2, 2, 0, 3, "the mesh is open: edge", HEDGE_SOLID_REFUSAL_OPEN);
  /* Off the surface: a refusal "auto" reports, whatever the mesh's shape. */
  check_refused(plate, 2, 2, 5, 3, "beyond the tolerance", HEDGE_SOLID_REFUSAL_OFF_SURFACE);
  CHECK_OK(hedge_mesh_destroy(plate));
  hedge_mesh* spot = read_spot();
  float at[3];
  spot_top(spot, at);
  check_refused(spot, NAN, at[1], at[2], 0.3, "finite", HEDGE_SOLID_REFUSAL_BAD_IMPACT);
  hedge_solid_refusal code = -1;
  CHECK_OK(hedge_solid_fracture_refusal_code(spot, at[0], at[1], at[2], NULL, &code));
  CHECK(code == HEDGE_SOLID_REFUSAL_NONE); /* closed: no fallback */
  /* An option out of range is a reason too, naming the field. */
  hedge_solid_fracture_options o = stone();
  o.density = -1;
  char why[256];
  uint32_t size = 0;
  CHECK_OK(hedge_solid_fracture_refusal(spot, at[0], at[1], at[2], &o, why, sizeof why, &size));
  CHECK(strstr(why, "density") != NULL);
  CHECK_OK(hedge_solid_fracture_refusal_code(spot, at[0], at[1], at[2], &o, &code));
  CHECK(code == HEDGE_SOLID_REFUSAL_BAD_OPTION);
  o.ring_count = HEDGE_FRACTURE_MAX_RINGS + 1; /* the C ABI's own check of the options */
  CHECK_OK(hedge_solid_fracture_refusal_code(spot, at[0], at[1], at[2], &o, &code));
  CHECK(code == HEDGE_SOLID_REFUSAL_BAD_OPTION);
  CHECK_STATUS(hedge_solid_fracture_refusal_code(spot, at[0], at[1], at[2], NULL, NULL),
               HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK_STATUS(hedge_solid_fracture_refusal_code(NULL, at[0], at[1], at[2], NULL, &code),
               HEDGE_ERROR_BAD_HANDLE);
  CHECK_STATUS(hedge_solid_fracture_refusal(spot, at[0], at[1], at[2], &o, why, 1, &size),
               HEDGE_ERROR_BUFFER_TOO_SMALL);
  o = stone();
  o.ring_count = HEDGE_FRACTURE_MAX_RINGS + 1;
  hedge_solid_fracture* result = NULL;
  CHECK_STATUS(hedge_mesh_fracture_solid(spot, at[0], at[1], at[2], &o, &result),
               HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK_ERROR_HAS("ring_count");
  CHECK_STATUS(hedge_mesh_fracture_solid(spot, at[0], at[1], at[2], NULL, NULL),
               HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK_STATUS(hedge_mesh_fracture_solid(NULL, at[0], at[1], at[2], NULL, &result), HEDGE_ERROR_BAD_HANDLE);
  CHECK_STATUS(hedge_solid_fracture_get_summary(NULL, NULL), HEDGE_ERROR_BAD_HANDLE);
  CHECK_STATUS(hedge_solid_fracture_copy_pieces(NULL, NULL, 0, &size), HEDGE_ERROR_BAD_HANDLE);
  CHECK_OK(hedge_mesh_destroy(spot));
}

void test_solid_fracture(void) {
  test_layout();
  test_spot();
  test_refusals();
}
