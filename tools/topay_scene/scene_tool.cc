#include "tools/topay_scene/scene_tool.h"

#include <chrono>
#include <cmath>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "core/io/robot_loader.h"
#include "tools/common/usage_error.h"
#include "core/map/scene_distance_fields.h"
#include "core/robot/kinematics.h"
#include "sim/scenes/benchmark_scene.h"
#include "sim/scenes/scene_json.h"
#include "sim/scenes/task_generator.h"
#include "sim/scenes/task_json.h"
#include "tools/viz/png_io.h"
#include "tools/viz/scene_renderer.h"

namespace topay::scene_tool {
using viz::BoxDrawingOptions;
using viz::Image;
using viz::IsRaised;
using viz::RenderScene;
using viz::SceneDrawing;
using viz::SceneRenderOptions;
using viz::WritePng;
namespace colors = viz::colors;

namespace {

struct SceneAndTask {
  Scene scene;
  std::vector<BoxRole> roles;
  std::optional<PlanningTask> task;
};

std::string Text(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

void CheckOptions(const SceneToolOptions& o) {
  if (o.scene_kind.empty() == o.scene_file.empty()) {
    throw tools::UsageError("give exactly one of --scene KIND and --scene-file FILE");
  }
  if (!o.range.empty() && !o.task_file.empty()) {
    throw tools::UsageError("give at most one of --range and --task-file");
  }
  if (!o.task_json_out.empty() && o.range.empty() && o.task_file.empty()) {
    throw tools::UsageError("--task-json: there is no task (give --range or --task-file)");
  }
  if (!(o.resolution_m >= 0.01 && o.resolution_m <= 2.0)) {
    throw tools::UsageError("--resolution: " + Text(o.resolution_m) +
                                " m is outside [0.01, 2] m");
  }
  if (!(o.px_per_m >= 1.0 && o.px_per_m <= 400.0)) {
    throw tools::UsageError("--px-per-m: " + Text(o.px_per_m) +
                                " is outside [1, 400]");
  }
}

SceneKind KindOf(const std::string& name) {
  const std::optional<SceneKind> kind = ParseSceneKind(name);
  if (!kind) {
    throw tools::UsageError("--scene: unknown kind '" + name + "' (cuboids or tables)");
  }
  return *kind;
}

std::optional<DistanceRange> RangeOf(const std::string& name) {
  if (name.empty()) return std::nullopt;
  const std::optional<DistanceRange> range = ParseDistanceRange(name);
  if (!range) {
    throw tools::UsageError("--range: unknown range '" + name +
                                "' (small, medium or large)");
  }
  return range;
}

SceneAndTask GetSceneAndTask(const SceneToolOptions& o, const Kinematics& kinematics) {
  const std::optional<DistanceRange> range = RangeOf(o.range);
  SceneAndTask out;
  if (!o.scene_kind.empty()) {
    const SceneKind kind = KindOf(o.scene_kind);
    if (range) {
      BenchmarkCase generated = GenerateBenchmarkCase(kind, *range, o.seed, kinematics);
      out.scene = std::move(generated.scene.scene);
      out.roles = std::move(generated.scene.roles);
      out.task = std::move(generated.task);
    } else {
      GeneratedScene generated = GenerateBenchmarkScene(kind, o.seed);
      out.scene = std::move(generated.scene);
      out.roles = std::move(generated.roles);
    }
  } else {
    out.scene = ReadSceneJson(o.scene_file, &out.roles);
    if (range) out.task = GenerateTask(out.scene, *range, o.seed, kinematics);
  }
  if (!o.task_file.empty()) out.task = ReadTaskJson(o.task_file, kinematics.num_joints());
  return out;
}

SceneDrawing MakeDrawing(const SceneAndTask& input, const SceneDistanceFields& fields,
                         const Kinematics& kinematics, const SceneToolSummary& summary) {
  SceneDrawing drawing;
  drawing.scene = &input.scene;
  drawing.base_field = &fields.base_field_2d;
  std::ostringstream title;
  title << (summary.scene_kind.empty() ? "scene" : summary.scene_kind) << " seed "
        << summary.scene_seed << ", " << summary.num_boxes << " boxes";
  drawing.title_lines.push_back(title.str());
  if (input.task) {
    drawing.kinematics = &kinematics;
    drawing.robots.push_back({input.task->start, colors::kStart, "start"});
    drawing.robots.push_back({input.task->goal, colors::kGoal, "goal"});
    drawing.targets.push_back({input.task->X_WE_goal, colors::kTarget, "end-effector goal"});
    std::ostringstream task;
    task.setf(std::ios::fixed);
    task.precision(2);
    task << DistanceRangeName(input.task->range) << " task seed " << input.task->seed
         << ", base distance " << input.task->base_distance_m << " m";
    drawing.title_lines.push_back(task.str());
  }
  return drawing;
}

double SecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

SceneToolSummary RunSceneTool(const SceneToolOptions& options) {
  CheckOptions(options);
  const RobotModel model = LoadRobotModel(options.robot_urdf, options.robot_yaml);
  const Kinematics kinematics(model);
  const SceneAndTask input = GetSceneAndTask(options, kinematics);

  if (!options.scene_json_out.empty()) {
    WriteSceneJson(options.scene_json_out, input.scene,
                   input.roles.size() == input.scene.boxes.size() ? &input.roles : nullptr);
  }
  if (input.task && !options.task_json_out.empty()) {
    WriteTaskJson(options.task_json_out, *input.task);
  }

  SceneDistanceFieldsOptions field_options;
  field_options.resolution_m = options.resolution_m;
  field_options.base_band = {0.0, model.base_cylinder.height_m};
  const auto start = std::chrono::steady_clock::now();
  const SceneDistanceFields fields = BuildSceneDistanceFields(input.scene, field_options);
  const double field_build_s = SecondsSince(start);

  SceneToolSummary summary;
  summary.scene_kind = input.scene.kind;
  summary.scene_seed = input.scene.seed;
  summary.num_boxes = static_cast<int>(input.scene.boxes.size());
  for (const OrientedBox& box : input.scene.boxes) {
    summary.num_raised_boxes += IsRaised(box, BoxDrawingOptions{}) ? 1 : 0;
  }
  summary.field_resolution_m = options.resolution_m;
  summary.field_cells_x = fields.base_field_2d.geometry().dims.x();
  summary.field_cells_y = fields.base_field_2d.geometry().dims.y();
  summary.num_boxes_in_base_band = fields.summary.num_boxes_in_base_band;
  summary.field_build_s = field_build_s;
  summary.base_field_build_s = fields.summary.rasterize_2d_s + fields.summary.build_2d_s;
  if (input.task) {
    summary.task_range = std::string(DistanceRangeName(input.task->range));
    summary.task_seed = input.task->seed;
    summary.task_distance_m = input.task->base_distance_m;
  }

  if (!options.png_out.empty()) {
    SceneRenderOptions render_options;
    render_options.px_per_m = options.px_per_m;
    const Image image =
        RenderScene(MakeDrawing(input, fields, kinematics, summary), render_options);
    WritePng(image, options.png_out);
    summary.png_width_px = image.width();
    summary.png_height_px = image.height();
  }
  return summary;
}

std::string SceneToolSummary::Paragraph(const SceneToolOptions& options) const {
  std::ostringstream out;
  out.setf(std::ios::fixed);
  out.precision(1);
  out << "Scene " << (scene_kind.empty() ? "(no kind)" : scene_kind) << " (seed " << scene_seed
      << "): " << num_boxes << " boxes, " << num_raised_boxes
      << " of them raised off the floor. Distance fields at " << field_resolution_m * 100.0
      << " cm: base field " << field_cells_x << " x " << field_cells_y << " cells ("
      << num_boxes_in_base_band << " boxes in the base band), both fields built in "
      << field_build_s * 1e3 << " ms (base field " << base_field_build_s * 1e3 << " ms).";
  if (task_range) {
    out.precision(2);
    out << " Task " << *task_range << " (seed " << task_seed << "): start-goal base distance "
        << task_distance_m << " m.";
  } else {
    out << " No task.";
  }
  std::vector<std::string> written;
  if (!options.scene_json_out.empty()) written.push_back(options.scene_json_out);
  if (task_range && !options.task_json_out.empty()) written.push_back(options.task_json_out);
  if (!options.png_out.empty()) {
    written.push_back(options.png_out + " (" + std::to_string(png_width_px) + " x " +
                      std::to_string(png_height_px) + " px)");
  }
  if (written.empty()) {
    out << " Wrote nothing (no --json, --task-json or --png).";
  } else {
    out << " Wrote ";
    for (std::size_t i = 0; i < written.size(); ++i) out << (i ? ", " : "") << written[i];
    out << ".";
  }
  return out.str();
}

}  // namespace topay::scene_tool
