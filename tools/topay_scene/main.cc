// topay-scene: generates or loads a benchmark scene (and optionally a task), writes its JSON
// files and a top-down PNG, and prints a one-paragraph summary. Logic: tools/topay_scene/scene_tool.h.
#include <cstdlib>
#include <exception>
#include <iostream>
#include <string>

#include <CLI/CLI.hpp>

#include "tools/common/tool_cli.h"
#include "tools/common/usage_error.h"
#include "tools/topay_scene/scene_tool.h"

namespace {

void AddOptions(CLI::App* app, topay::scene_tool::SceneToolOptions* o) {
  auto* kind = app->add_option("--scene", o->scene_kind, "Generate a scene: cuboids | tables");
  auto* file = app->add_option("--scene-file", o->scene_file, "Load a scene JSON instead");
  kind->excludes(file);
  app->add_option("--seed", o->seed, "Seed of the generated scene and task")
      ->capture_default_str()
      ->check(topay::tools::NonNegativeInteger());
  auto* range = app->add_option("--range", o->range, "Also generate a task: small | medium | large");
  auto* task = app->add_option("--task-file", o->task_file, "Load a task JSON instead");
  range->excludes(task);
  app->add_option("--json", o->scene_json_out, "Write the scene JSON here");
  app->add_option("--task-json", o->task_json_out, "Write the task JSON here");
  app->add_option("--png", o->png_out, "Write the top-down PNG here");
  app->add_option("--resolution", o->resolution_m, "Distance field cell size (m)")
      ->capture_default_str();
  app->add_option("--px-per-m", o->px_per_m, "PNG scale (pixels per metre)")->capture_default_str();
  const std::string config = topay::tools::ConfigDir(TOPAY_CONFIG_DIR);
  o->robot_urdf = config + "/robot/topay_mm.urdf";
  o->robot_yaml = config + "/robot/topay_mm.yaml";
  app->add_option("--robot", o->robot_urdf, "Robot URDF")->capture_default_str();
  app->add_option("--robot-config", o->robot_yaml, "Robot YAML")->capture_default_str();
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Generate or load a TopAY benchmark scene (and task) and draw it from above."};
  topay::scene_tool::SceneToolOptions options;
  AddOptions(&app, &options);
  app.footer(topay::tools::ExitCodesFooter(false));
  if (const auto code = topay::tools::ParseCommandLine(app, argc, argv, "topay-scene")) {
    return *code;
  }
  try {
    const topay::scene_tool::SceneToolSummary summary = topay::scene_tool::RunSceneTool(options);
    std::cout << summary.Paragraph(options) << "\n";
  } catch (const topay::tools::UsageError& e) {
    std::cerr << "topay-scene: " << e.what() << "\n(run with --help for usage)\n";
    return topay::tools::kExitUsageError;
  } catch (const std::exception& e) {
    std::cerr << "topay-scene: error: " << e.what() << "\n";
    return topay::tools::kExitFileError;
  }
  return topay::tools::kExitSuccess;
}
