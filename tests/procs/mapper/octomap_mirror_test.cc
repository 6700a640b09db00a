#include "procs/mapper/octomap_mirror.h"

#include <filesystem>
#include <fstream>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace topay::mapper {
namespace {

namespace fs = std::filesystem;

// A wall of points x = 2 m, |y| <= 1, z 0.3 .. 1.3 m, seen from (0, 0, 0.5).
std::vector<Eigen::Vector3f> Wall() {
  std::vector<Eigen::Vector3f> points;
  for (int i = 0; i <= 40; ++i) {
    for (int j = 0; j <= 20; ++j) points.emplace_back(2.02f, -1.0f + 0.05f * i, 0.3f + 0.05f * j);
  }
  return points;
}

const Eigen::Vector3d kOrigin(0.01, 0.01, 0.51);

// The node's state at p: -1 unknown, 0 free, 1 occupied.
int StateAt(const octomap::OcTree& tree, float x, float y, float z) {
  const octomap::OcTreeNode* node = tree.search(x, y, z);
  return node == nullptr ? -1 : (tree.isNodeOccupied(node) ? 1 : 0);
}

std::string TempPath(const std::string& name) {
  return (fs::temp_directory_path() / ("topay_mapper_" + name)).string();
}

std::string MessageOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

TEST(OctomapMirrorTest, AScanMarksItsReturnsOccupiedAndTheRaysFree) {
  OctomapMirror mirror;
  const OctomapInsertSummary s = mirror.Insert(kOrigin, Wall());
  EXPECT_EQ(s.num_points, 41 * 21);
  EXPECT_EQ(s.num_returns, 41 * 21);
  EXPECT_GT(s.num_free_voxels, 1000);
  const octomap::OcTree& tree = mirror.tree();
  EXPECT_DOUBLE_EQ(tree.getResolution(), 0.05);
  EXPECT_NEAR(tree.getProbHit(), 0.7, 1e-6);
  EXPECT_NEAR(tree.getOccupancyThres(), 0.5, 1e-6);
  // One hit at 0.7 is above the 0.5 threshold; one miss at 0.4 is below.
  EXPECT_EQ(StateAt(tree, 2.02f, 0.0f, 0.8f), 1);
  EXPECT_EQ(StateAt(tree, 1.0f, 0.005f, 0.505f), 0);  // on the ray to (2.02, 0, 0.5)
  EXPECT_EQ(StateAt(tree, 3.0f, 0.0f, 0.8f), -1);  // behind the wall
}

TEST(OctomapMirrorTest, InsideTheBoundsItMatchesInsertPointCloud) {
  OctomapMirror mirror;
  const std::vector<Eigen::Vector3f> wall = Wall();
  mirror.Insert(kOrigin, wall);
  octomap::OcTree reference(0.05);
  octomap::Pointcloud cloud;
  for (const Eigen::Vector3f& p : wall) cloud.push_back(p.x(), p.y(), p.z());
  reference.insertPointCloud(cloud, octomap::point3d(kOrigin.x(), kOrigin.y(), kOrigin.z()));
  int leaves = 0;
  for (auto it = reference.begin_leafs(); it != reference.end_leafs(); ++it, ++leaves) {
    const octomap::OcTreeNode* node = mirror.tree().search(it.getKey());
    ASSERT_NE(node, nullptr);
    EXPECT_FLOAT_EQ(node->getLogOdds(), it->getLogOdds());
  }
  EXPECT_EQ(leaves, static_cast<int>(mirror.tree().getNumLeafNodes()));
}

TEST(OctomapMirrorTest, ReturnsOutsideTheBoundsClearTheirRaysInsideOnly) {
  OctomapMirrorOptions options;
  options.bounds_W_m = Eigen::AlignedBox3d(Eigen::Vector3d(-2, -2, 0), Eigen::Vector3d(2, 2, 1));
  OctomapMirror mirror(options);
  // A return high above the box (z = 3) and one beyond its x side.
  const std::vector<Eigen::Vector3f> outside = {{1.0f, 0.0f, 3.0f}, {5.0f, 0.0f, 0.5f}};
  const OctomapInsertSummary s = mirror.Insert(kOrigin, outside);
  EXPECT_EQ(s.num_returns, 0);
  EXPECT_GT(s.num_free_voxels, 40);
  const octomap::OcTree& tree = mirror.tree();
  EXPECT_EQ(StateAt(tree, 1.5f, 0.0f, 0.51f), 0);  // on the ray to (5, 0, 0.5), inside
  EXPECT_EQ(StateAt(tree, 0.18f, 0.01f, 0.96f), 0);  // on the ray upwards, inside
  for (auto it = tree.begin_leafs(); it != tree.end_leafs(); ++it) {
    const octomap::point3d c = it.getCoordinate();
    EXPECT_TRUE(c.x() > -2 && c.x() < 2 && c.z() > 0 && c.z() < 1) << c;
  }
}

TEST(OctomapMirrorTest, ReturnsBeyondMaxRangeClearUpToIt) {
  OctomapMirrorOptions options;
  options.max_range_m = 1.0;
  OctomapMirror mirror(options);
  const OctomapInsertSummary s =
      mirror.Insert(kOrigin, std::vector<Eigen::Vector3f>{{3.0f, 0.01f, 0.51f}});
  EXPECT_EQ(s.num_returns, 0);
  EXPECT_EQ(StateAt(mirror.tree(), 0.9f, 0.01f, 0.51f), 0);
  EXPECT_EQ(StateAt(mirror.tree(), 1.2f, 0.01f, 0.51f), -1);
  EXPECT_EQ(StateAt(mirror.tree(), 3.0f, 0.01f, 0.51f), -1);
}

TEST(OctomapMirrorTest, SaveAndLoadPriorRoundTrip) {
  OctomapMirror mirror;
  mirror.Insert(kOrigin, Wall());
  const std::string path = TempPath("round_trip.bt");
  mirror.Save(path);
  const OctomapMirror loaded = OctomapMirror::LoadPrior(path);
  EXPECT_NEAR(loaded.tree().getProbMiss(), 0.4, 1e-6);  // the options' model
  int leaves = 0;
  for (auto it = mirror.tree().begin_leafs(); it != mirror.tree().end_leafs(); ++it, ++leaves) {
    const octomap::OcTreeNode* node = loaded.tree().search(it.getKey());
    ASSERT_NE(node, nullptr);
    EXPECT_EQ(loaded.tree().isNodeOccupied(node), mirror.tree().isNodeOccupied(*it));
  }
  EXPECT_GT(leaves, 1000);
  fs::remove(path);
}

TEST(OctomapMirrorTest, MissingGarbageOrMismatchedFilesErrorNamingThePath) {
  const std::string missing = TempPath("no_such_map.bt");
  EXPECT_EQ(MessageOf([&] { OctomapMirror::LoadPrior(missing); }),
            "OctoMap file " + missing + ": not found (or not a regular file)");
  const std::string garbage = TempPath("garbage.bt");
  std::ofstream(garbage) << "this is not an octree\n\x01\x02\x03";
  EXPECT_EQ(MessageOf([&] { OctomapMirror::LoadPrior(garbage); }),
            "OctoMap file " + garbage +
                ": not a readable OcTree binary file (.bt, OcTree::writeBinary)");
  fs::remove(garbage);
  const std::string coarse = TempPath("coarse.bt");
  OctomapMirrorOptions options;
  options.resolution_m = 0.1;
  OctomapMirror(options).Save(coarse);
  EXPECT_NE(MessageOf([&] { OctomapMirror::LoadPrior(coarse); }).find(coarse + ": resolution 0.1"),
            std::string::npos);
  fs::remove(coarse);
  const std::string unwritable = "/nonexistent_dir_topay/map.bt";
  EXPECT_EQ(MessageOf([&] { OctomapMirror().Save(unwritable); }),
            "OctoMap file " + unwritable + ": cannot be opened for writing");
}

TEST(OctomapMirrorTest, BadOptionsAreRejected) {
  OctomapMirrorOptions options;
  options.prob_hit = 0.4;
  EXPECT_THROW(OctomapMirror{options}, std::invalid_argument);
  options = {};
  options.clamping_max = 0.4;
  EXPECT_THROW(OctomapMirror{options}, std::invalid_argument);
  options = {};
  options.resolution_m = 0.0;
  EXPECT_THROW(OctomapMirror{options}, std::invalid_argument);
}

}  // namespace
}  // namespace topay::mapper
