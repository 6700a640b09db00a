#include "tools/topay_bench_plot/bench_plot.h"

#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include <gtest/gtest.h>

#include "tools/viz/color_map.h"
#include "tools/viz/png_io.h"

namespace topay::bench_plot {
namespace {

namespace fs = std::filesystem;

// Two methods on two cells: topay succeeds 80 % on cuboids, flatness 40 %; tables by topay only.
std::vector<SummaryEntry> Summaries() {
  return {{"topay", "cuboids", "small", 10, 0.8},
          {"flatness", "cuboids", "small", 10, 0.4},
          {"topay", "tables", "medium", 10, 0.5}};
}

std::vector<TaskLine> Lines() {
  std::vector<TaskLine> lines;
  for (int i = 0; i < 10; ++i) {
    lines.push_back({"cuboids", "small", "topay", true, 100.0 + 10.0 * i, 5.0 + i, 2.0 + i});
    lines.push_back({"cuboids", "small", "flatness", i % 2 == 0, 900.0 + 50.0 * i, 20.0, 2.0 + i});
  }
  lines.push_back({"cuboids", "small", "flatness", false, 3000.0, std::nullopt, 4.0});
  return lines;
}

bool Near(const viz::Rgb& a, const viz::Rgb& b) {
  return std::abs(a.r - b.r) + std::abs(a.g - b.g) + std::abs(a.b - b.b) < 12;
}

// How many pixels of the image have (about) this colour.
int CountColour(const viz::Image& image, const viz::Rgb& colour) {
  int count = 0;
  for (int y = 0; y < image.height(); ++y) {
    for (int x = 0; x < image.width(); ++x) count += Near(image.At(x, y), colour);
  }
  return count;
}

// The height (rows) of the tallest run of `colour` in any column.
int TallestRun(const viz::Image& image, const viz::Rgb& colour) {
  int best = 0;
  for (int x = 0; x < image.width(); ++x) {
    int run = 0;
    for (int y = 0; y < image.height(); ++y) {
      run = image.At(x, y) == colour ? run + 1 : 0;
      best = std::max(best, run);
    }
  }
  return best;
}

TEST(BenchPlotTest, BarsAreAsTallAsTheSuccessRates) {
  const viz::Image image = RenderSuccessRate(Summaries());
  const int topay = TallestRun(image, viz::CategoryColour(0));
  const int flatness = TallestRun(image, viz::CategoryColour(1));
  ASSERT_GT(flatness, 20);
  // 80 % against 40 %: twice as tall, to a pixel or two of rounding.
  EXPECT_NEAR(static_cast<double>(topay) / flatness, 2.0, 0.05);
}

TEST(BenchPlotTest, BoxStatisticsAreTheQuartilesAndTheWhiskersStopAtOnePointFiveIqr) {
  const BoxStats stats = ComputeBoxStats({5, 1, 3, 2, 4, 100});
  EXPECT_DOUBLE_EQ(stats.median, 3.5);
  EXPECT_DOUBLE_EQ(stats.q1, 2.25);
  EXPECT_DOUBLE_EQ(stats.q3, 4.75);
  EXPECT_DOUBLE_EQ(stats.whisker_low, 1.0);
  EXPECT_DOUBLE_EQ(stats.whisker_high, 5.0);
  ASSERT_EQ(stats.outliers.size(), 1u);
  EXPECT_DOUBLE_EQ(stats.outliers[0], 100.0);
}

TEST(BenchPlotTest, PlanningTimeHasOnePanelPerCellAndABoxPerMethod) {
  const viz::Image image = RenderPlanningTime(Lines());
  EXPECT_EQ(image.width(), 420);  // One cell in the task lines.
  // Both methods' boxes are drawn in their colours (outlines and light fills).
  for (int m : {0, 1}) {
    EXPECT_GT(CountColour(image, viz::CategoryColour(m)), 50) << m;
    EXPECT_GT(CountColour(image, viz::Lerp(viz::CategoryColour(m), viz::colors::kWhite, 0.6)),
              50)
        << m;
  }
}

TEST(BenchPlotTest, DurationScatterHasADotPerSuccess) {
  const viz::Image image = RenderDurationVsDistance(Lines());
  EXPECT_EQ(image.width(), 640);
  const int topay = CountColour(image, viz::CategoryColour(0));
  const int flatness = CountColour(image, viz::CategoryColour(1));
  // 10 topay dots against 5 flatness dots (plus one legend dot each; a dot of radius 3.5 px
  // covers about 30 pixels in full), not overlapping.
  EXPECT_GT(flatness, 5 * 20);
  EXPECT_GT(topay, flatness * 3 / 2);
}

class BenchPlotFilesTest : public ::testing::Test {
 protected:
  void TearDown() override { fs::remove_all(dir_); }
  std::string Write(const std::string& name, const std::string& text) {
    fs::create_directories((dir_ / name).parent_path());
    std::ofstream(dir_ / name) << text;
    return (dir_ / name).string();
  }
  std::string ErrorOf(const std::vector<std::string>& runs) {
    try {
      ReadBenchRuns(runs);
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  }
  fs::path dir_ = fs::temp_directory_path() / ("bench_plot_test_" + std::to_string(::getpid()));
};

TEST_F(BenchPlotFilesTest, ReadsRunsAndWritesThreeDecodablePngs) {
  Write("run/summary.json",
        R"([{"method": "topay", "scene": "cuboids", "range": "small", "tasks": 2,
             "success_rate": 0.5, "other": 1}])");
  Write("run/tasks.jsonl",
        R"({"task": 0, "scene": "cuboids", "range": "small", "method": "topay", "success": true,)"
        R"( "timings_ms": {"total": 120.5}, "duration_s": 7.5, "base_distance_m": 3.0})"
        "\n\n"
        R"({"task": 1, "scene": "cuboids", "range": "small", "method": "topay", "success": false,)"
        R"( "timings_ms": {"total": 3000}, "duration_s": null, "base_distance_m": 4.0})"
        "\n");
  const BenchRuns runs = ReadBenchRuns({(dir_ / "run").string()});
  ASSERT_EQ(runs.summaries.size(), 1u);
  EXPECT_DOUBLE_EQ(runs.summaries[0].success_rate, 0.5);
  ASSERT_EQ(runs.lines.size(), 2u);
  EXPECT_DOUBLE_EQ(runs.lines[0].total_ms, 120.5);
  EXPECT_EQ(runs.lines[0].duration_s, 7.5);
  EXPECT_FALSE(runs.lines[1].duration_s.has_value());

