#include "procs/log_info/mcap_writer.h"

#include <zlib.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <limits>
#include <stdexcept>

#ifdef TOPAY_HAVE_ZSTD
#include <zstd.h>
#endif

namespace topay::loginfo {
namespace {

// Spec "Magic": 0x89 M C A P, the major version '0', \r \n; at the start and the end of the file.
constexpr std::string_view kMagic("\x89MCAP0\r\n", 8);

// Spec "Records": one opcode byte per record type.
enum Opcode : std::uint8_t {
  kHeader = 0x01,
  kFooter = 0x02,
  kSchema = 0x03,
  kChannel = 0x04,
  kMessage = 0x05,
  kChunk = 0x06,
  kMessageIndex = 0x07,
  kChunkIndex = 0x08,
  kStatistics = 0x0B,
  kSummaryOffset = 0x0E,
  kDataEnd = 0x0F,
};

// A Message record's bytes besides its data: opcode, length, channel, sequence, two times.
constexpr std::uint64_t kMessageOverhead = 1 + 8 + 2 + 4 + 8 + 8;

// Spec "Serialization": fixed-width integers are little-endian.
void PutLe(std::string* out, std::uint64_t value, int bytes) {
  for (int i = 0; i < bytes; ++i) out->push_back(static_cast<char>((value >> (8 * i)) & 0xFF));
}
void Put8(std::string* out, std::uint8_t v) { PutLe(out, v, 1); }
void Put16(std::string* out, std::uint16_t v) { PutLe(out, v, 2); }
void Put32(std::string* out, std::uint32_t v) { PutLe(out, v, 4); }
void Put64(std::string* out, std::uint64_t v) { PutLe(out, v, 8); }

std::uint32_t Length32(std::size_t size, const char* what) {
  if (size > std::numeric_limits<std::uint32_t>::max()) {
    throw std::length_error(std::string("mcap: ") + what + " longer than 4 GiB");
  }
  return static_cast<std::uint32_t>(size);
}

// Spec "String": uint32 byte length, then the UTF-8 bytes (also "uint32 length-prefixed Bytes").
void PutString(std::string* out, std::string_view s) {
  Put32(out, Length32(s.size(), "string"));
  out->append(s);
}

// Spec "Map<K, V>" and "Array<T>": a uint32 byte length, then the entries. Returns where the
// length goes, for EndPrefixed.
std::size_t BeginPrefixed(std::string* out) {
  Put32(out, 0);
  return out->size();
}
void EndPrefixed(std::string* out, std::size_t body_start) {
  const std::uint32_t length = Length32(out->size() - body_start, "map or array");
  for (int i = 0; i < 4; ++i)
    (*out)[body_start - 4 + i] = static_cast<char>((length >> (8 * i)) & 0xFF);
}

// Spec "Records": <opcode uint8><content length uint64><content>.
void PutRecord(std::string* out, Opcode opcode, std::string_view content) {
  Put8(out, opcode);
  Put64(out, content.size());
  out->append(content);
}

// zlib's crc32 (the CRC-32 of the spec), continued over `bytes`; uInt lengths, so in pieces.
std::uint32_t Crc32(std::uint32_t crc, std::string_view bytes) {
  uLong value = crc;
  constexpr std::size_t kPiece = 1u << 30;
  for (std::size_t at = 0; at < bytes.size(); at += kPiece) {
    const std::size_t n = std::min(kPiece, bytes.size() - at);
    value = crc32(value, reinterpret_cast<const Bytef*>(bytes.data() + at), static_cast<uInt>(n));
  }
  return static_cast<std::uint32_t>(value);
}

// Spec "Message (op=0x05)": channel_id uint16, sequence uint32, log_time and publish_time
// Timestamp (uint64 ns), data Bytes (the rest of the record).
void PutMessage(std::string* out, std::uint16_t channel, std::uint32_t sequence,
                std::uint64_t log_time, std::uint64_t publish_time, std::string_view data) {
  Put8(out, kMessage);
  Put64(out, kMessageOverhead - 9 + data.size());
  Put16(out, channel);
  Put32(out, sequence);
  Put64(out, log_time);
  Put64(out, publish_time);
  out->append(data);
}

// Spec "Message Index (op=0x07)": channel_id uint16, records Array<Tuple<Timestamp, uint64>>
// (log time, offset of the Message record in the uncompressed chunk records), sorted by time.
std::string MessageIndexRecord(std::uint16_t channel,
                               std::vector<std::pair<std::uint64_t, std::uint64_t>> entries) {
  std::stable_sort(entries.begin(), entries.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });
  std::string content;
  Put16(&content, channel);
  const std::size_t body = BeginPrefixed(&content);
  for (const auto& [time, offset] : entries) {
    Put64(&content, time);
    Put64(&content, offset);
  }
  EndPrefixed(&content, body);
  std::string record;
  PutRecord(&record, kMessageIndex, content);
  return record;
}

// Spec "Summary Offset (op=0x0E)": group_opcode uint8, group_start uint64, group_length uint64.
std::string SummaryOffsetRecord(std::uint8_t opcode, std::uint64_t start, std::uint64_t length) {
  std::string content;
  Put8(&content, opcode);
  Put64(&content, start);
  Put64(&content, length);
  std::string record;
  PutRecord(&record, kSummaryOffset, content);
  return record;
}

// The chunk's records, zstd-compressed when asked and built with libzstd; `compression` names it.
std::string_view Compress(const std::string& records, bool wanted, std::string* buffer,
                          std::string* compression) {
  compression->clear();
#ifdef TOPAY_HAVE_ZSTD
  if (wanted) {
    buffer->resize(ZSTD_compressBound(records.size()));
    const std::size_t n =
        ZSTD_compress(buffer->data(), buffer->size(), records.data(), records.size(), 3);
    if (ZSTD_isError(n))
      throw std::runtime_error(std::string("mcap: zstd: ") + ZSTD_getErrorName(n));
    buffer->resize(n);
    *compression = "zstd";
    return *buffer;
  }
#else
  (void)wanted;
  (void)buffer;
#endif
  return records;
}

}  // namespace

