// ROS 2 bags written by writers antkit did not write (issue 42, "Checked by tools we did not
// write"), for the bag readers' tests: @mcap/core (MCAP, ros2 profile), @foxglove/wasm-zstd and
// lz4js (compressed chunks), @foxglove/rosmsg2-serialization (CDR, little-endian XCDR1) with the
// ROS 2 Humble definitions of @foxglove/rosmsg-msgs-common, sql.js (rosbag2's .db3 tables).
//   node write_bags.mjs OUT_DIR
// Writes (every pose topic's walk is given by walk1/walk2 below; tests/support/ros_bags.hpp says
// what the tests expect of them):
//   walk1.mcap        uncompressed chunks: /odom (Odometry), /pose (PoseStamped), /amcl_pose
//                     (PoseWithCovarianceStamped), /tf (TFMessage: odom->base_link and
//                     base_link->laser), /cmd_vel (Twist: 1 m/s, 0.5 rad/s), /chatter
//                     (std_msgs/msg/String)
//   walk2_zstd.mcap   /odom, zstd chunks        walk2_lz4.mcap  /odom, lz4 chunks
//   walk1.db3         /odom and /chatter        walk2_bag/      metadata.yaml + walk2_bag_0.db3
//   tour.mcap, tour_repeat.mcap  /pose (PoseStamped): tours for `check stc --bag` (below)
//   cover.mcap, cover_collide.mcap  /r0/pose, /r1/pose: two robots for `check cover --bag`
// Bag time of message i: 1.7e18 + i * 0.1 s; header.stamp: bag time - 0.25 s.
import { mkdirSync, writeFileSync } from "node:fs";
import { createRequire } from "node:module";

const require = createRequire(import.meta.url);
const { McapWriter, TempBuffer } = require("@mcap/core");
const { MessageWriter } = require("@foxglove/rosmsg2-serialization");
const { ros2humble } = require("@foxglove/rosmsg-msgs-common");
const zstd = require("@foxglove/wasm-zstd");
const lz4 = require("lz4js");
const initSqlJs = require("sql.js");

const out = process.argv[2];
mkdirSync(out, { recursive: true });
await zstd.isLoaded;
const SQL = await initSqlJs();

// Walk 1: along the x axis, (0, 0) to (10, 0), heading 0. Walk 2: a zigzag about it,
// (0.25 + i, (-1)^i) for i = 0..9, heading pi/4: nine proper crossings of walk 1.
const walk1 = Array.from({ length: 11 }, (_, i) => ({ x: i, y: 0, yaw: 0 }));
const walk2 = Array.from({ length: 10 }, (_, i) => ({ x: 0.25 + i, y: i % 2 ? -1 : 1, yaw: Math.PI / 4 }));

const T0 = 1700000000000000000n;
const bagTime = (i) => T0 + BigInt(i) * 100000000n;
const stampOf = (i) => {
  const ns = bagTime(i) - 250000000n;
  return { sec: Number(ns / 1000000000n), nanosec: Number(ns % 1000000000n) };
};

function writerFor(type) {
  const name = type.replace("/msg/", "/");
  const root = ros2humble[name];
  const rest = Object.entries(ros2humble)
    .filter(([n]) => n !== name)
    .map(([n, d]) => ({ ...d, name: n }));
  return new MessageWriter([root, ...rest]);
}
const writers = {};
const cdr = (type, msg) => (writers[type] ??= writerFor(type)).writeMessage(msg);

const header = (i, frame) => ({ stamp: stampOf(i), frame_id: frame });
const pose = (p) => ({
  position: { x: p.x, y: p.y, z: 0 },
  orientation: { x: 0, y: 0, z: Math.sin(p.yaw / 2), w: Math.cos(p.yaw / 2) },
});
const zeros = (n) => new Float64Array(n);
const odometry = (p, i) => ({
  header: header(i, "odom"),
  child_frame_id: "base_link",
  pose: { pose: pose(p), covariance: zeros(36) },
  twist: { twist: { linear: { x: 0, y: 0, z: 0 }, angular: { x: 0, y: 0, z: 0 } }, covariance: zeros(36) },
});
const transform = (p, i, parent, child) => ({
  header: header(i, parent),
  child_frame_id: child,
  transform: { translation: { x: p.x, y: p.y, z: 0 }, rotation: pose(p).orientation },
});

