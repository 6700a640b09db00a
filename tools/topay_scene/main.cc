// topay-scene: generates or loads a benchmark scene (and optionally a task), writes its JSON
// files and a top-down PNG, and prints a one-paragraph summary. Logic: tools/topay_scene/scene_tool.h.
#include <cstdlib>
#include <exception>
#include <iostream>
#include <string>

#include <CLI/CLI.hpp>

#include "tools/topay_scene/scene_tool.h"

namespace {

// The robot config folder: $TOPAY_CONFIG_DIR if set, else the repository's (compiled in).
std::string ConfigDir() {
  const char* from_env = std::getenv("TOPAY_CONFIG_DIR");
  return from_env != nullptr && *from_env != '\0' ? from_env : TOPAY_CONFIG_DIR;
}

void AddOptions(CLI::App* app, topay::scene_tool::SceneToolOptions* o) {
  auto* kind = app->add_option("--scene", o->scene_kind, "Generate a scene: cuboids | tables");
  auto* file = app->add_option("--scene-file", o->scene_file, "Load a scene JSON instead");
  kind->excludes(file);
  app->add_option("--seed", o->seed, "Seed of the generated scene and task")->capture_default_str();
  auto* range = app->add_option("--range", o->range, "Also generate a task: small | medium | large");
  auto* task = app->add_option("--task-file", o->task_file, "Load a task JSON instead");
  range->excludes(task);
  app->add_option("--json", o->scene_json_out, "Write the scene JSON here");
  app->add_option("--task-json", o->task_json_out, "Write the task JSON here");
  app->add_option("--png", o->png_out, "Write the top-down PNG here");
  app->add_option("--resolution", o->resolution_m, "Distance field cell size (m)")
      ->capture_default_str();
  app->add_option("--px-per-m", o->px_per_m, "PNG scale (pixels per metre)")->capture_default_str();
  const std::string config = ConfigDir();
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
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    std::cerr << "topay-scene: " << e.what() << "\n(run with --help for usage)\n";
    return 2;
  }
  try {
    const topay::scene_tool::SceneToolSummary summary = topay::scene_tool::RunSceneTool(options);
    std::cout << summary.Paragraph(options) << "\n";
  } catch (const std::exception& e) {
    std::cerr << "topay-scene: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
