// The text and datagram forms of CAN frames (drivers/can/): ParseCanFrame (cansend syntax),
// ParseCandumpLine and ReadCandumpLog (candump -l logs), DecodeUdpCanDatagram (the user-space
// bus), ParseCanUrl, FromLinuxFrame, and what a received frame goes through next (error frame
// decoding, the bus state, the frame's length on the wire). Checked: a refusal names why, with
// the same verdict without asking; what is accepted is valid and canonical forms round-trip:
// ParseCanFrame(ToString(f)) == f, FormatCandumpLine / ParseCandumpLine, a log written back and
// read again, a datagram encoded again (its reserved bytes aside), a URL's canonical text, a
// kernel frame converted back (its padding bytes aside).
//
// Input: [selector][rest of the input]; selector % 6 picks what reads the rest:
//   0 ParseCanFrame(text)      1 ParseCandumpLine(text)    2 ReadCandumpLog(text)
//   3 DecodeUdpCanDatagram(bytes); with selector bit 7 the first 5 bytes are made the magic and
//     version, so that mutations reach the frame
//   4 ParseCanUrl(text)        5 FromLinuxFrame(the first 16 bytes as a struct can_frame)
#include <linux/can/error.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "drivers/can/can_bus.h"
#include "drivers/can/can_error.h"
#include "drivers/can/can_frame.h"
#include "drivers/can/can_frame_bits.h"
#include "drivers/can/can_url.h"
#include "drivers/can/candump_log.h"
#include "drivers/can/udp_can_datagram.h"
#include "tests/fuzz/fuzz_check.h"
#include "tests/fuzz/fuzz_reader.h"

