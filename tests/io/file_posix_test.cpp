// Tests of file_posix.cpp: read_file() and write_file_atomic() on POSIX systems (permissions,
// owners, links, FIFOs, killed writers, unnamed temporaries).
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
#include "io/file_fixture.h"
#include "io/io_errors.h"
#include "test_meshes.h"

namespace hedge {
namespace {

namespace fs = std::filesystem;

using test::expect_io_error;
using test::FileTest;

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

TEST_F(FileTest, ReadingRefusesADeviceThatWouldNeverEnd) {
  // Through a link named like a mesh: /dev/zero would fill the memory before its end of file.
  fs::create_symlink("/dev/zero", path("zero.obj"));
  const IoError e = expect_io_error([&] { read_file(path("zero.obj")); }, "is a character device");
  EXPECT_EQ(e.path(), path("zero.obj"));
  expect_io_error([&] { read_indexed_file(path("zero.obj")); }, "cannot read: it is a character device");
  // A pipe is read to its end.
  int fds[2];
  ASSERT_EQ(::pipe(fds), 0);
  ASSERT_EQ(::write(fds[1], "v 0 0 0\n", 8), 8);
  ::close(fds[1]);
  EXPECT_EQ(read_file("/dev/fd/" + std::to_string(fds[0])), "v 0 0 0\n");
  ::close(fds[0]);
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

}  // namespace
}  // namespace hedge