McapWriter::McapWriter(const std::string& path, McapWriterOptions options)
    : path_(path), options_(std::move(options)) {
  file_.open(path, std::ios::binary | std::ios::trunc);
  if (!file_)
    throw std::runtime_error(path + ": cannot open for writing (" + std::strerror(errno) + ")");
  // Spec "Header (op=0x01)": profile String, library String; right after the leading magic.
  std::string start(kMagic);
  std::string header;
  PutString(&header, options_.profile);
  PutString(&header, options_.library);
  PutRecord(&start, kHeader, header);
  WriteRaw(start);
}

McapWriter::~McapWriter() {
  try {
    Close();
  } catch (...) {  // NOLINT(bugprone-empty-catch): a destructor must not throw; Close() reports
  }
}

bool McapWriter::CompressionAvailable() {
#ifdef TOPAY_HAVE_ZSTD
  return true;
#else
  return false;
#endif
}

std::uint16_t McapWriter::AddSchema(const std::string& name, const std::string& encoding,
                                    const std::string& data) {
  CheckOpen();
  if (schemas_.size() >= std::numeric_limits<std::uint16_t>::max()) {
    throw std::length_error("mcap: more than 65535 schemas");
  }
  schemas_.push_back({name, encoding, data});
  return static_cast<std::uint16_t>(schemas_.size());
}

std::uint16_t McapWriter::AddChannel(std::uint16_t schema_id, const std::string& topic,
                                     const std::string& message_encoding,
                                     const std::map<std::string, std::string>& metadata) {
  CheckOpen();
  if (schema_id > schemas_.size()) {
    throw std::invalid_argument("mcap: channel " + topic + ": unknown schema id " +
                                std::to_string(schema_id));
  }
  if (channels_.size() >= std::numeric_limits<std::uint16_t>::max()) {
    throw std::length_error("mcap: more than 65535 channels");
  }
  channels_.push_back({schema_id, topic, message_encoding, metadata});
  return static_cast<std::uint16_t>(channels_.size());
}

void McapWriter::WriteMessage(std::uint16_t channel_id, std::uint32_t sequence,
                              std::uint64_t log_time_ns, std::uint64_t publish_time_ns,
                              std::string_view data) {
  CheckOpen();
  if (channel_id == 0 || channel_id > channels_.size()) {
    throw std::invalid_argument("mcap: unknown channel id " + std::to_string(channel_id));
  }
  const bool chunked = options_.chunk_size_bytes > 0;
  // A message that would take the open chunk past its target starts a new one.
  if (chunked &&
      chunk_.records.size() + kMessageOverhead + data.size() > options_.chunk_size_bytes) {
    FlushChunk();
  }
  std::string direct;  // the records for the data section when not chunked
  std::string* out = chunked ? &chunk_.records : &direct;
  EnsureDefinitions(channel_id, out);
  if (chunked) {
    chunk_.index[channel_id].emplace_back(log_time_ns, chunk_.records.size());
    chunk_.start_time =
        chunk_.messages == 0 ? log_time_ns : std::min(chunk_.start_time, log_time_ns);
    chunk_.end_time = chunk_.messages == 0 ? log_time_ns : std::max(chunk_.end_time, log_time_ns);
    ++chunk_.messages;
  }
  PutMessage(out, channel_id, sequence, log_time_ns, publish_time_ns, data);
  start_time_ = messages_ == 0 ? log_time_ns : std::min(start_time_, log_time_ns);
  end_time_ = messages_ == 0 ? log_time_ns : std::max(end_time_, log_time_ns);
  ++messages_;
  ++channel_counts_[channel_id];
  if (!chunked) {
    WriteRaw(direct);
  } else if (chunk_.records.size() >= options_.chunk_size_bytes) {
    FlushChunk();
  }
}