// [topic, type, messages: [data]] for a walk.
function topics(walk, all) {
  const list = [["/odom", "nav_msgs/msg/Odometry", walk.map((p, i) => cdr("nav_msgs/msg/Odometry", odometry(p, i)))]];
  if (!all) return list;
  list.push(["/pose", "geometry_msgs/msg/PoseStamped",
    walk.map((p, i) => cdr("geometry_msgs/msg/PoseStamped", { header: header(i, "map"), pose: pose(p) }))]);
  list.push(["/amcl_pose", "geometry_msgs/msg/PoseWithCovarianceStamped",
    walk.map((p, i) => cdr("geometry_msgs/msg/PoseWithCovarianceStamped",
      { header: header(i, "map"), pose: { pose: pose(p), covariance: zeros(36) } }))]);
  list.push(["/tf", "tf2_msgs/msg/TFMessage",
    walk.map((p, i) => cdr("tf2_msgs/msg/TFMessage", { transforms: [
      transform({ x: 0.1, y: 0, yaw: 0 }, i, "base_link", "laser"), transform(p, i, "odom", "base_link")] }))]);
  list.push(["/cmd_vel", "geometry_msgs/msg/Twist",
    walk.map(() => cdr("geometry_msgs/msg/Twist", { linear: { x: 1, y: 0, z: 0 }, angular: { x: 0, y: 0, z: 0.5 } }))]);
  list.push(["/chatter", "std_msgs/msg/String", walk.map(() => cdr("std_msgs/msg/String", { data: "hello" }))]);
  return list;
}

async function writeMcap(path, list, compression) {
  const buffer = new TempBuffer();
  const compressChunk =
    compression === "zstd" ? (d) => ({ compression: "zstd", compressedData: zstd.compress(d, 3) })
    : compression === "lz4" ? (d) => ({ compression: "lz4", compressedData: new Uint8Array(lz4.compress(d)) })
    : undefined;
  const w = new McapWriter({ writable: buffer, useChunks: true, chunkSize: 4096, compressChunk });
  await w.start({ profile: "ros2", library: "write_bags.mjs" });
  const ids = [];
  for (const [topic, type] of list) {
    const schemaId = await w.registerSchema({ name: type, encoding: "ros2msg", data: new TextEncoder().encode("# " + type) });
    ids.push(await w.registerChannel({ schemaId, topic, messageEncoding: "cdr", metadata: new Map() }));
  }
  const n = list[0][2].length;
  for (let i = 0; i < n; ++i)
    for (let k = 0; k < list.length; ++k)
      await w.addMessage({ channelId: ids[k], sequence: i, logTime: bagTime(i), publishTime: bagTime(i), data: list[k][2][i] });
  await w.end();
  writeFileSync(path, buffer.get());
}

function writeDb3(path, list) {
  const db = new SQL.Database();
  db.run(`CREATE TABLE schema(schema_version INTEGER PRIMARY KEY, ros_distro TEXT NOT NULL);
          CREATE TABLE metadata(id INTEGER PRIMARY KEY, metadata_version INTEGER NOT NULL, metadata TEXT NOT NULL);
          CREATE TABLE topics(id INTEGER PRIMARY KEY, name TEXT NOT NULL, type TEXT NOT NULL,
            serialization_format TEXT NOT NULL, offered_qos_profiles TEXT NOT NULL, type_description_hash TEXT NOT NULL);
          CREATE TABLE messages(id INTEGER PRIMARY KEY, topic_id INTEGER NOT NULL, timestamp INTEGER NOT NULL, data BLOB NOT NULL);
          INSERT INTO schema VALUES (4, 'humble');`);
  list.forEach(([topic, type], k) => db.run("INSERT INTO topics VALUES (?, ?, ?, 'cdr', '', '')", [k + 1, topic, type]));
  const n = list[0][2].length;
  // Inserted in reverse: the reader orders by timestamp, not by row.
  for (let i = n - 1; i >= 0; --i)
    list.forEach(([, , data], k) =>
      db.run("INSERT INTO messages (topic_id, timestamp, data) VALUES (?, ?, ?)", [k + 1, bagTime(i).toString(), data[i]]));
  writeFileSync(path, Buffer.from(db.export()));
  db.close();
}

