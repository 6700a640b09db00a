#include "sim/scenes/table_group.h"

#include <cmath>

#include <gtest/gtest.h>

#include "core/geometry/box_overlap.h"

namespace topay {
namespace {

TEST(TableGroupTest, TwoByTwoTablesTileTheEnvelope) {
  TableGroupLayout layout;
  layout.center_W_m = {1.0, -2.0};
  layout.yaw_rad = 0.4;
  layout.column_widths_m = {0.8, 1.2};
  layout.row_depths_m = {1.0, 0.9};
  layout.top_height_m = 0.75;
  const TableGroupOptions options;
  const std::vector<OrientedBox> boxes = MakeTableGroupBoxes(layout, options);
  ASSERT_EQ(boxes.size(), 20u);
  const OrientedBox envelope = layout.Envelope();
  EXPECT_NEAR(envelope.size_m.x(), 2.0, 1e-12);
  EXPECT_NEAR(envelope.size_m.y(), 1.9, 1e-12);
  double top_area = 0.0;
  for (std::size_t t = 0; t < 4; ++t) {
    const OrientedBox& top = boxes[5 * t];
    top_area += top.size_m.x() * top.size_m.y();
    EXPECT_NEAR(top.center_W_m.z() + 0.5 * top.size_m.z(), 0.75, 1e-12);
    // Every part lies within the envelope (corners in the envelope's frame).
    for (std::size_t k = 5 * t; k < 5 * t + 5; ++k) {
      const Eigen::Vector3d p_G = envelope.ToBoxFrame(boxes[k].center_W_m);
      const Eigen::Vector3d h = boxes[k].HalfSize();
      EXPECT_LE(std::abs(p_G.x()) + h.x(), 0.5 * envelope.size_m.x() + 1e-12);
      EXPECT_LE(std::abs(p_G.y()) + h.y(), 0.5 * envelope.size_m.y() + 1e-12);
      EXPECT_NEAR(boxes[k].yaw_rad, 0.4, 1e-15);
    }
  }
  // The tops tile the envelope: their areas add up, no two overlap (shrunk by 1 um against
  // rounding: neighbours share an edge) and neighbours touch (grown by 1 um they overlap).
  EXPECT_NEAR(top_area, 2.0 * 1.9, 1e-12);
  int touching = 0;
  for (std::size_t a = 0; a < 4; ++a) {
    for (std::size_t b = a + 1; b < 4; ++b) {
      OrientedBox shrunk = boxes[5 * a];
      shrunk.size_m -= Eigen::Vector3d(1e-6, 1e-6, 0.0);
      EXPECT_FALSE(BoxesOverlap(shrunk, boxes[5 * b]));
      OrientedBox grown = boxes[5 * a];
      grown.size_m += Eigen::Vector3d(1e-6, 1e-6, 0.0);
      touching += BoxesOverlap(grown, boxes[5 * b]);
    }
  }
  EXPECT_EQ(touching, 6);  // in a 2 x 2 grid every pair shares an edge or a corner
}

}  // namespace
}  // namespace topay
