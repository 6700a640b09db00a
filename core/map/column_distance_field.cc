#include "core/map/column_distance_field.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "core/map/box_cell_overlap.h"

namespace topay {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// The nearest column of each phase at or before / at or after each column of the source
// range [begin, end) of one row (-1: none in the range), by one sweep each way.
void NearestColumns(const std::uint8_t* row, int begin, int end, ColumnDistanceWorkspace* ws) {
  int last_occupied = -1, last_free = -1;
  for (int c = begin; c < end; ++c) {
    (row[c] ? last_occupied : last_free) = c;
    ws->prev_occupied[c - begin] = last_occupied;
    ws->prev_free[c - begin] = last_free;
  }
  int next_occupied = -1, next_free = -1;
  for (int c = end - 1; c >= begin; --c) {
    (row[c] ? next_occupied : next_free) = c;
    ws->next_occupied[c - begin] = next_occupied;
    ws->next_free[c - begin] = next_free;
  }
}

// Distance along one axis from coordinate u to the nearest of two column squares: `before`
// at or below u's column (distance u - its upper edge, 0 inside) and `after` above it
// (distance its lower edge - u); -1 for none. Edges are origin + k res, one formula for all
// windows.
inline double AxisDistance(double u, int before, int after, double origin, double res) {
  double best = kInfinity;
  if (before >= 0) best = std::max(u - (origin + (before + 1) * res), 0.0);
  if (after >= 0) best = std::min(best, std::max((origin + after * res) - u, 0.0));
  return best;
}

// Step 1: per source row, the squared x distances from the target's field columns to the
// nearest occupied and free squares of the row (free also: the outside of the grid).
void RowTerms(const OccupancyGrid2& columns, const CellRange& rows, const CellRange& source_x,
              int num_targets, ColumnDistanceWorkspace* ws) {
  const GridGeometry2& cg = columns.geometry();
  const double ox = cg.origin_W_m.x(), rc = cg.resolution_m;
  const int ncx = cg.dims.x();
  const double grid_x_min = ox, grid_x_max = ox + ncx * rc;
  for (int cy = rows.begin; cy < rows.end; ++cy) {
    NearestColumns(columns.cells().data() + std::int64_t{cy} * ncx, source_x.begin, source_x.end,
                   ws);
    double* to_occupied =
        ws->squared_x_to_occupied.data() + std::int64_t{cy - rows.begin} * num_targets;
    double* to_free = ws->squared_x_to_free.data() + std::int64_t{cy - rows.begin} * num_targets;
    for (int i = 0; i < num_targets; ++i) {
      const double x = ws->x_m[i];
      const int c = ws->column_of_x[i];
      // Source columns at or before c, and after it (indices into the sweeps' arrays).
      const int at = std::min(c, source_x.end - 1) - source_x.begin;
      const int above = std::max(c + 1, source_x.begin) - source_x.begin;
      const bool has_at = at >= 0, has_above = above < source_x.end - source_x.begin;
      const double e_occupied = AxisDistance(x, has_at ? ws->prev_occupied[at] : -1,
                                             has_above ? ws->next_occupied[above] : -1, ox, rc);
      double e_free = AxisDistance(x, has_at ? ws->prev_free[at] : -1,
                                   has_above ? ws->next_free[above] : -1, ox, rc);
      // The outside of the grid is free: the distance to the grid's x interval's complement.
      e_free = std::min(e_free, std::max(std::min(x - grid_x_min, grid_x_max - x), 0.0));
      to_occupied[i] = e_occupied * e_occupied;
      to_free[i] = e_free * e_free;
    }
  }
}

}  // namespace

