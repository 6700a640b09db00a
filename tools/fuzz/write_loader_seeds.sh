#!/usr/bin/env bash
# Writes the seed corpora of the loader fuzz targets (tests/fuzz/loader_targets.cmake) into
# tests/fuzz/corpus/<target>/: the shipped config files (config/), each with the selector or
# flags byte its target's input format starts with, and a few small variants. The scene and
# task seeds are small hand-made files in the library's own format, plus, when BUILD_DIR holds
# a built topay-scene, the head of a generated Cuboids scene and a task in it, both written by
# the library. Existing seeds of the same name are overwritten, others are left alone.
#
#   tools/fuzz/write_loader_seeds.sh [BUILD_DIR]      (default BUILD_DIR: build)
set -euo pipefail

root=$(cd "$(dirname "$0")/../.." && pwd)
config=$root/config
corpus=$root/tests/fuzz/corpus
build_dir=${1:-$root/build}

# seed TARGET NAME PREFIX [FILE...]: the printf-escaped PREFIX, then the files.
seed() {
  local target=$1 name=$2 prefix=$3
  shift 3
  mkdir -p "$corpus/$target"
  { printf "$prefix"; [ $# -eq 0 ] || cat "$@"; } > "$corpus/$target/$name"
}

# --- robot_model: [URDF][0x00][robot YAML] ---------------------------------------------------
robot_pair() {  # robot_pair NAME URDF YAML
  mkdir -p "$corpus/robot_model"
  { cat "$2"; printf '\0'; cat "$3"; } > "$corpus/robot_model/$1"
}
robot_pair topay_mm "$config/robot/topay_mm.urdf" "$config/robot/topay_mm.yaml"
robot_pair six_joint_arm "$root/tests/data/robot/six_joint_arm.urdf" "$root/tests/data/robot/six_joint_arm.yaml"
robot_pair mismatched "$config/robot/topay_mm.urdf" "$root/tests/data/robot/six_joint_arm.yaml"
seed robot_model urdf_only '' "$config/robot/topay_mm.urdf"
# Two joints (continuous, prismatic), limits from the YAML, a stow pose.
seed robot_model minimal '<robot name="mini">
  <link name="base_link"/>
  <link name="arm"/>
  <link name="tool"/>
  <joint name="j1" type="continuous">
    <parent link="base_link"/><child link="arm"/>
    <origin xyz="0 0 0.2" rpy="0 0 0"/><axis xyz="0 0 1"/>
  </joint>
  <joint name="j2" type="prismatic">
    <parent link="arm"/><child link="tool"/>
    <origin xyz="0.1 0 0" rpy="0 1.5707963 0"/><axis xyz="1 0 0"/>
    <limit lower="0" upper="0.3" effort="1" velocity="1"/>
  </joint>
</robot>
\0base_link: base_link
base_cylinder: {radius: 0.3, height: 0.15}
spheres:
  - {link: base_link, xyz: [0, 0, 0.3], radius: 0.1}
  - {link: tool, xyz: [0, 0, 0], radius: 0.05}
base_limits: {v_max: 1, a_max: 1, omega_max: 1, beta_max: 1}
joint_limits:
  velocity: [1, 1]
  acceleration: [2, 2]
  position_lower: [-3.14, 0]
  position_upper: [3.14, 0.3]
end_effector: {link: tool, xyz: [0, 0, 0.05], rpy: [0, 0, 0]}
stow_q: [0, 0.1]
'

# --- planner_yaml: [selector][YAML]; bit 0: 0 core planner, 1 topay-planner --------------------
seed planner_yaml core_topay '\0' "$config/planner/topay.yaml"
seed planner_yaml core_empty '\0'
seed planner_yaml core_small '\0planner:
  time_limit_s: 1.0
  base_limits: {v_max_mps: 0.5}
front_end:
  rrt: {goal_bias: 0.1}
  topology: {mode: jps_only}
'
seed planner_yaml process_planner '\1' "$config/planner/planner.yaml"
seed planner_yaml process_replay '\1' "$config/planner/planner_replay.yaml"

# --- graph_yaml: [flags][names][0x00][YAML]; flags: 1 select, 2 exclude, 4 expand -------------
for graph in "$config"/graphs/*.yaml; do
  name=$(basename "$graph" .yaml)
  seed graph_yaml "$name" '\7\0' "$graph"
done
seed graph_yaml demo_groups '\7sim\nplanning\n-viewer\nBIN_DIR=/usr/local/bin\0' "$config/graphs/demo.yaml"
seed graph_yaml sim_load_only '\0' "$config/graphs/sim.yaml"
seed graph_yaml small '\7g
-h
X=1\0processes:
  - {name: a, command: "${X}/a", group: g}
  - {name: b, command: x, depends_on: [a], group: h, autostart: false}
  - {name: c, command: x, args: ["${RUN_DIR}"], env: {K: "${BIN_DIR}"}, realtime: {nice: 5, cpus: [0]}}
'

# --- scene_json: [flags][JSON]; flags bit 0: read the roles ------------------------------------
small_scene='{
  "kind": "hand-made",
  "seed": 0,
  "bounds": {"min":[-2.0,-2.0,0.0],"max":[2.0,2.0,1.6]},
  "boxes": [
    {"center":[1.0,0.0,0.5],"size":[0.2,0.4,1.0],"yaw":0.3,"role":"grounded_box"},
    {"center":[-1.0,1.0,0.75],"size":[0.5,0.5,0.05],"yaw":0.0,"role":"table_top"}
  ]
}
'
seed scene_json small_roles "\1$small_scene"
seed scene_json small "\0$small_scene"
seed scene_json boxes_only '\1{"boxes": [{"center":[0.5,-0.5,0.25],"size":[0.1,0.1,0.5],"yaw":-1.5}]}\n'
seed scene_json empty '\0{\n  "kind": "cuboids",\n  "seed": 7,\n  "boxes": []\n}\n'

# --- task_json: [robot joint count][JSON] ------------------------------------------------------
task_states='  "start": {"x_m": 0.0, "y_m": 0.0, "yaw_rad": 0.0, "q_rad": [0.0, 0.5, 0.0, 1.2, 0.0, 0.6, 0.0]},
  "goal": {"x_m": 3.0, "y_m": 4.0, "yaw_rad": 1.0, "q_rad": [0.1, 0.4, 0.0, 1.0, 0.0, 0.5, 0.2]},
  "goal_end_effector": {"position_m": [3.2, 4.1, 0.8],
                        "quaternion_wxyz": [0.7071067811865476, 0.0, 0.7071067811865476, 0.0]}'
seed task_json open "\7{
  \"range\": \"small\",
  \"seed\": 12,
  \"scene_seed\": 34,
  \"base_distance_m\": 5.0,
$task_states
}
"
seed task_json tight "\7{
  \"range\": \"medium\",
  \"seed\": 5,
  \"scene_seed\": 0,
  \"base_distance_m\": 5.0,
$task_states,
  \"tight\": {\"start\": {\"clearance_m\": 0.05, \"box\": 3, \"body\": \"arm\"},
            \"goal\": {\"clearance_m\": 0.02, \"box\": 7, \"body\": \"base\"},
            \"goal_kind\": \"on_table\", \"goal_table_top\": 7}
}
"
# No joints, a tight task near a box (goal_table_top null).
seed task_json no_joints '\0{"range": "large", "seed": 1, "scene_seed": 2, "base_distance_m": 0.0,
 "start": {"x_m": 1.0, "y_m": 1.0, "yaw_rad": 0.0, "q_rad": []},
 "goal": {"x_m": 1.0, "y_m": 1.0, "yaw_rad": 3.0, "q_rad": []},
 "goal_end_effector": {"position_m": [1.0, 1.0, 0.5], "quaternion_wxyz": [1.0, 0.0, 0.0, 0.0]},
 "tight": {"start": {"clearance_m": 0.1, "box": 0, "body": "base"},
           "goal": {"clearance_m": 0.1, "box": 1, "body": "arm"},
           "goal_kind": "near_box", "goal_table_top": null}}
'

# Written by the library (topay-scene): a generated Cuboids scene and a small-range task in it.
scene_tool=$build_dir/bin/topay-scene
if [ -x "$scene_tool" ]; then
  work=$(mktemp -d)
  trap 'rm -rf "$work"' EXIT
  (cd "$root" && "$scene_tool" --scene cuboids --seed 3 --range small --json "$work/scene.json" \
    --task-json "$work/task.json" > /dev/null)
  # Its header and first 8 boxes (4 walls, 4 cuboids): a seed of a few hundred bytes.
  { sed -n '1,13p' "$work/scene.json" | sed '$ s/,$//'; printf '  ]\n}\n'; } > "$work/scene_head.json"
  seed scene_json cuboids_seed3 '\1' "$work/scene_head.json"
  seed task_json cuboids_seed3_small '\7' "$work/task.json"
else
  echo "write_loader_seeds: no $scene_tool: the generated scene and task seeds are left as they are" >&2
fi

# --- config_yaml: [selector][YAML]; the selector's order is config_yaml_fuzz.cc's kLoaders -----
seed config_yaml 00_mission '\0' "$config/missions/pick_and_place.yaml"
# Every step type; a two-joint hint (CheckMissionForRobot).
seed config_yaml 00_mission_hint '\0name: m
steps:
  - {type: goto, position_m: [1, 0, 0.5], quat_wxyz: [1, 0, 0, 0], timeout_s: 5,
     hint: {x_m: 0, y_m: 0, yaw_rad: 0, q_rad: [0, 0.5]}}
  - {type: gripper, position: 0.5, settle_s: 0.2}
  - {type: wait, duration_s: 0}
  - {type: home, tolerance: {position_m: 0.1}}
'
seed config_yaml 01_motorsim '\1' "$config/sim/motorsim.yaml"
seed config_yaml 02_events '\2' "$config/sim/events_example.yaml"
seed config_yaml 03_lidar '\3' "$config/sim/lidar.yaml"
mkdir -p "$corpus/config_yaml"
{ printf '\4lidar:\n'; sed 's/^/  /' "$config/sim/lidar.yaml"; } > "$corpus/config_yaml/04_lidar_section"
seed config_yaml 05_canbridge '\5' "$config/canbridge/canbridge.yaml"
seed config_yaml 06_tracker '\6' "$config/tracker/tracker.yaml"
seed config_yaml 07_sim '\7' "$config/sim/sim.yaml"
seed config_yaml 07_sim_inline_lidar '\7lidar:
  options:
    points_per_s: 100000
    mount: {parent_link: base_link, xyz: [0.3, 0, 0.2], rpy: [0, 0.1, 0]}
'
seed config_yaml 08_director '\10' "$config/director/pick_place.yaml"
seed config_yaml 09_mission_options '\11' "$config/mission/mission.yaml"
seed config_yaml 10_estimator '\12' "$config/estimator/estimator.yaml"
seed config_yaml 11_viz '\13' "$config/viz/viz.yaml"
seed config_yaml 12_kinematic_sim '\14' "$config/sim/kinematic_sim.yaml"
seed config_yaml 13_pick_place '\15' "$config/scenarios/pick_place.yaml"

echo "write_loader_seeds: wrote the seeds of robot_model planner_yaml graph_yaml scene_json task_json config_yaml"
