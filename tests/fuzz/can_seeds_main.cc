// write_can_fuzz_seeds: writes the seed corpora of the CAN fuzz targets (base_frames,
// canopen_frames, can_text, motorsim_frames, canbridge) into CORPUS_ROOT/<target>/, each input
// in its target's format (the comment at the top of tests/fuzz/<target>_fuzz.cc), made with the
// protocols' own encoders: realistic frames, candump lines as can-utils writes them, a host
// starting the simulated devices, the bridge's command streams and stops. Existing files of the
// same name are overwritten; run it again after a format changes and commit the files.
//
//   write_can_fuzz_seeds CORPUS_ROOT   (e.g. tests/fuzz/corpus)
#include <linux/can/error.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <limits>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "drivers/arm/arm_pdo.h"
#include "drivers/arm/cia402_state.h"
#include "drivers/arm/emcy.h"
#include "drivers/arm/heartbeat.h"
#include "drivers/arm/nmt.h"
#include "drivers/arm/sdo.h"
#include "drivers/arm/startup_sdo.h"
#include "drivers/arm/sync.h"
#include "drivers/base/fault_frame.h"
#include "drivers/base/mode_request_frame.h"
#include "drivers/base/odometry_frame.h"
#include "drivers/base/status_frame.h"
#include "drivers/base/velocity_command_frame.h"
#include "drivers/base/wheel_speeds_frame.h"
#include "drivers/can/can_error.h"
#include "drivers/can/can_frame.h"
#include "drivers/can/candump_log.h"
#include "drivers/can/udp_can_datagram.h"
#include "tests/fuzz/can_fuzz.h"
#include "topay/control_command_t.hpp"

namespace topay::fuzz {
namespace {

namespace fs = std::filesystem;
using Bytes = std::vector<std::uint8_t>;

constexpr std::size_t kMaxSeedBytes = 4096;
constexpr int kBaseNode = 16;  // config/canbridge/canbridge.yaml, config/sim/motorsim.yaml

class SeedWriter {
 public:
  explicit SeedWriter(fs::path root) : root_(std::move(root)) {}

  void Write(const std::string& target, const std::string& name, const Bytes& bytes) {
    if (bytes.size() > kMaxSeedBytes) {
      std::fprintf(stderr, "seed %s/%s has %zu bytes, more than %zu\n", target.c_str(), name.c_str(), bytes.size(),
                   kMaxSeedBytes);
      ok_ = false;
      return;
    }
    const fs::path dir = root_ / target;
    fs::create_directories(dir);
    std::ofstream(dir / name, std::ios::binary)
        .write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
    ++count_;
  }
  void Write(const std::string& target, const std::string& name, const ByteWriter& writer) {
    Write(target, name, writer.bytes());
  }
  bool ok() const { return ok_; }
  int count() const { return count_; }

