#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <tuple>
#include <vector>

#include "hedge/core/build.h"
#include "hedge/error.h"
#include "hedge/io/io.h"
#include "io/io_errors.h"
#include "test_meshes.h"

namespace hedge {
namespace {

namespace fs = std::filesystem;

using test::catch_io_error;
using test::data_path;
using test::expect_io_error;

// A fresh folder per test, removed afterwards.
class FileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    std::random_device rd;
    dir_ = fs::temp_directory_path() / ("hedge_io_test_" + std::to_string(rd()) + std::to_string(rd()));
    fs::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ec;
    fs::permissions(dir_, fs::perms::owner_all, fs::perm_options::add, ec);
    fs::remove_all(dir_, ec);
  }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }
  std::vector<std::string> listing() const {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(dir_)) names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  }
  static void put(const std::string& p, const std::string& bytes) {
    std::ofstream(p, std::ios::binary) << bytes;
  }
  //! Writing over a file `name` that has the permissions `perms` replaces its bytes and keeps them.
  void expect_replaced_keeping(const std::string& name, fs::perms perms) const {
    put(path(name), "old");
    fs::permissions(path(name), perms);
    write_file_atomic(path(name), "new");
    EXPECT_EQ(read_file(path(name)), "new");
    EXPECT_EQ(fs::status(path(name)).permissions() & fs::perms::all, perms);
  }

  fs::path dir_;
};

TEST(FormatFromPath, ExtensionsAreCaseInsensitive) {
  EXPECT_EQ(format_from_path("a/b/mesh.obj"), FileFormat::obj);
  EXPECT_EQ(format_from_path("MESH.OFF"), FileFormat::off);
  EXPECT_EQ(format_from_path("x.y.Ply"), FileFormat::ply);
  EXPECT_EQ(format_from_path("/abs/part.StL"), FileFormat::stl);
  EXPECT_EQ(format_from_path("mesh.GLTF"), FileFormat::gltf);
  EXPECT_EQ(format_from_path("mesh.Glb"), FileFormat::glb);
  EXPECT_THROW(format_from_path("mesh.fbx"), IoError);
  EXPECT_THROW(format_from_path("dir.obj/mesh"), IoError);
  EXPECT_THROW(format_from_path("obj"), IoError);
  try {
    format_from_path("model.3ds");
  } catch (const IoError& e) {
    EXPECT_EQ(e.path(), "model.3ds");
    EXPECT_NE(std::string(e.what()).find("unknown file extension"), std::string::npos);
  }
}

TEST(DefaultBuildOptions, RepairEverywhereAndWeldOnlyStlAndGltf) {
  for (FileFormat f : {FileFormat::obj, FileFormat::off, FileFormat::ply, FileFormat::stl, FileFormat::gltf,
                       FileFormat::glb}) {
    const BuildOptions o = default_build_options(f);
    EXPECT_EQ(o.policy, TopologyPolicy::repair);
    const bool welds = f == FileFormat::stl || f == FileFormat::gltf || f == FileFormat::glb;
    EXPECT_EQ(o.weld, welds ? Weld::exact : Weld::none);
  }
}

TEST(ReadIndexed, DispatchesOnTheFormat) {
  const std::string off = "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  EXPECT_EQ(read_indexed(off, FileFormat::off).indices, (std::vector<std::uint32_t>{0, 1, 2}));
  EXPECT_THROW(read_indexed(off, FileFormat::obj), IoError);
  EXPECT_THROW(read_indexed(off, FileFormat::ply), IoError);
  EXPECT_THROW(read_indexed(off, FileFormat::gltf), IoError);
  IndexedMesh m = read_indexed(off, FileFormat::off);
  for (FileFormat f : {FileFormat::obj, FileFormat::off, FileFormat::ply, FileFormat::stl, FileFormat::gltf,
                       FileFormat::glb})
    EXPECT_EQ(read_indexed(write_indexed(m, f), f).positions, m.positions);
}

