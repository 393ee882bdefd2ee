#include "hedge/error.h"

#include <cstdio>
#include <utility>

namespace hedge {

namespace {
std::string io_message(const std::string& path, std::uint64_t line, std::int64_t offset,
                       const std::string& message) {
  // Appended piecewise: g++ 12 warns falsely (-Wrestrict) on chained temporaries here.
  std::string where = path.empty() ? std::string("<memory>") : path;
  if (line > 0) where.append(":").append(std::to_string(line));
  if (offset >= 0) where.append(" (byte ").append(std::to_string(offset)).append(")");
  where.append(": ").append(message);
  return where;
}
}  // namespace

IoError::IoError(std::string path, std::uint64_t line, std::int64_t byte_offset, const std::string& message)
    : Error(io_message(path, line, byte_offset, message)),
      path_(std::move(path)),
      line_(line),
      byte_offset_(byte_offset) {}

TopologyError::TopologyError(const std::string& message, std::vector<std::uint32_t> vertices,
                             std::vector<std::uint32_t> faces)
    : Error(message), vertices_(std::move(vertices)), faces_(std::move(faces)) {}

std::string bytes_text(double bytes) {
  static constexpr const char* kUnits[] = {"bytes", "KiB", "MiB", "GiB", "TiB", "PiB", "EiB"};
  int unit = 0;
  while (bytes >= 1024 && unit < 6) bytes /= 1024, ++unit;
  char text[64];
  std::snprintf(text, sizeof text, unit == 0 ? "%.0f %s" : "%.1f %s", bytes, kUnits[unit]);
  return text;
}

}  // namespace hedge
