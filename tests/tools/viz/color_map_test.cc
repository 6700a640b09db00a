#include "tools/viz/color_map.h"

#include <cmath>

#include <gtest/gtest.h>

namespace topay::viz {
namespace {

TEST(ColorMapTest, ViridisLuminanceRisesMonotonically) {
  // The map itself, before 8-bit quantisation: strictly increasing at fine steps.
  double previous = -1.0;
  for (int i = 0; i <= 1000; ++i) {
    const double luminance = Luminance(ViridisLinear(i / 1000.0));
    EXPECT_GT(luminance, previous) << "t = " << i / 1000.0;
    previous = luminance;
  }
  // The 8-bit colours, at steps of 1/32 (each step changes luminance by far more than the
  // rounding of a code value does).
  previous = -1.0;
  for (int i = 0; i <= 32; ++i) {
    const double luminance = RelativeLuminance(Viridis(i / 32.0));
    EXPECT_GT(luminance, previous) << "t = " << i / 32.0;
    previous = luminance;
  }
  EXPECT_GT(RelativeLuminance(Viridis(1.0)), 10 * RelativeLuminance(Viridis(0.0)));
  // The ends are the published anchors.
  EXPECT_EQ(Viridis(0.0), (Rgb{0x44, 0x01, 0x54}));
  EXPECT_EQ(Viridis(1.0), (Rgb{0xfd, 0xe7, 0x25}));
}

TEST(ColorMapTest, GreyAndWarmRampsGetDarkerWithT) {
  double grey_previous = 2.0;
  double warm_previous = 2.0;
  for (int i = 0; i <= 100; ++i) {
    const Rgb grey = GreyRamp(i / 100.0);
    EXPECT_EQ(grey.r, grey.g);
    EXPECT_EQ(grey.g, grey.b);
    EXPECT_LE(RelativeLuminance(grey), grey_previous);
    EXPECT_LE(RelativeLuminance(WarmRamp(i / 100.0)), warm_previous);
    grey_previous = RelativeLuminance(grey);
    warm_previous = RelativeLuminance(WarmRamp(i / 100.0));
  }
  EXPECT_LT(RelativeLuminance(GreyRamp(1.0)), 0.5 * RelativeLuminance(GreyRamp(0.0)));
}

TEST(ColorMapTest, EndsAreClampedAndNanIsSafe) {
  EXPECT_EQ(Viridis(-3.0), Viridis(0.0));
  EXPECT_EQ(Viridis(7.0), Viridis(1.0));
  EXPECT_EQ(Viridis(std::nan("")), Viridis(0.0));
  EXPECT_NE(Viridis(0.0), Viridis(1.0));
}

TEST(ScalarRangeTest, NormalizesAndClamps) {
  const ScalarRange range{2.0, 4.0};
  EXPECT_DOUBLE_EQ(range.Normalize(3.0), 0.5);
  EXPECT_DOUBLE_EQ(range.Normalize(-10.0), 0.0);
  EXPECT_DOUBLE_EQ(range.Normalize(10.0), 1.0);
  EXPECT_DOUBLE_EQ(range.Normalize(std::nan("")), 0.0);
  EXPECT_DOUBLE_EQ((ScalarRange{1.0, 1.0}).Normalize(5.0), 0.0);
}

}  // namespace
}  // namespace topay::viz
