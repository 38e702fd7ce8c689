#!/usr/bin/env node
// read_mcap.mjs - independent MCAP checker for the C++ tests, built on the official
// @mcap/core reader (https://mcap.dev). Needs Node.js >= 18 and `npm ci` in this folder.
//
// Usage: node read_mcap.mjs FILE [--messages all|N] [--stream]
//
//   (default)     Indexed read (McapIndexedReader: footer, summary, indexes). Prints one JSON
//                 object: header, schemas, channels, chunks, attachments, metadata, statistics,
//                 message counts and the decoded messages in log-time order. The data section
//                 CRC (which @mcap/core does not check) is verified here too.
//   --messages N  Decode at most N messages per channel ("all" = every message, the default in
//                 indexed mode; 0 = only count them).
//   --stream      Read front to back with McapStreamReader, tolerating a file cut short (e.g. a
//                 recording killed mid-write): reports what was read up to the first incomplete
//                 record, and "complete": true only if the footer and closing magic were reached.
//                 Messages (file order) are only listed when --messages is given.
//
// Decoding: "cdr" channels with a "ros2msg" schema via @foxglove/rosmsg2-serialization, "json"
// channels via JSON.parse; other encodings are given as "dataBase64". In the output, BigInt
// values (times, uint64/int64 fields, counts) are decimal strings, typed arrays are plain arrays,
// NaN/Infinity/-Infinity are the strings "NaN"/"Infinity"/"-Infinity".
//
// Exit status: 0 on success. 1 on any error: the output is then {"error": "..."} (indexed mode),
// or the stream report with "error" set (stream mode; a merely truncated file is not an error).
// 2 on bad usage.

import { open } from "node:fs/promises";
import { crc32Init, crc32Update, crc32Final } from "@foxglove/crc";
import { McapIndexedReader, McapStreamReader } from "@mcap/core";
import { ros2Definitions } from "./ros2_definitions.mjs";
import { MessageReader } from "@foxglove/rosmsg2-serialization";
import { decompress as zstdDecompress } from "fzstd";

// @mcap/core calls handler(compressedBytes, uncompressedSize: bigint) and expects a Uint8Array.
// fzstd is given no output buffer on purpose: with one it silently truncates or zero-pads a
// wrong-sized result and fails on multi-frame input; without one the length is checked here.
const decompressHandlers = {
  zstd: (buffer, decompressedSize) => {
    const out = zstdDecompress(buffer);
    if (BigInt(out.byteLength) !== decompressedSize) {
      throw new Error(`zstd chunk decompressed to ${out.byteLength} bytes, expected ${decompressedSize}`);
    }
    return out;
  },
};

const utf8 = new TextDecoder("utf-8", { fatal: true });

/** Converts decoded values to JSON-safe ones (see header comment). */
function toJson(v) {
  if (typeof v === "bigint") return v.toString();
  if (typeof v === "number") return Number.isFinite(v) ? v : String(v);
  if (v instanceof Map) return Object.fromEntries([...v].map(([k, x]) => [String(k), toJson(x)]));
  if (ArrayBuffer.isView(v)) return Array.from(v, toJson);
  if (Array.isArray(v)) return v.map(toJson);
  if (v !== null && typeof v === "object") {
    return Object.fromEntries(Object.entries(v).map(([k, x]) => [k, toJson(x)]));
  }
  return v;
}

/** Decodes message payloads; one MessageReader per schema id. */
class Decoder {
  #readers = new Map();
  #schemas;
  constructor(schemasById) {
    this.#schemas = schemasById;
  }
  decode(channel, data) {
    switch (channel.messageEncoding) {
      case "cdr": return this.#readerFor(channel.schemaId).readMessage(data);
      case "json": return JSON.parse(utf8.decode(data));
      default: return undefined;
    }
  }
  #readerFor(schemaId) {
    let reader = this.#readers.get(schemaId);
    if (!reader) {
      const schema = this.#schemas.get(schemaId);
      if (!schema) throw new Error(`cdr channel refers to unknown schema id ${schemaId}`);
      if (schema.encoding !== "ros2msg") {
        throw new Error(`cannot decode cdr with schema encoding "${schema.encoding}"`);
      }
      reader = new MessageReader(ros2Definitions(utf8.decode(schema.data)));
      this.#readers.set(schemaId, reader);
    }
    return reader;
  }
}

