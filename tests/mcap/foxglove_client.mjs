#!/usr/bin/env node
// foxglove_client.mjs - independent Foxglove WebSocket client for the C++ tests, built on the
// official FoxgloveClient from @foxglove/ws-protocol (https://github.com/foxglove/ws-protocol)
// over the `ws` package. Needs Node.js >= 18 and `npm ci` in this folder.
//
// Usage: node foxglove_client.mjs --url ws://127.0.0.1:PORT --subprotocol NAME [--seconds S]
//            [--quiet-ms MS] [--topics REGEX] [--values FILE.jsonl] [--expect-channels N]
//            [--period-ms P]
//
//   --url              server to connect to.
//   --subprotocol      the one WebSocket subprotocol offered, e.g. foxglove.websocket.v1 or
//                      foxglove.sdk.v1; the negotiated one is reported as "protocol".
//                      FoxgloveClient 0.8.0 does not check the negotiated subprotocol (only
//                      FoxgloveServer compares against SUPPORTED_SUBPROTOCOL), so the WebSocket is
//                      built here with exactly this name and handed to FoxgloveClient as is. The
//                      `ws` package itself fails the handshake if the server picks none or another.
//   --seconds S        stop S seconds (default 10) after start (the connection time included).
//   --quiet-ms MS      stop earlier once at least one message has arrived and none for MS ms
//                      (checked every MS/5 ms, so the stop comes within 1.2 * MS).
//   --topics REGEX     subscribe only to channels whose topic matches REGEX (unanchored; default
//                      all). Channels advertised at any later time are subscribed too.
//   --values FILE      also write every decoded message as a JSON line
//                      {"topic", "timestamp": "ns", "message": {...}} (BigInt -> decimal string,
//                      typed array -> array, NaN/Infinity -> null).
//   --expect-channels N  once subscribed to N channels (default 1), print "ready\n" to stderr.
//   --period-ms P      the devices' sample period: per topic, messages whose header.stamp is more
//                      than 1.5 P after the one before count as gaps ("stampGaps", and
//                      "stampMissing": the messages that would fill them); a message whose
//                      header.stamp differs from its frame's timestamp counts in "stampMismatch".
//
// Decoding: "cdr" channels with a "ros2msg" schema via @foxglove/rosmsg2-serialization (one
// reader per channel), "json" channels via JSON.parse; anything else, or a failure, counts as a
// decode error. It also stops on SIGTERM/SIGINT and when the server closes the connection
// ("closed": {code, reason}; null when this tool closed it).
//
// Output (stdout, one JSON object): protocol, serverInfo, channels (every channel advertised,
// with "subscribed" and "unadvertised" flags), counts / firstTimestamp / lastTimestamp /
// outOfOrder per topic (timestamps are the uint64 ns of the message frame as decimal strings;
// outOfOrder counts a topic's timestamp going backwards), timeMessages, lastTime, statuses
// ({level, message, id}), decodeErrors, firstDecodeError, protocolErrors, firstProtocolError
// (frames the official parser rejected), unknownSubscriptions (messages for a subscription id
// never sent), closed.
//
// Exit status: 0 after a run (whatever the server sent). 1 if it could not connect (the output is
// then {"error": "..."}). 2 on bad usage.

import { createWriteStream } from "node:fs";
import wsProtocol from "@foxglove/ws-protocol"; // CommonJS: its named exports are not detectable
import { WebSocket } from "ws";
import { ros2Definitions } from "./ros2_definitions.mjs";
import { MessageReader } from "@foxglove/rosmsg2-serialization";

const { FoxgloveClient } = wsProtocol;
const utf8 = new TextDecoder("utf-8", { fatal: true });

/** Returns a function bytes -> decoded message for a channel; throws if it cannot decode it. */
function makeDecoder(channel) {
  if (channel.encoding === "json") return (bytes) => JSON.parse(utf8.decode(bytes));
  if (channel.encoding === "cdr") {
    if (channel.schemaEncoding !== "ros2msg") {
      throw new Error(`cannot decode cdr with schema encoding "${channel.schemaEncoding}"`);
    }
    const reader = new MessageReader(ros2Definitions(channel.schema));
    return (bytes) => reader.readMessage(bytes);
  }
  throw new Error(`cannot decode message encoding "${channel.encoding}"`);
}

/** JSON.stringify replacer for decoded messages (see header comment). */
const jsonReplacer = (_key, v) =>
  typeof v === "bigint" ? v.toString() : ArrayBuffer.isView(v) ? Array.from(v) : v;

