// topay-viz's options (procs/viz/viz_options.h): the shipped file restates the defaults; a
// misspelt key, a wrong type or a bad value is an error naming the file and the field.

#include "procs/viz/viz_options.h"

#include <gtest/gtest.h>

#include <fstream>

#include "core/common/error.h"
#include "tests/tools/report/crafted_run_log.h"

namespace topay::viz {
namespace {

std::string Write(const std::string& text) {
  const std::string path = report::test::FreshTestDir("viz_options") + "/viz.yaml";
  std::ofstream(path) << text;
  return path;
}

std::string ErrorOf(const std::string& text) {
  try {
    LoadVizOptions(Write(text));
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "";
}

TEST(VizOptions, TheShippedFileRestatesTheDefaults) {
  const VizOptions shipped = LoadVizOptions(std::string(TOPAY_SOURCE_DIR) + "/config/viz/viz.yaml");
  const VizOptions defaults;
  EXPECT_EQ(shipped.server.bind_address, "127.0.0.1");
  EXPECT_EQ(shipped.server.port, defaults.server.port);
  EXPECT_EQ(shipped.server.max_clients, defaults.server.max_clients);
  EXPECT_EQ(shipped.server.max_queue_bytes, defaults.server.max_queue_bytes);
  EXPECT_EQ(shipped.server.max_incoming_message_bytes, defaults.server.max_incoming_message_bytes);
  EXPECT_DOUBLE_EQ(shipped.pipeline.rates.robot_state_hz, defaults.pipeline.rates.robot_state_hz);
  EXPECT_DOUBLE_EQ(shipped.pipeline.rates.map_hz, defaults.pipeline.rates.map_hz);
  EXPECT_EQ(shipped.pipeline.scan.max_points, defaults.pipeline.scan.max_points);
  EXPECT_DOUBLE_EQ(shipped.flush_hz, defaults.flush_hz);
  EXPECT_TRUE(shipped.robot_urdf.empty());
}

TEST(VizOptions, NamesTheFieldOfABadValue) {
  EXPECT_NE(ErrorOf("server:\n  prot: 80\n").find("server.prot"), std::string::npos);
  EXPECT_NE(ErrorOf("server:\n  port: 70000\n").find("server"), std::string::npos);
  EXPECT_NE(ErrorOf("server:\n  port: eighty\n").find("server.port"), std::string::npos);
  EXPECT_NE(ErrorOf("pipeline:\n  rates:\n    map_hz: -1\n").find("pipeline.rates"), std::string::npos);
  EXPECT_NE(ErrorOf("pipeline:\n  scan_max_points: 0\n").find("scan_max_points"), std::string::npos);
  EXPECT_NE(ErrorOf("flush_hz: 0\n").find("flush_hz"), std::string::npos);
  EXPECT_EQ(ErrorOf("server:\n  port: 0\n  bind_address: 0.0.0.0\n"), "");
}

}  // namespace
}  // namespace topay::viz
