# Fuzz targets of the file loaders (included by tests/fuzz/CMakeLists.txt): URDF + robot YAML,
# planner and graph YAML, scene and task JSON, and the other configuration files.
# Seeds: tools/fuzz/write_loader_seeds.sh (the shipped config files, a selector byte where the
# input format has one, and a few variants). Each target links only its loaders' libraries;
# topay-mapper's options and scan filter are not fuzzed here (topay_mapper_filters links PCL).

# URDF and robot YAML, alone and together: [URDF][0x00][YAML].
topay_add_fuzz_target(robot_model DEPS topay_core_io topay_robot topay_validate)
# The core planner's YAML and topay-planner's own: [selector][YAML].
topay_add_fuzz_target(planner_yaml DEPS topay_core_io topay_planner_proc)
# Process graph files, then group selection and variable expansion: [flags][names][0x00][YAML].
topay_add_fuzz_target(graph_yaml DEPS topay_launch)
# Scene files and their round trip: [flags][JSON].
topay_add_fuzz_target(scene_json DEPS topay_scenes)
# Planning task files and their round trip: [joint count][JSON].
topay_add_fuzz_target(task_json DEPS topay_scenes)
# The other configuration loaders, one per input: [selector][YAML].
topay_add_fuzz_target(config_yaml
  DEPS topay_mission_proc topay_sim_motors topay_sim_events topay_sim_lidar topay_canbridge_proc
       topay_tracker_proc topay_sim_proc topay_director_proc topay_estimator_proc topay_viz_proc
       topay_kinematic_sim topay_scenarios topay_core_io)
