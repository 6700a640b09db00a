// Log round trip: a graph (logger, robot model, seeded commands) recorded for a few seconds;
// topay-log-info's counts match what was published; replaying the log into a graph of the
// robot model alone (topay-launch --replay) reproduces its ROBOT_STATE outputs byte for byte.

#include <gtest/gtest.h>

#include "graph_test_support.h"
#include "procs/log_info/log_summary.h"
#include "topay/control_command_t.hpp"
#include "topay/robot_state_t.hpp"

namespace topay::test {
namespace {

constexpr int kCommands = 30;

std::vector<std::vector<std::uint8_t>> Payloads(const std::string& log_path, const std::string& channel) {
  std::vector<std::vector<std::uint8_t>> payloads;
  lcm::LogFile log(log_path, "r");
  while (const lcm::LogEvent* event = log.readNextEvent()) {
    if (event->channel != channel) continue;
    const auto* data = static_cast<const std::uint8_t*>(event->data);
    payloads.emplace_back(data, data + event->datalen);
  }
  return payloads;
}

std::string Processes(const std::string& config, bool with_commands) {
  std::string yaml = "  - name: logger\n    command: lcm-logger\n    args: [-f, '${RUN_DIR}/graph.lcmlog']\n"
                     "    heartbeat: false\n" +
                     ModelProcess("robot-model", config, "    depends_on: [logger]\n");
  if (with_commands) {
    yaml += "  - name: commands\n    command: ${BIN_DIR}/topay-command-pattern\n"
            "    args: [--count, " + std::to_string(kCommands) + ", --rate-hz, 30, --seed, 9]\n"
            "    depends_on: [robot-model]\n    publishes: [CONTROL_COMMAND]\n";
  }
  return yaml;
}

TEST(LogRoundTrip, CountsMatchAndReplayReproducesOutputs) {
  std::string why;
  if (!EnterTestNamespace(&why)) GTEST_SKIP() << why;
  const std::string dir = TestDir("log_round_trip");
  WriteText(dir + "/model.yaml", "state_rate_hz: 0\n");  // ROBOT_STATE only in answer to commands
  WriteText(dir + "/record.yaml", GraphYaml("record", Processes(dir + "/model.yaml", true)));
  WriteText(dir + "/replay.yaml", GraphYaml("replay", Processes(dir + "/model.yaml", false)));

  const pid_t recorder = StartLauncher(dir + "/record.yaml", dir + "/record", {"--duration", "3"});
  ASSERT_EQ(WaitFor(recorder, 15.0), 0) << ReadText(dir + "/record/launcher.out");
  const std::string recorded = dir + "/record/graph.lcmlog";

  // topay-log-info (the library and the binary) against what the processes published.
  const loginfo::LogSummary summary = loginfo::SummarizeLog(recorded);
  ASSERT_TRUE(summary.channels.contains("CONTROL_COMMAND"));
  EXPECT_EQ(summary.channels.at("CONTROL_COMMAND").count, kCommands);
  EXPECT_EQ(summary.channels.at("ROBOT_STATE").count, kCommands);
  EXPECT_EQ(summary.channels.at("CONTROL_COMMAND").types.at("control_command_t"), kCommands);
  EXPECT_GE(summary.channels.at("HEARTBEAT").count, 4);  // 2 processes x >= 2 s
  EXPECT_GE(summary.channels.at("GRAPH_STATUS").count, 2);
  for (const auto& [channel, c] : summary.channels) EXPECT_EQ(c.decode_failures, 0) << channel;
  EXPECT_GT(summary.channels.at("CONTROL_COMMAND").rate_hz(), 15.0);  // sent at 30 Hz
  EXPECT_LT(summary.channels.at("CONTROL_COMMAND").rate_hz(), 45.0);
  EXPECT_EQ(summary.channels.at("ROBOT_STATE").min_bytes, summary.channels.at("ROBOT_STATE").max_bytes);
  const pid_t info = Spawn({BinDir() + "/topay-log-info", "--json", recorded}, dir + "/info.json");
  ASSERT_EQ(WaitFor(info, 10.0), 0);
  const nlohmann::json json = nlohmann::json::parse(ReadText(dir + "/info.json"));
  EXPECT_EQ(json["channels"]["CONTROL_COMMAND"]["count"], kCommands);
  EXPECT_EQ(json["channels"]["ROBOT_STATE"]["decode_failures"], 0);

  // Replay at double speed into the robot model alone: its recorded ROBOT_STATE is left out.
  const pid_t replayer = StartLauncher(dir + "/replay.yaml", dir + "/replay", {"--replay", recorded, "--speed", "2"});
  ASSERT_EQ(WaitFor(replayer, 15.0), 0) << ReadText(dir + "/replay/launcher.out");
  const std::string out = ReadText(dir + "/replay/launcher.out");
  EXPECT_NE(out.find("replay done: " + std::to_string(kCommands) + " messages played"), std::string::npos) << out;
  const auto original = Payloads(recorded, "ROBOT_STATE");
  const auto replayed = Payloads(dir + "/replay/graph.lcmlog", "ROBOT_STATE");
  ASSERT_EQ(original.size(), static_cast<std::size_t>(kCommands));
  EXPECT_EQ(replayed.size(), original.size());
  EXPECT_TRUE(replayed == original) << "the replayed robot model published different states";
  EXPECT_EQ(Payloads(dir + "/replay/graph.lcmlog", "CONTROL_COMMAND"), Payloads(recorded, "CONTROL_COMMAND"));
}

}  // namespace
}  // namespace topay::test
