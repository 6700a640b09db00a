#pragma once

namespace topay {

// Options of the benchmark room generators. Defaults are the paper's benchmark protocol
// (paper Sec. IV-C, with the authors' code's figures).

/// The walled room, centred at W's origin, floor at z = 0.
struct RoomOptions {
  double size_x_m = 20.0;          ///< Outer size of the room (walls included).
  double size_y_m = 20.0;
  double wall_height_m = 1.0;
  double wall_thickness_m = 0.1;   ///< Walls lie inside the 20 x 20 m square.
  double map_height_m = 1.6;       ///< Top of Scene::bounds_W_m.
  /// Rejection sampling bound: an object that cannot be placed (inside the walls, outside the
  /// keep-out regions) in this many draws makes the generator throw.
  int max_tries_per_object = 1000;
};

/// Boxes standing on the floor, yaw uniform in [-pi, pi).
struct GroundedBoxOptions {
  int count = 80;
  double footprint_min_m = 0.2;    ///< Each footprint side uniform in [min, max].
  double footprint_max_m = 0.8;
  double height_min_m = 0.4;
  double height_max_m = 1.5;
};

/// Floating cubes, yaw uniform in [-pi, pi).
struct FloatingCubeOptions {
  int count = 80;
  double side_min_m = 0.3;
  double side_max_m = 0.6;
  double bottom_min_m = 0.4;       ///< Height of the cube's bottom face above the floor.
  double bottom_max_m = 0.8;
};

/// Groups of rows x columns adjacent tables (each a top and four legs), group yaw uniform in
/// [-pi, pi). Each column has its own width and each row its own depth, drawn uniformly in
/// [table_size_min_m, table_size_max_m], so every table's size is in that range and the
/// tables of a group tile a rectangle. One top height per group (uniform in range).
struct TableGroupOptions {
  int count = 40;
  int max_rows = 2;                ///< Rows and columns each uniform in {1, ..., max}.
  int max_columns = 2;
  double table_size_min_m = 0.75;
  double table_size_max_m = 1.25;
  double top_height_min_m = 0.5;   ///< Height of the top's upper face above the floor.
  double top_height_max_m = 1.0;
  double top_thickness_m = 0.05;
  double leg_width_m = 0.05;       ///< Square legs, flush with the top's corners.
};

/// Cuboids room: walls, 80 grounded boxes, 80 floating cubes.
struct CuboidsOptions {
  RoomOptions room;
  GroundedBoxOptions grounded;
  FloatingCubeOptions floating;
};

/// Tables room: walls, 40 table groups, 80 grounded boxes.
struct TablesOptions {
  RoomOptions room;
  TableGroupOptions tables;
  GroundedBoxOptions grounded;
};

}  // namespace topay
