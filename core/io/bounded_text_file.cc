#include "core/io/bounded_text_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "core/common/error.h"

namespace topay {
namespace {

// Closes the descriptor on every exit path.
class FileDescriptor {
 public:
  explicit FileDescriptor(int fd) : fd_(fd) {}
  ~FileDescriptor() {
    if (fd_ >= 0) ::close(fd_);
  }
  FileDescriptor(const FileDescriptor&) = delete;
  FileDescriptor& operator=(const FileDescriptor&) = delete;
  int get() const { return fd_; }

 private:
  int fd_;
};

std::string Bytes(std::size_t n) { return std::to_string(n) + " bytes"; }

[[noreturn]] void Fail(const std::string& path, const std::string& message) {
  throw ConfigError(path, "", message);
}

// Checks the kind of file and, for a regular file, its size before anything is read.
void CheckKindAndSize(const std::string& path, int fd, std::size_t max_bytes,
                      const std::string& what) {
  struct stat info {};
  if (::fstat(fd, &info) != 0) Fail(path, "cannot stat the " + what + ": " + std::strerror(errno));
  if (S_ISDIR(info.st_mode)) Fail(path, "is a directory, expected a " + what + " file");
  if (S_ISREG(info.st_mode)) {
    if (static_cast<unsigned long long>(info.st_size) > max_bytes) {
      Fail(path, "the " + what + " is " + Bytes(static_cast<std::size_t>(info.st_size)) +
                     ", above its limit of " + Bytes(max_bytes));
    }
    return;
  }
  if (!S_ISFIFO(info.st_mode) && !S_ISCHR(info.st_mode)) {
    Fail(path, "is not a regular file, a pipe or a character device; expected a " + what);
  }
}

}  // namespace

std::string ReadBoundedTextFile(const std::string& path, std::size_t max_bytes,
                                const std::string& what) {
  const FileDescriptor fd(::open(path.c_str(), O_RDONLY | O_CLOEXEC));
  if (fd.get() < 0) Fail(path, "cannot open the " + what + ": " + std::strerror(errno));
  CheckKindAndSize(path, fd.get(), max_bytes, what);
  std::string text;
  char block[65536];
  while (true) {
    const ssize_t n = ::read(fd.get(), block, sizeof(block));
    if (n < 0) {
      if (errno == EINTR) continue;
      Fail(path, "cannot read the " + what + ": " + std::strerror(errno));
    }
    if (n == 0) return text;
    const void* nul = std::memchr(block, '\0', static_cast<std::size_t>(n));
    if (nul != nullptr) {
      const std::size_t offset = text.size() + (static_cast<const char*>(nul) - block);
      Fail(path, "contains a NUL byte at offset " + std::to_string(offset) + ": not a " + what +
                     " (a text file)");
    }
    if (text.size() + static_cast<std::size_t>(n) > max_bytes) {
      Fail(path, "the " + what + " exceeds its limit of " + Bytes(max_bytes) +
                     " (a file that never ends?)");
    }
    text.append(block, static_cast<std::size_t>(n));
  }
}

}  // namespace topay
