// The progress of a long render on standard error. A renderer reports how far it is
// (cgfs::ReportProgress, common/include/cgfs/progress.h); the chapter program shows it,
// only when standard error is a terminal and the figure has taken more than a second,
// and erases the line when the figure is done.
#pragma once

#include <memory>
#include <string>

namespace cgfs {

// Shows the progress of one figure while it exists (see above). Output goes to
// standard error only if `enabled`; the chapter program enables it when standard
// error is a terminal.
class ProgressDisplay {
 public:
  ProgressDisplay(std::string figure, bool enabled);
  ~ProgressDisplay();
  ProgressDisplay(const ProgressDisplay&) = delete;
  ProgressDisplay& operator=(const ProgressDisplay&) = delete;

  // The line shown after `seconds`, with `fraction` done (negative: unknown).
  static std::string Line(const std::string& figure, double fraction, double seconds);

 private:
  struct State;
  std::unique_ptr<State> state_;
};

}  // namespace cgfs
