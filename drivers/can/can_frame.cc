#include "drivers/can/can_frame.h"

#include <cstdio>
#include <stdexcept>

namespace topay::can {
namespace {

std::string Hex(std::uint32_t value, int digits) {
  char text[16];
  std::snprintf(text, sizeof(text), "%0*X", digits, value);
  return text;
}

// Builds a data or remote frame, throwing std::invalid_argument when it is invalid.
CanFrame MakeChecked(const CanFrame& frame) {
  const std::string problem = CheckCanFrame(frame);
  if (!problem.empty()) throw std::invalid_argument("invalid CAN frame: " + problem);
  return frame;
}

CanFrame DataFrame(std::uint32_t id, bool extended, std::initializer_list<std::uint8_t> bytes) {
  if (bytes.size() > CanFrame::kMaxDlc) {
    throw std::invalid_argument("invalid CAN frame: " + std::to_string(bytes.size()) +
                                " data bytes, at most 8");
  }
  CanFrame frame;
  frame.id = id;
  frame.extended = extended;
  frame.dlc = static_cast<std::uint8_t>(bytes.size());
  int i = 0;
  for (const std::uint8_t byte : bytes) frame.data[i++] = byte;
  return MakeChecked(frame);
}

// Value of one hex digit, or -1.
int HexDigit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

bool Fail(std::string* error, std::string_view text, const std::string& message) {
  if (error != nullptr) *error = "'" + std::string(text) + "': " + message;
  return false;
}

// Parses the id part (before '#') into frame->id and its kind.
bool ParseId(std::string_view text, std::string_view id_text, CanFrame* frame, std::string* error) {
  if (id_text.size() != 3 && id_text.size() != 8) {
    return Fail(error, text, "the id must have 3 hex digits (standard) or 8 (extended), found " +
                                 std::to_string(id_text.size()));
  }
  std::uint32_t value = 0;
  for (const char c : id_text) {
    const int digit = HexDigit(c);
    if (digit < 0) return Fail(error, text, std::string("bad hex digit '") + c + "' in the id");
    value = value * 16 + static_cast<std::uint32_t>(digit);
  }
  if (id_text.size() == 3) {
    if (value > CanFrame::kMaxStandardId) {
      return Fail(error, text, "standard id 0x" + Hex(value, 3) + " is above 0x7FF");
    }
    frame->id = value;
    return true;
  }
  // 8 digits: an error frame if the error flag is set (candump's convention), else extended.
  if ((value & CAN_ERR_FLAG) != 0) {
    if ((value & ~(CAN_ERR_FLAG | CAN_ERR_MASK)) != 0) {
      return Fail(error, text, "error frame id 0x" + Hex(value, 8) + " has EFF/RTR flag bits set");
    }
    frame->error = true;
    frame->id = value & CAN_ERR_MASK;
    return true;
  }
  if (value > CanFrame::kMaxExtendedId) {
    return Fail(error, text, "extended id 0x" + Hex(value, 8) + " is above 0x1FFFFFFF");
  }
  frame->extended = true;
  frame->id = value;
  return true;
}

// Parses `R` or `R<len>` after the '#'.
bool ParseRemote(std::string_view text, std::string_view rest, CanFrame* frame, std::string* error) {
  if (frame->error) return Fail(error, text, "an error frame cannot be a remote frame (R)");
  frame->remote = true;
  if (rest.size() == 1) return true;
  if (rest.size() != 2 || rest[1] < '0' || rest[1] > '8') {
    return Fail(error, text, "a remote frame is 'R' or 'R' and one length digit 0-8, found '" +
                                 std::string(rest) + "'");
  }
  frame->dlc = static_cast<std::uint8_t>(rest[1] - '0');
  return true;
}

// Parses the data bytes after the '#': pairs of hex digits, optionally separated by '.'.
bool ParseData(std::string_view text, std::string_view rest, CanFrame* frame, std::string* error) {
  int count = 0;
  std::size_t i = 0;
  while (i < rest.size()) {
    if (rest[i] == '.') {
      ++i;
      continue;
    }
    if (i + 1 >= rest.size() || HexDigit(rest[i]) < 0 || HexDigit(rest[i + 1]) < 0) {
      return Fail(error, text, "data byte " + std::to_string(count) +
                                   " is not two hex digits (at '" + std::string(rest.substr(i)) + "')");
    }
    if (count == CanFrame::kMaxDlc) return Fail(error, text, "more than 8 data bytes");
    frame->data[count++] = static_cast<std::uint8_t>(HexDigit(rest[i]) * 16 + HexDigit(rest[i + 1]));
    i += 2;
  }
  frame->dlc = static_cast<std::uint8_t>(count);
  return true;
}

}  // namespace

CanFrame CanFrame::Standard(std::uint32_t id, std::initializer_list<std::uint8_t> bytes) {
  return DataFrame(id, false, bytes);
}

CanFrame CanFrame::Extended(std::uint32_t id, std::initializer_list<std::uint8_t> bytes) {
  return DataFrame(id, true, bytes);
}

CanFrame CanFrame::Remote(std::uint32_t id, int dlc, bool extended) {
  if (dlc < 0 || dlc > kMaxDlc) {
    throw std::invalid_argument("invalid CAN frame: DLC " + std::to_string(dlc) + " is outside 0..8");
  }
  CanFrame frame;
  frame.id = id;
  frame.extended = extended;
  frame.remote = true;
  frame.dlc = static_cast<std::uint8_t>(dlc);
  return MakeChecked(frame);
}

std::string CheckCanFrame(const CanFrame& frame) {
  if (frame.dlc > CanFrame::kMaxDlc) return "DLC " + std::to_string(frame.dlc) + " is above 8";
  if (frame.error) {
    if (frame.remote) return "an error frame cannot be a remote frame";
    if (frame.id > CAN_ERR_MASK) return "error class 0x" + Hex(frame.id, 8) + " is above 0x1FFFFFFF";
    return {};
  }
  if (frame.extended && frame.id > CanFrame::kMaxExtendedId) {
    return "extended id 0x" + Hex(frame.id, 8) + " is above 0x1FFFFFFF";
  }
  if (!frame.extended && frame.id > CanFrame::kMaxStandardId) {
    return "standard id 0x" + Hex(frame.id, 3) + " is above 0x7FF (use an extended id)";
  }
  return {};
}

bool operator==(const CanFrame& a, const CanFrame& b) {
  if (a.id != b.id || a.error != b.error || a.remote != b.remote || a.dlc != b.dlc) return false;
  if (!a.error && a.extended != b.extended) return false;
  if (a.remote) return true;
  for (int i = 0; i < a.dlc && i < CanFrame::kMaxDlc; ++i) {
    if (a.data[i] != b.data[i]) return false;
  }
  return true;
}

struct can_frame ToLinuxFrame(const CanFrame& frame) {
  const std::string problem = CheckCanFrame(frame);
  if (!problem.empty()) throw std::invalid_argument("invalid CAN frame: " + problem);
  struct can_frame out{};
  out.can_id = frame.id;
  if (frame.error) {
    out.can_id |= CAN_ERR_FLAG;
  } else {
    if (frame.extended) out.can_id |= CAN_EFF_FLAG;
    if (frame.remote) out.can_id |= CAN_RTR_FLAG;
  }
  out.len = frame.dlc;
  if (!frame.remote) {
    for (int i = 0; i < frame.dlc; ++i) out.data[i] = frame.data[i];
  }
  return out;
}

std::optional<CanFrame> FromLinuxFrame(const struct can_frame& in, std::string* error) {
  CanFrame frame;
  frame.error = (in.can_id & CAN_ERR_FLAG) != 0;
  frame.extended = !frame.error && (in.can_id & CAN_EFF_FLAG) != 0;
  frame.remote = (in.can_id & CAN_RTR_FLAG) != 0;
  frame.id = in.can_id & CAN_EFF_MASK;
  frame.dlc = in.len;
  if (frame.error && (in.can_id & CAN_EFF_FLAG) != 0) {
    if (error != nullptr) *error = "error frame with the EFF flag set";
    return std::nullopt;
  }
  const std::string problem = CheckCanFrame(frame);
  if (!problem.empty()) {
    if (error != nullptr) *error = problem;
    return std::nullopt;
  }
  if (!frame.remote) {
    for (int i = 0; i < frame.dlc; ++i) frame.data[i] = in.data[i];
  }
  return frame;
}

std::string ToString(const CanFrame& frame) {
  std::string text;
  if (frame.error) {
    text = Hex(frame.id | CAN_ERR_FLAG, 8);
  } else {
    text = frame.extended ? Hex(frame.id, 8) : Hex(frame.id, 3);
  }
  text += '#';
  if (frame.remote) {
    text += 'R';
    if (frame.dlc > 0) text += static_cast<char>('0' + frame.dlc);
    return text;
  }
  for (int i = 0; i < frame.dlc && i < CanFrame::kMaxDlc; ++i) text += Hex(frame.data[i], 2);
  return text;
}

std::optional<CanFrame> ParseCanFrame(std::string_view text, std::string* error) {
  const std::size_t hash = text.find('#');
  if (hash == std::string_view::npos) {
    Fail(error, text, "no '#' between the id and the data (expected e.g. 123#DEADBEEF)");
    return std::nullopt;
  }
  const std::string_view rest = text.substr(hash + 1);
  if (!rest.empty() && rest[0] == '#') {
    Fail(error, text, "CAN FD frames ('##') are not supported (classic CAN only)");
    return std::nullopt;
  }
  CanFrame frame;
  if (!ParseId(text, text.substr(0, hash), &frame, error)) return std::nullopt;
  const bool ok = (!rest.empty() && (rest[0] == 'R' || rest[0] == 'r'))
                      ? ParseRemote(text, rest, &frame, error)
                      : ParseData(text, rest, &frame, error);
  if (!ok) return std::nullopt;
  return frame;
}

}  // namespace topay::can
