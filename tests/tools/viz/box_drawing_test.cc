#include "tools/viz/box_drawing.h"

#include <gtest/gtest.h>

namespace topay::viz {
namespace {

WorldCanvas MakeCanvas() {
  const ViewTransform view(Eigen::AlignedBox2d(Eigen::Vector2d(0, 0), Eigen::Vector2d(10, 10)),
                           20.0);
  return WorldCanvas(Image(view.width_px(), view.height_px(), colors::kWhite), view);
}

OrientedBox Box(double x, double y, double bottom, double top) {
  OrientedBox box;
  box.center_W_m = {x, y, 0.5 * (bottom + top)};
  box.size_m = {2.0, 2.0, top - bottom};
  return box;
}

Rgb At(const WorldCanvas& canvas, const Eigen::Vector2d& p_W) {
  const Eigen::Vector2d p = canvas.view().ToPixel(p_W);
  return canvas.image().At(static_cast<int>(p.x()), static_cast<int>(p.y()));
}

TEST(BoxDrawingTest, TallerGroundedBoxesAreDarker) {
  WorldCanvas canvas = MakeCanvas();
  DrawBoxes(&canvas, {Box(2, 2, 0.0, 0.4), Box(7, 7, 0.0, 1.5)});
  const Rgb low = At(canvas, {2, 2});
  const Rgb tall = At(canvas, {7, 7});
  EXPECT_EQ(low, GreyRamp(0.4 / 1.6));
  EXPECT_EQ(tall, GreyRamp(1.5 / 1.6));
  EXPECT_LT(RelativeLuminance(tall), RelativeLuminance(low));
  EXPECT_EQ(At(canvas, {5, 2}), colors::kWhite);  // Between the boxes.
}

TEST(BoxDrawingTest, RaisedBoxesAreTranslucentAndHatched) {
  const OrientedBox raised = Box(5, 5, 0.6, 0.65);
  EXPECT_TRUE(IsRaised(raised, {}));
  EXPECT_FALSE(IsRaised(Box(5, 5, 0.0, 0.65), {}));
  WorldCanvas canvas = MakeCanvas();
  DrawBoxes(&canvas, {raised});
  // Inside the footprint there are at least two colours (fill and stripes), none of them the
  // opaque grey a grounded box of the same height would get.
  const Rgb opaque = GreyRamp(0.65 / 1.6);
  bool saw_stripe = false;
  bool saw_fill = false;
  const Rgb fill = Blend(colors::kWhite, opaque, BoxDrawingOptions{}.raised_fill_alpha);
  for (int y = 90; y < 110; ++y) {
    for (int x = 90; x < 110; ++x) {
      const Rgb c = canvas.image().At(x, y);
      EXPECT_NE(c, opaque);
      saw_fill |= c == fill;
      saw_stripe |= c != fill && c != colors::kWhite;
    }
  }
  EXPECT_TRUE(saw_fill);
  EXPECT_TRUE(saw_stripe);
}

}  // namespace
}  // namespace topay::viz
