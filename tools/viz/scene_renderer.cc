#include "tools/viz/scene_renderer.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "tools/viz/bitmap_font.h"
#include "tools/viz/color_map.h"
#include "tools/viz/legend.h"
#include "tools/viz/raster.h"
#include "tools/viz/world_canvas.h"

namespace topay::viz {
namespace {

std::string FormatNumber(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

void CheckInput(const SceneDrawing& drawing) {
  if (drawing.scene == nullptr) throw std::invalid_argument("RenderScene: no scene given");
  if (!drawing.robots.empty() && drawing.kinematics == nullptr) {
    throw std::invalid_argument("RenderScene: robot poses given without kinematics");
  }
  for (const RobotPoseDrawing& robot : drawing.robots) {
    if (robot.state.num_joints() != drawing.kinematics->num_joints() ||
        !robot.state.IsFinite()) {
      throw std::invalid_argument("RenderScene: robot pose '" + robot.label +
                                  "' has the wrong joint count or a non-finite value");
    }
  }
}

ViewTransform MapView(const Scene& scene, const SceneRenderOptions& options) {
  const Eigen::Vector2d margin = Eigen::Vector2d::Constant(options.margin_m);
  const Eigen::AlignedBox2d region(scene.bounds_W_m.min().head<2>() - margin,
                                   scene.bounds_W_m.max().head<2>() + margin);
  return ViewTransform(region, options.px_per_m);
}

// The legend items, in order; with a null image this only measures.
void LayOutLegend(const SceneDrawing& drawing, const SceneRenderOptions& options,
                  const ViewTransform& view, LegendLayout* legend) {
  for (const std::string& line : drawing.title_lines) legend->Text(line);
  legend->NewRow();
  for (const RobotPoseDrawing& robot : drawing.robots) {
    if (!robot.label.empty()) legend->Swatch(colors::kWhite, robot.colour, robot.label);
  }
  for (const TargetDrawing& target : drawing.targets) {
    if (!target.label.empty()) legend->Swatch(target.colour, target.colour, target.label);
  }
  const BoxDrawingOptions& boxes = options.boxes;
  legend->Swatch(GreyRamp(0.5), Lerp(GreyRamp(0.5), colors::kInk, 0.4), "raised (hatched)",
                 /*hatched=*/true);
  legend->ColourBar("box top", GreyRamp, FormatNumber(boxes.top_height_m.min),
                    FormatNumber(boxes.top_height_m.max) + " m");
  if (!drawing.robots.empty()) {
    legend->ColourBar("arm z", WarmRamp, FormatNumber(options.robot.sphere_height_m.min),
                      FormatNumber(options.robot.sphere_height_m.max) + " m");
  }
  if (drawing.base_field != nullptr) {
    legend->ColourBar("base clearance", Viridis, "0", FormatNumber(options.field.clip_m) + " m");
  }
  legend->ScaleBar(view);
}

void DrawMap(const SceneDrawing& drawing, const SceneRenderOptions& options,
             WorldCanvas* canvas) {
  if (drawing.base_field != nullptr) DrawDistanceField(canvas, *drawing.base_field, options.field);
  DrawBoxes(canvas, drawing.scene->boxes, options.boxes);
  if (!drawing.robots.empty()) {
    KinematicsCache cache = drawing.kinematics->MakeCache();
    for (const RobotPoseDrawing& robot : drawing.robots) {
      drawing.kinematics->Update(robot.state, &cache);
      RobotDrawingStyle style = options.robot;
      style.colour = robot.colour;
      DrawRobot(canvas, drawing.kinematics->model(), cache, style);
    }
  }
  for (const TargetDrawing& target : drawing.targets) {
    DrawEndEffectorTarget(canvas, target.X_WE, target.colour);
  }
}

}  // namespace

Image RenderScene(const SceneDrawing& drawing, const SceneRenderOptions& options_in) {
  CheckInput(drawing);
  SceneRenderOptions options = options_in;
  const Eigen::AlignedBox3d& bounds = drawing.scene->bounds_W_m;
  options.boxes.top_height_m = {bounds.min().z(), bounds.max().z()};

  const ViewTransform map_view = MapView(*drawing.scene, options);
  const int pad = 4 * options.text_scale;
  const int width = map_view.width_px();
  LegendLayout measure(nullptr, pad, 0, width - 2 * pad, options.text_scale);
  LayOutLegend(drawing, options, map_view, &measure);
  const int height = map_view.height_px() + measure.height() + 2 * pad;

  WorldCanvas canvas(Image(width, height, colors::kPaper), map_view);
  DrawMap(drawing, options, &canvas);
  // Whatever the map drew past its block (thick outlines at the border) is covered by the
  // legend strip's paper.
  FillRect(&canvas.image(), 0, map_view.height_px(), width, height, colors::kPaper);
  FillRect(&canvas.image(), 0, map_view.height_px(), width, map_view.height_px() + 1,
           colors::kInk);
  LegendLayout legend(&canvas.image(), pad, map_view.height_px() + pad + options.text_scale,
                      width - 2 * pad, options.text_scale);
  LayOutLegend(drawing, options, map_view, &legend);
  return std::move(canvas.image());
}

}  // namespace topay::viz
