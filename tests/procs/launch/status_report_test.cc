// The graph's status as JSON (<run>/status.json): a heartbeat status text with invalid UTF-8 (a
// corrupted or hostile HEARTBEAT on the bus) is written with replacement characters, never
// thrown: the exception stopped topay-launch and the whole graph with it (found by topay-faults'
// hostile-payloads episode).
#include "procs/launch/status_report.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace topay::launch {
namespace {

TEST(StatusReportTest, JsonReplacesInvalidUtf8FromAHeartbeat) {
  ProcessStatusRow row;
  row.name = "tracker";
  row.state_name = "RUNNING";
  row.status = std::string("ok \xff\xfe trailing \xc3", 14);
  std::string text;
  ASSERT_NO_THROW(text = ToJson("demo", "/tmp/run", 12.5, {row}));
  const nlohmann::json parsed = nlohmann::json::parse(text);  // valid JSON, valid UTF-8
  const std::string status = parsed.at("processes").at(0).at("status").get<std::string>();
  EXPECT_EQ(status.rfind("ok ", 0), 0u) << status;
  EXPECT_NE(status.find("\xef\xbf\xbd"), std::string::npos) << status;  // U+FFFD
  EXPECT_EQ(parsed.at("processes").at(0).at("name"), "tracker");
}

}  // namespace
}  // namespace topay::launch
