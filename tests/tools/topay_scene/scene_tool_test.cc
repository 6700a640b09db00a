#include "tools/topay_scene/scene_tool.h"

#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <string>

#include <unistd.h>

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include "sim/scenes/scene_json.h"
#include "tools/viz/box_drawing.h"
#include "tools/viz/png_io.h"
#include "tools/viz/scene_renderer.h"

namespace topay::scene_tool {
namespace {

namespace fs = std::filesystem;

class SceneToolTest : public ::testing::Test {
 protected:
  void TearDown() override { fs::remove_all(dir_); }
  SceneToolOptions Options() const {
    SceneToolOptions o;
    o.scene_kind = "cuboids";
    o.seed = 3;
    o.range = "small";
    o.px_per_m = 10.0;
    o.robot_urdf = TOPAY_SOURCE_DIR "/config/robot/topay_mm.urdf";
    o.robot_yaml = TOPAY_SOURCE_DIR "/config/robot/topay_mm.yaml";
    fs::create_directories(dir_);
    return o;
  }
  fs::path dir_ = fs::temp_directory_path() / ("scene_tool_test_" + std::to_string(::getpid()));
};

TEST_F(SceneToolTest, DrawsTheSceneWithItsGroundedBoxesInTheirGrey) {
  SceneToolOptions o = Options();
  o.range.clear();  // No task: nothing is drawn over the boxes.
  o.png_out = (dir_ / "scene.png").string();
  o.scene_json_out = (dir_ / "scene.json").string();
  const SceneToolSummary summary = RunSceneTool(o);
  const viz::Image png = viz::ReadPng(o.png_out);
  EXPECT_EQ(png.width(), summary.png_width_px);
  EXPECT_EQ(png.height(), summary.png_height_px);
  EXPECT_EQ(png.width(), viz::SceneImageWidth(205));  // 20.5 m at 10 px/m beside the y axis.
  EXPECT_NE(summary.Paragraph(o).find("scene.png"), std::string::npos);

  // The centre of a grounded box that no other box's footprint (grown by 0.1 m) covers shows
  // its top-height grey.
  const Scene scene = ReadSceneJson(o.scene_json_out);
  viz::SceneRenderOptions render;
  render.px_per_m = o.px_per_m;
  const viz::ViewTransform view = viz::SceneMapView(scene, render);
  const viz::ScalarRange heights{scene.bounds_W_m.min().z(), scene.bounds_W_m.max().z()};
  int checked = 0;
  for (const OrientedBox& box : scene.boxes) {
    if (viz::IsRaised(box, {}) || box.size_m.head<2>().minCoeff() < 0.6) continue;  // >= 6 px: inside the outline.
    bool alone = true;
    for (const OrientedBox& other : scene.boxes) {
      if (&other == &box) continue;
      const Eigen::Vector2d d = Eigen::Rotation2Dd(-other.yaw_rad) *
                                (box.center_W_m - other.center_W_m).head<2>();
      alone = alone && (std::abs(d.x()) > 0.5 * other.size_m.x() + 0.1 ||
                        std::abs(d.y()) > 0.5 * other.size_m.y() + 0.1);
    }
    if (!alone) continue;
    const Eigen::Vector2d p = view.ToPixel(box.center_W_m.head<2>());
    const double top = box.center_W_m.z() + 0.5 * box.size_m.z();
    EXPECT_EQ(png.At(static_cast<int>(p.x()), static_cast<int>(p.y())),
              viz::GreyRamp(heights.Normalize(top)))
        << "box at " << box.center_W_m.transpose() << " size " << box.size_m.transpose() << " yaw " << box.yaw_rad;
    ++checked;
  }
  EXPECT_GT(checked, 0);
}

TEST_F(SceneToolTest, ImpossibleOptionsNameTheOption) {
  SceneToolOptions o = Options();
  o.px_per_m = 0.5;
  try {
    RunSceneTool(o);
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("--px-per-m"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace topay::scene_tool
