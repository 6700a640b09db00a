// The MCAP writer (procs/log_info/mcap_writer.h) read back by a strict reader written apart from it
// (mcap_test_reader.h: magic, record bounds, CRCs, chunk and message indexes, summary, Statistics),
// and by the official TypeScript reader (@mcap/core, mcap_js/check.mjs) where Node and its
// node_modules are there: `npm ci --prefix tests/procs/log_info/mcap_js`.

#include "procs/log_info/mcap_writer.h"

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "graph_test_support.h"
#include "mcap_test_reader.h"

namespace topay::loginfo {
namespace {

namespace mt = mcap_test;

struct Sent {
  std::uint16_t channel;
  std::uint32_t sequence;
  std::uint64_t log_time, publish_time;
  std::string data;
};

// Each test writes its files into a fresh folder of its own.
class McapWriterTest : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = test::TestDir("mcap"); }
  std::string Path(const std::string& name) const { return dir_ + "/" + name; }

 private:
  std::string dir_;
};

void Send(McapWriter* w, std::vector<Sent>* sent, Sent m) {
  w->WriteMessage(m.channel, m.sequence, m.log_time, m.publish_time, m.data);
  sent->push_back(std::move(m));
}

void ExpectSameMessages(const std::vector<mt::Message>& got, const std::vector<Sent>& sent) {
  ASSERT_EQ(got.size(), sent.size());
  for (std::size_t i = 0; i < got.size(); ++i) {
    SCOPED_TRACE("message " + std::to_string(i));
    EXPECT_EQ(got[i].channel_id, sent[i].channel);
    EXPECT_EQ(got[i].sequence, sent[i].sequence);
    EXPECT_EQ(got[i].log_time, sent[i].log_time);
    EXPECT_EQ(got[i].publish_time, sent[i].publish_time);
    EXPECT_EQ(got[i].data, sent[i].data);
  }
}

std::string Json(int i) { return R"({"i":)" + std::to_string(i) + R"(,"pad":"........"})"; }

// Two schemas, three channels (one with metadata), 300 messages in ~60-byte records: many chunks
// of at most 512 bytes.
std::vector<Sent> WriteThreeChannels(const std::string& path, McapWriterOptions options) {
  McapWriter w(path, options);
  const std::uint16_t pose =
      w.AddSchema("topay.viz.RobotState", "jsonschema", R"({"type":"object"})");
  const std::uint16_t goal = w.AddSchema("topay.viz.Goal", "jsonschema", R"({"type":"object"})");
  const std::uint16_t a = w.AddChannel(pose, "/robot/state", "json", {{"rate", "30"}});
  const std::uint16_t b = w.AddChannel(goal, "/goal", "json");
  const std::uint16_t c = w.AddChannel(pose, "/plot/state", "json");
  std::vector<Sent> sent;
  for (int i = 0; i < 300; ++i) {
    const std::uint16_t channel = i % 7 == 0 ? b : (i % 2 ? a : c);
    const std::uint64_t t =
        1'700'000'000'000'000'000ull + static_cast<std::uint64_t>(i) * 1'000'000;
    Send(&w, &sent, {channel, static_cast<std::uint32_t>(i), t, t - 5, Json(i)});
  }
  w.Close();
  EXPECT_EQ(w.stats().messages, 300u);
  EXPECT_EQ(w.stats().bytes, std::filesystem::file_size(path));
  return sent;
}

