#include "core/map/signed_distance_field.h"

#include <stdexcept>
#include <string>

namespace topay {
namespace {

template <int Dim>
std::string Name(const char* method) {
  return std::string(Dim == 2 ? "SignedDistanceField2::" : "SignedDistanceField3::") + method;
}

Eigen::Vector3i Dims3(const GridGeometry2& g) { return {g.dims.x(), g.dims.y(), 1}; }
Eigen::Vector3i Dims3(const GridGeometry3& g) { return g.dims; }

}  // namespace

template <int Dim>
SignedDistanceField<Dim> SignedDistanceField<Dim>::Build(const OccupancyGrid<Dim>& occupancy,
                                                         const SignedDistanceFieldOptions& options,
                                                         EdtWorkspace* workspace) {
  SignedDistanceField field;
  field.Rebuild(occupancy, options, workspace);
  return field;
}

template <int Dim>
void SignedDistanceField<Dim>::Rebuild(const OccupancyGrid<Dim>& occupancy,
                                       const SignedDistanceFieldOptions& options,
                                       EdtWorkspace* workspace) {
  // Validates first, so a bad option leaves this field as it was.
  const Geometry& g = occupancy.geometry();
  const double max_distance_m = g.Bounds().diagonal().norm();
  BuildSignedDistanceValues(occupancy.cells().data(), Dims3(g), Dim, g.resolution_m,
                            max_distance_m, options, workspace, &values_);
  geometry_ = g;
  inv_resolution_ = 1.0 / g.resolution_m;
  max_distance_m_ = max_distance_m;
  exactness_margin_m_ = std::sqrt(static_cast<double>(Dim)) * g.resolution_m;
  offset_band_.reset();  // a rebuilt field holds no lowered band
  primary_band_.reset();
}

template <int Dim>
SignedDistanceField<Dim> SignedDistanceField<Dim>::FromCellValues(const Geometry& geometry,
                                                                  std::vector<float> values,
                                                                  double max_distance_m,
                                                                  double exactness_margin_m) {
  const std::string where = Name<Dim>("FromCellValues");
  geometry.Validate(where.c_str());
  if (static_cast<std::int64_t>(values.size()) != geometry.NumCells()) {
    throw std::invalid_argument(where + ": " + std::to_string(values.size()) + " values for " +
                                std::to_string(geometry.NumCells()) + " cells");
  }
  if (!(exactness_margin_m >= 0.0) || !std::isfinite(exactness_margin_m)) {
    throw std::invalid_argument(where + ": exactness_margin_m must be finite and >= 0");
  }
  SignedDistanceField field;
  field.geometry_ = geometry;
  field.inv_resolution_ = 1.0 / geometry.resolution_m;
  field.max_distance_m_ = max_distance_m;
  field.exactness_margin_m_ = exactness_margin_m;
  field.values_ = std::move(values);
  return field;
}

template <int Dim>
void SignedDistanceField<Dim>::LowerTo(const SignedDistanceField& other, double offset_m) {
  const Geometry& g = other.geometry();
  if (g.dims != geometry_.dims || g.resolution_m != geometry_.resolution_m ||
      g.origin_W_m != geometry_.origin_W_m) {
    throw std::invalid_argument(Name<Dim>("LowerTo") + ": the fields' grids differ");
  }
  if (!std::isfinite(offset_m)) {
    throw std::invalid_argument(Name<Dim>("LowerTo") + ": offset_m must be finite");
  }
  if (!primary_band_) primary_band_ = std::make_shared<SignedDistanceField>(*this);
  for (std::size_t i = 0; i < values_.size(); ++i) {
    values_[i] = std::min(values_[i], static_cast<float>(other.values_[i] + offset_m));
  }
  max_distance_m_ = std::max(max_distance_m_, other.max_distance_m_ + offset_m);
  exactness_margin_m_ = std::max(exactness_margin_m_, other.exactness_margin_m_);
}

template <int Dim>
std::vector<float>* SignedDistanceField<Dim>::mutable_primary_band_values() {
  if (!primary_band_) return nullptr;
  // Copy on write: a copy of this field (use count > 1) keeps the band it was copied with.
  if (primary_band_.use_count() > 1) {
    primary_band_ = std::make_shared<SignedDistanceField>(*primary_band_);
  }
  // The band is ours alone now, and it is a non-const object (made by make_shared of the
  // non-const type, here and in LowerTo), so writing through const_cast is defined.
  return &const_cast<SignedDistanceField*>(primary_band_.get())->values_;
}

template class SignedDistanceField<2>;
template class SignedDistanceField<3>;

}  // namespace topay
