/* Tests of the C ABI (include/hedge/c_api.h), compiled as C11: status codes, errors and version,
 * handles, creation, files and validation (src/capi/c_api.cpp), the error path of every function,
 * threads, and main(), which runs the tests of every file (capi_test.h lists them). */
#include <math.h>
#include <stdatomic.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "capi_test.h"

int g_checks = 0;

const float kTetPositions[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
const uint32_t kTetTriangles[] = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
const float kPyramidPositions[] = {0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0.5f, 0.5f, 1};
const uint32_t kPyramidTriangles[] = {0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4};
const float kGridPositions[] = {0, 0, 0, 1, 0, 0, 2, 0, 0, 0, 1, 0, 1, 1,
                                0, 2, 1, 0, 0, 2, 0, 1, 2, 0, 2, 2, 0};
const uint32_t kGridQuads[] = {0, 1, 4, 3, 1, 2, 5, 4, 3, 4, 7, 6, 4, 5, 8, 7};
const uint32_t kGridSizes[] = {4, 4, 4, 4};

/* ---------------------------------------------------------------------------------------------- */
/* Status codes, errors, version                                                                  */
/* ---------------------------------------------------------------------------------------------- */

void test_basics(void) {
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
  CHECK(sizeof(hedge_render_buffers_options) == 24);
  CHECK(sizeof(hedge_vertex_layout) == 32);
  CHECK(sizeof(hedge_engine_streams) == 8 + 8 * sizeof(void*));
  CHECK(sizeof(hedge_range) == 8);
  CHECK(sizeof(hedge_sync_result) == 40);
  CHECK(sizeof(hedge_buffer_counts) == 40);
  CHECK(sizeof(hedge_engine_import_options) == 24);
}

/* ---------------------------------------------------------------------------------------------- */
/* Handles: NULL, destroyed, never created, of the wrong kind                                     */
/* ---------------------------------------------------------------------------------------------- */

void test_bad_handles(void) {
  hedge_counts c;
  uint32_t out = 0;
  CHECK_STATUS(hedge_mesh_counts(NULL, &c), HEDGE_ERROR_BAD_HANDLE);
  CHECK_ERROR_HAS("NULL");
  CHECK_STATUS(hedge_mesh_destroy(NULL), HEDGE_ERROR_BAD_HANDLE);
  CHECK_STATUS(hedge_render_buffers_destroy(NULL), HEDGE_ERROR_BAD_HANDLE);
  CHECK_STATUS(hedge_render_buffers_sync(NULL, NULL), HEDGE_ERROR_BAD_HANDLE);

  hedge_mesh* mesh = make_mesh(kTetPositions, 4, kTetTriangles, 12, NULL, 0);
  CHECK_OK(hedge_mesh_counts(mesh, &c));
  CHECK(c.faces == 4);
  CHECK_OK(hedge_mesh_destroy(mesh));
  CHECK_STATUS(hedge_mesh_counts(mesh, &c), HEDGE_ERROR_BAD_HANDLE);
  CHECK_ERROR_HAS("not a live mesh");
  CHECK_STATUS(hedge_halfedge_twin(mesh, 0, &out), HEDGE_ERROR_BAD_HANDLE);
  CHECK_STATUS(hedge_mesh_split_all_faces(mesh, NULL, 0, &out), HEDGE_ERROR_BAD_HANDLE);
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
  hedge_render_buffers* render = NULL;
  CHECK_OK(hedge_render_buffers_create(again, NULL, &render));
  CHECK_STATUS(hedge_mesh_counts((const hedge_mesh*)render, &c), HEDGE_ERROR_BAD_HANDLE);
  CHECK_STATUS(hedge_render_buffers_sync((hedge_render_buffers*)again, NULL), HEDGE_ERROR_BAD_HANDLE);
  CHECK_OK(hedge_render_buffers_destroy(render));
  CHECK_STATUS(hedge_render_buffers_destroy(render), HEDGE_ERROR_BAD_HANDLE);
  CHECK_STATUS(hedge_render_buffers_sync(render, NULL), HEDGE_ERROR_BAD_HANDLE);
  CHECK_OK(hedge_mesh_destroy(again));
}

/* ---------------------------------------------------------------------------------------------- */
/* Input checks and the repair policy                                                             */
/* ---------------------------------------------------------------------------------------------- */

void test_create_errors(void) {
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
/* Files                                                                                          */
/* ---------------------------------------------------------------------------------------------- */

void test_files(void) {
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

/* File names are UTF-8 on every system: a name beyond ASCII is written and read back under that
 * name (on Windows, as UTF-16: _wfopen finds it), a written file is replaced whole, and on Windows
 * either slash separates folders. */
static void test_file_names(void) {
  hedge_mesh* m = make_mesh(kGridPositions, 9, kGridQuads, 16, kGridSizes, 4);
  const char* name = HEDGE_TEST_OUTPUT_DIR "/c_api_test_m\xc3\xa9sh_\xe6\xa0\xbc.obj";
  CHECK_OK(hedge_mesh_write(m, name, 0, 0));
  CHECK_OK(hedge_mesh_write(m, name, 0, 0)); /* replaces the file just written */
  hedge_mesh* back = NULL;
  CHECK_OK(hedge_mesh_read(name, NULL, NULL, &back));
  CHECK(same_counts(counts_of(back), counts_of(m)));
  CHECK_OK(hedge_mesh_destroy(back));
#if defined(_WIN32)
  const wchar_t* wide = L"" HEDGE_TEST_OUTPUT_DIR "/c_api_test_m\u00e9sh_\u683c.obj";
  FILE* f = _wfopen(wide, L"rb");
  CHECK(f != NULL);
  if (f) fclose(f);
  char backslashes[512];
  snprintf(backslashes, sizeof backslashes, "%s", name);
  for (char* c = backslashes; *c; ++c)
    if (*c == '/') *c = '\\';
  CHECK_OK(hedge_mesh_read(backslashes, NULL, NULL, &back));
  CHECK_OK(hedge_mesh_destroy(back));
  CHECK_STATUS(hedge_mesh_write(m, HEDGE_TEST_OUTPUT_DIR "\\no_such_folder\\x.obj", 0, 0), HEDGE_ERROR_IO);
  CHECK_ERROR_HAS("no_such_folder");
  _wremove(wide); /* remove() would read the name in the ANSI code page */
#else
  remove(name);
#endif
  CHECK_OK(hedge_mesh_destroy(m));
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

void test_hostile_files(void) {
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

void test_validation_text(void) {
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

/* Every function has an error path: each one taking a handle refuses NULL and destroyed handles,
 * and each one without a handle refuses a NULL out parameter. */
void test_every_function_error_path(void) {
  hedge_mesh* dead_mesh = make_mesh(kTetPositions, 4, kTetTriangles, 12, NULL, 0);
  hedge_render_buffers* dead_render = NULL;
  CHECK_OK(hedge_render_buffers_create(dead_mesh, NULL, &dead_render));
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
  hedge_render_buffers* const renders[] = {NULL, dead_render};
  for (int k = 0; k < 2; ++k) {
    hedge_mesh* m = meshes[k];
    hedge_render_buffers* r = renders[k];
#define BAD(call) CHECK_STATUS(call, HEDGE_ERROR_BAD_HANDLE)
    BAD(hedge_mesh_counts(m, &counts));
    BAD(hedge_mesh_fracture(m, 0, 0, 0, NULL, NULL, 0, &u));
    BAD(hedge_vertex_position(m, 0, f));
    BAD(hedge_set_vertex_position(m, 0, 0, 0, 0));
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
    BAD(hedge_mesh_split_all_faces(m, buffer, 16, &u));
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
    BAD(hedge_render_buffers_create(m, NULL, &r));
    BAD(hedge_render_buffers_sync(r, &result));
    BAD(hedge_render_buffers_begin(r));
    BAD(hedge_render_buffers_commit(r, &result));
    BAD(hedge_render_buffers_rebuild(r, &result));
    BAD(hedge_render_buffers_last_result(r, &result));
    BAD(hedge_render_buffers_dirty_vertex_ranges(r, ranges, 4, &u));
    BAD(hedge_render_buffers_dirty_index_ranges(r, ranges, 4, &u));
    BAD(hedge_render_buffers_compact(r, NULL, 0, NULL, NULL, 0, NULL));
    BAD(hedge_render_buffers_counts(r, &buffer_counts));
    BAD(hedge_render_buffers_layout(r, &layout));
    BAD(hedge_render_buffers_vertex_data(r, HEDGE_STREAM_VERTICES, &fp, &u64));
    BAD(hedge_render_buffers_copy_vertex_data(r, HEDGE_STREAM_VERTICES, f, 16, &u64));
    BAD(hedge_render_buffers_index_data(r, &up, &u64));
    BAD(hedge_render_buffers_copy_index_data(r, buffer, 16, &u64));
    BAD(hedge_render_buffers_vertex_source(r, buffer, 16, &u));
    BAD(hedge_render_buffers_corner_vertex(r, 0, &u));
    BAD(hedge_render_buffers_face_triangles(r, 0, &u, &u));
    BAD(hedge_render_buffers_triangle_face(r, 0, &u));
    BAD(hedge_render_buffers_destroy(r));
#undef BAD
  }
  CHECK(out_mesh == NULL);

#define NULL_OUT(call) CHECK_STATUS(call, HEDGE_ERROR_INVALID_ARGUMENT)
  NULL_OUT(hedge_version(&i, &i, NULL));
  NULL_OUT(hedge_build_options_default(NULL));
  NULL_OUT(hedge_render_buffers_options_default(NULL));
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
/* Threads: one mesh, one thread at a time; a second thread's overlapping call fails, never hangs   */
/* ---------------------------------------------------------------------------------------------- */

typedef struct {
  hedge_mesh* mesh;
  hedge_render_buffers* render;
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
      st = hedge_render_buffers_sync(s->render, &r);
    } while (st == HEDGE_ERROR_BUSY);
    if (st != HEDGE_OK) failed = 1;
  }
  atomic_store(&s->done, 1);
  return failed;
}

void test_threads(void) {
  hedge_mesh* mesh = make_mesh(kGridPositions, 9, kGridQuads, 16, kGridSizes, 4);
  uint32_t added = 0;
  CHECK_OK(hedge_mesh_split_all_faces(mesh, NULL, 0, &added)); /* triangles, for the midpoint scheme */
  CHECK_OK(hedge_mesh_subdivide(mesh, HEDGE_SUBDIVISION_MIDPOINT, 5));
  hedge_render_buffers* render = NULL;
  CHECK_OK(hedge_render_buffers_create(mesh, NULL, &render));
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
                              : i == 1 ? hedge_set_vertex_position(mesh, 0, 0.f, 0.f, 0.f)
                                       : hedge_render_buffers_sync(render, &r);
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
  CHECK_OK(hedge_render_buffers_destroy(render));
  CHECK_OK(hedge_mesh_destroy(mesh));
}

/* ---------------------------------------------------------------------------------------------- */
/* Deprecated names (kept for one release)                                                        */
/* ---------------------------------------------------------------------------------------------- */

/* The previous release's names still compile and reach the current functions. */
static void test_deprecated_names(void) {
  hedge_mesh* mesh = make_mesh(kGridPositions, 9, kGridQuads, 16, kGridSizes, 4);
  hedge_render_options options;
  CHECK_OK(hedge_render_options_default(&options));
  hedge_render* render = NULL;
  CHECK_OK(hedge_render_create(mesh, &options, &render));
  float p[3];
  CHECK_OK(hedge_mesh_set_position(mesh, 4, 1, 1, 0.5f));
  CHECK_OK(hedge_mesh_get_position(mesh, 4, p));
  CHECK(p[0] == 1 && p[1] == 1 && p[2] == 0.5f);
  uint32_t added = 0;
  CHECK_OK(hedge_split_all_faces(mesh, NULL, 0, &added));
  CHECK(added == 4);
  hedge_sync_result result;
  CHECK_OK(hedge_render_sync(render, &result));
  hedge_buffer_counts counts;
  CHECK_OK(hedge_render_counts(render, &counts));
  CHECK(counts.triangles == 16);
  CHECK_OK(hedge_render_destroy(render));
  CHECK_VALID(mesh);
  CHECK_OK(hedge_mesh_destroy(mesh));
}
/* End of deprecated names */

/* ---------------------------------------------------------------------------------------------- */
/* Refusal codes: one per refusal of the library's table, each with its name and text             */
/* ---------------------------------------------------------------------------------------------- */

static void test_refusal_codes(void) {
  /* Every code's name and text: refusals_test.c walks the whole table. */
  CHECK(strcmp(hedge_refusal_name(HEDGE_REFUSAL_FLIP_BOUNDARY_EDGE), "HEDGE_REFUSAL_FLIP_BOUNDARY_EDGE") ==
        0);
  CHECK(strcmp(hedge_refusal_name(HEDGE_REFUSAL_COUNT), "HEDGE_REFUSAL_UNKNOWN") == 0);
  CHECK(strcmp(hedge_refusal_text(HEDGE_REFUSAL_NONE), "") == 0);

  /* A refused edit sets the code with its text; a call that is not refused clears both. */
  hedge_mesh* tet = make_mesh(kTetPositions, 4, kTetTriangles, 12, NULL, 0);
  CHECK(hedge_last_refusal_code() == HEDGE_REFUSAL_NONE);
  CHECK_STATUS(hedge_flip(tet, 0), HEDGE_ERROR_REFUSED);
  CHECK(hedge_last_refusal_code() == HEDGE_REFUSAL_FLIP_VALENCE_THREE);
  CHECK(strcmp(hedge_refusal_text(hedge_last_refusal_code()), hedge_last_refusal()) == 0);
  CHECK(hedge_last_refusal_code() == HEDGE_REFUSAL_FLIP_VALENCE_THREE); /* reading it changes nothing */
  CHECK_STATUS(hedge_flip(tet, 999), HEDGE_ERROR_BAD_HANDLE);
  CHECK(hedge_last_refusal_code() == HEDGE_REFUSAL_NONE); /* a bad handle is no refusal */
  CHECK_STATUS(hedge_collapse(tet, 0, &(uint32_t){0}), HEDGE_ERROR_REFUSED);
  CHECK(hedge_last_refusal_code() != HEDGE_REFUSAL_NONE);
  CHECK(strcmp(hedge_refusal_text(hedge_last_refusal_code()), hedge_last_refusal()) == 0);
  CHECK_OK(hedge_can_split_edge(tet, 0, &(int32_t){0}));
  CHECK(hedge_last_refusal_code() == HEDGE_REFUSAL_NONE);
  uint32_t problems = 1;
  CHECK_OK(hedge_mesh_validate(tet, &problems));
  CHECK(problems == 0);
  CHECK_OK(hedge_mesh_destroy(tet));
}

int main(void) {
  test_basics();
  test_tetrahedron();
  test_bad_handles();
  test_create_errors();
  test_pyramid_operations();
  test_grid_operations();
  test_files();
  test_file_names();
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
  test_mirror();
  test_engine_sources();
  test_picking();
  test_solid_fracture();
  test_triangle_faces();
  test_submeshes();
  test_engine_streams();
  test_every_function_error_path();
  test_threads();
  test_deprecated_names();
  test_refusal_codes();
  printf("c_api_test: %d checks passed\n", g_checks);
  return 0;
}
