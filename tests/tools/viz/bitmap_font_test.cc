#include "tools/viz/bitmap_font.h"

#include <string>

#include <gtest/gtest.h>

namespace topay::viz {
namespace {

const Rgb kBg{255, 255, 255};
const Rgb kInk{0, 0, 0};

TEST(BitmapFontTest, EveryPrintableGlyphIsDistinct) {
  const std::string alphabet =
      "0123456789ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz.,:;-+=/()[]%_#<>'!?";
  for (std::size_t i = 0; i < alphabet.size(); ++i) {
    int ink = 0;
    for (int r = 0; r < 7; ++r) {
      for (int c = 0; c < 5; ++c) ink += BitmapFont::GlyphPixel(alphabet[i], c, r) ? 1 : 0;
    }
    EXPECT_GT(ink, 0) << alphabet[i];
    for (std::size_t j = i + 1; j < alphabet.size(); ++j) {
      bool same = true;
      for (int r = 0; r < 7 && same; ++r) {
        for (int c = 0; c < 5 && same; ++c) {
          same = BitmapFont::GlyphPixel(alphabet[i], c, r) ==
                 BitmapFont::GlyphPixel(alphabet[j], c, r);
        }
      }
      EXPECT_FALSE(same) << alphabet[i] << " and " << alphabet[j];
    }
  }
  EXPECT_FALSE(BitmapFont::GlyphPixel(' ', 2, 3));
}

TEST(BitmapFontTest, DrawsGlyphPixelsScaledAtThePen) {
  Image image(40, 30, kBg);
  DrawText(&image, 3, 4, "1", kInk, 2);
  for (int r = 0; r < 7; ++r) {
    for (int c = 0; c < 5; ++c) {
      const bool ink = BitmapFont::GlyphPixel('1', c, r);
      for (int dy = 0; dy < 2; ++dy) {
        for (int dx = 0; dx < 2; ++dx) {
          EXPECT_EQ(image.At(3 + 2 * c + dx, 4 + 2 * r + dy) == kInk, ink) << c << ", " << r;
        }
      }
    }
  }
  // Nothing outside the glyph's cell.
  for (int y = 0; y < 30; ++y) {
    for (int x = 0; x < 40; ++x) {
      if (x < 3 || x >= 13 || y < 4 || y >= 18) {
        EXPECT_EQ(image.At(x, y), kBg) << x << ", " << y;
      }
    }
  }
}

TEST(BitmapFontTest, TextWidthCountsTheLongestLine) {
  EXPECT_EQ(BitmapFont::TextWidth("", 1), 0);
  EXPECT_EQ(BitmapFont::TextWidth("a", 1), 5);
  EXPECT_EQ(BitmapFont::TextWidth("abc", 2), 2 * (2 * 6 + 5));
  EXPECT_EQ(BitmapFont::TextWidth("ab\nabcd", 1), 3 * 6 + 5);
}

TEST(BitmapFontTest, UnknownCharactersDrawAsABox) {
  Image image(10, 10, kBg);
  DrawText(&image, 0, 0, "\x01", kInk, 1);
  EXPECT_EQ(image.At(0, 0), kInk);
  EXPECT_EQ(image.At(4, 6), kInk);
  EXPECT_EQ(image.At(2, 3), kBg);
}

}  // namespace
}  // namespace topay::viz
