#include "core/map/signed_distance_values.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace topay {
namespace {

// Distance in cells from cell i to the nearest virtual cell beyond the grid (index -1 or n).
inline int CellsToBorder(int i, int n) { return std::min(i + 1, n - i); }

}  // namespace

void ValidateSignedDistanceFieldOptions(const SignedDistanceFieldOptions& options) {
  if (!(options.zero_level_inset_cells >= 0.0 && options.zero_level_inset_cells <= 0.5)) {
    throw std::invalid_argument(
        "SignedDistanceFieldOptions: zero_level_inset_cells must be in [0, 0.5], got " +
        std::to_string(options.zero_level_inset_cells));
  }
}

void SignedValuesFromSquaredDistances(const std::uint8_t* cells, const Eigen::Vector3i& dims,
                                      int num_axes, double resolution_m,
                                      double max_distance_m,
                                      const SignedDistanceFieldOptions& options,
                                      float* squared_to_signed) {
  SignedValuesFromSquaredDistancesInWindow(cells, dims, Eigen::Vector3i::Zero(), dims, num_axes,
                                           resolution_m, max_distance_m, options,
                                           squared_to_signed);
}

void SignedValuesFromSquaredDistancesInWindow(const std::uint8_t* cells,
                                              const Eigen::Vector3i& window_dims,
                                              const Eigen::Vector3i& window_origin,
                                              const Eigen::Vector3i& grid_dims, int num_axes,
                                              double resolution_m, double max_distance_m,
                                              const SignedDistanceFieldOptions& options,
                                              float* squared_to_signed) {
  const float res = static_cast<float>(resolution_m);
  const float cap = static_cast<float>(max_distance_m);
  const float outside_offset = static_cast<float>(options.zero_level_inset_cells) - 0.5f;
  const float inside_offset = -0.5f - static_cast<float>(options.zero_level_inset_cells);
  const int no_border = std::numeric_limits<int>::max() / 2;
  const Eigen::Vector3i& o = window_origin;
  std::size_t i = 0;
  for (int iz = 0; iz < window_dims.z(); ++iz) {
    const int border_z =
        num_axes == 3 ? CellsToBorder(o.z() + iz, grid_dims.z()) : no_border;
    for (int iy = 0; iy < window_dims.y(); ++iy) {
      const int border_yz = std::min(border_z, CellsToBorder(o.y() + iy, grid_dims.y()));
      for (int ix = 0; ix < window_dims.x(); ++ix, ++i) {
        if (cells[i] == 0) {
          // sqrt(inf) = inf, clipped to the cap.
          const float root = std::sqrt(squared_to_signed[i]);
          squared_to_signed[i] = std::min((root + outside_offset) * res, cap);
        } else {
          const int border = std::min(border_yz, CellsToBorder(o.x() + ix, grid_dims.x()));
          const float squared =
              std::min(squared_to_signed[i], static_cast<float>(border * border));
          squared_to_signed[i] = -std::min((std::sqrt(squared) + inside_offset) * res, cap);
        }
      }
    }
  }
}

void BuildSignedDistanceValues(const std::uint8_t* cells, const Eigen::Vector3i& dims,
                               int num_axes, double resolution_m, double max_distance_m,
                               const SignedDistanceFieldOptions& options,
                               EdtWorkspace* workspace, std::vector<float>* values) {
  ValidateSignedDistanceFieldOptions(options);
  EdtWorkspace local;
  EdtWorkspace* ws = workspace ? workspace : &local;
  values->resize(static_cast<std::size_t>(dims.x()) * dims.y() * dims.z());
  SquaredDistanceToOtherPhase(cells, dims, values->data(), ws);
  SignedValuesFromSquaredDistances(cells, dims, num_axes, resolution_m, max_distance_m, options,
                                   values->data());
}

}  // namespace topay