function parseArgs(argv) {
  const args = { seconds: 10, quietMs: undefined, topics: undefined, values: undefined, expectChannels: 1 };
  const number = (name, v, min) => {
    const n = Number(v);
    if (v === undefined || v === "" || !Number.isFinite(n) || n < min) throw new Error(`${name} wants a number >= ${min}, got ${v}`);
    return n;
  };
  for (let i = 0; i < argv.length; i++) {
    const a = argv[i];
    const v = argv[++i];
    switch (a) {
      case "--url": args.url = v; break;
      case "--subprotocol": args.subprotocol = v; break;
      case "--seconds": args.seconds = number(a, v, 0); break;
      case "--quiet-ms": args.quietMs = number(a, v, 1); break;
      case "--topics": args.topics = new RegExp(v ?? ""); break;
      case "--values": args.values = v; break;
      case "--expect-channels": args.expectChannels = Math.floor(number(a, v, 0)); break;
      case "--period-ms": args.periodMs = number(a, v, 0.001); break;
      default: throw new Error(`unexpected argument ${a}`);
    }
    if (v === undefined) throw new Error(`${a} wants a value`);
  }
  if (!args.url || !args.subprotocol) {
    throw new Error("usage: node foxglove_client.mjs --url ws://HOST:PORT --subprotocol NAME [--seconds S] " +
      "[--quiet-ms MS] [--topics REGEX] [--values FILE.jsonl] [--expect-channels N] [--period-ms P]");
  }
  return args;
}

const print = (obj) => new Promise((resolve) => process.stdout.write(JSON.stringify(obj) + "\n", resolve));

let args;
try {
  args = parseArgs(process.argv.slice(2));
} catch (e) {
  await print({ error: e.message });
  process.exit(2);
}

// --- state --------------------------------------------------------------------------------------
let opened = false;
let stopping = false;
let protocol = null;
let serverInfo = null;
let closed = null;
const channels = new Map(); // channel id -> {info (output), decode | decodeError}
const allChannels = []; // every advertisement, in order (a reused id after unadvertise adds one)
const subscriptions = new Map(); // subscription id -> channel entry (kept after unadvertise)
let subscribedCount = 0;
let readyPrinted = false;
const topicStats = new Map(); // topic -> {count, first, last (bigint), outOfOrder}
let messageCount = 0;
let timeMessages = 0;
let lastTime = null;
const statuses = [];
let decodeErrors = 0;
let firstDecodeError = null;
let protocolErrors = 0;
let firstProtocolError = null;
let unknownSubscriptions = 0;

let values = null; // buffered JSON lines writer
let valuesBuf = "";
if (args.values) {
  values = createWriteStream(args.values, { highWaterMark: 1 << 20 });
  values.on("error", (e) => { console.error(`cannot write ${args.values}: ${e.message}`); values = null; });
}
const flushValues = () => {
  if (values && valuesBuf.length > 0) values.write(valuesBuf);
  valuesBuf = "";
};

const maybeReady = () => {
  if (!readyPrinted && opened && subscribedCount >= args.expectChannels) {
    readyPrinted = true;
    process.stderr.write("ready\n");
  }
};

// --- connection ---------------------------------------------------------------------------------
const ws = new WebSocket(args.url, [args.subprotocol]);
const client = new FoxgloveClient({ ws });
let connectError = null;

client.on("open", () => {
  opened = true;
  protocol = ws.protocol;
  maybeReady();
});

client.on("error", (err) => {
  const text = err?.message ?? String(err);
  if (!opened) {
    connectError ??= text;
    return;
  }
  protocolErrors++;
  firstProtocolError ??= text;
});

client.on("close", (event) => {
  if (!opened) {
    fail(connectError ?? `connection closed before opening (code ${event.code})`);
  } else if (!stopping) {
    closed = { code: event.code, reason: String(event.reason ?? "") };
    stop();
  }
});

client.on("serverInfo", (msg) => {
  const { op: _op, ...info } = msg;
  serverInfo = info;
});

client.on("status", (msg) => {
  statuses.push({ level: msg.level, message: msg.message, id: msg.id ?? null });
});

client.on("advertise", (advertised) => {
  for (const ch of advertised) {
    const entry = {
      info: {
        id: ch.id,
        topic: ch.topic,
        encoding: ch.encoding,
        schemaName: ch.schemaName,
        schemaEncoding: ch.schemaEncoding ?? null,
        subscribed: false,
        unadvertised: false,
      },
      topic: ch.topic,
      decode: null,
      decodeError: null,
    };
    const old = channels.get(ch.id);
    if (old && !old.info.unadvertised) {
      // Re-advertised without an unadvertise: keep the existing subscription, refresh the decoder.
      Object.assign(old.info, entry.info, { subscribed: old.info.subscribed });
      setDecoder(old, ch);
      continue;
    }
    channels.set(ch.id, entry);
    allChannels.push(entry);
    setDecoder(entry, ch);
    if (!stopping && (!args.topics || args.topics.test(ch.topic))) {
      subscriptions.set(client.subscribe(ch.id), entry);
      entry.info.subscribed = true;
      subscribedCount++;
    }
  }
  maybeReady();
});

function setDecoder(entry, ch) {
  try {
    entry.decode = makeDecoder(ch);
    entry.decodeError = null;
  } catch (e) {
    entry.decode = null;
    entry.decodeError = `cannot decode "${ch.topic}": ${e.message}`;
  }
}

