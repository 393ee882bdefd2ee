#include "numbers.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <system_error>

namespace hedge::cli {

template <typename T>
std::optional<T> parse_integer(std::string_view text) {
  if (text.empty() || text.front() == '+') return std::nullopt;
  if constexpr (std::is_unsigned_v<T>) {
    if (text.front() == '-') return std::nullopt;
  }
  T value{};
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value, 10);
  if (ec != std::errc() || ptr != end) return std::nullopt;
  return value;
}

std::optional<double> parse_real(std::string_view text) {
  if (text.empty() || text.front() == '+') return std::nullopt;
  double value = 0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value, std::chars_format::general);
  if (ec != std::errc() || ptr != end) return std::nullopt;
  return value;
}

std::string finite_real(std::string_view text, double* value) {
  const std::optional<double> v = parse_real(text);
  if (!v) {
    // from_chars refuses a number beyond a double with result_out_of_range: say so rather than
    // "not a number".
    double big = 0;
    const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), big);
    if (ec == std::errc::result_out_of_range && ptr == text.data() + text.size())
      return "'" + std::string(text) + "' is beyond the range of a number (about 1.8e308)";
    return "'" + std::string(text) + "' is not a number";
  }
  if (!std::isfinite(*v)) return "'" + std::string(text) + "' is not a finite number";
  if (value) *value = *v;
  return "";
}

std::string number_text(double value) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.10g", value);
  return buf;
}

template <typename T>
CLI::Validator whole_number(T min, T max) {
  std::string bound;
  if (max == std::numeric_limits<T>::max()) {
    bound = min == 0 ? "must be 0 or more" : "must be at least " + std::to_string(min);
  } else {
    bound = "must be from " + std::to_string(min) + " to " + std::to_string(max);
  }
  const std::string description = max == std::numeric_limits<T>::max()
                                      ? (min == 0 ? "INT>=0" : "INT>=" + std::to_string(min))
                                      : "INT in " + std::to_string(min) + ".." + std::to_string(max);
  return CLI::Validator(
      [min, max, bound](std::string& text) -> std::string {
        const std::optional<T> v = parse_integer<T>(text);
        if (!v) {
          // A whole number too large (or too small) for the option, or not a whole number at all.
          const bool digits = !text.empty() && text.find_first_not_of("-0123456789") == std::string::npos &&
                              text.find_first_of("0123456789") != std::string::npos;
          if (digits && text.front() == '-' && std::is_unsigned_v<T>) return bound + ", got " + text;
          if (digits) return bound + "; " + text + " is too large";
          return "'" + text + "' is not a whole number (" + bound + ")";
        }
        if (*v < min || *v > max) return bound + ", got " + text;
        text = std::to_string(*v);
        return "";
      },
      description);
}

CLI::Validator real_number(double min, double max, bool min_open) {
  std::string bound;
  if (std::isinf(max) && std::isinf(min)) {
    bound = "must be a finite number";
  } else if (std::isinf(max)) {
    if (min == 0) {
      bound = min_open ? "must be positive" : "must be 0 or more";
    } else {
      bound = (min_open ? "must be more than " : "must be at least ") + number_text(min);
    }
  } else if (min_open) {
    bound = "must be more than " + number_text(min) + " and at most " + number_text(max);
  } else {
    bound = "must be from " + number_text(min) + " to " + number_text(max);
  }
  const std::string description = std::isinf(max) && std::isinf(min) ? std::string("NUMBER")
                                  : std::isinf(max) ? (min_open ? "NUMBER>" : "NUMBER>=") + number_text(min)
                                                    : (min_open ? "NUMBER in (" : "NUMBER in [") +
                                                          number_text(min) + ", " + number_text(max) + "]";
  return CLI::Validator(
      [min, max, min_open, bound](std::string& text) -> std::string {
        double v = 0;
        const std::string why = finite_real(text, &v);
        if (!why.empty()) return std::isinf(min) && std::isinf(max) ? why : why + " (" + bound + ")";
        if (v < min || (min_open && v == min) || v > max) return bound + ", got " + text;
        char buf[64];
        std::snprintf(buf, sizeof buf, "%.17g", v);
        text = buf;
        return "";
      },
      description);
}

template std::optional<int> parse_integer<int>(std::string_view);
template std::optional<unsigned> parse_integer<unsigned>(std::string_view);
template std::optional<long> parse_integer<long>(std::string_view);
template std::optional<unsigned long> parse_integer<unsigned long>(std::string_view);
template CLI::Validator whole_number<int>(int, int);
template CLI::Validator whole_number<unsigned>(unsigned, unsigned);
template CLI::Validator whole_number<long>(long, long);
template CLI::Validator whole_number<unsigned long>(unsigned long, unsigned long);

}  // namespace hedge::cli
