// time_plots.png's layout: a title, then v, omega and one panel per joint; switches marked.

#include "tools/report/run_time_plots.h"

#include <gtest/gtest.h>

#include <limits>
#include <stdexcept>

namespace topay::report {
namespace {

constexpr viz::Rgb kSwitch{120, 120, 120};

RunTimeSeries Series(int joints) {
  RunTimeSeries s;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (int k = 0; k <= 100; ++k) {
    const double t = 0.1 * k;
    s.t_s.push_back(t);
    s.v_measured_mps.push_back(0.05 * k);
    s.v_planned_mps.push_back(k < 20 ? nan : 0.05 * k);  // nothing active before 2 s
    s.omega_measured_radps.push_back(0.0);
    s.omega_planned_radps.push_back(0.0);
  }
  s.q_measured_rad.assign(joints, s.v_measured_mps);
  s.q_planned_rad.assign(joints, s.v_planned_mps);
  s.switch_t_s = {2.0, 6.0};
  return s;
}

int CountColour(const viz::Image& image, const viz::PixelRect& area, const viz::Rgb& colour) {
  int n = 0;
  for (int y = area.y0; y < area.y1; ++y) {
    for (int x = area.x0; x < area.x1; ++x) n += image.At(x, y) == colour;
  }
  return n;
}

TEST(RunTimePlots, OnePanelPerQuantityStackedUnderTheTitle) {
  RunTimePlotOptions options;
  const std::vector<viz::PixelRect> panels = RunTimePlotPanels(3, options);
  ASSERT_EQ(panels.size(), 5u);  // v, omega, q1..q3
  EXPECT_EQ(panels[1].y0, panels[0].y1);
  EXPECT_EQ(panels[4].height(), options.panel_height_px);
  const viz::Image image = RenderRunTimePlots(Series(3), options);
  EXPECT_EQ(image.width(), options.width_px);
  EXPECT_EQ(image.height(), panels.back().y1 + 4);
  // The switch lines (dotted grey) cross every panel.
  for (const viz::PixelRect& panel : panels) EXPECT_GT(CountColour(image, panel, kSwitch), 20);
}

TEST(RunTimePlots, AQuantityWithoutAnyValueGivesAnEmptyPanel) {
  RunTimeSeries s = Series(2);
  s.q_measured_rad[1].assign(s.t_s.size(), std::numeric_limits<double>::quiet_NaN());
  s.q_planned_rad[1] = s.q_measured_rad[1];
  const viz::Image image = RenderRunTimePlots(s, {});
  EXPECT_EQ(image.height(), RunTimePlotPanels(2, {}).back().y1 + 4);
}

TEST(RunTimePlots, WithoutMotionOnePanelSaysSo) {
  RunTimePlotOptions options;
  const viz::Image image = RenderRunTimePlots(RunTimeSeries{}, options);
  EXPECT_EQ(image.height(), RunTimePlotPanels(-1, options).back().y1 + 4);
  options.panel_height_px = 10;
  EXPECT_THROW(RenderRunTimePlots(Series(1), options), std::invalid_argument);
}

}  // namespace
}  // namespace topay::report
