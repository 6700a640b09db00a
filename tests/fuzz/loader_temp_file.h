#pragma once
// The file the loader targets feed the loaders that only take a path (Load*Options(path)):
// created once (mkstemps under /dev/shm if it is writable, else $TMPDIR, else /tmp), rewritten
// with each input, removed by the destructor. A target holds one in a function-local static.

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

#include "tests/fuzz/fuzz_check.h"

namespace topay::fuzz {

class LoaderTempFile {
 public:
  /// `stem` starts the file's name (e.g. "topay_fuzz_config"); `suffix` ends it (".yaml").
  LoaderTempFile(const std::string& stem, const std::string& suffix) {
    std::string pattern = Folder() + "/" + stem + "_XXXXXX" + suffix;
    std::vector<char> name(pattern.begin(), pattern.end());
    name.push_back('\0');
    const int fd = ::mkstemps(name.data(), static_cast<int>(suffix.size()));
    FuzzCheck(fd >= 0, "the fuzz target's temporary file can be created");
    ::close(fd);
    path_ = name.data();
  }
  ~LoaderTempFile() { ::unlink(path_.c_str()); }
  LoaderTempFile(const LoaderTempFile&) = delete;
  LoaderTempFile& operator=(const LoaderTempFile&) = delete;

  const std::string& path() const { return path_; }

  /// Replaces the file's content by `text`.
  void Write(std::string_view text) const {
    const int fd = ::open(path_.c_str(), O_WRONLY | O_TRUNC | O_CLOEXEC);
    FuzzCheck(fd >= 0, "the fuzz target's temporary file can be opened");
    std::size_t done = 0;
    while (done < text.size()) {
      const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
      if (n < 0 && errno == EINTR) continue;
      FuzzCheck(n > 0, "the fuzz target's temporary file can be written");
      done += static_cast<std::size_t>(n);
    }
    ::close(fd);
  }

 private:
  static std::string Folder() {
    if (::access("/dev/shm", W_OK | X_OK) == 0) return "/dev/shm";
    const char* tmpdir = std::getenv("TMPDIR");
    if (tmpdir != nullptr && *tmpdir != '\0') return tmpdir;
    return "/tmp";
  }

  std::string path_;
};

}  // namespace topay::fuzz