function messageJson(decoder, channel, msg) {
  const out = {
    topic: channel.topic,
    channelId: msg.channelId,
    sequence: msg.sequence,
    logTime: msg.logTime.toString(),
    publishTime: msg.publishTime.toString(),
  };
  try {
    const data = decoder.decode(channel, msg.data);
    if (data === undefined) out.dataBase64 = Buffer.from(msg.data).toString("base64");
    else out.data = toJson(data);
  } catch (e) {
    throw new Error(`cannot decode message seq ${msg.sequence} at logTime ${msg.logTime} on ` +
      `"${channel.topic}" (${channel.messageEncoding}): ${e.message}`);
  }
  return out;
}

/** Collects messages: counts, time range and the first `limit` decoded messages per channel. */
class MessageSink {
  count = 0n;
  perChannel = new Map();
  startTime = undefined;
  endTime = undefined;
  messages = [];
  constructor(decoder, limit) {
    this.decoder = decoder;
    this.limit = limit;
  }
  add(channel, msg) {
    const n = (this.perChannel.get(msg.channelId) ?? 0n) + 1n;
    this.perChannel.set(msg.channelId, n);
    this.count++;
    if (this.startTime === undefined || msg.logTime < this.startTime) this.startTime = msg.logTime;
    if (this.endTime === undefined || msg.logTime > this.endTime) this.endTime = msg.logTime;
    if (n <= this.limit) this.messages.push(messageJson(this.decoder, channel, msg));
  }
}

const schemaJson = (s) => ({ id: s.id, name: s.name, encoding: s.encoding });
const channelJson = (c, schemas) => ({
  id: c.id,
  topic: c.topic,
  schemaId: c.schemaId,
  schemaName: schemas.get(c.schemaId)?.name ?? null,
  messageEncoding: c.messageEncoding,
  metadata: toJson(c.metadata),
});

/** IReadable for McapIndexedReader over an fs.promises FileHandle. */
class FileReadable {
  constructor(handle, size) {
    this.handle = handle;
    this.fileSize = size;
  }
  async size() {
    return BigInt(this.fileSize);
  }
  async read(offset, length) {
    const buf = new Uint8Array(Number(length));
    for (let done = 0; done < buf.byteLength;) {
      const { bytesRead } = await this.handle.read(buf, done, buf.byteLength - done, Number(offset) + done);
      if (bytesRead === 0) throw new Error(`unexpected end of file reading ${length} bytes at ${offset}`);
      done += bytesRead;
    }
    return buf;
  }
}

async function readIndexed(handle, limit) {
  const { size } = await handle.stat();
  const readable = new FileReadable(handle, size);
  const reader = await McapIndexedReader.Initialize({ readable, decompressHandlers });

  // Data section CRC: CRC-32 of every byte from the file start up to the DataEnd record.
  let dataSectionCrc = null;
  if (reader.dataSectionCrc !== undefined) {
    let crc = crc32Init();
    const step = 1n << 20n;
    for (let pos = 0n; pos < reader.dataEndOffset; pos += step) {
      const len = reader.dataEndOffset - pos < step ? reader.dataEndOffset - pos : step;
      crc = crc32Update(crc, await readable.read(pos, len));
    }
    crc = crc32Final(crc);
    if (crc !== reader.dataSectionCrc) {
      throw new Error(`Incorrect data section CRC ${crc} (expected ${reader.dataSectionCrc})`);
    }
    dataSectionCrc = crc;
  }

  const schemas = reader.schemasById;
  const sink = new MessageSink(new Decoder(schemas), limit);
  for await (const msg of reader.readMessages()) {
    const channel = reader.channelsById.get(msg.channelId);
    if (!channel) throw new Error(`message on unknown channel id ${msg.channelId}`);
    sink.add(channel, msg);
  }

  const attachments = [];
  for await (const a of reader.readAttachments()) {
    const entry = {
      name: a.name,
      mediaType: a.mediaType,
      size: a.data.byteLength,
      logTime: a.logTime.toString(),
      createTime: a.createTime.toString(),
    };
    if (a.mediaType.startsWith("application/json") || a.mediaType.startsWith("text/")) {
      entry.text = utf8.decode(a.data);
    }
    attachments.push(entry);
  }
  const metadata = [];
  for await (const m of reader.readMetadata()) {
    metadata.push({ name: m.name, metadata: toJson(m.metadata) });
  }

  const { type: _type, ...stats } = reader.statistics ?? {};
  return {
    mode: "indexed",
    profile: reader.header.profile,
    library: reader.header.library,
    schemas: [...schemas.values()].map(schemaJson),
    channels: [...reader.channelsById.values()].map((c) => channelJson(c, schemas)),
    attachments,
    metadata,
    statistics: reader.statistics ? toJson(stats) : null,
    chunkCount: reader.chunkIndexes.length,
    chunks: reader.chunkIndexes.map((c) => toJson({
      compression: c.compression,
      compressedSize: c.compressedSize,
      uncompressedSize: c.uncompressedSize,
      messageStartTime: c.messageStartTime,
      messageEndTime: c.messageEndTime,
    })),
    dataSectionCrc,
    messageCount: sink.count.toString(),
    channelMessageCounts: toJson(sink.perChannel),
    messages: sink.messages,
  };
}

