#include "drivers/can/candump_log.h"

#include <net/if.h>

#include <cinttypes>
#include <cstdio>
#include <stdexcept>

namespace topay::can {
namespace {

bool Fail(std::string* error, const std::string& message) {
  if (error != nullptr) *error = message;
  return false;
}

// Empty when `name` is a usable interface name, else what is wrong.
std::string CheckInterface(std::string_view name) {
  if (name.empty()) return "empty interface name";
  if (name.size() >= IFNAMSIZ) {
    return "interface name '" + std::string(name) + "' is longer than " + std::to_string(IFNAMSIZ - 1);
  }
  for (const char c : name) {
    if (c <= ' ' || c > '~') return "interface name '" + std::string(name) + "' has a bad character";
  }
  return "";
}

// Splits `line` at runs of spaces/tabs.
std::vector<std::string_view> Fields(std::string_view line) {
  std::vector<std::string_view> fields;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    const std::size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t') ++i;
    if (i > start) fields.push_back(line.substr(start, i - start));
  }
  return fields;
}

bool AllDigits(std::string_view text) {
  if (text.empty()) return false;
  for (const char c : text) {
    if (c < '0' || c > '9') return false;
  }
  return true;
}

// "(SECONDS.MICROSECONDS)" -> microseconds.
bool ParseTimestamp(std::string_view text, std::int64_t* timestamp_us, std::string* error) {
  const std::string problem =
      "timestamp '" + std::string(text) + "' must be (SECONDS.MICROSECONDS) with 6 decimals";
  if (text.size() < 3 || text.front() != '(' || text.back() != ')') return Fail(error, problem);
  const std::string_view inner = text.substr(1, text.size() - 2);
  const std::size_t dot = inner.find('.');
  if (dot == std::string_view::npos) return Fail(error, problem);
  const std::string_view seconds = inner.substr(0, dot);
  const std::string_view micros = inner.substr(dot + 1);
  if (!AllDigits(seconds) || micros.size() != 6 || !AllDigits(micros)) return Fail(error, problem);
  if (seconds.size() > 12) return Fail(error, "timestamp '" + std::string(text) + "' is too large");
  *timestamp_us = std::stoll(std::string(seconds)) * 1'000'000 + std::stoll(std::string(micros));
  return true;
}

}  // namespace

std::string FormatCandumpLine(const CandumpRecord& record) {
  if (record.timestamp_us < 0) {
    throw std::invalid_argument("candump line: negative timestamp " + std::to_string(record.timestamp_us) + " us");
  }
  const std::string interface_problem = CheckInterface(record.interface);
  if (!interface_problem.empty()) throw std::invalid_argument("candump line: " + interface_problem);
  const std::string frame_problem = CheckCanFrame(record.frame);
  if (!frame_problem.empty()) throw std::invalid_argument("candump line: invalid frame: " + frame_problem);
  char stamp[48];
  std::snprintf(stamp, sizeof(stamp), "(%010" PRId64 ".%06" PRId64 ")", record.timestamp_us / 1'000'000,
                record.timestamp_us % 1'000'000);
  return std::string(stamp) + " " + record.interface + " " + ToString(record.frame);
}

std::optional<CandumpRecord> ParseCandumpLine(std::string_view line, std::string* error) {
  const std::vector<std::string_view> fields = Fields(line);
  const bool direction = fields.size() == 4 && (fields[3] == "T" || fields[3] == "R");
  if (fields.size() != 3 && !direction) {
    Fail(error, "expected '(SECONDS.MICROSECONDS) IFACE FRAME', found " + std::to_string(fields.size()) +
                    " fields");
    return std::nullopt;
  }
  CandumpRecord record;
  if (!ParseTimestamp(fields[0], &record.timestamp_us, error)) return std::nullopt;
  const std::string interface_problem = CheckInterface(fields[1]);
  if (!interface_problem.empty()) {
    Fail(error, interface_problem);
    return std::nullopt;
  }
  record.interface = std::string(fields[1]);
  std::string why;
  const std::optional<CanFrame> frame = ParseCanFrame(fields[2], &why);
  if (!frame) {
    Fail(error, "frame " + why);
    return std::nullopt;
  }
  record.frame = *frame;
  return record;
}

void CandumpLogWriter::Write(const CandumpRecord& record) { out_ << FormatCandumpLine(record) << '\n'; }

void CandumpLogWriter::Write(std::int64_t timestamp_ns, const std::string& interface, const CanFrame& frame) {
  Write(CandumpRecord{timestamp_ns / 1000, interface, frame});
}

bool ReadCandumpLog(std::istream& in, std::vector<CandumpRecord>* records, std::string* error) {
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (Fields(line).empty()) continue;
    std::string why;
    std::optional<CandumpRecord> record = ParseCandumpLine(line, &why);
    if (!record) return Fail(error, "line " + std::to_string(number) + ": " + why);
    records->push_back(std::move(*record));
  }
  return true;
}

}  // namespace topay::can
