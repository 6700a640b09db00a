// The analytic Jacobians of the NMPC's residuals (base: rollout, wrapped yaw, rates, hinges,
// coupled bound; joints) against central finite differences.

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "core/control/base_tracking_cost.h"
#include "core/control/joint_tracking_cost.h"
#include "core/control/unicycle_rollout.h"
#include "core/common/random.h"
#include "tests/core/control/control_test_support.h"

namespace topay {
namespace {

using testing::kJoints;
using testing::TopayLimits;
using RowMajor = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

// Central differences of cost's residuals at x (one parameter block).
RowMajor NumericJacobian(const ceres::CostFunction& cost, const Eigen::VectorXd& x) {
  const int m = cost.num_residuals();
  RowMajor J(m, x.size());
  Eigen::VectorXd plus(m), minus(m);
  for (int i = 0; i < x.size(); ++i) {
    const double h = 1e-6;
    Eigen::VectorXd xp = x, xm = x;
    xp(i) += h;
    xm(i) -= h;
    const double* pp = xp.data();
    const double* pm = xm.data();
    cost.Evaluate(&pp, plus.data(), nullptr);
    cost.Evaluate(&pm, minus.data(), nullptr);
    J.col(i) = (plus - minus) / (2 * h);
  }
  return J;
}

RowMajor AnalyticJacobian(const ceres::CostFunction& cost, const Eigen::VectorXd& x,
                          Eigen::VectorXd* residuals) {
  RowMajor J(cost.num_residuals(), x.size());
  residuals->resize(cost.num_residuals());
  const double* p = x.data();
  double* jacobians[1] = {J.data()};
  EXPECT_TRUE(cost.Evaluate(&p, residuals->data(), jacobians));
  return J;
}

ReferenceHorizon RandomReference(int steps, Rng* rng) {
  ReferenceHorizon reference = ReferenceHorizon::Zero(steps, kJoints);
  for (int k = 0; k <= steps; ++k) {
    reference.pose.col(k) << 0.03 * k + rng->Uniform(-0.2, 0.2), rng->Uniform(-0.2, 0.2),
        rng->Uniform(-0.5, 0.5);
    for (int j = 0; j < kJoints; ++j) reference.q_rad(j, k) = rng->Uniform(-1.0, 1.0);
    if (k == steps) break;
    reference.u_base.col(k) << rng->Uniform(-1.0, 1.0), rng->Uniform(-1.0, 1.0);
    for (int j = 0; j < kJoints; ++j) reference.qd_radps(j, k) = rng->Uniform(-2.0, 2.0);
  }
  return reference;
}

TEST(TrackingCostJacobianTest, BaseResidualsMatchCentralDifferences) {
  NmpcOptions options;
  options.horizon_steps = 12;
  options.cross_track_weight = 700.0;  // unlike position_weight: the rows in the reference's frame
  const TrackerLimits limits = TopayLimits();
  Rng rng(19);
  int active_hinges = 0;
  for (int trial = 0; trial < 20; ++trial) {
    const ReferenceHorizon reference = RandomReference(options.horizon_steps, &rng);
    BaseTrackingCost cost(options, limits);
    cost.SetProblem(Eigen::Vector3d(rng.Uniform(-1, 1), rng.Uniform(-1, 1), rng.Uniform(-0.5, 0.5)),
                    &reference, Eigen::Vector2d(rng.Uniform(-1, 1), rng.Uniform(-1, 1)));
    // Random inputs: large jumps (rate hinges active) and beyond the diamond (coupled active).
    Eigen::VectorXd u(2 * options.horizon_steps);
    for (int i = 0; i < u.size(); ++i) u(i) = rng.Uniform(-1.0, 1.0);
    Eigen::VectorXd residuals;
    const RowMajor analytic = AnalyticJacobian(cost, u, &residuals);
    const RowMajor numeric = NumericJacobian(cost, u);
    const int N = options.horizon_steps;
    for (int k = 1; k < N; ++k) {  // rates beyond their limits, coupled bound exceeded
      active_hinges += std::abs(u(2 * k) - u(2 * k - 2)) / options.step_s > limits.base.a_max_mps2;
    }
    active_hinges += (residuals.tail(N).array() > 0.0).count();
    const double error = (analytic - numeric).cwiseAbs().maxCoeff();
    EXPECT_LT(error, 1e-5 * std::max(1.0, numeric.cwiseAbs().maxCoeff())) << "trial " << trial;
  }
  EXPECT_GT(active_hinges, 0);  // the hinge rows were exercised
}

// The position rows measure the error in the reference's frame: along its heading with
// position_weight, across it with cross_track_weight; equal weights give the world-frame error.
TEST(TrackingCostJacobianTest, PositionErrorIsWeightedAlongAndAcrossTheReferenceHeading) {
  NmpcOptions options;
  options.horizon_steps = 2;
  options.position_weight = 100.0;
  options.cross_track_weight = 400.0;
  ReferenceHorizon reference = ReferenceHorizon::Zero(2, kJoints);
  const double yaw_ref = 0.7;
  for (int k = 0; k <= 2; ++k) reference.pose.col(k) << 1.0, 2.0, yaw_ref;
  const Eigen::Vector2d along(std::cos(yaw_ref), std::sin(yaw_ref));
  const Eigen::Vector2d across(-std::sin(yaw_ref), std::cos(yaw_ref));
  const Eigen::VectorXd u = Eigen::VectorXd::Zero(4);  // standing still at x0
  const auto position_cost = [&](const NmpcOptions& o, const Eigen::Vector2d& offset) {
    BaseTrackingCost cost(o, TopayLimits());
    const Eigen::Vector2d p = reference.pose.block<2, 1>(0, 1) + offset;
    cost.SetProblem(Eigen::Vector3d(p.x(), p.y(), yaw_ref), &reference, Eigen::Vector2d::Zero());
    Eigen::VectorXd r(cost.num_residuals());
    const double* x = u.data();
    cost.Evaluate(&x, r.data(), nullptr);
    return r(0) * r(0) + r(1) * r(1);  // the first node's position rows (factor 1)
  };
  EXPECT_NEAR(position_cost(options, 0.1 * along), 100.0 * 0.01, 1e-12);
  EXPECT_NEAR(position_cost(options, 0.1 * across), 400.0 * 0.01, 1e-12);
  NmpcOptions equal = options;
  equal.cross_track_weight = equal.position_weight;
  const Eigen::Vector2d offset(0.03, -0.08);
  EXPECT_NEAR(position_cost(equal, offset), 100.0 * offset.squaredNorm(), 1e-12);
}

TEST(TrackingCostJacobianTest, RolloutJacobianMatchesCentralDifferences) {
  Rng rng(3);
  const int N = 10;
  const double dt = 0.04;
  Eigen::Matrix2Xd u(2, N);
  for (int k = 0; k < N; ++k) u.col(k) << rng.Uniform(-1, 1), rng.Uniform(-1, 1);
  const Eigen::Vector3d x0(0.3, -0.2, 1.0);
  Eigen::Matrix3Xd states(3, N + 1);
  RolloutUnicycle(x0, u, dt, &states);
  Eigen::MatrixXd J(3 * N, 2 * N);
  RolloutJacobian(states, u, dt, &J);
  Eigen::Matrix3Xd plus(3, N + 1), minus(3, N + 1);
  for (int i = 0; i < 2 * N; ++i) {
    const double h = 1e-6;
    Eigen::Matrix2Xd up = u, um = u;
    up(i % 2, i / 2) += h;
    um(i % 2, i / 2) -= h;
    RolloutUnicycle(x0, up, dt, &plus);
    RolloutUnicycle(x0, um, dt, &minus);
    const Eigen::Matrix3Xd d = (plus - minus).rightCols(N) / (2 * h);
    for (int j = 0; j < N; ++j) {
      for (int r = 0; r < 3; ++r) EXPECT_NEAR(J(3 * j + r, i), d(r, j), 1e-7);
    }
  }
  // A straight step is exact: v dt along the heading.
  Eigen::Matrix2Xd straight = Eigen::Matrix2Xd::Zero(2, 1);
  straight(0, 0) = 1.0;
  Eigen::Matrix3Xd one(3, 2);
  RolloutUnicycle(Eigen::Vector3d(0, 0, 0.5), straight, 0.1, &one);
  EXPECT_NEAR(one(0, 1), 0.1 * std::cos(0.5), 1e-15);
  EXPECT_NEAR(one(1, 1), 0.1 * std::sin(0.5), 1e-15);
}

TEST(TrackingCostJacobianTest, JointResidualsMatchCentralDifferences) {
  NmpcOptions options;
  options.horizon_steps = 15;
  Rng rng(5);
  int active_hinges = 0;
  for (int trial = 0; trial < 10; ++trial) {
    const ReferenceHorizon reference = RandomReference(options.horizon_steps, &rng);
    const int joint = trial % kJoints;
    JointTrackingCost cost(options, joint, 6.28);
    cost.SetProblem(rng.Uniform(-1, 1), &reference, rng.Uniform(-2, 2));
    Eigen::VectorXd qd(options.horizon_steps);
    for (int k = 0; k < qd.size(); ++k) qd(k) = rng.Uniform(-2.3, 2.3);
    Eigen::VectorXd residuals;
    const RowMajor analytic = AnalyticJacobian(cost, qd, &residuals);
    const RowMajor numeric = NumericJacobian(cost, qd);
    for (int k = 1; k < qd.size(); ++k) {
      active_hinges += std::abs(qd(k) - qd(k - 1)) / options.step_s > 6.28;
    }
    EXPECT_LT((analytic - numeric).cwiseAbs().maxCoeff(),
              1e-5 * std::max(1.0, numeric.cwiseAbs().maxCoeff()));
  }
  EXPECT_GT(active_hinges, 0);
}

}  // namespace
}  // namespace topay
