#include "core/optimization/sample_penalties.h"

#include <cmath>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/common/random.h"
#include "core/optimization/smooth_penalty.h"
#include "tests/core/optimization/optimization_test_world.h"
#include "tests/core/robot/allocation_counter.h"

namespace topay {
namespace {

using testing::MakeWorld;
using testing::OptimizationWorld;

BaseLimits BenchmarkLimits() {
  BaseLimits limits;
  limits.omega_max_radps = 1.25;
  return limits;
}

PenaltyMask Only(PenaltyTerm term) {
  PenaltyMask mask = NoPenalties();
  mask[static_cast<int>(term)] = true;
  return mask;
}

// Pointers to every scalar of a SampleQuantities, in a fixed order, to perturb them one by one.
std::vector<double*> Scalars(SampleQuantities* q) {
  std::vector<double*> out = {&q->x_m,   &q->y_m,         &q->yaw_rad,    &q->v_mps,
                              &q->a_mps2, &q->omega_radps, &q->beta_radps2};
  for (int k = 0; k < q->q_rad.size(); ++k) out.push_back(&q->q_rad(k));
  for (int k = 0; k < q->qd_radps.size(); ++k) out.push_back(&q->qd_radps(k));
  for (int k = 0; k < q->qdd_radps2.size(); ++k) out.push_back(&q->qdd_radps2(k));
  return out;
}

std::string Name(int i, int n) {
  static const char* kBase[] = {"x", "y", "yaw", "v", "a", "omega", "beta"};
  if (i < 7) return kBase[i];
  const int k = (i - 7) % n;
  const char* kind[] = {"q", "qd", "qdd"};
  return std::string(kind[(i - 7) / n]) + std::to_string(k + 1);
}

class SamplePenaltiesTest : public ::testing::Test {
 protected:
  // The arm's test state: base at (-1.0123, 1.6047), yaw 1.5, ready joints.
  static WholeBodyState ArmState() {
    return testing::MakeState(-1.0123, 1.6047, 1.5, testing::ReadyJoints());
  }
  // A floating 0.3 m cube 0.3 m above the tool sphere (index 11) of ArmState().
  static OrientedBox BoxAboveTool() {
    const RobotModel model = testing::LoadTopayModel();
    const Kinematics kinematics(model);
    KinematicsCache cache = kinematics.MakeCache();
    kinematics.Update(ArmState(), &cache);
    return MakeBox(cache.p_WS[11] + Eigen::Vector3d(0.0, 0.0, 0.3), {0.3, 0.3, 0.3});
  }

  SamplePenaltiesTest()
      : world_(MakeWorld({MakeBox({1.3, 0.07, 0.4}, {0.6, 0.6, 0.8}),  // near the base
                          BoxAboveTool()})),
        penalties_(*world_->kinematics, world_->base_field(), world_->arm_field(),
                   BenchmarkLimits(), SamplePenaltyOptions()) {
    sample_ = penalties_.MakeQuantities();
    sample_.q_rad = testing::ReadyJoints();
  }

  // Expects P > 0 for the current sample and term, and every partial derivative to match
  // a central difference of P.
  void ExpectActiveAndGradientMatches(PenaltyTerm term) {
    penalties_.set_enabled(Only(term));
    SampleQuantities gradient = penalties_.MakeQuantities();
    PenaltyValues costs{};
    const double value = penalties_.Evaluate(sample_, &gradient, &costs);
    ASSERT_GT(value, 0.0) << ToString(term) << " is not active at the test sample";
    EXPECT_NEAR(costs[static_cast<int>(term)], value, 1e-12 * value);
    SampleQuantities perturbed = sample_;
    const std::vector<double*> scalars = Scalars(&perturbed);
    const std::vector<double*> analytic = Scalars(&gradient);
    const int n = static_cast<int>(sample_.q_rad.size());
    constexpr double kStep = 1e-6;
    // Central differences: truncation O(h^2) plus round-off. The constraint values are
    // computed from quantities of order 1 (m, rad, m/s...), so each carries an absolute
    // rounding error of a few eps, which the weight scales: about eps (|P| + rho_c) / h.
    const double weight = SamplePenaltyOptions().Weight(term);
    const double roundoff = 10.0 * 2.2e-16 * (value + weight) / kStep;
    for (std::size_t i = 0; i < scalars.size(); ++i) {
      const double original = *scalars[i];
      *scalars[i] = original + kStep;
      const double plus = penalties_.Evaluate(perturbed, nullptr);
      *scalars[i] = original - kStep;
      const double minus = penalties_.Evaluate(perturbed, nullptr);
      *scalars[i] = original;
      const double numeric = (plus - minus) / (2 * kStep);
      EXPECT_NEAR(*analytic[i], numeric, 1e-6 * std::max(1.0, std::abs(numeric)) + roundoff)
          << ToString(term) << ": d/d" << Name(static_cast<int>(i), n);
    }
  }

