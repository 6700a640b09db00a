#include "tools/viz/world_canvas.h"

#include <vector>

#include <gtest/gtest.h>

namespace topay::viz {
namespace {

const Rgb kBg{255, 255, 255};
const Rgb kRed{255, 0, 0};

WorldCanvas MakeCanvas() {
  // 10 x 10 m at 10 px/m: world (0, 0) is the bottom-left corner, pixel row 99.
  const ViewTransform view(Eigen::AlignedBox2d(Eigen::Vector2d(0, 0), Eigen::Vector2d(10, 10)),
                           10.0);
  return WorldCanvas(Image(view.width_px(), view.height_px(), kBg), view);
}

TEST(WorldCanvasTest, PolygonInMetresLandsOnTheRightPixels) {
  WorldCanvas canvas = MakeCanvas();
  const std::vector<Eigen::Vector2d> square_W = {{1, 1}, {3, 1}, {3, 2}, {1, 2}};
  canvas.FillPolygon(square_W, kRed);
  // x in [1, 3] m -> columns 10..29; y in [1, 2] m -> rows 80..89 (y up).
  EXPECT_EQ(canvas.image().At(10, 80), kRed);
  EXPECT_EQ(canvas.image().At(29, 89), kRed);
  EXPECT_EQ(canvas.image().At(30, 85), kBg);
  EXPECT_EQ(canvas.image().At(20, 79), kBg);
  EXPECT_EQ(canvas.image().At(20, 90), kBg);
}

TEST(WorldCanvasTest, CircleRadiusIsInMetres) {
  WorldCanvas canvas = MakeCanvas();
  canvas.FillCircle({5, 5}, 1.0, kRed);
  EXPECT_EQ(canvas.image().At(50, 50), kRed);
  EXPECT_EQ(canvas.image().At(58, 50), kRed);  // 0.85 m from the centre.
  EXPECT_EQ(canvas.image().At(62, 50), kBg);   // 1.25 m.
}

TEST(WorldCanvasTest, ArrowHasAHeadAtItsTip) {
  WorldCanvas canvas = MakeCanvas();
  canvas.DrawArrow({2, 5}, {8, 5}, kRed, 2.0, 10.0);
  EXPECT_EQ(canvas.image().At(30, 49), kRed);  // Shaft.
  EXPECT_EQ(canvas.image().At(72, 48), kRed);  // Head, 1.5 px off the axis.
  EXPECT_EQ(canvas.image().At(30, 46), kBg);   // Beside the thin shaft.
  EXPECT_EQ(canvas.image().At(85, 50), kBg);   // Past the tip.
}

}  // namespace
}  // namespace topay::viz
