// The pose update: the posterior mean's derivatives w.r.t. the prior mean (I - K) and the
// measurement (K) against finite differences; the yaw innovation is wrapped across +-pi; the
// Mahalanobis distance of a 1-sigma error; the covariance shrinks and stays symmetric.

#include "core/estimation/pose_update.h"

#include <cmath>
#include <numbers>

#include <Eigen/LU>
#include <gtest/gtest.h>

#include "core/common/angles.h"

namespace topay {
namespace {

constexpr double kStep = 1e-6;

Eigen::Vector3d Posterior(const Eigen::Vector3d& z, const Eigen::Matrix3d& R, Eigen::Vector3d X, Eigen::Matrix3d P) {
  UpdatePose(z, R, &X, &P);
  return X;
}

TEST(EstimatorPoseUpdate, DerivativesMatchTheGain) {
  const EstimatorOptions o;
  const Eigen::Matrix3d R = PoseMeasurementNoise(o);
  Eigen::Matrix3d P;
  P << 0.02, 0.005, 0.001, 0.005, 0.03, -0.002, 0.001, -0.002, 0.01;
  const Eigen::Vector3d X(1.0, 2.0, 0.5), z(1.05, 1.97, 0.52);
  const Eigen::Matrix3d K = P * (P + R).inverse();
  for (int j = 0; j < 3; ++j) {
    Eigen::Vector3d Xp = X, Xm = X, zp = z, zm = z;
    Xp[j] += kStep;
    Xm[j] -= kStep;
    zp[j] += kStep;
    zm[j] -= kStep;
    const Eigen::Vector3d dX = (Posterior(z, R, Xp, P) - Posterior(z, R, Xm, P)) / (2 * kStep);
    const Eigen::Vector3d dz = (Posterior(zp, R, X, P) - Posterior(zm, R, X, P)) / (2 * kStep);
    EXPECT_LT((dX - (Eigen::Matrix3d::Identity() - K).col(j)).cwiseAbs().maxCoeff(), 1e-7) << j;
    EXPECT_LT((dz - K.col(j)).cwiseAbs().maxCoeff(), 1e-7) << j;
  }
}

TEST(EstimatorPoseUpdate, YawInnovationIsWrapped) {
  const Eigen::Vector3d X(0.0, 0.0, std::numbers::pi - 0.01);
  const Eigen::Vector3d z(0.0, 0.0, -std::numbers::pi + 0.01);
  EXPECT_NEAR(PoseInnovation(z, X).z(), 0.02, 1e-12);
  Eigen::Vector3d Xu = X;
  Eigen::Matrix3d P = Eigen::Matrix3d::Identity() * 0.01;
  UpdatePose(z, PoseMeasurementNoise(EstimatorOptions{}), &Xu, &P);
  // Moves towards z across the cut (not the long way round) and stays wrapped.
  EXPECT_GT(std::abs(Xu.z()), std::numbers::pi - 0.01);
  EXPECT_LE(std::abs(Xu.z()), std::numbers::pi);
}

TEST(EstimatorPoseUpdate, MahalanobisAndCovariance) {
  const EstimatorOptions o;
  const Eigen::Matrix3d R = PoseMeasurementNoise(o);
  const Eigen::Matrix3d P = R;  // S = 2 R
  const Eigen::Vector3d nu(std::sqrt(2.0) * o.pose_xy_stddev_m, 0.0, 0.0);  // 1 sigma of S along x
  EXPECT_NEAR(PoseMahalanobis2(nu, P, R), 1.0, 1e-12);
  Eigen::Vector3d X = Eigen::Vector3d::Zero();
  Eigen::Matrix3d Pu = P;
  UpdatePose(nu, R, &X, &Pu);
  EXPECT_NEAR(X.x(), nu.x() / 2, 1e-12);  // equal weights: halfway
  EXPECT_LT((Pu - R / 2).cwiseAbs().maxCoeff(), 1e-15);  // two equal informations
  EXPECT_EQ((Pu - Pu.transpose()).norm(), 0.0);
}

}  // namespace
}  // namespace topay
