// The shipped simulation graph (config/graphs/sim.yaml) runs as it is, isolated by default:
// the logger records the simulator's ROBOT_STATE, BASE_POSE, POINT_CLOUD, SIM_STATUS, HEARTBEAT
// and the launcher's GRAPH_STATUS into <run>/graph.lcmlog; with --group drive the command
// pattern publishes CONTROL_COMMAND (the sim's plant takes them: the graph's sim is not --follow); with
// --group perception the mapper publishes MAP_UPDATE and saves its OctoMap; with --group
// planning the planner waits for goals and reports at the end.

#include <gtest/gtest.h>

#include "graph_test_support.h"
#include "procs/log_info/log_summary.h"

namespace topay::test {
namespace {

TEST(SimGraph, RunsIsolatedAndRecordsTheSimulator) {
  std::string why;
  if (!EnterTestNamespace(&why)) GTEST_SKIP() << why;  // the launcher nests its own namespace
  const std::string dir = TestDir("sim_graph");
  const pid_t launcher = StartLauncher(std::string(TOPAY_SOURCE_DIR) + "/config/graphs/sim.yaml", dir,
                                       {"--duration", "3", "--group", "sim", "--group", "perception", "--group", "drive",
                                        "--group", "planning"});
  const int status = WaitFor(launcher, 15.0);
  const std::string out = ReadText(dir + "/launcher.out");
  ASSERT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << out;
  EXPECT_NE(out.find("isolated: private network namespace"), std::string::npos) << out;
  const loginfo::LogSummary summary = loginfo::SummarizeLog(dir + "/graph.lcmlog");
  ASSERT_TRUE(summary.channels.contains("ROBOT_STATE")) << loginfo::FormatSummary(summary);
  EXPECT_GE(summary.channels.at("ROBOT_STATE").count, 150);  // 100 Hz for ~2-3 s
  ASSERT_TRUE(summary.channels.contains("SIM_STATUS"));
  EXPECT_GE(summary.channels.at("SIM_STATUS").count, 15);
  ASSERT_TRUE(summary.channels.contains("BASE_POSE"));
  ASSERT_TRUE(summary.channels.contains("POINT_CLOUD"));
  EXPECT_GE(summary.channels.at("POINT_CLOUD").count, 10);
  EXPECT_GE(summary.channels.at("HEARTBEAT").count, 4);
  EXPECT_GE(summary.channels.at("GRAPH_STATUS").count, 2);
  EXPECT_GE(summary.channels.at("CONTROL_COMMAND").count, 20);
  ASSERT_TRUE(summary.channels.contains("MAP_UPDATE")) << loginfo::FormatSummary(summary);
  EXPECT_GE(summary.channels.at("MAP_UPDATE").count, 5);  // >= 2 Hz, every scan
  EXPECT_NE(ReadText(dir + "/mapper.log").find("scan in -> MAP_UPDATE"), std::string::npos);  // report at the end
  EXPECT_TRUE(std::filesystem::exists(dir + "/map.bt"));
  for (const auto& [channel, c] : summary.channels) EXPECT_EQ(c.decode_failures, 0) << channel;
  EXPECT_NE(ReadText(dir + "/sim.log").find("final: sim time"), std::string::npos);  // counts printed on SIGTERM
  ASSERT_TRUE(summary.channels.contains("PLANNER_STATUS")) << loginfo::FormatSummary(summary);
  EXPECT_NE(ReadText(dir + "/planner.log").find("topay-planner: 0 goals"), std::string::npos);  // report at the end
  for (const char* log : {"/sim.log", "/drive-pattern.log", "/logger.log", "/launch.log", "/status.json", "/planner.log"}) {
    EXPECT_TRUE(std::filesystem::exists(dir + log)) << log;
  }
}

}  // namespace
}  // namespace topay::test
