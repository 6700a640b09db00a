#include "tools/topay_bench/plan_trajectory_file.h"

#include <cmath>
#include <stdexcept>

namespace topay::bench {
std::vector<TrajectorySample> SampleForFile(const SampledTrajectory& trajectory,
                                                  double period_s) {
  if (!(period_s >= 1e-4 && period_s <= 10.0)) {
    throw std::invalid_argument("SampleForFile: period_s outside [1e-4, 10] s");
  }
  if (!trajectory.make_sampler || !(trajectory.duration_s >= 0.0)) {
    throw std::invalid_argument("SampleForFile: no trajectory to sample");
  }
  const TrajectorySampler sampler = trajectory.make_sampler();
  TrajectorySample sample = MakeTrajectorySample(trajectory.num_joints);
  std::vector<TrajectorySample> samples;
  const double end_s = trajectory.duration_s;
  for (long k = 0;; ++k) {
    const double t_s = static_cast<double>(k) * period_s;
    const bool last = !(t_s < end_s - 1e-9);
    sampler(last ? end_s : t_s, &sample);
    samples.push_back(sample);
    samples.back().s_m = 0.0;  // integrated below from |v|
    if (samples.size() > 1) {
      const TrajectorySample& prev = samples[samples.size() - 2];
      samples.back().s_m = prev.s_m + 0.5 * (std::abs(prev.v_mps) + std::abs(sample.v_mps)) *
                                          (samples.back().t_s - prev.t_s);
    }
    if (last) break;
  }
  return samples;
}

plan::TrajectoryFile PlanTrajectoryFile(const plan::TrajectoryMetadata& metadata,
                                        const WholeBodyPlanResult& plan, double period_s) {
  plan::TrajectoryFile file;
  file.metadata = metadata;
  file.sample_period_s = period_s;
  if (plan.trajectory) {
    file.pieces = plan::PiecesOf(*plan.trajectory);
    file.samples = plan::SampleTrajectory(*plan.trajectory, period_s);
  } else if (plan.sampled && plan.success()) {
    file.samples = SampleForFile(*plan.sampled, period_s);
  }
  return file;
}

}  // namespace topay::bench