TEST_F(FileTest, ReadFileErrors) {
  const IoError e = expect_io_error([&] { read_file(path("missing.obj")); }, "cannot open");
  EXPECT_EQ(e.path(), path("missing.obj"));
  EXPECT_THROW(read_file(dir_.string()), IoError);
  EXPECT_THROW(read_indexed_file(path("missing.off")), IoError);
}

TEST_F(FileTest, ReadFileReturnsEveryByte) {
  std::string bytes(200000, '\0');
  for (std::size_t i = 0; i < bytes.size(); ++i) bytes[i] = static_cast<char>(i * 7 + i / 251);
  put(path("blob.bin"), bytes);
  EXPECT_EQ(read_file(path("blob.bin")), bytes);
  put(path("empty.bin"), "");
  EXPECT_EQ(read_file(path("empty.bin")), "");
}

// Switches write_file_atomic() to named temporary files, as on a file system without O_TMPFILE,
// for the life of the object.
class NamedTemporaryFiles {
 public:
  explicit NamedTemporaryFiles(bool on) : was_(detail::force_named_temporary_files(on)) {}
  NamedTemporaryFiles(const NamedTemporaryFiles&) = delete;
  NamedTemporaryFiles& operator=(const NamedTemporaryFiles&) = delete;
  ~NamedTemporaryFiles() { detail::force_named_temporary_files(was_); }

 private:
  bool was_;
};

// Whether the file system of `dir` has unnamed files (O_TMPFILE).
bool has_unnamed_files(const fs::path& dir) {
#ifdef O_TMPFILE
  const int fd = ::open(dir.c_str(), O_TMPFILE | O_WRONLY | O_CLOEXEC, 0600);
  if (fd < 0) return false;
  ::close(fd);
  return true;
#else
  (void)dir;
  return false;
#endif
}

// A process id that is certainly not running: a child that has exited and been reaped.
pid_t dead_pid() {
  const pid_t child = ::fork();
  if (child == 0) ::_exit(0);
  int status = 0;
  ::waitpid(child, &status, 0);
  return child;
}

// Forks a child that writes `bytes` to `target` and kills it with SIGKILL in the middle of the
// write: once one of its open files in `folder` (the temporary) holds some of the bytes, but not
// all. Returns the child's pid, reaped.
pid_t kill_in_the_middle_of_a_write(const std::string& target, const std::string& bytes,
                                    const fs::path& folder) {
  const pid_t child = ::fork();
  if (child == 0) {
    ::setpriority(PRIO_PROCESS, 0, 19);  // slower than the parent that watches it
    try {
      write_file_atomic(target, bytes);
    } catch (...) {
      ::_exit(2);
    }
    ::_exit(0);
  }
  const std::string inside = fs::canonical(folder).string() + "/";
  const std::string proc = "/proc/" + std::to_string(child);
  bool seen = false;
  std::uintmax_t seen_size = 0;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  int status = 0;
  bool exited = false;
  while (!seen && std::chrono::steady_clock::now() < deadline) {
    if (::waitpid(child, &status, WNOHANG) == child) {
      exited = true;
      break;
    }
    std::error_code ec;
    for (const auto& fd : fs::directory_iterator(proc + "/fd", ec)) {
      const std::string file = fs::read_symlink(fd.path(), ec).string();
      if (ec || file.rfind(inside, 0) != 0) continue;
      // The size of the file itself (the link leads to it), which grows during one long write().
      const std::uintmax_t size = fs::file_size(fd.path(), ec);
      if (!ec && size > 0) {
        seen = true;
        seen_size = size;
      }
    }
  }
  if (!exited) {
    ::kill(child, SIGKILL);
    ::waitpid(child, &status, 0);
  }
  EXPECT_TRUE(seen) << "the child's temporary file was never seen";
  EXPECT_LT(seen_size, bytes.size()) << "the child was not stopped in the middle of the write";
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL) << "the write ended before the kill";
  return child;
}

