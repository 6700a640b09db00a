#include "log_tail.h"

#include <fstream>

namespace topay::tools {

std::vector<std::string> LogTail::NewLines(bool flush) {
  std::vector<std::string> lines;
  std::ifstream in(path_, std::ios::binary);
  if (in) {
    in.seekg(0, std::ios::end);
    const std::uint64_t size = static_cast<std::uint64_t>(in.tellg());
    if (size < offset_) offset_ = 0;  // truncated: start over
    in.seekg(static_cast<std::streamoff>(offset_));
    std::string chunk(size - offset_, '\0');
    in.read(chunk.data(), static_cast<std::streamsize>(chunk.size()));
    offset_ = size;
    partial_ += chunk;
  }
  std::size_t begin = 0;
  for (std::size_t end; (end = partial_.find('\n', begin)) != std::string::npos; begin = end + 1) {
    lines.push_back(partial_.substr(begin, end - begin));
  }
  partial_.erase(0, begin);
  if (flush && !partial_.empty()) lines.push_back(std::move(partial_)), partial_.clear();
  return lines;
}

}  // namespace topay::tools
