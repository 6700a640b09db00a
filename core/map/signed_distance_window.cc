#include "core/map/signed_distance_window.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace topay {

int SignedDistanceReachCells(double cap_m, double resolution_m) {
  if (!(std::isfinite(cap_m) && cap_m > 0.0 && std::isfinite(resolution_m) && resolution_m > 0.0)) {
    throw std::invalid_argument(
        "SignedDistanceReachCells: cap_m and resolution_m must be finite and > 0");
  }
  return static_cast<int>(std::ceil(cap_m / resolution_m + 1.0)) + 1;
}

void RecomputeSignedDistanceWindow(const std::uint8_t* cells, const Eigen::Vector3i& dims,
                                   int num_axes, double resolution_m, double cap_m,
                                   const SignedDistanceFieldOptions& options, const CellBox& target,
                                   SignedDistanceWindowWorkspace* ws, float* values) {
  ValidateSignedDistanceFieldOptions(options);
  const CellBox grid{Eigen::Vector3i::Zero(), dims};
  if (target.empty() || (target.begin.array() < 0).any() ||
      (target.end.array() > dims.array()).any()) {
    throw std::invalid_argument("RecomputeSignedDistanceWindow: target window outside the grid");
  }
  const int reach = SignedDistanceReachCells(cap_m, resolution_m);
  Eigen::Vector3i reach_cells = Eigen::Vector3i::Constant(reach);
  if (num_axes == 2) reach_cells.z() = 0;
  const CellBox source = target.Dilated(reach_cells, dims);
  if (source.begin == grid.begin && source.end == grid.end) {
    // The whole grid: the full build, in place. Its values outside the target are as valid.
    SquaredDistanceToOtherPhase(cells, dims, values, &ws->edt);
    SignedValuesFromSquaredDistancesInWindow(cells, dims, Eigen::Vector3i::Zero(), dims, num_axes,
                                             resolution_m, cap_m, options, values);
    return;
  }
  // 1. Gather the source window's cells, row by row (x runs are contiguous).
  const Eigen::Vector3i s = source.sizes();
  const std::int64_t num_source = source.NumCells();
  ws->cells.resize(static_cast<std::size_t>(num_source));
  ws->values.resize(static_cast<std::size_t>(num_source));
  const std::int64_t nx = dims.x(), nxy = std::int64_t{dims.x()} * dims.y();
  std::uint8_t* window_cells = ws->cells.data();
  for (int z = 0; z < s.z(); ++z) {
    for (int y = 0; y < s.y(); ++y) {
      const std::uint8_t* row =
          cells + (source.begin.z() + z) * nxy + (source.begin.y() + y) * nx + source.begin.x();
      std::copy(row, row + s.x(), window_cells + (std::int64_t{z} * s.y() + y) * s.x());
    }
  }
  // 2. The exact EDT of the window, its later passes only on the lines through the target.
  float* window_values = ws->values.data();
  const Eigen::Vector3i t = target.sizes();
  const Eigen::Vector3i offset = target.begin - source.begin;
  SquaredDistanceToOtherPhaseAt(window_cells, s, offset, offset + t, window_values, &ws->edt);
  // 3. Gather the target's squared distances and cells, and make them signed, capped values
  // placed in the grid (the full build's conversion, on the target's block).
  ws->target_cells.resize(static_cast<std::size_t>(target.NumCells()));
  ws->target_values.resize(static_cast<std::size_t>(target.NumCells()));
  for (int z = 0; z < t.z(); ++z) {
    for (int y = 0; y < t.y(); ++y) {
      const std::int64_t from =
          (std::int64_t{offset.z() + z} * s.y() + offset.y() + y) * s.x() + offset.x();
      const std::int64_t to = (std::int64_t{z} * t.y() + y) * t.x();
      std::copy(window_values + from, window_values + from + t.x(), ws->target_values.data() + to);
      std::copy(window_cells + from, window_cells + from + t.x(), ws->target_cells.data() + to);
    }
  }
  SignedValuesFromSquaredDistancesInWindow(ws->target_cells.data(), t, target.begin, dims, num_axes,
                                           resolution_m, cap_m, options, ws->target_values.data());
  // 4. Scatter the target's rows into the grid's values.
  for (int z = 0; z < t.z(); ++z) {
    for (int y = 0; y < t.y(); ++y) {
      const float* from = ws->target_values.data() + (std::int64_t{z} * t.y() + y) * t.x();
      float* to =
          values + (target.begin.z() + z) * nxy + (target.begin.y() + y) * nx + target.begin.x();
      std::copy(from, from + t.x(), to);
    }
  }
}

}  // namespace topay
