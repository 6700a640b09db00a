#include "tools/viz/trajectory_view.h"

#include <sstream>
#include <stdexcept>

#include "tools/viz/color_map.h"
#include "tools/viz/legend.h"
#include "tools/viz/robot_drawing.h"
#include "tools/viz/world_canvas.h"

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

// The keys of the trajectory layer.
void LayOutTrajectoryLegend(const TrajectoryView& view, const TrajectoryViewOptions& options,
                            LegendLayout* legend) {
  legend->Swatch(colors::kWhite, colors::kStart, "start");
  if (view.trajectory == nullptr) {
    legend->Text("no trajectory");
    return;
  }
  const TrajectoryDrawingStyle& style = options.trajectory;
  legend->Swatch(colors::kWhite, colors::kGoal, "end");
  legend->LineKey(style.path_colour, style.path_width_px, "base path");
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

// Draws the trajectory layer over the map.
void DrawLayer(const TrajectoryView& view, const TrajectoryViewOptions& options,
               WorldCanvas* canvas) {
  if (view.trajectory != nullptr) {
    DrawTrajectory(canvas, *view.trajectory, *view.kinematics, options.trajectory);
  }
  DrawPose(canvas, *view.kinematics, view.start, colors::kStart, options);
  if (view.trajectory != nullptr) {
    TrajectorySample end = view.trajectory->MakePoint();
    view.trajectory->Evaluate(view.trajectory->duration_s(), &end);
    DrawPose(canvas, *view.kinematics, end.state, colors::kGoal, options);
  }
  DrawEndEffectorTarget(canvas, view.X_WE_goal, colors::kTarget);
}

}  // namespace

Image RenderTrajectoryView(const TrajectoryView& view, const TrajectoryViewOptions& options,
                           SceneRenderReport* report) {
  CheckView(view);
  SceneDrawing drawing;
  drawing.scene = view.scene;
  drawing.base_field = view.base_field;
  drawing.targets.push_back({view.X_WE_goal, colors::kTarget, "end-effector target"});
  drawing.title_lines = view.title_lines;
  SceneOverlay overlay;
  overlay.draw = [&](WorldCanvas* canvas) { DrawLayer(view, options, canvas); };
  overlay.legend = [&](LegendLayout* legend) { LayOutTrajectoryLegend(view, options, legend); };
  return RenderScene(drawing, options.scene, report, overlay);
}

}  // namespace topay::viz
