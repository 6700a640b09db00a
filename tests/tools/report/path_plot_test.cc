// path.png drawn directly: the start, a contact where the base was, an appeared box, and the
// legend below the map.

#include "tools/report/path_plot.h"

#include <gtest/gtest.h>

#include "tests/tools/report/crafted_run_log.h"
#include "tools/viz/color.h"

namespace topay::report {
namespace {

viz::Rgb PixelAt(const viz::Image& image, const viz::ViewTransform& view, const Eigen::Vector2d& p_W) {
  const Eigen::Vector2d px = view.ToPixel(p_W);
  return image.At(static_cast<int>(px.x()), static_cast<int>(px.y()));
}

TEST(PathPlot, MarksStartContactsAndAppearedBoxes) {
  const std::string path = test::FreshTestDir("path_plot") + "/graph.lcmlog";
  test::WriteCraftedRunLog(path);
  const RunLog log = ReadRunLog(path);
  PathPlotOptions options;
  options.px_per_m = 50.0;
  const viz::Image image = RenderPathPlot(log, nullptr, options);
  const viz::ViewTransform view = PathPlotView(log, nullptr, options);
  EXPECT_EQ(image.width(), PathPlotWidth(view, options));
  EXPECT_GT(image.height(), view.offset_px().y() + view.height_px() + 40);  // axes and legend
  EXPECT_EQ(PixelAt(image, view, {0.0, 0.0}), viz::colors::kStart);
  EXPECT_EQ(PixelAt(image, view, {3.0, 3.2}), (viz::Rgb{220, 0, 0}));  // contact at ROBOT_STATE 18
  const viz::Rgb box = PixelAt(image, view, {1.6, 2.6});
  EXPECT_GT(box.r, box.b + 60);
  EXPECT_EQ(PixelAt(image, view, {-0.5, -0.5}), viz::colors::kWhite);
}

}  // namespace
}  // namespace topay::report
