#pragma once

#include <vector>

#include <Eigen/Core>

#include "core/geometry/oriented_box.h"
#include "sim/scenes/room_options.h"

namespace topay {

/// Layout of one group of adjacent tables in its own frame G (upright, yawed by yaw_rad about
/// W's z, origin at the centre of the group's footprint on the floor).
struct TableGroupLayout {
  Eigen::Vector2d center_W_m = Eigen::Vector2d::Zero();
  double yaw_rad = 0.0;
  std::vector<double> column_widths_m;  ///< Along G's x; one entry per column.
  std::vector<double> row_depths_m;     ///< Along G's y; one entry per row.
  double top_height_m = 0.75;           ///< Upper face of the tops above the floor.

  /// The group's footprint (sum of widths x sum of depths) up to the top height.
  OrientedBox Envelope() const;
};

/// The boxes of the group: for each table (row-major), its top then its four legs. Tops are
/// top_thickness_m thick with the upper face at top_height_m; legs are leg_width_m square,
/// from the floor to the top's lower face, flush with the table's corners.
std::vector<OrientedBox> MakeTableGroupBoxes(const TableGroupLayout& layout,
                                             const TableGroupOptions& options);

}  // namespace topay
