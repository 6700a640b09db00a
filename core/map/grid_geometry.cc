#include "core/map/grid_geometry.h"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>

namespace topay {
namespace {

// Cells per axis covering [low, high]: ceil(extent / resolution), at least 2. A relative slack
// of 1e-9 keeps an extent that is a whole number of cells (20 m / 0.1 m) from gaining a cell to
// rounding. Validates as FromBounds documents; `what` names the caller for the message.
template <int Dim>
Eigen::Matrix<int, Dim, 1> CellsCovering(const Eigen::AlignedBox<double, Dim>& bounds_W_m,
                                         double resolution_m, const char* what) {
  if (!std::isfinite(resolution_m) || resolution_m <= 0.0) {
    throw std::invalid_argument(std::string(what) + ": resolution_m must be finite and > 0, got " +
                                std::to_string(resolution_m));
  }
  if (!bounds_W_m.min().allFinite() || !bounds_W_m.max().allFinite() || bounds_W_m.isEmpty() ||
      (bounds_W_m.sizes().array() <= 0.0).any()) {
    throw std::invalid_argument(std::string(what) +
                                ": bounds_W_m must be finite with max > min on every axis");
  }
  Eigen::Matrix<int, Dim, 1> dims;
  double total = 1.0;
  for (int a = 0; a < Dim; ++a) {
    const double cells = std::ceil(bounds_W_m.sizes()(a) / resolution_m * (1.0 - 1e-9));
    total *= std::max(cells, 2.0);
    if (total > std::numeric_limits<int>::max()) {
      throw std::invalid_argument(std::string(what) +
                                  ": the grid would have more than 2^31 - 1 cells");
    }
    dims(a) = static_cast<int>(std::max(cells, 2.0));
  }
  return dims;
}

template <int Dim>
void ValidateGeometry(const Eigen::Matrix<double, Dim, 1>& origin_W_m, double resolution_m,
                      const Eigen::Matrix<int, Dim, 1>& dims, const char* where) {
  if (!origin_W_m.allFinite() || !std::isfinite(resolution_m) || resolution_m <= 0.0) {
    throw std::invalid_argument(std::string(where) +
                                ": grid origin must be finite and resolution_m finite and > 0");
  }
  double total = 1.0;
  for (int a = 0; a < Dim; ++a) total *= dims(a);
  if ((dims.array() < 2).any() || total > std::numeric_limits<int>::max()) {
    throw std::invalid_argument(std::string(where) +
                                ": grid needs at least 2 cells per axis and at most 2^31 - 1 "
                                "cells in all");
  }
}

}  // namespace

void GridGeometry3::Validate(const char* where) const {
  ValidateGeometry<3>(origin_W_m, resolution_m, dims, where);
}

void GridGeometry2::Validate(const char* where) const {
  ValidateGeometry<2>(origin_W_m, resolution_m, dims, where);
}

GridGeometry3 GridGeometry3::FromBounds(const Eigen::AlignedBox3d& bounds_W_m,
                                        double resolution_m) {
  const Eigen::Vector3i dims = CellsCovering<3>(bounds_W_m, resolution_m, "GridGeometry3");
  return {bounds_W_m.min(), resolution_m, dims};
}

GridGeometry2 GridGeometry2::FromBounds(const Eigen::AlignedBox2d& bounds_W_m,
                                        double resolution_m) {
  const Eigen::Vector2i dims = CellsCovering<2>(bounds_W_m, resolution_m, "GridGeometry2");
  return {bounds_W_m.min(), resolution_m, dims};
}

}  // namespace topay