void FillColumnDistanceWindow(const OccupancyGrid2& columns, const GridGeometry2& fg,
                              const CellBox& target, double cap_m, ColumnDistanceWorkspace* ws,
                              float* values) {
  if (!(std::isfinite(cap_m) && cap_m > 0.0)) {
    throw std::invalid_argument("FillColumnDistanceWindow: cap_m must be finite and > 0, got " +
                                std::to_string(cap_m));
  }
  if (target.begin.x() < 0 || target.begin.y() < 0 || target.end.x() > fg.dims.x() ||
      target.end.y() > fg.dims.y() || target.end.x() <= target.begin.x() ||
      target.end.y() <= target.begin.y()) {
    throw std::invalid_argument("FillColumnDistanceWindow: target window outside the field grid");
  }
  const GridGeometry2& cg = columns.geometry();
  const double rc = cg.resolution_m;
  const Eigen::Vector2d oc = cg.origin_W_m;
  const int ncx = cg.dims.x(), ncy = cg.dims.y();
  const int num_targets = target.end.x() - target.begin.x();
  // The target's cell centres and the columns holding them.
  ws->x_m.resize(num_targets);
  ws->column_of_x.resize(num_targets);
  for (int i = 0; i < num_targets; ++i) {
    ws->x_m[i] = fg.origin_W_m.x() + (target.begin.x() + i + 0.5) * fg.resolution_m;
    ws->column_of_x[i] = static_cast<int>(std::floor((ws->x_m[i] - oc.x()) / rc));
  }
  // Source columns and rows: every square within cap_m + one column of a target centre.
  const double reach_m = cap_m + rc;
  const double y_first = fg.origin_W_m.y() + (target.begin.y() + 0.5) * fg.resolution_m;
  const double y_last = fg.origin_W_m.y() + (target.end.y() - 0.5) * fg.resolution_m;
  const CellRange source_x =
      CellsOverlapping(ws->x_m.front() - reach_m, ws->x_m.back() + reach_m, oc.x(), rc, ncx);
  const CellRange rows = CellsOverlapping(y_first - reach_m, y_last + reach_m, oc.y(), rc, ncy);
  const int num_rows = std::max(rows.end - rows.begin, 0);
  const int source_width = std::max(source_x.end - source_x.begin, 1);
  for (auto* v : {&ws->prev_occupied, &ws->next_occupied, &ws->prev_free, &ws->next_free}) {
    v->resize(source_width);
  }
  ws->squared_x_to_occupied.resize(std::int64_t{num_rows} * num_targets);
  ws->squared_x_to_free.resize(std::int64_t{num_rows} * num_targets);
  // Step 1. An empty source range holds no square (and no occupied target point: those lie in
  // columns of the range), so no row term can count.
  if (source_x.empty()) {
    std::fill(ws->squared_x_to_occupied.begin(), ws->squared_x_to_occupied.end(), kInfinity);
    std::fill(ws->squared_x_to_free.begin(), ws->squared_x_to_free.end(), kInfinity);
  } else {
    RowTerms(columns, rows, source_x, num_targets, ws);
  }

  // Step 2: per target row, the minimum over the source rows of ey^2 + the row's term, for
  // both phases at once. ey depends on the rows only, so the inner loops run along the
  // target's columns over contiguous terms; rows with ey^2 beyond the start
  // bound cannot lower a value below the cap and are skipped.
  const double grid_y_min = oc.y(), grid_y_max = oc.y() + ncy * rc;
  const double start_bound = (cap_m + rc) * (cap_m + rc);  // beyond it the value is the cap
  const std::uint8_t* cells = columns.cells().data();
  ws->best_to_occupied.resize(num_targets);
  ws->best_to_free.resize(num_targets);
  ws->occupied_in_row.resize(num_targets);
  double* to_occupied = ws->best_to_occupied.data();
  double* to_free = ws->best_to_free.data();
  for (int fy = target.begin.y(); fy < target.end.y(); ++fy) {
    const double y = fg.origin_W_m.y() + (fy + 0.5) * fg.resolution_m;
    const int r = static_cast<int>(std::floor((y - oc.y()) / rc));
    // Occupied points (inside the grid) also reach the free outside of the grid in y.
    const double e_outside_y = std::max(std::min(y - grid_y_min, grid_y_max - y), 0.0);
    // Which points of the row are occupied (the distance to the free squares is needed for
    // those only: most rows have none, and skip that half of the work).
    const bool row_inside = r >= 0 && r < ncy;
    bool any_occupied = false;
    for (int i = 0; i < num_targets; ++i) {
      const int c = ws->column_of_x[i];
      const bool occupied = row_inside && c >= 0 && c < ncx && cells[std::int64_t{r} * ncx + c];
      ws->occupied_in_row[i] = occupied;
      any_occupied = any_occupied || occupied;
    }
    std::fill_n(to_occupied, num_targets, start_bound);
    std::fill_n(to_free, num_targets, std::min(start_bound, e_outside_y * e_outside_y));
    for (int cy = rows.begin; cy < rows.end; ++cy) {
      // ey: distance from y to the row's interval (rows at or below r: y - upper edge, 0 in r
      // itself; rows above: lower edge - y), one formula whatever the window.
      const double ey = cy <= r ? std::max(y - (oc.y() + (cy + 1) * rc), 0.0)
                                : std::max((oc.y() + cy * rc) - y, 0.0);
      const double ey_squared = ey * ey;
      if (ey_squared >= start_bound) continue;
      const double* occupied_terms =
          ws->squared_x_to_occupied.data() + std::int64_t{cy - rows.begin} * num_targets;
      for (int i = 0; i < num_targets; ++i) {
        to_occupied[i] = std::min(to_occupied[i], ey_squared + occupied_terms[i]);
      }
      if (!any_occupied) continue;
      const double* free_terms =
          ws->squared_x_to_free.data() + std::int64_t{cy - rows.begin} * num_targets;
      for (int i = 0; i < num_targets; ++i) {
        to_free[i] = std::min(to_free[i], ey_squared + free_terms[i]);
      }
    }
    // The phase of each point picks its distance: to the occupied squares from a free point,
    // to the free squares (and the outside) from an occupied one.
    float* out = values + fg.Index(target.begin.x(), fy);
    for (int i = 0; i < num_targets; ++i) {
      const bool occupied = ws->occupied_in_row[i] != 0;
      const double distance = std::min(std::sqrt(occupied ? to_free[i] : to_occupied[i]), cap_m);
      out[i] = static_cast<float>(occupied ? -distance : distance);
    }
  }
}

