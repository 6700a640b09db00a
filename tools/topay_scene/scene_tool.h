#pragma once

#include <cstdint>
#include <optional>
#include <string>

namespace topay::scene_tool {

/// What the topay-scene command does, as plain values (the CLI only fills this in).
struct SceneToolOptions {
  /// Scene source: exactly one of scene_kind ("cuboids" | "tables", generated from `seed`) and
  /// scene_file (a scene JSON).
  std::string scene_kind;
  std::string scene_file;
  std::uint64_t seed = 1;
  /// Task source, optional, at most one: range ("small" | "medium" | "large") generates a task
  /// from `seed` (with scene_kind: GenerateBenchmarkCase, whose scene has keep-out zones
  /// around the task and the seed DeriveSeed(seed, 1); with scene_file: GenerateTask in the
  /// loaded scene); task_file loads a task JSON.
  std::string range;
  std::string task_file;
  /// Outputs; empty: not written.
  std::string scene_json_out;
  std::string task_json_out;
  std::string png_out;
  double resolution_m = 0.1;  ///< Cell size of the distance fields.
  double px_per_m = 40.0;     ///< Scale of the PNG.
  std::string robot_urdf;     ///< Robot description (required).
  std::string robot_yaml;
};

/// What was done, for the one-paragraph report.
struct SceneToolSummary {
  std::string scene_kind;  ///< Scene::kind.
  std::uint64_t scene_seed = 0;
  int num_boxes = 0;
  int num_raised_boxes = 0;  ///< Boxes whose bottom is above the floor (see IsRaised).
  double field_resolution_m = 0.0;
  int field_cells_x = 0;
  int field_cells_y = 0;
  int num_boxes_in_base_band = 0;
  double field_build_s = 0.0;  ///< Both distance fields, rasterisation included.
  double base_field_build_s = 0.0;
  std::optional<std::string> task_range;
  std::uint64_t task_seed = 0;
  double task_distance_m = 0.0;
  int png_width_px = 0;
  int png_height_px = 0;

  /// One paragraph (no trailing newline): boxes, field size and build time, task distance,
  /// files written.
  std::string Paragraph(const SceneToolOptions& options) const;
};

/// Loads the robot, gets the scene and the task, writes the requested JSON files, builds the
/// scene's distance fields (timed), draws the PNG. Throws topay::ConfigError for a missing or
/// malformed input file (naming it), tools::UsageError for impossible options (naming the
/// option as the CLI spells it, e.g. "--scene: unknown kind 'x' (cuboids or tables)"), and
/// std::runtime_error for an output that cannot be written or a generator that gives up.
SceneToolSummary RunSceneTool(const SceneToolOptions& options);

}  // namespace topay::scene_tool