TEST_F(McapWriterTest, RoundTripsSchemasChannelsAndMessagesAcrossChunks) {
  const std::string path = Path("three.mcap");
  McapWriterOptions options;
  options.profile = "x-topay";
  options.chunk_size_bytes = 512;
  const std::vector<Sent> sent = WriteThreeChannels(path, options);
  const mt::McapContents f = mt::ReadMcap(path);
  EXPECT_EQ(f.profile, "x-topay");
  EXPECT_EQ(f.library, "topay-log-info");
  ASSERT_EQ(f.schemas.size(), 2u);
  // In the order of first use: message 0 is on /goal.
  EXPECT_EQ(f.schemas[0], (mt::Schema{2, "topay.viz.Goal", "jsonschema", R"({"type":"object"})"}));
  EXPECT_EQ(f.schemas[1],
            (mt::Schema{1, "topay.viz.RobotState", "jsonschema", R"({"type":"object"})"}));
  ASSERT_EQ(f.channels.size(), 3u);
  EXPECT_EQ(f.channels[0], (mt::Channel{2, 2, "/goal", "json", {}}));
  EXPECT_EQ(f.channels[1], (mt::Channel{1, 1, "/robot/state", "json", {{"rate", "30"}}}));
  EXPECT_EQ(f.channels[2], (mt::Channel{3, 1, "/plot/state", "json", {}}));
  ExpectSameMessages(f.messages, sent);
  EXPECT_GT(f.chunks.size(), 20u);
  for (const mt::Chunk& c : f.chunks) {
    EXPECT_LE(c.uncompressed_size, 512u);
    EXPECT_EQ(c.compression, "");
    EXPECT_GT(c.messages, 0u);
  }
  for (const mt::Message& m : f.messages) EXPECT_NE(m.chunk_offset, 0u);
  EXPECT_EQ(f.chunk_indexes.size(), f.chunks.size());  // and each matches (the reader checks)
  ASSERT_EQ(f.summary_offsets.size(), 4u);             // Schema, Channel, Statistics, Chunk Index
  EXPECT_EQ(f.summary_offsets[0].opcode, 0x03);
  EXPECT_EQ(f.summary_offsets[3].opcode, 0x08);
  EXPECT_NE(f.data_section_crc, 0u);
  EXPECT_NE(f.summary_crc, 0u);
}

TEST_F(McapWriterTest, EmptyFileIsValid) {
  const std::string path = Path("empty.mcap");
  { McapWriter w(path); }  // the destructor closes
  const mt::McapContents f = mt::ReadMcap(path);
  EXPECT_TRUE(f.schemas.empty());
  EXPECT_TRUE(f.channels.empty());
  EXPECT_TRUE(f.messages.empty());
  EXPECT_TRUE(f.chunks.empty());
  ASSERT_TRUE(f.statistics);
  EXPECT_EQ(f.statistics->message_count, 0u);
  EXPECT_EQ(f.statistics->chunk_count, 0u);
  EXPECT_EQ(f.statistics->start_time, 0u);
  EXPECT_EQ(f.statistics->end_time, 0u);
  EXPECT_NE(f.summary_start, 0u);  // indexed readers need a summary
}

TEST_F(McapWriterTest, SchemasAndChannelsWithoutMessagesAreStillDefined) {
  const std::string path = Path("unused.mcap");
  {
    McapWriter w(path);
    const std::uint16_t s = w.AddSchema("topay.viz.Goal", "jsonschema", "{}");
    w.AddChannel(s, "/goal", "json");
    w.AddChannel(0, "/raw", "json");  // no schema
  }
  const mt::McapContents f = mt::ReadMcap(path);
  EXPECT_EQ(f.schemas.size(), 1u);
  EXPECT_EQ(f.channels.size(), 2u);
  EXPECT_EQ(f.summary_channels.size(), 2u);
  EXPECT_EQ(f.statistics->channel_count, 2u);
  EXPECT_TRUE(f.statistics->channel_message_counts.empty());
}

