#pragma once
// The launcher's terminal output: children's lines prefixed with their name (colour-tagged on a
// terminal), the launcher's own events, and the status table (redrawn below the scrolling lines
// on a terminal, printed as plain lines otherwise). Events also go to <run>/launch.log.

#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

namespace topay::launch {

class Console {
 public:
  /// `tty`: colours and a live table. `launch_log`: path of the launcher's own log (may be
  /// empty).
  Console(std::FILE* out, bool tty, const std::string& launch_log);

  bool tty() const { return tty_; }
  /// One line of a child: "[name] text", the prefix in the child's colour (index) on a tty.
  void ChildLine(const std::string& name, int colour, const std::string& text);
  /// One line of the launcher: "[topay-launch] text" (and in launch.log, with a timestamp).
  void Event(const std::string& text);
  /// The status table: on a tty, replaces the table drawn before (kept at the bottom); else
  /// printed as plain lines.
  void Table(const std::vector<std::string>& lines);
  /// Removes the live table (before exit).
  void ClearTable();

 private:
  void EraseTable();
  void Redraw();

  std::FILE* out_;
  bool tty_;
  std::ofstream launch_log_;
  std::vector<std::string> table_;
  int drawn_lines_ = 0;
};

}  // namespace topay::launch
