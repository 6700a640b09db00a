#include "tools/viz/map_axes.h"

#include <algorithm>

#include "tools/viz/chart_ticks.h"

namespace topay::viz {

MapTicks MapAxisTicks(const ViewTransform& view, const MapAxesStyle& style) {
  const Eigen::AlignedBox2d& region = view.region_W_m();
  const double spacing_px = std::max(style.tick_spacing_px, 10.0);
  const int count = std::max(1, static_cast<int>(view.width_px() / spacing_px));
  MapTicks ticks;
  ticks.step_m = NiceTickStep(region.sizes().x(), count);
  ticks.x_m = TicksIn(region.min().x(), region.max().x(), ticks.step_m);
  ticks.y_m = TicksIn(region.min().y(), region.max().y(), ticks.step_m);
  return ticks;
}

double MapAxesLeftPx(const MapAxesStyle& style) {
  return style.tick_px + 3.0 + 2.8 * style.font_px + LineHeight(style.font_px) + 4.0;
}

double MapAxesBottomPx(const MapAxesStyle& style) {
  return style.tick_px + 2.0 + 2.0 * LineHeight(style.font_px) + 4.0;
}

void DrawMapAxes(Painter* painter, const ViewTransform& view, const MapAxesStyle& style) {
  const MapTicks ticks = MapAxisTicks(view, style);
  const double x0 = view.offset_px().x(), y0 = view.offset_px().y();
  const double x1 = x0 + view.width_px(), y1 = y0 + view.height_px();
  const double t = style.tick_px;
  const double f = style.font_px;
  painter->StrokeRect(x0 - 1.0, y0 - 1.0, x1 + 1.0, y1 + 1.0, style.colour, 1.0);
  for (double x_m : ticks.x_m) {
    const double u = view.ToPixel({x_m, 0.0}).x();
    painter->DrawLine({u, y1 + 1.0}, {u, y1 + 1.0 + t}, style.colour, 1.0);
    painter->DrawLine({u, y0 - 1.0}, {u, y0 - 1.0 - t}, style.colour, 1.0);
    painter->Text(u, y1 + t + 2.0, FormatTick(x_m, ticks.step_m), style.colour, f,
                  TextAlign::kCentre);
  }
  for (double y_m : ticks.y_m) {
    const double v = view.ToPixel({0.0, y_m}).y();
    painter->DrawLine({x0 - 1.0, v}, {x0 - 1.0 - t, v}, style.colour, 1.0);
    painter->DrawLine({x1 + 1.0, v}, {x1 + 1.0 + t, v}, style.colour, 1.0);
    painter->Text(x0 - t - 3.0, v - 0.5 * LineHeight(f) - 0.1 * f,
                  FormatTick(y_m, ticks.step_m), style.colour, f, TextAlign::kRight);
  }
  painter->Text(0.5 * (x0 + x1), y1 + t + 2.0 + LineHeight(f), "x (m)", style.colour, f,
                TextAlign::kCentre);
  painter->VerticalText(x0 - t - 3.0 - 2.8 * f - 0.5 * LineHeight(f), 0.5 * (y0 + y1), "y (m)",
                        style.colour, f);
}

}  // namespace topay::viz
