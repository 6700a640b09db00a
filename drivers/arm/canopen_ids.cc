#include "drivers/arm/canopen_ids.h"

#include <array>
#include <cstdio>

namespace topay::canopen {
namespace {

struct FunctionRow {
  CanopenFunction function;
  std::uint32_t base;
  std::string_view name;
};

// CiA 301 Table 73 (predefined connection set), the part used here.
constexpr std::array<FunctionRow, 14> kFunctions{{
    {CanopenFunction::kNmt, 0x000, "NMT"},
    {CanopenFunction::kSync, 0x080, "SYNC"},
    {CanopenFunction::kEmcy, 0x080, "EMCY"},
    {CanopenFunction::kTpdo1, 0x180, "TPDO1"},
    {CanopenFunction::kRpdo1, 0x200, "RPDO1"},
    {CanopenFunction::kTpdo2, 0x280, "TPDO2"},
    {CanopenFunction::kRpdo2, 0x300, "RPDO2"},
    {CanopenFunction::kTpdo3, 0x380, "TPDO3"},
    {CanopenFunction::kRpdo3, 0x400, "RPDO3"},
    {CanopenFunction::kTpdo4, 0x480, "TPDO4"},
    {CanopenFunction::kRpdo4, 0x500, "RPDO4"},
    {CanopenFunction::kSdoTx, 0x580, "SDO tx"},
    {CanopenFunction::kSdoRx, 0x600, "SDO rx"},
    {CanopenFunction::kHeartbeat, 0x700, "heartbeat"},
}};

// For each of the 16 function bases (COB-ID >> 7), the row of kFunctions whose objects carry a
// node id there, or -1: ClassifyCobId looks a frame up instead of scanning the rows.
constexpr std::array<int, 16> MakeRowOfBase() {
  std::array<int, 16> rows{};
  rows.fill(-1);
  for (std::size_t i = 0; i < kFunctions.size(); ++i) {
    if (HasNodeId(kFunctions[i].function)) rows[kFunctions[i].base >> 7] = static_cast<int>(i);
  }
  return rows;
}
constexpr std::array<int, 16> kRowOfBase = MakeRowOfBase();

const FunctionRow& RowOf(CanopenFunction function) {
  for (const FunctionRow& row : kFunctions) {
    if (row.function == function) return row;
  }
  return kFunctions[0];  // unreachable: every enumerator has a row
}

std::string Hex(std::uint32_t value) {
  char text[16];
  std::snprintf(text, sizeof(text), "0x%03X", static_cast<unsigned>(value));
  return text;
}

}  // namespace

std::string_view ToString(CanopenFunction function) { return RowOf(function).name; }

std::uint32_t FunctionBaseCobId(CanopenFunction function) { return RowOf(function).base; }

std::string CheckNodeId(int node_id) {
  if (node_id >= kMinNodeId && node_id <= kMaxNodeId) return {};
  return "node id " + std::to_string(node_id) + " is outside 1..127";
}

std::optional<std::uint32_t> CobIdOf(CanopenFunction function, int node_id, std::string* error) {
  if (!HasNodeId(function)) return FunctionBaseCobId(function);
  const std::string problem = CheckNodeId(node_id);
  if (!problem.empty()) return Fail(error, std::string(ToString(function)) + ": " + problem);
  return FunctionBaseCobId(function) + static_cast<std::uint32_t>(node_id);
}

std::optional<CobIdClass> ClassifyCobId(std::uint32_t cob_id, std::string* error) {
  if (cob_id > can::CanFrame::kMaxStandardId) {
    if (error == nullptr) return std::nullopt;
    return Fail(error, "COB-ID " + Hex(cob_id) + " is above 0x7FF");
  }
  const int node_id = static_cast<int>(cob_id & 0x7F);
  if (cob_id == 0x000) return CobIdClass{CanopenFunction::kNmt, 0};
  if (cob_id == 0x080) return CobIdClass{CanopenFunction::kSync, 0};
  const int row = kRowOfBase[cob_id >> 7];
  if (row >= 0 && node_id != 0) return CobIdClass{kFunctions[static_cast<std::size_t>(row)].function, node_id};
  // The messages are built only when asked for: the bridge classifies every frame on the bus
  // once per drive, and most of them belong to another node.
  if (error == nullptr) return std::nullopt;
  if (row >= 0) {
    return Fail(error, "COB-ID " + Hex(cob_id) + " (" + std::string(kFunctions[static_cast<std::size_t>(row)].name) +
                           ") has node id 0, outside 1..127");
  }
  return Fail(error, "COB-ID " + Hex(cob_id) + " is not a CANopen object this stack uses");
}

std::string FrameError(std::string_view what, const can::CanFrame& frame,
                       std::string_view problem) {
  return std::string(what) + " frame '" + can::ToString(frame) + "': " + std::string(problem);
}

std::optional<int> CheckCanopenFrame(const can::CanFrame& frame, CanopenFunction function,
                                     int min_dlc, int max_dlc, std::string_view what,
                                     std::string* error) {
  if (frame.error) return Fail(error, FrameError(what, frame, "an error frame"));
  if (frame.extended) return Fail(error, FrameError(what, frame, "an extended (29-bit) id"));
  if (frame.remote) return Fail(error, FrameError(what, frame, "a remote (RTR) frame"));
  const std::string invalid = can::CheckCanFrame(frame);
  if (!invalid.empty()) return Fail(error, FrameError(what, frame, invalid));
  std::string id_error;
  const std::optional<CobIdClass> id = ClassifyCobId(frame.id, &id_error);
  if (!id) return Fail(error, FrameError(what, frame, id_error));
  if (id->function != function) {
    return Fail(error, FrameError(what, frame,
                                  "id " + Hex(frame.id) + " is " + std::string(ToString(id->function)) +
                                      ", expected " + std::string(ToString(function))));
  }
  if (frame.dlc < min_dlc || frame.dlc > max_dlc) {
    const std::string expected = min_dlc == max_dlc
                                     ? std::to_string(min_dlc)
                                     : std::to_string(min_dlc) + ".." + std::to_string(max_dlc);
    return Fail(error, FrameError(what, frame,
                                  "DLC " + std::to_string(frame.dlc) + ", expected " + expected));
  }
  return id->node_id;
}

}  // namespace topay::canopen
