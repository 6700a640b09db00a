#pragma once
// A strict MCAP reader for the tests only (https://mcap.dev/spec), written apart from
// procs/log_info/mcap_writer.cc: it reads a file record by record, the data section linearly
// (descending into chunks and their Message Index records) and the summary through the Footer,
// and throws McapFormatError on anything out of place: magic, record bounds, CRC32s (data
// section, chunks, summary), chunk times, Message Index entries, Chunk Index offsets and lengths,
// summary grouping and Summary Offsets, Statistics against what the data section holds.

#include <zlib.h>

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <map>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#if __has_include(<zstd.h>)
#include <zstd.h>
#define TOPAY_MCAP_TEST_ZSTD 1
#endif

namespace topay::loginfo::mcap_test {

class McapFormatError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct Schema {
  std::uint16_t id = 0;
  std::string name, encoding, data;
  bool operator==(const Schema&) const = default;
};

struct Channel {
  std::uint16_t id = 0, schema_id = 0;
  std::string topic, message_encoding;
  std::map<std::string, std::string> metadata;
  bool operator==(const Channel&) const = default;
};

struct Message {
  std::uint16_t channel_id = 0;
  std::uint32_t sequence = 0;
  std::uint64_t log_time = 0, publish_time = 0;
  std::string data;
  std::uint64_t chunk_offset = 0;  ///< file offset of its Chunk record, 0 outside chunks
};

/// A Chunk record with what follows it (its Message Index records), as found in the data section.
struct Chunk {
  std::uint64_t offset = 0, length = 0, start_time = 0, end_time = 0;
  std::uint64_t uncompressed_size = 0, compressed_size = 0, index_length = 0, messages = 0;
  std::string compression;
  std::map<std::uint16_t, std::uint64_t> index_offsets;  ///< channel -> Message Index record
  std::uint64_t records_offset = 0;  ///< file offset of the chunk's records field
};

struct ChunkIndex {
  std::uint64_t start_time = 0, end_time = 0, offset = 0, length = 0, index_length = 0;
  std::map<std::uint16_t, std::uint64_t> index_offsets;
  std::string compression;
  std::uint64_t compressed_size = 0, uncompressed_size = 0;
};

struct Statistics {
  std::uint64_t message_count = 0;
  std::uint16_t schema_count = 0;
  std::uint32_t channel_count = 0, attachment_count = 0, metadata_count = 0, chunk_count = 0;
  std::uint64_t start_time = 0, end_time = 0;
  std::map<std::uint16_t, std::uint64_t> channel_message_counts;
};

struct SummaryOffset {
  std::uint8_t opcode = 0;
  std::uint64_t start = 0, length = 0;
  auto operator<=>(const SummaryOffset&) const = default;
};

/// Everything a file holds, in file order.
struct McapContents {
  std::string profile, library;
  std::vector<Schema> schemas;    ///< data section (chunks included)
  std::vector<Channel> channels;  ///< data section (chunks included)
  std::vector<Message> messages;  ///< data section (chunks included)
  std::vector<Chunk> chunks;
  std::uint64_t data_end_offset = 0, summary_start = 0, summary_offset_start = 0;
  std::uint32_t data_section_crc = 0, summary_crc = 0;
  std::vector<Schema> summary_schemas;
  std::vector<Channel> summary_channels;
  std::vector<ChunkIndex> chunk_indexes;
  std::optional<Statistics> statistics;
  std::vector<SummaryOffset> summary_offsets;
};

namespace detail {

inline constexpr std::string_view kMagic("\x89MCAP0\r\n", 8);

inline std::uint32_t Crc(std::string_view bytes) {
  return static_cast<std::uint32_t>(
      crc32(0L, reinterpret_cast<const Bytef*>(bytes.data()), static_cast<uInt>(bytes.size())));
}

inline void Expect(bool ok, const std::string& what) {
  if (!ok) throw McapFormatError(what);
}

/// Little-endian fields of one record's content, bounds-checked.
class Cursor {
 public:
  Cursor(std::string_view bytes, std::string what) : bytes_(bytes), what_(std::move(what)) {}
  std::uint64_t Uint(int n) {
    const std::string_view b = Take(n);
    std::uint64_t v = 0;
    for (int i = n - 1; i >= 0; --i) v = (v << 8) | static_cast<unsigned char>(b[i]);
    return v;
  }
  std::uint8_t U8() { return static_cast<std::uint8_t>(Uint(1)); }
  std::uint16_t U16() { return static_cast<std::uint16_t>(Uint(2)); }
  std::uint32_t U32() { return static_cast<std::uint32_t>(Uint(4)); }
  std::uint64_t U64() { return Uint(8); }
  std::string_view Take(std::uint64_t n) {
    Expect(n <= bytes_.size() - at_, what_ + ": truncated at byte " + std::to_string(at_));
    const std::string_view out = bytes_.substr(at_, n);
    at_ += n;
    return out;
  }
  std::string String() { return std::string(Take(U32())); }
  Cursor Prefixed() { return Cursor(Take(U32()), what_); }  // Map or Array: uint32 byte length
  bool Done() const { return at_ == bytes_.size(); }
  void ExpectDone() { Expect(Done(), what_ + ": unexpected bytes at the end of the record"); }

