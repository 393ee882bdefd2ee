/* The shared table of refused edits and bad handles (tests/cases/refusals.txt, which says its
 * format) run through the C ABI: each case must give the table's status, text and refusal code, as
 * the JS API's and the C# binding's tests of the same table must. Then every refusal code of the
 * header, with its name and text. Compiled as C11. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "hedge/c_api.h"

#define MAX_MESHES 16
#define LINE_SIZE 4096

static int g_failures = 0;
static int g_cases = 0;

typedef struct {
  char name[32];
  char obj[LINE_SIZE];
} NamedMesh;

static NamedMesh g_meshes[MAX_MESHES];
static int g_mesh_count = 0;

/* Strips leading and trailing blanks in place. */
static char* trim(char* s) {
  while (*s == ' ' || *s == '\t') ++s;
  size_t n = strlen(s);
  while (n > 0 && (s[n - 1] == ' ' || s[n - 1] == '\t' || s[n - 1] == '\n' || s[n - 1] == '\r'))
    s[--n] = '\0';
  return s;
}

/* The next field of *s up to `sep` (or the end), trimmed; NULL when *s is used up. Cuts *s. */
static char* next_field(char** s, char sep) {
  if (*s == NULL) return NULL;
  char* start = *s;
  char* end = strchr(start, sep);
  if (end != NULL) {
    *end = '\0';
    *s = end + 1;
  } else {
    *s = NULL;
  }
  return trim(start);
}

static hedge_mesh* read_mesh(const char* name) {
  for (int i = 0; i < g_mesh_count; ++i) {
    if (strcmp(g_meshes[i].name, name) != 0) continue;
    char text[LINE_SIZE], file[64];
    strcpy(text, g_meshes[i].obj);
    for (char* c = text; *c; ++c)
      if (*c == ';') *c = '\n';
    snprintf(file, sizeof file, "%s.obj", name);
    hedge_mesh* mesh = NULL;
    if (hedge_mesh_read_memory(text, strlen(text), file, NULL, NULL, NULL, &mesh) != HEDGE_OK) {
      fprintf(stderr, "mesh %s: %s\n", name, hedge_last_error());
      exit(1);
    }
    return mesh;
  }
  fprintf(stderr, "no mesh named %s in the table\n", name);
  exit(1);
}

/* An element: e:A-B, h:A>B, or e:N, h:N, f:N. */
static uint32_t element(hedge_mesh* mesh, const char* token) {
  unsigned a = 0, b = 0;
  uint32_t h = HEDGE_INVALID_INDEX;
  if (sscanf(token, "e:%u-%u", &a, &b) == 2 || sscanf(token, "h:%u>%u", &a, &b) == 2) {
    if (hedge_mesh_find_halfedge(mesh, a, b, &h) != HEDGE_OK || h == HEDGE_INVALID_INDEX) {
      fprintf(stderr, "%s: no such half-edge (%s)\n", token, hedge_last_error());
      exit(1);
    }
    return token[0] == 'e' ? h >> 1 : h;
  }
  if (sscanf(token + 2, "%u", &a) == 1) return a;
  fprintf(stderr, "bad element %s\n", token);
  exit(1);
}

typedef struct {
  char name[32];
  uint32_t elements[2];
  int count;
} Edit;

static Edit parse_edit(hedge_mesh* mesh, char* text) {
  Edit edit;
  memset(&edit, 0, sizeof edit);
  char* rest = text;
  const char* name = next_field(&rest, ' ');
  snprintf(edit.name, sizeof edit.name, "%s", name != NULL ? name : "");
  for (char* t = next_field(&rest, ' '); t != NULL && edit.count < 2; t = next_field(&rest, ' '))
    if (*t != '\0') edit.elements[edit.count++] = element(mesh, t);
  return edit;
}

static hedge_status run_edit(hedge_mesh* mesh, const Edit* e) {
  uint32_t out = 0, faces[64], n = 0;
  const uint32_t a = e->elements[0], b = e->elements[1];
  if (strcmp(e->name, "flip") == 0) return hedge_flip(mesh, a);
  if (strcmp(e->name, "collapse") == 0) return hedge_collapse(mesh, a, &out);
  if (strcmp(e->name, "split_edge") == 0) return hedge_split_edge(mesh, a, 0, 0, 0, &out);
  if (strcmp(e->name, "split_face") == 0) return hedge_split_face(mesh, a, 0, 0, 0, &out);
  if (strcmp(e->name, "cut_face") == 0) return hedge_cut_face(mesh, a, b, &out);
  if (strcmp(e->name, "fill_hole") == 0) return hedge_fill_hole(mesh, a, faces, 64, &n);
  fprintf(stderr, "unknown edit %s\n", e->name);
  exit(1);
}

