#include "sim/viz/trajectory_view.h"

#include <sstream>
#include <stdexcept>

#include "sim/viz/color_map.h"
#include "sim/viz/legend.h"
#include "sim/viz/raster.h"
#include "sim/viz/robot_drawing.h"
#include "sim/viz/world_canvas.h"

namespace topay::viz {
namespace {

void CheckView(const TrajectoryView& view) {
  if (view.scene == nullptr) throw std::invalid_argument("RenderTrajectoryView: no scene given");
  if (view.kinematics == nullptr) {
    throw std::invalid_argument("RenderTrajectoryView: no kinematics given");
  }
  if (view.start.num_joints() != view.kinematics->num_joints() || !view.start.IsFinite()) {
    throw std::invalid_argument(
        "RenderTrajectoryView: the start state has the wrong joint count or a non-finite value");
  }
}

std::string Seconds(double value) {
  std::ostringstream out;
  out.setf(std::ios::fixed);
  out.precision(1);
  out << value << " s";
  return out.str();
}

// The keys of the trajectory layer; with a null image this only measures.
void LayOutTrajectoryLegend(const TrajectoryView& view, const TrajectoryViewOptions& options,
                            LegendLayout* legend) {
  legend->Swatch(colors::kWhite, colors::kStart, "start");
  if (view.trajectory == nullptr) {
    legend->Text("no trajectory");
    return;
  }
  const TrajectoryDrawingStyle& style = options.trajectory;
  legend->Swatch(colors::kWhite, colors::kGoal, "end");
  legend->Swatch(style.path_colour, style.path_colour, "base path");
  const double duration_s = view.trajectory->duration_s();
  std::ostringstream caption;
  caption << "footprints every " << style.footprint_interval_s << " s, time";
  legend->ColourBar(
      caption.str(), [&](double t) { return FootprintColour(style, t * duration_s, duration_s); },
      "0", Seconds(duration_s));
  std::ostringstream high;
  high << style.sphere_height_m.max << " m";
  std::ostringstream low;
  low << style.sphere_height_m.min;
  legend->ColourBar("arm z", WarmRamp, low.str(), high.str());
}

void DrawPose(WorldCanvas* canvas, const Kinematics& kinematics, const WholeBodyState& state,
              const Rgb& colour, const TrajectoryViewOptions& options) {
  KinematicsCache cache = kinematics.MakeCache();
  kinematics.Update(state, &cache);
  RobotDrawingStyle style = options.scene.robot;
  style.colour = colour;
  style.sphere_height_m = options.trajectory.sphere_height_m;
  DrawRobot(canvas, kinematics.model(), cache, style);
}

// Draws the trajectory layer over the map part of `image` (RenderScene's output).
void DrawLayer(const TrajectoryView& view, const TrajectoryViewOptions& options, Image* image) {
  WorldCanvas canvas(std::move(*image), SceneMapView(*view.scene, options.scene));
  if (view.trajectory != nullptr) {
    DrawTrajectory(&canvas, *view.trajectory, *view.kinematics, options.trajectory);
  }
  DrawPose(&canvas, *view.kinematics, view.start, colors::kStart, options);
  if (view.trajectory != nullptr) {
    TrajectorySample end = view.trajectory->MakePoint();
    view.trajectory->Evaluate(view.trajectory->duration_s(), &end);
    DrawPose(&canvas, *view.kinematics, end.state, colors::kGoal, options);
  }
  DrawEndEffectorTarget(&canvas, view.X_WE_goal, colors::kTarget);
  *image = std::move(canvas.image());
}

}  // namespace

ViewTransform SceneMapView(const Scene& scene, const SceneRenderOptions& options) {
  const Eigen::Vector2d margin = Eigen::Vector2d::Constant(options.margin_m);
  return ViewTransform(Eigen::AlignedBox2d(scene.bounds_W_m.min().head<2>() - margin,
                                           scene.bounds_W_m.max().head<2>() + margin),
                       options.px_per_m);
}

Image RenderTrajectoryView(const TrajectoryView& view, const TrajectoryViewOptions& options) {
  CheckView(view);
  SceneDrawing drawing;
  drawing.scene = view.scene;
  drawing.base_field = view.base_field;
  drawing.targets.push_back({view.X_WE_goal, colors::kTarget, "end-effector target"});
  drawing.title_lines = view.title_lines;
  Image scene_image = RenderScene(drawing, options.scene);
  const int map_height = SceneMapView(*view.scene, options.scene).height_px();

  // The map without RenderScene's legend, the trajectory layer over it (anything drawn past
  // the map's bottom edge is then covered by the legend, as in RenderScene).
  Image layer = scene_image;
  DrawLayer(view, options, &layer);

  const int scale = options.scene.text_scale;
  const int pad = 4 * scale;
  const int width = scene_image.width();
  LegendLayout measure(nullptr, pad, 0, width - 2 * pad, scale);
  LayOutTrajectoryLegend(view, options, &measure);
  const int strip = measure.height() + 2 * pad;
  Image out(width, scene_image.height() + strip, colors::kPaper);
  for (int y = 0; y < scene_image.height(); ++y) {
    const Image& from = y < map_height ? layer : scene_image;
    for (int x = 0; x < width; ++x) out.Set(x, y, from.At(x, y));
  }
  FillRect(&out, 0, scene_image.height(), width, scene_image.height() + 1, colors::kInk);
  LegendLayout legend(&out, pad, scene_image.height() + pad + scale, width - 2 * pad, scale);
  LayOutTrajectoryLegend(view, options, &legend);
  return out;
}

}  // namespace topay::viz
