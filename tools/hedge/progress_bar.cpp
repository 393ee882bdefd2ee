#include "progress_bar.h"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>

namespace hedge::cli {

namespace {

constexpr auto kDelay = std::chrono::milliseconds(500);
constexpr auto kInterval = std::chrono::milliseconds(100);
constexpr int kBarCells = 30;

}  // namespace

std::optional<std::string> ProgressBar::setting() {
  const char* value = std::getenv("HEDGE_PROGRESS");
  const std::string s = value ? value : "auto";
  if (s == "auto" || s == "always" || s == "never") return s;
  return std::nullopt;
}

ProgressBar::ProgressBar(std::string label)
    : label_(std::move(label)), start_(std::chrono::steady_clock::now()) {
  const std::string s = setting().value_or("auto");
  enabled_ = s == "always" || (s == "auto" && ::isatty(STDERR_FILENO) == 1);
  delayed_ = s != "always";
}

ProgressBar::~ProgressBar() {
  if (shown_) std::fputc('\n', stderr);
}

Progress ProgressBar::callback() {
  return [this](double fraction) { update(fraction); };
}

void ProgressBar::update(double fraction) {
  if (!enabled_) return;
  const auto now = std::chrono::steady_clock::now();
  if (delayed_ && now - start_ < kDelay) return;
  if (shown_ && fraction < 1 && now - last_draw_ < kInterval) return;
  last_draw_ = now;
  draw(fraction);
}

void ProgressBar::finish() {
  if (!shown_) return;
  draw(1);
  std::fputc('\n', stderr);
  std::fflush(stderr);
  shown_ = false;
}

void ProgressBar::draw(double fraction) {
  fraction = fraction < 0 ? 0 : fraction > 1 ? 1 : fraction;
  const int filled = int(fraction * kBarCells + 0.5);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  std::string line = label_ + " [" + std::string(std::size_t(filled), '#') +
                     std::string(std::size_t(kBarCells - filled), '.') + "] ";
  char tail[48];
  std::snprintf(tail, sizeof tail, "%3d%%  %.1f s", int(fraction * 100 + 1e-9), seconds);
  line += tail;
  // Blank out what is left of a longer previous line.
  const std::size_t width = line.size();
  if (width < width_) line.append(width_ - width, ' ');
  width_ = width;
  std::fputc('\r', stderr);
  std::fputs(line.c_str(), stderr);
  std::fflush(stderr);
  shown_ = true;
}

double ms_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

double run_with_progress(const std::string& label, const std::function<void(Progress)>& work) {
  const auto start = std::chrono::steady_clock::now();
  ProgressBar bar(label);
  work(bar.callback());
  bar.finish();
  return ms_since(start);
}

}  // namespace hedge::cli