 private:
  fs::path root_;
  bool ok_ = true;
  int count_ = 0;
};

template <class T>
T Must(const std::optional<T>& value) {
  if (!value) {
    std::fprintf(stderr, "an encoder refused a seed's value\n");
    std::exit(1);
  }
  return *value;
}

Bytes TextBytes(std::uint8_t selector, const std::string& text) {
  Bytes bytes(text.size() + 1);
  bytes[0] = selector;
  std::copy(text.begin(), text.end(), bytes.begin() + 1);
  return bytes;
}

// ---------------------------------------------------------------------------------------------
// base_frames: [op even][frame record][node][last counter][has last counter] and
// [op odd][kind][node][double a][double b][u16 bits][x][y][counter].

void DecodeRecord(ByteWriter& w, const can::CanFrame& frame, int node, std::optional<std::uint8_t> last = {},
                  std::uint8_t extra_flags = 0) {
  w.U8(0).Frame(frame, extra_flags).U8(static_cast<std::uint8_t>(node)).U8(last.value_or(0)).U8(last ? 1 : 0);
}

void BaseEncodeRecord(ByteWriter& w, int kind, int node, double a, double b, std::uint16_t bits, std::uint8_t x,
                      std::uint8_t y, std::uint8_t counter) {
  w.U8(1).U8(static_cast<std::uint8_t>(kind)).U8(static_cast<std::uint8_t>(node)).Double(a).Double(b).U16(bits);
  w.U8(x).U8(y).U8(counter);
}

void WriteBaseFrameSeeds(SeedWriter& out) {
  const std::string target = "base_frames";
  using base::BaseFault;
  using base::BaseMode;
  const auto status = Must(base::EncodeStatus({BaseMode::kCanCommand, 0, 0, 48.0, 7}, kBaseNode, nullptr));
  const auto faulted = Must(base::EncodeStatus(
      {BaseMode::kFault, 8, static_cast<std::uint16_t>(base::FaultBit(BaseFault::kCanBusError) | 1), 47.25, 200},
      kBaseNode, nullptr));
  const auto odometry = Must(base::EncodeOdometry({16383, 0xFFFFFF, 9}, kBaseNode, nullptr));
  const auto fault = Must(
      base::EncodeFault({BaseFault::kLeftMotorStall, BaseMode::kFault, base::FaultBit(BaseFault::kLeftMotorStall), 1},
                        kBaseNode, nullptr));
  const auto speeds = Must(base::EncodeWheelSpeeds({4.0, -2.5, 3}, kBaseNode, nullptr));
  const auto request = Must(base::EncodeModeRequest(base::ModeRequest::kCanCommand, kBaseNode, nullptr));
  const auto command = Must(base::EncodeVelocityCommand({0.4, -0.2, 41}, kBaseNode, nullptr));
  const auto stop = Must(base::EncodeVelocityCommand({0.0, 0.0, 0}, 1, nullptr));

  ByteWriter one;
  DecodeRecord(one, status, kBaseNode);
  out.Write(target, "status_can_command", one);
  ByteWriter two;
  DecodeRecord(two, faulted, kBaseNode);
  out.Write(target, "status_fault", two);
  ByteWriter three;
  DecodeRecord(three, odometry, kBaseNode, 8);
  DecodeRecord(three, odometry, kBaseNode, 9);  // the same counter again: stale
  out.Write(target, "odometry_then_stale", three);
  ByteWriter four;
  DecodeRecord(four, fault, kBaseNode);
  out.Write(target, "fault_left_stall", four);
  ByteWriter five;
  DecodeRecord(five, speeds, kBaseNode);
  out.Write(target, "wheel_speeds", five);
  ByteWriter six;
  DecodeRecord(six, request, kBaseNode);
  out.Write(target, "mode_request_can_command", six);
  ByteWriter seven;
  DecodeRecord(seven, command, kBaseNode, 40);
  DecodeRecord(seven, stop, 1);
  out.Write(target, "velocity_commands", seven);
  ByteWriter all;  // every frame of a status cycle, to the wrong node too
  for (const can::CanFrame& frame : {status, odometry, fault, speeds, request, command}) {
    DecodeRecord(all, frame, kBaseNode);
    DecodeRecord(all, frame, kBaseNode + 1);
  }
  out.Write(target, "every_kind", all);
  ByteWriter sealed;  // addressed and sealed: the id and checksum made right, mutations reach the fields
  for (std::uint32_t kind = 0; kind < 6; ++kind) {
    can::CanFrame frame = command;
    frame.id = kind;
    DecodeRecord(sealed, frame, kBaseNode, 0, kFrameAddressed | kFrameSeal);
  }
  out.Write(target, "addressed_sealed", sealed);
  ByteWriter bad;  // the shapes a decoder refuses: extended, remote, error, DLC 9, id above 0x7FF
  can::CanFrame extended = command;
  extended.extended = true;
  can::CanFrame remote = can::CanFrame::Remote(command.id, 8);
  can::CanFrame error = can::MakeCanErrorFrame(CAN_ERR_BUSOFF);
  can::CanFrame long_dlc = command;
  long_dlc.dlc = 9;
  can::CanFrame big_id = command;
  big_id.id = 0x1216;
  for (const can::CanFrame& frame : {extended, remote, error, long_dlc, big_id}) DecodeRecord(bad, frame, kBaseNode);
  out.Write(target, "refused_shapes", bad);
  ByteWriter encoders;
  BaseEncodeRecord(encoders, 2, kBaseNode, 48.0, 0.0, 0, 1, 0, 5);              // status
  BaseEncodeRecord(encoders, 5, kBaseNode, 1.5e6, 0.0, 0x1234, 0x56, 0x01, 6);  // odometry
  BaseEncodeRecord(encoders, 0, kBaseNode, 0.0, 0.0, 0x0001, 1, 3, 7);          // fault
  BaseEncodeRecord(encoders, 4, kBaseNode, 29.9995, -30.0, 0, 0, 0, 8);         // wheel speeds
  BaseEncodeRecord(encoders, 1, kBaseNode, 0.0, 0.0, 0, 3, 0, 9);               // mode request
  BaseEncodeRecord(encoders, 3, kBaseNode, 2.9995, -10.0, 0, 0, 0, 10);         // velocity command
  BaseEncodeRecord(encoders, 3, kBaseNode, std::numeric_limits<double>::quiet_NaN(), 1e300, 0, 0, 0, 11);
  BaseEncodeRecord(encoders, 3, 128, 0.1, 0.1, 0, 0, 0, 12);  // bad node
  out.Write(target, "encoders", encoders);
}

// ---------------------------------------------------------------------------------------------
// canopen_frames: [op even][frame record] and [op odd][which][node][u16 index][subindex][size]
// [u32 value][double x][u16 word][state].

void CanopenEncodeRecord(ByteWriter& w, int which, int node, std::uint16_t index, std::uint8_t sub, int size,
                         std::uint32_t value, double x, std::uint16_t word, std::uint8_t state) {
  w.U8(1).U8(static_cast<std::uint8_t>(which)).U8(static_cast<std::uint8_t>(node)).U16(index).U8(sub);
  w.U8(static_cast<std::uint8_t>(size)).U32(value).Double(x).U16(word).U8(state);
}

void WriteCanopenSeeds(SeedWriter& out) {
  const std::string target = "canopen_frames";
  const cia402::JointUnits units;
  using cia402::DriveState;
  const auto frame_seed = [&](const std::string& name, std::initializer_list<can::CanFrame> frames) {
    ByteWriter w;
    for (const can::CanFrame& frame : frames) w.U8(0).Frame(frame);
    out.Write(target, name, w);
  };
  frame_seed("rpdo1_enable", {Must(cia402::EncodeRpdo1({3, 0x000F, 1.25}, units, nullptr)),
                              Must(cia402::EncodeRpdo1({7, 0x0002, -2.35}, units, nullptr))});
  frame_seed("rpdo2", {Must(cia402::EncodeRpdo2({2, -3.0}, units, nullptr))});
  frame_seed("tpdo1_states",
             {Must(cia402::EncodeTpdo1({1, cia402::EncodeStatusword(DriveState::kOperationEnabled, 0x0210), 0.5}, units,
                                       nullptr)),
              Must(cia402::EncodeTpdo1({4, cia402::EncodeStatusword(DriveState::kFault), -6.28}, units, nullptr))});
  frame_seed("tpdo2", {Must(cia402::EncodeTpdo2({5, 4.7}, units, nullptr))});
  std::vector<can::CanFrame> startup;
  for (const cia402::SdoWrite& write : Must(cia402::StartupSdoWrites(2, cia402::StartupOptions{}, nullptr))) {
    startup.push_back(Must(canopen::EncodeSdoDownloadRequest(cia402::ToDownloadRequest(2, write), nullptr)));
  }
  {
    ByteWriter w;
    for (std::size_t i = 0; i < startup.size() && i < 12; ++i) w.U8(0).Frame(startup[i]);
    out.Write(target, "sdo_startup_writes", w);
  }
  frame_seed("sdo_replies", {Must(canopen::EncodeSdoDownloadResponse({2, {0x1017, 0}}, nullptr)),
                             Must(canopen::EncodeSdoUploadResponse({2, {0x6041, 0}, 2, 0x0237}, nullptr)),
                             Must(canopen::EncodeSdoAbort({2, {0x6060, 0}, canopen::sdo_abort::kValueRangeExceeded},
                                                          canopen::SdoChannel::kServerToClient, nullptr))});
  frame_seed("sdo_requests", {Must(canopen::EncodeSdoUploadRequest({6, {0x6064, 0}}, nullptr)),
                              Must(canopen::EncodeSdoDownloadRequest({6, {0x6040, 0}, 2, 0x0080}, nullptr)),
                              Must(canopen::EncodeSdoAbort({6, {0x1A00, 1}, canopen::sdo_abort::kTimedOut},
                                                           canopen::SdoChannel::kClientToServer, nullptr))});
  frame_seed("nmt", {Must(canopen::EncodeNmt({canopen::NmtCommand::kResetCommunication, 3}, nullptr)),
                     Must(canopen::EncodeNmt({canopen::NmtCommand::kStartRemoteNode, 0}, nullptr))});
  canopen::Emcy emcy;
  emcy.node_id = 3;
  emcy.error_code = canopen::emcy_code::kHeartbeatError;
  emcy.error_register = canopen::error_register::kCommunication | canopen::error_register::kGeneric;
  emcy.manufacturer_data = {1, 2, 3, 4, 5};
  frame_seed("emcy", {Must(canopen::EncodeEmcy(emcy, nullptr))});
  frame_seed("heartbeats", {Must(canopen::EncodeHeartbeat({7, canopen::NmtState::kBootUp}, nullptr)),
                            Must(canopen::EncodeHeartbeat({127, canopen::NmtState::kOperational}, nullptr))});
  frame_seed("sync", {Must(canopen::EncodeSync({}, nullptr)), Must(canopen::EncodeSync({240}, nullptr))});
  {
    ByteWriter w;  // addressed: every function of node 5
    for (std::uint32_t function = 0; function < 14; ++function) {
      can::CanFrame frame = Must(cia402::EncodeRpdo1({1, 0x000F, 0.5}, units, nullptr));
      frame.id = function | (5u << 8);
      w.U8(0).Frame(frame, kFrameAddressed);
    }
    out.Write(target, "addressed_functions", w);
  }
  ByteWriter encoders;
  CanopenEncodeRecord(encoders, 0, 1, 0, 0, 0, 0, 2.35, 0x000F, 0);
  CanopenEncodeRecord(encoders, 2, 4, 0, 0, 0, 0, -6.283185, 0x0637, 0);
  CanopenEncodeRecord(encoders, 4, 2, 0x1017, 0, 2, 100, 0.0, 0, 0);
  CanopenEncodeRecord(encoders, 7, 2, 0x6041, 0, 2, 0x0237, 0.0, 0, 0);
  CanopenEncodeRecord(encoders, 8, 2, 0x6060, 0, 4, canopen::sdo_abort::kGeneralError, 0.0, 0, 1);
  CanopenEncodeRecord(encoders, 9, 0, 0, 0, 0, 0, 0.0, 0, 0x82);
  CanopenEncodeRecord(encoders, 10, 3, 0, 0, 0, 0x04030201, 0.0, 0x8130, 0x11);
  CanopenEncodeRecord(encoders, 11, 127, 0, 0, 0, 0, 0.0, 0, 0x05);
  CanopenEncodeRecord(encoders, 12, 0, 0, 0, 0, 17, 0.0, 0, 1);
  CanopenEncodeRecord(encoders, 1, 3, 0, 0, 0, 0, std::numeric_limits<double>::infinity(), 0, 0);
  out.Write(target, "encoders", encoders);
}

// ---------------------------------------------------------------------------------------------
// can_text: [selector][rest].

void WriteCanTextSeeds(SeedWriter& out) {
  const std::string target = "can_text";
  const std::vector<std::string> frames = {
      "123#DEADBEEF",    "12345678#00",         "7FF#R", "123#R3", "20000040#0000000000000000", "123#",
      "1a0#de.ad.be.ef", "210#E803000000000016"};
  for (std::size_t i = 0; i < frames.size(); ++i)
    out.Write(target, "frame_" + std::to_string(i), TextBytes(0, frames[i]));
  // candump -l lines (as tests/drivers/can/candump_log_test.cc has them).
  const std::vector<std::string> lines = {
      "(1700000000.123456) can0 123#DEADBEEF", "(0000000000.000005) vcan0 12345678#00",
      "(0000000001.000000) can1 7FF#R", "(1700000000.000003) can0 123#11 T", "(1700000000.000002)   can0   00000abc#R"};
  for (std::size_t i = 0; i < lines.size(); ++i)
    out.Write(target, "candump_line_" + std::to_string(i), TextBytes(1, lines[i]));
  std::string log;
  {
    std::ostringstream text;
    can::CandumpLogWriter writer(text);
    const std::vector<can::CanFrame> bus = {
        Must(base::EncodeVelocityCommand({0.4, -0.2, 41}, kBaseNode, nullptr)),
        Must(cia402::EncodeRpdo1({3, 0x000F, 1.25}, cia402::JointUnits{}, nullptr)),
        Must(canopen::EncodeSync({}, nullptr)),
        Must(canopen::EncodeHeartbeat({127, canopen::NmtState::kOperational}, nullptr)),
        can::MakeCanErrorFrame(CAN_ERR_BUSOFF),
        can::MakeCanErrorFrame(CAN_ERR_CRTL, CAN_ERR_CRTL_TX_PASSIVE, 130, 4),
        can::CanFrame::Remote(0x705, 1)};
    std::int64_t t_ns = 1'700'000'000'000'000'000;
    for (const can::CanFrame& frame : bus) writer.Write(t_ns += 5'000'000, "can0", frame);
    log = text.str();
  }
  out.Write(target, "candump_log", TextBytes(2, log));
  out.Write(target, "candump_log_crlf_blank",
            TextBytes(2,
                      "(1700000000.000001) can0 1a0#deadbeef\r\n\n  \n"
                      "(1700000000.000002) can0 123#00 R\n"));
  const std::vector<can::CanFrame> datagrams = {
      Must(base::EncodeStatus({base::BaseMode::kStandby, 0, 0, 48.0, 1}, kBaseNode, nullptr)),
      can::CanFrame::Extended(0x18FF50E5, {1, 2, 3}), can::CanFrame::Remote(0x123, 4),
      can::MakeCanErrorFrame(CAN_ERR_RESTARTED)};
  for (std::size_t i = 0; i < datagrams.size(); ++i) {
    const auto bytes = can::EncodeUdpCanDatagram({0xC0FFEE, static_cast<std::uint32_t>(i), datagrams[i]});
    Bytes seed = {static_cast<std::uint8_t>(3 | (i % 2 == 0 ? 0x80 : 0))};
    seed.insert(seed.end(), bytes.begin(), bytes.end());
    out.Write(target, "udp_datagram_" + std::to_string(i), seed);
  }
  const std::vector<std::string> urls = {"socketcan://can0", "udp://239.255.1.1:9000", "socketcan://vcan0",
                                         "udp://224.0.0.1:1", "udp://239.255.1.10:9000"};
  for (std::size_t i = 0; i < urls.size(); ++i) out.Write(target, "url_" + std::to_string(i), TextBytes(4, urls[i]));
  for (std::size_t i = 0; i < datagrams.size(); ++i) {
    const struct can_frame kernel = can::ToLinuxFrame(datagrams[i]);
    Bytes seed = {5};
    const auto* raw = reinterpret_cast<const std::uint8_t*>(&kernel);
    seed.insert(seed.end(), raw, raw + sizeof kernel);
    out.Write(target, "linux_frame_" + std::to_string(i), seed);
  }
}

// ---------------------------------------------------------------------------------------------
// motorsim_frames: [fault seed] then ops (motorsim_frames_fuzz.cc).

struct MotorsimOps {
  ByteWriter w;
  MotorsimOps() { w.U8(1); }
  MotorsimOps& Frame(const can::CanFrame& frame) {
    w.U8(0).Frame(frame);
    return *this;
  }
  MotorsimOps& Step(int dt_ms) {
    w.U8(1).U8(static_cast<std::uint8_t>(dt_ms)).U8(0);
    return *this;
  }
  MotorsimOps& PlantStep(int dt_ms, std::int16_t v_mm, std::int16_t omega_mrad, std::int8_t q, std::int8_t qdot) {
    w.U8(1).U8(static_cast<std::uint8_t>(dt_ms)).U8(1).U16(static_cast<std::uint16_t>(v_mm));
    w.U16(static_cast<std::uint16_t>(omega_mrad));
    for (int k = 0; k < 7; ++k) w.U8(static_cast<std::uint8_t>(q));
    for (int k = 0; k < 7; ++k) w.U8(static_cast<std::uint8_t>(qdot));
    return *this;
  }
  MotorsimOps& Fault(int kind, int joint, int duration_ms, int value_hundredths, int code) {
    w.U8(2)
        .U8(static_cast<std::uint8_t>(kind))
        .U8(static_cast<std::uint8_t>(joint))
        .U16(static_cast<std::uint16_t>(duration_ms));
    w.U16(static_cast<std::uint16_t>(value_hundredths)).U16(static_cast<std::uint16_t>(code)).U8(0);
    return *this;
  }
  MotorsimOps& Host(int which, int node_index, std::uint16_t a, std::uint16_t b, std::uint8_t c) {
    w.U8(3).U8(static_cast<std::uint8_t>(which)).U8(static_cast<std::uint8_t>(node_index)).U16(a).U16(b).U8(c);
    return *this;
  }
  MotorsimOps& Run(int steps) {
    w.U8(4).U8(static_cast<std::uint8_t>(steps));
    return *this;
  }
  MotorsimOps& ErrorFrame(std::uint32_t class_bits, std::uint8_t controller, std::uint8_t tx, std::uint8_t rx) {
    w.U8(5).U32(class_bits).U8(controller).U8(tx).U8(rx);
    return *this;
  }
  // A host cycle: the RPDO1 of every drive with `controlword` and `target` (1e-4 rad/s), SYNC,
  // the base's velocity command, a 5 ms step.
  MotorsimOps& HostCycle(std::uint16_t controlword, std::int16_t target, std::uint8_t counter) {
    for (int node = 0; node < 7; ++node) Host(2, node, controlword, static_cast<std::uint16_t>(target), 0);
    Host(1, 0, 0, 0, 0);
    Host(6, 0, 400, static_cast<std::uint16_t>(-100), counter);
    return Step(5);
  }
  // Boot-up, NMT start of all, the base in CAN command mode, the drives enabled.
  MotorsimOps& Start() {
    Step(5).Host(0, 0, 0, 0, 130).Host(5, 0, 0, 0, 1);  // c 130: NMT start (130 % 5 = 0), all nodes
    std::uint8_t counter = 0;
    for (const std::uint16_t controlword : {0x0006, 0x0007, 0x000F, 0x000F}) HostCycle(controlword, 5000, counter++);
    return *this;
  }
};

void WriteMotorsimSeeds(SeedWriter& out) {
  const std::string target = "motorsim_frames";
  out.Write(target, "host_enables_and_drives", MotorsimOps().Start().Run(40).HostCycle(0x000F, -5000, 9).Run(20).w);
  out.Write(target, "plant_feedback",
            MotorsimOps().Start().PlantStep(5, 800, -300, 20, -40).PlantStep(10, -3000, 2000, -120, 120).Run(10).w);
  {
    MotorsimOps ops;
    ops.Step(5);
    for (const cia402::SdoWrite& write : Must(cia402::StartupSdoWrites(3, cia402::StartupOptions{}, nullptr))) {
      ops.Frame(Must(canopen::EncodeSdoDownloadRequest(cia402::ToDownloadRequest(3, write), nullptr))).Step(5);
    }
    ops.Host(0, 2, 0, 0, 0).Host(4, 2, 0, 0, 10).Step(5).Host(3, 2, 0xFFFF, 0, 0).Step(5).Run(30);
    out.Write(target, "sdo_startup_writes", ops.w);
  }
  out.Write(target, "faults",
            MotorsimOps()
                .Start()
                .Fault(1, 3, 0, 0, 0x2310)  // drive fault
                .Run(10)
                .Fault(7, 0, 0, 0, 1)  // base fault
                .Run(10)
                .Fault(2, 2, 300, 0, 0)  // heartbeat loss
                .Fault(3, 0, 100, 0, 0)  // bus-off
                .Run(40)
                .Fault(4, 0, 0, 2000, 0)    // rx loss 20 %
                .Fault(5, 0, 0, 1000, 0)    // tx loss 10 %
                .Fault(6, 0, 500, 3000, 0)  // delay 30 ms
                .Run(60)
                .Fault(0, 0, 0, 0, 0)  // clear
                .Run(20)
                .w);
  out.Write(target, "error_frames_and_resets",
            MotorsimOps()
                .Start()
                .ErrorFrame(CAN_ERR_BUSOFF, 0, 0, 0)
                .Run(5)
                .ErrorFrame(CAN_ERR_CRTL, CAN_ERR_CRTL_RX_PASSIVE, 10, 140)
                .Host(0, 4, 0, 0, 3)  // NMT reset node 5
                .Run(10)
                .Host(0, 0, 0, 0, 129)  // NMT reset communication, all
                .Run(10)
                .Host(7, 0, 0, 0, 1)  // the host's boot-up
                .w);
  {
    MotorsimOps ops;
    ops.Start();
    can::CanFrame raw = Must(base::EncodeVelocityCommand({0.4, 0.0, 200}, kBaseNode, nullptr));
    raw.id = 3;  // velocity command kind, addressed and sealed
    ops.w.U8(0).Frame(raw, kFrameAddressed | kFrameSeal | 0x20);
    can::CanFrame pdo = Must(cia402::EncodeRpdo1({2, 0x000F, 2.0}, cia402::JointUnits{}, nullptr));
    pdo.dlc = 5;  // a PDO length error: EMCY
    ops.Frame(pdo).Host(1, 0, 0, 0, 0).Step(5).Run(5);
    out.Write(target, "raw_frames", ops.w);
  }
}

// ---------------------------------------------------------------------------------------------
// canbridge: [start] then ops (canbridge_fuzz.cc).

struct BridgeOps {
  ByteWriter w;
  explicit BridgeOps(bool start_running = true) { w.U8(start_running ? 1 : 0); }
  BridgeOps& Cycles(int n) {  // n cycles, in ops of at most 16
    for (; n > 0; n -= 16) w.U8(0).U8(static_cast<std::uint8_t>(std::min(n, 16) - 1));
    return *this;
  }
  BridgeOps& CycleBy(std::int16_t dt_tenth_ms) {
    w.U8(1).U16(static_cast<std::uint16_t>(dt_tenth_ms));
    return *this;
  }
  // A command of i16 values (1e-3), the robot's joint count, received `offset` half-ms late.
  BridgeOps& Command(std::int16_t v, std::int16_t omega, std::int16_t qdot, std::int8_t offset = 0) {
    w.U8(3).U32(1234).U8(1).U16(static_cast<std::uint16_t>(v)).U8(1).U16(static_cast<std::uint16_t>(omega)).U8(0);
    for (int k = 0; k < 7; ++k) w.U8(1).U16(static_cast<std::uint16_t>(qdot));
    w.U8(static_cast<std::uint8_t>(offset));
    return *this;
  }
  // A command whose values are kSpecial[index] of canbridge_fuzz.cc, with `entries` joint values
  // (joints < 240: the robot's 7; else the count canbridge_fuzz.cc reads for that byte).
  BridgeOps& SpecialCommand(std::uint8_t v, std::uint8_t omega, std::uint8_t qdot, std::uint8_t joints = 0,
                            int entries = 7) {
    w.U8(3).U32(1).U8(2).U8(v).U8(2).U8(omega).U8(joints);
    for (int k = 0; k < entries; ++k) w.U8(2).U8(qdot);
    w.U8(0);
    return *this;
  }
  BridgeOps& EncodedCommand(double v, double omega, double qdot) {
    control_command_t msg{};
    msg.utime = 1;
    msg.v_mps = v;
    msg.omega_radps = omega;
    msg.num_joints = 7;
    msg.qdot_radps.assign(7, qdot);
    Bytes bytes(static_cast<std::size_t>(msg.getEncodedSize()));
    msg.encode(bytes.data(), 0, static_cast<int>(bytes.size()));
    w.U8(2).U8(0).U16(static_cast<std::uint16_t>(bytes.size())).Bytes(bytes).U8(0);
    return *this;
  }
  BridgeOps& FaultReset() {
    w.U8(4).U8(1).U8(8);
    return *this;
  }
  BridgeOps& Inject(const can::CanFrame& frame, std::uint8_t extra_flags = 0) {
    w.U8(5).Frame(frame, extra_flags);
    return *this;
  }
  BridgeOps& ErrorFrame(std::uint32_t class_bits) {
    w.U8(6).U32(class_bits).U8(0).U8(0).U8(0);
    return *this;
  }
  BridgeOps& DriveFault(std::uint8_t drive, std::uint16_t emcy_code) {
    w.U8(7).U8(2).U8(drive).U16(emcy_code);
    return *this;
  }
  BridgeOps& Peer(std::uint8_t action, std::uint8_t argument) {
    w.U8(7).U8(action).U8(argument);
    return *this;
  }
  // A zero command (every value's tag 3: zero), the shortest record.
  BridgeOps& ZeroCommand() {
    w.U8(3).U32(7).U8(3).U8(3).U8(0);
    for (int k = 0; k < 7; ++k) w.U8(3);
    w.U8(0);
    return *this;
  }
  // Commands every 4th cycle for n cycles (the tracker's 50 Hz).
  BridgeOps& CommandFor(int cycles, std::int16_t v, std::int16_t omega, std::int16_t qdot) {
    for (int i = 0; i < cycles; i += 4) {
      if (v == 0 && omega == 0 && qdot == 0) {
        ZeroCommand().Cycles(4);
      } else {
        Command(v, omega, qdot).Cycles(4);
      }
    }
    return *this;
  }
};

void WriteCanbridgeSeeds(SeedWriter& out) {
  const std::string target = "canbridge";
  out.Write(target, "from_power_on", BridgeOps(false).Cycles(160).CommandFor(40, 0, 0, 0).w);
  out.Write(target, "commands_clamped",
            BridgeOps()
                .CommandFor(60, 300, -200, 500)
                .CommandFor(60, 5000, -3000, 9000)
                .CommandFor(40, -5000, 3000, -9000)
                .w);
  out.Write(target, "sign_flips_and_bursts",
            BridgeOps()
                .Command(3000, 3000, 3000)
                .Cycles(1)
                .Command(-3000, -3000, -3000)
                .Cycles(1)
                .Command(3000, -3000, 3000, -6)
                .Command(-3000, 3000, -3000, -2)
                .Command(1000, 0, 2350)
                .Cycles(1)
                .Command(-1000, 0, -2350)
                .Cycles(2)
                .w);
  out.Write(target, "special_values",
            BridgeOps()
                .SpecialCommand(0, 1, 2)
                .Cycles(2)
                .SpecialCommand(3, 4, 5)
                .Cycles(2)
                .SpecialCommand(6, 7, 8)
                .Cycles(2)
                .SpecialCommand(9, 9, 9)
                .Cycles(2)
                .SpecialCommand(8, 8, 8, 241, 0)
                .SpecialCommand(8, 8, 8, 255, 6)
                .Cycles(4)
                .w);
  out.Write(target, "stale_gap_and_recovery",
            BridgeOps()
                .CommandFor(40, 500, 100, 300)
                .Cycles(40)
                .CommandFor(160, 500, 0, 0)
                .CommandFor(200, 0, 0, 0)
                .CommandFor(40, 400, 0, 200)
                .w);
  out.Write(target, "backwards_time",
            BridgeOps()
                .CommandFor(20, 500, 200, 300)
                .CycleBy(-30)
                .Command(800, 0, 800, -100)
                .CycleBy(-5000)
                .Cycles(4)
                .CycleBy(2)
                .CycleBy(1)
                .Command(-800, 0, -800, 100)
                .CycleBy(50)
                .Cycles(30)
                .w);
  out.Write(target, "decoded_commands",
            BridgeOps()
                .EncodedCommand(0.3, 0.1, 0.2)
                .Cycles(4)
                .EncodedCommand(std::numeric_limits<double>::quiet_NaN(), 0, 0)
                .Cycles(4)
                .EncodedCommand(1e300, -1e300, 5e-324)
                .Cycles(4)
                .w);
  out.Write(target, "drive_fault_and_reset",
            BridgeOps()
                .CommandFor(20, 400, 0, 200)
                .DriveFault(2, 0x2310)
                .CommandFor(40, 0, 0, 0)
                .FaultReset()
                .CommandFor(200, 0, 0, 0)
                .CommandFor(20, 300, 0, 100)
                .w);
  out.Write(target, "base_fault_and_reset",
            BridgeOps()
                .CommandFor(20, 400, 100, 0)
                .Peer(3, 0)
                .CommandFor(40, 0, 0, 0)
                .FaultReset()
                .CommandFor(200, 0, 0, 0)
                .w);
  out.Write(target, "bus_off_and_restart",
            BridgeOps()
                .CommandFor(20, 400, 0, 100)
                .ErrorFrame(CAN_ERR_BUSOFF)
                .CommandFor(40, 0, 0, 0)
                .ErrorFrame(CAN_ERR_RESTARTED)
                .CommandFor(200, 0, 0, 0)
                .w);
  out.Write(target, "lost_heartbeat_and_base",
            BridgeOps()
                .CommandFor(20, 300, 0, 300)
                .Peer(1, 5)
                .CommandFor(120, 0, 0, 0)
                .Peer(1, 5)
                .CommandFor(240, 0, 0, 0)
                .Peer(0, 0)
                .CommandFor(80, 0, 0, 0)
                .Peer(0, 0)
                .CommandFor(200, 0, 0, 0)
                .w);
  out.Write(target, "power_cycle_abort_down",
            BridgeOps()
                .CommandFor(20, 300, 0, 300)
                .Peer(5, 4)
                .Peer(4, 3)
                .CommandFor(200, 0, 0, 0)
                .Peer(5, 0x80)
                .Peer(6, 0)
                .Cycles(20)
                .Peer(6, 0)
                .CommandFor(240, 0, 0, 0)
                .w);
  {
    BridgeOps ops;
    ops.CommandFor(20, 300, 0, 300);
    ops.Inject(Must(base::EncodeStatus({base::BaseMode::kStandby, 0, 0, 48.0, 99}, kBaseNode, nullptr)));
    ops.Inject(Must(cia402::EncodeTpdo1({3, cia402::EncodeStatusword(cia402::DriveState::kQuickStopActive), 0.1},
                                        cia402::JointUnits{}, nullptr)));
    can::CanFrame status = Must(base::EncodeStatus({base::BaseMode::kCanCommand, 0, 0, 48.0, 1}, kBaseNode, nullptr));
    status.id = 2;  // status kind, addressed and sealed
    ops.Inject(status, kFrameAddressed | kFrameSeal | 0x20);
    ops.Inject(Must(canopen::EncodeEmcy({4, 0x8611, 1, {}}, nullptr)));
    ops.Peer(7, 0).w.Frame(Must(cia402::EncodeRpdo1({1, 0x0002, 0.0}, cia402::JointUnits{}, nullptr)));
    ops.CommandFor(120, 0, 0, 0);
    out.Write(target, "injected_frames", ops.w);
  }
}

}  // namespace
}  // namespace topay::fuzz

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s CORPUS_ROOT  (e.g. tests/fuzz/corpus)\n", argv[0]);
    return 2;
  }
  topay::fuzz::SeedWriter out(argv[1]);
  topay::fuzz::WriteBaseFrameSeeds(out);
  topay::fuzz::WriteCanopenSeeds(out);
  topay::fuzz::WriteCanTextSeeds(out);
  topay::fuzz::WriteMotorsimSeeds(out);
  topay::fuzz::WriteCanbridgeSeeds(out);
  std::printf("wrote %d seeds under %s\n", out.count(), argv[1]);
  return out.ok() ? 0 : 1;
}
