#include "core/planning/informed_joint_sampler.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

namespace topay {
namespace {

TEST(InformedJointSamplerTest, SamplesLieInTheWeightedProlateHyperspheroid) {
  const Eigen::VectorXd q_start = (Eigen::VectorXd(4) << 0.0, 0.5, -1.0, 2.0).finished();
  const Eigen::VectorXd q_goal = (Eigen::VectorXd(4) << 1.0, -0.5, 0.0, 1.5).finished();
  const Eigen::VectorXd weights = (Eigen::VectorXd(4) << 1.0, 4.0, 0.5, 2.0).finished();
  const InformedJointSampler sampler(q_start, q_goal, weights);
  const double c_min = std::sqrt((weights.array() * (q_goal - q_start).array().square()).sum());
  EXPECT_NEAR(sampler.min_cost(), c_min, 1e-12);
  EXPECT_NEAR(sampler.Distance(q_start, q_goal), c_min, 1e-12);

  const double c_max = 1.3 * c_min;
  Rng rng(5);
  Eigen::VectorXd q;
  Eigen::VectorXd mean = Eigen::VectorXd::Zero(4);
  double largest_sum = 0.0;
  const int n = 20000;
  for (int i = 0; i < n; ++i) {
    sampler.Sample(c_max, &rng, &q);
    const double sum = sampler.Distance(q, q_start) + sampler.Distance(q_goal, q);
    ASSERT_LE(sum, c_max * (1.0 + 1e-12));
    EXPECT_TRUE(sampler.InInformedSet(q, c_max));
    largest_sum = std::max(largest_sum, sum);
    mean += q / n;
  }
  // Samples fill the set up to its boundary, centred on the foci's midpoint.
  EXPECT_GT(largest_sum, 0.99 * c_max);
  EXPECT_LT((mean - 0.5 * (q_start + q_goal)).norm(), 0.02);
  EXPECT_FALSE(sampler.InInformedSet(q_start + 2.0 * (q_goal - q_start), c_max));
}

TEST(InformedJointSamplerTest, CoincidentFociGiveABall) {
  const Eigen::VectorXd q = Eigen::VectorXd::Constant(3, 0.2);
  const InformedJointSampler sampler(q, q, Eigen::VectorXd::Ones(3));
  EXPECT_EQ(sampler.min_cost(), 0.0);
  Rng rng(1);
  Eigen::VectorXd sample;
  for (int i = 0; i < 1000; ++i) {
    sampler.Sample(1.0, &rng, &sample);
    EXPECT_LE((sample - q).norm(), 0.5 + 1e-12);  // radius c_max / 2
  }
}

TEST(InformedJointSamplerTest, RejectsMismatchedOrNonPositiveWeights) {
  const Eigen::VectorXd q = Eigen::VectorXd::Zero(3);
  EXPECT_THROW(InformedJointSampler(q, q, Eigen::VectorXd::Ones(2)), std::invalid_argument);
  EXPECT_THROW(InformedJointSampler(q, q, Eigen::VectorXd::Zero(3)), std::invalid_argument);
}

}  // namespace
}  // namespace topay
