#include "core/planning/base_reachability.h"

#include <cmath>
#include <limits>
#include <random>

#include <gtest/gtest.h>

#include "core/robot/kinematics.h"
#include "core/robot/whole_body_ik.h"
#include "tests/common/make_box.h"
#include "tests/core/robot/robot_test_model.h"

namespace topay {
namespace {

// A 6 x 4 m room (walls 0.1 m thick, 1 m tall) split at x = 0 by a divider `thickness_m`
// thick from `wall_bottom_m` to `wall_top_m`, with one gap of `gap_m` centred at y = 0.
Scene SplitRoom(double gap_m, double wall_bottom_m = 0.0, double wall_top_m = 1.0,
                double thickness_m = 0.1) {
  Scene s;
  s.bounds_W_m = Eigen::AlignedBox3d(Eigen::Vector3d(-3, -2, 0), Eigen::Vector3d(3, 2, 1.6));
  s.boxes.push_back(MakeBox({0, 1.95, 0.5}, {6, 0.1, 1}));
  s.boxes.push_back(MakeBox({0, -1.95, 0.5}, {6, 0.1, 1}));
  s.boxes.push_back(MakeBox({2.95, 0, 0.5}, {0.1, 4, 1}));
  s.boxes.push_back(MakeBox({-2.95, 0, 0.5}, {0.1, 4, 1}));
  const double half_wall = 0.5 * (4.0 - gap_m);  // each side piece, from the gap to a wall
  const double height = wall_top_m - wall_bottom_m, z = wall_bottom_m + 0.5 * height;
  if (gap_m == 0.0) {  // one box: two touching ones would leave a seam of zero distance
    s.boxes.push_back(MakeBox({0, 0, z}, {thickness_m, 4.0, height}));
    return s;
  }
  s.boxes.push_back(
      MakeBox({0, 0.5 * gap_m + 0.5 * half_wall, z}, {thickness_m, half_wall, height}));
  s.boxes.push_back(
      MakeBox({0, -0.5 * gap_m - 0.5 * half_wall, z}, {thickness_m, half_wall, height}));
  return s;
}

const Eigen::Vector2d kLeft(-1.5, 0.3), kRight(1.5, -0.3);

// The TopAY robot: chassis r = 0.40 m to 0.155 m; rigid spheres up to 0.4915 m, the shoulder
// sphere (r = 0.08 m) centred at 0.4115 m, 0.115 m off the base axis.
class BaseReachabilityTest : public ::testing::Test {
 protected:
  BaseReachabilityTest() : model_(testing::LoadTopayModel()), kinematics_(model_) {}
  BaseReachability Certify(const Scene& s, const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                           const BaseReachabilityOptions& o = {}) const {
    return CertifyBaseUnreachable(s, kinematics_, a, b, o);
  }
  RobotModel model_;
  Kinematics kinematics_;
};

TEST_F(BaseReachabilityTest, AGapWiderThanTheChassisIsNotExcluded) {
  const BaseReachability r = Certify(SplitRoom(0.84), kLeft, kRight);
  EXPECT_FALSE(r.certified_unreachable) << r.reason;
  EXPECT_GT(r.component_cells, 0);
}

TEST_F(BaseReachabilityTest, AGapNarrowerThanTheChassisCertifiesUnreachable) {
  // 0.70 m < 2 (r - 0.05 / sqrt 2) = 0.729 m: no cell chain through the gap.
  const BaseReachability r = Certify(SplitRoom(0.70), kLeft, kRight);
  EXPECT_TRUE(r.certified_unreachable) << r.reason;
  EXPECT_NE(r.reason.find("no chain"), std::string::npos);
  // Both on one side: reachable.
  EXPECT_FALSE(Certify(SplitRoom(0.70), kLeft, {-0.8, -1.2})
                   .certified_unreachable);
}

TEST_F(BaseReachabilityTest, APocketInsideTheWindowIsCertifiedEnclosed) {
  // The left half of SplitRoom(0.70) is shut: the base centre stays in x ~ [-2.5, -0.45],
  // y ~ [-1.5, 1.5] (0.40 m from the walls and the divider). A window of half side 2.5 m
  // around kLeft (-1.5, 0.3) holds all of it, one of 1.0 m does not (its borders
  // y = -0.7 and y = 1.3 cross the half).
  const BaseReachability shut =
      CertifyBaseEnclosed(SplitRoom(0.70), kinematics_, kLeft, 2.5);
  EXPECT_TRUE(shut.certified_unreachable) << shut.reason;
  EXPECT_NE(shut.reason.find("pocket"), std::string::npos) << shut.reason;
  EXPECT_GT(shut.component_cells, 0);
  // The same cells as the whole-room test: its component from kLeft has the same size.
  EXPECT_EQ(shut.component_cells, Certify(SplitRoom(0.70), kLeft, kRight).component_cells);
  EXPECT_FALSE(CertifyBaseEnclosed(SplitRoom(0.70), kinematics_, kLeft, 1.0)
                   .certified_unreachable);
  // Through a gap wider than the chassis the base leaves the window.
  EXPECT_FALSE(CertifyBaseEnclosed(SplitRoom(0.84), kinematics_, kLeft, 2.5)
                   .certified_unreachable);
  // A base inside the divider is not allowed at all.
  const BaseReachability inside =
      CertifyBaseEnclosed(SplitRoom(0.70), kinematics_, {0.0, 1.5}, 1.0);
  EXPECT_TRUE(inside.certified_unreachable);
  EXPECT_NE(inside.reason.find("not allowed"), std::string::npos) << inside.reason;
  EXPECT_THROW(CertifyBaseEnclosed(SplitRoom(0.70), kinematics_, kLeft, 0.0),
               std::invalid_argument);
  EXPECT_THROW(CertifyBaseEnclosed(SplitRoom(0.70), kinematics_,
                                   {std::numeric_limits<double>::quiet_NaN(), 0.0}, 1.0),
               std::invalid_argument);
}

// CertifyBaseOpen proves a way out only through passages with the clearance to spare; a
// gap within a centimetre of the chassis' width (0.80 m) is neither proven open nor proven
// shut. (The cell centres nearest the gap's middle are 5 mm off it.)
TEST_F(BaseReachabilityTest, AWayOutMustKeepThePassageClearance) {
  const double window_m = 2.5;
  BaseOpennessOptions openness;  // 1 cm to spare
  // 0.86 m: 0.43 - 0.005 m from either side >= 0.40 + 0.01 + half a cell diagonal (0.007).
  EXPECT_FALSE(CertifyBaseOpen(SplitRoom(0.86), kinematics_, kLeft, window_m, openness)
                   .certified_unreachable);
  // 0.83 m: 0.41 m is not 0.417 m; the lenient test does not shut it either.
  const BaseReachability narrow =
      CertifyBaseOpen(SplitRoom(0.83), kinematics_, kLeft, window_m, openness);
  EXPECT_TRUE(narrow.certified_unreachable) << narrow.reason;
  EXPECT_NE(narrow.reason.find("no way out"), std::string::npos) << narrow.reason;
  EXPECT_FALSE(
      CertifyBaseEnclosed(SplitRoom(0.83), kinematics_, kLeft, window_m).certified_unreachable);
  // Without spare clearance it is enough (0.41 m >= 0.407 m).
  openness.clearance_m = 0.0;
  EXPECT_FALSE(CertifyBaseOpen(SplitRoom(0.83), kinematics_, kLeft, window_m, openness)
                   .certified_unreachable);
  // A shut pocket is never proven open.
  EXPECT_TRUE(CertifyBaseOpen(SplitRoom(0.70), kinematics_, kLeft, window_m, openness)
                  .certified_unreachable);
}

// A base 3 mm from a wall leaves through the lenient cells of its approach radius; without
// that radius its own cell keeps less than the clearance and nothing is proven.
TEST_F(BaseReachabilityTest, ATightEndLeavesThroughItsApproach) {
  const Eigen::Vector2d p_tight(-2.9 + 0.40 + 0.003, 0.3);  // the left wall's face is x = -2.9
  BaseOpennessOptions openness;
  EXPECT_FALSE(CertifyBaseOpen(SplitRoom(0.86), kinematics_, p_tight, 2.5, openness)
                   .certified_unreachable);
  openness.approach_radius_m = 0.0;
  const BaseReachability stuck =
      CertifyBaseOpen(SplitRoom(0.86), kinematics_, p_tight, 2.5, openness);
  EXPECT_TRUE(stuck.certified_unreachable);
  EXPECT_NE(stuck.reason.find("not allowed"), std::string::npos) << stuck.reason;
  openness.clearance_m = -0.01;
  EXPECT_THROW(CertifyBaseOpen(SplitRoom(0.86), kinematics_, kLeft, 2.5, openness),
               std::invalid_argument);
  EXPECT_THROW(CertifyBaseOpen(SplitRoom(0.86), kinematics_, kLeft, 0.0), std::invalid_argument);
}

// ProvenBaseRegion: the room-wide version, from a start to any end.
TEST_F(BaseReachabilityTest, TheProvenRegionCrossesOnlyGapsWithTheClearance) {
  // (The region keeps a pointer to its scene: the scenes must outlive it.)
  const Scene wide_gap = SplitRoom(0.86), narrow_gap = SplitRoom(0.83), shut = SplitRoom(0.70);
  const ProvenBaseRegion wide(wide_gap, kinematics_, kLeft);
  EXPECT_GT(wide.num_cells(), 0);
  EXPECT_TRUE(wide.Reaches(kRight));
  EXPECT_TRUE(wide.Reaches({-0.8, -1.2}));
  const ProvenBaseRegion narrow(narrow_gap, kinematics_, kLeft);
  EXPECT_FALSE(narrow.Reaches(kRight));
  EXPECT_TRUE(narrow.Reaches({-0.8, -1.2}));  // same side
  EXPECT_FALSE(ProvenBaseRegion(shut, kinematics_, kLeft).Reaches(kRight));
  // An end 3 mm from the right wall: reached through its approach disc.
  const Eigen::Vector2d p_tight(2.9 - 0.40 - 0.003, -0.3);
  EXPECT_TRUE(wide.Reaches(p_tight));
  BaseOpennessOptions no_approach;
  no_approach.approach_radius_m = 0.0;
  EXPECT_FALSE(ProvenBaseRegion(wide_gap, kinematics_, kLeft, no_approach).Reaches(p_tight));
  // Inside the divider, or outside the room: never.
  EXPECT_FALSE(wide.Reaches({0.0, 1.5}));
  EXPECT_FALSE(wide.Reaches({10.0, 0.0}));
  EXPECT_THROW(ProvenBaseRegion(wide_gap, kinematics_,
                                {std::numeric_limits<double>::quiet_NaN(), 0.0}),
               std::invalid_argument);
}

TEST_F(BaseReachabilityTest, AGoalDiscReachingTheStartsSideIsNotExcluded) {
  // Left cells end at x = -(0.40 - 0.01 / sqrt 2 + 0.05) ~ -0.44 m; kRight is at x = 1.5.
  BaseReachabilityOptions o;
  o.goal_radius_m = 1.5;  // the disc ends at x = 0: still the far side
  EXPECT_TRUE(Certify(SplitRoom(0.70), kLeft, kRight, o).certified_unreachable);
  o.goal_radius_m = 2.2;  // the disc crosses the divider
  EXPECT_FALSE(Certify(SplitRoom(0.70), kLeft, kRight, o).certified_unreachable);
  o.goal_radius_m = -0.1;
  EXPECT_THROW(Certify(SplitRoom(0.70), kLeft, kRight, o), std::invalid_argument);
}

TEST_F(BaseReachabilityTest, AGoalDiscLeavingTheBoundsJoinsTheOutside) {
  // A 6 x 4 m map without walls but one along its top edge; the goal sits in a pen closed by
  // that wall. The start's fill reaches the open bottom border, hence the (free) outside.
  Scene s;
  s.bounds_W_m = Eigen::AlignedBox3d(Eigen::Vector3d(-3, -2, 0), Eigen::Vector3d(3, 2, 1.6));
  s.boxes.push_back(MakeBox({0, 1.95, 0.5}, {6, 0.1, 1}));      // top edge
  s.boxes.push_back(MakeBox({0, 0.5, 0.5}, {2.1, 0.1, 1}));     // pen, bottom
  s.boxes.push_back(MakeBox({-1.0, 1.25, 0.5}, {0.1, 1.5, 1}));  // pen, sides
  s.boxes.push_back(MakeBox({1.0, 1.25, 0.5}, {0.1, 1.5, 1}));
  const Eigen::Vector2d start(-1.5, -1.0), goal(0.0, 1.2);
  BaseReachabilityOptions o;
  o.goal_radius_m = 0.5;  // inside the map: only the pen's cells, none reached
  EXPECT_TRUE(Certify(s, start, goal, o).certified_unreachable);
  o.goal_radius_m = 0.95;  // leaves the map at the top, where the outside counts as reached
  EXPECT_FALSE(Certify(s, start, goal, o).certified_unreachable);
}

TEST_F(BaseReachabilityTest, ATargetOnlyReachableFromTheFarSideIsCertified) {
  const WholeBodyIk ik(kinematics_);
  const double radius_m = ik.p_BS().head<2>().norm() + ik.shoulder_to_wrist_reach_m();
  ASSERT_LT(radius_m, 2.0);
  // Wrist centre at x: the goal disc spans [x - radius, x + radius].
  auto target_at = [&](double x) {
    Eigen::Isometry3d X_WE = Eigen::Isometry3d::Identity();
    X_WE.translation() = Eigen::Vector3d(x, 0.0, 0.6);
    X_WE.translation() -= X_WE.linear() * ik.p_EW();
    return X_WE;
  };
  const Scene room = SplitRoom(0.70);
  const double far_x = std::min(radius_m + 0.5, 2.8);
  const BaseReachability far = CertifyTargetUnreachable(room, kinematics_, kLeft, target_at(far_x));
  EXPECT_EQ(far.certified_unreachable, far_x - radius_m > 0.0) << far.reason;
  EXPECT_TRUE(far.certified_unreachable) << "radius " << radius_m;
  // Just beyond the divider: the arm reaches over it from the left.
  EXPECT_FALSE(CertifyTargetUnreachable(room, kinematics_, kLeft, target_at(0.3))
                   .certified_unreachable);
  Eigen::Isometry3d bad = target_at(1.0);
  bad.translation().x() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(CertifyTargetUnreachable(room, kinematics_, kLeft, bad), std::invalid_argument);
}

TEST_F(BaseReachabilityTest, OnlyWhatTheRigidLowerBodyMeetsBlocks) {
  // A divider from 0.1 m meets the chassis: blocked.
  EXPECT_TRUE(Certify(SplitRoom(0.0, 0.1), kLeft, kRight).certified_unreachable);
  // A 1 m deep table top from 0.45 to 0.5 m: the shoulder sphere (top 0.4915 m) cannot pass
  // under it, wherever its centre lies within 0.115 m of the base axis.
  EXPECT_TRUE(Certify(SplitRoom(0.0, 0.45, 0.5, 1.0), kLeft, kRight).certified_unreachable);
  // The same top from 0.55 m: the rigid body passes under it.
  EXPECT_FALSE(Certify(SplitRoom(0.0, 0.55, 0.6, 1.0), kLeft, kRight).certified_unreachable);
  // A 0.1 m thick divider from 0.2 m: with the base centre in its middle, the shoulder
  // sphere (r 0.08 m, at most 0.115 m off the axis) would reach into it. Blocked.
  EXPECT_TRUE(Certify(SplitRoom(0.0, 0.2), kLeft, kRight).certified_unreachable);
  // A 2 cm thick one is not excluded, though no real motion passes it: the test lets the yaw
  // jump, so it only sees each base position alone. It under-claims, never over-claims.
  EXPECT_FALSE(Certify(SplitRoom(0.0, 0.2, 1.0, 0.02), kLeft, kRight).certified_unreachable);
}

TEST_F(BaseReachabilityTest, TheOutsideOfTheBoundsJoinsTheBorder) {
  // No outer walls: a wall across the whole bounds can be driven around outside them.
  Scene s;
  s.bounds_W_m = Eigen::AlignedBox3d(Eigen::Vector3d(-3, -2, 0), Eigen::Vector3d(3, 2, 1.6));
  s.boxes.push_back(MakeBox({0, 0, 0.5}, {0.1, 4.0, 1.0}));
  EXPECT_FALSE(Certify(s, kLeft, kRight).certified_unreachable);
  // Start or goal outside the bounds: not tested, not certified.
  const BaseReachability out = Certify(s, kLeft, {9.0, 0.0});
  EXPECT_FALSE(out.certified_unreachable);
  EXPECT_NE(out.reason.find("outside"), std::string::npos);
}

TEST_F(BaseReachabilityTest, AStartInCollisionIsUnreachable) {
  const BaseReachability r =
      Certify(SplitRoom(0.84), {0.0, 1.5}, kRight);
  EXPECT_TRUE(r.certified_unreachable);
  EXPECT_NE(r.reason.find("start"), std::string::npos);
}

TEST_F(BaseReachabilityTest, BadInputThrows) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(Certify(SplitRoom(0.84), {nan, 0.0}, kRight),
               std::invalid_argument);
  BaseReachabilityOptions o;
  o.resolution_m = 0.0;
  EXPECT_THROW(Certify(SplitRoom(0.84), kLeft, kRight, o),
               std::invalid_argument);
}

// Soundness: whenever a straight motion between two random positions keeps the chassis clear
// (checked at 5 mm steps against the exact footprints), the pair must not be certified.
TEST_F(BaseReachabilityTest, NoClearStraightMotionIsEverCertified) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-4.5, 4.5), side(0.2, 0.9), yaw(-M_PI, M_PI);
  int clear_pairs = 0, certified = 0;
  for (int scene_index = 0; scene_index < 10; ++scene_index) {
    Scene s;
    s.bounds_W_m = Eigen::AlignedBox3d(Eigen::Vector3d(-5, -5, 0), Eigen::Vector3d(5, 5, 1.6));
    for (int b = 0; b < 25; ++b) {
      s.boxes.push_back(MakeBox({u(rng), u(rng), 0.5}, {side(rng), side(rng), 1.0}, yaw(rng)));
    }
    auto clearance = [&](const Eigen::Vector2d& p) {
      double d = std::numeric_limits<double>::infinity();
      for (const OrientedBox& box : s.boxes) d = std::min(d, SignedDistanceToFootprint(box, p));
      return d;
    };
    for (int k = 0; k < 60; ++k) {
      const Eigen::Vector2d a(u(rng), u(rng)), b(u(rng), u(rng));
      const int steps = static_cast<int>(std::ceil((b - a).norm() / 0.005));
      bool clear = true;
      for (int i = 0; i <= steps && clear; ++i) {
        clear = clearance(a + (b - a) * (double(i) / steps)) >= model_.base_cylinder.radius_m;
      }
      const bool cert = Certify(s, a, b).certified_unreachable;
      certified += cert;
      if (!clear) continue;
      ++clear_pairs;
      EXPECT_FALSE(cert) << "scene " << scene_index << " pair " << k;
    }
  }
  EXPECT_GT(clear_pairs, 30);  // the test exercised the claim
  EXPECT_GT(certified, 0);     // and the certificate does fire on these scenes
}

}  // namespace
}  // namespace topay
