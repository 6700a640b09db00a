// The event scheduler (sim/events/event_scheduler.h) with the world (apply_event.h): time and
// proximity triggers fire once, at the right step; jitter is seeded; run-time events.

#include "sim/events/event_scheduler.h"

#include <gtest/gtest.h>

#include "sim/events/apply_event.h"
#include "sim/events/event_file.h"

namespace topay::sim {
namespace {

constexpr double kStep = 0.002;

SimEvent AtTime(double t, int id, SimEvent::Action action = SimEvent::Action::kDisappear) {
  SimEvent e;
  e.trigger = SimEvent::Trigger::kAtTime;
  e.at_s = t;
  e.box_id = id;
  e.action = action;
  return e;
}

// Polls at every plant step up to t_end with the base moving along x at 1 m/s from x = 0;
// returns (step, event name) per firing.
std::vector<std::pair<int, std::string>> Drive(EventScheduler* s, double t_end) {
  std::vector<std::pair<int, std::string>> fired;
  for (int k = 0; k * kStep <= t_end + 1e-12; ++k) {
    for (const SimEvent& e : s->Poll(k * kStep, Eigen::Vector2d(k * kStep * 1.0, 0.0))) fired.emplace_back(k, e.name);
  }
  return fired;
}

TEST(EventScheduler, TimeAndProximityTriggersFireOnceAtTheRightStep) {
  SimEvent a = AtTime(1.0, 1);
  a.name = "at 1 s";
  SimEvent b = AtTime(0.3333, 2);
  b.name = "at 0.3333 s";
  SimEvent near;
  near.name = "near (2.5, 0.3)";
  near.trigger = SimEvent::Trigger::kNearPoint;
  near.point_W_m = Eigen::Vector2d(2.5, 0.3);
  near.distance_m = 0.5;  // the base (x = t) gets within 0.5 m at x = 2.5 - 0.4 = 2.1
  near.box_id = 3;
  EventScheduler s({a, b, near}, 1);
  const auto fired = Drive(&s, 5.0);
  ASSERT_EQ(fired.size(), 3u);
  EXPECT_EQ(fired[0], std::make_pair(167, std::string("at 0.3333 s")));  // first step at or after 0.3333 s
  EXPECT_EQ(fired[1], std::make_pair(500, std::string("at 1 s")));
  EXPECT_EQ(fired[2].second, "near (2.5, 0.3)");
  EXPECT_EQ(fired[2].first, 1050);  // x = 2.1 m
  EXPECT_EQ(s.pending(), 0);
  EXPECT_EQ(s.fired(), 3);
}

TEST(EventScheduler, JitterIsSeededAndWithinItsRange) {
  std::vector<SimEvent> events;
  for (int i = 0; i < 20; ++i) {
    SimEvent e = AtTime(1.0, i);
    e.jitter_s = 0.5;
    events.push_back(e);
  }
  EventScheduler a(events, 5), b(events, 5), c(events, 6);
  EXPECT_EQ(a.scripted_fire_times_s(), b.scripted_fire_times_s());
  EXPECT_NE(a.scripted_fire_times_s(), c.scripted_fire_times_s());
  for (const double t : a.scripted_fire_times_s()) {
    EXPECT_GE(t, 1.0);
    EXPECT_LT(t, 1.5);
  }
  // Firing follows the drawn times.
  const auto fired = Drive(&a, 2.0);
  ASSERT_EQ(fired.size(), 20u);
  for (const auto& [step, name] : fired) EXPECT_GE(step * kStep + 1e-9, 1.0);
}

TEST(EventScheduler, RunTimeEventsFireAtTheNextPoll) {
  EventScheduler s({}, 1);
  EXPECT_TRUE(s.Poll(0.0, Eigen::Vector2d::Zero()).empty());
  SimEvent now;
  now.trigger = SimEvent::Trigger::kNow;
  now.box_id = 4;
  s.Add(now);
  s.Add(AtTime(0.5, 5));  // in the past: fires at once
  s.Add(AtTime(9.0, 6));
  const std::vector<SimEvent> due = s.Poll(1.0, Eigen::Vector2d::Zero());
  ASSERT_EQ(due.size(), 2u);
  EXPECT_EQ(due[0].box_id, 4);
  EXPECT_EQ(due[1].box_id, 5);
  EXPECT_EQ(s.pending(), 1);
  EXPECT_TRUE(s.Poll(1.002, Eigen::Vector2d::Zero()).empty());
}

TEST(ApplyEvent, BoxesAppearAndDisappearInTheWorld) {
  Scene scene;
  scene.boxes.resize(3);
  SimWorld world(scene);
  SimEvent gone = AtTime(0, 1);
  EXPECT_EQ(ApplyEvent(gone, &world), "");
  EXPECT_FALSE(world.IsPresent(1));
  EXPECT_EQ(world.present_ids(), (std::vector<int>{0, 2}));
  SimEvent back = AtTime(0, 1, SimEvent::Action::kAppear);
  EXPECT_EQ(ApplyEvent(back, &world), "");
  EXPECT_TRUE(world.IsPresent(1));
  SimEvent fresh = AtTime(0, 1000, SimEvent::Action::kAppear);
  EXPECT_NE(ApplyEvent(fresh, &world).find("no geometry"), std::string::npos);
  OrientedBox box;
  box.center_W_m = Eigen::Vector3d(1, 2, 0.5);
  fresh.box = box;
  EXPECT_EQ(ApplyEvent(fresh, &world), "");
  EXPECT_EQ(world.present_ids(), (std::vector<int>{0, 1, 2, 1000}));
  EXPECT_EQ(world.IdOfPresentIndex(3), 1000);
  EXPECT_EQ(world.present_boxes()[3].center_W_m, box.center_W_m);
  EXPECT_NE(ApplyEvent(AtTime(0, 77), &world).find("does not exist"), std::string::npos);
}

}  // namespace
}  // namespace topay::sim
