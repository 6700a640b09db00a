#include "tools/report/path_plot.h"

#include <cmath>
#include <string>

#include <fmt/format.h>

#include "tools/report/map_drawing.h"
#include "tools/report/mission_summary.h"
#include "tools/report/robot_track.h"
#include "tools/viz/legend.h"
#include "tools/viz/shapes.h"
#include "tools/viz/trajectory_drawing.h"

namespace topay::report {
namespace {

namespace colors = viz::colors;
constexpr viz::Rgb kPlanned{0, 114, 178};
constexpr viz::Rgb kDriven{20, 20, 20};
constexpr viz::Rgb kAppeared{230, 159, 0};
constexpr viz::Rgb kContact{220, 0, 0};
constexpr viz::Rgb kArrival{0, 158, 115};
constexpr viz::Rgb kOutline{90, 90, 160};
constexpr double kMarkerPx = 5.0;

double Metres(const viz::WorldCanvas& canvas, double px) { return px / canvas.view().px_per_m(); }

void DrawSceneOutlines(viz::WorldCanvas* canvas, const Scene& scene) {
  for (const OrientedBox& box : scene.boxes) {
    const auto corners = viz::RectangleCorners(box.center_W_m.head<2>(), box.size_m.head<2>(), box.yaw_rad);
    canvas->DrawPolyline(corners, /*closed=*/true, kOutline, 1.0, 0.9);
  }
}

void DrawPlannedPaths(viz::WorldCanvas* canvas, const RunLog& log, const PathPlotOptions& options) {
  for (const LoggedTrajectory& t : log.trajectories) {
    canvas->DrawPolyline(viz::SampleBasePath(t.trajectory, options.planned_sample_period_s), false, kPlanned, 1.2,
                         0.7);
  }
}

void DrawAppearedBoxes(viz::WorldCanvas* canvas, const RunLog& log) {
  for (const sim_event_t& e : log.sim_events) {
    if (e.action != sim_event_t::APPEAR || !e.has_box) continue;
    const auto corners = viz::RectangleCorners({e.center_m[0], e.center_m[1]}, {e.size_m[0], e.size_m[1]}, e.yaw_rad);
    canvas->FillPolygon(corners, kAppeared, 0.45);
    canvas->DrawPolyline(corners, true, kAppeared, 2.5);
  }
}

void DrawDrivenPath(viz::WorldCanvas* canvas, const RunLog& log) {
  const std::vector<Eigen::Vector2d> path = DrivenPath(log.robot_states);
  canvas->DrawPolyline(path, false, colors::kWhite, 5.5);
  canvas->DrawPolyline(path, false, kDriven, 3.0);
}

void DrawContacts(viz::WorldCanvas* canvas, const RunLog& log) {
  for (const sim_contact_t& contact : log.sim_contacts) {
    const auto at = BasePositionAt(log.robot_states, contact.utime);
    if (at) canvas->FillCircle(*at, Metres(*canvas, kMarkerPx), kContact);
  }
}

void DrawCross(viz::WorldCanvas* canvas, const Eigen::Vector2d& p, const viz::Rgb& colour) {
  const double r = Metres(*canvas, kMarkerPx + 1.0);
  canvas->DrawLine(p + Eigen::Vector2d(-r, -r), p + Eigen::Vector2d(r, r), colour, 2.5);
  canvas->DrawLine(p + Eigen::Vector2d(-r, r), p + Eigen::Vector2d(r, -r), colour, 2.5);
}

// Start (blue disc), the goals' end-effector targets (crosses) and the base where each moving
// step (goto, home) ended (green rings).
void DrawMarkers(viz::WorldCanvas* canvas, const RunLog& log) {
  for (const goal_t& goal : log.goals) DrawCross(canvas, {goal.p_WE[0], goal.p_WE[1]}, colors::kGoal);
  for (const MissionStepSummary& step : SummarizeMission(log.mission_statuses).steps) {
    if (!step.moving) continue;
    const auto at = BasePositionAt(log.robot_states, step.end_utime);
    if (at) canvas->StrokeCircle(*at, Metres(*canvas, kMarkerPx + 2.0), kArrival, 2.5);
  }
  if (!log.robot_states.empty()) {
    const WholeBodyState& start = log.robot_states.front().state;
    canvas->FillCircle({start.x_m, start.y_m}, Metres(*canvas, kMarkerPx + 1.0), colors::kStart);
  }
}

void DrawLayers(viz::WorldCanvas* canvas, const RunLog& log, const Scene* scene, const PathPlotOptions& options) {
  const viz::ViewTransform& view = canvas->view();
  const Eigen::Vector2d& o = view.offset_px();
  canvas->painter().FillRect(o.x(), o.y(), o.x() + view.width_px(), o.y() + view.height_px(), colors::kWhite);
  if (log.map) DrawOccupiedColumns(canvas, *log.map);
  if (scene != nullptr) DrawSceneOutlines(canvas, *scene);
  DrawAppearedBoxes(canvas, log);
  DrawDrivenPath(canvas, log);
  DrawPlannedPaths(canvas, log, options);  // thin, over the bold driven path: both stay visible
  DrawContacts(canvas, log);
  DrawMarkers(canvas, log);
}

// The legend's items; with a null painter in `legend` this only measures.
void LayOutLegend(const RunLog& log, const Scene* scene, const viz::ViewTransform& view, viz::LegendLayout* legend) {
  const MissionSummary mission = SummarizeMission(log.mission_statuses);
  legend->Text(log.path);
  legend->Text(fmt::format("mission '{}': {} after {:.1f} s; {} SIM_CONTACT", mission.name, ToString(mission.result),
                           mission.elapsed_s, log.sim_contacts.size()));
  legend->NewRow();
  legend->LineKey(kDriven, 3.0, "driven base path (ROBOT_STATE)");
  legend->LineKey(kPlanned, 1.5, fmt::format("planned base paths ({} TRAJECTORY)", log.trajectories.size()));
  legend->Swatch(colors::kStart, colors::kStart, "start");
  legend->Swatch(colors::kWhite, colors::kGoal, "goal target (x)");
  legend->Swatch(colors::kWhite, kArrival, "arrival (ring)");
  legend->Swatch(kContact, kContact, fmt::format("contact ({})", log.sim_contacts.size()));
  legend->Swatch(kAppeared, kAppeared, "appeared box (SIM_EVENT)");
  if (scene != nullptr) legend->Swatch(colors::kWhite, kOutline, "scene boxes (outline)");
  if (log.map) {
    const viz::ScalarRange z = MapHeightRange(*log.map);
    legend->ColourBar("map: occupied, top", viz::GreyRamp, fmt::format("{:.2g}", z.min),
                      fmt::format("{:.2g} m", z.max));
  }
  legend->ScaleBar(view);
}

}  // namespace

viz::Image RenderPathPlot(const RunLog& log, const Scene* scene, const PathPlotOptions& options) {
  const viz::ViewTransform view = PathPlotView(log, scene, options);
  const int width = PathPlotWidth(view, options);
  const double pad = 0.5 * options.font_px;
  const double legend_top = view.offset_px().y() + view.height_px() + std::ceil(viz::MapAxesBottomPx(options.axes));
  viz::LegendLayout measure(nullptr, pad, 0.0, width - 2.0 * pad, options.font_px);
  LayOutLegend(log, scene, view, &measure);
  const int height = static_cast<int>(std::ceil(legend_top + measure.height() + 2.0 * pad));

  viz::WorldCanvas canvas(viz::Image(width, height, colors::kPaper), view, /*clip_to_view=*/true);
  DrawLayers(&canvas, log, scene, options);
  viz::Painter painter(&canvas.image());
  viz::DrawMapAxes(&painter, view, options.axes);
  viz::LegendLayout legend(&painter, pad, legend_top + 0.25 * options.font_px, width - 2.0 * pad, options.font_px);
  LayOutLegend(log, scene, view, &legend);
  return std::move(canvas.image());
}

}  // namespace topay::report