/* The predicate of an edit (hedge_can_*): its status, *ok its answer. */
static hedge_status run_predicate(hedge_mesh* mesh, const Edit* e, int32_t* ok) {
  const uint32_t a = e->elements[0], b = e->elements[1];
  if (strcmp(e->name, "flip") == 0) return hedge_can_flip(mesh, a, ok);
  if (strcmp(e->name, "collapse") == 0) return hedge_can_collapse(mesh, a, ok);
  if (strcmp(e->name, "split_edge") == 0) return hedge_can_split_edge(mesh, a, ok);
  if (strcmp(e->name, "split_face") == 0) return hedge_can_split_face(mesh, a, ok);
  if (strcmp(e->name, "cut_face") == 0) return hedge_can_cut_face(mesh, a, b, ok);
  if (strcmp(e->name, "fill_hole") == 0) return hedge_can_fill_hole(mesh, a, ok);
  fprintf(stderr, "unknown edit %s\n", e->name);
  exit(1);
}

static void run_case(char* line) {
  char* fields[6];
  char* rest = line;
  int n = 0;
  for (char* f = next_field(&rest, '|'); f != NULL && n < 6; f = next_field(&rest, '|')) fields[n++] = f;
  if (n != 6) {
    fprintf(stderr, "a case needs 6 fields: %s\n", line);
    exit(1);
  }
  ++g_cases;
  hedge_mesh* mesh = read_mesh(fields[0]);
  char edit_text[256];
  snprintf(edit_text, sizeof edit_text, "%s", fields[2]);
  const Edit checked = parse_edit(mesh, edit_text); /* before the edits done first */
  if (strcmp(fields[1], "-") != 0) {
    char* edits = fields[1];
    for (char* t = next_field(&edits, ';'); t != NULL; t = next_field(&edits, ';')) {
      const Edit done = parse_edit(mesh, t);
      if (run_edit(mesh, &done) != HEDGE_OK) {
        fprintf(stderr, "case %s | %s: the edit done first failed: %s\n", fields[0], fields[2],
                hedge_last_error());
        exit(1);
      }
    }
  }
  /* The predicate first (the edit may change the mesh): it answers 0 exactly when the edit is
   * refused, and leaves the same refusal code behind. */
  int32_t ok = -1;
  const hedge_status asked = run_predicate(mesh, &checked, &ok);
  const hedge_refusal predicted = hedge_last_refusal_code();
  const hedge_status status = run_edit(mesh, &checked);
  if (status == HEDGE_OK || status == HEDGE_ERROR_REFUSED) {
    if (asked != HEDGE_OK || ok != (status == HEDGE_OK) || predicted != hedge_last_refusal_code()) {
      fprintf(stderr, "case %s | %s: the predicate answered %d with code %s, the edit %s with code %s\n",
              fields[0], fields[2], (int)ok, hedge_refusal_name(predicted), hedge_status_string(status),
              hedge_refusal_name(hedge_last_refusal_code()));
      ++g_failures;
    }
  }
  const char* text = status == HEDGE_ERROR_REFUSED ? hedge_last_refusal() : hedge_last_error();
  const char* code = hedge_refusal_name(hedge_last_refusal_code());
  if (strcmp(hedge_status_string(status), fields[3]) != 0 || strcmp(text, fields[4]) != 0 ||
      strcmp(code, fields[5]) != 0) {
    fprintf(stderr, "case %s | %s | %s:\n  expected %s \"%s\" %s\n  got      %s \"%s\" %s\n", fields[0],
            fields[1], fields[2], fields[3], fields[4], fields[5], hedge_status_string(status), text, code);
    ++g_failures;
  }
  uint32_t problems = 1;
  if (hedge_mesh_validate(mesh, &problems) != HEDGE_OK || problems != 0) {
    fprintf(stderr, "case %s | %s: the mesh is not valid afterwards\n", fields[0], fields[2]);
    ++g_failures;
  }
  hedge_mesh_destroy(mesh);
}

