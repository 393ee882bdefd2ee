#include "memory_budget.h"

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <sstream>

#include "hedge/error.h"
#include "numbers.h"

namespace hedge::cli {

namespace {

constexpr std::uint64_t kFallbackBytes = std::uint64_t(4) << 30;

std::string budget_source(const MemoryBudget& budget) {
  return budget.text.empty() ? "the memory available now (raise it with --max-memory SIZE)"
                             : "--max-memory " + budget.text;
}

}  // namespace

std::optional<std::uint64_t> parse_memory_size(std::string_view text) {
  std::size_t digits = 0;
  while (digits < text.size() && text[digits] >= '0' && text[digits] <= '9') ++digits;
  const std::optional<std::uint64_t> number = parse_integer<unsigned long>(text.substr(0, digits));
  if (!number || *number == 0) return std::nullopt;
  std::string_view unit = text.substr(digits);
  int shift = 0;
  if (!unit.empty()) {
    switch (unit.front()) {
      case 'K':
      case 'k':
        shift = 10;
        break;
      case 'M':
      case 'm':
        shift = 20;
        break;
      case 'G':
      case 'g':
        shift = 30;
        break;
      case 'T':
      case 't':
        shift = 40;
        break;
      case 'B':
      case 'b':
        shift = -1;
        break;
      default:
        return std::nullopt;
    }
    unit.remove_prefix(1);
    if (shift == -1) {
      shift = 0;
      if (!unit.empty()) return std::nullopt;  // "B" alone: bytes
    } else if (!(unit.empty() || unit == "B" || unit == "b" || unit == "iB" || unit == "ib")) {
      return std::nullopt;
    }
  }
  if (shift > 0 && *number > (std::numeric_limits<std::uint64_t>::max() >> shift)) return std::nullopt;
  return *number << shift;
}

void add_max_memory_option(CLI::App& command, MemoryBudget& budget) {
  command
      .add_option("--max-memory", budget.text,
                  "Refuse work estimated to need more memory than SIZE: bytes, or with a unit K, M, G or T "
                  "(binary: 512M, 4G). Default: for reading a glTF, 64 times the input's size plus 64 MiB; "
                  "for the work the command's numbers ask for, the memory the machine has available now")
      ->check(CLI::Validator(
          [](std::string& s) -> std::string {
            return parse_memory_size(s)
                       ? ""
                       : "'" + s +
                             "' is not a memory size: give a whole number of bytes above 0, "
                             "optionally with a unit K, M, G or T (such as 512M or 4G), at most 2^64 bytes";
          },
          "SIZE"));
}

std::uint64_t available_memory() {
  std::ifstream in("/proc/meminfo");
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("MemAvailable:", 0) != 0) continue;
    std::istringstream fields(line.substr(13));
    std::uint64_t kib = 0;
    std::string unit;
    if (fields >> kib >> unit && unit == "kB" && kib > 0) return kib * 1024;
  }
  const long pages = ::sysconf(_SC_AVPHYS_PAGES), page = ::sysconf(_SC_PAGESIZE);
  if (pages > 0 && page > 0) return std::uint64_t(pages) * std::uint64_t(page);
  return kFallbackBytes;
}

std::uint64_t effective_budget(const MemoryBudget& budget) {
  if (!budget.text.empty()) {
    if (const auto bytes = parse_memory_size(budget.text)) return *bytes;
  }
  return available_memory();
}

void check_memory(double needed, const MemoryBudget& budget, const std::string& what,
                  const std::string& advice) {
  const std::uint64_t limit = effective_budget(budget);
  if (needed <= double(limit)) return;
  throw InvalidInputError(what + " would need about " + bytes_text(needed) +
                          " (estimated), more than the budget of " + bytes_text(double(limit)) + ", " +
                          budget_source(budget) + "; " + advice);
}

}  // namespace hedge::cli
