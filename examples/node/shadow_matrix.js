// A shadow matrix written in JavaScript, graded by shadowproof through its JSON-lines protocol:
//
//   shadowproof cases --op shadow-matrix --type f64 --count 1000 --seed 1 > cases.jsonl
//   node shadow_matrix.js cases.jsonl > outputs.jsonl
//   shadowproof grade cases.jsonl outputs.jsonl
//
// M = (P·L) I − L Pᵀ, row-major, column vectors (shadowproof's canonical form). JavaScript
// numbers are doubles; for f32 cases every operation is rounded to float with Math.fround,
// as a float shader would. Inputs arrive as hex-float strings ("0x1.8p+0"), which JavaScript
// cannot parse itself, so hexFloat() below decodes them exactly.
"use strict";
const fs = require("fs");

// Exact value of a C99 hex float string: sign, hex significand, binary exponent.
function hexFloat(text) {
  const m = /^([+-]?)0x([0-9a-f]+)(?:\.([0-9a-f]*))?p([+-]?\d+)$/i.exec(text);
  if (!m) {
    const x = Number(text);  // "inf", "-inf" or a decimal
    if (text === "inf") return Infinity;
    if (text === "-inf") return -Infinity;
    if (Number.isNaN(x)) throw new Error(`not a number: ${text}`);
    return x;
  }
  const digits = m[2] + (m[3] || "");
  let value = 0;
  for (const d of digits) value = value * 16 + parseInt(d, 16);  // ≤ 53 bits: exact
  const exponent = parseInt(m[4], 10) - 4 * (m[3] ? m[3].length : 0);
  // Scale in steps so that subnormal results are not rounded twice.
  let result = value;
  let e = exponent;
  while (e > 0) { const s = Math.min(e, 1000); result *= 2 ** s; e -= s; }
  while (e < 0) { const s = Math.max(e, -1000); result *= 2 ** s; e -= s; }
  return m[1] === "-" ? -result : result;
}

function shadowMatrix(P, L, round) {
  const r = round;
  let s = r(P[0] * L[0]);
  for (let i = 1; i < 4; i++) s = r(s + r(P[i] * L[i]));
  const M = [];
  for (let i = 0; i < 4; i++)
    for (let j = 0; j < 4; j++) M.push(r((i === j ? s : 0) - r(L[i] * P[j])));
  return M;
}

// Non-finite numbers have no JSON spelling: the protocol takes the strings "nan", "inf", "-inf".
function toJson(x) {
  if (Number.isNaN(x)) return "nan";
  if (x === Infinity) return "inf";
  if (x === -Infinity) return "-inf";
  return x;
}

const path = process.argv[2];
if (!path) {
  process.stderr.write("usage: node shadow_matrix.js cases.jsonl > outputs.jsonl\n");
  process.exit(2);
}
const out = [];
for (const line of fs.readFileSync(path, "utf8").split("\n")) {
  if (!line.trim()) continue;
  const c = JSON.parse(line);
  if (c.op !== "shadow-matrix") throw new Error(`case ${c.id}: this program only computes shadow-matrix`);
  const round = c.type === "f32" ? Math.fround : (x) => x;
  const M = shadowMatrix(c.plane.map(hexFloat), c.light.map(hexFloat), round);
  out.push(JSON.stringify({ id: c.id, output: M.map(toJson) }));
}
process.stdout.write(out.join("\n") + "\n");
