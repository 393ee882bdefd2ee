// Reading and atomic writing of files on POSIX systems (Linux, macOS, the BSDs): read_file(),
// write_file_atomic() and the file identities of file_system.h. file_windows.cpp is the Windows one.
#ifndef _WIN32

#include <dirent.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "fd.h"
#include "file_system.h"
#include "hedge/io/io.h"

namespace hedge {

using detail::Fd;
using detail::temporary_name;
using detail::temporary_owner;

namespace {

std::string errno_text(int err) { return std::strerror(err); }

}  // namespace

std::string read_file(const std::string& path) {
  Fd fd(::open(path.c_str(), O_RDONLY | O_CLOEXEC));
  if (fd.get() < 0) throw IoError(path, 0, -1, "cannot open: " + errno_text(errno));
  struct stat st {};
  if (::fstat(fd.get(), &st) != 0) throw IoError(path, 0, -1, "cannot stat: " + errno_text(errno));
  if (S_ISDIR(st.st_mode)) throw IoError(path, 0, -1, "cannot read: it is a directory");
  // A device never ends (/dev/zero, /dev/urandom) or is no mesh: reading one would take memory
  // without bound. Regular files and pipes are read.
  if (S_ISCHR(st.st_mode) || S_ISBLK(st.st_mode))
    throw IoError(path, 0, -1,
                  std::string("cannot read: it is a ") + (S_ISCHR(st.st_mode) ? "character" : "block") +
                      " device, not a file");
  std::string data;
  // The size is only a hint (pipes report 0, a file may grow): read until end of file. One byte
  // more than the size lets the first read() reach the end and the second one confirm it.
  data.resize(S_ISREG(st.st_mode) && st.st_size > 0 ? static_cast<std::size_t>(st.st_size) + 1 : 65536);
  std::size_t used = 0;
  for (;;) {
    if (used == data.size()) data.resize(2 * data.size());
    const ssize_t n = ::read(fd.get(), data.data() + used, data.size() - used);
    if (n < 0) {
      if (errno == EINTR) continue;
      throw IoError(path, 0, static_cast<std::int64_t>(used), "read error: " + errno_text(errno));
    }
    if (n == 0) break;
    used += static_cast<std::size_t>(n);
  }
  data.resize(used);
  return data;
}

// ---- write_file_atomic and its steps ----

namespace {

std::atomic<bool> force_named_temporaries{false};

// Numbers the temporary names of this process, so that two threads writing the same target at
// once pick different names.
std::atomic<unsigned> temporary_counter{0};

// What write_file_atomic() replaces: the file that `path` names once every symbolic link is
// followed, split into its folder and name.
struct Target {
  std::string path;  // the resolved file
  std::string dir;   // its folder, "./" when the path has no slash, else ending in '/'
  std::string base;  // its file name
  bool exists = false;
  struct stat st {};  // valid when exists
};

std::string folder_of(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  return slash == std::string::npos ? std::string("./") : path.substr(0, slash + 1);
}

std::string kind_of(mode_t mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISFIFO(mode)) return "a FIFO";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

// Follows the whole chain of symbolic links from `path`: a relative link is read from its own
// folder. The last step may name nothing yet (a dangling link, or a new file).
Target resolve_target(const std::string& path) {
  constexpr int max_links = 40;  // as the kernel's own limit
  std::string current = path;
  for (int links = 0;; ++links) {
    struct stat st {};
    if (::lstat(current.c_str(), &st) != 0) {
      if (errno != ENOENT)
        throw IoError(path, 0, -1, "cannot inspect '" + current + "': " + errno_text(errno));
      return Target{current, folder_of(current), current.substr(current.find_last_of('/') + 1), false, {}};
    }
    if (!S_ISLNK(st.st_mode)) {
      return Target{current, folder_of(current), current.substr(current.find_last_of('/') + 1), true, st};
    }
    if (links == max_links) throw IoError(path, 0, -1, "cannot write: too many levels of symbolic links");
    std::string link(static_cast<std::size_t>(st.st_size > 0 ? st.st_size : 256), '\0');
    for (;;) {
      const ssize_t n = ::readlink(current.c_str(), link.data(), link.size());
      if (n < 0) throw IoError(path, 0, -1, "cannot read the link '" + current + "': " + errno_text(errno));
      if (n == 0) throw IoError(path, 0, -1, "cannot follow the empty link '" + current + "'");
      if (static_cast<std::size_t>(n) < link.size()) {
        link.resize(static_cast<std::size_t>(n));
        break;
      }
      link.resize(2 * link.size());  // the link changed meanwhile: read it again, whole
    }
    current =
        link.front() == '/' || current.find('/') == std::string::npos ? link : folder_of(current) + link;
  }
}

// Refuses, before anything is written, a target that is not a regular file or that is read-only.
// Root could replace a read-only file; it is refused anyway, since read-only says "keep this".
void check_replaceable(const std::string& path, const Target& target) {
  if (target.base.empty() || target.base == "." || target.base == "..")
    throw IoError(path, 0, -1, "cannot write: not a file name");
  if (!target.exists) return;
  if (!S_ISREG(target.st.st_mode))
    throw IoError(path, 0, -1, "cannot write: '" + target.path + "' is " + kind_of(target.st.st_mode));
  if ((target.st.st_mode & 0222) == 0)
    throw IoError(path, 0, -1, "cannot replace '" + target.path + "': it is read-only (no write permission)");
}

// Removes the temporaries of the target left by writers that were killed: those whose process no
// longer exists. A live process's temporaries (being written now) are kept.
void remove_stale_temporaries(const Target& target) {
  DIR* folder = ::opendir(target.dir.c_str());
  if (!folder) return;  // the temporary file's creation will report it
  while (const dirent* entry = ::readdir(folder)) {
    const long pid = temporary_owner(entry->d_name, target.base);
    if (pid == 0 || pid == ::getpid()) continue;
    if (::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH)
      ::unlinkat(::dirfd(folder), entry->d_name, 0);
  }
  ::closedir(folder);
}

// The file being written: unnamed (O_TMPFILE) until it is published, or named. Unless publish()
// succeeded, the destructor removes the named file; an unnamed one vanishes when it is closed.
class Temporary {
 public:
  Temporary(int fd, std::string name) : fd_(fd), name_(std::move(name)) {}
  Temporary(const Temporary&) = delete;
  Temporary& operator=(const Temporary&) = delete;
  ~Temporary() {
    if (fd_.get() >= 0) fd_.close();
    if (!name_.empty()) ::unlink(name_.c_str());
  }
  int fd() const { return fd_.get(); }
  bool named() const { return !name_.empty(); }
  const std::string& name() const { return name_; }
  void set_name(std::string name) { name_ = std::move(name); }
  //! Closes the descriptor; returns close()'s result.
  int close() { return fd_.close(); }
  //! The file now belongs to the target: nothing to remove.
  void release() { name_.clear(); }

