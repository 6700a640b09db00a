// WriteReport on the crafted run: summary.json (the numbers), path.png (size from its view;
// the driven path, a contact, the map's occupied column and the appeared box where they
// belong) and time_plots.png (size from its panels; planned and measured curves drawn).

#include "tools/report/report_tool.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>

#include <nlohmann/json.hpp>

#include "tests/tools/report/crafted_run_log.h"
#include "tools/report/path_plot_view.h"
#include "tools/report/run_time_plots.h"
#include "tools/viz/color_map.h"
#include "tools/viz/png_io.h"

namespace topay::report {
namespace {

class ReportFilesTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = test::FreshTestDir("files");
    test::WriteCraftedRunLog(dir_ + "/run/graph.lcmlog");
    ReportOptions options;
    options.log_path = dir_ + "/run/graph.lcmlog";
    options.json_path = dir_ + "/copy.json";
    summary_ = WriteReport(options);
    log_ = ReadRunLog(options.log_path);
  }
  std::string dir_;
  RunSummary summary_;
  RunLog log_;
};

int DistinctColours(const viz::Image& image) {
  std::set<int> colours;
  for (int y = 0; y < image.height(); y += 2) {
    for (int x = 0; x < image.width(); x += 2) {
      const viz::Rgb c = image.At(x, y);
      colours.insert((c.r << 16) | (c.g << 8) | c.b);
    }
  }
  return static_cast<int>(colours.size());
}

viz::Rgb PixelAt(const viz::Image& image, const viz::ViewTransform& view, const Eigen::Vector2d& p_W) {
  const Eigen::Vector2d px = view.ToPixel(p_W);
  return image.At(static_cast<int>(px.x()), static_cast<int>(px.y()));
}

TEST_F(ReportFilesTest, FilesGoBesideTheLogByDefault) {
  EXPECT_EQ(summary_.files.summary_json, dir_ + "/run/summary.json");
  EXPECT_EQ(summary_.files.path_png, dir_ + "/run/path.png");
  EXPECT_EQ(summary_.files.time_plots_png, dir_ + "/run/time_plots.png");
  for (const std::string& f : {summary_.files.summary_json, summary_.files.path_png, summary_.files.time_plots_png,
                               dir_ + "/copy.json"}) {
    EXPECT_TRUE(std::filesystem::is_regular_file(f)) << f;
  }
}

TEST_F(ReportFilesTest, SummaryJsonHoldsTheNumbers) {
  std::ifstream file(summary_.files.summary_json);
  const nlohmann::json j = nlohmann::json::parse(file);
  EXPECT_EQ(j["success"], true);
  EXPECT_EQ(j["mission"]["result"], "SUCCEEDED");
  EXPECT_EQ(j["mission"]["elapsed_s"], 9.0);
  EXPECT_EQ(j["mission"]["steps"].size(), 3u);
  EXPECT_EQ(j["mission"]["steps"][0]["attempts"], 2);
  EXPECT_EQ(j["planner"]["replans"], 3);
  EXPECT_EQ(j["planner"]["trajectory_messages"], 3);
  EXPECT_EQ(j["planner"]["stopping"], 1);
  EXPECT_NEAR(j["planner"]["planning_total_ms"]["p95"].get<double>(), 290.0, 1e-12);
  EXPECT_EQ(j["planner"]["failure_reasons"]["target unreachable"], 1);
  EXPECT_EQ(j["collisions"]["contact_events"], 2);
  EXPECT_EQ(j["collisions"]["contact_messages"], 2);
  EXPECT_NEAR(j["tracking"]["position_m"]["rms"].get<double>(), 0.025, 1e-15);
  EXPECT_NEAR(j["tracking"]["solve_ms"]["p99"].get<double>(), 3.97, 1e-12);
  EXPECT_NEAR(j["distance_driven_m"].get<double>(), 7.0, 1e-12);
  EXPECT_EQ(j["appeared_boxes"][0]["center_m"][1], 2.5);
  EXPECT_EQ(j["channels"]["ROBOT_STATE"]["decode_failures"], 1);
  EXPECT_EQ(j["decode_failures"], 3);
  EXPECT_EQ(j["files"]["path_png"], summary_.files.path_png);
  std::ifstream copy(dir_ + "/copy.json");
  EXPECT_EQ(nlohmann::json::parse(copy), j);
}

