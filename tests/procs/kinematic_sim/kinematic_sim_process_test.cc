// topay-kinematic-sim as a real process over real LCM (private network namespace): it answers
// commands with ROBOT_STATE, drops malformed, truncated, oversized and wrong-type payloads on
// its subscribed channel (counted in its heartbeat) and keeps running; SIGTERM ends it with 0;
// exit codes 1 and 2 for a bad config and bad flags.

#include <gtest/gtest.h>

#include "../../lcm/sample_messages.h"
#include "graph_test_support.h"
#include "procs/command_pattern/command_pattern.h"
#include "topay/robot_state_t.hpp"

namespace topay::test {
namespace {

struct StateCounter {
  int count = 0;
  void On(const lcm::ReceiveBuffer*, const std::string&) { ++count; }
};

TEST(KinematicSimProcess, SurvivesBadPayloadsAndCountsThem) {
  std::string why;
  if (!EnterTestNamespace(&why)) GTEST_SKIP() << why;
  const std::string dir = TestDir("kinematic_sim_process");
  WriteText(dir + "/model.yaml", "state_rate_hz: 0\n");
  const pid_t sim = Spawn({BinDir() + "/topay-kinematic-sim", "--config", dir + "/model.yaml", "--name", "sim-under-test"},
                          dir + "/out.txt");
  HeartbeatWatcher watcher;
  StateCounter states;
  watcher.lcm().subscribe(std::string(channels::ROBOT_STATE), &StateCounter::On, &states);
  ASSERT_TRUE(watcher.SpinUntil([&] { return watcher.last.contains("sim-under-test"); }, 5.0)) << ReadText(dir + "/out.txt");

  const std::string channel(channels::CONTROL_COMMAND);
  const std::vector<std::uint8_t> good = Encode(pattern::PatternCommand({}, 0, 1'000'000));
  std::vector<std::vector<std::uint8_t>> bad = {
      {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12},                      // malformed
      std::vector<std::uint8_t>(good.begin(), good.end() - 3),      // truncated
      [&] { auto b = good; b.resize(good.size() + 1000, 7); return b; }(),  // oversized
      Encode(MessageSample<heartbeat_t>::Make()),                   // wrong type
  };
  for (const auto& payload : bad) watcher.lcm().publish(channel, payload.data(), static_cast<unsigned>(payload.size()));
  for (int i = 0; i < 3; ++i) {
    const control_command_t cmd = pattern::PatternCommand({}, i, 1'000'000 + i * 50'000);
    watcher.lcm().publish(channel, &cmd);
  }
  EXPECT_TRUE(watcher.SpinUntil([&] { return states.count >= 3; }, 3.0));
  EXPECT_EQ(states.count, 3);
  const Clock::time_point after = Clock::now();
  ASSERT_TRUE(watcher.SpinUntil([&] { return watcher.last["sim-under-test"].at > after; }, 3.0));
  EXPECT_NE(watcher.last["sim-under-test"].status.find("malformed messages dropped: 4"), std::string::npos)
      << watcher.last["sim-under-test"].status;
  EXPECT_TRUE(launch::ProcessAlive(sim));
  EXPECT_NE(ReadText(dir + "/out.txt").find("dropped malformed message #4 on CONTROL_COMMAND"), std::string::npos);

  kill(sim, SIGTERM);
  const int status = WaitFor(sim, 3.0);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << status;
}

TEST(KinematicSimProcess, ExitCodesForBadConfigAndBadFlags) {
  const std::string dir = TestDir("kinematic_sim_exit_codes");
  WriteText(dir + "/bad.yaml", "speed: 3\n");
  const pid_t config = Spawn({BinDir() + "/topay-kinematic-sim", "--config", dir + "/bad.yaml", "--lcm-url", "memq://"},
                             dir + "/config.txt");
  int status = WaitFor(config, 5.0);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 1) << ReadText(dir + "/config.txt");
  EXPECT_NE(ReadText(dir + "/config.txt").find("unknown key 'speed'"), std::string::npos);
  const pid_t usage = Spawn({BinDir() + "/topay-kinematic-sim", "--bogus"}, dir + "/usage.txt");
  status = WaitFor(usage, 5.0);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 2);
  const pid_t help = Spawn({BinDir() + "/topay-kinematic-sim", "--help"}, dir + "/help.txt");
  status = WaitFor(help, 5.0);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
  EXPECT_NE(ReadText(dir + "/help.txt").find("--lcm-url"), std::string::npos);
}

}  // namespace
}  // namespace topay::test
