// Reading and atomic writing of files on Windows: read_file(), write_file_atomic() and the file
// identities of file_system.h, over the wide-character Win32 API. Paths are UTF-8, as everywhere in
// hedge, and are converted to UTF-16, so that any file name Windows allows can be read and written.
// file_posix.cpp is the POSIX one.
#ifdef _WIN32

#ifndef NOMINMAX
#define NOMINMAX
#endif
#include <windows.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "file_system.h"
#include "hedge/io/io.h"

namespace hedge {

namespace {

using detail::temporary_name;
using detail::temporary_owner;

// Closes a handle on every exit path.
class WinHandle {
 public:
  explicit WinHandle(HANDLE h) : h_(h) {}
  WinHandle(const WinHandle&) = delete;
  WinHandle& operator=(const WinHandle&) = delete;
  ~WinHandle() { close(); }
  HANDLE get() const { return h_; }
  bool valid() const { return h_ != INVALID_HANDLE_VALUE && h_ != nullptr; }
  //! Closes now; false when CloseHandle() failed.
  bool close() {
    const bool ok = !valid() || CloseHandle(h_) != 0;
    h_ = INVALID_HANDLE_VALUE;
    return ok;
  }

 private:
  HANDLE h_;
};

// The text of a Win32 error. The common ones read as the C library's strerror() of the same errno
// does on every platform ("No such file or directory", ...), so that messages are the same on
// Windows as elsewhere; any other is Windows' own text with its number.
std::string error_text(DWORD err) {
  switch (err) {
    case ERROR_FILE_NOT_FOUND:
    case ERROR_PATH_NOT_FOUND:
    case ERROR_INVALID_DRIVE:
      return std::strerror(ENOENT);
    case ERROR_ACCESS_DENIED:
    case ERROR_SHARING_VIOLATION:
    case ERROR_LOCK_VIOLATION:
      return std::strerror(EACCES);
    case ERROR_FILE_EXISTS:
    case ERROR_ALREADY_EXISTS:
      return std::strerror(EEXIST);
    case ERROR_DISK_FULL:
    case ERROR_HANDLE_DISK_FULL:
      return std::strerror(ENOSPC);
    case ERROR_INVALID_NAME:
    case ERROR_BAD_PATHNAME:
      return std::strerror(EINVAL);
    default:
      break;
  }
  char* text = nullptr;
  const DWORD n = FormatMessageA(
      FORMAT_MESSAGE_ALLOCATE_BUFFER | FORMAT_MESSAGE_FROM_SYSTEM | FORMAT_MESSAGE_IGNORE_INSERTS, nullptr,
      err, 0, reinterpret_cast<char*>(&text), 0, nullptr);
  std::string s = n > 0 && text ? std::string(text, n) : std::string();
  if (text) LocalFree(text);
  while (!s.empty() && (s.back() == '\n' || s.back() == '\r' || s.back() == ' ' || s.back() == '.'))
    s.pop_back();
  return (s.empty() ? std::string("Windows error") : s) + " (error " + std::to_string(err) + ")";
}

// UTF-8 to UTF-16; throws for a path that is not UTF-8 or holds a NUL.
std::wstring wide(const std::string& path) {
  if (path.find('\0') != std::string::npos)
    throw IoError(path, 0, -1, "cannot use the path: it holds a NUL byte");
  if (path.empty()) return std::wstring();
  const int n = MultiByteToWideChar(CP_UTF8, MB_ERR_INVALID_CHARS, path.data(), static_cast<int>(path.size()),
                                    nullptr, 0);
  if (n <= 0) throw IoError(path, 0, -1, "cannot use the path: it is not UTF-8");
  std::wstring w(static_cast<std::size_t>(n), L'\0');
  MultiByteToWideChar(CP_UTF8, MB_ERR_INVALID_CHARS, path.data(), static_cast<int>(path.size()), w.data(), n);
  return w;
}

std::string narrow(const std::wstring& w) {
  if (w.empty()) return std::string();
  const int n =
      WideCharToMultiByte(CP_UTF8, 0, w.data(), static_cast<int>(w.size()), nullptr, 0, nullptr, nullptr);
  std::string s(static_cast<std::size_t>(n > 0 ? n : 0), '\0');
  if (n > 0)
    WideCharToMultiByte(CP_UTF8, 0, w.data(), static_cast<int>(w.size()), s.data(), n, nullptr, nullptr);
  return s;
}

constexpr DWORD kShareAll = FILE_SHARE_READ | FILE_SHARE_WRITE | FILE_SHARE_DELETE;

// The folder of a path with its separator ("./" for a bare name) and the file's name.
std::pair<std::string, std::string> split_path(const std::string& path) {
  const std::size_t slash = path.find_last_of(detail::kPathSeparators);
  if (slash == std::string::npos) return {"./", path};
  return {path.substr(0, slash + 1), path.substr(slash + 1)};
}

// Removes the temporaries of `base` in `dir` left by writers that were killed: those whose process
// no longer exists. A live process's temporaries (being written now) are kept.
void remove_stale_temporaries(const std::string& dir, const std::string& base) {
  WIN32_FIND_DATAW found;
  const HANDLE search =
      FindFirstFileW(wide(dir + "." + base + std::string(detail::temporary_tag) + "*").c_str(), &found);
  if (search == INVALID_HANDLE_VALUE) return;
  do {
    const std::string name = narrow(found.cFileName);
    const long pid = temporary_owner(name, base);
    if (pid == 0 || static_cast<DWORD>(pid) == GetCurrentProcessId()) continue;
    const HANDLE process = OpenProcess(PROCESS_QUERY_LIMITED_INFORMATION, FALSE, static_cast<DWORD>(pid));
    if (process) {
      CloseHandle(process);
    } else if (GetLastError() == ERROR_INVALID_PARAMETER) {  // no such process
      DeleteFileW(wide(dir + name).c_str());
    }
  } while (FindNextFileW(search, &found));
  FindClose(search);
}

std::atomic<unsigned> temporary_counter{0};

// Writes `bytes` to the new file `name`, flushed to the disk; returns 0 or the Win32 error. On an
// error the file is removed again.
DWORD write_temporary(const std::string& name, std::string_view bytes) {
  WinHandle file(
      CreateFileW(wide(name).c_str(), GENERIC_WRITE, 0, nullptr, CREATE_NEW, FILE_ATTRIBUTE_NORMAL, nullptr));
  if (!file.valid()) return GetLastError();
  DWORD err = 0;
  const char* p = bytes.data();
  std::size_t left = bytes.size();
  while (left > 0 && err == 0) {
    const DWORD chunk = static_cast<DWORD>(std::min<std::size_t>(left, std::size_t{1} << 30));
    DWORD written = 0;
    if (!WriteFile(file.get(), p, chunk, &written, nullptr) || written == 0) {
      err = GetLastError();
      break;
    }
    p += written;
    left -= written;
  }
  // The data must be on disk before the file takes the target's name, or a crash could leave an
  // empty file under that name.
  if (err == 0 && !FlushFileBuffers(file.get())) err = GetLastError();
  if (!file.close() && err == 0) err = GetLastError();
  if (err != 0) DeleteFileW(wide(name).c_str());
  return err;
}

}  // namespace

namespace detail {
// Windows has no unnamed temporary files: every temporary is named already.
bool force_named_temporary_files(bool) { return true; }
}  // namespace detail

std::string read_file(const std::string& path) {
  const std::wstring w = wide(path);
  const DWORD attributes = GetFileAttributesW(w.c_str());
  if (attributes != INVALID_FILE_ATTRIBUTES && (attributes & FILE_ATTRIBUTE_DIRECTORY))
    throw IoError(path, 0, -1, "cannot read: it is a directory");
  WinHandle file(CreateFileW(w.c_str(), GENERIC_READ, kShareAll, nullptr, OPEN_EXISTING,
                             FILE_ATTRIBUTE_NORMAL, nullptr));
  if (!file.valid()) throw IoError(path, 0, -1, "cannot open: " + error_text(GetLastError()));
  // A device (CON, a serial port) is no mesh and may never end: as on POSIX, only files and pipes.
  if (GetFileType(file.get()) == FILE_TYPE_CHAR)
    throw IoError(path, 0, -1, "cannot read: it is a character device, not a file");
  // The size is only a hint (a file may grow): read until end of file.
  LARGE_INTEGER size{};
  std::string data;
  data.resize(GetFileSizeEx(file.get(), &size) && size.QuadPart > 0
                  ? static_cast<std::size_t>(size.QuadPart) + 1
                  : 65536);
  std::size_t used = 0;
  for (;;) {
    if (used == data.size()) data.resize(2 * data.size());
    const DWORD want = static_cast<DWORD>(std::min<std::size_t>(data.size() - used, std::size_t{1} << 30));
    DWORD n = 0;
    if (!ReadFile(file.get(), data.data() + used, want, &n, nullptr))
      throw IoError(path, 0, static_cast<std::int64_t>(used), "read error: " + error_text(GetLastError()));
    if (n == 0) break;
    used += n;
  }
  data.resize(used);
  return data;
}

// The file is written under a temporary name in the target's folder, flushed, then renamed over
// the target in one step (MoveFileExW with MOVEFILE_REPLACE_EXISTING): a reader sees the old file
// or the new one, never a part. A target that is a directory or read-only is refused before
// anything is written. Unlike on POSIX systems, a symbolic link as the target is replaced itself.
void write_file_atomic(const std::string& path, std::string_view bytes) {
  if (path.empty() || std::string_view(detail::kPathSeparators).find(path.back()) != std::string_view::npos)
    throw IoError(path, 0, -1, "cannot write: not a file name");
  const auto [dir, base] = split_path(path);
  if (base == "." || base == "..") throw IoError(path, 0, -1, "cannot write: not a file name");
  const std::wstring target = wide(path);
  const DWORD attributes = GetFileAttributesW(target.c_str());
  if (attributes != INVALID_FILE_ATTRIBUTES) {
    if (attributes & FILE_ATTRIBUTE_DIRECTORY)
      throw IoError(path, 0, -1, "cannot write: '" + path + "' is a directory");
    if (attributes & FILE_ATTRIBUTE_READONLY)
      throw IoError(path, 0, -1, "cannot replace '" + path + "': it is read-only (no write permission)");
  }
  remove_stale_temporaries(dir, base);
  std::string temp;
  DWORD err = ERROR_FILE_EXISTS;
  for (int attempt = 0; attempt < 64 && err == ERROR_FILE_EXISTS; ++attempt) {
    temp = temporary_name(dir, base, static_cast<long>(GetCurrentProcessId()), temporary_counter++);
    err = write_temporary(temp, bytes);
  }
  if (err != 0) {
    const std::string what =
        err == ERROR_FILE_EXISTS || err == ERROR_PATH_NOT_FOUND || err == ERROR_ACCESS_DENIED
            ? "cannot create a temporary file in '" + dir + "': "
            : "write error: ";
    throw IoError(path, 0, -1, what + error_text(err));
  }
  if (!MoveFileExW(wide(temp).c_str(), target.c_str(), MOVEFILE_REPLACE_EXISTING | MOVEFILE_WRITE_THROUGH)) {
    err = GetLastError();
    DeleteFileW(wide(temp).c_str());
    throw IoError(path, 0, -1, "cannot replace the target: " + error_text(err));
  }
}

namespace detail {

std::string real_path(const std::string& path) {
  // Opening the folder or file (FILE_FLAG_BACKUP_SEMANTICS opens folders too) and asking for its
  // final path resolves `..` and every link.
  WinHandle h(CreateFileW(wide(path).c_str(), 0, kShareAll, nullptr, OPEN_EXISTING,
                          FILE_FLAG_BACKUP_SEMANTICS, nullptr));
  if (!h.valid()) {
    errno = GetLastError() == ERROR_ACCESS_DENIED ? EACCES : ENOENT;
    return std::string();
  }
  std::wstring w(MAX_PATH, L'\0');
  for (;;) {
    const DWORD n =
        GetFinalPathNameByHandleW(h.get(), w.data(), static_cast<DWORD>(w.size()), FILE_NAME_NORMALIZED);
    if (n == 0) {
      errno = ENOENT;
      return std::string();
    }
    if (n < w.size()) {
      w.resize(n);
      break;
    }
    w.resize(n + 1);
  }
  std::string s = narrow(w);
  // "\\?\C:\folder" -> "C:/folder"; "\\?\UNC\server\share" -> "//server/share".
  if (s.rfind("\\\\?\\UNC\\", 0) == 0)
    s = "\\\\" + s.substr(8);
  else if (s.rfind("\\\\?\\", 0) == 0)
    s = s.substr(4);
  std::replace(s.begin(), s.end(), '\\', '/');
  return s;
}

namespace {

bool identity_of(HANDLE h, FileIdentity* out) {
  BY_HANDLE_FILE_INFORMATION info;
  if (!GetFileInformationByHandle(h, &info) || (info.dwFileAttributes & FILE_ATTRIBUTE_DIRECTORY))
    return false;
  *out = FileIdentity{info.dwVolumeSerialNumber,
                      (static_cast<std::uint64_t>(info.nFileIndexHigh) << 32) | info.nFileIndexLow,
                      (static_cast<std::uint64_t>(info.nFileSizeHigh) << 32) | info.nFileSizeLow};
  return true;
}

}  // namespace

bool identify_regular_file(const std::string& path, FileIdentity* out) {
  WinHandle h(CreateFileW(wide(path).c_str(), 0, kShareAll, nullptr, OPEN_EXISTING,
                          FILE_FLAG_BACKUP_SEMANTICS, nullptr));
  return h.valid() && identity_of(h.get(), out);
}

bool read_if_unchanged(const std::string& path, const FileIdentity& expected,
                       std::vector<unsigned char>* out) {
  // FILE_FLAG_OPEN_REPARSE_POINT: a link put in the file's place is opened itself, not followed,
  // and then is not the file that was checked.
  WinHandle h(CreateFileW(wide(path).c_str(), GENERIC_READ, kShareAll, nullptr, OPEN_EXISTING,
                          FILE_ATTRIBUTE_NORMAL | FILE_FLAG_OPEN_REPARSE_POINT, nullptr));
  FileIdentity now;
  if (!h.valid() || !identity_of(h.get(), &now) || now.device != expected.device ||
      now.number != expected.number || now.size != expected.size)
    return false;
  out->resize(static_cast<std::size_t>(expected.size));
  std::size_t used = 0;
  while (used < out->size()) {
    const DWORD want = static_cast<DWORD>(std::min<std::size_t>(out->size() - used, std::size_t{1} << 30));
    DWORD n = 0;
    if (!ReadFile(h.get(), out->data() + used, want, &n, nullptr) || n == 0) return false;
    used += n;
  }
  return true;
}

}  // namespace detail

}  // namespace hedge

#endif  // _WIN32
