// The planner's newest TRAJECTORY until the tracker reports it (procs/planner/trajectory_delivery.h):
// copies every resend_period_s only once a tracker was heard, until TRACKER_STATUS names it or a
// newer one, the tracker is HELD, or give_up_s after its start; a newer trajectory replaces it.

#include "procs/planner/trajectory_delivery.h"

#include <gtest/gtest.h>

namespace topay::planner {
namespace {

constexpr std::int64_t kT0 = 1'700'000'000'000'000;
constexpr std::int64_t kMs = 1000;

poly_trajectory_t Trajectory(std::int64_t id, std::int64_t start_utime) {
  poly_trajectory_t m{};
  m.trajectory_id = id;
  m.start_utime = start_utime;
  return m;
}

tracker_status_t Status(std::int8_t state, std::int64_t trajectory_id) {
  tracker_status_t s{};
  s.state = state;
  s.trajectory_id = trajectory_id;
  return s;
}

// How many copies Due hands out from `from` to `to` (us), asked every 10 ms.
int CopiesBetween(TrajectoryDelivery* d, std::int64_t from, std::int64_t to) {
  int n = 0;
  for (std::int64_t t = from; t <= to; t += 10 * kMs) n += d->Due(t) != nullptr;
  return n;
}

TEST(TrajectoryDelivery, SendsCopiesUntilTheTrackerReportsIt) {
  TrajectoryDelivery d({});
  d.OnTrackerStatus(Status(tracker_status_t::IDLE, 0));
  d.Sent(Trajectory(5, kT0 + 500 * kMs), kT0);
  EXPECT_EQ(d.Due(kT0 + 50 * kMs), nullptr) << "not before resend_period_s";
  const poly_trajectory_t* copy = d.Due(kT0 + 100 * kMs);
  ASSERT_NE(copy, nullptr);
  EXPECT_EQ(copy->trajectory_id, 5);
  EXPECT_EQ(CopiesBetween(&d, kT0 + 110 * kMs, kT0 + 600 * kMs), 5);  // pending before its start: sent on
  d.OnTrackerStatus(Status(tracker_status_t::TRACKING, 4));  // still the older one
  EXPECT_TRUE(d.waiting());
  d.OnTrackerStatus(Status(tracker_status_t::TRACKING, 5));
  EXPECT_FALSE(d.waiting());
  EXPECT_EQ(CopiesBetween(&d, kT0 + 600 * kMs, kT0 + 2000 * kMs), 0);
  EXPECT_EQ(d.counts().resent, 6);
  EXPECT_EQ(d.counts().confirmed, 1);
}

TEST(TrajectoryDelivery, NoCopiesWithoutATracker) {
  TrajectoryDelivery d({});
  d.Sent(Trajectory(5, kT0), kT0);
  EXPECT_EQ(CopiesBetween(&d, kT0, kT0 + 1000 * kMs), 0) << "the simulator following TRAJECTORY itself";
}

TEST(TrajectoryDelivery, AHeldTrackerOrANewerTrajectoryEndsTheCopies) {
  TrajectoryDelivery d({});
  d.OnTrackerStatus(Status(tracker_status_t::IDLE, 0));
  d.Sent(Trajectory(5, kT0), kT0);
  d.Sent(Trajectory(6, kT0), kT0 + 20 * kMs);  // replaces 5
  EXPECT_EQ(d.Due(kT0 + 200 * kMs)->trajectory_id, 6);
  d.OnTrackerStatus(Status(tracker_status_t::TRACKING, 7));  // a newer one than it was sent
  EXPECT_FALSE(d.waiting());
  d.Sent(Trajectory(8, kT0), kT0 + 300 * kMs);
  d.OnTrackerStatus(Status(tracker_status_t::HELD, 0));
  EXPECT_FALSE(d.waiting());
  EXPECT_EQ(CopiesBetween(&d, kT0 + 300 * kMs, kT0 + 1000 * kMs), 0);
}

TEST(TrajectoryDelivery, GivesUpAfterItsStartAndCanBeSwitchedOff) {
  TrajectoryDelivery d({});
  d.OnTrackerStatus(Status(tracker_status_t::IDLE, 0));
  d.Sent(Trajectory(5, kT0), kT0);
  EXPECT_EQ(CopiesBetween(&d, kT0 + 10 * kMs, kT0 + 2000 * kMs), 20);
  EXPECT_EQ(d.Due(kT0 + 2100 * kMs), nullptr);
  EXPECT_FALSE(d.waiting());
  EXPECT_EQ(d.counts().given_up, 1);

  TrajectoryDeliveryOptions off;
  off.resend_period_s = 0.0;
  TrajectoryDelivery never(off);
  never.OnTrackerStatus(Status(tracker_status_t::IDLE, 0));
  never.Sent(Trajectory(5, kT0), kT0);
  EXPECT_EQ(CopiesBetween(&never, kT0, kT0 + 1000 * kMs), 0);
}

}  // namespace
}  // namespace topay::planner
