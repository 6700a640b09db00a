#include "procs/launch/console.h"

#include <chrono>
#include <ctime>

namespace topay::launch {
namespace {

constexpr int kColours[] = {36, 33, 32, 35, 34, 31, 96, 93, 92, 95, 94, 91};

std::string Timestamp() {
  const auto now = std::chrono::system_clock::now();
  const std::time_t seconds = std::chrono::system_clock::to_time_t(now);
  const auto ms = std::chrono::duration_cast<std::chrono::milliseconds>(now.time_since_epoch()) % 1000;
  char text[32];
  std::strftime(text, sizeof(text), "%F %T", std::localtime(&seconds));
  char out[48];
  std::snprintf(out, sizeof(out), "%s.%03d", text, static_cast<int>(ms.count()));
  return out;
}

}  // namespace

Console::Console(std::FILE* out, bool tty, const std::string& launch_log) : out_(out), tty_(tty) {
  if (!launch_log.empty()) launch_log_.open(launch_log, std::ios::app);
}

void Console::EraseTable() {
  if (drawn_lines_ > 0) std::fprintf(out_, "\x1b[%dF\x1b[J", drawn_lines_);
  drawn_lines_ = 0;
}

void Console::Redraw() {
  for (const std::string& line : table_) std::fprintf(out_, "%s\n", line.c_str());
  drawn_lines_ = static_cast<int>(table_.size());
  std::fflush(out_);
}

void Console::ChildLine(const std::string& name, int colour, const std::string& text) {
  if (!tty_) {
    std::fprintf(out_, "[%s] %s\n", name.c_str(), text.c_str());
    std::fflush(out_);
    return;
  }
  EraseTable();
  const int code = kColours[colour % static_cast<int>(std::size(kColours))];
  std::fprintf(out_, "\x1b[%dm[%s]\x1b[0m %s\n", code, name.c_str(), text.c_str());
  Redraw();
}

void Console::Event(const std::string& text) {
  if (launch_log_.is_open()) launch_log_ << Timestamp() << " " << text << std::endl;
  if (!tty_) {
    std::fprintf(out_, "[topay-launch] %s\n", text.c_str());
    std::fflush(out_);
    return;
  }
  EraseTable();
  std::fprintf(out_, "\x1b[1m[topay-launch]\x1b[0m %s\n", text.c_str());
  Redraw();
}

void Console::Table(const std::vector<std::string>& lines) {
  table_ = lines;
  if (!tty_) {
    for (const std::string& line : lines) std::fprintf(out_, "[status] %s\n", line.c_str());
    std::fflush(out_);
    return;
  }
  EraseTable();
  Redraw();
}

void Console::ClearTable() {
  if (tty_) EraseTable();
  table_.clear();
  std::fflush(out_);
}

}  // namespace topay::launch
