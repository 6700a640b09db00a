// topay-launch's stop: SIGTERM stops every child (reverse order; a child that ignores SIGTERM
// gets SIGKILL after the grace period) and the launcher exits 0; SIGKILL of the launcher takes
// every child with it within 1 s, grandchildren included. Nothing of the graph is left.

#include <gtest/gtest.h>

#include "graph_test_support.h"

namespace topay::test {
namespace {

constexpr double kGraceS = 1.5;

class LaunchStop : public testing::Test {
 protected:
  void SetUp() override {
    std::string why;
    if (!EnterTestNamespace(&why)) GTEST_SKIP() << why;
    dir_ = TestDir(testing::UnitTest::GetInstance()->current_test_info()->name());
    graph_ = dir_ + "/graph.yaml";
    // A shell that ignores SIGTERM and has a grandchild (sleep) in its process group.
    WriteText(graph_, GraphYaml("stop",
                                ModelProcess("robot-model") +
                                    "  - name: commands\n    command: ${BIN_DIR}/topay-command-pattern\n"
                                    "    depends_on: [robot-model]\n"
                                    "  - name: stubborn\n    command: /bin/sh\n"
                                    "    args: [-c, 'trap \"\" TERM; sleep 300 & wait; wait']\n"
                                    "    heartbeat: false\n",
                                kGraceS));
  }

  // Starts the graph; returns every pid of it (children and the grandchild sleep).
  std::vector<int> StartGraph() {
    HeartbeatWatcher watcher;
    EXPECT_TRUE(watcher.good());
    launcher_ = StartLauncher(graph_, dir_ + "/run", {"--no-isolated"});
    EXPECT_TRUE(watcher.SpinUntil([&] { return watcher.last.size() >= 2; }, 10.0));
    watcher.Spin(1.2);  // status.json is written every second
    std::vector<int> pids;
    for (const auto& [name, pid] : StatusPids(dir_ + "/run")) {
      EXPECT_GT(pid, 0) << name;
      pids.push_back(pid);
    }
    // The stubborn shell's children (the sleep).
    const std::string children = ReadText("/proc/" + std::to_string(pids.back()) + "/task/" +
                                          std::to_string(pids.back()) + "/children");
    std::istringstream in(children);
    for (int child; in >> child;) pids.push_back(child);
    EXPECT_EQ(pids.size(), 4u) << "3 children + the grandchild";
    return pids;
  }

  std::string dir_, graph_;
  pid_t launcher_ = -1;
};

TEST_F(LaunchStop, SigtermStopsEveryChildWithinTheGracePeriod) {
  const std::vector<int> pids = StartGraph();
  const Clock::time_point term = Clock::now();
  ASSERT_EQ(kill(launcher_, SIGTERM), 0);
  double gone_s = 0.0;
  EXPECT_TRUE(AllGoneWithin(pids, kGraceS + 1.0, &gone_s)) << ReadText(dir_ + "/run/launcher.out");
  std::printf("[ figure ] SIGTERM -> every child gone: %.3f s (grace %.1f s; one child ignores SIGTERM)\n", gone_s,
              kGraceS);
  const int status = WaitFor(launcher_, 3.0);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << status;
  EXPECT_LT(SecondsSince(term), kGraceS + 1.0);
  ReapOrphans();
  const std::string log = ReadText(dir_ + "/run/launch.log");
  EXPECT_NE(log.find("stubborn: still running after the grace period, SIGKILL"), std::string::npos) << log;
  // Reverse dependency order: stubborn (started last) is signalled first, robot-model last.
  EXPECT_LT(log.find("commands: exited"), log.find("robot-model: exited")) << log;
}

TEST_F(LaunchStop, SigkillOfTheLauncherTakesEveryChildWithinOneSecond) {
  const std::vector<int> pids = StartGraph();
  ASSERT_EQ(kill(launcher_, SIGKILL), 0);
  double gone_s = 0.0;
  EXPECT_TRUE(AllGoneWithin(pids, 1.0, &gone_s));
  std::printf("[ figure ] SIGKILL of topay-launch -> every child and grandchild gone: %.3f s\n", gone_s);
  WaitFor(launcher_, 1.0);
  ReapOrphans();
}

}  // namespace
}  // namespace topay::test
