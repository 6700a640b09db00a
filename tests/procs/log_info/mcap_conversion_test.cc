// topay-log-info --mcap (procs/log_info/mcap_conversion.h): a crafted run log converted into the
// viewer's channels, read back with the strict test reader: every channel with its JSON schema,
// each message valid JSON at its log time, every message of the log that the viewer shows there
// at full rate, malformed ones counted; a log that cannot be read named.

#include "procs/log_info/mcap_conversion.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "mcap_test_reader.h"
#include "tests/tools/report/crafted_run_log.h"

namespace topay::loginfo {
namespace {

McapConversionOptions ShippedRobot() {
  return {std::string(TOPAY_SOURCE_DIR) + "/config/robot/topay_mm.urdf",
          std::string(TOPAY_SOURCE_DIR) + "/config/robot/topay_mm.yaml"};
}

TEST(McapConversion, WritesTheViewersChannelsAtFullRate) {
  const std::string dir = report::test::FreshTestDir("mcap_conversion");
  report::test::WriteCraftedRunLog(dir + "/run.lcmlog");
  const McapConversionSummary summary = ConvertLogToMcap(dir + "/run.lcmlog", dir + "/run.mcap", ShippedRobot());
  const mcap_test::McapContents mcap = mcap_test::ReadMcap(dir + "/run.mcap");
  ASSERT_EQ(mcap.summary_channels.size(), 17u);
  std::map<std::uint16_t, std::string> topic_of;
  for (const auto& c : mcap.summary_channels) {
    EXPECT_EQ(c.message_encoding, "json");
    topic_of[c.id] = c.topic;
  }
  for (const auto& s : mcap.summary_schemas) {
    EXPECT_EQ(s.encoding, "jsonschema");
    EXPECT_EQ(nlohmann::json::parse(s.data)["type"], "object") << s.name;
  }
  std::map<std::string, int> count;
  for (const auto& m : mcap.messages) {
    ++count[topic_of.at(m.channel_id)];
    EXPECT_TRUE(nlohmann::json::accept(m.data)) << topic_of.at(m.channel_id);
    EXPECT_GE(m.log_time, static_cast<std::uint64_t>(report::test::kT0Utime) * 1000);
  }
  EXPECT_EQ(count["/robot/description"], 1);
  EXPECT_EQ(count["/robot/state"], report::test::kRobotStates);  // every one (no browser rate)
  EXPECT_EQ(count["/plot/state"], report::test::kRobotStates);
  EXPECT_EQ(count["/map/blocks"], 2);                             // the snapshot and the delta
  EXPECT_EQ(count["/sim/contacts"], 2);
  EXPECT_EQ(count["/goal"], 1);
  EXPECT_EQ(count["/planner/trajectory"], 2);  // 101 and 103; the bent one is not a MINCO solution
  EXPECT_EQ(summary.messages, static_cast<std::int64_t>(mcap.messages.size()));
  EXPECT_EQ(summary.per_topic.at("/robot/state"), report::test::kRobotStates);
  EXPECT_GE(summary.malformed, 3);  // garbage ROBOT_STATE, a tracker status on PLANNER_STATUS, the bent trajectory
}

TEST(McapConversion, NamesALogItCannotRead) {
  const std::string dir = report::test::FreshTestDir("mcap_conversion_missing");
  try {
    ConvertLogToMcap(dir + "/missing.lcmlog", dir + "/out.mcap", ShippedRobot());
    FAIL() << "converted a missing log";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("missing.lcmlog"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace topay::loginfo
