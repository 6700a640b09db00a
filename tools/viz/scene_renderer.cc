#include "tools/viz/scene_renderer.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "tools/viz/color_map.h"

namespace topay::viz {
namespace {

std::string FormatNumber(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

std::string FormatMetres(double value) {
  std::ostringstream out;
  out.setf(std::ios::fixed);
  out.precision(2);
  out << value << " m";
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

int LeftPx(const SceneRenderOptions& options) {
  return static_cast<int>(std::ceil(MapAxesLeftPx(options.axes)));
}

// The legend items, in order; with a null painter this only measures.
void LayOutLegend(const SceneDrawing& drawing, const SceneRenderOptions& options,
                  const SceneOverlay& overlay, const ViewTransform& view, LegendLayout* legend,
                  SceneRenderReport* report) {
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
    const ScalarRange range = DistanceColourRange(*drawing.base_field, options.field);
    const LegendBox bar = legend->ColourBar("base clearance", Viridis, FormatMetres(range.min),
                                            FormatMetres(range.max));
    if (report != nullptr) {
      report->field_range_m = range;
      report->clearance_bar = bar;
    }
  }
  legend->ScaleBar(view);
  if (overlay.legend) {
    legend->NewRow();
    overlay.legend(legend);
  }
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

ViewTransform SceneMapView(const Scene& scene, const SceneRenderOptions& options) {
  const Eigen::Vector2d margin = Eigen::Vector2d::Constant(options.margin_m);
  const Eigen::AlignedBox2d region(scene.bounds_W_m.min().head<2>() - margin,
                                   scene.bounds_W_m.max().head<2>() + margin);
  return ViewTransform(region, options.px_per_m,
                       Eigen::Vector2d(LeftPx(options), std::round(options.top_px)));
}

int SceneImageWidth(int map_width_px, const SceneRenderOptions& options) {
  return LeftPx(options) + map_width_px + static_cast<int>(std::round(options.right_px));
}

Image RenderScene(const SceneDrawing& drawing, const SceneRenderOptions& options_in,
                  SceneRenderReport* report, const SceneOverlay& overlay) {
  CheckInput(drawing);
  SceneRenderOptions options = options_in;
  const Eigen::AlignedBox3d& bounds = drawing.scene->bounds_W_m;
  options.boxes.top_height_m = {bounds.min().z(), bounds.max().z()};

  const ViewTransform view = SceneMapView(*drawing.scene, options);
  const double pad = 0.5 * options.font_px;
  const int width = SceneImageWidth(view.width_px(), options);
  const double legend_top =
      view.offset_px().y() + view.height_px() + std::ceil(MapAxesBottomPx(options.axes));
  LegendLayout measure(nullptr, pad, 0.0, width - 2.0 * pad, options.font_px);
  LayOutLegend(drawing, options, overlay, view, &measure, nullptr);
  const int height = static_cast<int>(std::ceil(legend_top + measure.height() + pad));

  WorldCanvas canvas(Image(width, height, colors::kPaper), view, /*clip_to_view=*/true);
  DrawMap(drawing, options, &canvas);
  if (overlay.draw) overlay.draw(&canvas);

  Painter painter(&canvas.image());
  DrawMapAxes(&painter, view, options.axes);
  painter.FillRect(0.0, legend_top - 2.0, width, legend_top - 1.0, Lerp(colors::kPaper, colors::kInk, 0.3));
  LegendLayout legend(&painter, pad, legend_top + 0.25 * options.font_px, width - 2.0 * pad,
                      options.font_px);
  if (report != nullptr) {
    *report = {};
    const Eigen::Vector2d& o = view.offset_px();
    report->map_px = {o.x(), o.y(), o.x() + view.width_px(), o.y() + view.height_px()};
  }
  LayOutLegend(drawing, options, overlay, view, &legend, report);
  return std::move(canvas.image());
}

}  // namespace topay::viz
