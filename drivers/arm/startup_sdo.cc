#include "drivers/arm/startup_sdo.h"

#include "drivers/arm/arm_pdo.h"
#include "drivers/arm/canopen_ids.h"

namespace topay::cia402 {
namespace {

using canopen::CanopenFunction;
using canopen::ObjectAddress;

constexpr std::uint32_t kPdoInvalid = 0x80000000u;  // COB-ID bit 31: PDO does not exist.
constexpr std::uint32_t kPdoNoRtr = 0x40000000u;    // COB-ID bit 30 (TPDO): no RTR allowed.
constexpr std::uint8_t kTransmissionSynchronous = 1;  // every SYNC (CiA 301 Table 71/72).

struct MappedObject {
  ObjectAddress address;
  int size_bits;
  std::string_view what;
};

struct PdoSpec {
  std::string_view name;
  CanopenFunction function;
  std::uint16_t communication_index;  // 0x1400+n (RPDO) / 0x1800+n (TPDO)
  bool is_transmit;
  std::vector<MappedObject> objects;   // empty: leave the PDO invalid
  std::uint8_t transmission_type = kTransmissionSynchronous;  // 1..240: every n-th SYNC
  std::optional<std::uint16_t> event_timer_ms;  // sub 5 (an RPDO's deadline), when written
};

void Add(std::vector<SdoWrite>* writes, std::uint16_t index, std::uint8_t subindex,
         std::uint32_t value, int size_bytes, std::string_view what) {
  writes->push_back(SdoWrite{ObjectAddress{index, subindex}, value, size_bytes, what});
}

void AddPdo(const PdoSpec& pdo, int node_id, std::vector<SdoWrite>* writes) {
  const std::uint32_t cob_id =
      canopen::FunctionBaseCobId(pdo.function) + static_cast<std::uint32_t>(node_id);
  const std::uint32_t flags = pdo.is_transmit ? kPdoNoRtr : 0;
  const std::uint16_t comm = pdo.communication_index;
  const auto mapping = static_cast<std::uint16_t>(comm + 0x200);  // 0x1600 / 0x1A00
  Add(writes, comm, 1, cob_id | flags | kPdoInvalid, 4, "invalidate the PDO (COB-ID bit 31)");
  if (pdo.objects.empty()) return;
  Add(writes, mapping, 0, 0, 1, "clear the mapping");
  std::uint8_t sub = 1;
  for (const MappedObject& object : pdo.objects) {
    Add(writes, mapping, sub++, PdoMappingEntry(object.address, object.size_bits), 4,
        object.what);
  }
  Add(writes, mapping, 0, static_cast<std::uint32_t>(pdo.objects.size()), 1,
      "number of mapped objects");
  Add(writes, comm, 2, pdo.transmission_type, 1,
      pdo.transmission_type == kTransmissionSynchronous ? "transmission type: synchronous, every SYNC"
                                                        : "transmission type: synchronous, every n-th SYNC");
  if (pdo.event_timer_ms) {
    Add(writes, comm, 5, *pdo.event_timer_ms, 2, "event timer: the RPDO's deadline (ms, 0: none)");
  }
  Add(writes, comm, 1, cob_id | flags, 4, "make the PDO valid with its default COB-ID");
}

std::vector<PdoSpec> PdoLayout(const StartupOptions& options) {
  std::vector<PdoSpec> layout;
  layout.push_back({"RPDO1", CanopenFunction::kRpdo1, 0x1400, false,
                    {{object::kControlword, 16, "RPDO1 map: controlword 0x6040"},
                     {object::kTargetVelocity, 32, "RPDO1 map: target velocity 0x60FF"}},
                    kTransmissionSynchronous,
                    static_cast<std::uint16_t>(options.rpdo_deadline_ms)});
  PdoSpec rpdo2{"RPDO2", CanopenFunction::kRpdo2, 0x1401, false, {}};
  if (options.map_target_position) {
    rpdo2.objects = {{object::kTargetPosition, 32, "RPDO2 map: target position 0x607A"}};
  }
  layout.push_back(rpdo2);
  layout.push_back({"RPDO3", CanopenFunction::kRpdo3, 0x1402, false, {}});
  layout.push_back({"RPDO4", CanopenFunction::kRpdo4, 0x1403, false, {}});
  layout.push_back({"TPDO1", CanopenFunction::kTpdo1, 0x1800, true,
                    {{object::kStatusword, 16, "TPDO1 map: statusword 0x6041"},
                     {object::kPositionActual, 32, "TPDO1 map: position actual 0x6064"}}});
  layout.push_back({"TPDO2", CanopenFunction::kTpdo2, 0x1801, true,
                    {{object::kVelocityActual, 32, "TPDO2 map: velocity actual 0x606C"}},
                    static_cast<std::uint8_t>(options.tpdo2_every_n_syncs)});
  layout.push_back({"TPDO3", CanopenFunction::kTpdo3, 0x1802, true, {}});
  layout.push_back({"TPDO4", CanopenFunction::kTpdo4, 0x1803, true, {}});
  return layout;
}

std::string CheckOptions(int node_id, const StartupOptions& options) {
  std::string problem = canopen::CheckNodeId(node_id);
  if (!problem.empty()) return "drive " + problem;
  problem = canopen::CheckNodeId(options.host_node_id);
  if (!problem.empty()) return "host " + problem;
  if (node_id == options.host_node_id) return "the drive and the host share node id " +
                                              std::to_string(node_id);
  for (int ms : {options.producer_heartbeat_ms, options.consumer_heartbeat_ms}) {
    if (ms < 0 || ms > 0xFFFF) return "heartbeat time " + std::to_string(ms) +
                                      " ms is outside 0..65535";
  }
  if (options.rpdo_deadline_ms < 0 || options.rpdo_deadline_ms > 0xFFFF) {
    return "RPDO deadline " + std::to_string(options.rpdo_deadline_ms) + " ms is outside 0..65535";
  }
  if (options.tpdo2_every_n_syncs < 1 || options.tpdo2_every_n_syncs > 240) {
    return "TPDO2 every " + std::to_string(options.tpdo2_every_n_syncs) + " SYNCs is outside 1..240";
  }
  if (options.sync_period_ms < 1 || options.sync_period_ms > 255) {
    return "SYNC period " + std::to_string(options.sync_period_ms) + " ms is outside 1..255";
  }
  const int m = options.mode_of_operation;
  if (m != mode::kProfileVelocity && m != mode::kCyclicSynchronousVelocity &&
      m != mode::kCyclicSynchronousPosition) {
    return "mode of operation " + std::to_string(m) + " is not 3, 8 or 9";
  }
  if (m == mode::kCyclicSynchronousPosition && !options.map_target_position) {
    return "mode 8 (cyclic synchronous position) needs map_target_position";
  }
  return "";
}

}  // namespace

std::uint32_t PdoMappingEntry(ObjectAddress address, int size_bits) {
  return (static_cast<std::uint32_t>(address.index) << 16) |
         (static_cast<std::uint32_t>(address.subindex) << 8) |
         static_cast<std::uint32_t>(size_bits & 0xFF);
}

std::optional<std::vector<SdoWrite>> StartupSdoWrites(int node_id, const StartupOptions& options,
                                                      std::string* error) {
  const std::string problem = CheckOptions(node_id, options);
  if (!problem.empty()) return canopen::Fail(error, "start-up SDO writes: " + problem);
  std::vector<SdoWrite> writes;
  for (const PdoSpec& pdo : PdoLayout(options)) {
    AddPdo(pdo, node_id, &writes);
  }
  Add(&writes, 0x1017, 0, static_cast<std::uint32_t>(options.producer_heartbeat_ms), 2,
      "producer heartbeat time (ms)");
  Add(&writes, 0x1016, 1,
      (static_cast<std::uint32_t>(options.host_node_id) << 16) |
          static_cast<std::uint32_t>(options.consumer_heartbeat_ms),
      4, "consumer heartbeat time: host node << 16 | ms");
  Add(&writes, 0x60C2, 1, static_cast<std::uint32_t>(options.sync_period_ms), 1,
      "interpolation time period value (ms)");
  Add(&writes, 0x60C2, 2, static_cast<std::uint8_t>(std::int8_t{-3}), 1,
      "interpolation time index: 10^-3 s");
  Add(&writes, object::kModesOfOperation.index, 0,
      static_cast<std::uint8_t>(options.mode_of_operation), 1, "mode of operation");
  return writes;
}

canopen::SdoDownloadRequest ToDownloadRequest(int node_id, const SdoWrite& write) {
  return canopen::SdoDownloadRequest{node_id, write.address, write.size_bytes, write.value};
}

}  // namespace topay::cia402
