#include "procs/mapper/map_journal.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <utility>

#include "core/common/error.h"
#include "procs/msgs/map_receiver.h"
#include "topay_msgs/checked_decode.h"

namespace topay::mapper {
namespace {

constexpr std::size_t kLengthBytes = 4;

// One record: the length (little endian) and the message's LCM encoding.
std::vector<std::uint8_t> RecordOf(const map_update_t& msg) {
  const int size = msg.getEncodedSize();
  std::vector<std::uint8_t> record(kLengthBytes + static_cast<std::size_t>(size));
  const auto length = static_cast<std::uint32_t>(size);
  for (std::size_t i = 0; i < kLengthBytes; ++i) record[i] = static_cast<std::uint8_t>(length >> (8 * i));
  if (msg.encode(record.data() + kLengthBytes, 0, size) != size) {
    throw std::runtime_error("map journal: map_update_t did not encode");
  }
  return record;
}

std::string SystemError(const std::string& what, const std::string& path) {
  return "map journal " + path + ": " + what + ": " + std::strerror(errno);
}

void WriteAll(std::FILE* file, const std::vector<std::uint8_t>& record, const std::string& path) {
  if (std::fwrite(record.data(), 1, record.size(), file) != record.size() || std::fflush(file) != 0) {
    throw std::runtime_error(SystemError("cannot write", path));
  }
}

std::vector<std::uint8_t> ReadWholeFile(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) throw ConfigError(path, "", "the map journal is not a regular file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ConfigError(path, "", "cannot open the map journal");
  try {
    std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (in.bad()) throw ConfigError(path, "", "cannot read the map journal");
    return bytes;
  } catch (const std::ios_base::failure& e) {
    throw ConfigError(path, "", std::string("cannot read the map journal: ") + e.what());
  }
}

// The record at *offset (advanced past it); nullopt with *error set if it is torn or does not
// decode.
std::optional<map_update_t> NextRecord(const std::vector<std::uint8_t>& bytes, std::size_t* offset,
                                       std::string* error) {
  const std::size_t left = bytes.size() - *offset;
  if (left < kLengthBytes) {
    *error = "torn record length at byte " + std::to_string(*offset);
    return std::nullopt;
  }
  std::uint32_t length = 0;
  for (std::size_t i = 0; i < kLengthBytes; ++i) length |= std::uint32_t{bytes[*offset + i]} << (8 * i);
  if (length > left - kLengthBytes) {
    *error = "torn record at byte " + std::to_string(*offset) + " (" + std::to_string(length) + " bytes, " +
             std::to_string(left - kLengthBytes) + " left)";
    return std::nullopt;
  }
  std::string why;
  std::optional<map_update_t> msg = CheckedDecode<map_update_t>(bytes.data() + *offset + kLengthBytes, length, &why);
  if (!msg) {
    *error = "record at byte " + std::to_string(*offset) + ": " + why;
    return std::nullopt;
  }
  *offset += kLengthBytes + length;
  return msg;
}

}  // namespace

MapJournal::MapJournal(std::string path) : path_(std::move(path)) {}

MapJournal::~MapJournal() { Close(); }

MapJournal::MapJournal(MapJournal&& other) noexcept
    : path_(std::move(other.path_)), file_(std::exchange(other.file_, nullptr)), records_(other.records_) {}

void MapJournal::Close() {
  if (file_ != nullptr) std::fclose(file_);
  file_ = nullptr;
}

void MapJournal::Record(const map_update_t& msg) {
  if (!msg.is_full && file_ == nullptr) return;  // no full map to replay it on
  const std::vector<std::uint8_t> record = RecordOf(msg);
  if (msg.is_full) {
    StartWith(record);
  } else {
    Append(record);
  }
}

void MapJournal::StartWith(const std::vector<std::uint8_t>& record) {
  Close();
  records_ = 0;
  const std::string tmp = path_ + ".tmp";
  std::FILE* file = std::fopen(tmp.c_str(), "wb");
  if (file == nullptr) throw std::runtime_error(SystemError("cannot create", tmp));
  try {
    WriteAll(file, record, tmp);
  } catch (...) {
    std::fclose(file);
    throw;
  }
  if (std::rename(tmp.c_str(), path_.c_str()) != 0) {
    std::fclose(file);
    throw std::runtime_error(SystemError("cannot rename " + tmp + " to it", path_));
  }
  file_ = file;  // the renamed file: deltas go on after the full map
  records_ = 1;
}

void MapJournal::Append(const std::vector<std::uint8_t>& record) {
  try {
    WriteAll(file_, record, path_);
  } catch (...) {
    Close();  // a partial record may be in the file: nothing more until the next full map
    throw;
  }
  ++records_;
}

std::optional<JournaledMap> ReadMapJournal(const std::string& path, const msgs::MapCodecOptions& options) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec) && !ec) return std::nullopt;
  const std::vector<std::uint8_t> bytes = ReadWholeFile(path);
  msgs::MapReceiver receiver(options);
  JournaledMap map;
  std::size_t offset = 0;
  while (offset < bytes.size()) {
    std::string error;
    const std::size_t at = offset;
    const std::optional<map_update_t> msg = NextRecord(bytes, &offset, &error);
    const msgs::MapAcceptResult result = msg ? receiver.Accept(*msg) : msgs::MapAcceptResult{};
    const bool applied = msg && (result.outcome == msgs::MapUpdateOutcome::kSnapshotApplied ||
                                 (map.records > 0 && result.outcome == msgs::MapUpdateOutcome::kDeltaApplied));
    if (!applied) {
      if (error.empty()) error = "record at byte " + std::to_string(at) + " does not apply: " + result.reason;
      if (map.records == 0) throw ConfigError(path, "", "the map journal does not start with a full map: " + error);
      map.stopped_early = error;
      break;
    }
    ++map.records;
  }
  if (map.records == 0) throw ConfigError(path, "", "the map journal is empty");
  map.geometry = receiver.geometry();
  map.states.assign(receiver.states().begin(), receiver.states().end());
  map.utime = receiver.utime();
  return map;
}

}  // namespace topay::mapper
