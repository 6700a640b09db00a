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
  // Validates first, so a bad option leaves this field as it was.
  const GridGeometry2& g = occupancy.geometry();
  const double max_distance_m = g.Bounds().diagonal().norm();
  BuildSignedDistanceValues(occupancy.cells().data(), Eigen::Vector3i(g.dims.x(), g.dims.y(), 1), 2, g.resolution_m,
                            max_distance_m, options, workspace, &values_);
  geometry_ = g;
  inv_resolution_ = 1.0 / g.resolution_m;
  max_distance_m_ = max_distance_m;
}

}  // namespace topay
