// Event files (sim/events/event_file.h): the shipped example loads; malformed files give a
// ConfigError naming the file and the entry / key, never a crash.

#include "sim/events/event_file.h"

#include <gtest/gtest.h>

#include "core/common/error.h"

namespace topay::sim {
namespace {

TEST(EventFile, LoadsTheShippedExample) {
  const std::string path = std::string(TOPAY_SOURCE_DIR) + "/config/sim/events_example.yaml";
  const EventScript script = LoadEventFile(path);
  ASSERT_GE(script.events.size(), 2u);
  bool time = false, near = false, appear_with_box = false, disappear = false;
  for (const SimEvent& e : script.events) {
    time = time || e.trigger == SimEvent::Trigger::kAtTime;
    near = near || e.trigger == SimEvent::Trigger::kNearPoint;
    appear_with_box = appear_with_box || (e.action == SimEvent::Action::kAppear && e.box.has_value());
    disappear = disappear || e.action == SimEvent::Action::kDisappear;
  }
  EXPECT_TRUE(time && near && appear_with_box && disappear);
}

TEST(EventFile, ReadsEveryField) {
  const EventScript script = ParseEventScript(R"(
seed: 42
events:
  - name: crate
    at_s: 2.5
    jitter_s: 0.5
    appear: {id: 1000, center: [1, 2, 0.5], size: [0.4, 0.6, 1.0], yaw: 0.3}
  - near: {point: [3, -1], distance_m: 1.5}
    disappear: {id: 3}
  - at_s: 4
    appear: {id: 3}
)", "mem.yaml");
  ASSERT_EQ(script.seed, std::optional<std::uint64_t>(42));
  ASSERT_EQ(script.events.size(), 3u);
  const SimEvent& a = script.events[0];
  EXPECT_EQ(a.name, "crate");
  EXPECT_EQ(a.trigger, SimEvent::Trigger::kAtTime);
  EXPECT_EQ(a.at_s, 2.5);
  EXPECT_EQ(a.jitter_s, 0.5);
  EXPECT_EQ(a.box_id, 1000);
  ASSERT_TRUE(a.box.has_value());
  EXPECT_EQ(a.box->center_W_m, Eigen::Vector3d(1, 2, 0.5));
  EXPECT_EQ(a.box->size_m, Eigen::Vector3d(0.4, 0.6, 1.0));
  EXPECT_EQ(a.box->yaw_rad, 0.3);
  const SimEvent& b = script.events[1];
  EXPECT_EQ(b.name, "event 1");
  EXPECT_EQ(b.trigger, SimEvent::Trigger::kNearPoint);
  EXPECT_EQ(b.point_W_m, Eigen::Vector2d(3, -1));
  EXPECT_EQ(b.distance_m, 1.5);
  EXPECT_EQ(b.action, SimEvent::Action::kDisappear);
  EXPECT_EQ(b.box_id, 3);
  EXPECT_FALSE(script.events[2].box.has_value());
}

// (file text, the field the error must name, a phrase of the message)
struct BadCase {
  const char* text;
  const char* field;
  const char* says;
};

class EventFileErrors : public testing::TestWithParam<BadCase> {};

TEST_P(EventFileErrors, NameTheFileAndTheEntry) {
  const BadCase& c = GetParam();
  try {
    ParseEventScript(c.text, "bad_events.yaml");
    FAIL() << "accepted: " << c.text;
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.file(), "bad_events.yaml");
    EXPECT_EQ(e.field(), c.field) << e.what();
    EXPECT_NE(std::string(e.what()).find(c.says), std::string::npos) << e.what();
  }
}

INSTANTIATE_TEST_SUITE_P(
    Cases, EventFileErrors,
    testing::Values(
        BadCase{"events: [ {at_s: 1, appear: {id: 1}", "", "malformed YAML"},
        BadCase{"- 1\n- 2\n", "(top level)", "expected a map"},
        BadCase{"seed: 1\n", "events", "missing"},
        BadCase{"events: {at_s: 1}\n", "events", "expected a list"},
        BadCase{"events:\n  - 7\n", "events[0]", "expected a map"},
        BadCase{"events:\n  - {appear: {id: 1}}\n", "events[0]", "exactly one trigger"},
        BadCase{"events:\n  - {at_s: 1, near: {point: [0, 0], distance_m: 1}, appear: {id: 1}}\n", "events[0]", "exactly one trigger"},
        BadCase{"events:\n  - {at_s: 1}\n", "events[0]", "exactly one action"},
        BadCase{"events:\n  - {at_s: 1, appear: {id: 1}}\n  - {at_s: soon, appear: {id: 1}}\n", "events[1].at_s", "expected a number"},
        BadCase{"events:\n  - {at_s: -1, appear: {id: 1}}\n", "events[0].at_s", ">= 0"},
        BadCase{"events:\n  - {at_s: 1, jitter_s: -0.5, appear: {id: 1}}\n", "events[0].jitter_s", ">= 0"},
        BadCase{"events:\n  - {at_s: 1, appear: {id: -4}}\n", "events[0].appear.id", "box id >= 0"},
        BadCase{"events:\n  - {at_s: 1, appear: {}}\n", "events[0].appear.id", "required"},
        BadCase{"events:\n  - {at_s: 1, appear: {id: 9, center: [0, 0]}}\n", "events[0].appear.center", "expected 3 numbers"},
        BadCase{"events:\n  - {at_s: 1, appear: {id: 9, center: [0, 0, 1]}}\n", "events[0].appear.center", "together"},
        BadCase{"events:\n  - {at_s: 1, appear: {id: 9, center: [0, 0, 1], size: [1, 0, 1]}}\n", "events[0].appear.size", "> 0"},
        BadCase{"events:\n  - {at_s: 1, appear: {id: 9, center: [0, .nan, 1], size: [1, 1, 1]}}\n", "events[0].appear.center[1]", "finite"},
        // An infinite yaw used to load (config_yaml fuzz target, regressions/config_yaml/event_yaw_finite).
        BadCase{"events:\n  - {at_s: 1, appear: {id: 9, center: [0, 0, 1], size: [1, 1, 1], yaw: .inf}}\n", "events[0].appear.yaw", "finite"},
        BadCase{"events:\n  - {at_s: 1, appear: {id: 9, center: [0, 0, 1], size: [1, 1, 1], yaw: -.inf}}\n", "events[0].appear.yaw", "finite"},
        BadCase{"events:\n  - {at_s: 1, appear: {id: 9, colour: red}}\n", "events[0].appear.colour", "unknown field"},
        BadCase{"events:\n  - {at_s: 1, when: 3, appear: {id: 9}}\n", "events[0].when", "unknown field"},
        BadCase{"events:\n  - {near: {point: [1, 2]}, disappear: {id: 2}}\n", "events[0].near.distance_m", "required"},
        BadCase{"events:\n  - {near: {point: [1, 2, 3], distance_m: 1}, disappear: {id: 2}}\n", "events[0].near.point", "expected 2 numbers"},
        BadCase{"events:\n  - {near: {point: [1, 2], distance_m: 1}, jitter_s: 1, disappear: {id: 2}}\n", "events[0].jitter_s", "unknown field"},
        BadCase{"seed: -3\nevents: []\n", "seed", "whole number"}));

TEST(EventFile, MissingFileIsAConfigError) {
  EXPECT_THROW(LoadEventFile("/nonexistent/events.yaml"), ConfigError);
}

}  // namespace
}  // namespace topay::sim
