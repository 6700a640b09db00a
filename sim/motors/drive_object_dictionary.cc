#include "sim/motors/drive_object_dictionary.h"

#include <utility>
#include <vector>

#include "drivers/arm/arm_pdo.h"
#include "drivers/arm/startup_sdo.h"

namespace topay::sim::motors {
namespace {

using canopen::ObjectAddress;
namespace abort = canopen::sdo_abort;

constexpr std::uint32_t kInvalidBit = 0x80000000u;
constexpr std::uint32_t kNoRtrBit = 0x40000000u;
constexpr std::uint32_t kCiA402Servo = 0x00020192u;  // 0x1000: CiA 402, servo drive

std::uint32_t Entry(ObjectAddress a, int bits) { return cia402::PdoMappingEntry(a, bits); }

// The one layout this drive implements per PDO (mapping index -> entries).
std::vector<std::uint32_t> Layout(std::uint16_t map_index) {
  switch (map_index) {
    case 0x1600: return {Entry(cia402::object::kControlword, 16), Entry(cia402::object::kTargetVelocity, 32)};
    case 0x1601: return {Entry(cia402::object::kTargetPosition, 32)};
    case 0x1A00: return {Entry(cia402::object::kStatusword, 16), Entry(cia402::object::kPositionActual, 32)};
    case 0x1A01: return {Entry(cia402::object::kVelocityActual, 32)};
    default: return {};
  }
}

bool Mappable(std::uint32_t entry) {
  for (std::uint16_t map : {0x1600, 0x1601, 0x1A00, 0x1A01}) {
    for (std::uint32_t e : Layout(map)) {
      if (e == entry) return true;
    }
  }
  return false;
}

bool IsCommunication(std::uint16_t index) {
  return (index >= 0x1400 && index <= 0x1403) || (index >= 0x1800 && index <= 0x1803);
}
bool IsMapping(std::uint16_t index) {
  return (index >= 0x1600 && index <= 0x1603) || (index >= 0x1A00 && index <= 0x1A03);
}

std::uint16_t CommIndexOf(Pdo pdo) {
  switch (pdo) {
    case Pdo::kRpdo1: return 0x1400;
    case Pdo::kRpdo2: return 0x1401;
    case Pdo::kTpdo1: return 0x1800;
    case Pdo::kTpdo2: return 0x1801;
  }
  return 0x1400;
}

// The default COB-ID (predefined connection set) of communication index `comm` for `node`.
std::uint32_t DefaultCobId(std::uint16_t comm, int node) {
  const bool transmit = comm >= 0x1800;
  const std::uint32_t n = comm - (transmit ? 0x1800u : 0x1400u);  // 0..3
  const std::uint32_t base = (transmit ? 0x180u : 0x200u) + 0x100u * n;
  return base + static_cast<std::uint32_t>(node);
}

}  // namespace

DriveObjectDictionary::DriveObjectDictionary(int node_id, int producer_heartbeat_ms)
    : node_id_(node_id), power_on_producer_heartbeat_ms_(producer_heartbeat_ms) {
  using A = ObjectAccess;
  Add(0x1000, 0, 4, A::kReadOnly, kCiA402Servo);
  Add(0x1001, 0, 1, A::kReadOnly, 0);
  Add(0x1016, 0, 1, A::kReadOnly, 1);
  Add(0x1016, 1, 4, A::kReadWrite, 0);
  Add(0x1017, 0, 2, A::kReadWrite, static_cast<std::uint32_t>(producer_heartbeat_ms));
  Add(0x1018, 0, 1, A::kReadOnly, 1);
  Add(0x1018, 1, 4, A::kReadOnly, 0);  // vendor id: none (a simulator)
  AddPdo(0x1400, DefaultCobId(0x1400, node_id), true, {Layout(0x1600)[0], Layout(0x1600)[1]});
  AddPdo(0x1401, DefaultCobId(0x1401, node_id), false, {});
  AddPdo(0x1402, DefaultCobId(0x1402, node_id), false, {});
  AddPdo(0x1403, DefaultCobId(0x1403, node_id), false, {});
  AddPdo(0x1800, DefaultCobId(0x1800, node_id) | kNoRtrBit, true, {Layout(0x1A00)[0], Layout(0x1A00)[1]});
  AddPdo(0x1801, DefaultCobId(0x1801, node_id) | kNoRtrBit, true, {Layout(0x1A01)[0]});
  AddPdo(0x1802, DefaultCobId(0x1802, node_id) | kNoRtrBit, false, {});
  AddPdo(0x1803, DefaultCobId(0x1803, node_id) | kNoRtrBit, false, {});
  Add(0x603F, 0, 2, A::kReadOnly, 0);   // error code
  Add(0x6040, 0, 2, A::kReadWrite, 0);  // controlword
  Add(0x6041, 0, 2, A::kReadOnly, 0);   // statusword
  Add(0x6060, 0, 1, A::kReadWrite, static_cast<std::uint8_t>(cia402::mode::kCyclicSynchronousVelocity));
  Add(0x6061, 0, 1, A::kReadOnly, static_cast<std::uint8_t>(cia402::mode::kCyclicSynchronousVelocity));
  Add(0x6064, 0, 4, A::kReadOnly, 0);   // position actual
  Add(0x606C, 0, 4, A::kReadOnly, 0);   // velocity actual
  Add(0x607A, 0, 4, A::kReadWrite, 0);  // target position
  Add(0x60C2, 0, 1, A::kReadOnly, 2);
  Add(0x60C2, 1, 1, A::kReadWrite, 10);
  Add(0x60C2, 2, 1, A::kReadWrite, static_cast<std::uint8_t>(std::int8_t{-3}));
  Add(0x60FF, 0, 4, A::kReadWrite, 0);  // target velocity
}

void DriveObjectDictionary::Add(std::uint16_t index, std::uint8_t sub, int size, ObjectAccess access,
                                std::uint32_t value) {
  objects_[{index, sub}] = ObjectEntry{size, access, value};
}

void DriveObjectDictionary::AddPdo(std::uint16_t comm, std::uint32_t cob_id, bool valid,
                                   std::initializer_list<std::uint32_t> mapping) {
  Add(comm, 0, 1, ObjectAccess::kReadOnly, 5);  // the highest sub-index: 5 (3 and 4 not implemented)
  Add(comm, 1, 4, ObjectAccess::kReadWrite, valid ? cob_id : cob_id | kInvalidBit);
  Add(comm, 2, 1, ObjectAccess::kReadWrite, 1);  // synchronous, every SYNC
  Add(comm, 5, 2, ObjectAccess::kReadWrite, 0);  // event timer, ms: an RPDO's deadline (0: none)
  const auto map = static_cast<std::uint16_t>(comm + 0x200);
  Add(map, 0, 1, ObjectAccess::kReadWrite, static_cast<std::uint32_t>(mapping.size()));
  for (std::uint8_t sub = 1; sub <= 8; ++sub) Add(map, sub, 4, ObjectAccess::kReadWrite, 0);
  std::uint8_t sub = 1;
  for (std::uint32_t entry : mapping) objects_[{map, sub++}].value = entry;
}

std::uint32_t DriveObjectDictionary::Write(ObjectAddress address, int size_bytes, std::uint32_t value) {
  const auto it = objects_.find(KeyOf(address));
  if (it == objects_.end()) {
    const bool index_known = objects_.lower_bound({address.index, 0}) != objects_.end() &&
                             objects_.lower_bound({address.index, 0})->first.first == address.index;
    return index_known ? abort::kSubIndexDoesNotExist : abort::kObjectDoesNotExist;
  }
  if (it->second.access == ObjectAccess::kReadOnly) return abort::kReadOnly;
  if (size_bytes != it->second.size_bytes) return abort::kLengthMismatch;
  if (const std::uint32_t code = CheckWrite(address, value); code != 0) return code;
  it->second.value = value;
  if (address.index == 0x6060) Set({0x6061, 0}, value);  // the mode takes effect at once
  return 0;
}

std::uint32_t DriveObjectDictionary::CheckWrite(ObjectAddress address, std::uint32_t value) const {
  if (IsCommunication(address.index)) return CheckCommunication(address.index, address.subindex, value);
  if (IsMapping(address.index)) return CheckMapping(address.index, address.subindex, value);
  if (address.index == 0x6060) {
    const auto mode = static_cast<std::int8_t>(value & 0xFF);
    // Only the velocity modes are simulated (both act as cyclic synchronous velocity).
    if (mode != cia402::mode::kCyclicSynchronousVelocity && mode != cia402::mode::kProfileVelocity) {
      return abort::kValueRangeExceeded;
    }
  }
  if (address.index == 0x60C2 && address.subindex == 1 && value == 0) return abort::kValueRangeExceeded;
  return 0;
}

std::uint32_t DriveObjectDictionary::CheckCommunication(std::uint16_t comm, std::uint8_t sub,
                                                        std::uint32_t value) const {
  if (sub == 2) return value <= 240 || value >= 252 ? 0 : abort::kValueRangeExceeded;
  if (sub == 5) return 0;  // any event timer (uint16; the size was checked)
  // sub 1, the COB-ID: the predefined connection set's only (no remapping of ids).
  if ((value & 0x7FFu) != DefaultCobId(comm, node_id_) || (value & 0x3FFFF800u) != 0) {
    return abort::kValueRangeExceeded;
  }
  const bool making_valid = (value & kInvalidBit) == 0;
  if (!making_valid) return 0;
  const auto map = static_cast<std::uint16_t>(comm + 0x200);
  const std::vector<std::uint32_t> layout = Layout(map);
  if (layout.empty() || Get({map, 0}) != layout.size()) return abort::kCannotBeMapped;
  for (std::size_t i = 0; i < layout.size(); ++i) {
    if (Get({map, static_cast<std::uint8_t>(i + 1)}) != layout[i]) return abort::kCannotBeMapped;
  }
  return 0;
}

std::uint32_t DriveObjectDictionary::CheckMapping(std::uint16_t map, std::uint8_t sub, std::uint32_t value) const {
  const auto comm = static_cast<std::uint16_t>(map - 0x200);
  if ((Get({comm, 1}) & kInvalidBit) == 0) return abort::kUnsupportedAccess;  // invalidate the PDO first
  if (sub == 0) {
    if (value > 8) return abort::kValueRangeExceeded;
    int bits = 0;
    for (std::uint8_t i = 1; i <= value; ++i) bits += static_cast<int>(Get({map, i}) & 0xFF);
    return bits > 64 ? abort::kPdoLengthExceeded : 0;
  }
  if (Get({map, 0}) != 0) return abort::kUnsupportedAccess;  // sub 0 = 0 before the entries change
  return Mappable(value) ? 0 : abort::kCannotBeMapped;
}

std::uint32_t DriveObjectDictionary::Read(ObjectAddress address, ObjectEntry* entry) const {
  const auto it = objects_.find(KeyOf(address));
  if (it == objects_.end()) return abort::kObjectDoesNotExist;
  *entry = it->second;
  return 0;
}

void DriveObjectDictionary::Set(ObjectAddress address, std::uint32_t value) { objects_[KeyOf(address)].value = value; }

std::uint32_t DriveObjectDictionary::Get(ObjectAddress address) const {
  const auto it = objects_.find(KeyOf(address));
  return it == objects_.end() ? 0 : it->second.value;
}

void DriveObjectDictionary::ResetCommunicationArea() {
  DriveObjectDictionary power_on(node_id_, power_on_producer_heartbeat_ms_);
  for (const auto& [key, entry] : objects_) {
    if (key.first >= 0x2000 || key == Key{0x1001, 0}) power_on.objects_[key] = entry;
  }
  objects_ = std::move(power_on.objects_);
}

bool DriveObjectDictionary::PdoValid(Pdo pdo) const { return (Get({CommIndexOf(pdo), 1}) & kInvalidBit) == 0; }

}  // namespace topay::sim::motors