 private:
  std::string_view bytes_;
  std::string what_;
  std::uint64_t at_ = 0;
};

struct Record {
  std::uint8_t opcode = 0;
  std::uint64_t offset = 0, end = 0;  ///< in the buffer it was read from
  std::string_view content;
};

/// `<opcode uint8><content length uint64><content>` at `at`, within `bytes`.
inline Record ReadRecord(std::string_view bytes, std::uint64_t at, const std::string& where) {
  Cursor c(bytes.substr(std::min<std::uint64_t>(at, bytes.size())), where + " record header");
  Record r;
  r.offset = at;
  r.opcode = c.U8();
  r.content = c.Take(c.U64());
  r.end = at + 9 + r.content.size();
  return r;
}

inline Schema ParseSchema(std::string_view content) {
  Cursor c(content, "Schema");
  Schema s;
  s.id = c.U16();
  s.name = c.String();
  s.encoding = c.String();
  s.data = c.String();
  c.ExpectDone();
  Expect(s.id != 0, "Schema with id 0");
  return s;
}

inline std::map<std::string, std::string> ParseStringMap(Cursor c) {
  std::map<std::string, std::string> out;
  while (!c.Done()) {
    std::string key = c.String();
    Expect(out.emplace(key, c.String()).second, "duplicate map key " + key);
  }
  return out;
}

inline std::map<std::uint16_t, std::uint64_t> ParseIdMap(Cursor c) {
  std::map<std::uint16_t, std::uint64_t> out;
  while (!c.Done()) {
    const std::uint16_t key = c.U16();
    Expect(out.emplace(key, c.U64()).second, "duplicate map key " + std::to_string(key));
  }
  return out;
}

inline Channel ParseChannel(std::string_view content) {
  Cursor c(content, "Channel");
  Channel ch;
  ch.id = c.U16();
  ch.schema_id = c.U16();
  ch.topic = c.String();
  ch.message_encoding = c.String();
  ch.metadata = ParseStringMap(c.Prefixed());
  c.ExpectDone();
  return ch;
}

inline Message ParseMessage(std::string_view content) {
  Cursor c(content, "Message");
  Message m;
  m.channel_id = c.U16();
  m.sequence = c.U32();
  m.log_time = c.U64();
  m.publish_time = c.U64();
  m.data = std::string(content.substr(22));
  return m;
}

/// The data section's definitions so far, by id: a message must follow its channel, a channel
/// its schema, and a repeated definition must be identical.
struct Definitions {
  std::map<std::uint16_t, Schema> schemas;
  std::map<std::uint16_t, Channel> channels;