  std::unique_ptr<OptimizationWorld> world_;
  SamplePenalties penalties_;
  SampleQuantities sample_;
};

TEST_F(SamplePenaltiesTest, FeasibleSampleHasNoPenalty) {
  sample_.x_m = -2.0;
  sample_.y_m = -2.0;
  sample_.v_mps = 0.5;
  sample_.omega_radps = 0.3;
  sample_.a_mps2 = 0.2;
  sample_.beta_radps2 = -0.5;
  sample_.qd_radps.setConstant(1.0);
  sample_.qdd_radps2.setConstant(-3.0);
  SampleQuantities gradient = penalties_.MakeQuantities();
  EXPECT_EQ(penalties_.Evaluate(sample_, &gradient), 0.0);
  EXPECT_EQ(gradient.v_mps, 0.0);
  EXPECT_EQ(gradient.q_rad.norm(), 0.0);
}

// Eq. (9) against 0.98 x the limits (rate_limit_fraction): v_max' = 0.98, omega_max' = 1.225;
// (0.8, 0.4) gives 0.98 x 0.4 + 1.225 x 0.8 = 1.372 > 0.98 x 1.225 = 1.2005.
TEST_F(SamplePenaltiesTest, VelocityOmegaTermIsTheCoupledConstraint) {
  sample_.x_m = -2.0;
  sample_.v_mps = 0.8;
  sample_.omega_radps = 0.4;
  penalties_.set_enabled(Only(PenaltyTerm::kVelocityOmega));
  const double v_max = 0.98 * 1.0, w_max = 0.98 * 1.25;
  const double u = v_max * 0.4 + w_max * 0.8;
  const double expected =
      300.0 * SmoothPenalty(u * u - v_max * v_max * w_max * w_max, 1e-3).value;
  EXPECT_NEAR(penalties_.Evaluate(sample_, nullptr), expected, 1e-12);
  ExpectActiveAndGradientMatches(PenaltyTerm::kVelocityOmega);
  sample_.omega_radps = -0.4;  // the other sign of eq. (9)
  ExpectActiveAndGradientMatches(PenaltyTerm::kVelocityOmega);
  sample_.v_mps = 0.5;  // 0.98 x 0.4 + 1.225 x 0.5 = 1.0045 < 1.2005
  EXPECT_EQ(penalties_.Evaluate(sample_, nullptr), 0.0);
}

// The feasible sample of FeasibleSampleHasNoPenalty becomes penalised in each tightened
// term, and only there; the gradients of the tightened terms still match.
TEST_F(SamplePenaltiesTest, TighteningMovesEachThreshold) {
  sample_.x_m = -2.0;
  sample_.y_m = -2.0;
  sample_.v_mps = 0.5;
  sample_.omega_radps = 0.3;
  sample_.a_mps2 = 0.7;          // 0.98 x 0.8 = 0.784
  sample_.q_rad(0) = 3.05;       // limit 3.1 - 0.01 margin (about z: no geometry change)
  sample_.qd_radps(2) = 2.2;     // 0.98 x 2.35 = 2.303
  ASSERT_EQ(penalties_.Evaluate(sample_, nullptr), 0.0);
  const auto cost_of = [&](PenaltyTerm term) {
    PenaltyValues costs{};
    penalties_.Evaluate(sample_, nullptr, &costs);
    return costs[static_cast<int>(term)];
  };
  PenaltyTightening tightening;
  tightening.rate_scale = 0.85;  // a_max' = 0.666 < 0.7, q'_max' = 1.958 < 2.2
  penalties_.set_tightening(tightening);
  EXPECT_GT(cost_of(PenaltyTerm::kAcceleration), 0.0);
  EXPECT_GT(cost_of(PenaltyTerm::kJointVelocity), 0.0);
  EXPECT_EQ(cost_of(PenaltyTerm::kJointPosition), 0.0);
  EXPECT_EQ(cost_of(PenaltyTerm::kVelocityOmega), 0.0);
  ExpectActiveAndGradientMatches(PenaltyTerm::kAcceleration);
  penalties_.set_enabled(AllPenalties());  // the gradient check enabled one term only
  tightening = PenaltyTightening();
  tightening.joint_rad = 0.1;  // half range 3.09 - 0.1 = 2.99 < 3.05
  penalties_.set_tightening(tightening);
  EXPECT_GT(cost_of(PenaltyTerm::kJointPosition), 0.0);
  EXPECT_EQ(cost_of(PenaltyTerm::kAcceleration), 0.0);
  ExpectActiveAndGradientMatches(PenaltyTerm::kJointPosition);
  penalties_.set_enabled(AllPenalties());
  // The base at (-2, -2) is 3.5 m from the box near the base: 5 m more clearance.
  tightening = PenaltyTightening();
  tightening.base_m = 5.0;
  penalties_.set_tightening(tightening);
  EXPECT_GT(cost_of(PenaltyTerm::kBaseObstacle), 0.0);
  EXPECT_EQ(cost_of(PenaltyTerm::kJointPosition), 0.0);
  penalties_.set_tightening(PenaltyTightening());
  EXPECT_EQ(penalties_.Evaluate(sample_, nullptr), 0.0);
}

TEST_F(SamplePenaltiesTest, AccelerationTermsGradient) {
  sample_.x_m = -2.0;
  sample_.a_mps2 = -0.93;
  ExpectActiveAndGradientMatches(PenaltyTerm::kAcceleration);
  sample_.beta_radps2 = 1.3;
  ExpectActiveAndGradientMatches(PenaltyTerm::kYawAcceleration);
}

TEST_F(SamplePenaltiesTest, JointTermsGradient) {
  sample_.x_m = -2.0;
  sample_.q_rad(1) = 2.31;   // limit 2.26
  sample_.q_rad(3) = -2.4;   // limit 2.355
  ExpectActiveAndGradientMatches(PenaltyTerm::kJointPosition);
  sample_.qd_radps(2) = -2.6;  // limit 2.35
  ExpectActiveAndGradientMatches(PenaltyTerm::kJointVelocity);
  sample_.qdd_radps2(6) = 7.0;  // limit 6.28
  ExpectActiveAndGradientMatches(PenaltyTerm::kJointAcceleration);
}

TEST_F(SamplePenaltiesTest, BaseObstacleGradient) {
  // The box's face at x = 1.0; the base 0.38 m from it is within 1.05 x 0.4 + margin.
  sample_.x_m = 0.6231;
  sample_.y_m = 0.0123;
  ExpectActiveAndGradientMatches(PenaltyTerm::kBaseObstacle);
  EXPECT_NEAR(penalties_.base_threshold_m(), 1.05 * 0.4 + std::sqrt(2.0) * 0.05, 1e-12);
}

TEST_F(SamplePenaltiesTest, ArmObstacleGradient) {
  // The tool sphere 0.3 m below the floating cube's centre (0.15 m from its face).
  const WholeBodyState state = ArmState();
  sample_.x_m = state.x_m;
  sample_.y_m = state.y_m;
  sample_.yaw_rad = state.yaw_rad;
  ExpectActiveAndGradientMatches(PenaltyTerm::kArmObstacle);
  EXPECT_NEAR(penalties_.sphere_thresholds_m()(2), 1.1 * 0.08 + std::sqrt(3.0) * 0.1, 1e-12);
}

// Self collision and chassis: the first seeded random arm configurations that activate them.
TEST_F(SamplePenaltiesTest, SelfCollisionAndChassisGradients) {
  sample_.x_m = -2.0;
  for (PenaltyTerm term : {PenaltyTerm::kSelfCollision, PenaltyTerm::kChassis}) {
    penalties_.set_enabled(Only(term));
    Rng rng(term == PenaltyTerm::kChassis ? 3 : 2);
    bool found = false;
    for (int draw = 0; draw < 2000 && !found; ++draw) {
      const WholeBodyState random = testing::RandomState(world_->model, &rng);
      sample_.q_rad = random.q_rad;
      sample_.yaw_rad = random.yaw_rad;
      found = penalties_.Evaluate(sample_, nullptr) > 0.0;
    }
    ASSERT_TRUE(found) << ToString(term);
    ExpectActiveAndGradientMatches(term);
  }
}

// The chassis margin (20 mm by default) applies to the spheres the joints can raise: the
// stowed arm (its shoulder sphere a constant 5 mm above the top, link7 37 mm) costs nothing;
// the same margin on the shoulder sphere would cost everywhere with no gradient to follow.
// Folding the wrist down until link7's sphere is within the margin costs.
TEST_F(SamplePenaltiesTest, ChassisMarginLeavesFixedHeightSpheresOutAndHoldsTheRest) {
  penalties_.set_enabled(Only(PenaltyTerm::kChassis));
  ASSERT_EQ(world_->model.stow_q_rad.size(), world_->model.num_joints());
  sample_.x_m = -2.0;
  sample_.q_rad = world_->model.stow_q_rad;
  EXPECT_EQ(penalties_.Evaluate(sample_, nullptr), 0.0);
  const Kinematics& kinematics = *world_->kinematics;
  KinematicsCache cache = kinematics.MakeCache();
  const double top_m = world_->model.base_cylinder.height_m;
  const auto sphere_margin_m = [&](int s) {
    WholeBodyState state = testing::MakeState(sample_.x_m, sample_.y_m, sample_.yaw_rad, sample_.q_rad);
    kinematics.Update(state, &cache);
    return cache.p_WS[s].z() - world_->model.spheres[s].radius_m - top_m;
  };
  EXPECT_NEAR(sphere_margin_m(0), 0.005, 1e-3);  // below the 20 mm margin, yet no cost
  // Lower the wrist (joint 6) in small steps until sphere 11 is within the margin.
  bool lowered = false;
  for (int step = 0; step < 400 && !lowered; ++step) {
    sample_.q_rad(5) += (step % 2 == 0 ? 1 : -1) * 0.005 * (step + 1);
    lowered = sphere_margin_m(11) > 0.0 && sphere_margin_m(11) < 0.015;
  }
  ASSERT_TRUE(lowered) << "no wrist angle put link7's sphere 0-15 mm above the chassis";
  EXPECT_GT(penalties_.Evaluate(sample_, nullptr), 0.0);
  ExpectActiveAndGradientMatches(PenaltyTerm::kChassis);
}

TEST_F(SamplePenaltiesTest, AllTermsTogetherSumTheirParts) {
  sample_.x_m = 0.6231;
  sample_.y_m = 0.0123;
  sample_.v_mps = 1.1;
  sample_.a_mps2 = 0.9;
  sample_.qd_radps(0) = 3.0;
  PenaltyValues costs{};
  SampleQuantities gradient = penalties_.MakeQuantities();
  const double total = penalties_.Evaluate(sample_, &gradient, &costs);
  double sum = 0.0;
  int active = 0;
  for (double c : costs) {
    sum += c;
    active += c > 0.0;
  }
  EXPECT_NEAR(sum, total, 1e-12 * total);
  EXPECT_GE(active, 4);
}

TEST_F(SamplePenaltiesTest, EvaluateDoesNotAllocate) {
  sample_.x_m = 0.6231;
  sample_.q_rad(1) = 2.31;
  SampleQuantities gradient = penalties_.MakeQuantities();
  testing::AllocationCounter counter;
  penalties_.Evaluate(sample_, &gradient);
  EXPECT_EQ(counter.count(), 0);
}

TEST_F(SamplePenaltiesTest, RejectsBadOptionsNamingThem) {
  SamplePenaltyOptions options;
  options.smoothing_mu = 0.0;
  try {
    SamplePenalties bad(*world_->kinematics, world_->base_field(), world_->arm_field(),
                        BenchmarkLimits(), options);
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("smoothing_mu"), std::string::npos) << e.what();
  }
  BaseLimits limits = BenchmarkLimits();
  limits.a_max_mps2 = -1.0;
  EXPECT_THROW(SamplePenalties(*world_->kinematics, world_->base_field(), world_->arm_field(),
                               limits, SamplePenaltyOptions()),
               std::invalid_argument);
}

}  // namespace
}  // namespace topay
