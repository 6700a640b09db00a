#include "tools/viz/legend.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace topay::viz {
namespace {

std::string FormatMetres(double length_m) {
  std::ostringstream out;
  out << length_m << " m";
  return out.str();
}

}  // namespace

LegendLayout::LegendLayout(Painter* painter, double x0, double y0, double width_px,
                           double font_px)
    : painter_(painter), x0_(x0), y0_(y0), width_(width_px), font_(std::max(font_px, 4.0)),
      pen_x_(x0) {}

double LegendLayout::RowHeight() const { return LineHeight(font_) + 0.5 * font_; }
double LegendLayout::Gap() const { return 1.5 * font_; }
double LegendLayout::Top() const { return y0_ + row_ * RowHeight(); }

double LegendLayout::height() const { return (row_ + (row_empty_ ? 0 : 1)) * RowHeight(); }

void LegendLayout::NewRow() {
  if (row_empty_) return;
  ++row_;
  pen_x_ = x0_;
  row_empty_ = true;
}

double LegendLayout::Place(double width) {
  if (!row_empty_ && pen_x_ + width > x0_ + width_) NewRow();
  const double left = pen_x_;
  pen_x_ += width + Gap();
  row_empty_ = false;
  return left;
}

void LegendLayout::Text(const std::string& text, const Rgb& colour) {
  const double left = Place(TextWidth(text, font_));
  if (painter_) painter_->Text(left, Top(), text, colour, font_);
}

void LegendLayout::Swatch(const Rgb& fill, const Rgb& outline, const std::string& label,
                          bool hatched) {
  const double side = std::round(0.9 * font_);
  const double text_x = side + 0.5 * font_;
  const double left = std::round(Place(text_x + TextWidth(label, font_)));
  if (!painter_) return;
  const double top = std::round(Top() + 0.5 * (LineHeight(font_) - side));
  const Eigen::Vector2d corners[] = {
      {left, top}, {left + side, top}, {left + side, top + side}, {left, top + side}};
  painter_->FillPolygon(corners, fill, hatched ? 0.35 : 1.0);
  if (hatched) painter_->HatchPolygon(corners, outline, 4.0, 1.0);
  painter_->StrokeRect(left, top, left + side, top + side, outline, 1.0);
  painter_->Text(left + text_x, Top(), label, colors::kInk, font_);
}

void LegendLayout::LineKey(const Rgb& colour, double width_px, const std::string& label) {
  const double key = 1.6 * font_;
  const double left = Place(key + 0.4 * font_ + TextWidth(label, font_));
  if (!painter_) return;
  const double mid = Top() + 0.65 * font_;
  painter_->DrawLine({left, mid}, {left + key, mid}, colour, width_px);
  painter_->Text(left + key + 0.4 * font_, Top(), label, colors::kInk, font_);
}

LegendBox LegendLayout::ColourBar(const std::string& caption,
                                  const std::function<Rgb(double)>& colour_of,
                                  const std::string& low, const std::string& high) {
  const double space = 0.5 * font_;
  const double caption_w = TextWidth(caption, font_);
  const double low_w = TextWidth(low, font_);
  const double high_w = TextWidth(high, font_);
  // 10 em long, shorter (down to 3 em) where the strip is narrow, so the labels fit.
  const double room = width_ - (caption_w + low_w + high_w + 4 * space);
  const double bar = std::round(std::clamp(room, 3.0 * font_, 10.0 * font_));
  const double left = Place(caption_w + low_w + bar + high_w + 4 * space);
  double x = left + caption_w + space;
  LegendBox box;
  box.x0 = std::round(x + low_w + space);
  box.x1 = box.x0 + bar;
  box.y0 = std::round(Top() + 0.1 * font_);
  box.y1 = std::round(Top() + 1.2 * font_);
  if (!painter_) return box;
  painter_->Text(left, Top(), caption, colors::kInk, font_);
  painter_->Text(x, Top(), low, colors::kInk, font_);
  for (int i = 0; i < static_cast<int>(bar); ++i) {
    painter_->FillRect(box.x0 + i, box.y0, box.x0 + i + 1, box.y1, colour_of((i + 0.5) / bar));
  }
  painter_->Text(box.x1 + space, Top(), high, colors::kInk, font_);
  return box;
}

double LegendLayout::ScaleBarLength(const ViewTransform& view, double target_px) {
  const double target_m = std::max(target_px / view.px_per_m(), 0.01);
  const double decade = std::pow(10.0, std::floor(std::log10(target_m)));
  double best = decade;
  for (double mantissa : {1.0, 2.0, 5.0}) {
    if (mantissa * decade <= target_m * (1.0 + 1e-9)) best = mantissa * decade;
  }
  return best;
}

LegendBox LegendLayout::ScaleBar(const ViewTransform& view, double target_px) {
  const double length_m = ScaleBarLength(view, target_px);
  const double length_px = std::round(view.ToPixels(length_m));
  const std::string label = FormatMetres(length_m);
  const double space = 0.5 * font_;
  const double left = std::round(Place(length_px + space + TextWidth(label, font_)));
  const double mid = std::round(Top() + 0.65 * font_);
  LegendBox box{left, mid - 1.0, left + length_px, mid + 1.0};
  if (!painter_) return box;
  const double tick = 0.4 * font_;
  painter_->FillRect(box.x0, box.y0, box.x1, box.y1, colors::kInk);
  painter_->FillRect(left, mid - tick, left + 2.0, mid + tick, colors::kInk);
  painter_->FillRect(box.x1 - 2.0, mid - tick, box.x1, mid + tick, colors::kInk);
  painter_->Text(box.x1 + space, Top(), label, colors::kInk, font_);
  return box;
}

}  // namespace topay::viz
