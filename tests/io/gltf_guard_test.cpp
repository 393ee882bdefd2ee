// Hostile glTF files: what src/io/gltf_guard.cpp refuses before tinygltf parses, and the reader's
// memory budget (src/io/gltf_read.cpp). Each file here is one an attacker could send.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

#include "heap_hooks.h"
#include "io/base64.h"
#include "io/gltf_test_common.h"
#include "io/io_errors.h"
#include "test_meshes.h"

namespace hedge {
namespace {

using namespace gltf_test;
using test::catch_io_error;

using test::heap_peak_during;

TEST(HeapHooks, SeeAnAllocationAndItsRelease) {
  std::size_t held_after = 0;
  const std::size_t peak = heap_peak_during([&] {
    std::vector<char> v(10 << 20);
    v[5] = 1;
    held_after = test::heap_held();
  });
  EXPECT_GE(peak, std::size_t{10} << 20);
  EXPECT_LT(test::heap_held(), held_after);
}

using test::base64;

// A triangle's buffer: three float positions, then `indices` u16 indices cycling 0, 1, 2.
std::string triangle_buffer(std::size_t indices) {
  std::string b;
  auto put = [&](const void* p, std::size_t n) { b.append(static_cast<const char*>(p), n); };
  for (const float v : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f}) put(&v, 4);
  for (std::size_t i = 0; i < indices; ++i) {
    const auto k = static_cast<std::uint16_t>(i % 3);
    put(&k, 2);
  }
  while (b.size() % 4 != 0) b += '\0';
  return b;
}

// A document whose mesh has `primitives` primitives, all on the same two accessors (`indices`
// indices), placed by `nodes` nodes; its buffer is embedded unless `uri` is given.
json document(std::size_t indices = 3, std::size_t primitives = 1, std::size_t nodes = 1,
              const std::string& uri = {}) {
  const std::string buffer = triangle_buffer(indices);
  json doc = {{"asset", {{"version", "2.0"}}}};
  json roots = json::array(), node_list = json::array(), prims = json::array();
  for (std::size_t n = 0; n < nodes; ++n) {
    roots.push_back(n);
    node_list.push_back({{"mesh", 0}});
  }
  for (std::size_t p = 0; p < primitives; ++p)
    prims.push_back({{"attributes", {{"POSITION", 0}}}, {"indices", 1}});
  doc["scenes"] = json::array({{{"nodes", roots}}});
  doc["nodes"] = node_list;
  doc["meshes"] = json::array({{{"primitives", prims}}});
  doc["accessors"] =
      json::array({{{"bufferView", 0}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"}},
                   {{"bufferView", 1}, {"componentType", 5123}, {"count", indices}, {"type", "SCALAR"}}});
  doc["bufferViews"] = json::array({{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", 36}},
                                    {{"buffer", 0}, {"byteOffset", 36}, {"byteLength", 2 * indices}}});
  doc["buffers"] =
      json::array({{{"byteLength", buffer.size()},
                    {"uri", uri.empty() ? "data:application/octet-stream;base64," + base64(buffer) : uri}}});
  return doc;
}

std::string message(const std::string& text, const ReadOptions& options = {}) {
  return catch_io_error([&] { read_gltf(text, "m.gltf", options); }).what();
}

#define EXPECT_HAS(text, part)                               \
  do {                                                       \
    const std::string what_ = (text);                        \
    EXPECT_NE(what_.find(part), std::string::npos) << what_; \
  } while (false)

TEST(GltfGuard, TheTestDocumentReads) {
  const IndexedMesh m = read_gltf(document(6, 2, 2).dump(), "m.gltf");
  EXPECT_EQ(m.face_count(), 8u);  // 2 nodes x 2 primitives x 2 triangles
}

// --- nesting -------------------------------------------------------------------------------------

TEST(GltfGuard, DeepNestingIsRefusedBeforeParsing) {
  std::string text = document().dump();
  text.pop_back();  // the closing brace
  text += ",\"extras\":" + std::string(17000, '[') + std::string(17000, ']') + "}";
  const std::string what = message(text);
  EXPECT_HAS(what, "m.gltf: malformed glTF: JSON nested deeper than 64 levels (extras[0][0]");
  // The same in a .glb's JSON chunk.
  std::string glb = "glTF";
  auto u32 = [&](std::uint32_t v) { glb.append(reinterpret_cast<const char*>(&v), 4); };
  std::string chunk = text;
  while (chunk.size() % 4 != 0) chunk += ' ';
  u32(2);
  u32(static_cast<std::uint32_t>(20 + chunk.size()));
  u32(static_cast<std::uint32_t>(chunk.size()));
  u32(0x4E4F534Au);
  glb += chunk;
  EXPECT_HAS(message(glb), "nested deeper than 64 levels");
}

TEST(GltfGuard, NestingUpToTheLimitIsRead) {
  json doc = document();
  json extras = json::array();
  for (int level = 1; level < kMaxJsonDepth - 1; ++level) extras = json::array({extras});  // root + 63 levels
  doc["extras"] = extras;
  EXPECT_EQ(read_gltf(doc.dump(), "m.gltf").face_count(), 1u);
  doc["extras"] = json::array({extras});
  EXPECT_HAS(message(doc.dump()), "nested deeper than 64");
}

// --- the GLB container ---------------------------------------------------------------------------

// data/two_quads.glb: the 12-byte header (length 1096), the JSON chunk's header at byte 12 and its
// 788 bytes of data from byte 20 to 808, the BIN chunk's header at byte 808 and its 280 bytes to 1096.
class GlbFraming : public ::testing::Test {
 protected:
  const std::string glb = read_file(test::data_path("two_quads.glb"));

  // The error of reading `bytes`, which must be hedge's and say where.
  IoError error(const std::string& bytes) const {
    const IoError e = catch_io_error([&] { read_gltf(bytes, "q.glb"); });
    const std::string what = e.what();
    EXPECT_EQ(what.find("Invalid glTF binary"), std::string::npos) << what;  // not tinygltf's
    EXPECT_NE(what.find("malformed glTF binary: "), std::string::npos) << what;
    return e;
  }
  std::string with_u32(std::size_t at, std::uint32_t v) const {
    std::string out = glb;
    for (int k = 0; k < 4; ++k)
      out[at + static_cast<std::size_t>(k)] = static_cast<char>(v >> (8 * k) & 0xFF);
    return out;
  }
};

TEST_F(GlbFraming, TheWholeFileReads) {
  ASSERT_EQ(glb.size(), 1096u);
  EXPECT_GT(read_gltf(glb, "q.glb").face_count(), 0u);
}

TEST_F(GlbFraming, ACutInTheHeaderSaysWhere) {
  IoError e = error(glb.substr(0, 10));
  EXPECT_HAS(e.what(), "truncated: the file ends at byte 10, inside the 12-byte GLB header");
  EXPECT_EQ(e.byte_offset(), 10);
  e = error(glb.substr(0, 16));
  EXPECT_HAS(
      e.what(),
      "the file ends at byte 16, inside the JSON chunk's 8-byte header at byte 12 (the header declares "
      "1096 bytes, the file has 16)");
  EXPECT_EQ(e.byte_offset(), 16);
}

TEST_F(GlbFraming, ACutInTheJsonChunkNamesTheChunkAndTheLengths) {
  for (std::size_t cut : {20u, 400u, 807u}) {
    const IoError e = error(glb.substr(0, cut));
    EXPECT_HAS(e.what(),
               "q.glb (byte 12): malformed glTF binary: truncated: the JSON chunk at byte 12 declares "
               "788 bytes of data, to end at byte 808, past the end of the file (the header "
               "declares 1096 bytes, the file has " +
                   std::to_string(cut) + ")");
    EXPECT_EQ(e.byte_offset(), 12);
  }
}

TEST_F(GlbFraming, ACutInTheBinChunkNamesTheChunkAndTheLengths) {
  IoError e = error(glb.substr(0, 812));
  EXPECT_HAS(e.what(),
             "the file ends at byte 812, inside the BIN chunk's 8-byte header at byte 808 (the "
             "header declares 1096 bytes, the file has 812)");
  EXPECT_EQ(e.byte_offset(), 812);
  for (std::size_t cut : {808u, 816u, 1000u, 1095u}) {
    e = error(glb.substr(0, cut));
    if (cut == 808) {
      EXPECT_HAS(e.what(), "inside the BIN chunk's 8-byte header at byte 808");
      continue;
    }
    EXPECT_HAS(e.what(),
               "truncated: the BIN chunk at byte 808 declares 280 bytes of data, to end at byte 1096, "
               "past the end of the file (the header declares 1096 bytes, the file has " +
                   std::to_string(cut) + ")");
    EXPECT_EQ(e.byte_offset(), 808);
  }
}

TEST_F(GlbFraming, LengthsThatDisagreeSayWhich) {
  IoError e = error(with_u32(8, 1200));
  EXPECT_HAS(e.what(), "truncated: the header declares 1200 bytes, the file has 1096");
  EXPECT_EQ(e.byte_offset(), 8);
  e = error(with_u32(8, 900));
  EXPECT_HAS(e.what(),
             "the BIN chunk at byte 808 declares 280 bytes of data, to end at byte 1096, past the 900 "
             "bytes the header declares");
  e = error(with_u32(8, 700));
  EXPECT_HAS(e.what(),
             "the JSON chunk at byte 12 declares 788 bytes of data, to end at byte 808, past the 700 "
             "bytes the header declares");
  e = error(with_u32(812, 0x12345678));
  EXPECT_HAS(e.what(), "the chunk at byte 808 is not BIN");
  EXPECT_EQ(e.byte_offset(), 812);
  EXPECT_HAS(error(with_u32(16, 0x12345678)).what(), "the chunk at byte 12 is not JSON");
  EXPECT_HAS(error(with_u32(12, 0)).what(), "the JSON chunk at byte 12 is empty");
  EXPECT_HAS(error(with_u32(4, 1)).what(), "version 1, expected 2");
}

// --- negative numbers ----------------------------------------------------------------------------

TEST(GltfGuard, NegativeOffsetsIndicesAndModesNameTheirElement) {
  json doc = document();
  doc["accessors"][0]["byteOffset"] = -4;
  EXPECT_HAS(message(doc.dump()), "m.gltf: accessor 0: byteOffset is -4; it must be 0 or more");
  doc = document();
  doc["meshes"][0]["primitives"][0]["indices"] = -5;
  EXPECT_HAS(message(doc.dump()), "m.gltf: mesh 0 primitive 0: indices is -5; it must be 0 or more");
  doc = document();
  doc["meshes"][0]["primitives"][0]["mode"] = -7;
  EXPECT_HAS(message(doc.dump()), "mesh 0 primitive 0: mode is -7");
  doc = document();
  doc["scenes"][0]["nodes"] = {-1};
  EXPECT_HAS(message(doc.dump()), "scene 0: nodes[0] is -1");
  doc = document();
  doc["meshes"][0]["primitives"][0]["attributes"]["POSITION"] = -1.5;
  EXPECT_HAS(message(doc.dump()), "mesh 0 primitive 0: attributes.POSITION is -1.5");
  doc = document();
  doc["accessors"][1]["sparse"] = {
      {"count", 1}, {"indices", {{"bufferView", 1}, {"byteOffset", -2}, {"componentType", 5123}}}};
  EXPECT_HAS(message(doc.dump()), "accessor 1: sparse.indices.byteOffset is -2");
  // Negative numbers where glTF allows them, and anything inside extras, are read.
  doc = document();
  doc["nodes"][0]["translation"] = {-1, -2, -3};
  doc["extras"] = {{"count", -3}};
  EXPECT_EQ(read_gltf(doc.dump(), "m.gltf").positions[0].x, -1.0f);
}

// tinygltf takes an index written with a point or an exponent for a missing one, and wraps one past
// 2^31 - 1 into 32 bits: either would read another mesh than the file's without a word.
TEST(GltfGuard, IndicesThatAreNotWholeOrTooLargeNameTheirElement) {
  json doc = document();
  doc["accessors"][0]["byteOffset"] = 1.5;
  EXPECT_HAS(message(doc.dump()), "m.gltf: accessor 0: byteOffset is 1.5; it must be a whole number");
  doc = document();
  doc["meshes"][0]["primitives"][0]["indices"] = 1.0;
  EXPECT_HAS(message(doc.dump()), "mesh 0 primitive 0: indices is 1.0; it must be a whole number");
  doc = document();
  doc["meshes"][0]["primitives"][0]["attributes"]["POSITION"] = std::uint64_t{1} << 32;
  EXPECT_HAS(message(doc.dump()),
             "mesh 0 primitive 0: attributes.POSITION is 4294967296; it must be at most 2147483647");
  doc = document();
  doc["nodes"][0]["mesh"] = (std::uint64_t{1} << 32) + 0;
  EXPECT_HAS(message(doc.dump()), "node 0: mesh is 4294967296");
  doc = document();
  doc["scenes"][0]["nodes"] = {std::uint64_t{1} << 31};
  EXPECT_HAS(message(doc.dump()), "scene 0: nodes[0] is 2147483648");
  doc = document();
  doc["accessors"][1]["sparse"] = {{"count", std::uint64_t{1} << 32},
                                   {"indices", {{"bufferView", 1}, {"componentType", 5123}}}};
  EXPECT_HAS(message(doc.dump()), "accessor 1: sparse.count is 4294967296");
  // A bare number as the whole document has no element to name: it is no glTF.
  EXPECT_HAS(message("4294967295"), "m.gltf");
  EXPECT_HAS(message("1.5"), "m.gltf");
  // Offsets and counts outside `sparse` are kept in 64 bits: the reader checks them against the data.
  doc = document();
  doc["accessors"][0]["byteOffset"] = std::uint64_t{1} << 32;
  EXPECT_HAS(message(doc.dump()), "accessor 0: 3 elements of 12 bytes (stride 12) from byte 4294967296");
  // Numbers glTF allows to be fractional or large, and anything inside extras, are read.
  doc = document();
  doc["nodes"][0]["scale"] = {1.5, 1.0, 1e0};
  doc["extras"] = {{"count", 0.5}, {"mesh", std::uint64_t{1} << 40}};
  EXPECT_EQ(read_gltf(doc.dump(), "m.gltf").positions[1].x, 1.5f);
}

// --- data URIs -----------------------------------------------------------------------------------

TEST(GltfGuard, DataUrisMustBeBase64BuffersOfTheirByteLength) {
  json doc = document();
  doc["buffers"][0]["uri"] = "data:text/plain,hello";
  const std::string what = message(doc.dump());
  EXPECT_HAS(what, "buffer 0: a data URI must be base64 application/octet-stream or application/gltf-buffer");
  doc["buffers"][0]["uri"] = "data:application/octet-stream;base64,AAA*";
  EXPECT_HAS(message(doc.dump()), "buffer 0: the data URI's payload is not base64");
  doc = document();
  doc["buffers"][0]["byteLength"] = 48;
  EXPECT_HAS(message(doc.dump()), "buffer 0: its data URI holds 44 bytes, but its byteLength is 48");
  doc = document();
  doc["buffers"][0]["uri"] = "data:application/gltf-buffer;base64," + base64(triangle_buffer(3));
  EXPECT_EQ(read_gltf(doc.dump(), "m.gltf").face_count(), 1u);
}

// --- external buffers ----------------------------------------------------------------------------

// A folder with a model in a subfolder and a file beside that subfolder, removed at the end.
struct Folder {
  fs::path root = fs::temp_directory_path() / ("hedge_guard_" + std::to_string(::getpid()));
  fs::path models = root / "models";
  Folder() {
    fs::remove_all(root);
    fs::create_directories(models / "bin");
    write(root / "secret.bin", triangle_buffer(3));
    write(models / "bin" / "tri.bin", triangle_buffer(3));
  }
  ~Folder() { fs::remove_all(root); }
  static void write(const fs::path& path, const std::string& bytes) {
    std::ofstream(path, std::ios::binary) << bytes;
  }
  // The model's path, with its buffer at `uri`.
  std::string model(const std::string& uri) const {
    const fs::path path = models / "m.gltf";
    write(path, document(3, 1, 1, uri).dump());
    return path.string();
  }
  std::string refusal(const std::string& uri) const {
    return catch_io_error([&] { read_indexed_file(model(uri)); }).what();
  }
};

TEST(GltfGuard, ExternalBuffersInsideTheFolderAreRead) {
  Folder f;
  EXPECT_EQ(read_indexed_file(f.model("bin/tri.bin")).face_count(), 1u);
  EXPECT_EQ(read_indexed_file(f.model("bin/../bin/tri.bin")).face_count(), 1u);
  EXPECT_EQ(read_indexed_file(f.model("bin%2Ftri.bin")).face_count(), 1u);
  // A link inside the folder to a file inside the folder is followed.
  fs::create_symlink("bin/tri.bin", f.models / "inside.bin");
  EXPECT_EQ(read_indexed_file(f.model("inside.bin")).face_count(), 1u);
}

TEST(GltfGuard, NothingOutsideTheFolderIsRead) {
  Folder f;
  const std::string outside = "does not name a regular file inside the .gltf's folder";
  for (const std::string uri :
       {"../secret.bin", "bin/../../secret.bin", "%2e%2e/secret.bin",
        "../../../../../../../../../../etc/passwd", "bin/../../../../../../../etc/passwd"}) {
    const std::string what = f.refusal(uri);
    EXPECT_HAS(what, "buffer 0: uri '" + uri + "' " + outside);
    // Nothing of the target comes out: neither its content nor its size.
    EXPECT_EQ(what.find("root"), std::string::npos) << what;
    EXPECT_EQ(what.find("got"), std::string::npos) << what;
  }
  EXPECT_HAS(f.refusal("/etc/passwd"), "buffer 0: uri is an absolute path");
  EXPECT_HAS(f.refusal((f.root / "secret.bin").string()), "uri is an absolute path");
  EXPECT_HAS(f.refusal("file:///etc/passwd"), "uri has a scheme");
  EXPECT_HAS(f.refusal("https://example.com/a.bin"), "uri has a scheme");
  EXPECT_HAS(f.refusal("bin/tri.bin%00.png"), "malformed %-escape or an escaped NUL");
  EXPECT_HAS(f.refusal("bin/tri.bin%2"), "malformed %-escape");
  // A link inside the folder to a file outside it.
  fs::create_symlink("../secret.bin", f.models / "link.bin");
  EXPECT_HAS(f.refusal("link.bin"), outside);
  fs::create_symlink(f.root, f.models / "up");
  EXPECT_HAS(f.refusal("up/secret.bin"), outside);
  // A folder is not a buffer.
  EXPECT_HAS(f.refusal("bin"), outside);
}

TEST(GltfGuard, AMissingBufferIsNotLookedUpInTheWorkingFolder) {
  Folder f;
  const std::string model = f.model("secret.bin");  // not beside the model, but in the working folder
  const fs::path was = fs::current_path();
  fs::current_path(f.root);
  const std::string what = catch_io_error([&] { read_indexed_file(model); }).what();
  fs::current_path(was);
  EXPECT_HAS(what, "uri 'secret.bin' does not name a regular file inside");
}

TEST(GltfGuard, AFileOfAnotherSizeIsRefusedBeforeItIsRead) {
  Folder f;
  // 20 GB, sparse: reading it would take minutes and all the memory.
  const fs::path huge = f.models / "huge.bin";
  Folder::write(huge, "");
  fs::resize_file(huge, std::uintmax_t{20} << 30);
  std::string what;
  const std::size_t peak = heap_peak_during([&] { what = f.refusal("huge.bin"); });
  EXPECT_HAS(what, "buffer 0: file 'huge.bin' is not the buffer's byteLength of 44 bytes");
  EXPECT_EQ(what.find("21474836480"), std::string::npos) << what;
  EXPECT_LT(peak, std::size_t{1} << 20);
}

TEST(GltfGuard, ExternalBuffersAreOffForBytesInMemory) {
  Folder f;
  const std::string path = f.model("bin/tri.bin");
  const std::string text = read_file(path);
  const std::string what = catch_io_error([&] { read_gltf(text, path); }).what();
  EXPECT_HAS(what,
             "buffer 0: its data is in a separate file ('uri'), and reading external buffers is turned off");
  ReadOptions on;
  on.external_buffers = true;
  EXPECT_EQ(read_gltf(text, path, on).face_count(), 1u);
  ReadOptions off;
  EXPECT_HAS(std::string(catch_io_error([&] { read_indexed_file(path, off); }).what()), "turned off");
}

// --- the memory budget ---------------------------------------------------------------------------

TEST(GltfGuard, PrimitivesSharingOneIndexAccessorAreCountedEachTime) {
  // 1,000 primitives on one accessor of 30,000 indices: 30M corners from a 130 KB file.
  const std::string text = document(30000, 1000).dump();
  ASSERT_LT(text.size(), 200000u);
  std::string what;
  const std::size_t peak = heap_peak_during([&] { what = message(text); });
  EXPECT_HAS(what, "m.gltf: its JSON and the meshes its nodes place would take about");
  EXPECT_HAS(what, "more than the read budget of");
  EXPECT_HAS(what, "raise the budget: max_memory");
  EXPECT_LT(peak, std::size_t{16} << 20);
}

TEST(GltfGuard, NodesPlacingAMeshManyTimesAreCountedEachTime) {
  const std::string text = document(30000, 1, 20000).dump();  // 6e8 corners
  std::string what;
  const std::size_t peak = heap_peak_during([&] { what = message(text); });
  EXPECT_HAS(what, "more than the read budget");
  EXPECT_LT(peak, std::size_t{64} << 20);
}

TEST(GltfGuard, AMillionEmptyNodesAreRefusedBeforeParsing) {
  std::string text = document().dump();
  const std::string one = "\"nodes\":[{\"mesh\":0}]";
  const std::size_t at = text.find(one);
  ASSERT_NE(at, std::string::npos) << text;
  std::string nodes = "\"nodes\":[{\"mesh\":0}";
  for (int i = 0; i < 1000000; ++i) nodes += ",{}";
  text.replace(at, one.size(), nodes + "]");
  std::string what;
  const std::size_t peak = heap_peak_during([&] { what = message(text); });
  EXPECT_HAS(what, "m.gltf: its JSON would take about");
  EXPECT_LT(peak, 3 * text.size());  // the scan's own buffers; parsing would have taken 550 MB
}

TEST(GltfGuard, ARaisedBudgetReadsWhatTheDefaultRefuses) {
  const std::string text = document(3000, 1200).dump();  // 3.6M corners from about 80 KB
  EXPECT_HAS(message(text), "more than the read budget");
  ReadOptions trusted;
  trusted.max_memory = std::uint64_t{512} << 20;
  std::size_t faces = 0;
  const std::size_t peak = heap_peak_during([&] { faces = read_gltf(text, "m.gltf", trusted).face_count(); });
  EXPECT_EQ(faces, 1200u * 1000u);
  EXPECT_LT(peak, trusted.max_memory);  // the estimate bounds what reading took
  ReadOptions tight;
  tight.max_memory = 1000;
  EXPECT_HAS(message(document().dump(), tight), "more than the read budget of 1000 bytes");
}

TEST(GltfGuard, TheDefaultBudgetFollowsTheInputSize) {
  EXPECT_EQ(read_budget({}, 0), kDefaultReadMemoryFloor);
  EXPECT_EQ(read_budget({}, 1000), 64000 + kDefaultReadMemoryFloor);
  ReadOptions set;
  set.max_memory = 12345;
  EXPECT_EQ(read_budget(set, 1000), 12345u);
  EXPECT_EQ(read_budget({}, ~std::uint64_t{0} / 2), ~std::uint64_t{0});
}

}  // namespace
}  // namespace hedge
