// An MCAP file antkit wrote, held against the official readers (issue 42, "Checked by tools we did
// not write"): @mcap/core's indexed reader (magic, footer, summary CRC, chunk indexes, chunk CRCs)
// and its stream reader (every record in file order, the data section's CRC recomputed here with
// @foxglove/crc), every foxglove.* message against @foxglove/schemas' JSON Schema (ajv).
//   node check_mcap.mjs FILE.mcap [TOPIC=COUNT ...] [error@STEP]
// TOPIC=COUNT: that many messages on TOPIC; error@STEP: exactly one foxglove.Log of level ERROR
// (4) on /log, with sequence STEP, at the log time of that step's /recorded/step message (or, past
// the recorded steps, the last one's); in a file without /recorded/step (a tour, a run), at the
// log time of the /pose message with sequence STEP.
// Also checks: the Statistics equal the messages read; every message of the stream is reached
// through the index; schema encoding jsonschema, message encoding json; each message's JSON parses
// and its timestamp {sec, nsec} is its log time; sequence is its step where it has one. Exits 1 with
// the first failure; prints one line per channel.
import { readFile } from "node:fs/promises";
import { createRequire } from "node:module";

const require = createRequire(import.meta.url);
function load(name) {
  try {
    return require(name);
  } catch {
    console.error(
      `check_mcap: cannot load ${name}: the node packages are not installed; run \`scripts/bootstrap.sh --node-packages\` ` +
        "(or `npm ci` in the checkout)",
    );
    process.exit(1);
  }
}
const { McapIndexedReader, McapStreamReader } = load("@mcap/core");
const { crc32 } = load("@foxglove/crc");
const foxglove = load("@foxglove/schemas/jsonschema");
const Ajv = load("ajv").default;

const [file, ...expectations] = process.argv.slice(2);
const fail = (what) => {
  console.error(`check_mcap: ${file}: ${what}`);
  process.exit(1);
};
const bytes = new Uint8Array(await readFile(file));

// The indexed reader, through the summary.
const readable = {
  size: async () => BigInt(bytes.length),
  read: async (offset, size) => bytes.subarray(Number(offset), Number(offset + size)),
};
let reader;
try {
  reader = await McapIndexedReader.Initialize({ readable });
} catch (e) {
  fail(`the indexed reader refuses the file: ${e.message}`);
}
const ajv = new Ajv({ strict: false });
const validators = new Map();
for (const schema of reader.schemasById.values()) {
  if (schema.encoding !== "jsonschema") fail(`schema ${schema.name}: encoding ${schema.encoding}`);
  JSON.parse(new TextDecoder().decode(schema.data));
  if (schema.name.startsWith("foxglove.")) {
    const official = foxglove[schema.name.slice("foxglove.".length)];
    if (!official) fail(`schema ${schema.name} is not one of Foxglove's`);
    validators.set(schema.id, ajv.compile(official));
  }
}
const indexed = new Map(); // topic -> count
const seen = [];
const errors = []; // [sequence, log time] of /log's ERROR messages
const stepTimes = new Map(); // step -> log time on /recorded/step
const poseTimes = new Map(); // sequence -> log time on /pose
for await (const m of reader.readMessages()) {
  const channel = reader.channelsById.get(m.channelId);
  if (channel.messageEncoding !== "json") fail(`${channel.topic}: encoding ${channel.messageEncoding}`);
  let json;
  try {
    json = JSON.parse(new TextDecoder().decode(m.data));
  } catch (e) {
    fail(`${channel.topic}: a message that is not JSON: ${e.message}`);
  }
  const validate = validators.get(channel.schemaId);
  if (validate && !validate(json))
    fail(`${channel.topic}: not a valid ${reader.schemasById.get(channel.schemaId).name}: ` +
         ajv.errorsText(validate.errors));
  const stamp = json.timestamp ?? json.entities?.[0]?.timestamp;
  if (stamp && BigInt(stamp.sec) * 1000000000n + BigInt(stamp.nsec) !== m.logTime)
    fail(`${channel.topic}: timestamp ${stamp.sec}.${stamp.nsec} is not the log time ${m.logTime}`);
  if (json.step !== undefined && json.step !== m.sequence)
    fail(`${channel.topic}: sequence ${m.sequence} is not step ${json.step}`);
  if (m.publishTime !== m.logTime) fail(`${channel.topic}: publish time is not the log time`);
  if (channel.topic === "/log" && json.level === 4) errors.push([m.sequence, m.logTime]);
  if (channel.topic === "/recorded/step") stepTimes.set(json.step, m.logTime);
  if (channel.topic === "/pose") poseTimes.set(m.sequence, m.logTime);
  indexed.set(channel.topic, (indexed.get(channel.topic) ?? 0) + 1);
  seen.push(`${m.channelId}:${m.logTime}:${m.sequence}`);
}

