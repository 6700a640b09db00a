#include "procs/launch/group_guardian.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <set>
#include <system_error>

namespace topay::launch {
namespace {

// Messages are fixed-size records: +pgid or -pgid as one int32 (sign = add/remove).
[[noreturn]] void GuardianMain(int read_fd) {
  prctl(PR_SET_NAME, "topay-guardian");
  // Keep running through the terminal's SIGINT and a SIGTERM meant for the launcher: only the
  // pipe's end counts. (Signals blocked by the launcher stay blocked here.)
  signal(SIGINT, SIG_IGN);
  signal(SIGTERM, SIG_IGN);
  signal(SIGHUP, SIG_IGN);
  std::set<pid_t> groups;
  std::int32_t record = 0;
  while (true) {
    const ssize_t n = read(read_fd, &record, sizeof(record));
    if (n == sizeof(record)) {
      if (record > 0) groups.insert(record);
      else groups.erase(-record);
      continue;
    }
    if (n < 0 && errno == EINTR) continue;
    break;  // EOF: the launcher is gone
  }
  for (const pid_t group : groups) kill(-group, SIGKILL);
  _exit(0);
}

}  // namespace

GroupGuardian::GroupGuardian() {
  int fds[2];
  if (pipe2(fds, O_CLOEXEC) != 0) throw std::system_error(errno, std::generic_category(), "pipe2");
  pid_ = fork();
  if (pid_ < 0) throw std::system_error(errno, std::generic_category(), "fork");
  if (pid_ == 0) {
    close(fds[1]);
    // Close everything else inherited (e.g. a terminal held open would delay nothing, but
    // pipes of earlier children must not be kept open by the guardian).
    for (int fd = 3; fd < 1024; ++fd) {
      if (fd != fds[0]) close(fd);
    }
    GuardianMain(fds[0]);
  }
  close(fds[0]);
  write_fd_ = fds[1];
}

GroupGuardian::~GroupGuardian() {
  close(write_fd_);
  waitpid(pid_, nullptr, 0);
}

void GroupGuardian::Add(pid_t pgid) {
  const std::int32_t record = pgid;
  (void)!write(write_fd_, &record, sizeof(record));
}

void GroupGuardian::Remove(pid_t pgid) {
  const std::int32_t record = -pgid;
  (void)!write(write_fd_, &record, sizeof(record));
}

}  // namespace topay::launch
