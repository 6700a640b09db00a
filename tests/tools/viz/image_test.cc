#include "tools/viz/image.h"

#include <cmath>
#include <stdexcept>

#include <gtest/gtest.h>

namespace topay::viz {
namespace {

TEST(ImageTest, StartsFilledAndStoresPixelsRowMajor) {
  Image image(3, 2, Rgb{1, 2, 3});
  EXPECT_EQ(image.bytes().size(), 18u);
  EXPECT_EQ(image.At(2, 1), (Rgb{1, 2, 3}));
  image.Set(1, 1, Rgb{9, 8, 7});
  EXPECT_EQ(image.bytes()[3 * (1 * 3 + 1)], 9);
  EXPECT_EQ(image.At(1, 1), (Rgb{9, 8, 7}));
}

TEST(ImageTest, WritesOutsideAreIgnoredAndReadsOutsideThrow) {
  Image image(2, 2, Rgb{0, 0, 0});
  image.Set(-1, 0, Rgb{255, 0, 0});
  image.Set(2, 1, Rgb{255, 0, 0});
  image.Paint(0, 5, Rgb{255, 0, 0}, 1.0);
  for (int y = 0; y < 2; ++y) {
    for (int x = 0; x < 2; ++x) EXPECT_EQ(image.At(x, y), (Rgb{0, 0, 0}));
  }
  EXPECT_THROW(image.At(2, 0), std::out_of_range);
}

TEST(ImageTest, PaintBlendsByAlpha) {
  Image image(1, 1, Rgb{0, 100, 200});
  image.Paint(0, 0, Rgb{200, 100, 0}, 0.25);
  EXPECT_EQ(image.At(0, 0), (Rgb{50, 100, 150}));
  image.Paint(0, 0, Rgb{1, 1, 1}, 0.0);
  EXPECT_EQ(image.At(0, 0), (Rgb{50, 100, 150}));
  image.Paint(0, 0, Rgb{1, 1, 1}, std::nan(""));
  EXPECT_EQ(image.At(0, 0), (Rgb{50, 100, 150}));
}

TEST(ImageTest, RejectsImpossibleSizes) {
  EXPECT_THROW(Image(0, 10), std::invalid_argument);
  EXPECT_THROW(Image(10, -1), std::invalid_argument);
  EXPECT_THROW(Image(Image::kMaxSidePx + 1, 1), std::invalid_argument);
}

}  // namespace
}  // namespace topay::viz