void McapWriter::Close() {
  if (closed_) return;
  closed_ = true;  // even if what follows throws: the destructor must not write again
  FlushChunk();
  WriteUnusedDefinitions();
  // Spec "Data End (op=0x0F)": data_section_crc uint32, the CRC32 of every byte before this record
  // (leading magic and Header included).
  std::string data_end;
  std::string crc;
  Put32(&crc, section_crc_);
  PutRecord(&data_end, kDataEnd, crc);
  WriteRaw(data_end);
  WriteSummary();
  file_.close();
  if (!file_) throw std::runtime_error(path_ + ": cannot close the MCAP file");
}

McapWriterStats McapWriter::stats() const { return {messages_, chunk_indexes_.size(), offset_}; }

void McapWriter::CheckOpen() const {
  if (closed_) throw std::invalid_argument("mcap: " + path_ + " is already closed");
}

void McapWriter::WriteRaw(std::string_view bytes) {
  file_.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (!file_) throw std::runtime_error(path_ + ": cannot write the MCAP file");
  offset_ += bytes.size();
  section_crc_ = Crc32(section_crc_, bytes);
}

void McapWriter::EnsureDefinitions(std::uint16_t channel_id, std::string* out) {
  Channel& channel = channels_[channel_id - 1];
  if (channel.written) return;
  if (channel.schema_id != 0 && !schemas_[channel.schema_id - 1].written) {
    *out += SchemaRecord(channel.schema_id);
    schemas_[channel.schema_id - 1].written = true;
  }
  *out += ChannelRecord(channel_id);
  channel.written = true;
}

// Spec "Chunk (op=0x06)": message_start_time, message_end_time (Timestamp), uncompressed_size
// uint64, uncompressed_crc uint32, compression String, records (uint64 length-prefixed Bytes);
// then one Message Index record per channel in the chunk.
void McapWriter::FlushChunk() {
  if (chunk_.records.empty()) return;
  ChunkIndex index;
  index.offset = offset_;
  index.start_time = chunk_.start_time;
  index.end_time = chunk_.end_time;
  index.uncompressed_size = chunk_.records.size();
  std::string buffer;
  const std::string_view payload =
      Compress(chunk_.records, options_.compress_chunks, &buffer, &index.compression);
  index.compressed_size = payload.size();
  std::string head;
  Put8(&head, kChunk);
  Put64(&head, 8 + 8 + 8 + 4 + 4 + index.compression.size() + 8 + payload.size());
  Put64(&head, chunk_.start_time);
  Put64(&head, chunk_.end_time);
  Put64(&head, chunk_.records.size());
  Put32(&head, Crc32(0, chunk_.records));
  PutString(&head, index.compression);
  Put64(&head, payload.size());
  WriteRaw(head);
  WriteRaw(payload);
  index.length = offset_ - index.offset;
  const std::uint64_t index_start = offset_;
  for (auto& [channel, entries] : chunk_.index) {
    index.index_offsets[channel] = offset_;
    WriteRaw(MessageIndexRecord(channel, std::move(entries)));
  }
  index.index_length = offset_ - index_start;
  chunk_indexes_.push_back(std::move(index));
  chunk_ = OpenChunk{};
}

// Schemas and channels without messages still go to the data section (and the summary).
void McapWriter::WriteUnusedDefinitions() {
  for (std::size_t i = 0; i < schemas_.size(); ++i) {
    if (!schemas_[i].written) WriteRaw(SchemaRecord(static_cast<std::uint16_t>(i + 1)));
    schemas_[i].written = true;
  }
  for (std::size_t i = 0; i < channels_.size(); ++i) {
    if (!channels_[i].written) WriteRaw(ChannelRecord(static_cast<std::uint16_t>(i + 1)));
    channels_[i].written = true;
  }
}

