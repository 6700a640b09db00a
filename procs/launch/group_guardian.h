#pragma once
// The last line against orphans: a small helper process, forked by the launcher before anything
// else, that learns every child's process group over a pipe and, when the pipe closes (the
// launcher exited or was killed, even with SIGKILL), SIGKILLs every group still registered.
// PR_SET_PDEATHSIG covers each direct child; this covers what the children started themselves.

#include <sys/types.h>

namespace topay::launch {

class GroupGuardian {
 public:
  /// Forks the guardian (call before any thread starts and before opening sockets you do not
  /// want it to hold). Throws std::system_error if pipe or fork fail.
  GroupGuardian();
  /// Closes the pipe: the guardian kills what is left and exits; reaps it.
  ~GroupGuardian();
  GroupGuardian(const GroupGuardian&) = delete;
  GroupGuardian& operator=(const GroupGuardian&) = delete;

  void Add(pid_t pgid);     ///< a new child's process group
  void Remove(pid_t pgid);  ///< a group that is gone (so a reused id is never killed)
  pid_t pid() const { return pid_; }

 private:
  int write_fd_ = -1;
  pid_t pid_ = -1;
};

}  // namespace topay::launch