 private:
  Fd fd_;
  std::string name_;
};

Temporary create_named_temporary(const std::string& path, const Target& target) {
  int err = 0;
  for (int attempt = 0; attempt < 64; ++attempt) {
    std::string name = temporary_name(target.dir, target.base, ::getpid(), temporary_counter++);
    const int fd = ::open(name.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd >= 0) return Temporary(fd, std::move(name));
    err = errno;
    if (err != EEXIST) break;
  }
  throw IoError(path, 0, -1, "cannot create a temporary file in '" + target.dir + "': " + errno_text(err));
}

// An unnamed file in the target's folder where the file system has them (O_TMPFILE), else a named one.
Temporary create_temporary(const std::string& path, const Target& target) {
#ifdef O_TMPFILE
  if (!force_named_temporaries) {
    const int fd = ::open(target.dir.c_str(), O_TMPFILE | O_WRONLY | O_CLOEXEC, 0666);
    if (fd >= 0) return Temporary(fd, std::string());
    // No O_TMPFILE here: the file system lacks it (EOPNOTSUPP), or the kernel does not know the
    // flag (EISDIR, EINVAL). Any other error is the folder's, and a named file would meet it too.
    if (errno != EOPNOTSUPP && errno != EISDIR && errno != EINVAL)
      throw IoError(path, 0, -1,
                    "cannot create a temporary file in '" + target.dir + "': " + errno_text(errno));
  }
#endif
  return create_named_temporary(path, target);
}

// The replaced file's owner and group (where this process may set them) and permission bits. The
// owner goes first: changing it clears the set-user-id and set-group-id bits.
void copy_owner_and_mode(const Temporary& temp, const Target& target) {
  if (!target.exists) return;
  if (::fchown(temp.fd(), target.st.st_uid, target.st.st_gid) != 0) {
    // Only a privileged process may give a file away; others keep at least the group, when they
    // belong to it. Failing that too, the new file has this process's owner and group.
    const int group_kept = ::fchown(temp.fd(), static_cast<uid_t>(-1), target.st.st_gid);
    static_cast<void>(group_kept);
  }
  ::fchmod(temp.fd(), target.st.st_mode & 07777);
}

// Returns 0 or the errno of write().
int write_all(int fd, std::string_view bytes) {
  const char* p = bytes.data();
  std::size_t left = bytes.size();
  while (left > 0) {
    const ssize_t n = ::write(fd, p, std::min<std::size_t>(left, std::size_t{1} << 30));
    if (n < 0) {
      if (errno == EINTR) continue;
      return errno;
    }
    p += n;
    left -= static_cast<std::size_t>(n);
  }
  return 0;
}

#ifdef O_TMPFILE
// Gives the unnamed file `fd` the name `name`; returns 0 or the errno (EEXIST when it is taken).
int link_unnamed(int fd, const std::string& name) {
  const std::string self = "/proc/self/fd/" + std::to_string(fd);
  if (::linkat(AT_FDCWD, self.c_str(), AT_FDCWD, name.c_str(), AT_SYMLINK_FOLLOW) == 0) return 0;
  const int err = errno;
  if (err != ENOENT) return err;
  // No /proc: AT_EMPTY_PATH links the descriptor itself, where this process is allowed to.
  return ::linkat(fd, "", AT_FDCWD, name.c_str(), AT_EMPTY_PATH) == 0 ? 0 : err;
}
#endif

// Makes the written, flushed file the target. An unnamed file becomes the target directly when
// there is none; otherwise it gets a temporary name first, renamed over the target at once.
void publish(const std::string& path, const Target& target, Temporary& temp) {
  auto fail = [&](const std::string& what, int e) {
    throw IoError(path, 0, -1, what + ": " + errno_text(e));
  };
#ifdef O_TMPFILE
  if (!temp.named()) {
    int err = target.exists ? EEXIST : link_unnamed(temp.fd(), target.path);
    if (err == 0) {
      if (temp.close() != 0) {
        const int close_err = errno;
        ::unlink(target.path.c_str());  // the new file may lack bytes: leave nothing
        fail("write error on close", close_err);
      }
      return;
    }
    // Someone created the target meanwhile: replace it like an existing one.
    if (err != EEXIST) fail("cannot create '" + target.path + "'", err);
    for (int attempt = 0; attempt < 64 && !temp.named(); ++attempt) {
      std::string name = temporary_name(target.dir, target.base, ::getpid(), temporary_counter++);
      err = link_unnamed(temp.fd(), name);
      if (err == 0)
        temp.set_name(std::move(name));
      else if (err != EEXIST)
        break;
    }
    if (!temp.named()) fail("cannot name a temporary file in '" + target.dir + "'", err);
  }
#endif
  if (temp.close() != 0) fail("write error on close", errno);
  if (::rename(temp.name().c_str(), target.path.c_str()) != 0) fail("cannot replace the target", errno);
  temp.release();
}

}  // namespace

namespace detail {
bool force_named_temporary_files(bool on) { return force_named_temporaries.exchange(on); }
}  // namespace detail

void write_file_atomic(const std::string& path, std::string_view bytes) {
  if (path.empty() || path.back() == '/') throw IoError(path, 0, -1, "cannot write: not a file name");
  const Target target = resolve_target(path);
  check_replaceable(path, target);
  remove_stale_temporaries(target);
  Temporary temp = create_temporary(path, target);
  copy_owner_and_mode(temp, target);
  if (const int err = write_all(temp.fd(), bytes))
    throw IoError(path, 0, -1, "write error: " + errno_text(err));
  // The data must be on disk before the file takes the target's name, or a crash could leave an
  // empty file under that name.
  if (::fsync(temp.fd()) != 0 && errno != EINVAL)
    throw IoError(path, 0, -1, "cannot flush: " + errno_text(errno));
  publish(path, target, temp);
}

}  // namespace hedge

