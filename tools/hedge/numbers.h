// Numbers on the command line: one parser, with overflow and range checks, for every number the
// tool reads, whether CLI11 converts the option or a command splits a text such as "800x600" or
// "1,2,3" by hand. Refusals say the bound in words ("must be at least 1", "must be 0 or more"),
// never a range up to the largest double, and a NaN or an infinity is refused as such.
#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <string_view>

namespace hedge::cli {

inline constexpr double kInf = std::numeric_limits<double>::infinity();

//! The whole text as a decimal integer (an optional '-' for signed types only, no '+', no spaces,
//! no other base); nothing if it is not one or does not fit T.
template <typename T>
std::optional<T> parse_integer(std::string_view text);

//! The whole text as a decimal or scientific number ("1.5", "-2e3"); "nan" and "inf" parse, so that
//! the caller can refuse them by name. Nothing if it is not a number or lies beyond a double.
std::optional<double> parse_real(std::string_view text);

//! The reason `text` is not a finite number, or "" if it is one (then *value gets it).
std::string finite_real(std::string_view text, double* value = nullptr);

//! A CLI11 transformer for a whole-number option: refuses what is not a whole number of type T or
//! lies outside [min, max], saying the bound in words, and passes the number on in plain decimal
//! (so that CLI11's own conversion, which would read "010" as octal, sees what was checked).
template <typename T>
CLI::Validator whole_number(T min, T max = std::numeric_limits<T>::max());

//! A CLI11 transformer for a real option: refuses NaN and infinities, then what lies below `min`
//! (or at it, when `min_open`) or above `max`. Bounds are said in words: "must be positive",
//! "must be 0 or more", "must be from 0 to 180". real_number(-inf, inf) only refuses non-finite.
CLI::Validator real_number(double min, double max = std::numeric_limits<double>::infinity(),
                           bool min_open = false);

//! Adds to `app` an option `name` whose value is a real number checked by
//! real_number(min, max, min_open), with its default shown in --help.
template <typename T>
CLI::Option* add_real_option(CLI::App& app, const std::string& name, T& value, const std::string& description,
                             double min, double max = std::numeric_limits<double>::infinity(),
                             bool min_open = false) {
  return app.add_option(name, value, description)
      ->capture_default_str()
      ->transform(real_number(min, max, min_open));
}

//! The number in plain words: "0", "1", "0.5", "1e+30".
std::string number_text(double value);

}  // namespace hedge::cli