// Spec "Summary Section": records grouped by opcode (Schema, Channel, Statistics, Chunk Index),
// then "Summary Offset Section" (one Summary Offset per group), the Footer and the magic.
void McapWriter::WriteSummary() {
  const std::uint64_t summary_start = offset_;
  section_crc_ = 0;  // the summary CRC starts here
  std::string offsets;
  auto group = [&](Opcode opcode, const std::string& records) {
    if (records.empty()) return;
    offsets += SummaryOffsetRecord(opcode, offset_, records.size());
    WriteRaw(records);
  };
  std::string records;
  for (std::size_t i = 0; i < schemas_.size(); ++i) {
    records += SchemaRecord(static_cast<std::uint16_t>(i + 1));
  }
  group(kSchema, records);
  records.clear();
  for (std::size_t i = 0; i < channels_.size(); ++i) {
    records += ChannelRecord(static_cast<std::uint16_t>(i + 1));
  }
  group(kChannel, records);
  group(kStatistics, StatisticsRecord());
  records.clear();
  for (const ChunkIndex& c : chunk_indexes_) records += ChunkIndexRecord(c);
  group(kChunkIndex, records);
  const std::uint64_t summary_offset_start = offset_;
  WriteRaw(offsets);
  // Spec "Footer (op=0x02)": summary_start uint64, summary_offset_start uint64, summary_crc
  // uint32 (the CRC32 from the summary's start through summary_offset_start).
  std::string footer;
  Put8(&footer, kFooter);
  Put64(&footer, 8 + 8 + 4);
  Put64(&footer, summary_start);
  Put64(&footer, summary_offset_start);
  WriteRaw(footer);
  std::string end;
  Put32(&end, section_crc_);
  end.append(kMagic);
  WriteRaw(end);
}

// Spec "Schema (op=0x03)": id uint16, name String, encoding String, data (uint32
// length-prefixed Bytes).
std::string McapWriter::SchemaRecord(std::uint16_t id) const {
  const Schema& s = schemas_[id - 1];
  std::string content;
  Put16(&content, id);
  PutString(&content, s.name);
  PutString(&content, s.encoding);
  PutString(&content, s.data);
  std::string record;
  PutRecord(&record, kSchema, content);
  return record;
}

// Spec "Channel (op=0x04)": id uint16, schema_id uint16, topic String, message_encoding String,
// metadata Map<string, string>.
std::string McapWriter::ChannelRecord(std::uint16_t id) const {
  const Channel& c = channels_[id - 1];
  std::string content;
  Put16(&content, id);
  Put16(&content, c.schema_id);
  PutString(&content, c.topic);
  PutString(&content, c.message_encoding);
  const std::size_t body = BeginPrefixed(&content);
  for (const auto& [key, value] : c.metadata) {
    PutString(&content, key);
    PutString(&content, value);
  }
  EndPrefixed(&content, body);
  std::string record;
  PutRecord(&record, kChannel, content);
  return record;
}

// Spec "Chunk Index (op=0x08)": message_start_time, message_end_time, chunk_start_offset,
// chunk_length (uint64), message_index_offsets Map<uint16, uint64>, message_index_length uint64,
// compression String, compressed_size uint64, uncompressed_size uint64.
std::string McapWriter::ChunkIndexRecord(const ChunkIndex& c) const {
  std::string content;
  Put64(&content, c.start_time);
  Put64(&content, c.end_time);
  Put64(&content, c.offset);
  Put64(&content, c.length);
  const std::size_t body = BeginPrefixed(&content);
  for (const auto& [channel, offset] : c.index_offsets) {
    Put16(&content, channel);
    Put64(&content, offset);
  }
  EndPrefixed(&content, body);
  Put64(&content, c.index_length);
  PutString(&content, c.compression);
  Put64(&content, c.compressed_size);
  Put64(&content, c.uncompressed_size);
  std::string record;
  PutRecord(&record, kChunkIndex, content);
  return record;
}

// Spec "Statistics (op=0x0B)": message_count uint64, schema_count uint16, channel_count,
// attachment_count, metadata_count, chunk_count (uint32), message_start_time, message_end_time
// (Timestamp), channel_message_counts Map<uint16, uint64> (the channels with messages).
std::string McapWriter::StatisticsRecord() const {
  std::string content;
  Put64(&content, messages_);
  Put16(&content, static_cast<std::uint16_t>(schemas_.size()));
  Put32(&content, static_cast<std::uint32_t>(channels_.size()));
  Put32(&content, 0);
  Put32(&content, 0);
  Put32(&content, static_cast<std::uint32_t>(chunk_indexes_.size()));
  Put64(&content, start_time_);
  Put64(&content, end_time_);
  const std::size_t body = BeginPrefixed(&content);
  for (const auto& [channel, count] : channel_counts_) {
    Put16(&content, channel);
    Put64(&content, count);
  }
  EndPrefixed(&content, body);
  std::string record;
  PutRecord(&record, kStatistics, content);
  return record;
}

}  // namespace topay::loginfo