// The statistics against what was read.
const stats = reader.statistics;
if (!stats) fail("no Statistics record");
let total = 0;
for (const n of indexed.values()) total += n;
if (BigInt(total) !== stats.messageCount) fail(`statistics say ${stats.messageCount} messages, read ${total}`);
for (const [id, n] of stats.channelMessageCounts) {
  const topic = reader.channelsById.get(id).topic;
  if (BigInt(indexed.get(topic) ?? 0) !== n) fail(`${topic}: statistics say ${n}, read ${indexed.get(topic) ?? 0}`);
}
if (stats.chunkCount !== reader.chunkIndexes.length) fail("chunk count is not the chunk indexes'");

// The stream reader, record by record; the data section's CRC.
const stream = new McapStreamReader({ validateCrcs: true });
stream.append(bytes);
const streamed = [];
let dataEnd = null;
for (let r; (r = stream.nextRecord()); ) {
  if (r.type === "Message") streamed.push(`${r.channelId}:${r.logTime}:${r.sequence}`);
  if (r.type === "DataEnd") dataEnd = r;
}
if (!stream.done()) fail("the stream reader did not reach the end magic");
if (!dataEnd) fail("no DataEnd record");
// DataEnd is the record before the summary: its CRC covers every byte before it.
const summaryStart = Number(reader.footer.summaryStart);
const dataEndAt = summaryStart - (1 + 8 + 4);
if (bytes[dataEndAt] !== 0x0f) fail("DataEnd is not just before the summary");
const crc = crc32(bytes.subarray(0, dataEndAt));
if (dataEnd.dataSectionCrc !== crc) fail(`data section CRC ${dataEnd.dataSectionCrc}, computed ${crc}`);
const sortKey = (a, b) => (a < b ? -1 : a > b ? 1 : 0);
if (JSON.stringify([...streamed].sort(sortKey)) !== JSON.stringify([...seen].sort(sortKey)))
  fail(`the index reaches ${seen.length} messages, the file holds ${streamed.length}`);

for (const e of expectations) {
  if (e.startsWith("error@")) {
    const step = Number(e.slice("error@".length));
    if (errors.length !== 1 || errors[0][0] !== step)
      fail(`expected one ERROR log at step ${step}, found ${JSON.stringify(errors.map((x) => x[0]))}`);
    const last = [...stepTimes.keys()].reduce((a, b) => Math.max(a, b), -1);
    const t =
      stepTimes.size > 0 ? stepTimes.get(step) ?? stepTimes.get(last) : poseTimes.get(step);
    if (errors[0][1] !== t) fail(`the ERROR log's time ${errors[0][1]} is not step ${step}'s ${t}`);
    continue;
  }
  const [topic, count] = e.split("=");
  if ((indexed.get(topic) ?? 0) !== Number(count))
    fail(`${topic}: ${indexed.get(topic) ?? 0} messages, expected ${count}`);
}
for (const [topic, n] of [...indexed].sort()) {
  const c = [...reader.channelsById.values()].find((ch) => ch.topic === topic);
  console.log(`${topic} ${reader.schemasById.get(c.schemaId).name} ${n}`);
}
