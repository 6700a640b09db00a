#include "tools/viz/painter.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace topay::viz {
namespace {

constexpr const char* kFontFace = "sans-serif";

void SelectFont(cairo_t* cr, double size_px) {
  cairo_select_font_face(cr, kFontFace, CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, size_px);
}

// A scratch context for text measurement (text metrics do not depend on the target).
class Measurer {
 public:
  Measurer()
      : surface_(cairo_image_surface_create(CAIRO_FORMAT_RGB24, 1, 1)), cr_(cairo_create(surface_)) {}
  ~Measurer() {
    cairo_destroy(cr_);
    cairo_surface_destroy(surface_);
  }
  cairo_t* cr() { return cr_; }

 private:
  cairo_surface_t* surface_;
  cairo_t* cr_;
};

}  // namespace

Painter::Painter(Image* image) : cr_(cairo_create(image->surface())) {
  cairo_set_antialias(cr_, CAIRO_ANTIALIAS_GOOD);
  cairo_set_fill_rule(cr_, CAIRO_FILL_RULE_EVEN_ODD);
  cairo_set_line_join(cr_, CAIRO_LINE_JOIN_ROUND);
  cairo_set_line_cap(cr_, CAIRO_LINE_CAP_ROUND);
}

Painter::Painter(Painter&& other) noexcept : cr_(std::exchange(other.cr_, nullptr)) {}

Painter& Painter::operator=(Painter&& other) noexcept {
  std::swap(cr_, other.cr_);
  return *this;
}

Painter::~Painter() {
  if (cr_ != nullptr) cairo_destroy(cr_);
}

void Painter::SetSource(const Rgb& colour, double alpha) {
  alpha = std::isnan(alpha) ? 0.0 : std::clamp(alpha, 0.0, 1.0);
  cairo_set_source_rgba(cr_, colour.r / 255.0, colour.g / 255.0, colour.b / 255.0, alpha);
}

void Painter::PathOf(std::span<const Eigen::Vector2d> points, bool closed) {
  cairo_new_path(cr_);
  bool open = false;
  for (const Eigen::Vector2d& p : points) {
    if (!p.allFinite()) {
      open = false;
      continue;
    }
    if (open) {
      cairo_line_to(cr_, p.x(), p.y());
    } else {
      cairo_move_to(cr_, p.x(), p.y());
      open = true;
    }
  }
  if (closed) cairo_close_path(cr_);
}

void Painter::FillPolygon(std::span<const Eigen::Vector2d> vertices_px, const Rgb& colour,
                          double alpha) {
  if (vertices_px.size() < 3) return;
  PathOf(vertices_px, /*closed=*/true);
  SetSource(colour, alpha);
  cairo_fill(cr_);
}

void Painter::HatchPolygon(std::span<const Eigen::Vector2d> vertices_px, const Rgb& colour,
                           double spacing_px, double stripe_px, double alpha) {
  if (vertices_px.size() < 3 || !(spacing_px > 0.0) || !(stripe_px > 0.0)) return;
  cairo_save(cr_);
  PathOf(vertices_px, /*closed=*/true);
  double x0, y0, x1, y1;
  cairo_path_extents(cr_, &x0, &y0, &x1, &y1);
  cairo_clip(cr_);
  // Lines x + y = c for c a multiple of the spacing, across the polygon's bounding box.
  cairo_new_path(cr_);
  for (double c = std::floor((x0 + y0) / spacing_px) * spacing_px; c <= x1 + y1;
       c += spacing_px) {
    cairo_move_to(cr_, c - y0, y0);
    cairo_line_to(cr_, c - y1, y1);
  }
  SetSource(colour, alpha);
  cairo_set_line_width(cr_, stripe_px);
  cairo_set_line_cap(cr_, CAIRO_LINE_CAP_BUTT);
  cairo_stroke(cr_);
  cairo_restore(cr_);
}

void Painter::DrawPolyline(std::span<const Eigen::Vector2d> points_px, bool closed,
                           const Rgb& colour, double width_px, double alpha,
                           const DashPattern* dash) {
  if (points_px.size() < 2 || !(width_px > 0.0)) return;
  cairo_save(cr_);
  PathOf(points_px, closed);
  if (dash != nullptr) {
    const double pattern[] = {dash->dash_px, dash->gap_px};
    cairo_set_dash(cr_, pattern, 2, 0.0);
    cairo_set_line_cap(cr_, CAIRO_LINE_CAP_BUTT);
  }
  SetSource(colour, alpha);
  cairo_set_line_width(cr_, width_px);
  cairo_stroke(cr_);
  cairo_restore(cr_);
}

void Painter::DrawLine(const Eigen::Vector2d& a_px, const Eigen::Vector2d& b_px,
                       const Rgb& colour, double width_px, double alpha) {
  const Eigen::Vector2d points[] = {a_px, b_px};
  DrawPolyline(points, /*closed=*/false, colour, width_px, alpha);
}

