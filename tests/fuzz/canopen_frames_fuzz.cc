// The arm's CANopen / CiA 402 frames (drivers/arm/): ClassifyCobId and CheckCanopenFrame, the
// PDOs of arm_pdo.h, expedited SDO requests, responses and aborts with the server's and client's
// dispatchers, NMT, EMCY, heartbeat, SYNC, and the statusword / controlword helpers, on fuzzed
// frames; and every encoder on fuzzed values. Checked: a refusal names why, with the same verdict
// without asking; a decoded frame is the function its id classifies as, with that node id; values
// are within their bounds; a decoded frame encodes back to the same frame where every bit of it
// is carried (PDOs, aborts, NMT, EMCY, heartbeat, SYNC), and to the same meaning where the
// protocol has don't-care bits (SDO: the size bits of a specifier without s, data bytes beyond
// the size, reserved bytes of requests); an encoded value decodes back to itself.
//
// Input: records until the input ends, each [op] then
//   op even: a frame record (can_fuzz.h; addressed: the id of function (id % 14) for node
//            (id >> 8) & 0x7F; seal: unused): 15 bytes with the op;
//   op odd:  an encoder record [which][node id][u16 index][subindex][size][u32 value]
//            [double x][u16 word][state]: which % 13 picks the encoder: 23 bytes with the op.
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <variant>

#include "drivers/arm/arm_pdo.h"
#include "drivers/arm/canopen_ids.h"
#include "drivers/arm/cia402_state.h"
#include "drivers/arm/emcy.h"
#include "drivers/arm/heartbeat.h"
#include "drivers/arm/nmt.h"
#include "drivers/arm/sdo.h"
#include "drivers/arm/sync.h"
#include "tests/fuzz/can_frame_kinds.h"
#include "tests/fuzz/can_fuzz.h"
#include "tests/fuzz/fuzz_check.h"

