#include "core/map/cell_box.h"

#include <vector>

#include <gtest/gtest.h>

namespace topay {
namespace {

TEST(CellBoxTest, SizesDilationUnionAndContainment) {
  const CellBox box{{2, 3, 0}, {5, 4, 2}};
  EXPECT_FALSE(box.empty());
  EXPECT_EQ(box.NumCells(), 3 * 1 * 2);
  const CellBox grown = box.Dilated({3, 1, 1}, {6, 10, 2});
  EXPECT_EQ(grown.begin, Eigen::Vector3i(0, 2, 0));
  EXPECT_EQ(grown.end, Eigen::Vector3i(6, 5, 2));
  EXPECT_TRUE(box.Contains({4, 3, 1}));
  EXPECT_FALSE(box.Contains({5, 3, 1}));
  const CellBox both = box.Union({{0, 0, 1}, {1, 1, 3}});
  EXPECT_EQ(both.begin, Eigen::Vector3i(0, 0, 0));
  EXPECT_EQ(both.end, Eigen::Vector3i(5, 4, 3));
  EXPECT_TRUE((CellBox{{1, 1, 1}, {1, 2, 2}}).empty());
  EXPECT_EQ((CellBox{{1, 1, 1}, {1, 2, 2}}).NumCells(), 0);
}

TEST(CellBoxTest, TileBoundsGroupCellsByTile) {
  const std::vector<Eigen::Vector3i> cells = {
      {0, 0, 0}, {3, 2, 0}, {9, 1, 0}, {12, 7, 0}, {1, 1, 0}};
  const std::vector<CellBox> boxes = TileBoundsOfCells(cells, {8, 8, 1});
  ASSERT_EQ(boxes.size(), 2u);
  EXPECT_EQ(boxes[0].begin, Eigen::Vector3i(0, 0, 0));
  EXPECT_EQ(boxes[0].end, Eigen::Vector3i(4, 3, 1));
  EXPECT_EQ(boxes[1].begin, Eigen::Vector3i(9, 1, 0));
  EXPECT_EQ(boxes[1].end, Eigen::Vector3i(13, 8, 1));
}

TEST(CellBoxTest, MergeJoinsBoxesOnlyWhenThatSavesWorkAndCoversEveryCell) {
  const Eigen::Vector3i dims(200, 200, 1);
  // Two neighbours (their sources overlap almost wholly) merge; a far box stays apart.
  std::vector<CellBox> boxes = {
      {{10, 10, 0}, {12, 12, 1}}, {{12, 10, 0}, {14, 12, 1}}, {{150, 150, 0}, {152, 152, 1}}};
  const std::vector<CellBox> merged = MergeCellBoxes(boxes, {10, 10, 0}, dims);
  ASSERT_EQ(merged.size(), 2u);
  for (const CellBox& box : boxes) {
    for (const Eigen::Vector3i& corner :
         {box.begin, Eigen::Vector3i(box.end - Eigen::Vector3i::Ones())}) {
      bool covered = false;
      for (const CellBox& m : merged) covered = covered || m.Contains(corner);
      EXPECT_TRUE(covered);
    }
  }
  // Above max_boxes: one union.
  const std::vector<CellBox> one = MergeCellBoxes(boxes, {10, 10, 0}, dims, 2);
  ASSERT_EQ(one.size(), 1u);
  EXPECT_EQ(one[0].begin, Eigen::Vector3i(10, 10, 0));
  EXPECT_EQ(one[0].end, Eigen::Vector3i(152, 152, 1));
  EXPECT_TRUE(MergeCellBoxes({}, {1, 1, 1}, dims).empty());
  // Four corner windows each reading 0.36 of the grid (reach 80 in 200 x 200): together they
  // read more than the grid, so they end as the whole grid, recomputed once.
  const std::vector<CellBox> corners = {{{0, 0, 0}, {40, 40, 1}},
                                        {{160, 0, 0}, {200, 40, 1}},
                                        {{0, 160, 0}, {40, 200, 1}},
                                        {{160, 160, 0}, {200, 200, 1}}};
  const std::vector<CellBox> whole = MergeCellBoxes(corners, {80, 80, 0}, dims);
  ASSERT_EQ(whole.size(), 1u);
  EXPECT_EQ(whole[0].begin, Eigen::Vector3i(0, 0, 0));
  EXPECT_EQ(whole[0].end, dims);
}

}  // namespace
}  // namespace topay
