#include "tools/viz/image.h"

#include <stdexcept>

#include <gtest/gtest.h>

namespace topay::viz {
namespace {

TEST(ImageTest, StartsFilledAndSetsChosenPixels) {
  Image image(3, 2, Rgb{1, 2, 3});
  EXPECT_EQ(image.width(), 3);
  EXPECT_EQ(image.height(), 2);
  EXPECT_EQ(image.At(2, 1), (Rgb{1, 2, 3}));
  image.SetPixels([](int x, int y) -> std::optional<Rgb> {
    if (x == 1 && y == 1) return Rgb{9, 8, 7};
    return std::nullopt;
  });
  EXPECT_EQ(image.At(1, 1), (Rgb{9, 8, 7}));
  EXPECT_EQ(image.At(0, 1), (Rgb{1, 2, 3}));
  EXPECT_EQ(image.At(1, 0), (Rgb{1, 2, 3}));
}

TEST(ImageTest, ReadsOutsideThrow) {
  Image image(2, 2, Rgb{0, 0, 0});
  EXPECT_THROW(image.At(2, 0), std::out_of_range);
  EXPECT_THROW(image.At(0, -1), std::out_of_range);
}

TEST(ImageTest, CopiesAreIndependentAndMovesKeepThePixels) {
  Image a(4, 3, Rgb{10, 20, 30});
  Image b = a;
  b.SetPixels([](int, int) { return std::optional<Rgb>(Rgb{1, 1, 1}); });
  EXPECT_EQ(a.At(3, 2), (Rgb{10, 20, 30}));
  EXPECT_EQ(b.At(3, 2), (Rgb{1, 1, 1}));
  Image c = std::move(a);
  EXPECT_EQ(c.width(), 4);
  EXPECT_EQ(c.At(0, 0), (Rgb{10, 20, 30}));
}

TEST(ImageTest, AdoptConvertsAnAlphaSurfaceOverWhite) {
  cairo_surface_t* argb = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, 2, 1);
  cairo_t* cr = cairo_create(argb);
  cairo_set_operator(cr, CAIRO_OPERATOR_SOURCE);
  cairo_set_source_rgba(cr, 0.0, 0.0, 0.0, 0.0);  // Transparent: white after adoption.
  cairo_paint(cr);
  cairo_rectangle(cr, 1, 0, 1, 1);
  cairo_set_source_rgba(cr, 1.0, 0.0, 0.0, 1.0);
  cairo_fill(cr);
  cairo_destroy(cr);
  const Image image = Image::Adopt(argb, "test surface");
  EXPECT_EQ(image.At(0, 0), colors::kWhite);
  EXPECT_EQ(image.At(1, 0), (Rgb{255, 0, 0}));
}

TEST(ImageTest, RejectsImpossibleSizes) {
  EXPECT_THROW(Image(0, 10), std::invalid_argument);
  EXPECT_THROW(Image(10, -1), std::invalid_argument);
  EXPECT_THROW(Image(Image::kMaxSidePx + 1, 1), std::invalid_argument);
}

}  // namespace
}  // namespace topay::viz
