// node check.mjs FILE: reads an MCAP file with the official TypeScript reader (@mcap/core), both
// through its index (McapIndexedReader: footer, summary CRC, chunk indexes, message indexes, chunk
// CRCs) and linearly (McapStreamReader: every record, chunk CRCs), checks that the two agree and
// that the Data End CRC covers the data section, and prints
//   {"schemas": N, "channels": N, "messageCount": N, "topics": {topic: count}, "chunkCount": N}
// Exit code 0 when all is well, 1 (with the reason on stderr) otherwise.
// The independent check of procs/log_info/mcap_writer.cc, run by
// tests/procs/log_info/mcap_writer_test.cc. Install: npm ci --prefix tests/procs/log_info/mcap_js

import { readFile } from "node:fs/promises";

import { crc32 } from "@foxglove/crc";
import { McapIndexedReader, McapStreamReader } from "@mcap/core";
import { decompress } from "fzstd";

const decompressHandlers = {
  zstd: (data, size) => decompress(data, new Uint8Array(Number(size))),
};

function fail(message) {
  throw new Error(message);
}

// One message as a comparable key: channel, sequence, times and a CRC of the data.
function messageKey(m) {
  const { channelId, sequence, logTime, publishTime, data } = m;
  return `${channelId}/${sequence}/${logTime}/${publishTime}/${data.length}/${crc32(data)}`;
}

async function readIndexed(bytes) {
  const readable = {
    size: async () => BigInt(bytes.length),
    read: async (offset, length) => bytes.subarray(Number(offset), Number(offset + length)),
  };
  const reader = await McapIndexedReader.Initialize({ readable, decompressHandlers });
  const dataCrc = crc32(bytes.subarray(0, Number(reader.dataEndOffset)));
  if (reader.dataSectionCrc !== undefined && reader.dataSectionCrc !== dataCrc) {
    fail(`data section CRC ${reader.dataSectionCrc}, computed ${dataCrc}`);
  }
  const topics = {};
  const keys = [];
  let lastTime = 0n;  // readMessages yields in log-time order
  for await (const m of reader.readMessages({ validateCrcs: true })) {
    if (m.logTime < lastTime) fail(`indexed messages out of log-time order at ${m.logTime}`);
    lastTime = m.logTime;
    const topic = reader.channelsById.get(m.channelId)?.topic ?? fail(`no channel ${m.channelId}`);
    topics[topic] = (topics[topic] ?? 0) + 1;
    keys.push(messageKey(m));
  }
  const stats = reader.statistics ?? fail("no Statistics record");
  if (reader.chunkIndexes.length > 0 && stats.messageCount !== BigInt(keys.length)) {
    fail(`Statistics count ${stats.messageCount} messages, the index ${keys.length}`);
  }
  if (stats.chunkCount !== reader.chunkIndexes.length) fail("Statistics chunk count is wrong");
  return { reader, topics, keys };
}

function readStream(bytes) {
  const reader = new McapStreamReader({ validateCrcs: true, decompressHandlers });
  reader.append(bytes);
  const schemas = new Set();
  const channels = new Map();  // id -> topic
  const topics = {};
  const keys = [];
  let dataEnd = false;
  for (let record; (record = reader.nextRecord()); ) {
    if (record.type === "DataEnd") dataEnd = true;
    if (dataEnd) continue;  // the summary repeats schemas and channels
    if (record.type === "Schema") schemas.add(record.id);
    if (record.type === "Channel") channels.set(record.id, record.topic);
    if (record.type === "Message") {
      const topic = channels.get(record.channelId) ?? fail(`message before its channel`);
      topics[topic] = (topics[topic] ?? 0) + 1;
      keys.push(messageKey(record));
    }
  }
  if (!reader.done()) fail("the stream reader did not reach the end of the file");
  if (!dataEnd) fail("no Data End record");
  return { schemas, channels, topics, keys };
}

async function main() {
  const path = process.argv[2] ?? fail("usage: node check.mjs FILE.mcap");
  const bytes = new Uint8Array(await readFile(path));
  const indexed = await readIndexed(bytes);
  const stream = readStream(bytes);
  const chunkCount = indexed.reader.chunkIndexes.length;
  const sortedIndexed = [...indexed.keys].sort();
  const sortedStream = [...stream.keys].sort();
  // Without chunks, messages are not indexed: only the stream reader sees them.
  if (chunkCount > 0 && JSON.stringify(sortedIndexed) !== JSON.stringify(sortedStream)) {
    const counts = `${sortedIndexed.length} vs ${sortedStream.length} messages`;
    fail(`the indexed and stream readers disagree (${counts})`);
  }
  if (BigInt(stream.keys.length) !== indexed.reader.statistics.messageCount) {
    fail("Statistics count other messages than the data section holds");
  }
  if (stream.schemas.size !== indexed.reader.schemasById.size ||
      stream.channels.size !== indexed.reader.channelsById.size) {
    fail("the data section and the summary define different schemas or channels");
  }
  const result = {
    schemas: indexed.reader.schemasById.size,
    channels: indexed.reader.channelsById.size,
    messageCount: stream.keys.length,
    topics: stream.topics,
    chunkCount,
  };
  process.stdout.write(`${JSON.stringify(result)}\n`);
}

main().catch((error) => {
  process.stderr.write(`mcap check: ${error.message}\n`);
  process.exit(1);
});
