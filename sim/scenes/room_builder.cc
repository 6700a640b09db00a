#include "sim/scenes/room_builder.h"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "sim/scenes/quantize.h"
#include "sim/scenes/table_group.h"

namespace topay {
namespace {

void Require(bool condition, const std::string& option, const std::string& message) {
  if (!condition) throw std::invalid_argument("room generator option " + option + ": " + message);
}

void RequireRange(double min, double max, const std::string& name) {
  Require(std::isfinite(min) && std::isfinite(max) && 0.0 < min && min <= max,
          name + "_min/_max", "need 0 < min <= max, got [" + std::to_string(min) + ", " +
                                  std::to_string(max) + "]");
}

double DrawYaw(Rng& rng) { return rng.Uniform(-std::numbers::pi, std::numbers::pi); }

}  // namespace

RoomBuilder::RoomBuilder(const RoomOptions& room, const KeepOutRegions& keep_out, Rng* rng,
                         GeneratedScene* out)
    : room_(room), keep_out_(keep_out), rng_(*rng), out_(*out) {
  Require(room.wall_thickness_m > 0.0 && room.size_x_m > 2.0 * room.wall_thickness_m &&
              room.size_y_m > 2.0 * room.wall_thickness_m,
          "size/wall_thickness_m", "the room must be larger than its two walls");
  Require(room.wall_height_m > 0.0 && room.map_height_m >= room.wall_height_m,
          "wall_height_m/map_height_m", "need 0 < wall height <= map height");
  Require(room.max_tries_per_object > 0, "max_tries_per_object", "must be positive");
  const Eigen::Vector2d half(0.5 * room.size_x_m, 0.5 * room.size_y_m);
  interior_min_m_ = -half + Eigen::Vector2d::Constant(room.wall_thickness_m);
  interior_max_m_ = half - Eigen::Vector2d::Constant(room.wall_thickness_m);
  out_.scene.bounds_W_m = Eigen::AlignedBox3d(Eigen::Vector3d(-half.x(), -half.y(), 0.0),
                                              Eigen::Vector3d(half.x(), half.y(),
                                                              room.map_height_m));
}

void RoomBuilder::AddWalls() {
  const double t = room_.wall_thickness_m;
  const double h = room_.wall_height_m;
  const double hx = 0.5 * room_.size_x_m;
  const double hy = 0.5 * room_.size_y_m;
  // Walls at x = +-: full length in y; walls at y = +-: between them (no overlap at corners).
  for (const double side : {-1.0, 1.0}) {
    OrientedBox wall;
    wall.center_W_m = {side * (hx - 0.5 * t), 0.0, 0.5 * h};
    wall.size_m = {t, room_.size_y_m, h};
    Append(QuantizeMicro(wall), BoxRole::kWall);
  }
  for (const double side : {-1.0, 1.0}) {
    OrientedBox wall;
    wall.center_W_m = {0.0, side * (hy - 0.5 * t), 0.5 * h};
    wall.size_m = {room_.size_x_m - 2.0 * t, t, h};
    Append(QuantizeMicro(wall), BoxRole::kWall);
  }
}

void RoomBuilder::AddGroundedBoxes(const GroundedBoxOptions& options) {
  Require(options.count >= 0, "grounded.count", "must be >= 0");
  RequireRange(options.footprint_min_m, options.footprint_max_m, "grounded.footprint");
  RequireRange(options.height_min_m, options.height_max_m, "grounded.height");
  for (int i = 0; i < options.count; ++i) {
    OrientedBox box;
    int tries = 0;
    while (true) {
      if (tries++ == room_.max_tries_per_object) ThrowNoRoom("grounded box", i, options.count);
      const Eigen::Vector3d size(rng_.Uniform(options.footprint_min_m, options.footprint_max_m),
                                 rng_.Uniform(options.footprint_min_m, options.footprint_max_m),
                                 rng_.Uniform(options.height_min_m, options.height_max_m));
      const double yaw = DrawYaw(rng_);
      if (TryPlaceBox(size, yaw, 0.5 * size.z(), &box)) break;
    }
    Append(box, BoxRole::kGroundedBox);
  }
}

void RoomBuilder::AddFloatingCubes(const FloatingCubeOptions& options) {
  Require(options.count >= 0, "floating.count", "must be >= 0");
  RequireRange(options.side_min_m, options.side_max_m, "floating.side");
  RequireRange(options.bottom_min_m, options.bottom_max_m, "floating.bottom");
  for (int i = 0; i < options.count; ++i) {
    OrientedBox box;
    int tries = 0;
    while (true) {
      if (tries++ == room_.max_tries_per_object) ThrowNoRoom("floating cube", i, options.count);
      const double side = rng_.Uniform(options.side_min_m, options.side_max_m);
      const double bottom = rng_.Uniform(options.bottom_min_m, options.bottom_max_m);
      const double yaw = DrawYaw(rng_);
      if (TryPlaceBox(Eigen::Vector3d::Constant(side), yaw, bottom + 0.5 * side, &box)) break;
    }
    Append(box, BoxRole::kFloatingCube);
  }
}

void RoomBuilder::AddTableGroups(const TableGroupOptions& options) {
  Require(options.count >= 0, "tables.count", "must be >= 0");
  Require(options.max_rows >= 1 && options.max_columns >= 1, "tables.max_rows/max_columns",
          "must be >= 1");
  RequireRange(options.table_size_min_m, options.table_size_max_m, "tables.table_size");
  RequireRange(options.top_height_min_m, options.top_height_max_m, "tables.top_height");
  Require(options.top_thickness_m > 0.0 && options.top_thickness_m < options.top_height_min_m,
          "tables.top_thickness_m", "must be in (0, top_height_min_m)");
  Require(options.leg_width_m > 0.0 && 2.0 * options.leg_width_m <= options.table_size_min_m,
          "tables.leg_width_m", "must be in (0, table_size_min_m / 2]");
  for (int i = 0; i < options.count; ++i) {
    std::vector<OrientedBox> boxes;
    int tries = 0;
    while (true) {
      if (tries++ == room_.max_tries_per_object) ThrowNoRoom("table group", i, options.count);
      TableGroupLayout layout;
      const auto rows = rng_.UniformInt(1, options.max_rows);
      const auto columns = rng_.UniformInt(1, options.max_columns);
      for (int c = 0; c < columns; ++c) {
        layout.column_widths_m.push_back(
            rng_.Uniform(options.table_size_min_m, options.table_size_max_m));
      }
      for (int r = 0; r < rows; ++r) {
        layout.row_depths_m.push_back(
            rng_.Uniform(options.table_size_min_m, options.table_size_max_m));
      }
      layout.top_height_m = rng_.Uniform(options.top_height_min_m, options.top_height_max_m);
      layout.yaw_rad = DrawYaw(rng_);
      OrientedBox envelope = layout.Envelope();
      if (!TryPlaceBox(envelope.size_m, layout.yaw_rad, envelope.center_W_m.z(), &envelope)) {
        continue;
      }
      layout.center_W_m = envelope.center_W_m.head<2>();
      layout.yaw_rad = envelope.yaw_rad;  // Already on the grid.
      boxes = MakeTableGroupBoxes(layout, options);
      bool all_fit = true;
      for (OrientedBox& box : boxes) {
        box = QuantizeMicro(box);
        all_fit = all_fit && Fits(box);
      }
      if (all_fit) break;
    }
    for (std::size_t b = 0; b < boxes.size(); ++b) {
      Append(boxes[b], b % 5 == 0 ? BoxRole::kTableTop : BoxRole::kTableLeg);
    }
    out_.num_tables += static_cast<int>(boxes.size() / 5);
  }
}

bool RoomBuilder::TryPlaceBox(const Eigen::Vector3d& size_m, double yaw_rad,
                              double center_z_m, OrientedBox* box) {
  // Half extent of the yawed footprint's AABB: |c| hx + |s| hy, |s| hx + |c| hy.
  const double c = std::abs(std::cos(yaw_rad));
  const double s = std::abs(std::sin(yaw_rad));
  const Eigen::Vector2d extent(0.5 * (c * size_m.x() + s * size_m.y()),
                               0.5 * (s * size_m.x() + c * size_m.y()));
  const Eigen::Vector2d low = interior_min_m_ + extent;
  const Eigen::Vector2d high = interior_max_m_ - extent;
  // Draw the centre even when the box cannot fit, so every try uses the same number of draws.
  const double u = rng_.Uniform01();
  const double v = rng_.Uniform01();
  if (low.x() > high.x() || low.y() > high.y()) return false;
  box->center_W_m = {low.x() + u * (high.x() - low.x()), low.y() + v * (high.y() - low.y()),
                     center_z_m};
  box->size_m = size_m;
  box->yaw_rad = yaw_rad;
  *box = QuantizeMicro(*box);
  return Fits(*box);
}

bool RoomBuilder::Fits(const OrientedBox& box) const {
  const Eigen::AlignedBox3d bounds = box.WorldBounds();
  const bool inside = (bounds.min().head<2>().array() >= interior_min_m_.array()).all() &&
                      (bounds.max().head<2>().array() <= interior_max_m_.array()).all() &&
                      bounds.min().z() >= 0.0;
  return inside && keep_out_.Admits(box);
}

void RoomBuilder::Append(const OrientedBox& box, BoxRole role) {
  out_.scene.boxes.push_back(box);
  out_.roles.push_back(role);
}

void RoomBuilder::ThrowNoRoom(const std::string& what, int index, int count) const {
  throw std::runtime_error("room generator: could not place " + what + " " +
                           std::to_string(index + 1) + " of " + std::to_string(count) + " in " +
                           std::to_string(room_.max_tries_per_object) +
                           " tries: the room or the keep-out regions leave too little space");
}

}  // namespace topay
