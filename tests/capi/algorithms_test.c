/* The C ABI's algorithms (src/capi/algorithms.cpp): geometry, normals, distance, smoothing,
 * decimation, fracture, subdivision. */
#include <stddef.h>

#include "capi_test.h"

/* ---------------------------------------------------------------------------------------------- */
/* Geometry and normals                                                                           */
/* ---------------------------------------------------------------------------------------------- */

/* The unit cube as 6 quads, outward counter-clockwise. */
static const float kCubePositions[] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0,
                                       0, 0, 1, 1, 0, 1, 1, 1, 1, 0, 1, 1};
static const uint32_t kCubeQuads[] = {0, 3, 2, 1, 4, 5, 6, 7, 0, 1, 5, 4, 1, 2, 6, 5, 2, 3, 7, 6, 3, 0, 4, 7};
static const uint32_t kCubeSizes[] = {4, 4, 4, 4, 4, 4};

static int near(double a, double b, double eps) { return fabs(a - b) <= eps; }

void test_geometry(void) {
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
  hedge_render_buffers_options ro;
  CHECK_OK(hedge_render_buffers_options_default(&ro));
  ro.normals = HEDGE_NORMALS_ATTRIBUTE;
  hedge_render_buffers* render = NULL;
  CHECK_OK(hedge_render_buffers_create(cube, &ro, &render));
  hedge_buffer_counts bc;
  CHECK_OK(hedge_render_buffers_counts(render, &bc));
  CHECK(bc.vertices == 24);
  CHECK_OK(hedge_render_buffers_destroy(render));

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
    hedge_render_buffers_options follow;
    CHECK_OK(hedge_render_buffers_options_default(&follow));
    hedge_render_buffers *kept = NULL, *followed = NULL;
    CHECK_OK(hedge_render_buffers_create(cube, &ro, &kept));
    CHECK_OK(hedge_render_buffers_create(cube, &follow, &followed));
    CHECK_OK(hedge_set_vertex_position(cube, 6, 1, 1, 1.5f));
    hedge_render_buffers* both[2] = {kept, followed};
    float n[2][3];
    for (int i = 0; i < 2; ++i) {
      CHECK_OK(hedge_render_buffers_sync(both[i], NULL));
      hedge_vertex_layout layout;
      CHECK_OK(hedge_render_buffers_layout(both[i], &layout));
      uint32_t rv = INVALID;
      CHECK_OK(hedge_render_buffers_corner_vertex(both[i], top, &rv));
      const float* data = NULL;
      uint64_t floats = 0;
      CHECK_OK(hedge_render_buffers_vertex_data(both[i], HEDGE_STREAM_VERTICES, &data, &floats));
      CHECK((uint64_t)(rv + 1) * layout.stride <= floats && layout.normal >= 0);
      for (int a = 0; a < 3; ++a) n[i][a] = data[(uint64_t)rv * layout.stride + (uint32_t)layout.normal + a];
    }
    CHECK(n[0][0] == 0 && n[0][1] == 0 && n[0][2] == 1); /* kept */
    CHECK(n[1][2] < 0.99f && n[1][2] > 0.5f);            /* tilted by the raised corner */
    CHECK(near(n[1][0] * n[1][0] + n[1][1] * n[1][1] + n[1][2] * n[1][2], 1, 1e-6));
    CHECK_OK(hedge_render_buffers_destroy(kept));
    CHECK_OK(hedge_render_buffers_destroy(followed));
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
void test_hausdorff(void) {
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

void test_smooth(void) {
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
  CHECK_OK(hedge_vertex_position(grid, 4, p));
  CHECK(p[2] < 0.01f && p[2] >= 0);
  CHECK_OK(hedge_vertex_position(grid, 0, p));
  CHECK(p[0] == 0 && p[1] == 0 && p[2] == 0);
  /* A mask that excludes vertex 4: nothing moves. */
  hedge_mesh* again = make_mesh(lifted, 9, kGridQuads, 16, kGridSizes, 4);
  uint8_t mask[9] = {1, 1, 1, 1, 0, 1, 1, 1, 1};
  CHECK_OK(hedge_mesh_smooth(again, NULL, mask, 9));
  CHECK_OK(hedge_vertex_position(again, 4, p));
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
  CHECK_OK(hedge_vertex_position(again, 4, p));
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
    CHECK_OK(hedge_vertex_position(pyramid, 4, p));
    CHECK(p[2] < 0.5f && p[2] >= 0);
    CHECK_OK(hedge_mesh_destroy(pyramid));
  }
  CHECK_OK(hedge_vertex_position(again, 4, p));
  CHECK(p[2] < 1);
  CHECK_STATUS(hedge_smooth_options_default(NULL), HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK_OK(hedge_mesh_destroy(again));
  CHECK_OK(hedge_mesh_destroy(grid));
}

void test_decimate(void) {
  hedge_decimate_options o;
  memset(&o, 0xFF, sizeof o);
  CHECK(sizeof o == 80 && sizeof(hedge_decimate_result) == 64);
  CHECK(offsetof(hedge_decimate_options, relax_normal_change) == 72 &&
        offsetof(hedge_decimate_result, stop) == 32 &&
        offsetof(hedge_decimate_result, refused_topology) == 40 &&
        offsetof(hedge_decimate_result, refused_shape) == 56);
  CHECK_OK(hedge_decimate_options_default(&o));
  CHECK(o.target_vertices == 0 && o.target_faces == 0 && isinf(o.max_error) && o.boundary_weight == 1 &&
        o.max_normal_change_degrees == 60 && o.keep_boundary == 0 && o.keep_seams == 1 &&
        o.relax_normal_change == 1 && o.reserved == 0);
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
  CHECK(r.stop == HEDGE_DECIMATE_TARGET_REACHED && r.reserved == 0);
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
  CHECK(r.stop == HEDGE_DECIMATE_NO_LEGAL_COLLAPSE);
  CHECK_OK(hedge_mesh_validate(fresh, &problems));
  CHECK(problems == 0);
  CHECK_OK(hedge_mesh_destroy(fresh));
  /* A normal limit of 1 degree held to the end stops the run short, counting its refusals; relaxed
   * (the default) it is raised to 90 degrees and the run goes further. */
  uint64_t strict_collapses = 0;
  for (int32_t relax = 0; relax <= 1; ++relax) {
    hedge_mesh* curved = make_mesh(positions, 81, triangles, n, NULL, 0);
    CHECK_OK(hedge_decimate_options_default(&o));
    o.target_vertices = 4;
    o.max_normal_change_degrees = 1;
    o.relax_normal_change = relax;
    CHECK_OK(hedge_mesh_decimate(curved, &o, &r));
    if (relax == 0) {
      CHECK(r.stop == HEDGE_DECIMATE_NO_LEGAL_COLLAPSE && r.refused_normal > 0 && r.vertices > 4);
      strict_collapses = r.collapses;
    } else {
      CHECK(r.collapses > strict_collapses);
    }
    CHECK_OK(hedge_mesh_validate(curved, &problems));
    CHECK(problems == 0);
    CHECK_OK(hedge_mesh_destroy(curved));
  }
  o.relax_normal_change = 2;
  CHECK_STATUS(hedge_mesh_decimate(field, &o, NULL), HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK_ERROR_HAS("relax_normal_change");
  o.relax_normal_change = 1;
  o.reserved = 3;
  CHECK_STATUS(hedge_mesh_decimate(field, &o, NULL), HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK_ERROR_HAS("decimate_options.reserved is 3, not 0");
  o.reserved = 0;
  /* Quads are refused, unchanged. */
  hedge_mesh* grid = make_mesh(kGridPositions, 9, kGridQuads, 16, kGridSizes, 4);
  CHECK_STATUS(hedge_mesh_decimate(grid, NULL, NULL), HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK_ERROR_HAS("triangles");
  CHECK(counts_of(grid).faces == 4);
  CHECK_STATUS(hedge_decimate_options_default(NULL), HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK_OK(hedge_mesh_destroy(grid));
  CHECK_OK(hedge_mesh_destroy(field));
}

/* The library's FractureMaterial.TheDefaultStrikeOnSpotThatEveryBindingChecks gives these numbers:
 * the C ABI's defaults (NULL options, the glass preset) are the library's. */
static void test_fracture_default_strike_on_spot(void) {
  hedge_mesh* spot = NULL;
  CHECK_OK(hedge_mesh_read(HEDGE_DATA_DIR "/spot_triangulated.obj", NULL, NULL, &spot));
  hedge_fracture_shard shards[40];
  uint32_t count = 0;
  CHECK_OK(hedge_mesh_fracture(spot, 0.380073f, -0.0641595f, 0.195141f, NULL, shards, 40, &count));
  CHECK(count == 40);
  double area = 0, mass = 0;
  for (uint32_t i = 0; i < count; ++i) {
    area += shards[i].area, mass += shards[i].mass;
    CHECK(shards[i].closed == 0 && shards[i].mass > 0 && shards[i].principal_moments[0] > 0);
    CHECK_OK(hedge_mesh_destroy(shards[i].mesh));
    if (shards[i].hull != NULL) CHECK_OK(hedge_mesh_destroy(shards[i].hull));
  }
  CHECK(fabs(area - 0.498213) < 1e-6 && fabs(mass - 0.00838123) < 1e-8);
  CHECK_VALID(spot);
  CHECK_OK(hedge_mesh_destroy(spot));
}

void test_fracture(void) {
  test_fracture_default_strike_on_spot();
  CHECK(sizeof(hedge_fracture_ring) == 24 && sizeof(hedge_fracture_options) == 488 &&
        sizeof(hedge_fracture_shard) == 264);
  CHECK(offsetof(hedge_fracture_options, units) == 388 && offsetof(hedge_fracture_options, radius) == 472 &&
        offsetof(hedge_fracture_options, shell_thickness) == 480);
  hedge_fracture_options o;
  CHECK_OK(hedge_fracture_options_default(HEDGE_FRACTURE_GLASS, &o));
  CHECK(o.ring_count == 4 && o.rings[0].points == 4 && o.rings[3].points == 16 && o.density == 1 &&
        o.hulls == 1 && o.thickness == 0 && o.units == HEDGE_FRACTURE_UNITS_DIAGONAL_FRACTION &&
        o.radius == 0.13 && o.shell_thickness == 0);
  CHECK_OK(hedge_fracture_options_default(HEDGE_FRACTURE_WOOD, &o));
  CHECK(o.grain[0] == 1 && o.grain_stretch == 3);
  CHECK_STATUS(hedge_fracture_options_default(7, &o), HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK_ERROR_HAS("preset");
  CHECK_STATUS(hedge_fracture_options_default(HEDGE_FRACTURE_ICE, NULL), HEDGE_ERROR_INVALID_ARGUMENT);
  /* A break radius in model units (tested further in fracture_test.c): glass's rings summed. */
  CHECK_OK(hedge_fracture_options_default(HEDGE_FRACTURE_GLASS, &o));
  CHECK(o.inner_submesh == -1 && o.relative_thickness == 0);
  CHECK_OK(hedge_fracture_options_at_radius(&o, 14));
  CHECK(o.units == HEDGE_FRACTURE_UNITS_MODEL && o.radius == 14 && fabs(o.rings[0].spacing - 2) < 1e-12 &&
        fabs(o.rings[3].spacing - 4.8) < 1e-12);
  o.ring_count = 0;
  CHECK_STATUS(hedge_fracture_options_at_radius(&o, 1), HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK_ERROR_HAS("no ring");

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
  o.units = 3;
  CHECK_STATUS(hedge_mesh_fracture(plate, 15, 15, 0, &o, shards, 40, &count), HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK_ERROR_HAS("units is 3");
  o.units = HEDGE_FRACTURE_UNITS_MODEL;
  o.radius = 0;
  CHECK_STATUS(hedge_mesh_fracture(plate, 15, 15, 0, &o, shards, 40, &count), HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK_ERROR_HAS("radius");
  o.radius = 1;
  o.shell_thickness = -1;
  CHECK_STATUS(hedge_mesh_fracture(plate, 15, 15, 0, &o, shards, 40, &count), HEDGE_ERROR_INVALID_ARGUMENT);
  CHECK_ERROR_HAS("shell_thickness");
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
  /* The solids' added faces are in the automatic inner submesh, 1 (the plate has none). */
  int32_t submesh[4096];
  uint64_t slots = 0;
  CHECK_OK(hedge_mesh_copy_face_submeshes(shards[0].mesh, submesh, 4096, &slots));
  CHECK(slots == counts_of(shards[0].mesh).face_slots);
  uint32_t inner = 0;
  for (uint64_t f = 0; f < slots; ++f) inner += submesh[f] == 1;
  CHECK(inner > slots / 2);
  CHECK_STATUS(hedge_mesh_copy_face_submeshes(shards[0].mesh, submesh, 1, &slots),
               HEDGE_ERROR_BUFFER_TOO_SMALL);
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

void test_subdivide(void) {
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
  /* The second step splits each of the 16 boundary edges in three: one more vertex each. */
  CHECK(counts_of(grid).faces == 9 * 64 && counts_of(grid).vertices == 41 + 64 + 192 + 16);
  CHECK_OK(hedge_mesh_validate(grid, &problems));
  CHECK(problems == 0);
  /* A render object of the mesh rebuilds at its next sync: 64 triangles. */
  hedge_render_buffers* render = NULL;
  CHECK_OK(hedge_render_buffers_create(tet, NULL, &render));
  CHECK_OK(hedge_mesh_subdivide(tet, HEDGE_SUBDIVISION_MIDPOINT, 1));
  hedge_sync_result sync;
  CHECK_OK(hedge_render_buffers_sync(render, &sync));
  hedge_buffer_counts bc;
  CHECK_OK(hedge_render_buffers_counts(render, &bc));
  CHECK(bc.triangles == 256);
  CHECK_OK(hedge_render_buffers_destroy(render));
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

/* The open pyramid mirrored in x: positions negated, faces reversed (the base loop 0-1 is now a
 * boundary half-edge, 1-0 an inner one), and mirrored again it is back. */
void test_mirror(void) {
  hedge_mesh* m = make_mesh(kPyramidPositions, 5, kPyramidTriangles, 12, NULL, 0);
  uint32_t h01 = 0, h10 = 0;
  int32_t boundary = 0;
  CHECK_OK(hedge_mesh_find_halfedge(m, 0, 1, &h01));
  CHECK_OK(hedge_halfedge_is_boundary(m, h01, &boundary));
  CHECK(!boundary);
  CHECK_OK(hedge_mesh_mirror_x(m));
  float p[3];
  get_position(m, 1, p);
  CHECK(p[0] == -1 && p[1] == 0 && p[2] == 0);
  CHECK_OK(hedge_mesh_find_halfedge(m, 1, 0, &h10));
  CHECK_OK(hedge_halfedge_is_boundary(m, h10, &boundary));
  CHECK(!boundary);
  CHECK_OK(hedge_mesh_find_halfedge(m, 0, 1, &h01));
  CHECK_OK(hedge_halfedge_is_boundary(m, h01, &boundary));
  CHECK(boundary);
  CHECK_VALID(m);
  CHECK_OK(hedge_mesh_mirror_x(m));
  get_position(m, 1, p);
  CHECK(p[0] == 1);
  CHECK_OK(hedge_mesh_find_halfedge(m, 0, 1, &h01));
  CHECK_OK(hedge_halfedge_is_boundary(m, h01, &boundary));
  CHECK(!boundary);
  CHECK_VALID(m);
  CHECK_OK(hedge_mesh_destroy(m));
  CHECK_STATUS(hedge_mesh_mirror_x(m), HEDGE_ERROR_BAD_HANDLE);
  CHECK_STATUS(hedge_mesh_mirror_x(NULL), HEDGE_ERROR_BAD_HANDLE);
}