TEST_F(FileTest, AtomicWriteCreatesAndReplaces) {
  for (bool named : {false, true}) {
    SCOPED_TRACE(named ? "named temporary files" : "unnamed temporary files");
    NamedTemporaryFiles mode(named);
    write_file_atomic(path("a.txt"), "first");
    EXPECT_EQ(read_file(path("a.txt")), "first");
    write_file_atomic(path("a.txt"), "second, longer");
    EXPECT_EQ(read_file(path("a.txt")), "second, longer");
    EXPECT_EQ(listing(), (std::vector<std::string>{"a.txt"}));  // no temporary left behind
    fs::remove(path("a.txt"));
  }
}

TEST_F(FileTest, AtomicWriteKeepsThePermissionsOfTheFileItReplaces) {
  for (bool named : {false, true}) {
    SCOPED_TRACE(named ? "named temporary files" : "unnamed temporary files");
    NamedTemporaryFiles mode(named);
    expect_replaced_keeping("p.txt", fs::perms::owner_read | fs::perms::owner_write);
    fs::remove(path("p.txt"));
  }
}

TEST_F(FileTest, AtomicWriteKeepsTheOwnerAndGroupOfTheFileItReplaces) {
  if (::geteuid() != 0) GTEST_SKIP() << "only root may give a file to another owner";
  put(path("owned.txt"), "old");
  ASSERT_EQ(::chown(path("owned.txt").c_str(), 4321, 4322), 0);
  write_file_atomic(path("owned.txt"), "new");
  struct stat st {};
  ASSERT_EQ(::stat(path("owned.txt").c_str(), &st), 0);
  EXPECT_EQ(st.st_uid, 4321u);
  EXPECT_EQ(st.st_gid, 4322u);
  EXPECT_EQ(read_file(path("owned.txt")), "new");
}

TEST_F(FileTest, AtomicWriteRefusesAReadOnlyFileEvenAsRoot) {
  put(path("ro.obj"), "keep");
  fs::permissions(path("ro.obj"), fs::perms::owner_read | fs::perms::group_read | fs::perms::others_read);
  const IoError e = expect_io_error([&] { write_file_atomic(path("ro.obj"), "new"); }, "read-only");
  EXPECT_EQ(e.path(), path("ro.obj"));
  EXPECT_EQ(read_file(path("ro.obj")), "keep");
  EXPECT_EQ(fs::status(path("ro.obj")).permissions() & fs::perms::all,
            fs::perms::owner_read | fs::perms::group_read | fs::perms::others_read);
  EXPECT_EQ(listing(), (std::vector<std::string>{"ro.obj"}));
  // One write permission bit is enough, and it is kept.
  expect_replaced_keeping("group.obj", fs::perms::owner_read | fs::perms::group_write);
}

TEST_F(FileTest, AtomicWriteIntoAMissingFolderCreatesNothing) {
  const std::string target = path("no/such/dir/mesh.obj");
  const IoError e =
      expect_io_error([&] { write_file_atomic(target, "data"); }, "cannot create a temporary file");
  EXPECT_EQ(e.path(), target);
  EXPECT_FALSE(fs::exists(path("no")));
  EXPECT_TRUE(listing().empty());
}

TEST_F(FileTest, AtomicWriteOverADirectoryFailsAndLeavesIt) {
  fs::create_directories(path("target.obj"));
  put(path("target.obj/inside.txt"), "keep");
  expect_io_error([&] { write_file_atomic(path("target.obj"), "data"); }, "is a directory");
  EXPECT_TRUE(fs::is_directory(path("target.obj")));
  EXPECT_EQ(read_file(path("target.obj/inside.txt")), "keep");
  EXPECT_EQ(listing(), (std::vector<std::string>{"target.obj"}));  // the temporary was removed
}