namespace topay::fuzz {
namespace {

using canopen::CanopenFunction;


template <class Decode>
auto DecodeBothWays(Decode decode) {
  std::string error;
  auto decoded = decode(&error);
  FuzzCheck(decoded.has_value() || !error.empty(), "a refused frame comes with a reason");
  FuzzCheck(decode(nullptr).has_value() == decoded.has_value(), "the verdict does not depend on the error string");
  return decoded;
}

// A decoded frame is a valid standard data frame of `function`, and the node id is its id's.
void CheckIsFunction(const can::CanFrame& frame, CanopenFunction function, int node_id) {
  FuzzCheck(can::CheckCanFrame(frame).empty() && !frame.extended && !frame.remote && !frame.error,
            "a decoded frame is a valid standard data frame");
  const auto cob = canopen::ClassifyCobId(frame.id, nullptr);
  FuzzCheck(cob && cob->function == function && cob->node_id == node_id,
            "a decoded frame's id is its function's, for its node");
}

void CheckSame(const std::optional<can::CanFrame>& again, const can::CanFrame& frame, const char* what) {
  FuzzCheck(again.has_value() && *again == frame, what);
}

void CheckClassification(const can::CanFrame& frame) {
  std::string error;
  const auto cob = canopen::ClassifyCobId(frame.id, &error);
  FuzzCheck(cob.has_value() || !error.empty(), "an unclassified id comes with a reason");
  if (cob) {
    FuzzCheck(canopen::HasNodeId(cob->function) == (cob->node_id != 0), "node id 0 exactly for NMT and SYNC");
    FuzzCheck(cob->node_id >= 0 && cob->node_id <= canopen::kMaxNodeId, "node id in 0..127");
    FuzzCheck(canopen::CobIdOf(cob->function, cob->node_id, nullptr) == frame.id,
              "the COB-ID of the classified function and node is the id");
    FuzzCheck(!canopen::ToString(cob->function).empty(), "every function has a name");
  }
  const bool data_frame = can::CheckCanFrame(frame).empty() && !frame.extended && !frame.remote && !frame.error;
  for (const CanopenFunction function : kFunctions) {
    const auto node =
        DecodeBothWays([&](std::string* e) { return canopen::CheckCanopenFrame(frame, function, 0, 8, "fuzz", e); });
    FuzzCheck(node.has_value() == (data_frame && cob && cob->function == function),
              "CheckCanopenFrame passes exactly the valid data frames of the function");
    if (node) FuzzCheck(*node == cob->node_id, "CheckCanopenFrame gives the id's node");
  }
}

void CheckPdos(const can::CanFrame& frame, const cia402::JointUnits& units) {
  if (const auto pdo = DecodeBothWays([&](std::string* e) { return cia402::DecodeRpdo1(frame, units, e); })) {
    CheckIsFunction(frame, CanopenFunction::kRpdo1, pdo->node_id);
    FuzzCheck(std::abs(pdo->target_velocity_rad_per_s) <= units.max_target_velocity_rad_per_s,
              "RPDO1: |target velocity| within its bound");
    CheckSame(cia402::EncodeRpdo1(*pdo, units, nullptr), frame, "a decoded RPDO1 encodes to the same frame");
    const cia402::Command command = cia402::DecodeControlwordCommand(pdo->controlword);
    FuzzCheck(cia402::DecodeControlwordCommand(cia402::ControlwordOf(command)) == command,
              "a decoded controlword command's word decodes to it");
  }
  if (const auto pdo = DecodeBothWays([&](std::string* e) { return cia402::DecodeRpdo2(frame, units, e); })) {
    CheckIsFunction(frame, CanopenFunction::kRpdo2, pdo->node_id);
    FuzzCheck(std::abs(pdo->target_position_rad) <= units.max_position_rad, "RPDO2: |target position| within");
    CheckSame(cia402::EncodeRpdo2(*pdo, units, nullptr), frame, "a decoded RPDO2 encodes to the same frame");
  }
  if (const auto pdo = DecodeBothWays([&](std::string* e) { return cia402::DecodeTpdo1(frame, units, e); })) {
    CheckIsFunction(frame, CanopenFunction::kTpdo1, pdo->node_id);
    FuzzCheck(cia402::DecodeStatusword(pdo->statusword, nullptr).has_value(), "TPDO1: the statusword is a state");
    FuzzCheck(std::abs(pdo->position_rad) <= units.max_position_rad, "TPDO1: |position| within its bound");
    CheckSame(cia402::EncodeTpdo1(*pdo, units, nullptr), frame, "a decoded TPDO1 encodes to the same frame");
  }
  if (const auto pdo = DecodeBothWays([&](std::string* e) { return cia402::DecodeTpdo2(frame, units, e); })) {
    CheckIsFunction(frame, CanopenFunction::kTpdo2, pdo->node_id);
    FuzzCheck(std::abs(pdo->velocity_rad_per_s) <= units.max_actual_velocity_rad_per_s, "TPDO2: |velocity| within");
    CheckSame(cia402::EncodeTpdo2(*pdo, units, nullptr), frame, "a decoded TPDO2 encodes to the same frame");
  }
}

bool Same(const canopen::ObjectAddress& a, const canopen::ObjectAddress& b) { return a == b; }

// The index, sub-index and the `size` data bytes of two SDO frames agree (the rest may be
// don't-care bits of the protocol).
void CheckSameSdoBytes(const can::CanFrame& a, const can::CanFrame& b, int size, const char* what) {
  FuzzCheck(a.id == b.id && a.dlc == 8 && b.dlc == 8, what);
  for (int i = 1; i < 4 + size; ++i) FuzzCheck(a.data[i] == b.data[i], what);
}

template <class Encode, class Decode>
void CheckSdoDataRoundTrip(const can::CanFrame& frame, int size, Encode encode, Decode decode, const char* what) {
  const std::optional<can::CanFrame> again = encode();
  FuzzCheck(again.has_value(), what);
  CheckSameSdoBytes(*again, frame, size, what);
  FuzzCheck(decode(*again), what);
}

void CheckSdo(const can::CanFrame& frame) {
  using namespace canopen;
  const auto download = DecodeBothWays([&](std::string* e) { return DecodeSdoDownloadRequest(frame, e); });
  const auto upload = DecodeBothWays([&](std::string* e) { return DecodeSdoUploadRequest(frame, e); });
  const auto client_abort =
      DecodeBothWays([&](std::string* e) { return DecodeSdoAbort(frame, SdoChannel::kClientToServer, e); });
  const auto request = DecodeBothWays([&](std::string* e) { return DecodeSdoClientRequest(frame, e); });
  FuzzCheck(request.has_value() == (download || upload || client_abort),
            "the client dispatcher decodes exactly what one of the request decoders does");
  if (download) {
    CheckIsFunction(frame, CanopenFunction::kSdoRx, download->node_id);
    FuzzCheck(download->size_bytes >= 1 && download->size_bytes <= 4, "download: 1..4 bytes");
    const auto* same = std::get_if<SdoDownloadRequest>(&*request);
    FuzzCheck(same && same->value == download->value && Same(same->address, download->address),
              "the client dispatcher gives the download request");
    CheckSdoDataRoundTrip(
        frame, download->size_bytes, [&] { return EncodeSdoDownloadRequest(*download, nullptr); },
        [&](const can::CanFrame& again) {
          const auto back = DecodeSdoDownloadRequest(again, nullptr);
          return back && back->node_id == download->node_id && Same(back->address, download->address) &&
                 back->size_bytes == download->size_bytes && back->value == download->value;
        },
        "a decoded download request encodes to the same address and data");
  }
  if (upload) {
    CheckIsFunction(frame, CanopenFunction::kSdoRx, upload->node_id);
    FuzzCheck(std::holds_alternative<SdoUploadRequest>(*request), "the client dispatcher gives the upload request");
    CheckSdoDataRoundTrip(
        frame, 0, [&] { return EncodeSdoUploadRequest(*upload, nullptr); },
        [&](const can::CanFrame& again) {
          const auto back = DecodeSdoUploadRequest(again, nullptr);
          return back && back->node_id == upload->node_id && Same(back->address, upload->address);
        },
        "a decoded upload request encodes to the same address");
  }
  if (client_abort) {
    CheckIsFunction(frame, CanopenFunction::kSdoRx, client_abort->node_id);
    FuzzCheck(std::holds_alternative<SdoAbort>(*request), "the client dispatcher gives the abort");
    CheckSame(EncodeSdoAbort(*client_abort, SdoChannel::kClientToServer, nullptr), frame,
              "a decoded abort encodes to the same frame");
    FuzzCheck(!SdoAbortCodeName(client_abort->abort_code).empty(), "every abort code has a name");
  }

  const auto done = DecodeBothWays([&](std::string* e) { return DecodeSdoDownloadResponse(frame, e); });
  const auto value = DecodeBothWays([&](std::string* e) { return DecodeSdoUploadResponse(frame, e); });
  const auto server_abort =
      DecodeBothWays([&](std::string* e) { return DecodeSdoAbort(frame, SdoChannel::kServerToClient, e); });
  const auto reply = DecodeBothWays([&](std::string* e) { return DecodeSdoServerReply(frame, e); });
  FuzzCheck(reply.has_value() == (done || value || server_abort),
            "the server dispatcher decodes exactly what one of the reply decoders does");
  if (done) {
    CheckIsFunction(frame, CanopenFunction::kSdoTx, done->node_id);
    FuzzCheck(std::holds_alternative<SdoDownloadResponse>(*reply), "the server dispatcher gives the response");
    CheckSdoDataRoundTrip(
        frame, 0, [&] { return EncodeSdoDownloadResponse(*done, nullptr); },
        [&](const can::CanFrame& again) {
          const auto back = DecodeSdoDownloadResponse(again, nullptr);
          return back && back->node_id == done->node_id && Same(back->address, done->address);
        },
        "a decoded download response encodes to the same address");
  }
  if (value) {
    CheckIsFunction(frame, CanopenFunction::kSdoTx, value->node_id);
    FuzzCheck(value->size_bytes >= 1 && value->size_bytes <= 4, "upload response: 1..4 bytes");
    const auto* same = std::get_if<SdoUploadResponse>(&*reply);
    FuzzCheck(same && same->value == value->value, "the server dispatcher gives the upload response");
    CheckSdoDataRoundTrip(
        frame, value->size_bytes, [&] { return EncodeSdoUploadResponse(*value, nullptr); },
        [&](const can::CanFrame& again) {
          const auto back = DecodeSdoUploadResponse(again, nullptr);
          return back && back->node_id == value->node_id && Same(back->address, value->address) &&
                 back->size_bytes == value->size_bytes && back->value == value->value;
        },
        "a decoded upload response encodes to the same address and data");
  }
  if (server_abort) {
    CheckIsFunction(frame, CanopenFunction::kSdoTx, server_abort->node_id);
    FuzzCheck(std::holds_alternative<SdoAbort>(*reply), "the server dispatcher gives the abort");
    CheckSame(EncodeSdoAbort(*server_abort, SdoChannel::kServerToClient, nullptr), frame,
              "a decoded abort encodes to the same frame");
  }
}

void CheckNetworkManagement(const can::CanFrame& frame) {
  using namespace canopen;
  if (const auto nmt = DecodeBothWays([&](std::string* e) { return DecodeNmt(frame, e); })) {
    CheckIsFunction(frame, CanopenFunction::kNmt, 0);
    FuzzCheck(nmt->node_id >= 0 && nmt->node_id <= kMaxNodeId, "NMT: node 0..127");
    FuzzCheck(!ToString(nmt->command).empty(), "NMT: the command has a name");
    CheckSame(EncodeNmt(*nmt, nullptr), frame, "a decoded NMT command encodes to the same frame");
  }
  if (const auto emcy = DecodeBothWays([&](std::string* e) { return DecodeEmcy(frame, e); })) {
    CheckIsFunction(frame, CanopenFunction::kEmcy, emcy->node_id);
    CheckSame(EncodeEmcy(*emcy, nullptr), frame, "a decoded EMCY encodes to the same frame");
  }
  if (const auto beat = DecodeBothWays([&](std::string* e) { return DecodeHeartbeat(frame, e); })) {
    CheckIsFunction(frame, CanopenFunction::kHeartbeat, beat->node_id);
    FuzzCheck(!ToString(beat->state).empty(), "heartbeat: the state has a name");
    CheckSame(EncodeHeartbeat(*beat, nullptr), frame, "a decoded heartbeat encodes to the same frame");
  }
  if (const auto sync = DecodeBothWays([&](std::string* e) { return DecodeSync(frame, e); })) {
    CheckIsFunction(frame, CanopenFunction::kSync, 0);
    if (sync->counter) {
      FuzzCheck(*sync->counter >= kMinSyncCounter && *sync->counter <= kMaxSyncCounter, "SYNC: counter 1..240");
      const int next = NextSyncCounter(*sync->counter);
      FuzzCheck(next >= kMinSyncCounter && next <= kMaxSyncCounter, "SYNC: the next counter is 1..240");
    }
    CheckSame(EncodeSync(*sync, nullptr), frame, "a decoded SYNC encodes to the same frame");
  }
}

void CheckStateWords(std::uint16_t statusword, std::uint16_t controlword, std::uint16_t previous) {
  std::string error;
  const auto state = cia402::DecodeStatusword(statusword, &error);
  FuzzCheck(state.has_value() || !error.empty(), "a statusword without a state comes with a reason");
  if (state) {
    const std::uint16_t canonical = cia402::EncodeStatusword(*state, statusword);
    FuzzCheck(cia402::DecodeStatusword(canonical, nullptr) == state, "a state's statusword decodes to it");
    FuzzCheck((canonical & ~0x6Fu) == (statusword & ~0x6Fu), "the bits outside the state bits are kept");
    FuzzCheck(!cia402::ToString(*state).empty(), "every state has a name");
  }
  const cia402::Command command = cia402::DecodeControlwordCommand(controlword);
  FuzzCheck(cia402::DecodeControlwordCommand(cia402::ControlwordOf(command)) == command,
            "a controlword's command encodes to a word with that command");
  FuzzCheck(!cia402::ToString(command).empty(), "every command has a name");
  FuzzCheck(cia402::IsFaultResetEdge(previous, controlword) == ((previous & cia402::controlword::kFaultReset) == 0 &&
                                                                (controlword & cia402::controlword::kFaultReset) != 0),
            "a fault reset edge is bit 7 rising");
}

void DecodeFrameRecord(FuzzReader& in) {
  FrameRecord record = NextFrameRecord(in);
  can::CanFrame& frame = record.frame;
  if (record.addressed()) {
    const CanopenFunction function = kFunctions[frame.id % kFunctions.size()];
    const int node_id = static_cast<int>((frame.id >> 8) & 0x7F);
    frame.id = canopen::FunctionBaseCobId(function) + (canopen::HasNodeId(function) ? node_id : 0);
  }
  CheckClassification(frame);
  CheckPdos(frame, cia402::JointUnits{});
  CheckSdo(frame);
  CheckNetworkManagement(frame);
  CheckStateWords(static_cast<std::uint16_t>(frame.data[0] | (frame.data[1] << 8)),
                  static_cast<std::uint16_t>(frame.data[2] | (frame.data[3] << 8)),
                  static_cast<std::uint16_t>(frame.data[4] | (frame.data[5] << 8)));
  FuzzCheck(!canopen::FrameError("fuzz", frame, "x").empty(), "any frame can be named in an error");
}

// Encodes fuzzed values with one encoder: a frame that decodes back to them, or a reason.
void EncodeRecord(FuzzReader& in) {
  using namespace canopen;
  const int which = in.Byte() % 13;
  const int node_id = static_cast<std::int8_t>(in.Byte());  // -128..127: invalid ones too
  const ObjectAddress address{in.U16(), in.Byte()};
  const int size = static_cast<std::int8_t>(in.Byte());
  const std::uint32_t value = in.U32();
  const double x = in.RawDouble();
  const std::uint16_t word = in.U16();
  const std::uint8_t state = in.Byte();
  const cia402::JointUnits units;
  std::string error;
  std::optional<can::CanFrame> frame;
  bool decodes_back = false;
  const auto near = [](double a, double b, double unit) { return std::abs(a - b) <= unit / 2 + 1e-12; };
  switch (which) {
    case 0:
      if ((frame = cia402::EncodeRpdo1({node_id, word, x}, units, &error))) {
        const auto back = cia402::DecodeRpdo1(*frame, units, nullptr);
        decodes_back = back && back->node_id == node_id && back->controlword == word &&
                       near(back->target_velocity_rad_per_s, x, units.rad_per_s_per_velocity_unit);
      }
      break;
    case 1:
      if ((frame = cia402::EncodeRpdo2({node_id, x}, units, &error))) {
        const auto back = cia402::DecodeRpdo2(*frame, units, nullptr);
        decodes_back =
            back && back->node_id == node_id && near(back->target_position_rad, x, units.rad_per_position_unit);
      }
      break;
    case 2:
      if ((frame = cia402::EncodeTpdo1({node_id, word, x}, units, &error))) {
        // A TPDO1 decoder also wants the statusword to be a state: the encoder takes any word.
        const auto back = cia402::DecodeTpdo1(*frame, units, nullptr);
        decodes_back = cia402::DecodeStatusword(word, nullptr)
                           ? back && back->node_id == node_id && back->statusword == word &&
                                 near(back->position_rad, x, units.rad_per_position_unit)
                           : !back;
      }
      break;
    case 3:
      if ((frame = cia402::EncodeTpdo2({node_id, x}, units, &error))) {
        const auto back = cia402::DecodeTpdo2(*frame, units, nullptr);
        decodes_back =
            back && back->node_id == node_id && near(back->velocity_rad_per_s, x, units.rad_per_s_per_velocity_unit);
      }
      break;
    case 4:
      if ((frame = EncodeSdoDownloadRequest({node_id, address, size, value}, &error))) {
        const auto back = DecodeSdoDownloadRequest(*frame, nullptr);
        decodes_back = back && back->node_id == node_id && back->address == address && back->size_bytes == size &&
                       back->value == value;
      }
      break;
    case 5:
      if ((frame = EncodeSdoDownloadResponse({node_id, address}, &error))) {
        const auto back = DecodeSdoDownloadResponse(*frame, nullptr);
        decodes_back = back && back->node_id == node_id && back->address == address;
      }
      break;
    case 6:
      if ((frame = EncodeSdoUploadRequest({node_id, address}, &error))) {
        const auto back = DecodeSdoUploadRequest(*frame, nullptr);
        decodes_back = back && back->node_id == node_id && back->address == address;
      }
      break;
    case 7:
      if ((frame = EncodeSdoUploadResponse({node_id, address, size, value}, &error))) {
        const auto back = DecodeSdoUploadResponse(*frame, nullptr);
        decodes_back = back && back->node_id == node_id && back->address == address && back->size_bytes == size &&
                       back->value == value;
      }
      break;
    case 8: {
      const SdoChannel channel = state % 2 == 0 ? SdoChannel::kClientToServer : SdoChannel::kServerToClient;
      if ((frame = EncodeSdoAbort({node_id, address, value}, channel, &error))) {
        const auto back = DecodeSdoAbort(*frame, channel, nullptr);
        decodes_back = back && back->node_id == node_id && back->address == address && back->abort_code == value;
      }
      break;
    }
    case 9:
      if ((frame = EncodeNmt({static_cast<NmtCommand>(state), node_id}, &error))) {
        const auto back = DecodeNmt(*frame, nullptr);
        decodes_back = back && back->node_id == node_id && static_cast<std::uint8_t>(back->command) == state;
      }
      break;
    case 10: {
      Emcy emcy;
      emcy.node_id = node_id;
      emcy.error_code = word;
      emcy.error_register = state;
      for (int i = 0; i < 4; ++i) emcy.manufacturer_data[i] = static_cast<std::uint8_t>(value >> (8 * i));
      emcy.manufacturer_data[4] = address.subindex;
      if ((frame = EncodeEmcy(emcy, &error))) {
        const auto back = DecodeEmcy(*frame, nullptr);
        decodes_back = back && back->node_id == node_id && back->error_code == word && back->error_register == state &&
                       back->manufacturer_data == emcy.manufacturer_data;
      }
      break;
    }
    case 11:
      if ((frame = EncodeHeartbeat({node_id, static_cast<NmtState>(state)}, &error))) {
        const auto back = DecodeHeartbeat(*frame, nullptr);
        decodes_back = back && back->node_id == node_id && static_cast<std::uint8_t>(back->state) == state;
      }
      break;
    default: {
      const SyncMessage sync{state % 2 == 0 ? std::nullopt : std::optional<int>(static_cast<std::int32_t>(value))};
      if ((frame = EncodeSync(sync, &error))) {
        const auto back = DecodeSync(*frame, nullptr);
        decodes_back = back && back->counter == sync.counter;
      }
      break;
    }
  }
  if (!frame) {
    FuzzCheck(!error.empty(), "a refused value comes with a reason");
    return;
  }
  FuzzCheck(can::CheckCanFrame(*frame).empty() && !frame->extended && !frame->remote && !frame->error,
            "an encoder makes a valid standard data frame");
  FuzzCheck(decodes_back, "an encoded value decodes back to itself");
}

}  // namespace
}  // namespace topay::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace topay::fuzz;
  FuzzReader in(data, size);
  while (!in.empty()) {
    if (in.Byte() % 2 == 0) {
      DecodeFrameRecord(in);
    } else {
      EncodeRecord(in);
    }
  }
  return 0;
}
