/* The C ABI's picking (src/capi/picking.cpp). */
#include "capi_test.h"

/* ---------------------------------------------------------------------------------------------- */
/* Picking and the render-triangle-to-face map                                                    */
/* ---------------------------------------------------------------------------------------------- */

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

void test_picking(void) {
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
  CHECK_OK(hedge_set_vertex_position(mesh, 4, 1, 1, 3));
  const float centre[3] = {1, 1, 10};
  CHECK_OK(hedge_mesh_raycast(mesh, centre, down, INFINITY, &hit, &found));
  CHECK(found == 1 && fabsf(hit.point[2] - 3) < 1e-5f);
  CHECK_OK(hedge_set_vertex_position(mesh, 4, 1, 1, 0));
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
  CHECK_ERROR_HAS("direction has zero length");
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
