#pragma once

// Hand-built scenes and checks shared by the tests of the topological base-path
// search.

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "core/common/random.h"
#include "core/geometry/primitive_box_distance.h"
#include "core/geometry/scene.h"
#include "core/map/scene_distance_fields.h"
#include "tests/common/make_box.h"

namespace topay::topo_test {

constexpr double kBaseRadius = 0.40;
constexpr double kRequired = 0.50;  // base radius + 0.1 m clearance
constexpr double kChassisTop = 0.155;

/// A 16 x 12 m room (no walls: the map edge bounds it) with the given boxes.
inline Scene Room(std::vector<OrientedBox> boxes) {
  Scene scene;
  scene.bounds_W_m = Eigen::AlignedBox3d(Eigen::Vector3d(-8, -6, 0), Eigen::Vector3d(8, 6, 1.6));
  scene.boxes = std::move(boxes);
  scene.kind = "topo test";
  return scene;
}

/// A 1 m tall square pillar of side `side` centred at (x, y).
inline OrientedBox Pillar(double x, double y, double side = 1.0) {
  return MakeBox(Eigen::Vector3d(x, y, 0.5), Eigen::Vector3d(side, side, 1.0));
}

/// A wall across the room at x = 0 (0.2 m thick) with one gap of `gap` metres
/// centred at y.
inline std::vector<OrientedBox> WallWithGap(double gap_center_y, double gap) {
  const double lo = gap_center_y - 0.5 * gap, hi = gap_center_y + 0.5 * gap;
  const double bottom = -7.0, top = 7.0;  // past the map edge
  return {
      MakeBox(Eigen::Vector3d(0, 0.5 * (bottom + lo), 0.5), Eigen::Vector3d(0.2, lo - bottom, 1)),
      MakeBox(Eigen::Vector3d(0, 0.5 * (hi + top), 0.5), Eigen::Vector3d(0.2, top - hi, 1))};
}

/// `count` 1 m tall boxes at random positions, sizes (0.2-3 m) and yaws in the room.
inline std::vector<OrientedBox> RandomBoxes(Rng& rng, int count) {
  std::vector<OrientedBox> boxes;
  for (int k = 0; k < count; ++k) {
    boxes.push_back(MakeBox(Eigen::Vector3d(rng.Uniform(-7, 7), rng.Uniform(-5, 5), 0.5),
                            Eigen::Vector3d(rng.Uniform(0.2, 3.0), rng.Uniform(0.2, 3.0), 1.0),
                            rng.Uniform(0, 3.14)));
  }
  return boxes;
}

inline SignedDistanceField2 BaseField(const Scene& scene) {
  return BuildSceneDistanceFields(scene).base_field_2d;
}

/// Checks every segment densely (1 cm) against the field (>= base radius +
/// clearance) and against the exact boxes (base cylinder clear of every box
/// that reaches the chassis band).
inline void ExpectPathCollisionFree(const Scene& scene, const SignedDistanceField2& field,
                                    const std::vector<Eigen::Vector2d>& path) {
  ASSERT_GE(path.size(), 2u);
  for (std::size_t i = 1; i < path.size(); ++i) {
    const Eigen::Vector2d a = path[i - 1], b = path[i];
    const int steps = std::max(1, static_cast<int>(std::ceil((b - a).norm() / 0.01)));
    for (int k = 0; k <= steps; ++k) {
      const Eigen::Vector2d p = a + (b - a) * (double(k) / steps);
      // 1e-9: rounding of the interpolation at points computed from the
      // segment's ends.
      ASSERT_GE(field.Distance(p), kRequired - 1e-9) << "segment " << i << " at " << p.transpose();
      VerticalCylinder base;
      base.axis_W_m = p;
      base.radius_m = kBaseRadius;
      base.height_m = kChassisTop;
      for (std::size_t j = 0; j < scene.boxes.size(); ++j) {
        ASSERT_GE(SignedDistanceCylinderToBox(scene.boxes[j], base), 0.0)
            << "segment " << i << " at " << p.transpose() << " hits box " << j;
      }
    }
  }
}

/// The y at which a path first crosses x = x0 (NaN if it does not).
inline double CrossingY(const std::vector<Eigen::Vector2d>& path, double x0) {
  for (std::size_t i = 1; i < path.size(); ++i) {
    const Eigen::Vector2d a = path[i - 1], b = path[i];
    if ((a.x() - x0) * (b.x() - x0) <= 0.0 && a.x() != b.x()) {
      const double t = (x0 - a.x()) / (b.x() - a.x());
      return a.y() + t * (b.y() - a.y());
    }
  }
  return std::numeric_limits<double>::quiet_NaN();
}

}  // namespace topay::topo_test
