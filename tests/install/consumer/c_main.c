/* Uses the installed C ABI (hedge::hedge_c) from C: builds a tetrahedron and checks its counts. */
#include <hedge/c_api.h>
#include <stdio.h>

int main(void) {
  const float positions[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
  const uint32_t triangles[] = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
  hedge_mesh* mesh = NULL;
  hedge_counts counts;
  uint32_t problems = 1;
  if (hedge_mesh_create(positions, 4, triangles, 12, NULL, 0, NULL, NULL, NULL, NULL, &mesh) != HEDGE_OK ||
      hedge_mesh_counts(mesh, &counts) != HEDGE_OK || hedge_mesh_validate(mesh, &problems) != HEDGE_OK) {
    fprintf(stderr, "C ABI call failed: %s\n", hedge_last_error());
    return 1;
  }
  printf("C ABI tetrahedron: %u vertices, %u edges, %u faces\n", (unsigned)counts.vertices,
         (unsigned)counts.edges, (unsigned)counts.faces);
  const int ok = counts.vertices == 4 && counts.edges == 6 && counts.faces == 4 && problems == 0;
  if (hedge_mesh_destroy(mesh) != HEDGE_OK || !ok) {
    fprintf(stderr, "unexpected counts or an invalid mesh\n");
    return 1;
  }
  printf("ok\n");
  return 0;
}
