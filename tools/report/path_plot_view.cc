#include "tools/report/path_plot_view.h"

#include <algorithm>
#include <cmath>

#include "tools/viz/trajectory_drawing.h"

namespace topay::report {

Eigen::AlignedBox2d PathPlotRegion(const RunLog& log, const Scene* scene, const PathPlotOptions& options) {
  Eigen::AlignedBox2d region;  // empty
  if (scene != nullptr) {
    region.extend(scene->bounds_W_m.min().head<2>()).extend(scene->bounds_W_m.max().head<2>());
  } else if (log.map) {
    const Eigen::AlignedBox3d bounds = log.map->geometry.Bounds();
    region.extend(bounds.min().head<2>()).extend(bounds.max().head<2>());
  }
  for (const msgs::RobotStateEstimate& s : log.robot_states) region.extend(Eigen::Vector2d(s.state.x_m, s.state.y_m));
  for (const LoggedTrajectory& t : log.trajectories) {
    for (const Eigen::Vector2d& p : viz::SampleBasePath(t.trajectory, options.planned_sample_period_s)) {
      region.extend(p);
    }
  }
  for (const sim_event_t& e : log.sim_events) {
    if (e.action == sim_event_t::APPEAR && e.has_box) region.extend(Eigen::Vector2d(e.center_m[0], e.center_m[1]));
  }
  if (region.isEmpty()) return {Eigen::Vector2d(-1.0, -1.0), Eigen::Vector2d(1.0, 1.0)};
  return region;
}

viz::ViewTransform PathPlotView(const RunLog& log, const Scene* scene, const PathPlotOptions& options) {
  Eigen::AlignedBox2d region = PathPlotRegion(log, scene, options);
  region.extend(region.min() - Eigen::Vector2d::Constant(options.margin_m));
  region.extend(region.max() + Eigen::Vector2d::Constant(options.margin_m));
  const double longer_m = region.sizes().maxCoeff();
  const double px_per_m =
      options.px_per_m > 0.0 ? options.px_per_m : std::clamp(options.target_map_px / longer_m, 4.0, 200.0);
  const double left_px = std::ceil(viz::MapAxesLeftPx(options.axes));
  return viz::ViewTransform(region, px_per_m, Eigen::Vector2d(left_px, std::round(options.top_px)));
}

int PathPlotWidth(const viz::ViewTransform& view, const PathPlotOptions& options) {
  return static_cast<int>(view.offset_px().x()) + view.width_px() + static_cast<int>(std::round(options.right_px));
}

}  // namespace topay::report