TEST_F(McapWriterTest, InterleavedChannelsWithDecreasingLogTimes) {
  const std::string path = Path("backwards.mcap");
  McapWriterOptions options;
  options.chunk_size_bytes = 400;
  std::vector<Sent> sent;
  {
    McapWriter w(path, options);
    const std::uint16_t s = w.AddSchema("S", "jsonschema", "{}");
    const std::uint16_t a = w.AddChannel(s, "/a", "json");
    const std::uint16_t b = w.AddChannel(s, "/b", "json");
    for (int i = 0; i < 40; ++i) {
      const std::uint64_t t = 10'000 - static_cast<std::uint64_t>(i) * 100 + (i % 3) * 250;
      Send(&w, &sent, {i % 2 ? a : b, static_cast<std::uint32_t>(i), t, t, Json(i)});
    }
  }
  const mt::McapContents f = mt::ReadMcap(path);  // checks each chunk's min / max and its indexes
  ExpectSameMessages(f.messages, sent);
  ASSERT_GT(f.chunks.size(), 3u);
  for (const mt::Chunk& c : f.chunks) {
    EXPECT_LT(c.start_time, c.end_time);
    EXPECT_EQ(c.index_offsets.size(), 2u);  // both channels in every chunk
  }
  EXPECT_EQ(f.statistics->start_time, 10'000u - 39 * 100);  // i = 39: 39 % 3 == 0
  EXPECT_EQ(f.statistics->end_time, 10'000u - 2 * 100 + 2 * 250);
}

TEST_F(McapWriterTest, StatisticsCountWhatWasWritten) {
  const std::string path = Path("stats.mcap");
  McapWriterOptions options;
  options.chunk_size_bytes = 512;
  const std::vector<Sent> sent = WriteThreeChannels(path, options);
  const mt::McapContents f = mt::ReadMcap(path);
  ASSERT_TRUE(f.statistics);
  const mt::Statistics& s = *f.statistics;
  EXPECT_EQ(s.message_count, 300u);
  EXPECT_EQ(s.schema_count, 2u);
  EXPECT_EQ(s.channel_count, 3u);
  EXPECT_EQ(s.attachment_count, 0u);
  EXPECT_EQ(s.metadata_count, 0u);
  EXPECT_EQ(s.chunk_count, f.chunks.size());
  EXPECT_EQ(s.start_time, sent.front().log_time);
  EXPECT_EQ(s.end_time, sent.back().log_time);
  // /goal (2): i % 7 == 0, 43 of 300; /robot/state (1): the other odd i (150 - 21); /plot/state
  // (3): the other even i (150 - 22).
  const std::map<std::uint16_t, std::uint64_t> counts = {{1, 129}, {2, 43}, {3, 128}};
  EXPECT_EQ(s.channel_message_counts, counts);
}

// A copy of `path` at `out` with the byte at `offset` flipped; returns `out`.
std::string Corrupt(const std::string& path, std::uint64_t offset, const std::string& out) {
  std::ifstream in(path, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  bytes.at(offset) ^= 0x01;
  std::ofstream(out, std::ios::binary) << bytes;
  return out;
}

void ExpectFault(const std::string& path, const std::string& fault) {
  try {
    mt::ReadMcap(path);
    ADD_FAILURE() << path << ": no fault found, expected " << fault;
  } catch (const mt::McapFormatError& e) {
    EXPECT_NE(std::string(e.what()).find(fault), std::string::npos) << e.what();
  }
}

TEST_F(McapWriterTest, ReaderDetectsACorruptByteByItsCrc) {
  const std::string chunked = Path("good.mcap");
  McapWriterOptions options;
  options.chunk_size_bytes = 512;
  WriteThreeChannels(chunked, options);
  const mt::McapContents f = mt::ReadMcap(chunked);
  // A byte of the Header's library string, of a message's data (inside the third chunk's
  // records), and of a Schema record's name in the summary.
  ExpectFault(Corrupt(chunked, 8 + 9 + 4 + 4 + 2, Path("header.mcap")), "data section CRC");
  ExpectFault(Corrupt(chunked, f.chunks[2].records_offset + f.chunks[2].uncompressed_size - 3,
                      Path("chunk.mcap")),
              "chunk CRC");
  ExpectFault(Corrupt(chunked, f.summary_start + 9 + 2 + 4 + 1, Path("summary.mcap")),
              "summary CRC");
  // Without chunks a message's data is only under the data section CRC.
  options.chunk_size_bytes = 0;
  const std::string flat = Path("flat.mcap");
  WriteThreeChannels(flat, options);
  const mt::McapContents g = mt::ReadMcap(flat);
  ExpectFault(Corrupt(flat, g.data_end_offset - 3, Path("flat_message.mcap")), "data section CRC");
}

// Every byte of a file is under a CRC, a length or the magic: flipping any one of them is caught
// (and never crashes the reader).
TEST_F(McapWriterTest, ReaderDetectsEveryFlippedByte) {
  const std::string path = Path("small.mcap");
  McapWriterOptions options;
  options.chunk_size_bytes = 200;
  {
    McapWriter w(path, options);
    const std::uint16_t c =
        w.AddChannel(w.AddSchema("S", "jsonschema", "{}"), "/a", "json", {{"k", "v"}});
    for (int i = 0; i < 6; ++i) w.WriteMessage(c, i, 100 - i, 0, Json(i));
  }
  std::ifstream in(path, std::ios::binary);
  const std::string good((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ASSERT_NO_THROW(mt::ParseMcap(good));
  ASSERT_GT(mt::ParseMcap(good).chunks.size(), 1u);
  for (std::size_t i = 0; i < good.size(); ++i) {
    std::string bad = good;
    bad[i] ^= 0x10;
    EXPECT_THROW(mt::ParseMcap(bad), mt::McapFormatError) << "byte " << i << " of " << good.size();
  }
}

TEST_F(McapWriterTest, MessageLargerThanAChunkGetsAChunkOfItsOwn) {
  const std::string path = Path("big.mcap");
  McapWriterOptions options;
  options.chunk_size_bytes = 1024;
  std::vector<Sent> sent;
  std::string big(10'000, '\0');
  for (std::size_t i = 0; i < big.size(); ++i) big[i] = static_cast<char>(i * 31 % 251);
  {
    McapWriter w(path, options);
    const std::uint16_t c = w.AddChannel(w.AddSchema("Blob", "jsonschema", "{}"), "/blob", "json");
    for (int i = 0; i < 5; ++i)
      Send(&w, &sent, {c, static_cast<std::uint32_t>(i), 100u + i, 0, Json(i)});
    Send(&w, &sent, {c, 5, 105, 0, big});
    Send(&w, &sent, {c, 6, 106, 0, Json(6)});
    Send(&w, &sent, {c, 7, 107, 0, big + big});
  }
  const mt::McapContents f = mt::ReadMcap(path);
  ExpectSameMessages(f.messages, sent);
  ASSERT_EQ(f.chunks.size(), 4u);
  EXPECT_EQ(f.chunks[0].messages, 5u);
  EXPECT_EQ(f.chunks[1].messages, 1u);  // the big one alone
  EXPECT_GT(f.chunks[1].uncompressed_size, 10'000u);
  EXPECT_EQ(f.chunks[2].messages, 1u);
  EXPECT_EQ(f.chunks[3].messages, 1u);
  EXPECT_GT(f.chunks[3].uncompressed_size, 20'000u);
}

TEST_F(McapWriterTest, WithoutChunksMessagesAreInTheDataSection) {
  const std::string path = Path("flat.mcap");
  McapWriterOptions options;
  options.chunk_size_bytes = 0;
  const std::vector<Sent> sent = WriteThreeChannels(path, options);
  const mt::McapContents f = mt::ReadMcap(path);
  ExpectSameMessages(f.messages, sent);
  EXPECT_TRUE(f.chunks.empty());
  EXPECT_TRUE(f.chunk_indexes.empty());
  for (const mt::Message& m : f.messages) EXPECT_EQ(m.chunk_offset, 0u);
  EXPECT_EQ(f.statistics->message_count, 300u);
}

TEST_F(McapWriterTest, ZstdChunksRoundTrip) {
  if (!McapWriter::CompressionAvailable()) GTEST_SKIP() << "built without libzstd";
  const std::string path = Path("zstd.mcap");
  McapWriterOptions options;
  options.chunk_size_bytes = 4096;
  options.compress_chunks = true;
  const std::vector<Sent> sent = WriteThreeChannels(path, options);
  const mt::McapContents f = mt::ReadMcap(path);
  ExpectSameMessages(f.messages, sent);
  ASSERT_FALSE(f.chunks.empty());
  for (const mt::Chunk& c : f.chunks) {
    EXPECT_EQ(c.compression, "zstd");
    EXPECT_LT(c.compressed_size, c.uncompressed_size);
  }
}

TEST_F(McapWriterTest, UnopenablePathThrowsNamingIt) {
  const std::string path = Path("no") + "/such/dir/out.mcap";
  try {
    McapWriter w(path);
    FAIL() << "opened " << path;
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
  }
}

TEST_F(McapWriterTest, RejectsUnknownIdsAndUseAfterClose) {
  McapWriter w(Path("misuse.mcap"));
  EXPECT_THROW(w.AddChannel(1, "/a", "json"), std::invalid_argument);  // no schema 1 yet
  const std::uint16_t c = w.AddChannel(0, "/a", "json");
  EXPECT_THROW(w.WriteMessage(0, 0, 1, 1, "{}"), std::invalid_argument);
  EXPECT_THROW(w.WriteMessage(c + 1, 0, 1, 1, "{}"), std::invalid_argument);
  w.WriteMessage(c, 0, 1, 1, "{}");
  w.Close();
  w.Close();  // a second call does nothing
  EXPECT_THROW(w.WriteMessage(c, 1, 2, 2, "{}"), std::invalid_argument);
  EXPECT_EQ(mt::ReadMcap(Path("misuse.mcap")).messages.size(), 1u);
}

// ---- The official TypeScript reader (@mcap/core) ----

std::string JsDir() { return std::string(TOPAY_SOURCE_DIR) + "/tests/procs/log_info/mcap_js"; }

// Why the JS check cannot run here, or "" if it can.
std::string JsCheckMissing() {
  if (std::system("node --version > /dev/null 2>&1") != 0) return "node is not installed";
  if (!std::filesystem::exists(JsDir() + "/node_modules/@mcap/core/package.json")) {
    return JsDir() + "/node_modules is missing: run `npm ci --prefix " + JsDir() + "`";
  }
  return "";
}

// Runs check.mjs on `path`: its exit code and its output (stdout and stderr).
std::pair<int, std::string> RunJsCheck(const std::string& path) {
  const std::string command = "node '" + JsDir() + "/check.mjs' '" + path + "' 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return {-1, "popen failed"};
  std::string output;
  char buffer[4096];
  for (std::size_t n; (n = std::fread(buffer, 1, sizeof(buffer), pipe)) > 0;)
    output.append(buffer, n);
  const int status = pclose(pipe);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, output};
}

void ExpectJsReaderAgrees(const std::string& path, std::uint64_t chunks) {
  SCOPED_TRACE(path);
  const auto [code, output] = RunJsCheck(path);
  ASSERT_EQ(code, 0) << output;
  const nlohmann::json j = nlohmann::json::parse(output);
  EXPECT_EQ(j.at("schemas"), 2);
  EXPECT_EQ(j.at("channels"), 3);
  EXPECT_EQ(j.at("messageCount"), 300);
  EXPECT_EQ(j.at("topics"),
            nlohmann::json({{"/robot/state", 129}, {"/goal", 43}, {"/plot/state", 128}}));
  EXPECT_EQ(j.at("chunkCount"), chunks);
}

TEST_F(McapWriterTest, OfficialJsReaderAgrees) {
  if (const std::string missing = JsCheckMissing(); !missing.empty()) {
    GTEST_SKIP() << "SKIPPED the @mcap/core check: " << missing;
  }
  McapWriterOptions options;
  for (const std::uint64_t chunk_size :
       {std::uint64_t{512}, std::uint64_t{0}, std::uint64_t{1} << 20}) {
    options.chunk_size_bytes = chunk_size;
    const std::string path = Path("js_" + std::to_string(chunk_size) + ".mcap");
    WriteThreeChannels(path, options);
    ExpectJsReaderAgrees(path, mt::ReadMcap(path).chunks.size());
  }
  if (McapWriter::CompressionAvailable()) {
    options.chunk_size_bytes = 4096;
    options.compress_chunks = true;
    WriteThreeChannels(Path("js_zstd.mcap"), options);
    ExpectJsReaderAgrees(Path("js_zstd.mcap"), mt::ReadMcap(Path("js_zstd.mcap")).chunks.size());
  }
  // And it must fail on a corrupt file (a flipped byte in a chunk's records).
  options = {};
  options.chunk_size_bytes = 512;
  const std::string good = Path("js_good.mcap");
  WriteThreeChannels(good, options);
  const mt::Chunk chunk = mt::ReadMcap(good).chunks.at(1);
  const std::string bad =
      Corrupt(good, chunk.records_offset + chunk.uncompressed_size - 3, Path("js_bad.mcap"));
  const auto [code, output] = RunJsCheck(bad);
  EXPECT_NE(code, 0) << output;
  EXPECT_NE(output.find("CRC"), std::string::npos) << output;
}

}  // namespace
}  // namespace topay::loginfo
