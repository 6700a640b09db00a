#include "core/map/scene_distance_fields.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "core/map/box_distance_field.h"
#include "core/map/footprint_distance_field.h"

namespace topay {
namespace {

double SecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The 2D base grid: the 3D grid's footprint, or its own cell size over the same xy bounds.
GridGeometry2 BaseGeometry(const GridGeometry3& geometry_3d, const Eigen::AlignedBox3d& bounds_W_m,
                           double base_resolution_m) {
  if (!(std::isfinite(base_resolution_m) && base_resolution_m >= 0.0)) {
    throw std::invalid_argument(
        "SceneDistanceFieldsOptions: base_resolution_m must be finite and >= 0 (0: the 3D "
        "field's), got " + std::to_string(base_resolution_m));
  }
  if (base_resolution_m == 0.0) return GridGeometry2::FootprintOf(geometry_3d);
  return GridGeometry2::FromBounds(
      Eigen::AlignedBox2d(bounds_W_m.min().head<2>(), bounds_W_m.max().head<2>()),
      base_resolution_m);
}


// The 2D field from the band(s) rasterised on the base grid, by the EDT.
SignedDistanceField2 BuildRasterisedBaseField(const Scene& scene, const GridGeometry2& geometry,
                                              const SceneDistanceFieldsOptions& options,
                                              EdtWorkspace* workspace,
                                              SceneDistanceFieldsSummary* summary) {
  std::chrono::steady_clock::time_point phase = std::chrono::steady_clock::now();
  OccupancyGrid2 occupancy(geometry);
  for (const OrientedBox& box : scene.boxes) {
    summary->num_boxes_in_base_band += occupancy.AddBoxInBand(box, options.base_band) ? 1 : 0;
  }
  summary->rasterize_2d_s = SecondsSince(phase);
  phase = std::chrono::steady_clock::now();
  SignedDistanceField2 field = SignedDistanceField2::Build(occupancy, options.field, workspace);
  summary->build_2d_s = SecondsSince(phase);
  if (!options.base_upper_band) return field;
  phase = std::chrono::steady_clock::now();
  occupancy.ClearAll();
  for (const OrientedBox& box : scene.boxes) {
    summary->num_boxes_in_upper_band +=
        occupancy.AddBoxInBand(box, *options.base_upper_band) ? 1 : 0;
  }
  summary->rasterize_2d_s += SecondsSince(phase);
  phase = std::chrono::steady_clock::now();
  field.LowerTo(SignedDistanceField2::Build(occupancy, options.field, workspace),
                options.base_upper_band_offset_m);
  field.set_offset_band({*options.base_upper_band, options.base_upper_band_offset_m});
  summary->build_2d_s += SecondsSince(phase);
  return field;
}

// The 2D field from the exact footprint distances of the band(s) (no rasterisation).
SignedDistanceField2 BuildExactBaseField(const Scene& scene, const GridGeometry2& geometry,
                                         const SceneDistanceFieldsOptions& options,
                                         std::stop_token stop,
                                         SceneDistanceFieldsSummary* summary) {
  const std::chrono::steady_clock::time_point phase = std::chrono::steady_clock::now();
  FootprintDistanceFieldSummary band_summary;
  SignedDistanceField2 field =
      BuildFootprintDistanceField(geometry, scene.boxes, options.base_band,
                                  options.base_exact_cap_m, &band_summary, stop);
  summary->num_boxes_in_base_band = band_summary.num_boxes_in_band;
  summary->stopped = summary->stopped || band_summary.stopped;
  if (options.base_upper_band) {
    field.LowerTo(BuildFootprintDistanceField(geometry, scene.boxes, *options.base_upper_band,
                                              options.base_exact_cap_m, &band_summary, stop),
                  options.base_upper_band_offset_m);
    field.set_offset_band({*options.base_upper_band, options.base_upper_band_offset_m});
    summary->num_boxes_in_upper_band = band_summary.num_boxes_in_band;
    summary->stopped = summary->stopped || band_summary.stopped;
  }
  summary->build_2d_s = SecondsSince(phase);
  return field;
}

// The 3D field from the boxes rasterised on its grid, by the EDT.
SignedDistanceField3 BuildRasterisedArmField(const Scene& scene, const GridGeometry3& geometry,
                                             const SceneDistanceFieldsOptions& options,
                                             std::stop_token stop,
                                             SceneDistanceFieldsSummary* summary) {
  std::chrono::steady_clock::time_point phase = std::chrono::steady_clock::now();
  OccupancyGrid3 occupancy(geometry);
  for (std::size_t i = 0; i < scene.boxes.size(); ++i) {
    if (i % 1024 == 0 && stop.stop_requested()) {
      summary->stopped = true;
      break;
    }
    try {
      occupancy.AddBox(scene.boxes[i]);
    } catch (const std::invalid_argument& error) {
      throw std::invalid_argument("scene box " + std::to_string(i) + ": " + error.what());
    }
  }
  summary->rasterize_3d_s = SecondsSince(phase);
  summary->num_occupied_3d = occupancy.CountOccupied();
  phase = std::chrono::steady_clock::now();
  EdtWorkspace workspace;
  SignedDistanceField3 field = SignedDistanceField3::Build(occupancy, options.field, &workspace);
  summary->build_3d_s = SecondsSince(phase);
  return field;
}

// The 3D field from the exact box distances (no rasterisation).
SignedDistanceField3 BuildExactArmField(const Scene& scene, const GridGeometry3& geometry,
                                        const SceneDistanceFieldsOptions& options,
                                        std::stop_token stop,
                                        SceneDistanceFieldsSummary* summary) {
  const std::chrono::steady_clock::time_point phase = std::chrono::steady_clock::now();
  BoxDistanceFieldSummary arm_summary;
  SignedDistanceField3 field = BuildBoxDistanceField(geometry, scene.boxes,
                                                     options.arm_exact_cap_m, &arm_summary, stop);
  summary->stopped = summary->stopped || arm_summary.stopped;
  summary->num_occupied_3d = std::count_if(field.values().begin(), field.values().end(),
                                           [](float v) { return v <= 0.0f; });
  summary->build_3d_s = SecondsSince(phase);
  return field;
}

}  // namespace

double ArmFieldMargin(const SceneDistanceFieldsOptions& options) {
  return options.arm_exact_cap_m > 0.0 ? BoxDistanceFieldMargin(options.resolution_m)
                                       : std::sqrt(3.0) * options.resolution_m;
}

SceneDistanceFields BuildSceneDistanceFields(const Scene& scene,
                                             const SceneDistanceFieldsOptions& options,
                                             std::stop_token stop) {
  using Clock = std::chrono::steady_clock;
  const Clock::time_point start = Clock::now();
  ValidateBand(options.base_band, "SceneDistanceFieldsOptions: base_band");
  if (options.base_upper_band) {
    ValidateBand(*options.base_upper_band, "SceneDistanceFieldsOptions: base_upper_band");
    if (!(std::isfinite(options.base_upper_band_offset_m) &&
          options.base_upper_band_offset_m >= 0.0)) {
      throw std::invalid_argument(
          "SceneDistanceFieldsOptions: base_upper_band_offset_m must be finite and >= 0, got " +
          std::to_string(options.base_upper_band_offset_m));
    }
  }
  if (!(std::isfinite(options.arm_exact_cap_m) && options.arm_exact_cap_m >= 0.0)) {
    throw std::invalid_argument(
        "SceneDistanceFieldsOptions: arm_exact_cap_m must be finite and >= 0, got " +
        std::to_string(options.arm_exact_cap_m));
  }
  if (!(std::isfinite(options.base_exact_cap_m) && options.base_exact_cap_m >= 0.0)) {
    throw std::invalid_argument(
        "SceneDistanceFieldsOptions: base_exact_cap_m must be finite and >= 0, got " +
        std::to_string(options.base_exact_cap_m));
  }
  ValidateSignedDistanceFieldOptions(options.field);
  const Eigen::AlignedBox3d bounds_W_m = options.bounds_W_m.value_or(scene.bounds_W_m);
  const GridGeometry3 geometry = GridGeometry3::FromBounds(bounds_W_m, options.resolution_m);
  const GridGeometry2 base_geometry =
      BaseGeometry(geometry, bounds_W_m, options.base_resolution_m);
  SceneDistanceFieldsSummary summary;

  SignedDistanceField3 field_3d = options.arm_exact_cap_m > 0.0
                                      ? BuildExactArmField(scene, geometry, options, stop, &summary)
                                      : BuildRasterisedArmField(scene, geometry, options, stop,
                                                                &summary);
  EdtWorkspace workspace;
  SignedDistanceField2 field_2d = options.base_exact_cap_m > 0.0
                                      ? BuildExactBaseField(scene, base_geometry, options, stop,
                                                            &summary)
                                      : BuildRasterisedBaseField(scene, base_geometry, options,
                                                                 &workspace, &summary);
  summary.num_cells_3d = geometry.NumCells();
  summary.num_cells_2d = base_geometry.NumCells();
  summary.num_occupied_2d = std::count_if(field_2d.values().begin(), field_2d.values().end(),
                                          [](float v) { return v <= 0.0f; });
  summary.total_s = SecondsSince(start);
  return {std::move(field_3d), std::move(field_2d), summary};
}

}  // namespace topay
