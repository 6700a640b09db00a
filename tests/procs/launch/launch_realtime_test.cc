// Real-time settings of a graph process: applied between fork and exec where permitted, and
// each one that did not take effect reported as a warning (never silently dropped). Nice
// levels >= 0 and affinity to CPU 0 are always permitted; SCHED_FIFO and mlockall depend on
// privileges (root in CI: applied; an unprivileged user: warned).

#include <sched.h>
#include <sys/resource.h>

#include <gtest/gtest.h>

#include "graph_test_support.h"

namespace topay::test {
namespace {

TEST(LaunchRealtime, SettingsAppliedOrWarned) {
  std::string why;
  if (!EnterTestNamespace(&why)) GTEST_SKIP() << why;
  const std::string dir = TestDir("launch_realtime");
  WriteText(dir + "/graph.yaml",
            GraphYaml("rt", ModelProcess("rt-model", "", "    realtime: {nice: 7, cpus: [0], fifo_priority: 10, mlockall: true}\n")));
  HeartbeatWatcher watcher;
  const pid_t launcher = StartLauncher(dir + "/graph.yaml", dir + "/run", {});
  ASSERT_TRUE(watcher.SpinUntil([&] { return watcher.last.contains("rt-model"); }, 10.0));
  const int pid = watcher.last["rt-model"].pid;
  const bool fifo = sched_getscheduler(pid) == SCHED_FIFO;
  // SCHED_FIFO ignores nice; check it only under SCHED_OTHER.
  if (!fifo) {
    EXPECT_EQ(getpriority(PRIO_PROCESS, pid), 7);
  }
  cpu_set_t set;
  CPU_ZERO(&set);
  ASSERT_EQ(sched_getaffinity(pid, sizeof(set), &set), 0);
  EXPECT_EQ(CPU_COUNT(&set), 1);
  EXPECT_TRUE(CPU_ISSET(0, &set));
  kill(launcher, SIGTERM);
  ASSERT_EQ(WaitFor(launcher, 5.0), 0);
  const std::string log = ReadText(dir + "/run/launch.log");
  EXPECT_EQ(fifo, log.find("SCHED_FIFO priority 10 not applied") == std::string::npos) << log;
  const std::string process_log = ReadText(dir + "/run/rt-model.log");
  std::printf("SCHED_FIFO %s; mlockall %s\n", fifo ? "applied" : "warned",
              process_log.find("mlockall not permitted") == std::string::npos ? "applied" : "warned");
  EXPECT_EQ(log.find("nice 7 not applied"), std::string::npos) << log;
  EXPECT_EQ(log.find("CPU affinity not applied"), std::string::npos) << log;
}

}  // namespace
}  // namespace topay::test
