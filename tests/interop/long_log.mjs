// A long hardware log for interop.mcap: the committed recording's header, then its 120 step
// records over and over, renumbered and retimed (1 us apart), and a stop record.
//   node long_log.mjs SOURCE.jsonl OUT.jsonl STEPS
import { readFileSync, writeFileSync } from "node:fs";

const [source, out, count] = process.argv.slice(2);
const lines = readFileSync(source, "utf8").split("\n").filter((l) => l.length > 0);
const steps = lines.filter((l) => l.startsWith('{"step":'));
const n = Number(count);
let text = lines[0] + "\n";
for (let i = 0; i < n; ++i) {
  const r = steps[i % steps.length];
  text += `{"step":${i},"t_ns":${i * 1000}${r.slice(r.indexOf(',"io":'))}\n`;
}
text += `{"stop":"done","step":${n},"io":[]}\n`;
writeFileSync(out, text);
