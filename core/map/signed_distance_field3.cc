#include "core/map/signed_distance_field3.h"

#include "core/map/signed_distance_values.h"

namespace topay {

SignedDistanceField3 SignedDistanceField3::Build(const OccupancyGrid3& occupancy,
                                                 const SignedDistanceFieldOptions& options,
                                                 EdtWorkspace* workspace) {
  SignedDistanceField3 field;
  field.Rebuild(occupancy, options, workspace);
  return field;
}

void SignedDistanceField3::Rebuild(const OccupancyGrid3& occupancy,
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
  SquaredDistanceToOtherPhase(cells, geometry_.dims, values_.data(), ws);
  SignedValuesFromSquaredDistances(cells, geometry_.dims, 3,
                                   geometry_.resolution_m, max_distance_m_, options,
                                   values_.data());
}

}  // namespace topay