namespace topay::fuzz {
namespace {

template <class Parse>
auto ParseBothWays(Parse parse) {
  std::string error;
  auto parsed = parse(&error);
  FuzzCheck(parsed.has_value() || !error.empty(), "a refused input comes with a reason");
  FuzzCheck(parse(nullptr).has_value() == parsed.has_value(), "the verdict does not depend on the error string");
  return parsed;
}

bool SameRecord(const can::CandumpRecord& a, const can::CandumpRecord& b) {
  return a.timestamp_us == b.timestamp_us && a.interface == b.interface && a.frame == b.frame;
}

// What a valid frame from any source must satisfy, and what a receiver does with it next.
void CheckValidFrame(const can::CanFrame& frame) {
  FuzzCheck(can::CheckCanFrame(frame).empty(), "an accepted frame is valid");
  for (int i = frame.remote ? 0 : frame.dlc; i < can::CanFrame::kMaxDlc; ++i) {
    FuzzCheck(frame.data[i] == 0, "data bytes beyond the DLC (all of a remote frame's) are zero");
  }
  const std::string text = can::ToString(frame);
  const auto parsed = can::ParseCanFrame(text, nullptr);
  FuzzCheck(parsed && *parsed == frame, "ParseCanFrame(ToString(frame)) is the frame");
  FuzzCheck(can::ToString(*parsed) == text, "ToString is canonical");
  const auto back = can::FromLinuxFrame(can::ToLinuxFrame(frame), nullptr);
  FuzzCheck(back && *back == frame, "the kernel form converts back to the frame");
  const can::UdpCanDatagram datagram{0x12345678u, 42u, frame};
  const auto bytes = can::EncodeUdpCanDatagram(datagram);
  const auto decoded = can::DecodeUdpCanDatagram(bytes.data(), bytes.size(), nullptr);
  FuzzCheck(decoded && decoded->frame == frame && decoded->sender_id == datagram.sender_id &&
                decoded->sequence == datagram.sequence,
            "an encoded datagram decodes back");
  if (frame.error) {
    const can::CanErrorReport report = can::DecodeCanErrorFrame(frame);
    FuzzCheck(!report.description.empty(), "an error frame has a description");
    for (const auto state : {can::CanBusState::kErrorActive, can::CanBusState::kErrorWarning,
                             can::CanBusState::kErrorPassive, can::CanBusState::kBusOff}) {
      const can::CanBusState next = can::NextBusState(state, report);
      FuzzCheck(std::string(can::ToString(next)) != "unknown", "the next bus state is a state");
      if (report.bus_off) FuzzCheck(next == can::CanBusState::kBusOff, "a bus-off report gives bus-off");
    }
    can::CanBusStatus status;
    can::ApplyErrorFrame(frame, &status);
    FuzzCheck(status.error_frames == 1, "an error frame is counted");
    FuzzCheck(can::CanFrameLengthBits(frame) == 0, "an error frame has no bits on the wire");
  } else {
    FuzzCheck(can::DecodeCanErrorFrame(frame).description.empty(), "a data frame is no error report");
    const int bits = can::CanFrameLengthBits(frame);
    FuzzCheck(bits >= 47 && bits <= 160, "a frame is 47..160 bits on the wire");
  }
}

void CheckCanFrameText(const std::string& text) {
  const auto frame = ParseBothWays([&](std::string* e) { return can::ParseCanFrame(text, e); });
  if (frame) CheckValidFrame(*frame);
}

void CheckCandumpLine(const std::string& line) {
  const auto record = ParseBothWays([&](std::string* e) { return can::ParseCandumpLine(line, e); });
  if (!record) return;
  CheckValidFrame(record->frame);
  FuzzCheck(record->timestamp_us >= 0, "a timestamp is not negative");
  const std::string formatted = can::FormatCandumpLine(*record);  // must not throw
  const auto again = can::ParseCandumpLine(formatted, nullptr);
  FuzzCheck(again && SameRecord(*again, *record), "a formatted line parses back to the record");
  FuzzCheck(can::FormatCandumpLine(*again) == formatted, "the formatted line is canonical");
  std::istringstream in(line);
  std::vector<can::CandumpRecord> records;
  FuzzCheck(can::ReadCandumpLog(in, &records, nullptr) && records.size() == 1 && SameRecord(records[0], *record),
            "a line that parses is a log of that one record");
}

void CheckCandumpLog(const std::string& text) {
  std::istringstream in(text);
  std::vector<can::CandumpRecord> records;
  std::string error;
  const bool ok = can::ReadCandumpLog(in, &records, &error);
  if (!ok) FuzzCheck(error.rfind("line ", 0) == 0, "a refused log names the line");
  FuzzCheck(records.size() <= text.size() / 8 + 1, "no more records than lines");
  std::ostringstream out;
  can::CandumpLogWriter writer(out);
  for (const can::CandumpRecord& record : records) {
    CheckValidFrame(record.frame);
    writer.Write(record);
  }
  std::istringstream written(out.str());
  std::vector<can::CandumpRecord> again;
  FuzzCheck(can::ReadCandumpLog(written, &again, nullptr) && again.size() == records.size(),
            "a written log reads back");
  for (std::size_t i = 0; i < again.size(); ++i) {
    FuzzCheck(SameRecord(again[i], records[i]), "a written log reads back to the same records");
  }
}

void CheckDatagram(std::vector<std::uint8_t> bytes, bool fix_header) {
  if (fix_header && bytes.size() >= 5) {
    const std::uint8_t header[5] = {'T', 'C', 'A', 'N', can::kUdpCanDatagramVersion};
    std::copy(std::begin(header), std::end(header), bytes.begin());
  }
  const auto datagram = ParseBothWays([&](std::string* e) {
    return can::DecodeUdpCanDatagram(bytes.empty() ? nullptr : bytes.data(), bytes.size(), e);
  });
  if (!datagram) return;
  FuzzCheck(bytes.size() == can::kUdpCanDatagramBytes, "a datagram has 32 bytes");
  CheckValidFrame(datagram->frame);
  const auto again = can::EncodeUdpCanDatagram(*datagram);
  // Reserved bytes (5-7, 21-23) and data bytes beyond the length are not carried.
  for (std::size_t i = 0; i < 21; ++i) {
    if (i < 5 || i >= 8) FuzzCheck(again[i] == bytes[i], "a datagram encodes back to its header and frame id");
  }
  const int carried = datagram->frame.remote ? 0 : datagram->frame.dlc;
  for (int i = 0; i < carried; ++i) FuzzCheck(again[24 + i] == bytes[24 + i], "a datagram keeps its data bytes");
}

void CheckUrl(const std::string& text) {
  const auto url = ParseBothWays([&](std::string* e) { return can::ParseCanUrl(text, e); });
  if (!url) return;
  const std::string canonical = url->ToString();
  const auto again = can::ParseCanUrl(canonical, nullptr);
  FuzzCheck(again && again->scheme == url->scheme && again->interface == url->interface && again->group == url->group &&
                again->port == url->port,
            "a URL's canonical text parses back to it");
  FuzzCheck(again->ToString() == canonical, "the canonical text is canonical");
  if (url->scheme == can::CanUrl::Scheme::kUdp) {
    FuzzCheck(url->port >= 1, "a UDP port is 1-65535");
    FuzzCheck(!url->group.empty() && url->group.find_first_not_of("0123456789.") == std::string::npos,
              "a UDP group is a dotted quad");
  } else {
    FuzzCheck(!url->interface.empty() && url->interface.size() <= 15, "an interface name is 1-15 characters");
    for (const char c : url->interface) FuzzCheck(c > ' ' && c <= '~', "an interface name is printable");
  }
}

void CheckLinuxFrame(const std::vector<std::uint8_t>& bytes) {
  struct can_frame in {};
  if (!bytes.empty()) std::memcpy(&in, bytes.data(), std::min(bytes.size(), sizeof in));
  const auto frame = ParseBothWays([&](std::string* e) { return can::FromLinuxFrame(in, e); });
  if (!frame) return;
  CheckValidFrame(*frame);
  const struct can_frame out = can::ToLinuxFrame(*frame);
  FuzzCheck(out.can_id == in.can_id && out.len == in.len, "a kernel frame converts back to its id and length");
  const int carried = frame->remote ? 0 : frame->dlc;
  for (int i = 0; i < carried; ++i) FuzzCheck(out.data[i] == in.data[i], "a kernel frame keeps its data bytes");
}

}  // namespace
}  // namespace topay::fuzz

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace topay::fuzz;
  FuzzReader in(data, size);
  const std::uint8_t selector = in.Byte();
  const auto rest = in.Rest();
  const std::string text(reinterpret_cast<const char*>(rest.data()), rest.size());
  const std::vector<std::uint8_t> bytes(rest.begin(), rest.end());
  switch (selector % 6) {
    case 0:
      CheckCanFrameText(text);
      break;
    case 1:
      CheckCandumpLine(text);
      break;
    case 2:
      CheckCandumpLog(text);
      break;
    case 3:
      CheckDatagram(bytes, (selector & 0x80) != 0);
      break;
    case 4:
      CheckUrl(text);
      break;
    default:
      CheckLinuxFrame(bytes);
      break;
  }
  return 0;
}
