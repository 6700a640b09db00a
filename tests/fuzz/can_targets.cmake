# Fuzz targets of the CAN side (included by tests/fuzz/CMakeLists.txt): the frame decoders of the
# base protocol and of CANopen / CiA 402, the text and datagram forms of frames, and the two
# stateful ends of the bus (the motor simulator's devices, the bridge).

# drivers/base/: every decoder and encoder of the base controller's frames.
topay_add_fuzz_target(base_frames DEPS topay_base_protocol)
# drivers/arm/: PDOs, SDO, NMT, EMCY, heartbeat, SYNC, COB-IDs, statusword / controlword.
topay_add_fuzz_target(canopen_frames DEPS topay_cia402)
# drivers/can/: cansend text, candump lines and logs, UDP datagrams, URLs, kernel frames.
topay_add_fuzz_target(can_text DEPS topay_can)
# sim/motors/: the simulated wheel controller and drives under received frames, steps, faults.
topay_add_fuzz_target(motorsim_frames DEPS topay_sim_motors)
# procs/canbridge/: the bridge on the in-memory bus with the device peers (tests/procs/canbridge/).
topay_add_fuzz_target(canbridge DEPS topay_canbridge_proc topay_core_io)

# The seed corpora of the targets above (tests/fuzz/corpus/<target>/): not a test, run by hand:
#   build-test/tests/fuzz/write_can_fuzz_seeds tests/fuzz/corpus
if(NOT TOPAY_FUZZ)
  add_executable(write_can_fuzz_seeds ${CMAKE_CURRENT_SOURCE_DIR}/can_seeds_main.cc)
  target_link_libraries(write_can_fuzz_seeds PRIVATE topay_base_protocol topay_cia402 topay_can topay_lcmtypes)
endif()
