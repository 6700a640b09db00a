#pragma once
// The object dictionary of a simulated arm drive (docs/motorsim.md, "Drives"): the CANopen and
// CiA 402 objects the host reads or writes over SDO (docs/cia402.md's start-up list and the
// process data), each with its size, access and power-on value, and the rules a write must
// pass (size, access, value range, and this drive's one PDO layout: the robot's RPDO1/2 and
// TPDO1/2 of drivers/arm/arm_pdo.h, with the CiA 301 mapping procedure: a PDO is invalidated
// before its mapping changes, and becomes valid only with the layout the drive implements).

#include <cstdint>
#include <map>
#include <optional>
#include <utility>

#include "drivers/arm/sdo.h"

namespace topay::sim::motors {

enum class ObjectAccess { kReadOnly, kReadWrite };

struct ObjectEntry {
  int size_bytes = 4;  ///< 1, 2 or 4
  ObjectAccess access = ObjectAccess::kReadWrite;
  std::uint32_t value = 0;
};

/// Index of the four PDOs this stack uses, and whether each is valid (COB-ID bit 31 clear).
enum class Pdo { kRpdo1, kRpdo2, kTpdo1, kTpdo2 };

class DriveObjectDictionary {
 public:
  /// The power-on values for `node_id`: RPDO1, TPDO1, TPDO2 valid with the robot's mapping
  /// (RPDO2 and the PDOs 3/4 invalid), producer heartbeat `producer_heartbeat_ms`, no consumer
  /// heartbeat, mode of operation 9 (cyclic synchronous velocity).
  DriveObjectDictionary(int node_id, int producer_heartbeat_ms);

  /// An SDO download: 0 when written, else the abort code (object does not exist, read only,
  /// length mismatch, value range exceeded, cannot be mapped, unsupported access).
  std::uint32_t Write(canopen::ObjectAddress address, int size_bytes, std::uint32_t value);
  /// An SDO upload: the entry, or the abort code.
  std::uint32_t Read(canopen::ObjectAddress address, ObjectEntry* entry) const;

  /// The drive's own updates of read-only objects (statusword, actual values, error register).
  void Set(canopen::ObjectAddress address, std::uint32_t value);
  std::uint32_t Get(canopen::ObjectAddress address) const;

  /// NMT reset communication (CiA 301 §7.3.2.2.3): every object of the communication profile
  /// area (0x1000-0x1FFF) back to its power-on value; the rest kept (the error code 0x603F of a
  /// fault still present among them), and the error register 0x1001 too, which shows the
  /// errors present, not a setting.
  void ResetCommunicationArea();

  bool PdoValid(Pdo pdo) const;
  /// Producer heartbeat time 0x1017, ms (0: none).
  int producer_heartbeat_ms() const { return static_cast<int>(Get({0x1017, 0})); }
  /// Consumer heartbeat 0x1016:01: the host node id and its time, ms (0: none).
  int consumer_node_id() const { return static_cast<int>((Get({0x1016, 1}) >> 16) & 0x7F); }
  int consumer_heartbeat_ms() const { return static_cast<int>(Get({0x1016, 1}) & 0xFFFF); }
  /// RPDO1's deadline, its event timer 0x1400:05 (CiA 301 §7.5.2.35), ms (0: not monitored).
  int rpdo1_deadline_ms() const { return static_cast<int>(Get({0x1400, 5})); }

 private:
  using Key = std::pair<std::uint16_t, std::uint8_t>;
  static Key KeyOf(canopen::ObjectAddress a) { return {a.index, a.subindex}; }
  void Add(std::uint16_t index, std::uint8_t sub, int size, ObjectAccess access, std::uint32_t value);
  void AddPdo(std::uint16_t comm_index, std::uint32_t cob_id, bool valid, std::initializer_list<std::uint32_t> mapping);
  std::uint32_t CheckWrite(canopen::ObjectAddress address, std::uint32_t value) const;
  std::uint32_t CheckCommunication(std::uint16_t comm_index, std::uint8_t sub, std::uint32_t value) const;
  std::uint32_t CheckMapping(std::uint16_t map_index, std::uint8_t sub, std::uint32_t value) const;

  int node_id_;
  int power_on_producer_heartbeat_ms_;
  std::map<Key, ObjectEntry> objects_;
};

}  // namespace topay::sim::motors
