#include "tools/topay_bench/plan_trajectory_file.h"

#include <cmath>
#include <stdexcept>

namespace topay::bench {
namespace {

plan::TrajectorySample FileSample(const TrajectorySample& s) {
  plan::TrajectorySample out;
  out.t_s = s.t_s;
  out.x_m = s.state.x_m;
  out.y_m = s.state.y_m;
  out.yaw_rad = s.state.yaw_rad;
  out.v_mps = s.v_mps;
  out.omega_radps = s.omega_radps;
  out.a_mps2 = s.a_mps2;
  out.beta_radps2 = s.beta_radps2;
  out.q_rad = s.state.q_rad;
  return out;
}

}  // namespace

std::vector<plan::TrajectorySample> SampleForFile(const SampledTrajectory& trajectory,
                                                  double period_s) {
  if (!(period_s >= 1e-4 && period_s <= 10.0)) {
    throw std::invalid_argument("SampleForFile: period_s outside [1e-4, 10] s");
  }
  if (!trajectory.make_sampler || !(trajectory.duration_s >= 0.0)) {
    throw std::invalid_argument("SampleForFile: no trajectory to sample");
  }
  const TrajectorySampler sampler = trajectory.make_sampler();
  TrajectorySample sample = MakeTrajectorySample(trajectory.num_joints);
  std::vector<plan::TrajectorySample> samples;
  const double end_s = trajectory.duration_s;
  for (long k = 0;; ++k) {
    const double t_s = static_cast<double>(k) * period_s;
    const bool last = !(t_s < end_s - 1e-9);
    sampler(last ? end_s : t_s, &sample);
    samples.push_back(FileSample(sample));
    if (samples.size() > 1) {
      const plan::TrajectorySample& prev = samples[samples.size() - 2];
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