/* Every refusal code of the header: in order, none missing, each with its name and its own text. */
#define EXPECT(cond)                                                           \
  do {                                                                         \
    if (!(cond)) {                                                             \
      fprintf(stderr, "%s:%d: check failed: %s\n", __FILE__, __LINE__, #cond); \
      ++g_failures;                                                            \
    }                                                                          \
  } while (0)

static void check_every_code(void) {
#define NAMED(code) \
  { code, #code }
  const struct {
    hedge_refusal code;
    const char* name;
  } named[] = {NAMED(HEDGE_REFUSAL_NONE),
               NAMED(HEDGE_REFUSAL_EDGE_NOT_LIVE),
               NAMED(HEDGE_REFUSAL_HALFEDGE_NOT_LIVE),
               NAMED(HEDGE_REFUSAL_FACE_NOT_LIVE),
               NAMED(HEDGE_REFUSAL_VERTEX_NOT_LIVE),
               NAMED(HEDGE_REFUSAL_COLLAPSE_JOINS_SEAM_SIDES),
               NAMED(HEDGE_REFUSAL_COLLAPSE_PULLS_SEAM_VERTEX),
               NAMED(HEDGE_REFUSAL_COLLAPSE_SHORTENS_SEAM),
               NAMED(HEDGE_REFUSAL_COLLAPSE_SAME_FACE_BOTH_SIDES),
               NAMED(HEDGE_REFUSAL_COLLAPSE_PINCHES_BOUNDARY),
               NAMED(HEDGE_REFUSAL_COLLAPSE_SECOND_EDGE),
               NAMED(HEDGE_REFUSAL_COLLAPSE_LINK_CONDITION),
               NAMED(HEDGE_REFUSAL_COLLAPSE_DANGLING_EDGE),
               NAMED(HEDGE_REFUSAL_COLLAPSE_TIP_TOO_FEW_EDGES),
               NAMED(HEDGE_REFUSAL_COLLAPSE_SURVIVOR_TOO_FEW_EDGES),
               NAMED(HEDGE_REFUSAL_FLIP_TIPS_SHARED),
               NAMED(HEDGE_REFUSAL_FLIP_VALENCE_THREE),
               NAMED(HEDGE_REFUSAL_FLIP_TIPS_JOINED),
               NAMED(HEDGE_REFUSAL_FLIP_BOUNDARY_EDGE),
               NAMED(HEDGE_REFUSAL_FLIP_NOT_TRIANGLE),
               NAMED(HEDGE_REFUSAL_CUT_HALFEDGE_NOT_LIVE),
               NAMED(HEDGE_REFUSAL_CUT_SAME_HALFEDGE),
               NAMED(HEDGE_REFUSAL_CUT_ON_BOUNDARY),
               NAMED(HEDGE_REFUSAL_CUT_DIFFERENT_FACES),
               NAMED(HEDGE_REFUSAL_CUT_NEIGHBOUR_TARGETS),
               NAMED(HEDGE_REFUSAL_CUT_TARGETS_JOINED),
               NAMED(HEDGE_REFUSAL_ADD_FACE_TOO_FEW_CORNERS),
               NAMED(HEDGE_REFUSAL_ADD_FACE_CORNER_NOT_LIVE),
               NAMED(HEDGE_REFUSAL_ADD_FACE_CORNER_REPEATED),
               NAMED(HEDGE_REFUSAL_ADD_FACE_EDGE_TAKEN),
               NAMED(HEDGE_REFUSAL_ADD_FACE_INTERIOR_CORNER),
               NAMED(HEDGE_REFUSAL_ADD_FACE_SECOND_GAP),
               NAMED(HEDGE_REFUSAL_REMOVE_FACE_PINCHES),
               NAMED(HEDGE_REFUSAL_REMOVE_VERTEX_PINCHES),
               NAMED(HEDGE_REFUSAL_FILL_HOLE_NOT_BOUNDARY),
               NAMED(HEDGE_REFUSAL_FILL_HOLE_LOOP_DAMAGED),
               NAMED(HEDGE_REFUSAL_FILL_HOLE_LOOP_TOO_SHORT)};
#undef NAMED
  const int32_t listed = (int32_t)(sizeof named / sizeof named[0]);
  EXPECT(listed == HEDGE_REFUSAL_COUNT);
  for (int32_t i = 0; i < HEDGE_REFUSAL_COUNT && i < listed; ++i) {
    EXPECT(named[i].code == i); /* the header's constants in order, none missing */
    EXPECT(strcmp(hedge_refusal_name(i), named[i].name) == 0);
    EXPECT((strcmp(hedge_refusal_text(i), "") == 0) == (i == HEDGE_REFUSAL_NONE));
    for (int32_t j = 0; j < i; ++j) EXPECT(strcmp(hedge_refusal_text(i), hedge_refusal_text(j)) != 0);
  }
  EXPECT(strcmp(hedge_refusal_name(HEDGE_REFUSAL_COUNT), "HEDGE_REFUSAL_UNKNOWN") == 0);
  EXPECT(strcmp(hedge_refusal_name(-1), "HEDGE_REFUSAL_UNKNOWN") == 0);
  EXPECT(strcmp(hedge_refusal_text(HEDGE_REFUSAL_COUNT), "") == 0);
}
#undef EXPECT

int main(void) {
  const char* path = HEDGE_CASES_DIR "/refusals.txt";
  FILE* in = fopen(path, "r");
  if (in == NULL) {
    fprintf(stderr, "cannot open %s\n", path);
    return 1;
  }
  char line[LINE_SIZE];
  while (fgets(line, sizeof line, in) != NULL) {
    char* s = trim(line);
    if (strncmp(s, "mesh ", 5) == 0) {
      char* eq = strchr(s, '=');
      if (eq == NULL || g_mesh_count == MAX_MESHES) return fprintf(stderr, "bad mesh line: %s\n", s), 1;
      *eq = '\0';
      snprintf(g_meshes[g_mesh_count].name, sizeof g_meshes[0].name, "%s", trim(s + 5));
      snprintf(g_meshes[g_mesh_count].obj, sizeof g_meshes[0].obj, "%s", trim(eq + 1));
      ++g_mesh_count;
    } else if (strncmp(s, "case ", 5) == 0) {
      run_case(s + 5);
    }
  }
  fclose(in);
  check_every_code();
  if (g_cases == 0) return fprintf(stderr, "no cases in %s\n", path), 1;
  if (g_failures > 0) return fprintf(stderr, "%d of %d cases failed\n", g_failures, g_cases), 1;
  printf("refusals_test: %d cases passed\n", g_cases);
  return 0;
}
