#include "sim/monitor/collision_monitor.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/collision/scene_clearance.h"
#include "core/common/random.h"
#include "core/geometry/primitive_box_distance.h"
#include "core/robot/self_collision.h"
#include "tests/common/make_box.h"
#include "tests/core/robot/allocation_counter.h"
#include "tests/core/robot/robot_test_model.h"

namespace topay::sim {
namespace {

constexpr double kDt = 0.002;  // the plant's 500 Hz step

class CollisionMonitorTest : public ::testing::Test {
 protected:
  CollisionMonitorTest() : model_(testing::LoadTopayModel()), kinematics_(model_) {}

  WholeBodyState State(double x, double y, double yaw, Eigen::VectorXd q = {}) const {
    WholeBodyState state;
    state.x_m = x;
    state.y_m = y;
    state.yaw_rad = yaw;
    state.q_rad = q.size() ? q : Eigen::VectorXd::Zero(model_.num_joints());
    return state;
  }

  RobotModel model_;
  Kinematics kinematics_;
};

// Driving along +x at v from x = 0 with the arm upright (within 0.2 m of the base axis), the
// base cylinder (radius 0.4 m) is the first body to reach a box face at x = 3.0003: at
// t* = (3.0003 - 0.4) / v. The first step after t* reports it, with depth x(t) + 0.4 - 3.0003.
TEST_F(CollisionMonitorTest, StraightDriveIntoABoxIsReportedAtTheAnalyticTime) {
  const double v = 0.5, face_x = 3.0003;  // t* = 5.2006 s, between two steps
  CollisionMonitor monitor(kinematics_);
  monitor.SetWorld({MakeBox({10, 10, 0.5}, {1, 1, 1}),  // far away
                    MakeBox({face_x + 0.25, 0, 0.25}, {0.5, 2.0, 0.5})});
  const double t_star = (face_x - model_.base_cylinder.radius_m) / v;
  int reported = 0;
  for (int k = 0; k <= 2650; ++k) {
    const double t = k * kDt;
    const std::vector<Contact>& started = monitor.Check(State(v * t, 0, 0), t);
    for (const Contact& c : started) {
      ++reported;
      EXPECT_EQ(c.body, "base");
      EXPECT_EQ(c.box, 1);
      EXPECT_GT(c.t_s, t_star);
      EXPECT_LE(c.t_s, t_star + kDt + 1e-12);
      EXPECT_NEAR(c.depth_m, v * t + model_.base_cylinder.radius_m - face_x, 1e-9);
    }
    if (t > t_star) {  // every step after t* is in contact, at the analytic depth
      ASSERT_EQ(monitor.active().size(), 1u) << t;
      EXPECT_NEAR(monitor.active()[0].depth_m, v * t + 0.4 - face_x, 1e-9);
    }
  }
  EXPECT_EQ(reported, 1);
  const CollisionMonitor::Counts& counts = monitor.counts();
  EXPECT_EQ(counts.events, 1);
  EXPECT_EQ(counts.steps, 2651);
  EXPECT_GT(counts.first_contact_t_s, t_star);
  EXPECT_LE(counts.first_contact_t_s, t_star + kDt + 1e-12);
  EXPECT_NEAR(counts.max_depth_m, v * 2650 * kDt + 0.4 - face_x, 1e-9);  // 5 cm
  EXPECT_EQ(counts.steps_in_contact, counts.steps - static_cast<std::int64_t>(
                                                        std::floor(t_star / kDt + 1e-9)) - 1);
  ASSERT_EQ(monitor.events().size(), 1u);
  EXPECT_TRUE(monitor.events()[0].active);
  EXPECT_NE(monitor.Report().find("base vs box 1"), std::string::npos) << monitor.Report();
}

TEST_F(CollisionMonitorTest, ClearDriveReportsNone) {
  // The same drive 1 cm beside the box's side (y face at -1.0 + ... ): never in contact.
  CollisionMonitor monitor(kinematics_);
  monitor.SetWorld({MakeBox({3.0, 1.41, 0.5}, {2.0, 2.0, 1.0}),
                    MakeBox({3.0, -1.41, 0.5}, {2.0, 2.0, 1.0})});
  for (int k = 0; k <= 5000; ++k) {
    const double t = k * kDt;
    EXPECT_TRUE(monitor.Check(State(0.6 * t, 0, 0), t).empty());
  }
  EXPECT_EQ(monitor.counts().events, 0);
  EXPECT_EQ(monitor.counts().steps, 5001);
  EXPECT_EQ(monitor.counts().max_depth_m, 0.0);
  EXPECT_TRUE(std::isnan(monitor.counts().first_contact_t_s));
  EXPECT_EQ(monitor.Report(), "collision monitor: no contact in 5001 steps\n");
}

TEST_F(CollisionMonitorTest, UprightArmIntoATableTop) {
  // A table top (z 0.98..1.02 m) over the upright arm: the spheres at 0.9515 m (r 0.035) and
  // 1.0215 m (r 0.035) of link7 reach into it; the tool sphere (1.1215 m, r 0.08) stays
  // above, the wrist (0.8775 m, r 0.06) below, the base far below.
  CollisionMonitor monitor(kinematics_);
  const OrientedBox top = MakeBox({0.2, 0.1, 1.0}, {1.2, 0.8, 0.04});
  monitor.SetWorld({top});
  const WholeBodyState state = State(0, 0, 0);
  const std::vector<Contact>& started = monitor.Check(state, 0.0);
  std::set<std::string> bodies;
  KinematicsCache cache = kinematics_.MakeCache();
  kinematics_.Update(state, &cache);
  for (const Contact& c : started) {
    bodies.insert(c.body);
    EXPECT_EQ(c.box, 0);
    const int s = std::stoi(c.body.substr(7));
    EXPECT_NEAR(c.depth_m, -SignedDistanceSphereToBox(top, cache.p_WS[s], model_.spheres[s].radius_m),
                1e-12);
  }
  EXPECT_EQ(bodies, (std::set<std::string>{"sphere 9 (link link7)", "sphere 10 (link link7)"}));
  EXPECT_NEAR(monitor.counts().max_depth_m, 0.035 - 0.0015, 1e-9);
}

TEST_F(CollisionMonitorTest, FoldedArmCollidesWithItself) {
  // Fold shoulder and elbow until a self-collision pair overlaps.
  const SelfCollision self(kinematics_);
  KinematicsCache cache = kinematics_.MakeCache();
  Eigen::VectorXd distances(self.num_pairs());
  WholeBodyState folded;
  bool found = false;
  for (double q2 = 0.0; q2 <= 2.26 && !found; q2 += 0.05) {
    for (double q4 = 0.0; q4 <= 2.355 && !found; q4 += 0.05) {
      Eigen::VectorXd q = Eigen::VectorXd::Zero(model_.num_joints());
      q(1) = q2;
      q(3) = q4;
      folded = State(0, 0, 0, q);
      kinematics_.Update(folded, &cache);
      found = self.MinDistance(cache) < -0.01;
    }
  }
  ASSERT_TRUE(found);
  self.Distances(cache, distances);
  std::set<std::string> expected;
  for (int k = 0; k < self.num_pairs(); ++k) {
    if (distances(k) < 0.0) {
      const auto [i, j] = model_.self_collision_pairs[k];
      expected.insert("self: sphere " + std::to_string(i) + " - sphere " + std::to_string(j));
    }
  }
  CollisionMonitorOptions options;
  options.check_chassis = false;
  CollisionMonitor monitor(kinematics_, options);
  monitor.SetWorld({});
  std::set<std::string> reported;
  for (const Contact& c : monitor.Check(folded, 0.0)) {
    reported.insert(c.body);
    EXPECT_EQ(c.box, -1);
    EXPECT_GT(c.depth_m, 0.0);
  }
  EXPECT_EQ(reported, expected);
  EXPECT_NEAR(monitor.counts().max_depth_m, -self.MinDistance(cache), 1e-12);
  // Without the self check, the same state is clear.
  options.check_self = false;
  CollisionMonitor no_self(kinematics_, options);
  no_self.SetWorld({});
  EXPECT_TRUE(no_self.Check(folded, 0.0).empty());
}

TEST_F(CollisionMonitorTest, APersistentContactIsOneEventAndToleranceFiltersShallowOnes) {
  // The base standing 2 cm into a box for 100 steps.
  const std::vector<OrientedBox> boxes = {MakeBox({0.88, 0, 0.25}, {1.0, 1.0, 0.5})};
  CollisionMonitor monitor(kinematics_);
  monitor.SetWorld(boxes);
  for (int k = 0; k < 100; ++k) monitor.Check(State(0, 0, 0), k * kDt);
  EXPECT_EQ(monitor.counts().events, 1);
  EXPECT_EQ(monitor.counts().steps_in_contact, 100);
  ASSERT_EQ(monitor.events().size(), 1u);
  EXPECT_NEAR(monitor.events()[0].max_depth_m, 0.02, 1e-12);
  EXPECT_NEAR(monitor.events()[0].duration_s(), 99 * kDt, 1e-12);
  EXPECT_EQ(monitor.events()[0].steps, 100);
  CollisionMonitorOptions tolerant;
  tolerant.contact_tolerance_m = 0.03;
  CollisionMonitor lenient(kinematics_, tolerant);
  lenient.SetWorld(boxes);
  EXPECT_TRUE(lenient.Check(State(0, 0, 0), 0.0).empty());
  EXPECT_EQ(lenient.Check(State(0.02, 0, 0), kDt).size(), 1u);  // 4 cm deep
  tolerant.contact_tolerance_m = -0.01;
  EXPECT_THROW(CollisionMonitor(kinematics_, tolerant), std::invalid_argument);
}

TEST_F(CollisionMonitorTest, SetWorldChangesTheBoxes) {
  CollisionMonitor monitor(kinematics_);
  EXPECT_TRUE(monitor.Check(State(0, 0, 0), -kDt).empty());  // no world yet: no box
  const OrientedBox box = MakeBox({0.88, 0, 0.25}, {1.0, 1.0, 0.5});
  monitor.SetWorld({box});
  EXPECT_EQ(monitor.Check(State(0, 0, 0), 0.0).size(), 1u);
  monitor.SetWorld({});  // the box disappears: the event ends
  EXPECT_TRUE(monitor.Check(State(0, 0, 0), kDt).empty());
  EXPECT_TRUE(monitor.active().empty());
  EXPECT_FALSE(monitor.events()[0].active);
  // It appears again, now as box 1 behind an unrelated box 0: a new event.
  monitor.SetWorld({MakeBox({-5, -5, 0.5}, {1, 1, 1}), box});
  const std::vector<Contact>& started = monitor.Check(State(0, 0, 0), 2 * kDt);
  ASSERT_EQ(started.size(), 1u);
  EXPECT_EQ(started[0].box, 1);
  EXPECT_EQ(monitor.counts().events, 2);
  EXPECT_EQ(monitor.num_boxes(), 2);
}

TEST_F(CollisionMonitorTest, BadStateThrowsAndCountsNothing) {
  CollisionMonitor monitor(kinematics_);
  monitor.SetWorld({});
  WholeBodyState state = State(0, 0, 0);
  state.yaw_rad = std::nan("");
  EXPECT_THROW(monitor.Check(state, 0.0), std::invalid_argument);
  state.q_rad.resize(3);
  state.yaw_rad = 0.0;
  EXPECT_THROW(monitor.Check(state, 0.0), std::invalid_argument);
  EXPECT_EQ(monitor.counts().steps, 0);
}

TEST_F(CollisionMonitorTest, AClearCheckDoesNotAllocate) {
  CollisionMonitor monitor(kinematics_);
  monitor.SetWorld({MakeBox({2.0, 0, 0.5}, {1, 1, 1}), MakeBox({0, 2.0, 0.5}, {1, 1, 1})});
  monitor.Check(State(0, 0, 0), 0.0);
  int allocations = 0;
  {
    testing::AllocationCounter counter;
    for (int k = 1; k <= 10; ++k) monitor.Check(State(0.01 * k, 0, 0.1 * k), k * kDt);
    allocations = counter.count();
  }
  EXPECT_EQ(allocations, 0);
  EXPECT_EQ(monitor.counts().events, 0);
}

// Against the exact minimum of core's SceneClearanceChecker and a brute-force count over every
// (primitive, box) pair: random states in a cluttered scene.
TEST_F(CollisionMonitorTest, AgreesWithTheExactClearanceOnRandomStates) {
  Rng rng(17);
  Scene scene;
  for (int i = 0; i < 300; ++i) {
    const Eigen::Vector3d size(rng.Uniform(0.1, 0.8), rng.Uniform(0.1, 0.8), rng.Uniform(0.1, 1.2));
    const double bottom = rng.Uniform01() < 0.5 ? 0.0 : rng.Uniform(0.2, 1.0);
    scene.boxes.push_back(MakeBox({rng.Uniform(-6, 6), rng.Uniform(-6, 6), bottom + 0.5 * size.z()},
                                  size, rng.Uniform(-3.2, 3.2)));
  }
  const SceneClearanceChecker checker(kinematics_, scene);
  CollisionMonitor monitor(kinematics_);
  monitor.SetWorld(scene.boxes);
  KinematicsCache cache = kinematics_.MakeCache();
  int states_in_contact = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const WholeBodyState state = testing::RandomState(model_, &rng);
    monitor.Check(state, trial * kDt);
    const SceneClearance clearance = checker.Compute(state);
    double base_depth = 0.0, sphere_depth = 0.0, self_depth = 0.0, chassis_depth = 0.0;
    int box_contacts = 0;
    for (const Contact& c : monitor.active()) {
      double* depth = c.body == "base"                      ? &base_depth
                      : c.body.rfind("sphere", 0) == 0      ? &sphere_depth
                      : c.body.rfind("self", 0) == 0        ? &self_depth
                                                            : &chassis_depth;
      *depth = std::max(*depth, c.depth_m);
      if (c.box >= 0) ++box_contacts;
    }
    EXPECT_NEAR(base_depth, std::max(0.0, -clearance.base_m), 1e-12) << trial;
    EXPECT_NEAR(sphere_depth, std::max(0.0, -clearance.spheres_m), 1e-12) << trial;
    EXPECT_NEAR(self_depth, std::max(0.0, -clearance.self_m), 1e-12) << trial;
    EXPECT_NEAR(chassis_depth, std::max(0.0, -clearance.chassis_m), 1e-12) << trial;
    // Every overlapping (primitive, box) pair is reported, not only the deepest.
    kinematics_.Update(state, &cache);
    const VerticalCylinder base{cache.X_WB.translation().head<2>(), model_.base_cylinder.radius_m,
                                0.0, model_.base_cylinder.height_m};
    int expected = 0;
    for (const OrientedBox& box : scene.boxes) {
      expected += SignedDistanceCylinderToBox(box, base) < 0.0 ? 1 : 0;
      for (std::size_t s = 0; s < model_.spheres.size(); ++s) {
        expected +=
            SignedDistanceSphereToBox(box, cache.p_WS[s], model_.spheres[s].radius_m) < 0.0 ? 1 : 0;
      }
    }
    EXPECT_EQ(box_contacts, expected) << trial;
    states_in_contact += monitor.active().empty() ? 0 : 1;
  }
  EXPECT_GT(states_in_contact, 50);
}

}  // namespace
}  // namespace topay::sim