  void Add(const Schema& s, McapContents* out) {
    const auto [it, added] = schemas.emplace(s.id, s);
    Expect(added || it->second == s, "Schema " + std::to_string(s.id) + " redefined differently");
    if (added) out->schemas.push_back(s);
  }
  void Add(const Channel& ch, McapContents* out) {
    Expect(ch.schema_id == 0 || schemas.count(ch.schema_id), "Channel before its schema");
    const auto [it, added] = channels.emplace(ch.id, ch);
    Expect(added || it->second == ch,
           "Channel " + std::to_string(ch.id) + " redefined differently");
    if (added) out->channels.push_back(ch);
  }
  void Check(const Message& m) const {
    Expect(channels.count(m.channel_id),
           "Message before its channel " + std::to_string(m.channel_id));
  }
};

inline std::string Decompress(std::string_view data, const std::string& compression,
                              std::uint64_t size) {
  if (compression.empty()) {
    Expect(data.size() == size, "uncompressed chunk: sizes differ");
    return std::string(data);
  }
#ifdef TOPAY_MCAP_TEST_ZSTD
  if (compression == "zstd") {
    std::string out(size, '\0');
    const std::size_t n = ZSTD_decompress(out.data(), out.size(), data.data(), data.size());
    Expect(!ZSTD_isError(n) && n == size, "zstd chunk does not decompress to its size");
    return out;
  }
#endif
  throw McapFormatError("unsupported chunk compression " + compression);
}

/// The chunk's Message Index records (right after it): every message indexed exactly once, at its
/// offset and log time, one record per channel.
inline std::uint64_t ReadMessageIndexes(std::string_view file, std::uint64_t at,
                                        const std::string& records,
                                        const std::map<std::uint64_t, Message>& by_offset,
                                        Chunk* chunk) {
  std::set<std::uint64_t> indexed;
  for (Record r; (r = ReadRecord(file, at, "Message Index")).opcode == 0x07; at = r.end) {
    Cursor c(r.content, "Message Index");
    const std::uint16_t channel = c.U16();
    Expect(chunk->index_offsets.emplace(channel, r.offset).second, "two indexes for a channel");
    for (Cursor e = c.Prefixed(); !e.Done();) {
      const std::uint64_t time = e.U64(), offset = e.U64();
      const auto it = by_offset.find(offset);
      Expect(it != by_offset.end() && offset < records.size(), "index entry not on a message");
      Expect(it->second.channel_id == channel && it->second.log_time == time,
             "index entry with the wrong channel or time");
      Expect(indexed.insert(offset).second, "message indexed twice");
    }
    c.ExpectDone();
  }
  Expect(indexed.size() == by_offset.size(), "messages missing from the chunk's Message Index");
  return at;
}

/// Spec "Chunk (op=0x06)" and the Message Index records after it; returns the offset after them.
inline std::uint64_t ReadChunk(std::string_view file, const Record& rec, Definitions* defs,
                               McapContents* out) {
  Cursor c(rec.content, "Chunk");
  Chunk chunk;
  chunk.offset = rec.offset;
  chunk.length = rec.end - rec.offset;
  chunk.start_time = c.U64();
  chunk.end_time = c.U64();
  chunk.uncompressed_size = c.U64();
  const std::uint32_t crc = c.U32();
  chunk.compression = c.String();
  const std::string_view data = c.Take(c.U64());
  c.ExpectDone();
  chunk.compressed_size = data.size();
  chunk.records_offset = rec.end - data.size();
  const std::string records = Decompress(data, chunk.compression, chunk.uncompressed_size);
  Expect(crc == 0 || crc == Crc(records), "chunk CRC mismatch at " + std::to_string(rec.offset));
  std::map<std::uint64_t, Message> by_offset;
  for (std::uint64_t at = 0; at < records.size();) {
    const Record r = ReadRecord(records, at, "chunk");
    if (r.opcode == 0x03) {
      defs->Add(ParseSchema(r.content), out);
    } else if (r.opcode == 0x04) {
      defs->Add(ParseChannel(r.content), out);
    } else {
      Expect(r.opcode == 0x05, "record " + std::to_string(r.opcode) + " inside a chunk");
      Message m = ParseMessage(r.content);
      defs->Check(m);
      m.chunk_offset = rec.offset;
      by_offset.emplace(at, m);
    }
    at = r.end;
  }
  std::uint64_t lo = UINT64_MAX, hi = 0;
  for (const auto& [offset, m] : by_offset) {
    lo = std::min(lo, m.log_time);
    hi = std::max(hi, m.log_time);
    out->messages.push_back(m);
  }
  if (by_offset.empty()) lo = 0;
  Expect(chunk.start_time == lo && chunk.end_time == hi, "chunk start/end times are not min/max");
  chunk.messages = by_offset.size();
  const std::uint64_t end = ReadMessageIndexes(file, rec.end, records, by_offset, &chunk);
  chunk.index_length = end - rec.end;
  out->chunks.push_back(chunk);
  return end;
}

/// The data section, after the Header, up to and including Data End (its CRC checked).
inline void ReadDataSection(std::string_view file, std::uint64_t at, McapContents* out) {
  Definitions defs;
  for (;;) {
    const Record r = ReadRecord(file, at, "data section");
    at = r.end;
    switch (r.opcode) {
      case 0x03:
        defs.Add(ParseSchema(r.content), out);
        break;
      case 0x04:
        defs.Add(ParseChannel(r.content), out);
        break;
      case 0x05:
        out->messages.push_back(ParseMessage(r.content));
        defs.Check(out->messages.back());
        break;
      case 0x06:
        at = ReadChunk(file, r, &defs, out);
        break;
      case 0x0F: {
        Cursor c(r.content, "Data End");
        out->data_section_crc = c.U32();
        c.ExpectDone();
        out->data_end_offset = r.offset;
        const std::uint32_t crc = Crc(file.substr(0, r.offset));
        Expect(out->data_section_crc == 0 || out->data_section_crc == crc,
               "data section CRC mismatch");
        return;
      }
      default:
        throw McapFormatError("record " + std::to_string(r.opcode) + " in the data section");
    }
  }
}

inline ChunkIndex ParseChunkIndex(std::string_view content) {
  Cursor c(content, "Chunk Index");
  ChunkIndex i;
  i.start_time = c.U64();
  i.end_time = c.U64();
  i.offset = c.U64();
  i.length = c.U64();
  i.index_offsets = ParseIdMap(c.Prefixed());
  i.index_length = c.U64();
  i.compression = c.String();
  i.compressed_size = c.U64();
  i.uncompressed_size = c.U64();
  c.ExpectDone();
  return i;
}

inline Statistics ParseStatistics(std::string_view content) {
  Cursor c(content, "Statistics");
  Statistics s;
  s.message_count = c.U64();
  s.schema_count = c.U16();
  s.channel_count = c.U32();
  s.attachment_count = c.U32();
  s.metadata_count = c.U32();
  s.chunk_count = c.U32();
  s.start_time = c.U64();
  s.end_time = c.U64();
  s.channel_message_counts = ParseIdMap(c.Prefixed());
  c.ExpectDone();
  return s;
}

/// The summary section [begin, end): records grouped by opcode; returns the groups found.
inline std::vector<SummaryOffset> ReadSummary(std::string_view file, std::uint64_t begin,
                                              std::uint64_t end, McapContents* out) {
  std::vector<SummaryOffset> groups;
  for (std::uint64_t at = begin; at < end;) {
    const Record r = ReadRecord(file.substr(0, end), at, "summary");
    if (groups.empty() || groups.back().opcode != r.opcode) {
      for (const SummaryOffset& g : groups) Expect(g.opcode != r.opcode, "summary not grouped");
      groups.push_back({r.opcode, r.offset, 0});
    }
    groups.back().length += r.end - r.offset;
    at = r.end;
    switch (r.opcode) {
      case 0x03:
        out->summary_schemas.push_back(ParseSchema(r.content));
        break;
      case 0x04:
        out->summary_channels.push_back(ParseChannel(r.content));
        break;
      case 0x08:
        out->chunk_indexes.push_back(ParseChunkIndex(r.content));
        break;
      case 0x0B:
        Expect(!out->statistics, "two Statistics records");
        out->statistics = ParseStatistics(r.content);
        break;
      default:
        throw McapFormatError("record " + std::to_string(r.opcode) + " in the summary");
    }
  }
  return groups;
}

/// Summary Offset records [begin, end).
inline void ReadSummaryOffsets(std::string_view file, std::uint64_t begin, std::uint64_t end,
                               McapContents* out) {
  for (std::uint64_t at = begin; at < end;) {
    const Record r = ReadRecord(file.substr(0, end), at, "summary offsets");
    Expect(r.opcode == 0x0E, "not a Summary Offset in the summary offset section");
    Cursor c(r.content, "Summary Offset");
    SummaryOffset s;
    s.opcode = c.U8();
    s.start = c.U64();
    s.length = c.U64();
    c.ExpectDone();
    out->summary_offsets.push_back(s);
    at = r.end;
  }
}

/// The summary against the data section: the same definitions, a Chunk Index per chunk that
/// matches it field by field, Statistics that count what is there.
inline void CrossCheck(const McapContents& f) {
  auto by_id = [](auto v) {
    std::sort(v.begin(), v.end(), [](const auto& a, const auto& b) { return a.id < b.id; });
    return v;
  };
  Expect(by_id(f.summary_schemas) == by_id(f.schemas), "summary schemas differ from the data's");
  Expect(by_id(f.summary_channels) == by_id(f.channels), "summary channels differ from the data's");
  Expect(f.chunk_indexes.size() == f.chunks.size(), "not one Chunk Index per chunk");
  for (std::size_t i = 0; i < f.chunks.size(); ++i) {
    const Chunk& c = f.chunks[i];
    const ChunkIndex& x = f.chunk_indexes[i];
    Expect(x.offset == c.offset && x.length == c.length && x.start_time == c.start_time &&
               x.end_time == c.end_time && x.index_offsets == c.index_offsets &&
               x.index_length == c.index_length && x.compression == c.compression &&
               x.compressed_size == c.compressed_size && x.uncompressed_size == c.uncompressed_size,
           "Chunk Index " + std::to_string(i) + " does not match its chunk");
  }
  if (!f.statistics) return;
  const Statistics& s = *f.statistics;
  std::map<std::uint16_t, std::uint64_t> counts;
  std::uint64_t lo = f.messages.empty() ? 0 : UINT64_MAX, hi = 0;
  for (const Message& m : f.messages) {
    ++counts[m.channel_id];
    lo = std::min(lo, m.log_time);
    hi = std::max(hi, m.log_time);
  }
  Expect(s.message_count == f.messages.size() && s.schema_count == f.schemas.size() &&
             s.channel_count == f.channels.size() && s.chunk_count == f.chunks.size() &&
             s.start_time == lo && s.end_time == hi &&
             (s.channel_message_counts.empty() || s.channel_message_counts == counts),
         "Statistics do not count what the file holds");
}

}  // namespace detail

/// Reads and checks a whole MCAP file from memory. Throws McapFormatError naming the first fault.
inline McapContents ParseMcap(std::string_view file) {
  using namespace detail;  // NOLINT(google-build-using-namespace): this function's own helpers
  constexpr std::uint64_t kFooterSize = 1 + 8 + 8 + 8 + 4;
  Expect(file.size() >= 2 * kMagic.size() + kFooterSize, "too short for MCAP");
  Expect(file.substr(0, 8) == kMagic, "bad leading magic");
  Expect(file.substr(file.size() - 8) == kMagic, "bad trailing magic");
  McapContents out;
  const Record header = ReadRecord(file, 8, "Header");
  Expect(header.opcode == 0x01, "the first record is not a Header");
  Cursor h(header.content, "Header");
  out.profile = h.String();
  out.library = h.String();
  h.ExpectDone();
  ReadDataSection(file, header.end, &out);
  const std::uint64_t footer_at = file.size() - 8 - kFooterSize;
  const Record footer = ReadRecord(file.substr(0, file.size() - 8), footer_at, "Footer");
  Expect(footer.opcode == 0x02 && footer.end == file.size() - 8, "no Footer before the magic");
  Cursor fc(footer.content, "Footer");
  out.summary_start = fc.U64();
  out.summary_offset_start = fc.U64();
  out.summary_crc = fc.U32();
  const std::uint64_t data_end = out.data_end_offset + 13;
  if (out.summary_start == 0) {
    Expect(out.summary_offset_start == 0 && data_end == footer_at, "stray bytes after Data End");
    return out;
  }
  Expect(out.summary_start == data_end, "summary_start is not right after Data End");
  const std::uint64_t offsets_at = out.summary_offset_start ? out.summary_offset_start : footer_at;
  Expect(offsets_at >= data_end && offsets_at <= footer_at, "summary_offset_start out of range");
  const std::uint32_t crc = Crc(file.substr(data_end, footer_at + 25 - data_end));
  Expect(out.summary_crc == 0 || out.summary_crc == crc, "summary CRC mismatch");
  std::vector<SummaryOffset> groups = ReadSummary(file, data_end, offsets_at, &out);
  ReadSummaryOffsets(file, offsets_at, footer_at, &out);
  std::vector<SummaryOffset> offsets = out.summary_offsets;
  std::sort(groups.begin(), groups.end());
  std::sort(offsets.begin(), offsets.end());
  Expect(offsets.empty() || offsets == groups, "Summary Offsets do not match the summary's groups");
  CrossCheck(out);
  return out;
}

/// Reads and checks a whole MCAP file. Throws McapFormatError naming the first fault (or the path
/// if it cannot be read).
inline McapContents ReadMcap(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw McapFormatError(path + ": cannot open");
  const std::string file((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return ParseMcap(file);
}

}  // namespace topay::loginfo::mcap_test
