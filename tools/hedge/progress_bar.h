// The progress bar of the long commands (smooth, subdivide, decimate): one line on stderr, redrawn
// in place, that appears only when stderr is a terminal and the work has taken more than half a
// second, so quick runs, pipes and log files see nothing of it.
//
// The environment variable HEDGE_PROGRESS changes when it shows: "auto" (the default, as above),
// "never", or "always" (drawn from the start even into a file or pipe, one carriage-return-separated
// line per update: for logs and tests).
#pragma once

#include <chrono>
#include <functional>
#include <optional>
#include <string>

#include "hedge/core/progress.h"

namespace hedge::cli {

class ProgressBar {
 public:
  //! `label` starts the line, e.g. the command's name.
  explicit ProgressBar(std::string label);
  ~ProgressBar();
  ProgressBar(const ProgressBar&) = delete;
  ProgressBar& operator=(const ProgressBar&) = delete;

  //! A callback for the library's algorithms; it updates this bar, which must outlive its use.
  Progress callback();
  //! Shows `fraction` done (0..1), at most every 100 ms unless it is the end.
  void update(double fraction);
  //! Ends the line (at 100%) if the bar was shown. The destructor ends it too, without the 100%,
  //! so that an error message that follows starts on a line of its own.
  void finish();

  //! The HEDGE_PROGRESS setting, or nothing if it is set to something else than auto, always or never.
  static std::optional<std::string> setting();

 private:
  void draw(double fraction);

  std::string label_;
  bool enabled_ = false;  // may ever show
  bool delayed_ = true;   // waits for half a second first
  bool shown_ = false;
  std::size_t width_ = 0;  // of the last line drawn
  std::chrono::steady_clock::time_point start_, last_draw_;
};

//! Milliseconds since `start`.
double ms_since(std::chrono::steady_clock::time_point start);

//! Runs `work`, handing it the callback of a bar labelled `label`, and returns how long it took in
//! milliseconds. The bar is finished when the work returns.
double run_with_progress(const std::string& label, const std::function<void(Progress)>& work);

}  // namespace hedge::cli
