// The memory budget of a command: how much memory a command may plan to use for work whose size
// a user's number sets (subdivision steps, picture sizes, samples, edits). Work estimated beyond it
// is refused before anything is allocated, with a message giving the estimate and the budget.
//
// The budget is --max-memory SIZE when given (bytes, or with a binary unit: 512K, 512M, 4G, 1T;
// "B" or "iB" may follow, as in 4GiB), else what the machine has available now: MemAvailable of
// /proc/meminfo, else free physical pages (sysconf), else 4 GiB. Every command has the option (see
// add_load_options()); given, it is also the budget of reading a glTF (ReadOptions::max_memory),
// whose default is relative to the file's size instead.
#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace hedge::cli {

struct MemoryBudget {
  std::string text;  //!< --max-memory as given; empty: the default
};

//! Adds --max-memory SIZE to a subcommand, checked while parsing (a malformed or zero size is a
//! usage error that says how to write one).
void add_max_memory_option(CLI::App& command, MemoryBudget& budget);

//! "512M" -> 536870912 and so on; nothing for a malformed size, zero, or one beyond 2^64 bytes.
std::optional<std::uint64_t> parse_memory_size(std::string_view text);

//! The budget in bytes: --max-memory when given, else available_memory().
std::uint64_t effective_budget(const MemoryBudget& budget);

//! What the machine has available now (see the file comment). Never 0.
std::uint64_t available_memory();

//! \throw InvalidInputError unless `needed` fits the budget; the message says what needs how much,
//!   the budget and where it comes from, and `advice` (such as "use fewer --steps").
void check_memory(double needed, const MemoryBudget& budget, const std::string& what,
                  const std::string& advice);

}  // namespace hedge::cli