  WriteBenchPlots(runs, (dir_ / "plots").string());
  for (const char* name : {"success_rate.png", "planning_time.png", "duration_vs_distance.png"}) {
    const viz::Image png = viz::ReadPng((dir_ / "plots" / name).string());
    EXPECT_GE(png.width(), 400) << name;
    EXPECT_GE(png.height(), 400) << name;
  }
}

TEST_F(BenchPlotFilesTest, BadInputNamesTheFileAndTheLine) {
  const std::string run = (dir_ / "run").string();
  EXPECT_NE(ErrorOf({run}).find("summary.json"), std::string::npos);  // missing
  Write("run/summary.json", R"([{"method": "topay"}])");
  EXPECT_NE(ErrorOf({run}).find("summary.json: entry 0: missing scene"), std::string::npos)
      << ErrorOf({run});
  Write("run/summary.json", "[{\"method\": ");
  EXPECT_NE(ErrorOf({run}).find("summary.json: malformed JSON"), std::string::npos);
  Write("run/summary.json",
        R"([{"method": "topay", "scene": "c", "range": "small", "tasks": 1, "success_rate": 1}])");
  Write("run/tasks.jsonl", "{}\n{\"scene\": 1}\n");
  EXPECT_NE(ErrorOf({run}).find("tasks.jsonl:1: missing scene"), std::string::npos)
      << ErrorOf({run});
  Write("run/tasks.jsonl",
        R"({"scene": "c", "range": "small", "method": "topay", "success": "yes"})");
  EXPECT_NE(ErrorOf({run}).find("tasks.jsonl:1: success has the wrong type"), std::string::npos)
      << ErrorOf({run});
  EXPECT_NE(ErrorOf({dir_.string()}).find("summary.json"), std::string::npos);
}

}  // namespace
}  // namespace topay::bench_plot