await writeMcap(`${out}/walk1.mcap`, topics(walk1, true), undefined);
await writeMcap(`${out}/walk2_zstd.mcap`, topics(walk2, false), "zstd");
await writeMcap(`${out}/walk2_lz4.mcap`, topics(walk2, false), "lz4");
writeDb3(`${out}/walk1.db3`, topics(walk1, true).filter(([t]) => t === "/odom" || t === "/chatter"));
mkdirSync(`${out}/walk2_bag`, { recursive: true });
writeDb3(`${out}/walk2_bag/walk2_bag_0.db3`, topics(walk2, false));
writeFileSync(`${out}/walk2_bag/metadata.yaml`, `rosbag2_bagfile_information:
  version: 5
  storage_identifier: sqlite3
  duration:
    nanoseconds: 900000000
  starting_time:
    nanoseconds_since_epoch: ${T0}
  message_count: 10
  topics_with_message_count:
    - topic_metadata:
        name: /odom
        type: nav_msgs/msg/Odometry
        serialization_format: cdr
        offered_qos_profiles: ""
      message_count: 10
  compression_format: ""
  compression_mode: ""
  relative_file_paths:
    - walk2_bag_0.db3
`);
// Tours on the tests' 4 x 2 free ROS map (resolution 0.5 m, origin (-1, -2, 0); cell (x, y) with y
// down from the first row has its centre at (-0.75 + 0.5 x, -1.25 - 0.5 y)): /pose at the centres
// of cells (0,0), (3,0), (3,1), (0,1) (tour.mcap: filled in, every cell once) and (0,0), (3,0),
// (1,0) (tour_repeat.mcap: cell (2,0) entered twice).
const centre = ([x, y]) => ({ x: -0.75 + 0.5 * x, y: -1.25 - 0.5 * y, yaw: 0 });
for (const [name, cells] of [["tour", [[0, 0], [3, 0], [3, 1], [0, 1]]], ["tour_repeat", [[0, 0], [3, 0], [1, 0]]]])
  await writeMcap(`${out}/${name}.mcap`, [["/pose", "geometry_msgs/msg/PoseStamped",
    cells.map(centre).map((p, i) => cdr("geometry_msgs/msg/PoseStamped", { header: header(i, "map"), pose: pose(p) }))]], undefined);
// Two robots for `check cover --bag`, on the same map: /r0/pose and /r1/pose, one pose each at bag
// times 0 and 0.1 s. cover.mcap: r0 along row 0 from (0,0) to (3,0), r1 along row 1 from (3,1) to
// (0,1) (never on one cell). cover_collide.mcap: r0 from (0,0) to (3,0), r1 from (3,0) to (0,0) on
// the same row: at 0.05 s (half-way) r0 enters (2,0), where r1 already is.
const poses = (cells) => cells.map(centre).map((p, i) => cdr("geometry_msgs/msg/PoseStamped", { header: header(i, "map"), pose: pose(p) }));
for (const [name, a, b] of [["cover", [[0, 0], [3, 0]], [[3, 1], [0, 1]]], ["cover_collide", [[0, 0], [3, 0]], [[3, 0], [0, 0]]]])
  await writeMcap(`${out}/${name}.mcap`, [["/r0/pose", "geometry_msgs/msg/PoseStamped", poses(a)],
                                          ["/r1/pose", "geometry_msgs/msg/PoseStamped", poses(b)]], undefined);
console.log("write_bags: wrote", out);
