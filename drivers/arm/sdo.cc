#include "drivers/arm/sdo.h"

#include <cstdio>

#include "drivers/can/little_endian.h"
#include "drivers/arm/canopen_ids.h"

namespace topay::canopen {
namespace {

constexpr std::string_view kSdoRx = "SDO request";
constexpr std::string_view kSdoTx = "SDO response";

std::string Hex(std::uint32_t value, int digits) {
  char text[16];
  std::snprintf(text, sizeof(text), "0x%0*X", digits, static_cast<unsigned>(value));
  return text;
}

// The client command specifier (ccs/scs) in bits 5-7 of byte 0.
int CommandOf(std::uint8_t byte0) { return byte0 >> 5; }

std::string CheckSize(int size_bytes, std::uint32_t value) {
  if (size_bytes < 1 || size_bytes > 4) {
    return "size " + std::to_string(size_bytes) + " bytes is outside 1..4 (expedited)";
  }
  if (size_bytes < 4 && (value >> (8 * size_bytes)) != 0) {
    return "value " + Hex(value, 8) + " does not fit in " + std::to_string(size_bytes) +
           " bytes";
  }
  return "";
}

// An 8-byte SDO frame: specifier, index, sub-index, and up to 4 data bytes.
std::optional<can::CanFrame> MakeSdoFrame(CanopenFunction function, int node_id,
                                          std::uint8_t specifier, ObjectAddress address,
                                          int size_bytes, std::uint32_t value,
                                          std::string* error) {
  const auto id = CobIdOf(function, node_id, error);
  if (!id) return std::nullopt;
  can::CanFrame frame = can::CanFrame::Standard(*id);
  frame.dlc = 8;
  frame.data[0] = specifier;
  can::PutLittleEndian(address.index, 2, 1, &frame.data);
  frame.data[3] = address.subindex;
  can::PutLittleEndian(value, size_bytes, 4, &frame.data);
  return frame;
}

ObjectAddress AddressOf(const can::CanFrame& frame) {
  return {static_cast<std::uint16_t>(can::GetLittleEndian(frame.data, 2, 1)), frame.data[3]};
}

std::string SpecifierProblem(std::uint8_t byte0, std::string_view expected) {
  return "command specifier " + Hex(byte0, 2) + " is not " + std::string(expected);
}

// The data size of an expedited transfer's specifier (e = 1); 4 when s = 0 (size not
// indicated); nullopt for a segmented transfer (e = 0).
std::optional<int> ExpeditedSize(std::uint8_t byte0) {
  if ((byte0 & 0x02) == 0) return std::nullopt;
  if ((byte0 & 0x01) == 0) return 4;
  return 4 - ((byte0 >> 2) & 0x03);
}

std::uint8_t ExpeditedSpecifier(int command, int size_bytes) {
  return static_cast<std::uint8_t>((command << 5) | ((4 - size_bytes) << 2) | 0x03);
}

std::uint32_t Masked(std::uint32_t value, int size_bytes) {
  return size_bytes >= 4 ? value : value & ((1u << (8 * size_bytes)) - 1);
}

// Decodes an expedited download request (ccs 1) or upload response (scs 2).
std::optional<std::pair<int, std::uint32_t>> DecodeExpeditedData(const can::CanFrame& frame,
                                                                 int command,
                                                                 std::string_view what,
                                                                 std::string* error) {
  const std::uint8_t byte0 = frame.data[0];
  const std::string expected = command == 1 ? "an expedited download request (0x2F/2B/27/23)"
                                            : "an expedited upload response (0x4F/4B/47/43)";
  if (CommandOf(byte0) != command || (byte0 & 0x10) != 0) {
    return Fail(error, FrameError(what, frame, SpecifierProblem(byte0, expected)));
  }
  const std::optional<int> size = ExpeditedSize(byte0);
  if (!size) {
    return Fail(error, FrameError(what, frame,
                                  SpecifierProblem(byte0, expected) +
                                      " (segmented transfers are not supported)"));
  }
  return std::make_pair(*size, Masked(can::GetLittleEndian(frame.data, 4, 4), *size));
}

}  // namespace

bool operator==(const ObjectAddress& a, const ObjectAddress& b) {
  return a.index == b.index && a.subindex == b.subindex;
}

std::string SdoAbortCodeName(std::uint32_t abort_code) {
  switch (abort_code) {
    case sdo_abort::kToggleBitNotAlternated: return "toggle bit not alternated";
    case sdo_abort::kTimedOut: return "SDO protocol timed out";
    case sdo_abort::kInvalidCommandSpecifier: return "invalid command specifier";
    case sdo_abort::kUnsupportedAccess: return "unsupported access to an object";
    case sdo_abort::kWriteOnly: return "attempt to read a write-only object";
    case sdo_abort::kReadOnly: return "attempt to write a read-only object";
    case sdo_abort::kObjectDoesNotExist: return "object does not exist";
    case sdo_abort::kCannotBeMapped: return "object cannot be mapped to the PDO";
    case sdo_abort::kPdoLengthExceeded: return "mapped objects exceed the PDO length";
    case sdo_abort::kLengthMismatch: return "data type length does not match";
    case sdo_abort::kSubIndexDoesNotExist: return "sub-index does not exist";
    case sdo_abort::kValueRangeExceeded: return "value range of parameter exceeded";
    case sdo_abort::kGeneralError: return "general error";
    case sdo_abort::kCannotStoreLocalControl:
      return "data cannot be transferred or stored (local control)";
    case sdo_abort::kCannotStoreDeviceState:
      return "data cannot be transferred or stored (device state)";
  }
  return "abort code " + Hex(abort_code, 8);
}

std::optional<can::CanFrame> EncodeSdoDownloadRequest(const SdoDownloadRequest& request,
                                                      std::string* error) {
  const std::string problem = CheckSize(request.size_bytes, request.value);
  if (!problem.empty()) return Fail(error, "SDO download request: " + problem);
  return MakeSdoFrame(CanopenFunction::kSdoRx, request.node_id,
                      ExpeditedSpecifier(1, request.size_bytes), request.address,
                      request.size_bytes, request.value, error);
}

std::optional<can::CanFrame> EncodeSdoDownloadResponse(const SdoDownloadResponse& response,
                                                       std::string* error) {
  return MakeSdoFrame(CanopenFunction::kSdoTx, response.node_id, sdo_cs::kDownloadResponse,
                      response.address, 0, 0, error);
}

std::optional<can::CanFrame> EncodeSdoUploadRequest(const SdoUploadRequest& request,
                                                    std::string* error) {
  return MakeSdoFrame(CanopenFunction::kSdoRx, request.node_id, sdo_cs::kUploadRequest,
                      request.address, 0, 0, error);
}

std::optional<can::CanFrame> EncodeSdoUploadResponse(const SdoUploadResponse& response,
                                                     std::string* error) {
  const std::string problem = CheckSize(response.size_bytes, response.value);
  if (!problem.empty()) return Fail(error, "SDO upload response: " + problem);
  return MakeSdoFrame(CanopenFunction::kSdoTx, response.node_id,
                      ExpeditedSpecifier(2, response.size_bytes), response.address,
                      response.size_bytes, response.value, error);
}

std::optional<can::CanFrame> EncodeSdoAbort(const SdoAbort& abort, SdoChannel channel,
                                            std::string* error) {
  const CanopenFunction function = channel == SdoChannel::kClientToServer
                                       ? CanopenFunction::kSdoRx
                                       : CanopenFunction::kSdoTx;
  return MakeSdoFrame(function, abort.node_id, sdo_cs::kAbort, abort.address, 4,
                      abort.abort_code, error);
}

std::optional<SdoDownloadRequest> DecodeSdoDownloadRequest(const can::CanFrame& frame,
                                                           std::string* error) {
  const auto node_id = CheckCanopenFrame(frame, CanopenFunction::kSdoRx, 8, 8, kSdoRx, error);
  if (!node_id) return std::nullopt;
  const auto data = DecodeExpeditedData(frame, 1, kSdoRx, error);
  if (!data) return std::nullopt;
  return SdoDownloadRequest{*node_id, AddressOf(frame), data->first, data->second};
}

std::optional<SdoDownloadResponse> DecodeSdoDownloadResponse(const can::CanFrame& frame,
                                                             std::string* error) {
  const auto node_id = CheckCanopenFrame(frame, CanopenFunction::kSdoTx, 8, 8, kSdoTx, error);
  if (!node_id) return std::nullopt;
  if (frame.data[0] != sdo_cs::kDownloadResponse) {
    return Fail(error, FrameError(kSdoTx, frame,
                                  SpecifierProblem(frame.data[0], "a download response (0x60)")));
  }
  return SdoDownloadResponse{*node_id, AddressOf(frame)};
}

std::optional<SdoUploadRequest> DecodeSdoUploadRequest(const can::CanFrame& frame,
                                                       std::string* error) {
  const auto node_id = CheckCanopenFrame(frame, CanopenFunction::kSdoRx, 8, 8, kSdoRx, error);
  if (!node_id) return std::nullopt;
  if (frame.data[0] != sdo_cs::kUploadRequest) {
    return Fail(error, FrameError(kSdoRx, frame,
                                  SpecifierProblem(frame.data[0], "an upload request (0x40)")));
  }
  return SdoUploadRequest{*node_id, AddressOf(frame)};
}

std::optional<SdoUploadResponse> DecodeSdoUploadResponse(const can::CanFrame& frame,
                                                         std::string* error) {
  const auto node_id = CheckCanopenFrame(frame, CanopenFunction::kSdoTx, 8, 8, kSdoTx, error);
  if (!node_id) return std::nullopt;
  const auto data = DecodeExpeditedData(frame, 2, kSdoTx, error);
  if (!data) return std::nullopt;
  return SdoUploadResponse{*node_id, AddressOf(frame), data->first, data->second};
}

std::optional<SdoAbort> DecodeSdoAbort(const can::CanFrame& frame, SdoChannel channel,
                                       std::string* error) {
  const bool to_server = channel == SdoChannel::kClientToServer;
  const std::string_view what = to_server ? kSdoRx : kSdoTx;
  const auto node_id = CheckCanopenFrame(
      frame, to_server ? CanopenFunction::kSdoRx : CanopenFunction::kSdoTx, 8, 8, what, error);
  if (!node_id) return std::nullopt;
  if (frame.data[0] != sdo_cs::kAbort) {
    return Fail(error,
                FrameError(what, frame, SpecifierProblem(frame.data[0], "an abort (0x80)")));
  }
  return SdoAbort{*node_id, AddressOf(frame), can::GetLittleEndian(frame.data, 4, 4)};
}

std::optional<SdoServerReply> DecodeSdoServerReply(const can::CanFrame& frame,
                                                   std::string* error) {
  if (!CheckCanopenFrame(frame, CanopenFunction::kSdoTx, 8, 8, kSdoTx, error)) {
    return std::nullopt;
  }
  switch (CommandOf(frame.data[0])) {
    case 3: if (auto r = DecodeSdoDownloadResponse(frame, error)) return *r; break;
    case 2: if (auto r = DecodeSdoUploadResponse(frame, error)) return *r; break;
    case 4: if (auto r = DecodeSdoAbort(frame, SdoChannel::kServerToClient, error)) return *r;
      break;
    default:
      return Fail(error, FrameError(kSdoTx, frame,
                                    SpecifierProblem(frame.data[0],
                                                     "a download or upload response or an "
                                                     "abort")));
  }
  return std::nullopt;
}

std::optional<SdoClientRequest> DecodeSdoClientRequest(const can::CanFrame& frame,
                                                       std::string* error) {
  if (!CheckCanopenFrame(frame, CanopenFunction::kSdoRx, 8, 8, kSdoRx, error)) {
    return std::nullopt;
  }
  switch (CommandOf(frame.data[0])) {
    case 1: if (auto r = DecodeSdoDownloadRequest(frame, error)) return *r; break;
    case 2: if (auto r = DecodeSdoUploadRequest(frame, error)) return *r; break;
    case 4: if (auto r = DecodeSdoAbort(frame, SdoChannel::kClientToServer, error)) return *r;
      break;
    default:
      return Fail(error, FrameError(kSdoRx, frame,
                                    SpecifierProblem(frame.data[0],
                                                     "a download or upload request or an "
                                                     "abort")));
  }
  return std::nullopt;
}

}  // namespace topay::canopen