client.on("unadvertise", (ids) => {
  for (const id of ids) {
    const entry = channels.get(id);
    if (entry) entry.info.unadvertised = true;
  }
});

client.on("message", ({ subscriptionId, timestamp, data }) => {
  if (stopping) return;
  const entry = subscriptions.get(subscriptionId);
  if (!entry) {
    unknownSubscriptions++;
    return;
  }
  messageCount++;
  const topic = entry.topic;
  let st = topicStats.get(topic);
  if (!st) {
    st = { count: 0, first: timestamp, last: timestamp, outOfOrder: 0 };
    topicStats.set(topic, st);
  } else if (timestamp < st.last) {
    st.outOfOrder++;
  }
  st.count++;
  st.last = timestamp;

  let message;
  try {
    if (!entry.decode) throw new Error(entry.decodeError);
    message = entry.decode(new Uint8Array(data.buffer, data.byteOffset, data.byteLength));
  } catch (e) {
    decodeErrors++;
    firstDecodeError ??= `${topic} @ ${timestamp}: ${e?.message ?? e}`;
    return;
  }
  if (args.periodMs !== undefined && message?.header?.stamp) {
    const stamp = BigInt(message.header.stamp.sec) * 1000000000n + BigInt(message.header.stamp.nanosec);
    if (stamp !== timestamp) st.stampMismatch = (st.stampMismatch ?? 0) + 1;
    if (st.prevStamp !== undefined) {
      const gapMs = Number(stamp - st.prevStamp) / 1e6;
      if (gapMs > 1.5 * args.periodMs) {
        st.stampGaps = (st.stampGaps ?? 0) + 1;
        st.stampMissing = (st.stampMissing ?? 0) + Math.round(gapMs / args.periodMs) - 1;
      }
    }
    st.prevStamp = stamp;
  }
  if (values) {
    valuesBuf += `{"topic":${JSON.stringify(topic)},"timestamp":"${timestamp}","message":${JSON.stringify(message, jsonReplacer)}}\n`;
    if (valuesBuf.length >= 1 << 18) flushValues();
  }
});

client.on("time", ({ timestamp }) => {
  if (stopping) return;
  timeMessages++;
  lastTime = timestamp.toString();
});

// --- stopping -----------------------------------------------------------------------------------
const timers = [];
timers.push(setTimeout(() => (opened ? stop() : fail(`no connection within ${args.seconds} s`)), args.seconds * 1000));
if (args.quietMs !== undefined) {
  let seen = -1;
  let quietSince = 0;
  const step = Math.max(1, Math.floor(args.quietMs / 5));
  timers.push(setInterval(() => {
    if (messageCount === 0) return;
    const now = Date.now();
    if (messageCount !== seen) {
      seen = messageCount;
      quietSince = now;
    } else if (now - quietSince >= args.quietMs) {
      stop();
    }
  }, step));
}
process.on("SIGTERM", () => stop());
process.on("SIGINT", () => stop());

function clearTimers() {
  for (const t of timers) clearTimeout(t);
}

async function fail(text) {
  if (stopping) return;
  stopping = true;
  clearTimers();
  try { ws.terminate(); } catch { /* not connected */ }
  await print({ error: `cannot connect to ${args.url} (subprotocol ${args.subprotocol}): ${text}` });
  process.exit(1);
}

async function stop() {
  if (stopping) return;
  stopping = true;
  clearTimers();
  // Close politely (waits at most 1 s for the server's close frame) unless the server did already.
  if (ws.readyState === WebSocket.OPEN || ws.readyState === WebSocket.CONNECTING) {
    await new Promise((resolve) => {
      const t = setTimeout(resolve, 1000);
      ws.once("close", () => { clearTimeout(t); resolve(); });
      try { ws.close(1000, "done"); } catch { ws.terminate(); }
    });
  }
  if (values) {
    flushValues();
    await new Promise((resolve) => values.end(resolve));
  }
  const perTopic = (f) => Object.fromEntries([...topicStats].map(([topic, st]) => [topic, f(st)]));
  await print({
    protocol,
    serverInfo,
    channels: allChannels.map((e) => e.info),
    counts: perTopic((st) => st.count),
    firstTimestamp: perTopic((st) => st.first.toString()),
    lastTimestamp: perTopic((st) => st.last.toString()),
    outOfOrder: perTopic((st) => st.outOfOrder),
    stampGaps: perTopic((st) => st.stampGaps ?? 0),
    stampMissing: perTopic((st) => st.stampMissing ?? 0),
    stampMismatch: perTopic((st) => st.stampMismatch ?? 0),
    timeMessages,
    lastTime,
    statuses,
    decodeErrors,
    firstDecodeError,
    protocolErrors,
    firstProtocolError,
    unknownSubscriptions,
    closed,
  });
  process.exit(0);
}
