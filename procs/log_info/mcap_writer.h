#pragma once
// A writer of MCAP files (https://mcap.dev/spec, major version 0) for topay-log-info --mcap:
// schemas, channels and messages in chunks (uncompressed, or zstd where built with libzstd),
// each chunk followed by its Message Index records, then Data End, a summary (Schema, Channel,
// Statistics and Chunk Index records), Summary Offsets and the Footer, with the data section,
// chunk and summary CRC32s filled in, so that Foxglove can open the file and seek in it.

#include <cstdint>
#include <fstream>
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace topay::loginfo {

struct McapWriterOptions {
  std::string profile = "";                ///< Header.profile ("" for none; custom ones start "x-")
  std::string library = "topay-log-info";  ///< Header.library
  /// Target uncompressed size of a chunk's records, bytes: a message that would take the open
  /// chunk past it starts a new one, so only a message larger than the target (alone in its
  /// chunk) makes a bigger chunk. 0: no chunks, messages in the data section (no Chunk Index,
  /// so readers cannot seek).
  std::uint64_t chunk_size_bytes = 1 << 20;
  /// Compress each chunk with zstd. Only where the library was built with libzstd
  /// (McapWriter::CompressionAvailable()); elsewhere chunks stay uncompressed.
  bool compress_chunks = false;
};

/// What has been written so far.
struct McapWriterStats {
  std::uint64_t messages = 0;  ///< Message records
  std::uint64_t chunks = 0;    ///< Chunk records (closed ones)
  std::uint64_t bytes = 0;     ///< bytes in the file (its size once closed)
};

/// Writes one MCAP file. Not thread-safe. Every method but the destructor throws
/// std::runtime_error (naming the path) if the file cannot be written, and std::invalid_argument
/// on an unknown schema or channel id or a call after Close().
class McapWriter {
 public:
  /// Opens (truncates) the file and writes the magic and the Header. Throws std::runtime_error
  /// naming the path if it cannot be opened.
  explicit McapWriter(const std::string& path, McapWriterOptions options = {});
  /// Closes the file (Close()) if it was not; errors are swallowed there: call Close() to see them.
  ~McapWriter();
  McapWriter(const McapWriter&) = delete;
  McapWriter& operator=(const McapWriter&) = delete;

  /// Whether compress_chunks has an effect in this build (zstd).
  static bool CompressionAvailable();

  /// A new schema, ids from 1 up. `encoding` e.g. "jsonschema", `data` the schema itself. It is
  /// written to the data section (in the chunk) just before the first message of a channel that
  /// uses it (by Close() if none does), and again in the summary. Channels likewise.
  std::uint16_t AddSchema(const std::string& name, const std::string& encoding,
                          const std::string& data);
  /// A new channel, ids from 1 up. `schema_id` 0 means no schema. `message_encoding` e.g. "json".
  std::uint16_t AddChannel(std::uint16_t schema_id, const std::string& topic,
                           const std::string& message_encoding,
                           const std::map<std::string, std::string>& metadata = {});
  /// One message. Log times need not increase (chunks and the summary carry the min and max).
  void WriteMessage(std::uint16_t channel_id, std::uint32_t sequence, std::uint64_t log_time_ns,
                    std::uint64_t publish_time_ns, std::string_view data);
  /// Flushes the last chunk and writes Data End (data section CRC32), the summary (Schema,
  /// Channel, Statistics, Chunk Index groups), Summary Offsets, the Footer (summary CRC32) and the
  /// closing magic. A second call does nothing.
  void Close();

  /// Messages, closed chunks and bytes written so far (the open chunk is still in memory).
  McapWriterStats stats() const;

 private:
  struct Schema {
    std::string name, encoding, data;
    bool written = false;  // to the data section (or the open chunk)
  };
  struct Channel {
    std::uint16_t schema_id = 0;
    std::string topic, message_encoding;
    std::map<std::string, std::string> metadata;
    bool written = false;
  };
  struct ChunkIndex {
    std::uint64_t start_time = 0, end_time = 0, offset = 0, length = 0, index_length = 0;
    std::uint64_t compressed_size = 0, uncompressed_size = 0;
    std::string compression;
    std::map<std::uint16_t, std::uint64_t> index_offsets;  // channel -> its Message Index record
  };
  struct OpenChunk {  // the records of the chunk being filled, and their index
    std::string records;
    std::uint64_t start_time = 0, end_time = 0, messages = 0;
    std::map<std::uint16_t, std::vector<std::pair<std::uint64_t, std::uint64_t>>>
        index;  // time, offset
  };

  void CheckOpen() const;
  void WriteRaw(std::string_view bytes);  // to the file, counted in the data CRC before Data End
  void EnsureDefinitions(std::uint16_t channel_id, std::string* out);
  void FlushChunk();
  void WriteUnusedDefinitions();
  void WriteSummary();
  std::string SchemaRecord(std::uint16_t id) const;
  std::string ChannelRecord(std::uint16_t id) const;
  std::string StatisticsRecord() const;
  std::string ChunkIndexRecord(const ChunkIndex& index) const;

  std::string path_;
  McapWriterOptions options_;
  std::ofstream file_;
  bool closed_ = false;
  std::uint64_t offset_ = 0;       // bytes written to the file
  std::uint32_t section_crc_ = 0;  // zlib crc32 of the data (then the summary) section so far
  std::vector<Schema> schemas_;    // id - 1
  std::vector<Channel> channels_;  // id - 1
  OpenChunk chunk_;
  std::vector<ChunkIndex> chunk_indexes_;
  std::map<std::uint16_t, std::uint64_t> channel_counts_;  // messages per channel
  std::uint64_t messages_ = 0, start_time_ = 0, end_time_ = 0;
};

}  // namespace topay::loginfo
