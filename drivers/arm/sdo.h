#pragma once
// Expedited SDO transfers (CiA 301 §7.2.4.3): the client (host) sends requests on 0x600 + node,
// the server (drive) answers on 0x580 + node; every frame has DLC 8: byte 0 the command
// specifier, bytes 1-2 the object index (little-endian), byte 3 the sub-index, bytes 4-7 data.
// Only expedited transfers (up to 4 data bytes) are supported; segmented and block transfers
// are rejected as such.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <variant>

#include "drivers/can/can_frame.h"

namespace topay::canopen {

/// Command specifier bytes (CiA 301 §7.2.4.3.3-.17; ccs/scs in bits 5-7, n in bits 2-3, e = bit 1,
/// s = bit 0).
namespace sdo_cs {
inline constexpr std::uint8_t kDownloadRequestBase = 0x23;  ///< ccs 1, e = s = 1, n = 0 (4 B).
inline constexpr std::uint8_t kDownloadResponse = 0x60;     ///< scs 3.
inline constexpr std::uint8_t kUploadRequest = 0x40;        ///< ccs 2.
inline constexpr std::uint8_t kUploadResponseBase = 0x43;   ///< scs 2, e = s = 1, n = 0 (4 B).
inline constexpr std::uint8_t kAbort = 0x80;                ///< cs 4, either direction.
}  // namespace sdo_cs

/// Common SDO abort codes (CiA 301 Table 22).
namespace sdo_abort {
inline constexpr std::uint32_t kToggleBitNotAlternated = 0x05030000;
inline constexpr std::uint32_t kTimedOut = 0x05040000;
inline constexpr std::uint32_t kInvalidCommandSpecifier = 0x05040001;
inline constexpr std::uint32_t kUnsupportedAccess = 0x06010000;
inline constexpr std::uint32_t kWriteOnly = 0x06010001;
inline constexpr std::uint32_t kReadOnly = 0x06010002;
inline constexpr std::uint32_t kObjectDoesNotExist = 0x06020000;
inline constexpr std::uint32_t kCannotBeMapped = 0x06040041;
inline constexpr std::uint32_t kPdoLengthExceeded = 0x06040042;
inline constexpr std::uint32_t kLengthMismatch = 0x06070010;
inline constexpr std::uint32_t kSubIndexDoesNotExist = 0x06090011;
inline constexpr std::uint32_t kValueRangeExceeded = 0x06090030;
inline constexpr std::uint32_t kGeneralError = 0x08000000;
inline constexpr std::uint32_t kCannotStoreLocalControl = 0x08000021;
inline constexpr std::uint32_t kCannotStoreDeviceState = 0x08000022;
}  // namespace sdo_abort

/// A short name of a known abort code ("object does not exist", ...), or "abort code 0x........".
std::string SdoAbortCodeName(std::uint32_t abort_code);

/// An object dictionary entry.
struct ObjectAddress {
  std::uint16_t index = 0;
  std::uint8_t subindex = 0;
};
bool operator==(const ObjectAddress& a, const ObjectAddress& b);

/// Expedited download (write) request, client -> server (0x600 + node).
struct SdoDownloadRequest {
  int node_id = 1;
  ObjectAddress address;
  int size_bytes = 4;       ///< 1..4.
  std::uint32_t value = 0;  ///< Must fit in size_bytes.
};
/// Download (write) confirmation, server -> client (0x580 + node).
struct SdoDownloadResponse {
  int node_id = 1;
  ObjectAddress address;
};
/// Upload (read) request, client -> server.
struct SdoUploadRequest {
  int node_id = 1;
  ObjectAddress address;
};
/// Expedited upload (read) response, server -> client.
struct SdoUploadResponse {
  int node_id = 1;
  ObjectAddress address;
  int size_bytes = 4;  ///< 1..4.
  std::uint32_t value = 0;
};
/// Abort transfer, either direction.
struct SdoAbort {
  int node_id = 1;
  ObjectAddress address;
  std::uint32_t abort_code = sdo_abort::kGeneralError;
};

/// Which way an SDO frame goes: requests (and the client's aborts) on 0x600 + node, responses
/// (and the server's aborts) on 0x580 + node.
enum class SdoChannel { kClientToServer, kServerToClient };

// Encoders: nullopt with *error for a node id outside 1..127, a size outside 1..4 or a value
// that does not fit in size_bytes.
std::optional<can::CanFrame> EncodeSdoDownloadRequest(const SdoDownloadRequest& request,
                                                      std::string* error);
std::optional<can::CanFrame> EncodeSdoDownloadResponse(const SdoDownloadResponse& response,
                                                       std::string* error);
std::optional<can::CanFrame> EncodeSdoUploadRequest(const SdoUploadRequest& request,
                                                    std::string* error);
std::optional<can::CanFrame> EncodeSdoUploadResponse(const SdoUploadResponse& response,
                                                     std::string* error);
std::optional<can::CanFrame> EncodeSdoAbort(const SdoAbort& abort, SdoChannel channel,
                                            std::string* error);

// Decoders: nullopt with *error naming the frame for the wrong id (direction), DLC other than
// 8, or a command specifier other than the expected one (e.g. a segmented transfer).
std::optional<SdoDownloadRequest> DecodeSdoDownloadRequest(const can::CanFrame& frame,
                                                           std::string* error);
std::optional<SdoDownloadResponse> DecodeSdoDownloadResponse(const can::CanFrame& frame,
                                                             std::string* error);
std::optional<SdoUploadRequest> DecodeSdoUploadRequest(const can::CanFrame& frame,
                                                       std::string* error);
std::optional<SdoUploadResponse> DecodeSdoUploadResponse(const can::CanFrame& frame,
                                                         std::string* error);
std::optional<SdoAbort> DecodeSdoAbort(const can::CanFrame& frame, SdoChannel channel,
                                       std::string* error);

/// What a server (drive) may answer: the bridge decodes a 0x580 + node frame with this.
using SdoServerReply = std::variant<SdoDownloadResponse, SdoUploadResponse, SdoAbort>;
std::optional<SdoServerReply> DecodeSdoServerReply(const can::CanFrame& frame,
                                                   std::string* error);

/// What a client (host) may send: the simulated drive decodes a 0x600 + node frame with this.
using SdoClientRequest = std::variant<SdoDownloadRequest, SdoUploadRequest, SdoAbort>;
std::optional<SdoClientRequest> DecodeSdoClientRequest(const can::CanFrame& frame,
                                                       std::string* error);

}  // namespace topay::canopen