SignedDistanceField2 BuildColumnDistanceField(const OccupancyGrid2& columns,
                                              const GridGeometry2& field_geometry, double cap_m,
                                              ColumnDistanceWorkspace* workspace) {
  field_geometry.Validate("BuildColumnDistanceField");
  ColumnDistanceWorkspace local;
  std::vector<float> values(static_cast<std::size_t>(field_geometry.NumCells()));
  const CellBox all{Eigen::Vector3i::Zero(),
                    Eigen::Vector3i(field_geometry.dims.x(), field_geometry.dims.y(), 1)};
  FillColumnDistanceWindow(columns, field_geometry, all, cap_m, workspace ? workspace : &local,
                           values.data());
  return SignedDistanceField2::FromCellValues(field_geometry, std::move(values), cap_m,
                                              field_geometry.resolution_m / std::sqrt(2.0));
}

CellBox FieldCellsNearColumns(const GridGeometry2& cg, const CellBox& columns,
                              const GridGeometry2& fg, double cap_m) {
  const double reach_m = cap_m + fg.resolution_m;
  CellBox box{Eigen::Vector3i::Zero(), Eigen::Vector3i::Ones()};
  for (int a = 0; a < 2; ++a) {
    const double low = cg.origin_W_m(a) + columns.begin(a) * cg.resolution_m - reach_m;
    const double high = cg.origin_W_m(a) + columns.end(a) * cg.resolution_m + reach_m;
    const CellRange range =
        CellsOverlapping(low, high, fg.origin_W_m(a), fg.resolution_m, fg.dims(a));
    box.begin(a) = range.begin;
    box.end(a) = range.end;
  }
  return box;
}

}  // namespace topay