TEST_F(FileTest, AtomicWriteRefusesAFifoAndADevice) {
  // Opening the FIFO to write would wait for a reader: a hang here means it was not refused.
  ASSERT_EQ(::mkfifo(path("pipe.obj").c_str(), 0666), 0);
  expect_io_error([&] { write_file_atomic(path("pipe.obj"), "data"); }, "is a FIFO");
  EXPECT_TRUE(fs::is_fifo(fs::symlink_status(path("pipe.obj"))));
  // A device, reached through a link (writing to /dev/null itself would "succeed" unseen).
  fs::create_symlink("/dev/null", path("null.obj"));
  expect_io_error([&] { write_file_atomic(path("null.obj"), "data"); }, "is a character device");
  EXPECT_TRUE(fs::is_character_file("/dev/null"));
  EXPECT_TRUE(fs::is_symlink(path("null.obj")));
  EXPECT_EQ(listing(), (std::vector<std::string>{"null.obj", "pipe.obj"}));
}

TEST_F(FileTest, AtomicWriteThroughALinkReplacesTheFileItLeadsTo) {
  put(path("real.obj"), "old");
  fs::permissions(path("real.obj"), fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
  fs::create_symlink("real.obj", path("link.obj"));
  write_file_atomic(path("link.obj"), "new");
  EXPECT_TRUE(fs::is_symlink(path("link.obj")));
  EXPECT_EQ(fs::read_symlink(path("link.obj")), "real.obj");
  EXPECT_EQ(read_file(path("real.obj")), "new");
  EXPECT_EQ(fs::status(path("real.obj")).permissions() & fs::perms::all,
            fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
  // An absolute link.
  fs::create_symlink(path("real.obj"), path("absolute.obj"));
  write_file_atomic(path("absolute.obj"), "newer");
  EXPECT_TRUE(fs::is_symlink(path("absolute.obj")));
  EXPECT_EQ(read_file(path("real.obj")), "newer");
  // A chain whose second link is relative to its own folder: chain.obj -> sub/mid.obj -> end.obj,
  // which is sub/end.obj.
  fs::create_directories(path("sub"));
  put(path("sub/end.obj"), "old");
  fs::create_symlink("sub/mid.obj", path("chain.obj"));
  fs::create_symlink("end.obj", path("sub/mid.obj"));
  write_file_atomic(path("chain.obj"), "through two links");
  EXPECT_TRUE(fs::is_symlink(path("chain.obj")));
  EXPECT_TRUE(fs::is_symlink(path("sub/mid.obj")));
  EXPECT_EQ(read_file(path("sub/end.obj")), "through two links");
  EXPECT_EQ(listing(),
            (std::vector<std::string>{"absolute.obj", "chain.obj", "link.obj", "real.obj", "sub"}));
}

TEST_F(FileTest, AtomicWriteThroughADanglingLinkCreatesItsTarget) {
  fs::create_symlink("made.obj", path("dangling.obj"));
  write_file_atomic(path("dangling.obj"), "new");
  EXPECT_TRUE(fs::is_symlink(path("dangling.obj")));
  EXPECT_TRUE(fs::is_regular_file(fs::symlink_status(path("made.obj"))));
  EXPECT_EQ(read_file(path("made.obj")), "new");
  // Links in a loop are refused.
  fs::create_symlink("loop_b.obj", path("loop_a.obj"));
  fs::create_symlink("loop_a.obj", path("loop_b.obj"));
  expect_io_error([&] { write_file_atomic(path("loop_a.obj"), "data"); },
                  "too many levels of symbolic links");
  EXPECT_TRUE(fs::is_symlink(path("loop_a.obj")));
  EXPECT_EQ(listing(), (std::vector<std::string>{"dangling.obj", "loop_a.obj", "loop_b.obj", "made.obj"}));
}

TEST_F(FileTest, AtomicWriteThatFailsHalfwayLeavesTheOldFileIntact) {
  for (bool named : {false, true}) {
    SCOPED_TRACE(named ? "named temporary files" : "unnamed temporary files");
    NamedTemporaryFiles mode(named);
    put(path("mesh.off"), "old contents");
    // A file size limit makes write() fail after the first kilobyte, with the temporary file
    // open: the failure happens in the middle of writing, where a non-atomic writer would have
    // truncated the target already. (Running as root, a permission trick would not fail.)
    rlimit old_limit{};
    ASSERT_EQ(getrlimit(RLIMIT_FSIZE, &old_limit), 0);
    const auto old_handler = std::signal(SIGXFSZ, SIG_IGN);
    rlimit small = old_limit;
    small.rlim_cur = 1024;
    ASSERT_EQ(setrlimit(RLIMIT_FSIZE, &small), 0);
    bool threw = false;
    try {
      write_file_atomic(path("mesh.off"), std::string(100000, 'x'));
    } catch (const IoError& e) {
      threw = true;
      EXPECT_NE(std::string(e.what()).find("write error"), std::string::npos) << e.what();
    }
    setrlimit(RLIMIT_FSIZE, &old_limit);
    std::signal(SIGXFSZ, old_handler);
    EXPECT_TRUE(threw);
    EXPECT_EQ(read_file(path("mesh.off")), "old contents");
    EXPECT_EQ(listing(), (std::vector<std::string>{"mesh.off"}));
  }
}

TEST_F(FileTest, AKilledWriteLeavesNoTemporaryFile) {
  if (!has_unnamed_files(dir_)) GTEST_SKIP() << "no O_TMPFILE on this file system";
  const std::string bytes(std::size_t{64} << 20, 'x');
  // No target yet: nothing at all is left.
  kill_in_the_middle_of_a_write(path("big.obj"), bytes, dir_);
  EXPECT_TRUE(listing().empty());
  // A target: it keeps its old bytes, and nothing else is left.
  put(path("big.obj"), "old");
  kill_in_the_middle_of_a_write(path("big.obj"), bytes, dir_);
  EXPECT_EQ(listing(), (std::vector<std::string>{"big.obj"}));
  EXPECT_EQ(read_file(path("big.obj")), "old");
}

TEST_F(FileTest, AKilledWritesNamedTemporaryIsRemovedByTheNextWrite) {
  NamedTemporaryFiles mode(true);
  const std::string bytes(std::size_t{64} << 20, 'x');
  put(path("big.obj"), "old");
  const pid_t child = kill_in_the_middle_of_a_write(path("big.obj"), bytes, dir_);
  const std::vector<std::string> left = listing();
  ASSERT_EQ(left.size(), 2u);
  EXPECT_EQ(left[0].rfind(".big.obj.hedge-tmp." + std::to_string(child) + ".", 0), 0u) << left[0];
  EXPECT_EQ(read_file(path("big.obj")), "old");
  write_file_atomic(path("big.obj"), "new");
  EXPECT_EQ(listing(), (std::vector<std::string>{"big.obj"}));
  EXPECT_EQ(read_file(path("big.obj")), "new");
}

TEST_F(FileTest, AtomicWriteRemovesOnlyTheStaleTemporariesOfItsTarget) {
  const std::string dead = std::to_string(dead_pid());
  const std::string live = std::to_string(::getppid());
  const std::string stale = ".t.obj.hedge-tmp." + dead + ".3";
  const std::vector<std::string> kept = {
      ".t.obj.hedge-tmp." + live + ".0",      // its writer is still running
      ".t.obj.hedge-tmp." + dead + ".3.bak",  // not a name the writer makes
      ".t.obj.hedge-tmp." + dead + ".",       // nor this
      ".t.obj.hedge-tmp.-" + dead + ".0",     // nor this
      ".u.obj.hedge-tmp." + dead + ".0",      // another target's
  };
  put(path(stale), "stale");
  for (const std::string& name : kept) put(path(name), "kept");
  write_file_atomic(path("t.obj"), "new");
  std::vector<std::string> expected = kept;
  expected.push_back("t.obj");
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(listing(), expected);
  EXPECT_EQ(read_file(path("t.obj")), "new");
}

TEST_F(FileTest, IndexedFilesInEveryFormat) {
  IndexedMesh m = read_indexed_file(data_path("fandisk_quads.off"));
  // Colours, which only glTF carries, are left out by the other writers.
  m.colors = {{1, 0, 0, 1}, {0, 0, 1, 0.5f}};
  for (std::size_t c = 0; c < m.indices.size(); ++c)
    m.color_indices.push_back(static_cast<std::uint32_t>(c % 2));
  for (const char* ext : {"obj", "off", "ply"}) {
    SCOPED_TRACE(ext);
    const std::string p = path(std::string("m.") + ext);
    write_indexed_file(m, p);
    const IndexedMesh back = read_indexed_file(p);
    EXPECT_EQ(back.positions, m.positions);
    EXPECT_EQ(back.indices, m.indices);
    EXPECT_EQ(back.face_sizes, m.face_sizes);
    EXPECT_TRUE(back.color_indices.empty());
  }
  write_indexed_file(m, path("m.stl"));
  const IndexedMesh stl = read_indexed_file(path("m.stl"));
  EXPECT_EQ(stl.face_count(), 2 * m.face_count());  // quads fanned into two triangles
  EXPECT_THROW(write_indexed_file(m, path("m.xyz")), IoError);
  EXPECT_FALSE(fs::exists(path("m.xyz")));
}

TEST_F(FileTest, ErrorsFromFilesNameThePath) {
  put(path("bad.obj"), "v 0 0 0\nv 1 0 0\nf 1 2 x\n");
  const IoError e = catch_io_error([&] { read_indexed_file(path("bad.obj")); });
  EXPECT_EQ(e.path(), path("bad.obj"));
  EXPECT_EQ(e.line(), 3u);
  EXPECT_EQ(std::string(e.what()), path("bad.obj") + ":3: expected a vertex index after 'f', got 'x'");
}

TEST_F(FileTest, ATruncatedFaceLineIsNamedWithItsLine) {
  // A file cut in the middle of its last face line: "f 3" has one corner.
  const std::string cut = path("cut.obj");
  put(cut, "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3\nf 3\n");
  // Strict: refused, with the line.
  try {
    read_mesh(cut, BuildOptions{.policy = TopologyPolicy::strict});
    FAIL() << "a one-corner face under the strict policy";
  } catch (const IoError& e) {
    EXPECT_EQ(e.line(), 6u);
    EXPECT_EQ(std::string(e.what()),
              cut + ":6: face 1 has 1 corner; a face needs at least 3 (the file may be truncated)");
  }
  // Repair: the face is dropped, and the report says where and why, not only a count.
  BuildReport report;
  const SurfaceMesh m = read_mesh(cut, &report);
  EXPECT_EQ(m.n_faces(), 1u);
  EXPECT_EQ(report.degenerate_faces, 1u);
  ASSERT_EQ(report.warnings.size(), 1u);
  EXPECT_EQ(report.warnings[0],
            cut + ":6: face 1 has 1 corner; a face needs at least 3 (the file may be truncated)");
  EXPECT_TRUE(m.validate().empty());

  // The same in OFF (line of the record) and PLY (ascii: line; binary: byte offset of the face).
  const std::string off = path("cut.off");
  put(off, "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n3 0 1 2\n2 2 1\n");
  report = {};
  read_mesh(off, &report);
  ASSERT_EQ(report.warnings.size(), 1u);
  EXPECT_EQ(report.warnings[0],
            off + ":8: face 1 has 2 corners; a face needs at least 3 (the file may be truncated)");
  EXPECT_THROW(read_mesh(off, BuildOptions{.policy = TopologyPolicy::strict}), IoError);

  const std::string header =
      "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 2\nproperty list uchar int vertex_indices\nend_header\n";
  const std::string ascii = path("cut.ply");
  put(ascii, "ply\nformat ascii 1.0\n" + header + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n1 2\n");
  report = {};
  read_mesh(ascii, &report);
  ASSERT_EQ(report.warnings.size(), 1u);
  EXPECT_EQ(report.warnings[0],
            ascii + ":14: face 1 has 1 corner; a face needs at least 3 (the file may be truncated)");
  const std::string binary = path("cut_binary.ply");
  std::string body;
  auto f32 = [&](float v) { body.append(reinterpret_cast<const char*>(&v), 4); };
  auto i32 = [&](std::int32_t v) { body.append(reinterpret_cast<const char*>(&v), 4); };
  for (float v : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f}) f32(v);
  body += char(3);
  for (int v : {0, 1, 2}) i32(v);
  const std::size_t second_face = body.size();
  body += char(1);
  i32(2);
  const std::string head = "ply\nformat binary_little_endian 1.0\n" + header;
  put(binary, head + body);
  report = {};
  read_mesh(binary, &report);
  ASSERT_EQ(report.warnings.size(), 1u);
  EXPECT_EQ(report.warnings[0],
            binary + " (byte " + std::to_string(head.size() + second_face) +
                "): face 1 has 1 corner; a face needs at least 3 (the file may be truncated)");
}

TEST(ReadMesh, BuildsWithTheFormatDefaults) {
  BuildReport report;
  const SurfaceMesh tet = read_mesh(data_path("tet.obj"), &report);
  EXPECT_EQ(tet.n_vertices(), 4u);
  EXPECT_EQ(tet.n_faces(), 4u);
  EXPECT_EQ(report.repairs(), 0u);
  // STL: 60 soup corners welded exactly into the icosahedron's 12 vertices.
  const SurfaceMesh ico = read_mesh(data_path("icosahedron_binary.stl"), &report);
  EXPECT_EQ(ico.n_vertices(), 12u);
  EXPECT_EQ(ico.n_faces(), 20u);
  EXPECT_EQ(report.welded_vertices, 48u);
  // Explicit options override the defaults.
  BuildOptions none;
  none.policy = TopologyPolicy::repair;
  EXPECT_EQ(read_mesh(data_path("icosahedron_binary.stl"), none).n_vertices(), 60u);
  EXPECT_THROW(read_mesh(data_path("hourglass_ico.obj"), BuildOptions{}), TopologyError);
}

TEST(ReadMesh, EveryDataFileLoadsWithRepair) {
  for (const auto& entry : fs::directory_iterator(HEDGE_DATA_DIR)) {
    const std::string p = entry.path().string();
    const std::string ext = entry.path().extension().string();
    if (ext != ".obj" && ext != ".off" && ext != ".ply" && ext != ".stl") continue;
    SCOPED_TRACE(p);
    BuildReport report;
    const IndexedMesh input = read_indexed_file(p);
    const SurfaceMesh m = read_mesh(p, &report);
    EXPECT_GT(m.n_faces(), 0u);
    EXPECT_LE(m.n_faces(), input.face_count());
    EXPECT_EQ(m.n_faces() + report.degenerate_faces, input.face_count());
  }
  BuildReport spider;
  read_mesh(data_path("Spider_binary.stl"), &spider);
  EXPECT_GT(spider.repairs(), 0u);
  EXPECT_GT(spider.degenerate_faces, 0u);
}

// Faces as position triples, each rotated to start at its smallest corner, sorted: equal for two
// meshes with the same positions and oriented connectivity, whatever their vertex order.
std::vector<std::array<std::tuple<float, float, float>, 3>> canonical_triangles(const IndexedMesh& m) {
  std::vector<std::array<std::tuple<float, float, float>, 3>> out;
  for (std::size_t t = 0; t < m.face_count(); ++t) {
    std::array<std::tuple<float, float, float>, 3> tri;
    for (int k = 0; k < 3; ++k) {
      const Vec3& p = m.positions[m.indices[3 * t + static_cast<std::size_t>(k)]];
      tri[static_cast<std::size_t>(k)] = {p.x, p.y, p.z};
    }
    std::rotate(tri.begin(), std::min_element(tri.begin(), tri.end()), tri.end());
    out.push_back(tri);
  }
  std::sort(out.begin(), out.end());
  return out;
}

TEST_F(FileTest, RoundTripThroughEveryFormatKeepsPositionsAndConnectivity) {
  const std::string start = data_path("spot_triangulated.obj");
  const IndexedMesh original = read_indexed_file(start);
  SurfaceMesh mesh = read_mesh(start);
  for (const char* ext : {"off", "ply", "stl", "obj"}) {
    SCOPED_TRACE(ext);
    const std::string p = path(std::string("step.") + ext);
    write_mesh(mesh, p);
    mesh = read_mesh(p);
    EXPECT_EQ(mesh.n_vertices(), original.positions.size());
    EXPECT_EQ(mesh.n_faces(), original.face_count());
  }
  const IndexedMesh final_mesh = read_indexed_file(path("step.obj"));
  EXPECT_EQ(final_mesh.positions.size(), original.positions.size());
  std::vector<Vec3> a = original.positions, b = final_mesh.positions;
  auto less = [](const Vec3& u, const Vec3& v) { return std::tie(u.x, u.y, u.z) < std::tie(v.x, v.y, v.z); };
  std::sort(a.begin(), a.end(), less);
  std::sort(b.begin(), b.end(), less);
  EXPECT_EQ(a, b);
  EXPECT_TRUE(canonical_triangles(final_mesh) == canonical_triangles(original));
}

TEST_F(FileTest, WriteMeshTriangulatesForStl) {
  const SurfaceMesh m = read_mesh(data_path("spot_control_mesh.obj"));
  write_mesh(m, path("cage.stl"));
  // 4 triangles, 160 quads and 16 pentagons: 4 + 320 + 48 triangles.
  EXPECT_EQ(read_indexed_file(path("cage.stl")).face_count(), 372u);
  write_mesh(m, path("cage.obj"));
  const IndexedMesh obj = read_indexed_file(path("cage.obj"));
  EXPECT_EQ(obj.face_count(), 180u);
  EXPECT_EQ(obj.texcoord_indices.size(), obj.indices.size());
  WriteOptions ascii;
  ascii.binary = false;
  write_mesh(m, path("cage.ply"), ascii);
  EXPECT_EQ(read_file(path("cage.ply")).find("format ascii 1.0"), 4u);
}

// Every real mesh beside the project, defects included, loads in repair mode into a valid mesh,
// and only degenerate faces are dropped. Skipped where the shared meshes are absent.
TEST(ReadMesh, EverySharedMeshRepairsIntoAValidMesh) {
  const fs::path dir = HEDGE_SHARED_MESHES_DIR;
  if (!fs::is_directory(dir)) GTEST_SKIP() << "no shared meshes beside the project";
  std::size_t checked = 0;
  for (const auto& entry : fs::directory_iterator(dir)) {
    std::string ext = entry.path().extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    if (ext != ".obj" && ext != ".off" && ext != ".ply" && ext != ".stl") continue;
    SCOPED_TRACE(entry.path().filename().string());
    const IndexedMesh indexed = read_indexed_file(entry.path().string());
    BuildReport report;
    const SurfaceMesh mesh = read_mesh(entry.path().string(), &report);
    EXPECT_TRUE(mesh.validate().empty());
    EXPECT_EQ(mesh.n_faces() + report.degenerate_faces, indexed.face_count());
    for (Vertex v : mesh.vertices()) ASSERT_TRUE(mesh.is_manifold(v));
    ++checked;
  }
  EXPECT_GE(checked, 20u);
}

}  // namespace
}  // namespace hedge
