#include "core/map/signed_distance_field2.h"

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
  ValidateSignedDistanceFieldOptions(options);
  EdtWorkspace local;
  EdtWorkspace* ws = workspace ? workspace : &local;
  geometry_ = occupancy.geometry();
  inv_resolution_ = 1.0 / geometry_.resolution_m;
  max_distance_m_ = geometry_.Bounds().diagonal().norm();
  const std::size_t n = static_cast<std::size_t>(geometry_.NumCells());
  values_.resize(n);
  const std::uint8_t* cells = occupancy.cells().data();
  const Eigen::Vector3i dims(geometry_.dims.x(), geometry_.dims.y(), 1);
  SquaredDistanceToOtherPhase(cells, dims, values_.data(), ws);
  SignedValuesFromSquaredDistances(cells, dims, 2, geometry_.resolution_m,
                                   max_distance_m_, options, values_.data());
}

}  // namespace topay
