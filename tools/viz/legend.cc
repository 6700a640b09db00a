#include "tools/viz/legend.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "tools/viz/bitmap_font.h"
#include "tools/viz/raster.h"

namespace topay::viz {
namespace {

std::string FormatMetres(double length_m) {
  std::ostringstream out;
  out << length_m << " m";
  return out.str();
}

}  // namespace

LegendLayout::LegendLayout(Image* image, int x0, int y0, int width_px, int text_scale)
    : image_(image), x0_(x0), y0_(y0), width_(width_px), scale_(std::max(text_scale, 1)),
      pen_x_(x0) {}

int LegendLayout::RowHeight() const { return (BitmapFont::kLineHeight + 4) * scale_; }
int LegendLayout::Gap() const { return 4 * BitmapFont::kAdvance * scale_ / 2; }

int LegendLayout::height() const { return (row_ + (row_empty_ ? 0 : 1)) * RowHeight(); }

void LegendLayout::NewRow() {
  if (row_empty_) return;
  ++row_;
  pen_x_ = x0_;
  row_empty_ = true;
}

int LegendLayout::Place(int width) {
  if (!row_empty_ && pen_x_ + width > x0_ + width_) NewRow();
  const int left = pen_x_;
  pen_x_ += width + Gap();
  row_empty_ = false;
  return left;
}

void LegendLayout::Text(const std::string& text, const Rgb& colour) {
  const int left = Place(BitmapFont::TextWidth(text, scale_));
  if (image_) DrawText(image_, left, y0_ + row_ * RowHeight(), text, colour, scale_);
}

void LegendLayout::Swatch(const Rgb& fill, const Rgb& outline, const std::string& label,
                          bool hatched) {
  const int side = BitmapFont::TextHeight(scale_) + 2;
  const int text_x = side + BitmapFont::kAdvance * scale_;
  const int left = Place(text_x + BitmapFont::TextWidth(label, scale_));
  if (!image_) return;
  const int top = y0_ + row_ * RowHeight() - 1;
  FillRect(image_, left, top, left + side, top + side, fill, hatched ? 0.35 : 1.0);
  if (hatched) {
    for (int y = top; y < top + side; ++y) {
      for (int x = left; x < left + side; ++x) {
        if ((x + y) % 5 == 0) image_->Set(x, y, outline);
      }
    }
  }
  const Eigen::Vector2d corners[] = {{left + 0.5, top + 0.5}, {left + side - 0.5, top + 0.5},
                                     {left + side - 0.5, top + side - 0.5},
                                     {left + 0.5, top + side - 0.5}};
  DrawPolyline(image_, corners, /*closed=*/true, outline, 1.0);
  DrawText(image_, left + text_x, y0_ + row_ * RowHeight(), label, colors::kInk, scale_);
}

void LegendLayout::ColourBar(const std::string& caption,
                             const std::function<Rgb(double)>& colour_of, const std::string& low,
                             const std::string& high) {
  const int space = BitmapFont::kAdvance * scale_;
  const int bar = 20 * space;
  const int caption_w = BitmapFont::TextWidth(caption, scale_);
  const int low_w = BitmapFont::TextWidth(low, scale_);
  const int high_w = BitmapFont::TextWidth(high, scale_);
  const int left = Place(caption_w + low_w + bar + high_w + 3 * space);
  if (!image_) return;
  const int text_y = y0_ + row_ * RowHeight();
  int x = left;
  DrawText(image_, x, text_y, caption, colors::kInk, scale_);
  x += caption_w + space;
  DrawText(image_, x, text_y, low, colors::kInk, scale_);
  x += low_w + space / 2;
  const int bar_top = text_y - 1;
  const int bar_bottom = text_y + BitmapFont::TextHeight(scale_) + 1;
  for (int i = 0; i < bar; ++i) {
    FillRect(image_, x + i, bar_top, x + i + 1, bar_bottom, colour_of((i + 0.5) / bar));
  }
  x += bar + space / 2;
  DrawText(image_, x, text_y, high, colors::kInk, scale_);
}

double LegendLayout::ScaleBarLength(const ViewTransform& view, int target_px) {
  const double target_m = std::max(target_px / view.px_per_m(), 0.01);
  const double decade = std::pow(10.0, std::floor(std::log10(target_m)));
  double best = decade;
  for (double mantissa : {1.0, 2.0, 5.0}) {
    if (mantissa * decade <= target_m * (1.0 + 1e-9)) best = mantissa * decade;
  }
  return best;
}

void LegendLayout::ScaleBar(const ViewTransform& view, int target_px) {
  const double length_m = ScaleBarLength(view, target_px);
  const int length_px = static_cast<int>(std::lround(view.ToPixels(length_m)));
  const std::string label = FormatMetres(length_m);
  const int space = BitmapFont::kAdvance * scale_;
  const int left = Place(length_px + space + BitmapFont::TextWidth(label, scale_));
  if (!image_) return;
  const int text_y = y0_ + row_ * RowHeight();
  const int bar_y = text_y + BitmapFont::TextHeight(scale_) / 2;
  const int thickness = std::max(2, scale_);
  FillRect(image_, left, bar_y - thickness / 2, left + length_px, bar_y - thickness / 2 + thickness,
           colors::kInk);
  const int tick = BitmapFont::TextHeight(scale_) / 2 + 1;
  FillRect(image_, left, bar_y - tick, left + thickness, bar_y + tick, colors::kInk);
  FillRect(image_, left + length_px - thickness, bar_y - tick, left + length_px, bar_y + tick,
           colors::kInk);
  DrawText(image_, left + length_px + space, text_y, label, colors::kInk, scale_);
}

}  // namespace topay::viz
