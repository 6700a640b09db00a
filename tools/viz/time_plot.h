#pragma once

#include <Eigen/Core>
#include <string>
#include <vector>

#include "core/robot/robot_model.h"
#include "core/trajectory/arc_yaw_trajectory.h"
#include "tools/viz/image.h"
#include "tools/viz/line_chart.h"

namespace topay::viz {

/// The quantities the time plots show, sampled at the times t_s (every vector as long as t_s;
/// q_rad[k] is joint k + 1 over time).
struct TimePlotData {
  std::vector<double> t_s;
  std::vector<double> v_mps;
  std::vector<double> omega_radps;
  std::vector<double> a_mps2;
  std::vector<double> beta_radps2;
  std::vector<std::vector<double>> q_rad;
};

/// Samples a trajectory for the plots at t = 0, period, 2 period, ... and at its exact end
/// (ArcYawTrajectory::Evaluate). Throws std::invalid_argument for a period that is not in
/// [1e-4, 10] s or a trajectory that has not been solved.
TimePlotData SampleTimePlotData(const ArcYawTrajectory& trajectory, double period_s = 0.01);

/// The limit lines drawn: +-v_max, +-omega_max, +-a_max, +-beta_max and each joint's
/// [q_min, q_max] (in its colour).
struct TimePlotLimits {
  BaseLimits base;
  Eigen::VectorXd q_min_rad;
  Eigen::VectorXd q_max_rad;
};

struct TimePlotOptions {
  std::string title;  ///< Top lines ('\n' between them), e.g. scene, task and duration.
  int width_px = 1100;
  int base_panel_height_px = 190;   ///< Each of v, omega, a, beta.
  int joint_panel_height_px = 300;  ///< The joint angles.
  ChartStyle style{.font_px = 15.0};
};

/// The distinct colour of joint k (0-based; the palette of Okabe and Ito, 2008, without its
/// yellow, repeating after 7).
Rgb JointColour(int joint);

/// One PNG-ready image of stacked panels sharing the time axis (like the paper's Fig. 5):
/// v with +-v_max and, in grey, the speed bound the coupled constraint (eq. (9)) leaves at
/// the current yaw rate, +-v_max (1 - |omega| / omega_max); omega with +-omega_max, a with +-a_max,
/// beta with +-beta_max, then every joint angle (one colour each, legend q1..qN) with its position
/// limits dashed. Throws std::invalid_argument for data of mismatched sizes, fewer than 2 samples,
/// a joint count other than the limits', non-finite limits, or options that make no room for the
/// panels.
Image RenderTimePlots(const TimePlotData& data, const TimePlotLimits& limits,
                      const TimePlotOptions& options = {});

/// The panels' areas in the image RenderTimePlots makes (v, omega, a, beta, joints), for
/// tests and overlays.
std::vector<PixelRect> TimePlotPanels(const TimePlotOptions& options);

/// The chart of each panel, in the same order (what RenderTimePlots draws).
std::vector<LineChart> TimePlotCharts(const TimePlotData& data, const TimePlotLimits& limits);

}  // namespace topay::viz
