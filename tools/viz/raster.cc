#include "tools/viz/raster.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace topay::viz {
namespace {

struct PixelBox {
  int x0, y0, x1, y1;  // Half-open: x0 <= x < x1.
};

// The pixels whose centres can lie within `pad` of the points, clipped to the image.
PixelBox BoundsOf(const Image& image, std::span<const Eigen::Vector2d> points, double pad) {
  double x_min = std::numeric_limits<double>::infinity();
  double y_min = x_min;
  double x_max = -x_min;
  double y_max = -x_min;
  for (const Eigen::Vector2d& p : points) {
    x_min = std::min(x_min, p.x());
    y_min = std::min(y_min, p.y());
    x_max = std::max(x_max, p.x());
    y_max = std::max(y_max, p.y());
  }
  auto clamp_to = [](double v, int hi) {
    return static_cast<int>(std::clamp(v, 0.0, static_cast<double>(hi)));
  };
  return {clamp_to(std::floor(x_min - pad), image.width()),
          clamp_to(std::floor(y_min - pad), image.height()),
          clamp_to(std::ceil(x_max + pad) + 1, image.width()),
          clamp_to(std::ceil(y_max + pad) + 1, image.height())};
}

bool AllFinite(std::span<const Eigen::Vector2d> points) {
  return std::all_of(points.begin(), points.end(),
                     [](const Eigen::Vector2d& p) { return p.allFinite(); });
}

// Calls paint(x, y) for every pixel whose centre is inside the polygon (even-odd rule):
// for each pixel row, the crossings of the row's centre line with the edges, sorted, bound the
// inside spans in pairs.
template <typename PaintFn>
void ScanPolygon(const Image& image, std::span<const Eigen::Vector2d> v, PaintFn paint) {
  if (v.size() < 3 || !AllFinite(v)) return;
  const PixelBox box = BoundsOf(image, v, 0.0);
  std::vector<double> crossings;
  for (int y = box.y0; y < box.y1; ++y) {
    const double yc = y + 0.5;
    crossings.clear();
    for (std::size_t i = 0; i < v.size(); ++i) {
      const Eigen::Vector2d& a = v[i];
      const Eigen::Vector2d& b = v[(i + 1) % v.size()];
      if ((a.y() <= yc) == (b.y() <= yc)) continue;
      crossings.push_back(a.x() + (yc - a.y()) * (b.x() - a.x()) / (b.y() - a.y()));
    }
    std::sort(crossings.begin(), crossings.end());
    for (std::size_t k = 0; k + 1 < crossings.size(); k += 2) {
      // Pixels whose centre x + 0.5 lies in [crossings[k], crossings[k + 1]).
      const int xa = std::max(box.x0, static_cast<int>(std::ceil(crossings[k] - 0.5)));
      const int xb = std::min(box.x1, static_cast<int>(std::ceil(crossings[k + 1] - 0.5)));
      for (int x = xa; x < xb; ++x) paint(x, y);
    }
  }
}

// Distance from p to the segment [a, b] (the textbook projection clamped to the segment).
double DistanceToSegment(const Eigen::Vector2d& p, const Eigen::Vector2d& a,
                         const Eigen::Vector2d& b) {
  const Eigen::Vector2d ab = b - a;
  const double length_sq = ab.squaredNorm();
  const double t = length_sq > 0.0 ? std::clamp((p - a).dot(ab) / length_sq, 0.0, 1.0) : 0.0;
  return (p - (a + t * ab)).norm();
}

// Opacity of a pixel whose centre is `excess` pixels inside an edge: 1 well inside, 0 outside,
// linear across the one-pixel-wide band around the edge (box-filter coverage estimate).
double Coverage(double excess) { return std::clamp(excess + 0.5, 0.0, 1.0); }

}  // namespace

void FillPolygon(Image* image, std::span<const Eigen::Vector2d> vertices_px, const Rgb& colour,
                 double alpha) {
  ScanPolygon(*image, vertices_px, [&](int x, int y) { image->Paint(x, y, colour, alpha); });
}

void HatchPolygon(Image* image, std::span<const Eigen::Vector2d> vertices_px, const Rgb& colour,
                  int spacing_px, int stripe_px, double alpha) {
  spacing_px = std::max(spacing_px, 1);
  ScanPolygon(*image, vertices_px, [&](int x, int y) {
    if ((x + y) % spacing_px < stripe_px) image->Paint(x, y, colour, alpha);
  });
}

void DrawPolyline(Image* image, std::span<const Eigen::Vector2d> points_px, bool closed,
                  const Rgb& colour, double width_px, double alpha) {
  if (points_px.empty() || !AllFinite(points_px) || !(width_px > 0.0)) return;
  const double half_width = 0.5 * width_px;
  const PixelBox box = BoundsOf(*image, points_px, half_width + 1.0);
  const std::size_t n = points_px.size();
  const std::size_t segments = n == 1 ? 1 : (closed ? n : n - 1);
  for (int y = box.y0; y < box.y1; ++y) {
    for (int x = box.x0; x < box.x1; ++x) {
      const Eigen::Vector2d centre(x + 0.5, y + 0.5);
      double distance = std::numeric_limits<double>::infinity();
      for (std::size_t i = 0; i < segments; ++i) {
        distance = std::min(distance,
                            DistanceToSegment(centre, points_px[i], points_px[(i + 1) % n]));
      }
      image->Paint(x, y, colour, alpha * Coverage(half_width - distance));
    }
  }
}

void DrawLine(Image* image, const Eigen::Vector2d& a_px, const Eigen::Vector2d& b_px,
              const Rgb& colour, double width_px, double alpha) {
  const Eigen::Vector2d points[] = {a_px, b_px};
  DrawPolyline(image, points, false, colour, width_px, alpha);
}

void FillCircle(Image* image, const Eigen::Vector2d& centre_px, double radius_px,
                const Rgb& colour, double alpha) {
  if (!centre_px.allFinite() || !(radius_px > 0.0)) return;
  const Eigen::Vector2d centre[] = {centre_px};
  const PixelBox box = BoundsOf(*image, centre, radius_px + 1.0);
  for (int y = box.y0; y < box.y1; ++y) {
    for (int x = box.x0; x < box.x1; ++x) {
      const double distance = (Eigen::Vector2d(x + 0.5, y + 0.5) - centre_px).norm();
      image->Paint(x, y, colour, alpha * Coverage(radius_px - distance));
    }
  }
}

void StrokeCircle(Image* image, const Eigen::Vector2d& centre_px, double radius_px,
                  const Rgb& colour, double width_px, double alpha) {
  if (!centre_px.allFinite() || !(radius_px > 0.0) || !(width_px > 0.0)) return;
  const Eigen::Vector2d centre[] = {centre_px};
  const PixelBox box = BoundsOf(*image, centre, radius_px + 0.5 * width_px + 1.0);
  for (int y = box.y0; y < box.y1; ++y) {
    for (int x = box.x0; x < box.x1; ++x) {
      const double distance = (Eigen::Vector2d(x + 0.5, y + 0.5) - centre_px).norm();
      image->Paint(x, y, colour, alpha * Coverage(0.5 * width_px - std::abs(distance - radius_px)));
    }
  }
}

void FillRect(Image* image, int x0, int y0, int x1, int y1, const Rgb& colour, double alpha) {
  x0 = std::max(x0, 0);
  y0 = std::max(y0, 0);
  x1 = std::min(x1, image->width());
  y1 = std::min(y1, image->height());
  for (int y = y0; y < y1; ++y) {
    for (int x = x0; x < x1; ++x) image->Paint(x, y, colour, alpha);
  }
}

}  // namespace topay::viz
