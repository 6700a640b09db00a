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
  // Validates first, so a bad option leaves this field as it was.
  const GridGeometry3& g = occupancy.geometry();
  const double max_distance_m = g.Bounds().diagonal().norm();
  BuildSignedDistanceValues(occupancy.cells().data(), g.dims, 3, g.resolution_m,
                            max_distance_m, options, workspace, &values_);
  geometry_ = g;
  inv_resolution_ = 1.0 / g.resolution_m;
  max_distance_m_ = max_distance_m;
}

}  // namespace topay
