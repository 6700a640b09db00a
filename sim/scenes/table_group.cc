#include "sim/scenes/table_group.h"

#include <cmath>
#include <numeric>

namespace topay {
namespace {

// Box of the given size, centred at p_G (in the group frame G), expressed in W.
OrientedBox PlaceInGroup(const TableGroupLayout& layout, const Eigen::Vector3d& p_G,
                         const Eigen::Vector3d& size_m) {
  const double c = std::cos(layout.yaw_rad);
  const double s = std::sin(layout.yaw_rad);
  OrientedBox box;
  // p_W = p_WG + R_WG(yaw) p_G (rotation about z).
  box.center_W_m = {layout.center_W_m.x() + c * p_G.x() - s * p_G.y(),
                    layout.center_W_m.y() + s * p_G.x() + c * p_G.y(), p_G.z()};
  box.size_m = size_m;
  box.yaw_rad = layout.yaw_rad;
  return box;
}

void AppendTable(const TableGroupLayout& layout, const TableGroupOptions& options,
                 const Eigen::Vector2d& center_G, double width, double depth,
                 std::vector<OrientedBox>* boxes) {
  const double thickness = options.top_thickness_m;
  const double leg = options.leg_width_m;
  const double top_z = layout.top_height_m;
  boxes->push_back(PlaceInGroup(layout, {center_G.x(), center_G.y(), top_z - 0.5 * thickness},
                                {width, depth, thickness}));
  const double leg_height = top_z - thickness;
  const double dx = 0.5 * (width - leg);
  const double dy = 0.5 * (depth - leg);
  for (const double sx : {-1.0, 1.0}) {
    for (const double sy : {-1.0, 1.0}) {
      boxes->push_back(PlaceInGroup(
          layout, {center_G.x() + sx * dx, center_G.y() + sy * dy, 0.5 * leg_height},
          {leg, leg, leg_height}));
    }
  }
}

}  // namespace

OrientedBox TableGroupLayout::Envelope() const {
  OrientedBox box;
  box.center_W_m = {center_W_m.x(), center_W_m.y(), 0.5 * top_height_m};
  box.size_m = {std::accumulate(column_widths_m.begin(), column_widths_m.end(), 0.0),
                std::accumulate(row_depths_m.begin(), row_depths_m.end(), 0.0), top_height_m};
  box.yaw_rad = yaw_rad;
  return box;
}

std::vector<OrientedBox> MakeTableGroupBoxes(const TableGroupLayout& layout,
                                             const TableGroupOptions& options) {
  const Eigen::Vector3d envelope = layout.Envelope().size_m;
  std::vector<OrientedBox> boxes;
  boxes.reserve(5 * layout.column_widths_m.size() * layout.row_depths_m.size());
  double y = -0.5 * envelope.y();
  for (const double depth : layout.row_depths_m) {
    double x = -0.5 * envelope.x();
    for (const double width : layout.column_widths_m) {
      AppendTable(layout, options, {x + 0.5 * width, y + 0.5 * depth}, width, depth, &boxes);
      x += width;
    }
    y += depth;
  }
  return boxes;
}

}  // namespace topay