TEST_F(ReportFilesTest, PathPlotHasItsSizeAndShowsTheRun) {
  const viz::Image image = viz::ReadPng(summary_.files.path_png);
  const viz::ViewTransform view = PathPlotView(log_, nullptr, {});
  EXPECT_EQ(image.width(), PathPlotWidth(view, {}));
  EXPECT_GT(image.height(), view.offset_px().y() + view.height_px());  // axes and legend below
  EXPECT_GT(DistinctColours(image), 20);
  // Region: the map's x -1..3, y -1..3 and the driven path to (3, 4), plus 0.5 m.
  EXPECT_DOUBLE_EQ(view.region_W_m().min().x(), -1.5);
  EXPECT_DOUBLE_EQ(view.region_W_m().max().y(), 4.5);
  const viz::Rgb driven = PixelAt(image, view, {1.5, 0.0});
  EXPECT_LT(driven.r + driven.g + driven.b, 3 * 60) << "driven path";
  EXPECT_EQ(PixelAt(image, view, {0.6, 0.0}), (viz::Rgb{220, 0, 0})) << "contact at ROBOT_STATE 2";
  EXPECT_EQ(PixelAt(image, view, {-0.85, 1.55}), viz::GreyRamp(0.8)) << "occupied column, top 0.8 m of 1 m";
  EXPECT_EQ(PixelAt(image, view, {-0.5, -0.5}), viz::colors::kWhite) << "free map";
  const viz::Rgb box = PixelAt(image, view, {1.5, 2.5});
  EXPECT_GT(box.r, box.b + 60) << "appeared box (orange)";
}

TEST_F(ReportFilesTest, TimePlotsHaveTheirSizeAndCurves) {
  const viz::Image image = viz::ReadPng(summary_.files.time_plots_png);
  const RunTimePlotOptions options;
  EXPECT_EQ(image.width(), options.width_px);
  EXPECT_EQ(image.height(), RunTimePlotPanels(test::kJoints, options).back().y1 + 4);
  int planned = 0, measured = 0;  // pixels of each series' colour
  for (int y = 0; y < image.height(); ++y) {
    for (int x = 0; x < image.width(); ++x) {
      const viz::Rgb c = image.At(x, y);
      planned += c == viz::Rgb{0, 90, 181};
      measured += c == viz::Rgb{230, 120, 0};
    }
  }
  EXPECT_GT(planned, 500);
  EXPECT_GT(measured, 500);
}

TEST(ReportFiles, AnEmptyLogStillGivesEveryFile) {
  const std::string dir = test::FreshTestDir("files");
  { test::CraftedLogWriter log(dir + "/graph.lcmlog"); }
  ReportOptions options;
  options.log_path = dir + "/graph.lcmlog";
  const RunSummary summary = WriteReport(options);
  EXPECT_FALSE(summary.succeeded());
  const viz::Image time_plots = viz::ReadPng(summary.files.time_plots_png);
  EXPECT_EQ(time_plots.height(), RunTimePlotPanels(-1, {}).back().y1 + 4);  // one panel: "no motion"
  const viz::Image path = viz::ReadPng(summary.files.path_png);
  const viz::ViewTransform view = PathPlotView(ReadRunLog(options.log_path), nullptr, {});
  EXPECT_DOUBLE_EQ(view.region_W_m().sizes().x(), 3.0);  // 2 x 2 m at the origin, 0.5 m margin
  EXPECT_EQ(path.width(), PathPlotWidth(view, {}));
}

TEST(ReportFiles, ASceneAddsItsOutlinesAndABadSceneIsAnErrorNamingIt) {
  const std::string dir = test::FreshTestDir("files");
  test::WriteCraftedRunLog(dir + "/graph.lcmlog");
  std::ofstream(dir + "/room.json")
      << R"({"bounds": {"min": [-2, -2, 0], "max": [5, 5, 1.6]},)"
      << R"( "boxes": [{"center": [4, 0, 0.5], "size": [1, 1, 1], "yaw": 0}]})";
  ReportOptions options;
  options.log_path = dir + "/graph.lcmlog";
  options.scene_path = dir + "/room.json";
  options.out_dir = dir + "/out";
  const RunSummary summary = WriteReport(options);
  EXPECT_EQ(summary.files.path_png, dir + "/out/path.png");
  const viz::Image image = viz::ReadPng(summary.files.path_png);
  Scene scene;
  scene.bounds_W_m = Eigen::AlignedBox3d(Eigen::Vector3d(-2, -2, 0), Eigen::Vector3d(5, 5, 1.6));
  const viz::ViewTransform view = PathPlotView(ReadRunLog(options.log_path), &scene, {});
  EXPECT_DOUBLE_EQ(view.region_W_m().min().x(), -2.5);  // the scene's bounds
  EXPECT_EQ(image.width(), PathPlotWidth(view, {}));
  const viz::Rgb edge = PixelAt(image, view, {3.5, 0.0});  // the box's left edge, outlined
  EXPECT_LT(edge.r, 200) << "outline";
  EXPECT_EQ(PixelAt(image, view, {4.0, 0.0}), viz::colors::kWhite) << "outline only, not filled";

  options.scene_path = dir + "/missing.json";
  try {
    WriteReport(options);
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("missing.json"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace topay::report
