// topay-launch with three real processes over real LCM (in a private network namespace):
// every heartbeat arrives; a process killed with SIGKILL is restarted and heartbeats again
// within 2 s while the others keep running untouched; a hung (SIGSTOPped) process is detected
// by its silence and restarted.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <map>

#include "graph_test_support.h"
#include "tests/common/real_time_skip.h"

namespace topay::test {
namespace {

class LaunchRestart : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string why;
    if (!EnterTestNamespace(&why)) GTEST_SKIP() << why;
    dir_ = TestDir(::testing::UnitTest::GetInstance()->current_test_info()->name());
    graph_ = dir_ + "/graph.yaml";
    WriteText(graph_, GraphYaml("three", ModelProcess("robot-model") +
                                             "  - name: commands\n    command: ${BIN_DIR}/topay-command-pattern\n"
                                             "    args: [--rate-hz, 10]\n    depends_on: [robot-model]\n" +
                                             ModelProcess("robot-model-2", "", "    depends_on: [robot-model]\n")));
  }
  void TearDown() override {
    if (launcher_ > 0) {
      kill(launcher_, SIGTERM);
      EXPECT_EQ(WaitFor(launcher_, 5.0), 0) << ReadText(dir_ + "/launcher.out");
    }
  }

  // Starts the graph and waits for the three heartbeats; returns the start-up time.
  double StartAndWaitForAll(HeartbeatWatcher& watcher) {
    const Clock::time_point start = Clock::now();
    launcher_ = StartLauncher(graph_, dir_ + "/run", {"--no-isolated"});
    const bool all = watcher.SpinUntil([&] { return watcher.last.size() >= 3; }, 10.0);
    EXPECT_TRUE(all) << ReadText(dir_ + "/run/launcher.out");
    return SecondsSince(start);
  }

  std::string dir_, graph_;
  pid_t launcher_ = -1;
};

TEST_F(LaunchRestart, KilledProcessIsBackWithinTwoSecondsOthersUntouched) {
  // Under ASan + UBSan (2026-12-06) a process's restart took longer and a second process's
  // heartbeats came late enough for the launcher to restart it too: the 2 s and the untouched
  // heartbeats are rates. HungProcessIsDetectedAndRestarted runs there (its budget is generous).
  TOPAY_SKIP_IN_SLOW_BUILD("the 2 s restart and the other processes' 1 Hz heartbeats");
  HeartbeatWatcher watcher;
  ASSERT_TRUE(watcher.good());
  const double startup_s = StartAndWaitForAll(watcher);
  std::printf("[ figure ] graph of 3 processes: every heartbeat %.3f s after topay-launch started\n", startup_s);
  ASSERT_EQ(watcher.last.size(), 3u);
  const int victim = watcher.last["robot-model"].pid;
  const int commands = watcher.last["commands"].pid;
  const int model2 = watcher.last["robot-model-2"].pid;
  ASSERT_GT(victim, 0);

  const Clock::time_point killed = Clock::now();
  ASSERT_EQ(kill(victim, SIGKILL), 0);
  const bool back = watcher.SpinUntil(
      [&] { return watcher.last["robot-model"].pid != victim && watcher.last["robot-model"].at > killed; }, 5.0);
  const double restart_s = SecondsSince(killed);
  ASSERT_TRUE(back) << ReadText(dir_ + "/run/launcher.out");
  std::printf("[ figure ] kill -9 -> restarted process's first heartbeat: %.3f s\n", restart_s);
  EXPECT_LT(restart_s, 2.0);

  // The others keep their pids and keep heartbeating.
  const Clock::time_point after = Clock::now();
  watcher.SpinUntil([&] { return watcher.last["commands"].at > after && watcher.last["robot-model-2"].at > after; }, 2.5);
  EXPECT_EQ(watcher.last["commands"].pid, commands);
  EXPECT_EQ(watcher.last["robot-model-2"].pid, model2);
  EXPECT_GT(watcher.last["commands"].at, after);
  EXPECT_GT(watcher.last["robot-model-2"].at, after);
  const std::map<std::string, int> pids = StatusPids(dir_ + "/run");
  EXPECT_EQ(pids.at("commands"), commands);
  // The status (status.json, the same rows as the table and GRAPH_STATUS) after a restart.
  nlohmann::json status;
  const auto restarted_in_status = [&] {
    status = nlohmann::json::parse(ReadText(dir_ + "/run/status.json"), nullptr, false);
    if (status.is_discarded()) return false;
    for (const auto& p : status.at("processes")) {
      if (p.at("name") == "robot-model") return p.at("restarts") == 1 && p.at("state") == "RUNNING";
    }
    return false;
  };
  EXPECT_TRUE(watcher.SpinUntil(restarted_in_status, 2.5)) << status.dump();  // rewritten every second
  for (const auto& p : status.at("processes")) {
    EXPECT_EQ(p.at("state"), "RUNNING") << p.dump();
    EXPECT_GT(p.at("rss_kB").get<int>(), 0) << p.dump();
    EXPECT_GE(p.at("heartbeat_age_s").get<double>(), 0.0) << p.dump();
    EXPECT_LT(p.at("heartbeat_age_s").get<double>(), 1.5) << p.dump();
    EXPECT_EQ(p.at("restarts").get<int>(), p.at("name") == "robot-model" ? 1 : 0) << p.dump();
  }
  EXPECT_FALSE(launch::ProcessAlive(victim));
}