void Painter::DrawDashedLine(const Eigen::Vector2d& a_px, const Eigen::Vector2d& b_px,
                             const Rgb& colour, double width_px, const DashPattern& pattern,
                             double alpha) {
  if (!a_px.allFinite() || !b_px.allFinite()) return;
  if (!(pattern.dash_px > 0.0) || !(pattern.gap_px >= 0.0)) return;
  const Eigen::Vector2d points[] = {a_px, b_px};
  DrawPolyline(points, /*closed=*/false, colour, width_px, alpha, &pattern);
}

void Painter::FillCircle(const Eigen::Vector2d& centre_px, double radius_px, const Rgb& colour,
                         double alpha) {
  if (!centre_px.allFinite() || !(radius_px > 0.0)) return;
  cairo_new_path(cr_);
  cairo_arc(cr_, centre_px.x(), centre_px.y(), radius_px, 0.0, 2.0 * M_PI);
  SetSource(colour, alpha);
  cairo_fill(cr_);
}

void Painter::StrokeCircle(const Eigen::Vector2d& centre_px, double radius_px, const Rgb& colour,
                           double width_px, double alpha) {
  if (!centre_px.allFinite() || !(radius_px > 0.0) || !(width_px > 0.0)) return;
  cairo_new_path(cr_);
  cairo_arc(cr_, centre_px.x(), centre_px.y(), radius_px, 0.0, 2.0 * M_PI);
  SetSource(colour, alpha);
  cairo_set_line_width(cr_, width_px);
  cairo_stroke(cr_);
}

void Painter::FillRect(double x0, double y0, double x1, double y1, const Rgb& colour,
                       double alpha) {
  if (!(x1 > x0) || !(y1 > y0)) return;
  cairo_new_path(cr_);
  cairo_rectangle(cr_, x0, y0, x1 - x0, y1 - y0);
  SetSource(colour, alpha);
  cairo_fill(cr_);
}

void Painter::StrokeRect(double x0, double y0, double x1, double y1, const Rgb& colour,
                         double width_px) {
  const double h = 0.5 * width_px;
  if (!(x1 - x0 > width_px) || !(y1 - y0 > width_px)) return;
  cairo_save(cr_);
  cairo_new_path(cr_);
  cairo_rectangle(cr_, x0 + h, y0 + h, x1 - x0 - width_px, y1 - y0 - width_px);
  SetSource(colour, 1.0);
  cairo_set_line_width(cr_, width_px);
  cairo_set_line_join(cr_, CAIRO_LINE_JOIN_MITER);
  cairo_stroke(cr_);
  cairo_restore(cr_);
}

void Painter::Text(double x_px, double y_px, const std::string& text, const Rgb& colour,
                   double size_px, TextAlign align) {
  if (text.empty() || !(size_px > 0.0)) return;
  SelectFont(cr_, size_px);
  cairo_text_extents_t extents;
  cairo_text_extents(cr_, text.c_str(), &extents);
  double x = x_px;
  if (align == TextAlign::kCentre) x -= 0.5 * extents.x_advance;
  if (align == TextAlign::kRight) x -= extents.x_advance;
  cairo_new_path(cr_);
  cairo_move_to(cr_, x, y_px + TextAscent(size_px));
  SetSource(colour, 1.0);
  cairo_show_text(cr_, text.c_str());
}

void Painter::VerticalText(double x_px, double y_px, const std::string& text, const Rgb& colour,
                           double size_px) {
  cairo_save(cr_);
  cairo_translate(cr_, x_px, y_px);
  cairo_rotate(cr_, -0.5 * M_PI);
  Text(0.0, -0.5 * LineHeight(size_px), text, colour, size_px, TextAlign::kCentre);
  cairo_restore(cr_);
}

void Painter::PushClip(double x0, double y0, double x1, double y1) {
  cairo_save(cr_);
  cairo_new_path(cr_);
  cairo_rectangle(cr_, x0, y0, std::max(x1 - x0, 0.0), std::max(y1 - y0, 0.0));
  cairo_clip(cr_);
}

void Painter::PopClip() { cairo_restore(cr_); }

double TextWidth(const std::string& text, double size_px) {
  if (text.empty() || !(size_px > 0.0)) return 0.0;
  Measurer measurer;
  SelectFont(measurer.cr(), size_px);
  cairo_text_extents_t extents;
  cairo_text_extents(measurer.cr(), text.c_str(), &extents);
  return extents.x_advance;
}

double TextAscent(double size_px) {
  // In the 1.3 em line box, capitals (about 0.73 em tall) then span 0.27..1.0 em and
  // descenders reach 1.24 em: the text sits in the box with a little air above and below.
  return size_px;
}

}  // namespace topay::viz
