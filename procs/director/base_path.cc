#include "procs/director/base_path.h"

#include <algorithm>
#include <cmath>

#include "procs/msgs/convert_trajectory.h"
#include "procs/msgs/trajectory_from_message.h"

namespace topay::director {

std::optional<std::size_t> BasePath::IndexAt(std::int64_t utime) const {
  if (p_W_m.empty() || utime < start_utime) return std::nullopt;
  const double t_s = 1e-6 * static_cast<double>(utime - start_utime);
  const auto i = static_cast<std::size_t>(std::floor(t_s / dt_s));
  return std::min(i, p_W_m.size() - 1);
}

std::optional<BasePath> SampleBasePath(const poly_trajectory_t& msg, double dt_s, std::string* error) {
  const std::optional<msgs::PolyTrajectory> poly = msgs::FromMessage(msg, error);
  if (!poly) return std::nullopt;
  const std::optional<ArcYawTrajectory> trajectory = msgs::ToArcYaw(*poly, {}, error);
  if (!trajectory) return std::nullopt;
  BasePath path;
  path.trajectory_id = msg.trajectory_id;
  path.start_utime = msg.start_utime;
  path.dt_s = dt_s;
  TrajectorySample sample = trajectory->MakePoint();
  const double end_s = trajectory->duration_s();
  for (double t = 0.0;; t = std::min(t + dt_s, end_s)) {
    trajectory->Evaluate(t, &sample);
    path.p_W_m.emplace_back(sample.state.x_m, sample.state.y_m);
    if (t >= end_s) break;
  }
  return path;
}

}  // namespace topay::director
