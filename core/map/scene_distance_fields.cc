#include "core/map/scene_distance_fields.h"

#include <chrono>
#include <stdexcept>
#include <string>

namespace topay {
namespace {

double SecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

SceneDistanceFields BuildSceneDistanceFields(const Scene& scene,
                                             const SceneDistanceFieldsOptions& options) {
  using Clock = std::chrono::steady_clock;
  const Clock::time_point start = Clock::now();
  ValidateBand(options.base_band, "SceneDistanceFieldsOptions: base_band");
  ValidateSignedDistanceFieldOptions(options.field);
  const GridGeometry3 geometry = GridGeometry3::FromBounds(
      options.bounds_W_m.value_or(scene.bounds_W_m), options.resolution_m);
  SceneDistanceFieldsSummary summary;

  Clock::time_point phase = Clock::now();
  OccupancyGrid3 occupancy_3d(geometry);
  OccupancyGrid2 occupancy_2d(GridGeometry2::FootprintOf(geometry));
  for (std::size_t i = 0; i < scene.boxes.size(); ++i) {
    try {
      occupancy_3d.AddBox(scene.boxes[i]);
    } catch (const std::invalid_argument& error) {
      throw std::invalid_argument("scene box " + std::to_string(i) + ": " + error.what());
    }
  }
  summary.rasterize_3d_s = SecondsSince(phase);

  phase = Clock::now();
  EdtWorkspace workspace;
  SignedDistanceField3 field_3d = SignedDistanceField3::Build(occupancy_3d, options.field, &workspace);
  summary.build_3d_s = SecondsSince(phase);

  phase = Clock::now();
  for (const OrientedBox& box : scene.boxes) {
    summary.num_boxes_in_base_band += occupancy_2d.AddBoxInBand(box, options.base_band) ? 1 : 0;
  }
  summary.rasterize_2d_s = SecondsSince(phase);

  phase = Clock::now();
  SignedDistanceField2 field_2d = SignedDistanceField2::Build(occupancy_2d, options.field, &workspace);
  summary.build_2d_s = SecondsSince(phase);

  summary.num_cells_3d = geometry.NumCells();
  summary.num_occupied_3d = occupancy_3d.CountOccupied();
  summary.num_cells_2d = occupancy_2d.geometry().NumCells();
  summary.num_occupied_2d = occupancy_2d.CountOccupied();
  summary.total_s = SecondsSince(start);
  return {std::move(field_3d), std::move(field_2d), summary};
}

}  // namespace topay