namespace hedge::detail {

std::string real_path(const std::string& path) {
  std::unique_ptr<char, decltype(&std::free)> resolved(::realpath(path.c_str(), nullptr), &std::free);
  return resolved ? std::string(resolved.get()) : std::string();
}

bool identify_regular_file(const std::string& path, FileIdentity* out) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0 || !S_ISREG(st.st_mode)) return false;
  *out = FileIdentity{static_cast<std::uint64_t>(st.st_dev), static_cast<std::uint64_t>(st.st_ino),
                      static_cast<std::uint64_t>(st.st_size)};
  return true;
}

bool read_if_unchanged(const std::string& path, const FileIdentity& expected,
                       std::vector<unsigned char>* out) {
  Fd fd(::open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NOFOLLOW));
  struct stat st {};
  if (fd.get() < 0 || ::fstat(fd.get(), &st) != 0 ||
      static_cast<std::uint64_t>(st.st_dev) != expected.device ||
      static_cast<std::uint64_t>(st.st_ino) != expected.number ||
      static_cast<std::uint64_t>(st.st_size) != expected.size)
    return false;
  out->resize(static_cast<std::size_t>(expected.size));
  std::size_t used = 0;
  while (used < out->size()) {
    const ssize_t n = ::read(fd.get(), out->data() + used, out->size() - used);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    used += static_cast<std::size_t>(n);
  }
  return true;
}

}  // namespace hedge::detail

#endif  // !_WIN32
