#include "tools/viz/color.h"

#include <gtest/gtest.h>

namespace topay::viz {
namespace {

TEST(ColorTest, BlendIsAlphaWeightedMean) {
  EXPECT_EQ(Blend(Rgb{0, 0, 0}, Rgb{255, 255, 255}, 1.0), (Rgb{255, 255, 255}));
  EXPECT_EQ(Blend(Rgb{0, 0, 0}, Rgb{255, 255, 255}, 0.0), (Rgb{0, 0, 0}));
  EXPECT_EQ(Blend(Rgb{0, 100, 200}, Rgb{100, 100, 0}, 0.5), (Rgb{50, 100, 100}));
  EXPECT_EQ(Blend(Rgb{0, 0, 0}, Rgb{100, 100, 100}, 7.0), (Rgb{100, 100, 100}));
}

TEST(ColorTest, LuminanceOfBlackWhiteAndPrimaries) {
  EXPECT_DOUBLE_EQ(RelativeLuminance(colors::kBlack), 0.0);
  EXPECT_NEAR(RelativeLuminance(colors::kWhite), 1.0, 1e-12);
  // Green carries most of the luminance, blue the least (BT.709).
  EXPECT_GT(RelativeLuminance(Rgb{0, 255, 0}), RelativeLuminance(Rgb{255, 0, 0}));
  EXPECT_GT(RelativeLuminance(Rgb{255, 0, 0}), RelativeLuminance(Rgb{0, 0, 255}));
  // Mid grey code 128 is about 22 % of white's light (sRGB is not linear).
  EXPECT_NEAR(RelativeLuminance(Rgb{128, 128, 128}), 0.216, 0.002);
}

TEST(ColorTest, LinearRoundTripIsExactForEveryCode) {
  for (int code = 0; code < 256; ++code) {
    const auto c = static_cast<std::uint8_t>(code);
    EXPECT_EQ(FromLinear(ToLinear(Rgb{c, c, c})), (Rgb{c, c, c})) << code;
  }
}

}  // namespace
}  // namespace topay::viz
