#include "tools/viz/time_plot.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "tests/core/validate/rest_to_rest_motion.h"

namespace topay::viz {
namespace {

constexpr Rgb kSeriesColour{0, 90, 181};
constexpr Rgb kLimitColour{200, 30, 30};

// 10 s at 10 ms: v = 0.5, omega = -0.25 t / 10, a = 0, beta = 0.1 sin t; two joints.
TimePlotData MakeData() {
  TimePlotData data;
  data.q_rad.assign(2, {});
  for (int i = 0; i <= 1000; ++i) {
    const double t = 0.01 * i;
    data.t_s.push_back(t);
    data.v_mps.push_back(0.5);
    data.omega_radps.push_back(-0.025 * t);
    data.a_mps2.push_back(0.0);
    data.beta_radps2.push_back(0.1 * std::sin(t));
    data.q_rad[0].push_back(1.0);
    data.q_rad[1].push_back(-2.0);
  }
  return data;
}

TimePlotLimits MakeLimits() {
  TimePlotLimits limits;
  limits.base.v_max_mps = 1.0;
  limits.base.omega_max_radps = 1.25;
  limits.base.a_max_mps2 = 0.8;
  limits.base.beta_max_radps2 = 1.0;
  limits.q_min_rad = Eigen::Vector2d(-3.0, -2.5);
  limits.q_max_rad = Eigen::Vector2d(3.0, 2.5);
  return limits;
}

// The layout of panel i as RenderTimePlots drew it (same charts, areas and common inset).
ChartLayout PanelLayout(const TimePlotData& data, const TimePlotOptions& options, int i) {
  const std::vector<LineChart> charts = TimePlotCharts(data, MakeLimits());
  const std::vector<PixelRect> panels = TimePlotPanels(options);
  int inset = 0;
  for (std::size_t k = 0; k < charts.size(); ++k) {
    inset = std::max(inset,
                     LayOutLineChart(panels[k], charts[k], options.style).plot.x0 - panels[k].x0);
  }
  ChartStyle style = options.style;
  style.plot_left_inset_px = inset;
  return LayOutLineChart(panels[i], charts[i], style);
}

// True if the pixel is closer to `colour` than to white (a thin anti-aliased line's pixels
// rarely show its exact colour).
bool Tinted(const Rgb& pixel, const Rgb& colour) {
  auto distance = [](const Rgb& a, const Rgb& b) {
    return std::abs(a.r - b.r) + std::abs(a.g - b.g) + std::abs(a.b - b.b);
  };
  return distance(pixel, colour) < distance(pixel, colors::kWhite);
}

// The most pixels tinted with `colour` on one of the rows around the value y (a horizontal
// line of width <= 2 px lies on those rows), across the plot.
int TintedAlongRow(const Image& image, const ChartLayout& layout, double y, const Rgb& colour) {
  const int row = static_cast<int>(std::floor(layout.ToPixel(0.0, y).y()));
  int best = 0;
  for (int r = row - 1; r <= row + 1; ++r) {
    int count = 0;
    for (int x = layout.plot.x0; x < layout.plot.x1; ++x) count += Tinted(image.At(x, r), colour);
    best = std::max(best, count);
  }
  return best;
}

Rgb At(const Image& image, const ChartLayout& layout, double x, double y) {
  const Eigen::Vector2d p = layout.ToPixel(x, y);
  return image.At(static_cast<int>(std::floor(p.x())), static_cast<int>(std::floor(p.y())));
}

TEST(TimePlotTest, StacksFivePanelsOfTheConfiguredSizes) {
  const TimePlotOptions options;
  const Image image = RenderTimePlots(MakeData(), MakeLimits(), options);
  const std::vector<PixelRect> panels = TimePlotPanels(options);
  ASSERT_EQ(panels.size(), 5u);
  EXPECT_EQ(image.width(), options.width_px);
  EXPECT_EQ(image.height(), panels.back().y1 + 4);
  for (int i = 0; i < 4; ++i) EXPECT_EQ(panels[i].height(), options.base_panel_height_px);
  EXPECT_EQ(panels[4].height(), options.joint_panel_height_px);
  for (int i = 1; i < 5; ++i) EXPECT_EQ(panels[i].y0, panels[i - 1].y1);
  // Every panel's plot starts at the same x, so the time axes line up.
  for (int i = 1; i < 5; ++i) {
    EXPECT_EQ(PanelLayout(MakeData(), options, i).plot.x0,
              PanelLayout(MakeData(), options, 0).plot.x0);
  }
}

TEST(TimePlotTest, SeriesAndLimitLinesAreWhereTheirValuesMap) {
  const TimePlotData data = MakeData();
  const TimePlotOptions options;
  const Image image = RenderTimePlots(data, MakeLimits(), options);
  const ChartLayout v = PanelLayout(data, options, 0);
  const ChartLayout omega = PanelLayout(data, options, 1);
  for (double t : {1.0, 4.0, 8.5}) {
    EXPECT_EQ(At(image, v, t, 0.5), kSeriesColour) << t;  // v = 0.5
    EXPECT_NE(At(image, v, t, 0.0), kSeriesColour) << t;
    EXPECT_EQ(At(image, omega, t, -0.025 * t), kSeriesColour) << t;  // the omega ramp
  }
  // +-v_max and +-omega_max are dashed red lines (8 px dashes every 13 px): red along their
  // rows, but not all along, and not half-way to the series.
  for (const auto& [layout, bound] : {std::pair{v, 1.0}, std::pair{omega, 1.25}}) {
    for (double limit : {bound, -bound}) {
      const int red = TintedAlongRow(image, layout, limit, kLimitColour);
      EXPECT_GT(red, layout.plot.width() / 2) << limit;
      // Dashed, not solid: a dash tints at most 8 px + its round caps (1.5 px) + 1 px of
      // anti-aliasing of every 13 px.
      EXPECT_LT(red, layout.plot.width() * 11 / 13 + 11) << limit;
    }
  }
  EXPECT_EQ(TintedAlongRow(image, v, 0.75, kLimitColour), 0);
  // The coupled constraint's speed bound, v_max (1 - |omega| / omega_max), in grey: at t = 8 s
  // omega = -0.2 rad/s leaves |v| <= 0.84 m/s; at t = 1 s, 0.98 m/s.
  const Rgb grey{150, 150, 150};
  // One of the 3 rows around the value has a pixel centre within 0.5 px of the 1.5 px line:
  // coverage >= 0.75, so within 0.25 x 315 of grey over white (or 0.25 x 290 over the red
  // limit), while the blue series and the red limits are farther than 240 from grey.
  auto grey_near = [&](double t, double value) {
    const Eigen::Vector2d p = v.ToPixel(t, value);
    for (int dy = -1; dy <= 1; ++dy) {
      const Rgb pixel = image.At(static_cast<int>(p.x()), static_cast<int>(p.y()) + dy);
      if (std::abs(pixel.r - grey.r) + std::abs(pixel.g - grey.g) + std::abs(pixel.b - grey.b) <
          100) {
        return true;
      }
    }
    return false;
  };
  for (double t : {1.0, 8.0}) {
    const double bound = 1.0 - 0.025 * t / 1.25;
    EXPECT_TRUE(grey_near(t, bound)) << t;
    EXPECT_TRUE(grey_near(t, -bound)) << t;
    EXPECT_FALSE(grey_near(t, 0.25)) << t;
  }
  // Each joint in its own colour at its value, its limits dashed in that colour.
  const ChartLayout joints = PanelLayout(data, options, 4);
  EXPECT_EQ(At(image, joints, 5.0, 1.0), JointColour(0));
  EXPECT_EQ(At(image, joints, 5.0, -2.0), JointColour(1));
  EXPECT_NE(JointColour(0), JointColour(1));
  EXPECT_GT(TintedAlongRow(image, joints, 3.0, JointColour(0)), joints.plot.width() / 3);
  EXPECT_GT(TintedAlongRow(image, joints, -2.5, JointColour(1)), joints.plot.width() / 3);
  EXPECT_EQ(TintedAlongRow(image, joints, 2.0, JointColour(0)), 0);
  // The joint panel's range covers every limit.
  EXPECT_LE(joints.y_min, -3.0);
  EXPECT_GE(joints.y_max, 3.0);
}

TEST(TimePlotTest, SamplesATrajectoryEveryPeriodAndAtItsEnd) {
  ArcYawTrajectory trajectory(2, 1, {});
  testing::RestToRest motion;
  motion.s_f_m = 3.0;
  motion.yaw_f_rad = 0.5;
  motion.q0_rad = Eigen::Vector2d(0.1, 0.2);
  motion.q_f_rad = Eigen::Vector2d(-0.3, 0.4);
  motion.duration_s = 2.345;
  testing::UpdateRestToRest(motion, &trajectory);
  const TimePlotData data = SampleTimePlotData(trajectory, 0.01);
  ASSERT_EQ(data.t_s.size(), 236u);  // 0, 0.01, ..., 2.34 and 2.345
  EXPECT_DOUBLE_EQ(data.t_s.back(), 2.345);
  EXPECT_DOUBLE_EQ(data.t_s[100], 1.0);
  ASSERT_EQ(data.q_rad.size(), 2u);
  EXPECT_NEAR(data.q_rad[0].back(), -0.3, 1e-9);
  EXPECT_NEAR(data.v_mps.front(), 0.0, 1e-12);
  // Mid-way the ramp's speed is 15/8 s_f / T.
  const double tau = data.t_s[117] / 2.345;
  EXPECT_NEAR(data.v_mps[117], 3.0 / 2.345 * testing::RampRate(tau), 1e-9);
  EXPECT_THROW(SampleTimePlotData(trajectory, 0.0), std::invalid_argument);
  ArcYawTrajectory unsolved(2, 1, {});
  EXPECT_THROW(SampleTimePlotData(unsolved, 0.01), std::invalid_argument);
}

TEST(TimePlotTest, MismatchedDataAndLimitsAreRejectedByName) {
  TimePlotData data = MakeData();
  data.a_mps2.pop_back();
  try {
    RenderTimePlots(data, MakeLimits());
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("a_mps2"), std::string::npos) << e.what();
  }
  TimePlotLimits three = MakeLimits();
  three.q_min_rad = Eigen::Vector3d::Zero();
  EXPECT_THROW(RenderTimePlots(MakeData(), three), std::invalid_argument);
  TimePlotLimits no_v = MakeLimits();
  no_v.base.v_max_mps = 0.0;
  EXPECT_THROW(RenderTimePlots(MakeData(), no_v), std::invalid_argument);
  TimePlotData one;
  one.t_s = {0.0};
  one.v_mps = one.omega_radps = one.a_mps2 = one.beta_radps2 = {0.0};
  EXPECT_THROW(RenderTimePlots(one, TimePlotLimits{}), std::invalid_argument);
  TimePlotOptions narrow;
  narrow.width_px = 50;
  EXPECT_THROW(RenderTimePlots(MakeData(), MakeLimits(), narrow), std::invalid_argument);
}

}  // namespace
}  // namespace topay::viz
