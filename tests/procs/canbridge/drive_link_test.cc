// The host side of one CiA 402 drive: the start-up sequence (NMT reset, boot-up or its timeout,
// the SDO writes with confirmation, retries and aborts, NMT start), the controlword per intent
// (enable steps, quick stop, fault reset only when armed), feedback and the lost drive.
#include "procs/canbridge/drive_link.h"

#include <gtest/gtest.h>

#include "drivers/arm/arm_pdo.h"
#include "drivers/arm/emcy.h"
#include "drivers/arm/heartbeat.h"
#include "drivers/arm/nmt.h"
#include "drivers/arm/sdo.h"

namespace topay::canbridge {
namespace {

using cia402::DriveState;

DriveLink MakeLink(int node = 3) {
  DriveLinkOptions options;
  auto writes = cia402::StartupSdoWrites(node, options.startup, nullptr);
  return DriveLink(node, "joint3", options, *writes);
}

std::vector<can::CanFrame> Step(DriveLink& link, double t) {
  std::vector<can::CanFrame> out;
  link.StartupStep(t, &out);
  return out;
}

can::CanFrame Tpdo1(DriveState state, double position = 0.0) {
  return *cia402::EncodeTpdo1({3, cia402::EncodeStatusword(state), position}, {}, nullptr);
}

TEST(DriveLinkTest, StartupSequence) {
  DriveLink link = MakeLink();
  std::string error;
  auto out = Step(link, 0.0);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(canopen::DecodeNmt(out[0], nullptr)->command, canopen::NmtCommand::kResetCommunication);
  EXPECT_EQ(link.phase(), DrivePhase::kWaitingBootUp);
  EXPECT_TRUE(Step(link, 0.1).empty());
  link.Handle(*canopen::EncodeHeartbeat({3, canopen::NmtState::kBootUp}, nullptr), 0.1, &error);
  out = Step(link, 0.11);  // enter pre-operational + the first write
  ASSERT_EQ(out.size(), 2u);
  EXPECT_EQ(canopen::DecodeNmt(out[0], nullptr)->command, canopen::NmtCommand::kEnterPreOperational);
  const auto writes = cia402::StartupSdoWrites(3, {}, nullptr);
  double t = 0.11;
  for (std::size_t i = 0; i < writes->size(); ++i) {
    if (i > 0) out = Step(link, t);
    const auto request = canopen::DecodeSdoDownloadRequest(out.back(), nullptr);
    ASSERT_TRUE(request) << i;
    EXPECT_EQ(request->address, (*writes)[i].address);
    EXPECT_TRUE(Step(link, t + 0.01).empty());  // waits for the confirmation
    link.Handle(*canopen::EncodeSdoDownloadResponse({3, request->address}, nullptr), t + 0.02, &error);
    t += 0.03;
  }
  out = Step(link, t);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(canopen::DecodeNmt(out[0], nullptr)->command, canopen::NmtCommand::kStartRemoteNode);
  EXPECT_EQ(link.phase(), DrivePhase::kOperational);
  // Lost: no TPDO1 for 0.1 s, no heartbeat for 0.5 s (counted from NMT start).
  EXPECT_EQ(link.LostReason(t + 0.05), "");
  EXPECT_NE(link.LostReason(t + 0.15).find("no TPDO1"), std::string::npos);
  link.Handle(Tpdo1(DriveState::kSwitchOnDisabled), t + 0.49, &error);
  EXPECT_EQ(link.LostReason(t + 0.48), "");
  EXPECT_NE(link.LostReason(t + 0.55).find("no heartbeat"), std::string::npos);
}

// Brings a link through its start-up to operational (every write confirmed); returns the time.
double MakeOperational(DriveLink& link) {
  std::string error;
  Step(link, 0.0);
  link.Handle(*canopen::EncodeHeartbeat({3, canopen::NmtState::kBootUp}, nullptr), 0.01, &error);
  double t = 0.02;
  for (int i = 0; i < 100 && link.phase() != DrivePhase::kOperational; ++i, t += 0.01) {
    for (const can::CanFrame& f : Step(link, t)) {
      if (const auto request = canopen::DecodeSdoDownloadRequest(f, nullptr)) {
        link.Handle(*canopen::EncodeSdoDownloadResponse({3, request->address}, nullptr), t, &error);
      }
    }
  }
  return t;
}

TEST(DriveLinkTest, ErrorCodeReadBySdoNamesAFaultWithoutEmcy) {
  DriveLink link = MakeLink();
  double t = MakeOperational(link);
  ASSERT_EQ(link.phase(), DrivePhase::kOperational);
  std::string error;
  EXPECT_TRUE(Step(link, t).empty());  // nothing asked: nothing sent
  link.Handle(Tpdo1(DriveState::kFault), t, &error);
  EXPECT_TRUE(link.faulted());
  EXPECT_FALSE(link.FaultCode().has_value());  // no EMCY came
  link.RequestErrorCode();
  auto out = Step(link, t);
  ASSERT_EQ(out.size(), 1u);
  const auto read = canopen::DecodeSdoUploadRequest(out[0], nullptr);
  ASSERT_TRUE(read);
  EXPECT_EQ(read->address, (canopen::ObjectAddress{0x603F, 0}));
  EXPECT_TRUE(Step(link, t + 0.05).empty());  // waits sdo_timeout_s
  EXPECT_EQ(Step(link, t + 0.11).size(), 1u);  // asked again
  link.Handle(*canopen::EncodeSdoUploadResponse({3, {0x603F, 0}, 2, 0x8130}, nullptr), t + 0.12, &error);
  EXPECT_EQ(link.FaultCode(), std::optional<std::uint16_t>(0x8130));
  EXPECT_TRUE(Step(link, t + 0.3).empty());
  link.ArmFaultReset();  // the reset forgets the code: a later fault is read again
  EXPECT_FALSE(link.FaultCode().has_value());
  // An EMCY names the fault without a read.
  link.Handle(*canopen::EncodeEmcy({3, 0x2310, 1, {}}, nullptr), t + 0.4, &error);
  EXPECT_EQ(link.FaultCode(), std::optional<std::uint16_t>(0x2310));
}

TEST(DriveLinkTest, ErrorCodeReadGivesUpAfterItsAttemptsOrAnAbort) {
  DriveLink link = MakeLink();
  const double t = MakeOperational(link);
  link.RequestErrorCode();
  EXPECT_EQ(Step(link, t).size(), 1u);
  EXPECT_EQ(Step(link, t + 0.11).size(), 1u);
  EXPECT_EQ(Step(link, t + 0.22).size(), 1u);
  EXPECT_TRUE(Step(link, t + 0.33).empty());  // three unanswered: gave up
  EXPECT_TRUE(link.error_code_unavailable());
  EXPECT_FALSE(link.FaultCode().has_value());
  DriveLink other = MakeLink();
  const double u = MakeOperational(other);
  other.RequestErrorCode();
  Step(other, u);
  std::string error;
  other.Handle(*canopen::EncodeSdoAbort({3, {0x603F, 0}, canopen::sdo_abort::kGeneralError},
                                        canopen::SdoChannel::kServerToClient, nullptr),
               u + 0.01, &error);
  EXPECT_TRUE(other.error_code_unavailable());
  EXPECT_TRUE(Step(other, u + 0.2).empty());
}

TEST(DriveLinkTest, NoBootUpNoAnswerAndAbort) {
  DriveLink link = MakeLink();
  std::string error;
  Step(link, 0.0);
  auto out = Step(link, 0.6);  // boot-up timeout: on without it
  ASSERT_EQ(out.size(), 2u);
  EXPECT_TRUE(Step(link, 0.65).empty());
  EXPECT_EQ(Step(link, 0.71).size(), 1u);  // second request after 0.1 s
  EXPECT_EQ(Step(link, 0.82).size(), 1u);  // third
  EXPECT_TRUE(Step(link, 0.93).empty());   // three requests unanswered: failed
  EXPECT_EQ(link.phase(), DrivePhase::kFailed);
  EXPECT_NE(link.failure().find("not confirmed after 3 requests"), std::string::npos) << link.failure();
  EXPECT_TRUE(Step(link, 1.5).empty());
  out = Step(link, 1.94);  // retried after 1 s: NMT reset again
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(canopen::DecodeNmt(out[0], nullptr)->command, canopen::NmtCommand::kResetCommunication);
  out = Step(link, 2.5);
  const auto request = canopen::DecodeSdoDownloadRequest(out.back(), nullptr);
  link.Handle(*canopen::EncodeSdoAbort({3, request->address, canopen::sdo_abort::kObjectDoesNotExist},
                                       canopen::SdoChannel::kServerToClient, nullptr),
              2.51, &error);
  EXPECT_EQ(link.phase(), DrivePhase::kFailed);
  EXPECT_NE(link.failure().find("aborted: object does not exist"), std::string::npos) << link.failure();
}

TEST(DriveLinkTest, ControlwordsPerIntent) {
  DriveLink link = MakeLink();
  std::string error;
  const auto controlword = [&link](DriveIntent intent, double qdot = 0.0) {
    return cia402::DecodeRpdo1(link.Rpdo(intent, qdot), {}, nullptr)->controlword;
  };
  EXPECT_EQ(controlword(DriveIntent::kEnable), 0x0000);  // no statusword yet
  link.Handle(Tpdo1(DriveState::kSwitchOnDisabled), 0, &error);
  EXPECT_EQ(controlword(DriveIntent::kEnable), 0x0006);
  link.Handle(Tpdo1(DriveState::kReadyToSwitchOn), 0, &error);
  EXPECT_EQ(controlword(DriveIntent::kEnable), 0x0007);
  link.Handle(Tpdo1(DriveState::kOperationEnabled, 0.5), 0, &error);
  const auto rpdo = cia402::DecodeRpdo1(link.Rpdo(DriveIntent::kEnable, 1.5), {}, nullptr);
  EXPECT_EQ(rpdo->controlword, 0x000F);
  EXPECT_NEAR(rpdo->target_velocity_rad_per_s, 1.5, 1e-9);
  EXPECT_NEAR(link.position_rad(), 0.5, 1e-6);
  EXPECT_EQ(cia402::DecodeRpdo1(link.Rpdo(DriveIntent::kQuickStop, 1.5), {}, nullptr)->target_velocity_rad_per_s, 0.0);
  EXPECT_EQ(controlword(DriveIntent::kQuickStop), 0x0002);
  link.Handle(Tpdo1(DriveState::kSwitchedOn), 0, &error);
  EXPECT_EQ(controlword(DriveIntent::kQuickStop), 0x0000);  // not moving: disable voltage
  link.Handle(Tpdo1(DriveState::kOperationEnabled), 0, &error);
  // Fault: EMCY + statusword; held at 0x0000 until armed, then the reset edge.
  canopen::Emcy emcy;
  emcy.node_id = 3;
  emcy.error_code = 0x2310;
  link.Handle(*canopen::EncodeEmcy(emcy, nullptr), 0, &error);
  link.Handle(Tpdo1(DriveState::kFault), 0, &error);
  EXPECT_TRUE(link.faulted());
  EXPECT_EQ(link.last_emcy_code(), 0x2310);
  EXPECT_EQ(controlword(DriveIntent::kEnable), 0x0000);
  EXPECT_EQ(controlword(DriveIntent::kQuickStop), 0x0000);
  link.ArmFaultReset();
  EXPECT_EQ(controlword(DriveIntent::kEnable), 0x0080);
  link.Handle(Tpdo1(DriveState::kSwitchOnDisabled), 0, &error);
  EXPECT_FALSE(link.faulted());
  EXPECT_EQ(controlword(DriveIntent::kEnable), 0x0006);
  EXPECT_EQ(link.Handle(can::CanFrame::Standard(0x183, {1}), 0, &error), FrameResult::kMalformed);
  EXPECT_EQ(link.Handle(can::CanFrame::Standard(0x203, {0, 0, 0, 0, 0, 0}), 0, &error), FrameResult::kHostFrame);
  EXPECT_EQ(link.Handle(can::CanFrame::Standard(0x184, {0, 0, 0, 0, 0, 0}), 0, &error), FrameResult::kNotMine);
}

}  // namespace
}  // namespace topay::canbridge
