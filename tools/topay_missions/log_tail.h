#pragma once
// Following a growing text file (a process's log) from a tool: each call returns the complete
// lines added since the last one.

#include <cstdint>
#include <string>
#include <vector>

namespace topay::tools {

class LogTail {
 public:
  explicit LogTail(std::string path) : path_(std::move(path)) {}

  /// The complete lines written since the last call (a missing file: none yet); a line still
  /// being written waits for its newline unless `flush` (the writer has ended).
  std::vector<std::string> NewLines(bool flush = false);

 private:
  std::string path_;
  std::uint64_t offset_ = 0;
  std::string partial_;
};

}  // namespace topay::tools
