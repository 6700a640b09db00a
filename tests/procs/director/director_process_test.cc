// The topay-director process: exit codes (a bad script or scene -> 1, usage -> 2, a clean stop
// on SIGINT -> 0, the last in a private network namespace) and its heartbeat's status line.

#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>

#include "graph_test_support.h"

namespace topay::test {
namespace {

constexpr const char* kLcmUrl = "udpm://239.255.76.68:7667?ttl=0";

int ExitStatusOf(const std::vector<std::string>& argv, const std::string& out) {
  const pid_t pid = Spawn(argv, out);
  const int status = WaitFor(pid, 20.0);
  return status >= 0 && WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

class DirectorProcess : public testing::Test {
 protected:
  void SetUp() override {
    dir_ = TestDir("director");
    WriteText(dir_ + "/room.json", "{\"boxes\": []}\n");
    WriteText(dir_ + "/script.yaml", "events:\n  - type: box_on_route\n    during_step: dropoff\n");
  }
  std::string dir_;
};

TEST_F(DirectorProcess, BadConfigOrSceneExitsOne) {
  WriteText(dir_ + "/bad.yaml", "events:\n  - type: box_on_route\n    during_stp: dropoff\n");
  EXPECT_EQ(ExitStatusOf({BinDir() + "/topay-director", "--scene", dir_ + "/room.json", "--config", dir_ + "/bad.yaml"},
                         dir_ + "/bad.txt"),
            1);
  EXPECT_NE(ReadText(dir_ + "/bad.txt").find("events[0].during_stp"), std::string::npos) << ReadText(dir_ + "/bad.txt");
  EXPECT_EQ(ExitStatusOf({BinDir() + "/topay-director", "--scene", dir_ + "/missing.json", "--config",
                          dir_ + "/script.yaml"},
                         dir_ + "/scene.txt"),
            1);
}

TEST_F(DirectorProcess, UsageErrorsExitTwo) {
  EXPECT_EQ(ExitStatusOf({BinDir() + "/topay-director", "--config", dir_ + "/script.yaml"}, dir_ + "/u1.txt"), 2);
  EXPECT_EQ(ExitStatusOf({BinDir() + "/topay-director", "--scene", dir_ + "/room.json", "--frobnicate"},
                         dir_ + "/u2.txt"),
            2);
}

TEST_F(DirectorProcess, WaitsForItsStepAndStopsCleanly) {
  std::string why;
  if (!EnterTestNamespace(&why)) GTEST_SKIP() << why;
  HeartbeatWatcher watcher(kLcmUrl);
  const pid_t pid = Spawn({BinDir() + "/topay-director", "--scene", dir_ + "/room.json", "--config",
                           dir_ + "/script.yaml", "--name", "director", "--lcm-url", kLcmUrl},
                          dir_ + "/run.txt");
  EXPECT_TRUE(watcher.SpinUntil(
      [&] { return watcher.last.count("director") && watcher.last["director"].status == "waiting for step dropoff"; },
      10.0))
      << ReadText(dir_ + "/run.txt");
  kill(pid, SIGINT);
  const int status = WaitFor(pid, 10.0);
  ASSERT_TRUE(status >= 0 && WIFEXITED(status)) << ReadText(dir_ + "/run.txt");
  EXPECT_EQ(WEXITSTATUS(status), 0);
}

}  // namespace
}  // namespace topay::test