async function readStream(handle, limit) {
  const reader = new McapStreamReader({ decompressHandlers, includeChunks: true });
  const schemas = new Map();
  const channels = new Map();
  const sink = new MessageSink(new Decoder(schemas), limit);
  const counts = { chunkCount: 0, attachmentCount: 0, metadataCount: 0 };
  let header = null;
  let error = null;
  const buf = new Uint8Array(1 << 20);
  try {
    for (;;) {
      const { bytesRead } = await handle.read(buf, 0, buf.byteLength, null);
      if (bytesRead === 0) break;
      if (reader.done()) throw new Error("data after the closing magic");
      reader.append(buf.subarray(0, bytesRead));
      for (let rec; (rec = reader.nextRecord());) {
        switch (rec.type) {
          case "Header": header = rec; break;
          case "Schema": schemas.set(rec.id, rec); break;
          case "Channel": channels.set(rec.id, rec); break;
          case "Message": sink.add(channels.get(rec.channelId), rec); break;
          case "Chunk": counts.chunkCount++; break;
          case "Attachment": counts.attachmentCount++; break;
          case "Metadata": counts.metadataCount++; break;
        }
      }
    }
  } catch (e) {
    error = e.message;
  }
  return {
    mode: "stream",
    complete: reader.done(),
    error,
    unparsedBytes: reader.bytesRemaining(),
    profile: header?.profile ?? null,
    library: header?.library ?? null,
    messageCount: sink.count.toString(),
    channelMessageCounts: toJson(sink.perChannel),
    messageStartTime: sink.startTime?.toString() ?? null,
    messageEndTime: sink.endTime?.toString() ?? null,
    ...counts,
    schemas: [...schemas.values()].map(schemaJson),
    channels: [...channels.values()].map((c) => channelJson(c, schemas)),
    ...(limit > 0 ? { messages: sink.messages } : {}),
  };
}

function parseArgs(argv) {
  const args = { file: undefined, stream: false, limit: undefined };
  for (let i = 0; i < argv.length; i++) {
    const a = argv[i];
    if (a === "--stream") {
      args.stream = true;
    } else if (a === "--messages") {
      const v = argv[++i];
      if (v === "all") args.limit = Infinity;
      else if (/^\d+$/.test(v ?? "")) args.limit = Number(v);
      else throw new Error(`--messages wants "all" or a count, got ${v}`);
    } else if (a.startsWith("--") || args.file !== undefined) {
      throw new Error(`unexpected argument ${a}`);
    } else {
      args.file = a;
    }
  }
  if (args.file === undefined) throw new Error("usage: node read_mcap.mjs FILE [--messages all|N] [--stream]");
  args.limit ??= args.stream ? 0 : Infinity;
  return args;
}

const print = (obj) => process.stdout.write(JSON.stringify(obj) + "\n");

let args;
try {
  args = parseArgs(process.argv.slice(2));
} catch (e) {
  print({ error: e.message });
  process.exit(2);
}
let handle;
try {
  handle = await open(args.file, "r");
  const result = args.stream ? await readStream(handle, args.limit) : await readIndexed(handle, args.limit);
  print(result);
  process.exitCode = result.error ? 1 : 0;
} catch (e) {
  print({ error: e?.message ?? String(e) });
  process.exitCode = 1;
} finally {
  await handle?.close();
}