TEST_F(LaunchRestart, HungProcessIsDetectedAndRestarted) {
  HeartbeatWatcher watcher;
  ASSERT_TRUE(watcher.good());
  StartAndWaitForAll(watcher);
  const int hung = watcher.last["robot-model"].pid;
  const int others = watcher.last["commands"].pid;
  const Clock::time_point stopped = Clock::now();
  ASSERT_EQ(kill(hung, SIGSTOP), 0);
  // Silent after the heartbeat period (1 s) + the default timeout (3 s): killed and restarted.
  const bool back = watcher.SpinUntil([&] { return watcher.last["robot-model"].pid != hung; }, 9.0);
  ASSERT_TRUE(back) << ReadText(dir_ + "/run/launcher.out");
  EXPECT_GE(SecondsSince(stopped), 3.0);  // not before three heartbeats could have been lost
  std::printf("[ figure ] SIGSTOP -> restarted process's first heartbeat: %.3f s\n", SecondsSince(stopped));
  EXPECT_EQ(watcher.last["commands"].pid, others);
  double took = 0.0;
  EXPECT_TRUE(AllGoneWithin({hung}, 1.0, &took));
  EXPECT_NE(ReadText(dir_ + "/run/launch.log").find("robot-model: no heartbeat for"), std::string::npos);
  EXPECT_NE(ReadText(dir_ + "/run/launch.log").find("killed after its heartbeat stopped, restart 1"), std::string::npos);
}

// Finding 40 (fault table of the twenty-seventh session): with 10 % of the bus's datagrams
// dropped, four of the mapper's heartbeats in a row were lost and the launcher killed it while it
// worked. Every child now also sends a watchdog datagram to the launcher's local socket with each
// heartbeat (procs/runtime/watchdog_notify.h): with every HEARTBEAT dropped on the bus for 6 s,
// nothing is killed. A SIGSTOPped process sends neither and is still killed (above).
TEST_F(LaunchRestart, ProcessesWhoseBusHeartbeatsAreAllLostAreNotKilledWhileTheyLive) {
  if (std::system("command -v nft > /dev/null 2>&1") != 0) GTEST_SKIP() << "nft is not installed (package nftables)";
  HeartbeatWatcher watcher;
  ASSERT_TRUE(watcher.good());
  StartAndWaitForAll(watcher);
  std::map<std::string, int> pids;
  for (const auto& [name, last] : watcher.last) pids[name] = last.pid;
  // HEARTBEAT\0 as the channel of a short LCM message (UDP payload offset 8, after the magic and
  // the sequence number; @th counts bits from the UDP header).
  const std::string rules = dir_ + "/drop_heartbeats.nft";
  WriteText(rules, "table inet topay_test_heartbeats {\n  chain out {\n    type filter hook output priority 0;\n"
                   "    udp dport 7667 @th,128,80 0x48454152544245415400 drop\n  }\n}\n");
  if (std::system(("nft -f " + rules + " > /dev/null 2>&1").c_str()) != 0) GTEST_SKIP() << "nft refused " << rules;
  struct RemoveRules {
    ~RemoveRules() { std::system("nft delete table inet topay_test_heartbeats > /dev/null 2>&1"); }
  } remove_rules;
  const Clock::time_point dropped = Clock::now();
  watcher.Spin(6.0);  // the launcher's limit is 4 s of silence
  for (const auto& [name, last] : watcher.last) {
    EXPECT_LT(last.at, dropped + std::chrono::milliseconds(200)) << name << ": a heartbeat passed the rule";
  }
  std::system("nft delete table inet topay_test_heartbeats > /dev/null 2>&1");
  const Clock::time_point restored = Clock::now();
  ASSERT_TRUE(watcher.SpinUntil(
      [&] {
        return std::all_of(watcher.last.begin(), watcher.last.end(), [&](const auto& e) { return e.second.at > restored; });
      },
      3.0))
      << ReadText(dir_ + "/run/launch.log");
  for (const auto& [name, pid] : pids) EXPECT_EQ(watcher.last[name].pid, pid) << name << " was restarted";
  EXPECT_EQ(ReadText(dir_ + "/run/launch.log").find("no heartbeat for"), std::string::npos)
      << ReadText(dir_ + "/run/launch.log");
}

}  // namespace
}  // namespace topay::test
