#include "procs/runtime/thread_priority.h"

#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>

namespace topay::procs {

bool LowerThisThreadPriority(int increment) {
  const int tid = static_cast<int>(syscall(SYS_gettid));
  errno = 0;
  const int nice = getpriority(PRIO_PROCESS, tid);
  if (errno != 0) return false;
  return setpriority(PRIO_PROCESS, tid, std::min(19, nice + increment)) == 0;
}

}  // namespace topay::procs
