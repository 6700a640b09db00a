#include "core/map/signed_distance_field2.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "core/map/signed_distance_values.h"

namespace topay {

SignedDistanceField2 SignedDistanceField2::Build(const OccupancyGrid2& occupancy,
                                                 const SignedDistanceFieldOptions& options,
                                                 EdtWorkspace* workspace) {
  SignedDistanceField2 field;
  field.Rebuild(occupancy, options, workspace);
  return field;
}

void SignedDistanceField2::Rebuild(const OccupancyGrid2& occupancy,
                                   const SignedDistanceFieldOptions& options,
                                   EdtWorkspace* workspace) {
  // Validates first, so a bad option leaves this field as it was.
  const GridGeometry2& g = occupancy.geometry();
  const double max_distance_m = g.Bounds().diagonal().norm();
  BuildSignedDistanceValues(occupancy.cells().data(), Eigen::Vector3i(g.dims.x(), g.dims.y(), 1), 2, g.resolution_m,
                            max_distance_m, options, workspace, &values_);
  geometry_ = g;
  inv_resolution_ = 1.0 / g.resolution_m;
  max_distance_m_ = max_distance_m;
  exactness_margin_m_ = std::sqrt(2.0) * g.resolution_m;
}

SignedDistanceField2 SignedDistanceField2::FromCellValues(const GridGeometry2& geometry,
                                                          std::vector<float> values,
                                                          double max_distance_m,
                                                          double exactness_margin_m) {
  geometry.Validate("SignedDistanceField2::FromCellValues");
  if (static_cast<std::int64_t>(values.size()) != geometry.NumCells()) {
    throw std::invalid_argument("SignedDistanceField2::FromCellValues: " +
                                std::to_string(values.size()) + " values for " +
                                std::to_string(geometry.NumCells()) + " cells");
  }
  if (!(exactness_margin_m >= 0.0) || !std::isfinite(exactness_margin_m)) {
    throw std::invalid_argument(
        "SignedDistanceField2::FromCellValues: exactness_margin_m must be finite and >= 0");
  }
  SignedDistanceField2 field;
  field.geometry_ = geometry;
  field.inv_resolution_ = 1.0 / geometry.resolution_m;
  field.max_distance_m_ = max_distance_m;
  field.exactness_margin_m_ = exactness_margin_m;
  field.values_ = std::move(values);
  return field;
}

void SignedDistanceField2::LowerTo(const SignedDistanceField2& other, double offset_m) {
  const GridGeometry2& g = other.geometry();
  if (g.dims != geometry_.dims || g.resolution_m != geometry_.resolution_m ||
      g.origin_W_m != geometry_.origin_W_m) {
    throw std::invalid_argument("SignedDistanceField2::LowerTo: the fields' grids differ");
  }
  if (!std::isfinite(offset_m)) {
    throw std::invalid_argument("SignedDistanceField2::LowerTo: offset_m must be finite");
  }
  for (std::size_t i = 0; i < values_.size(); ++i) {
    values_[i] = std::min(values_[i], static_cast<float>(other.values_[i] + offset_m));
  }
  max_distance_m_ = std::max(max_distance_m_, other.max_distance_m_ + offset_m);
  exactness_margin_m_ = std::max(exactness_margin_m_, other.exactness_margin_m_);
}

}  // namespace topay
