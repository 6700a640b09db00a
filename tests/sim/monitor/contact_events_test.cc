#include "sim/monitor/contact_events.h"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

namespace topay::sim {
namespace {

ContactEvents MakeEvents() { return ContactEvents({"base", "sphere 0 (link a)", "chassis"}); }

TEST(ContactEventsTest, NothingCountsNoEvent) {
  ContactEvents events = MakeEvents();
  std::vector<RawContact> none;
  for (int k = 0; k < 5; ++k) EXPECT_TRUE(events.Step(0.002 * k, &none).empty());
  EXPECT_EQ(events.counts().events, 0);
  EXPECT_EQ(events.counts().steps, 5);
  EXPECT_EQ(events.counts().steps_in_contact, 0);
  EXPECT_TRUE(std::isnan(events.counts().first_contact_t_s));
  EXPECT_EQ(events.Report(), "collision monitor: no contact in 5 steps\n");
}

TEST(ContactEventsTest, APersistentContactIsOneEvent) {
  ContactEvents events = MakeEvents();
  for (int k = 0; k < 20; ++k) {
    std::vector<RawContact> contacts;
    if (k >= 3 && k < 13) contacts.push_back({7, 0, 4, 0.001 * k});
    const std::vector<Contact>& started = events.Step(0.5 * k, &contacts);
    EXPECT_EQ(started.size(), k == 3 ? 1u : 0u) << k;
    EXPECT_EQ(events.active().size(), contacts.size());
  }
  const auto& c = events.counts();
  EXPECT_EQ(c.events, 1);
  EXPECT_EQ(c.steps_in_contact, 10);
  EXPECT_EQ(c.steps, 20);
  EXPECT_DOUBLE_EQ(c.max_depth_m, 0.012);
  EXPECT_DOUBLE_EQ(c.first_contact_t_s, 1.5);
  ASSERT_EQ(events.events().size(), 1u);
  const ContactEvent& e = events.events()[0];
  EXPECT_EQ(e.first.body, "base");
  EXPECT_EQ(e.first.box, 4);
  EXPECT_DOUBLE_EQ(e.first.depth_m, 0.003);
  EXPECT_DOUBLE_EQ(e.max_depth_m, 0.012);
  EXPECT_DOUBLE_EQ(e.duration_s(), 4.5);
  EXPECT_EQ(e.steps, 10);
  EXPECT_FALSE(e.active);
}

TEST(ContactEventsTest, AGapOrAnotherBoxStartsANewEvent) {
  ContactEvents events = MakeEvents();
  const std::vector<std::vector<RawContact>> script = {
      {{1, 0, 0, 0.01}},                      // event 1: base vs box 0
      {{1, 0, 0, 0.02}, {2, 0, 1, 0.01}},     // goes on; event 2: base vs box 1
      {},                                     // both end
      {{1, 0, 0, 0.005}, {9, 2, -1, 0.03}},   // event 3 (same pair again), event 4 (chassis)
  };
  std::vector<std::size_t> started;
  for (std::size_t k = 0; k < script.size(); ++k) {
    std::vector<RawContact> contacts = script[k];
    started.push_back(events.Step(double(k), &contacts).size());
  }
  EXPECT_EQ(started, (std::vector<std::size_t>{1, 1, 0, 2}));
  EXPECT_EQ(events.counts().events, 4);
  EXPECT_EQ(events.counts().steps_in_contact, 3);
  EXPECT_DOUBLE_EQ(events.counts().max_depth_m, 0.03);
  ASSERT_EQ(events.events().size(), 4u);
  EXPECT_DOUBLE_EQ(events.events()[0].max_depth_m, 0.02);
  EXPECT_EQ(events.events()[0].steps, 2);
  EXPECT_EQ(events.events()[3].first.body, "chassis");
  EXPECT_TRUE(events.events()[3].active);
  // The report lists the deepest event first.
  const std::string report = events.Report();
  EXPECT_EQ(report.find("collision monitor: 4 contact events, 3 of 4 steps in contact"), 0u)
      << report;
  EXPECT_LT(report.find("chassis: depth 0.0300 m"), report.find("base vs box 0: depth 0.0200"))
      << report;
  EXPECT_NE(report.find("still in contact"), std::string::npos);
}

TEST(ContactEventsTest, RecordingLimitKeepsCounting) {
  ContactEvents events({"base"}, 2);
  for (int k = 0; k < 10; ++k) {
    std::vector<RawContact> contacts;
    if (k % 2 == 0) contacts.push_back({1, 0, 0, 0.01});
    events.Step(k, &contacts);
  }
  EXPECT_EQ(events.counts().events, 5);
  EXPECT_EQ(events.events().size(), 2u);
  EXPECT_NE(events.Report().find("... 3 more"), std::string::npos);
}

}  // namespace
}  // namespace topay::sim
