// The checks a glTF passes before tinygltf parses it (see gltf_guard.h).

#include "gltf_guard.h"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "file_system.h"
#include "hedge/error.h"

namespace hedge::detail {

namespace {

std::string str(std::uint64_t v) { return std::to_string(v); }

// --- the JSON scan -------------------------------------------------------------------------------

// Upper bounds of what tinygltf allocates, per JSON element, for its JSON tree and the model it
// fills from it (measured on tinygltf 2.7 with nlohmann-json 3.11: an object of the model costs
// 300 to 600 bytes, a value of an `extras` tree about 250). Strings are counted twice (tree and
// model).
constexpr std::uint64_t kCostPerObject = 768;
constexpr std::uint64_t kCostPerArray = 128;
constexpr std::uint64_t kCostPerValue = 320;

// The largest index, enum or sparse offset or count a glTF may hold: tinygltf keeps them as int.
constexpr std::uint64_t kMaxGltfIndex = 2147483647;

// glTF properties whose values are indices, offsets, counts or enums: none may be negative.
bool is_unsigned_property(std::string_view key) {
  static constexpr std::string_view kKeys[] = {
      "bufferView", "byteOffset", "byteLength", "byteStride", "componentType", "count",  "indices", "mode",
      "material",   "buffer",     "mesh",       "camera",     "skin",          "node",   "sampler", "source",
      "texCoord",   "index",      "scene",      "skeleton",   "input",         "output", "target"};
  for (std::string_view k : kKeys)
    if (k == key) return true;
  return false;
}

// Arrays of indices (a node's children, a scene's root nodes, a skin's joints).
bool is_index_array(std::string_view key) { return key == "children" || key == "nodes" || key == "joints"; }

// "accessors" -> "accessor": the top-level arrays and a mesh's primitives are named in messages as
// the reader names them ("mesh 0 primitive 1").
std::string_view singular(std::string_view key, std::size_t depth) {
  static constexpr std::pair<std::string_view, std::string_view> kTop[] = {
      {"accessors", "accessor"},  {"bufferViews", "bufferView"},
      {"buffers", "buffer"},      {"meshes", "mesh"},
      {"nodes", "node"},          {"scenes", "scene"},
      {"materials", "material"},  {"textures", "texture"},
      {"images", "image"},        {"samplers", "sampler"},
      {"skins", "skin"},          {"cameras", "camera"},
      {"animations", "animation"}};
  if (depth == 0) {
    for (const auto& [plural, one] : kTop)
      if (plural == key) return one;
  }
  if (key == "primitives") return "primitive";
  return {};
}

constexpr std::string_view kDataPrefixes[] = {"data:application/octet-stream;base64,",
                                              "data:application/gltf-buffer;base64,"};

bool starts_with_ignoring_case(std::string_view s, std::string_view prefix) {
  if (s.size() < prefix.size()) return false;
  for (std::size_t i = 0; i < prefix.size(); ++i) {
    char c = s[i];
    if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
    if (c != prefix[i]) return false;
  }
  return true;
}

// The size of what a base64 text decodes to, or -1 when it is not base64.
std::int64_t base64_size(std::string_view text) {
  std::size_t n = text.size();
  std::size_t padding = 0;
  while (n > 0 && text[n - 1] == '=' && padding < 2) --n, ++padding;
  for (std::size_t i = 0; i < n; ++i) {
    const char c = text[i];
    const bool ok =
        (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '+' || c == '/';
    if (!ok) return -1;
  }
  if ((n + padding) % 4 == 1 || (padding > 0 && (n + padding) % 4 != 0)) return -1;
  return static_cast<std::int64_t>(n * 3 / 4);
}

// A SAX handler: nlohmann's parser is iterative, so a deep file costs this handler a frame per
// level, and the scan stops at kMaxJsonDepth.
class Scanner {
 public:
  Scanner(const std::string& name, GltfScan& scan) : name_(name), scan_(scan) {}

  bool null() { return value(); }
  bool boolean(bool) { return value(); }
  bool number_integer(std::int64_t v) {
    if (v < 0) refuse(std::to_string(v), "it must be 0 or more");
    return value();
  }
  bool number_unsigned(std::uint64_t v) {
    if (in_buffer() && key_is("byteLength")) buffer_.byte_length = v;
    if (v > kMaxGltfIndex && !is_size())
      refuse(std::to_string(v), "it must be at most " + str(kMaxGltfIndex));
    return value();
  }
  bool number_float(double v, const std::string& text) {
    refuse(text, v < 0 ? "it must be 0 or more"
                       : "it must be a whole number, written without a point or an exponent");
    return value();
  }
  bool string(std::string& s) {
    cost_ += 2 * s.size();
    if (in_buffer() && key_is("uri")) buffer_uri(s);
    return value();
  }
  bool binary(nlohmann::json::binary_t&) { return value(); }
  bool start_object(std::size_t) {
    open(false);
    cost_ += kCostPerObject;
    if (in_buffer()) {
      buffer_ = GltfBufferDecl{buffer_index(), {}, false, 0};
      data_size_ = 0;
    }
    return true;
  }
  bool end_object() {
    if (in_buffer()) end_buffer();
    return close();
  }
  bool start_array(std::size_t) {
    open(true);
    if (frames_.size() == 2 && path_is_buffer())
      scan_.buffers.clear();  // a repeated key: the last one counts
    cost_ += kCostPerArray;
    return true;
  }
  bool end_array() { return close(); }
  bool key(std::string& k) {
    frames_.back().key = k;
    cost_ += 2 * k.size();
    return true;
  }
  bool parse_error(std::size_t, const std::string&, const nlohmann::json::exception& e) {
    // nlohmann's message names the line, the column and what it expected; its exception id is
    // left out.
    std::string what = e.what();
    if (const std::size_t close = what.find("] ");
        what.rfind("[json.exception", 0) == 0 && close != std::string::npos)
      what = what.substr(close + 2);
    throw IoError(name_, 0, -1, "malformed glTF JSON: " + what);
  }

  std::uint64_t cost() const { return cost_; }

 private:
  struct Frame {
    bool array = false;
    bool opaque = false;   // inside extras or extensions: anything goes
    std::size_t next = 0;  // arrays: the number of elements seen
    std::string key;       // objects: the current member
  };

  // Every value, and every nested container, takes the next slot of an enclosing array.
  void place() {
    if (!frames_.empty() && frames_.back().array) ++frames_.back().next;
  }
  bool value() {
    place();
    cost_ += kCostPerValue;
    return true;
  }
  void open(bool array) {
    if (static_cast<int>(frames_.size()) >= kMaxJsonDepth)
      throw IoError(name_, 0, -1,
                    "malformed glTF: JSON nested deeper than " + std::to_string(kMaxJsonDepth) + " levels (" +
                        where() + ")");
    const bool opaque =
        !frames_.empty() &&
        (frames_.back().opaque ||
         (!frames_.back().array && (frames_.back().key == "extras" || frames_.back().key == "extensions")));
    place();
    frames_.push_back({array, opaque, 0, {}});
  }
  bool close() {
    frames_.pop_back();
    return true;
  }

  bool key_is(std::string_view k) const {
    return !frames_.empty() && !frames_.back().array && frames_.back().key == k;
  }
  // The current value is a member of buffers[i] (frames: root, buffers array, buffer object).
  bool path_is_buffer() const {
    return frames_.size() >= 2 && !frames_[0].array && frames_[0].key == "buffers" && frames_[1].array;
  }
  bool in_buffer() const { return frames_.size() == 3 && path_is_buffer() && !frames_[2].array; }
  std::size_t buffer_index() const { return frames_[1].next - 1; }

  void buffer_uri(const std::string& uri) {
    GltfBufferDecl& b = buffer_;
    b.data_uri = false;
    if (!starts_with_ignoring_case(uri, "data:")) {
      b.uri = uri;
      return;
    }
    const std::string at = "buffer " + str(b.index) + ": ";
    for (std::string_view prefix : kDataPrefixes)
      if (uri.compare(0, prefix.size(), prefix) == 0) {
        const std::int64_t size = base64_size(std::string_view(uri).substr(prefix.size()));
        if (size < 0) throw IoError(name_, 0, -1, at + "the data URI's payload is not base64");
        b.data_uri = true;
        b.uri.clear();
        data_size_ = static_cast<std::uint64_t>(size);  // checked against byteLength at the object's end
        return;
      }
    throw IoError(name_, 0, -1,
                  at + "a data URI must be base64 application/octet-stream or application/gltf-buffer (got " +
                      quote_prefix(uri) + ")");
  }

  static std::string quote_prefix(std::string_view uri) {
    const std::size_t comma = uri.find(',');
    std::string head(
        uri.substr(0, std::min<std::size_t>(comma == std::string_view::npos ? uri.size() : comma, 48)));
    for (char& c : head)
      if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7f) c = '?';
    return "'" + head + ",...'";
  }

  // True when the current value is an index, offset, count or enum (see is_unsigned_property).
  bool is_checked() const {
    if (frames_.empty() || frames_.back().opaque) return false;
    const Frame& f = frames_.back();
    return f.array ? frames_.size() >= 2 && is_index_array(frames_[frames_.size() - 2].key)
                   : is_unsigned_property(f.key) ||
                         (frames_.size() >= 2 && frames_[frames_.size() - 2].key == "attributes");
  }

  // True for a byte offset, length or stride or an element count that tinygltf keeps in 64 bits:
  // those outside an accessor's `sparse` object. It keeps every other checked value in 32 signed
  // bits, which would wrap a larger one into another, valid looking index.
  bool is_size() const {
    if (frames_.empty()) return false;  // a bare number as the whole document
    const Frame& f = frames_.back();
    if (f.array ||
        !(f.key == "byteOffset" || f.key == "byteLength" || f.key == "byteStride" || f.key == "count"))
      return false;
    for (const Frame& outer : frames_)
      if (!outer.array && outer.key == "sparse") return false;
    return true;
  }

  // Refuses a checked value: negative, not a whole number (tinygltf would take it for a missing
  // property and silently use the default), or too large for tinygltf to keep.
  void refuse(const std::string& text, const std::string& why) {
    if (is_checked()) throw IoError(name_, 0, -1, where() + " is " + text + "; " + why);
  }

  // The index the current value (or container being opened) takes in array frame j.
  std::size_t index_in(std::size_t j) const { return frames_[j].next - (j + 1 == frames_.size() ? 0 : 1); }

  // The path of the current value: "mesh 0 primitive 1: indices", "accessor 2: sparse.count".
  std::string where() const {
    std::string elements, members;
    for (std::size_t i = 0; i < frames_.size(); ++i) {
      const Frame& f = frames_[i];
      if (f.array) {
        if (i == 0 || frames_[i - 1].array) members += "[" + str(index_in(i)) + "]";
        continue;
      }
      const bool indexed = i + 1 < frames_.size() && frames_[i + 1].array;
      const std::string_view one = indexed && members.empty() ? singular(f.key, i) : std::string_view();
      if (!one.empty()) {
        elements += (elements.empty() ? "" : " ") + std::string(one) + " " + str(index_in(i + 1));
        continue;
      }
      if (f.key.empty()) continue;
      members += (members.empty() ? "" : ".") + f.key;
      if (indexed) members += "[" + str(index_in(i + 1)) + "]";
    }
    if (members.size() > 60) members = members.substr(0, 60) + "...";
    if (elements.empty()) return members.empty() ? "the top level" : members;
    return members.empty() ? elements : elements + ": " + members;
  }

  // Only buffers with a uri are kept (a GLB's own buffer has none), so that what the scan keeps
  // is no larger than the uris the file spells out.
  void end_buffer() {
    const GltfBufferDecl& b = buffer_;
    if (b.data_uri && data_size_ != b.byte_length)
      throw IoError(name_, 0, -1,
                    "buffer " + str(b.index) + ": its data URI holds " + str(data_size_) +
                        " bytes, but its byteLength is " + str(b.byte_length));
    if (b.data_uri || !b.uri.empty()) scan_.buffers.push_back(b);
  }

  const std::string& name_;
  GltfScan& scan_;
  std::vector<Frame> frames_;
  GltfBufferDecl buffer_;  // the buffer being scanned
  std::uint64_t data_size_ = 0;
  std::uint64_t cost_ = 0;
};

std::uint32_t le32(const char* p) {
  const auto* b = reinterpret_cast<const unsigned char*>(p);
  return static_cast<std::uint32_t>(b[0]) | static_cast<std::uint32_t>(b[1]) << 8 |
         static_cast<std::uint32_t>(b[2]) << 16 | static_cast<std::uint32_t>(b[3]) << 24;
}

// --- the GLB container ---------------------------------------------------------------------------

// A GLB is a 12-byte header (magic, version, total length) and chunks, each an 8-byte header
// (data length, type) and its data: JSON first, then BIN unless the JSON chunk ends the file. Every
// length is checked against the file and against the declared total before tinygltf sees the
// bytes, so that a truncated or inconsistent file says where it goes wrong: which chunk, its
// declared length and where it would end, and the declared against the actual file length.
// Returns the JSON chunk's text.
std::string_view frame_glb(std::string_view data, const std::string& name) {
  const std::uint64_t size = data.size();
  auto fail = [&](std::uint64_t at, const std::string& why) {
    throw IoError(name, 0, static_cast<std::int64_t>(at), "malformed glTF binary: " + why);
  };
  if (size < 12)
    fail(size, "truncated: the file ends at byte " + str(size) + ", inside the 12-byte GLB header");
  const std::uint64_t version = le32(data.data() + 4);
  if (version != 2) fail(4, "version " + str(version) + ", expected 2");
  const std::uint64_t declared = le32(data.data() + 8);
  const std::string lengths = "the header declares " + str(declared) + " bytes, the file has " + str(size);
  // A chunk of `length` bytes of data whose 8-byte header is at byte `at`, named `what`.
  auto check_chunk = [&](std::uint64_t at, const char* what, std::uint32_t type, const char* type_name) {
    if (at + 8 > size)
      fail(size, "truncated: the file ends at byte " + str(size) + ", inside the " + what +
                     " chunk's 8-byte header at byte " + str(at) + " (" + lengths + ")");
    if (at + 8 > declared)
      fail(8, "the header declares " + str(declared) + " bytes, too few for the " + what +
                  " chunk's 8-byte header at byte " + str(at));
    if (le32(data.data() + at + 4) != type)
      fail(at + 4, std::string("the chunk at byte ") + str(at) + " is not " + type_name);
    const std::uint64_t length = le32(data.data() + at);
    if (length == 0) fail(at, std::string("the ") + what + " chunk at byte " + str(at) + " is empty");
    const std::uint64_t end = at + 8 + length;
    const std::string chunk = std::string("the ") + what + " chunk at byte " + str(at) + " declares " +
                              str(length) + " bytes of data, to end at byte " + str(end);
    if (end > size) fail(at, "truncated: " + chunk + ", past the end of the file (" + lengths + ")");
    if (end > declared) fail(at, chunk + ", past the " + str(declared) + " bytes the header declares");
    return end;
  };
  const std::uint64_t json_end = check_chunk(12, "JSON", 0x4E4F534Au, "JSON");
  // tinygltf's rule: a BIN chunk follows unless the declared total ends with the JSON chunk.
  if (declared > json_end) check_chunk(json_end, "BIN", 0x004E4942u, "BIN");
  if (declared > size) fail(8, "truncated: " + lengths);
  return data.substr(20, static_cast<std::size_t>(json_end - 20));
}

// --- external buffers ----------------------------------------------------------------------------

// The folder part of a path, with its slash ("" for a bare name).
std::string folder_of(const std::string& path) {
  const std::size_t slash = path.find_last_of(kPathSeparators);
  return slash == std::string::npos ? std::string() : path.substr(0, slash + 1);
}

// The path tinygltf asks for: its JoinPath of the base folder and its URL-decoding of the uri.
std::string tinygltf_path(const std::string& base_dir, const std::string& decoded_for_tinygltf) {
  if (base_dir.empty()) return decoded_for_tinygltf;
  return base_dir + (base_dir.back() == '/' ? "" : "/") + decoded_for_tinygltf;
}

int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

// Percent-decodes a uri. `plus_is_space` mirrors tinygltf's decoding (form encoding), which is how
// it will spell the path it asks for; the file opened is the RFC 3986 reading, where '+' is '+'.
// Returns false for a malformed escape or a decoded NUL.
bool percent_decode(const std::string& uri, bool plus_is_space, std::string* out) {
  out->clear();
  for (std::size_t i = 0; i < uri.size(); ++i) {
    char c = uri[i];
    if (c == '%') {
      if (i + 2 >= uri.size()) return false;
      const int hi = hex_digit(uri[i + 1]), lo = hex_digit(uri[i + 2]);
      if (hi < 0 || lo < 0) return false;
      c = static_cast<char>(hi * 16 + lo);
      i += 2;
    } else if (c == '+' && plus_is_space) {
      c = ' ';
    }
    if (c == '\0') return false;
    *out += c;
  }
  return true;
}

bool has_scheme(const std::string& uri) {
  std::size_t i = 0;
  if (uri.empty() || !((uri[0] >= 'a' && uri[0] <= 'z') || (uri[0] >= 'A' && uri[0] <= 'Z'))) return false;
  for (i = 1; i < uri.size(); ++i) {
    const char c = uri[i];
    if (c == ':') return true;
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '+' ||
                    c == '-' || c == '.';
    if (!ok) return false;
  }
  return false;
}

}  // namespace

std::string over_budget(const std::string& what, double cost, std::uint64_t budget) {
  return what + " would take about " + bytes_text(cost) + " of memory, more than the read budget of " +
         bytes_text(static_cast<double>(budget)) +
         " (by default 64 times the input's size plus 64 MiB); if you trust the file, raise the budget: "
         "max_memory in the read options (hedge: --max-memory)";
}

GltfScan scan_gltf(std::string_view data, const std::string& name) {
  GltfScan scan;
  scan.json = data;
  if (data.size() >= 4 && data.substr(0, 4) == "glTF") {
    scan.binary = true;
    scan.json = frame_glb(data, name);
  }
  Scanner scanner(name, scan);
  const char* first = scan.json.data();
  if (!nlohmann::json::sax_parse(first, first + scan.json.size(), &scanner))
    throw IoError(name, 0, -1, "malformed glTF JSON");
  scan.parse_cost = scanner.cost();
  return scan;
}

GltfBufferFiles::GltfBufferFiles(const GltfScan& scan, const std::string& name, const ReadOptions& options)
    : base_dir_(folder_of(name)) {
  std::string root;
  for (const GltfBufferDecl& b : scan.buffers) {
    if (b.data_uri || b.uri.empty()) continue;
    const std::string at = "buffer " + str(b.index) + ": ";
    if (!options.external_buffers)
      throw IoError(name, 0, -1,
                    at + "its data is in a separate file ('uri'), and reading external buffers is turned off "
                         "(bytes read from memory; embed the buffer, or read the .gltf from its folder)");
    if (has_scheme(b.uri))
      throw IoError(name, 0, -1, at + "uri has a scheme; only data URIs and relative file paths are read");
    std::string for_tinygltf, relative;
    if (!percent_decode(b.uri, true, &for_tinygltf) || !percent_decode(b.uri, false, &relative))
      throw IoError(name, 0, -1, at + "uri has a malformed %-escape or an escaped NUL");
    if (relative.empty() || relative[0] == '/' || relative[0] == '\\')
      throw IoError(name, 0, -1,
                    at + "uri is an absolute path; external buffers are read only from the .gltf's folder");
    if (root.empty()) {
      root = real_path(base_dir_.empty() ? std::string(".") : base_dir_);
      if (root.empty())
        throw IoError(name, 0, -1, at + "cannot resolve the folder of the .gltf: " + std::strerror(errno));
    }
    // Resolved with `..` and every symbolic link followed: what is opened is what was checked.
    // A path outside, missing or not a regular file gets one message, so that the answer tells
    // nothing of what exists outside the folder.
    const std::string resolved = real_path(root + "/" + relative);
    const std::string inside = root == "/" ? root : root + "/";
    FileIdentity id;
    if (resolved.empty() || resolved.compare(0, inside.size(), inside) != 0 ||
        !identify_regular_file(resolved, &id))
      throw IoError(name, 0, -1,
                    at + "uri '" + b.uri +
                        "' does not name a regular file inside the .gltf's folder (external buffers are read "
                        "only from there and below)");
    if (id.size != b.byte_length)
      throw IoError(
          name, 0, -1,
          at + "file '" + b.uri + "' is not the buffer's byteLength of " + str(b.byte_length) + " bytes");
    const std::string key = tinygltf_path(base_dir_, for_tinygltf);
    files_[key] = File{resolved, id};
    bytes_ += b.byte_length;
  }
}

bool GltfBufferFiles::exists(const std::string& path, void* self) {
  return static_cast<GltfBufferFiles*>(self)->files_.count(path) != 0;
}

std::string GltfBufferFiles::expand(const std::string& path, void*) { return path; }

bool GltfBufferFiles::read(std::vector<unsigned char>* out, std::string* err, const std::string& path,
                           void* self) {
  const auto& files = static_cast<GltfBufferFiles*>(self)->files_;
  const auto it = files.find(path);
  auto fail = [&](const std::string& why) {
    if (err) *err += why + "\n";
    return false;
  };
  if (it == files.end()) return fail("not an approved buffer file");
  const File& f = it->second;
  // The file is opened without following a final link and must still be the one checked (a swap
  // in between is refused), and exactly its checked size is read.
  if (!read_if_unchanged(f.real_path, f.id, out)) return fail("the buffer file changed while it was read");
  return true;
}

}  // namespace hedge::detail

namespace hedge {

std::uint64_t read_budget(const ReadOptions& options, std::uint64_t input_bytes) {
  if (options.max_memory != 0) return options.max_memory;
  constexpr std::uint64_t kFactor = 64;
  const std::uint64_t limit = std::numeric_limits<std::uint64_t>::max();
  return input_bytes > (limit - kDefaultReadMemoryFloor) / kFactor
             ? limit
             : kFactor * input_bytes + kDefaultReadMemoryFloor;
}

}  // namespace hedge
