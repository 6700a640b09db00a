// Restart policies of topay-launch: on-failure with an exponential backoff capped at its
// maximum and a restart limit, never, always; the launcher ends by itself once every process
// has exited for good. (No heartbeats: the graph's LCM is memq://, nothing leaves the process.)

#include <gtest/gtest.h>

#include "graph_test_support.h"

namespace topay::test {
namespace {

TEST(LaunchRestartPolicy, BackoffDoublesToItsMaximumUntilTheLimit) {
  const std::string dir = TestDir("policy");
  WriteText(dir + "/graph.yaml", R"(name: policy
lcm_url: memq://
processes:
  - {name: failing, command: /bin/false, heartbeat: false, ready_delay_s: 0,
     restart: on-failure, restart_delay_s: 0.05, restart_delay_max_s: 0.2, max_restarts: 4}
  - {name: once, command: /bin/true, heartbeat: false, restart: on-failure}
  - {name: never, command: /bin/false, heartbeat: false, restart: never}
  - {name: always, command: /bin/true, heartbeat: false, restart: always, restart_delay_s: 0.05,
     restart_delay_max_s: 0.05, max_restarts: 2}
)");
  const pid_t launcher = StartLauncher(dir + "/graph.yaml", dir + "/run", {});
  const int status = WaitFor(launcher, 10.0);
  const std::string log = ReadText(dir + "/run/launch.log");
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << ReadText(dir + "/run/launcher.out");
  for (const char* expected : {"failing: exited with code 1, restart 1 in 0.05 s", "failing: exited with code 1, restart 2 in 0.10 s",
                               "failing: exited with code 1, restart 3 in 0.20 s", "failing: exited with code 1, restart 4 in 0.20 s",
                               "failing: exited with code 1, restart limit reached, not restarted",
                               "once: exited with code 0, not restarted", "never: exited with code 1, not restarted",
                               "always: exited with code 0, restart 1 in 0.05 s", "always: exited with code 0, restart 2 in 0.05 s",
                               "stopping the graph (every process has exited)"}) {
    EXPECT_NE(log.find(expected), std::string::npos) << expected << "\n" << log;
  }
  EXPECT_EQ(log.find("restart 5"), std::string::npos) << log;
  EXPECT_NE(ReadText(dir + "/run/failing.log").find("=== started pid"), std::string::npos);
}

// An `ends_graph` process (a mission) ends the graph when it exits for good: the others are
// stopped (a sleeper that would run for a minute) and the launcher exits with its exit code.
TEST(LaunchRestartPolicy, AnEndsGraphProcessStopsTheGraphAndGivesItsExitCode) {
  const std::string dir = TestDir("ends_graph");
  WriteText(dir + "/graph.yaml", R"(name: job
lcm_url: memq://
processes:
  - {name: sleeper, command: /bin/sleep, args: ["60"], heartbeat: false, restart: always}
  - {name: job, command: /bin/sh, args: [-c, "sleep 0.5; exit 3"], heartbeat: false, restart: never,
     ends_graph: true, depends_on: [sleeper]}
)");
  const pid_t launcher = StartLauncher(dir + "/graph.yaml", dir + "/run", {});
  const int status = WaitFor(launcher, 10.0);
  const std::string log = ReadText(dir + "/run/launch.log");
  ASSERT_TRUE(WIFEXITED(status)) << log;
  EXPECT_EQ(WEXITSTATUS(status), 3) << log;
  EXPECT_NE(log.find("job ended the graph (exit code 3)"), std::string::npos) << log;
  EXPECT_NE(log.find("sleeper: killed by"), std::string::npos) << log;
}

}  // namespace
}  // namespace topay::test
