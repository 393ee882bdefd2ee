// What a glTF must pass before tinygltf sees it. tinygltf trusts its input: it recurses once per
// level of JSON nesting, allocates a model whatever its size, and opens any path a buffer names.
// So the JSON is scanned first, in one pass that allocates nothing per value (a SAX parse): its
// depth, its indices and offsets that are negative, fractional or too large for tinygltf, an estimate of what
// parsing it will allocate, and its buffers; and the only files tinygltf may then open are the external
// buffers this guard approved.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "file_system.h"
#include "hedge/io/io.h"

namespace hedge::detail {

//! A buffer of the glTF, as its JSON declares it.
struct GltfBufferDecl {
  std::size_t index = 0;  //!< in the file's buffers
  std::string uri;        //!< an external file's uri; data URIs are checked by the scan and not kept
  bool data_uri = false;
  std::uint64_t byte_length = 0;
};

//! What scan_gltf() learned.
struct GltfScan {
  std::string_view json;  //!< the JSON text: the whole data, or a GLB's JSON chunk
  bool binary = false;
  //! Bytes that parsing the JSON into tinygltf's model is estimated to allocate, at most.
  std::uint64_t parse_cost = 0;
  std::vector<GltfBufferDecl> buffers;  //!< those with a uri
};

//! Frames a GLB and scans the JSON. \throw IoError for malformed JSON or GLB framing, nesting
//! deeper than kMaxJsonDepth, an index, offset, count or mode that is negative, not written as a
//! whole number or (but for a byte offset, length or stride or a count) above 2^31 - 1, or a data
//! URI that is not base64 application/octet-stream or application/gltf-buffer or whose size is not
//! its byteLength.
//! O(data size) time; allocates O(depth) plus the buffers' declarations.
GltfScan scan_gltf(std::string_view data, const std::string& name);

//! The message of a file refused for its memory: `what` asks for about `cost` bytes, over `budget`.
std::string over_budget(const std::string& what, double cost, std::uint64_t budget);

//! The external buffer files tinygltf may read: each one approved by the ReadOptions policy,
//! resolved to a regular file inside the folder of the .gltf and of the declared size. tinygltf's
//! file callbacks answer from this table only, so no other path can be opened.
class GltfBufferFiles {
 public:
  //! Checks every external buffer of `scan`. \throw IoError naming the buffer when one is refused.
  GltfBufferFiles(const GltfScan& scan, const std::string& name, const ReadOptions& options);

  //! The folder tinygltf joins buffer uris to (the folder of `name`).
  const std::string& base_dir() const { return base_dir_; }
  //! The approved files' bytes, in all.
  std::uint64_t bytes() const { return bytes_; }

  //! tinygltf's callbacks (user data: this object).
  static bool exists(const std::string& path, void* self);
  static std::string expand(const std::string& path, void* self);
  static bool read(std::vector<unsigned char>* out, std::string* err, const std::string& path, void* self);

 private:
  struct File {
    std::string real_path;
    FileIdentity id;
  };
  std::string base_dir_;
  std::unordered_map<std::string, File> files_;  // by the path tinygltf will ask for
  std::uint64_t bytes_ = 0;
};

}  // namespace hedge::detail
