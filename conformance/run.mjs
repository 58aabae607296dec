// The conformance table: grades every adapter (conformance/README.md) against shadowproof's
// exact answers and writes docs/conformance.md. Run through conformance/run.sh, which builds
// what this needs; by hand:
//
//   node conformance/run.mjs --shadowproof BUILD/shadowproof --vk-build VKBUILD
//        [--cases N] [--seed S] [--out docs/conformance.md] [--sample]
//
// Three kinds of adapters, all graded the same way (shadowproof's own grade, never a
// tolerance of ours): JavaScript libraries (js/adapters.mjs: `shadowproof cases`, the library,
// `shadowproof grade --json`), C++ libraries built into shadowproof (src/impls/: `shadowproof
// check --impl NAME --json`), and shaders on a Vulkan driver (vulkan/: cases, the runner,
// grade). --sample grades a few cases of every adapter and fails when any adapter cannot be
// run or graded (what CI runs); the full run writes the table.
import { execFileSync, spawnSync } from "node:child_process";
import { copyFileSync, existsSync, mkdtempSync, writeFileSync, rmSync } from "node:fs";
import { tmpdir } from "node:os";
import { join, dirname } from "node:path";
import { fileURLToPath } from "node:url";

const here = dirname(fileURLToPath(import.meta.url));
const args = process.argv.slice(2);
const option = (name, fallback) => {
  const i = args.indexOf(name);
  return i >= 0 ? args[i + 1] : fallback;
};
const sample = args.includes("--sample");
const shadowproof = option("--shadowproof");
const vkBuild = option("--vk-build");
const cases = Number(option("--cases", sample ? "30" : "3000"));
const seed = option("--seed", "1");
const out = option("--out", sample ? null : join(here, "..", "docs", "conformance.md"));
if (!shadowproof) {
  process.stderr.write("usage: node run.mjs --shadowproof PATH [--vk-build DIR] [--cases N] [--seed S] [--out FILE] [--sample]\n");
  process.exit(2);
}
// Under ctest: skipped (exit 77), and said so, when conformance/setup.sh has not run.
if (args.includes("--skip-when-not-set-up") &&
    (!existsSync(join(here, "js", "node_modules", "three")) || !vkBuild || !existsSync(join(vkBuild, "shadowproof_vk_runner")))) {
  process.stderr.write("conformance sample skipped: run conformance/setup.sh first (npm ci, the Vulkan runner)\n");
  process.exit(77);
}
const work = mkdtempSync(join(tmpdir(), "shadowproof-conformance-"));

function run(file, argv, options = {}) {
  const r = spawnSync(file, argv, { encoding: "utf8", maxBuffer: 1 << 30, ...options });
  if (r.status !== 0 && !(options.okStatus ?? [0]).includes(r.status))
    throw new Error(`${file} ${argv.join(" ")} exited with ${r.status}: ${r.stderr}`);
  return r.stdout;
}

// ------------------------------------------------------------------------------------------
// Verdicts. A grade today reports per input class the largest error in ulps and the counts of
// non-finite outputs (where the exact value is finite) and finite garbage (where it does not
// exist); the verdict summarises them in the order a user cares about. When `grade` reports
// a verdict of its own, that one is shown instead.

const SHARP = 4;          // a few roundings
const WRONG = 2 ** 20;    // more than 2^20 ulps: no correct digits left in f32, few in f64

function verdict(byClass) {
  if (byClass.verdict) return byClass.verdict;
  const regular = byClass.regular ?? {};
  const all = Object.values(byClass).filter((s) => s && typeof s === "object" && "max_ulps" in s);
  const max = (key) => Math.max(0, ...all.map((s) => s[key] ?? 0));
  const worstUlps = max("max_ulps");
  if ((regular.max_ulps ?? 0) > WRONG || (regular.nonfinite ?? 0) > 0 || (regular.garbage ?? 0) > 0 ||
      (regular.misclassified ?? 0) > 0)
    return "wrong on regular inputs";
  if (worstUlps === 0 && max("nonfinite") === 0 && max("garbage") === 0) return "correctly rounded";
  if (worstUlps > WRONG) return "unstable near degeneracies";
  if (worstUlps <= SHARP) return `within ${worstUlps} ulp${worstUlps === 1 ? "" : "s"}`;
  return `within ${worstUlps} ulps`;
}

function undefinedHandling(byClass) {
  const all = Object.values(byClass).filter((s) => s && typeof s === "object" && "max_ulps" in s);
  const nonfinite = all.reduce((n, s) => n + (s.nonfinite ?? 0), 0);
  const garbage = all.reduce((n, s) => n + (s.garbage ?? 0), 0);
  const parts = [];
  if (nonfinite) parts.push(`${nonfinite} non-finite`);
  if (garbage) parts.push(`${garbage} garbage`);
  return parts.join(", ") || "-";
}

// The worst case over all classes: the largest finite error when there is one (non-finite and
// garbage answers have their own column), else the first non-finite or garbage case.
function worstCase(byClass) {
  let worst = null;
  for (const s of Object.values(byClass)) {
    if (!s || typeof s !== "object" || !Array.isArray(s.worst)) continue;
    for (const w of s.worst) {
      const score = w.nonfinite || w.garbage ? -1 : (w.bits ?? 0);
      if (!worst || score > worst.score) worst = { ...w, score };
    }
  }
  return worst;
}

// ------------------------------------------------------------------------------------------
// The adapters

const rows = [];

function gradeFile(casesPath, outputsPath) {
  return JSON.parse(run(shadowproof, ["grade", casesPath, outputsPath, "--json"]));
}

function addRow(row, graded) {
  const byClass = { ...(graded.by_class ?? {}) };
  if (graded.verdict) byClass.verdict = graded.verdict;
  const summaries = Object.values(byClass).filter((s) => s && s.max_ulps !== undefined);
  rows.push({ ...row, verdict: verdict(byClass), undefinedHandling: undefinedHandling(byClass), worst: worstCase(byClass),
              maxUlps: Math.max(0, ...summaries.map((s) => s.max_ulps)), maxBits: Math.max(0, ...summaries.map((s) => s.max_bits)) });
}

// Adapters with the same operation, type and conventions grade the same cases: `shadowproof
// cases` runs once for each such combination and the file is copied for the others.
const casesWritten = new Map();
function writeCases(path, op, type, conventions, extra = []) {
  const argv = ["cases", "--op", op, "--type", type, "--count", String(cases), "--seed", seed, ...extra];
  for (const c of conventions) argv.push("--convention", c);
  const key = argv.join("\u0000");
  if (casesWritten.has(key)) {
    copyFileSync(casesWritten.get(key), path);
    return;
  }
  writeFileSync(path, run(shadowproof, argv));
  casesWritten.set(key, path);
}

// JavaScript: one node process per library and float type (Babylon's matrix precision is a
// process-wide switch).
const jsDir = join(here, "js");
const jsAdapters = run("node", [join(jsDir, "adapters.mjs"), "list"]).trim().split("\n").map((l) => JSON.parse(l));
const groups = new Map();
jsAdapters.forEach((a, i) => {
  const key = `${a.library}:${a.type}`;
  const casesPath = join(work, `js-${i}.cases.jsonl`);
  writeCases(casesPath, a.op, a.type, a.conventions);
  if (!groups.has(key)) groups.set(key, []);
  groups.get(key).push({ name: a.name, cases: casesPath, outputs: join(work, `js-${i}.outputs.jsonl`), adapter: a });
});
for (const jobs of groups.values()) {
  const jobsPath = join(work, `jobs-${rows.length}-${jobs[0].adapter.library}-${jobs[0].adapter.type}.json`);
  writeFileSync(jobsPath, JSON.stringify(jobs.map(({ adapter, ...j }) => j)));
  run("node", [join(jsDir, "adapters.mjs"), "batch", jobsPath]);
  for (const j of jobs) {
    const a = j.adapter;
    addRow({ kind: "JavaScript", library: a.library, version: a.version, function: a.function, op: a.op, type: a.type,
             conventions: a.conventions.join(", ") }, gradeFile(j.cases, j.outputs));
  }
}

// C++ libraries built into shadowproof: the engines, not shadowproof's own seed routines.
const engines = /^(glm|eigen|irrlicht|ogre|qt|osg)-/;
for (const name of run(shadowproof, ["check", "--list"]).trim().split("\n").filter((n) => engines.test(n))) {
  const doc = JSON.parse(run(shadowproof, ["check", "--impl", name, "--cases", String(cases), "--seed", seed, "--json"],
                             { okStatus: [0, 1] }));
  const byClass = {};
  let first = null;
  for (const r of doc.results) {
    byClass[r.class] = r;
    first ??= r;
  }
  const origin = first.origin;
  const conv = first.conventions;
  const conventions = [
    conv.storage !== "row-major" && `layout=${conv.storage}`, conv.vectors !== "column" && `vectors=${conv.vectors}`,
    `depth=${conv.depth}`, conv.handedness !== "right" && `handedness=${conv.handedness}`,
    conv.angle !== "radians" && `angle=${conv.angle}`, conv.normalises_plane && "normalises plane",
    conv.symmetric_view && "symmetric=true",
  ].filter(Boolean).join(", ");
  const library = { glm: "GLM", eigen: "Eigen", irrlicht: "Irrlicht", ogre: "Ogre", qt: "Qt 5", osg: "OpenSceneGraph" }[name.split("-")[0]];
  const version = (origin.match(/\d+(\.\d+)+/) ?? ["?"])[0];
  addRow({ kind: "C++", library, version, function: origin.replace(/^\S+ \S+ /, ""), op: first.op, type: first.type, conventions },
         { by_class: byClass });
}

// Shaders on a Vulkan driver.
if (vkBuild) {
  const runner = join(vkBuild, "shadowproof_vk_runner");
  const driver = run(runner, ["--describe"]).trim();
  const compilers = {
    glsl: run("glslc", ["--version"]).split("\n")[0],
    hlsl: run("glslangValidator", ["--version"]).split("\n")[0].replace(/^Glslang Version: /, "glslang "),
  };
  const shaders = [
    { file: "shadow_point.glsl.spv", source: "shadow_point.comp", lang: "glsl", op: "shadow-point", inputs: 11, outputs: 3, extra: ["--directional"] },
    { file: "shadow_point.hlsl.spv", source: "shadow_point.hlsl", lang: "hlsl", op: "shadow-point", inputs: 11, outputs: 3, extra: ["--directional"] },
    { file: "shadow_matrix.glsl.spv", source: "shadow_matrix.comp", lang: "glsl", op: "shadow-matrix", inputs: 8, outputs: 16, extra: [] },
    { file: "normal_matrix.glsl.spv", source: "normal_matrix.comp", lang: "glsl", op: "normal-matrix", inputs: 9, outputs: 9, extra: [] },
  ];
  for (const s of shaders) {
    const casesPath = join(work, `${s.file}.cases.jsonl`);
    const outputsPath = join(work, `${s.file}.outputs.jsonl`);
    writeCases(casesPath, s.op, "f32", [], s.extra);
    writeFileSync(outputsPath, run(runner, [join(vkBuild, s.file), "--inputs", String(s.inputs), "--outputs", String(s.outputs), casesPath]));
    const mesa = (driver.match(/Mesa [0-9.]+/) ?? [driver])[0];
    addRow({ kind: "shader", library: `${s.lang.toUpperCase()} shader on lavapipe`, version: `${mesa}, ${compilers[s.lang]}`,
             function: s.source,
             op: s.op, type: "f32", conventions: s.extra.includes("--directional") ? "directional lights" : "" },
           gradeFile(casesPath, outputsPath));
  }
}
rmSync(work, { recursive: true, force: true });

// ------------------------------------------------------------------------------------------
// The table

const count = (pred) => rows.filter(pred).length;
process.stderr.write(`graded ${rows.length} adapters: ${count((r) => r.verdict === "correctly rounded")} correctly rounded, ` +
                     `${count((r) => r.verdict === "wrong on regular inputs")} wrong on regular inputs\n`);
if (!out) process.exit(0);

const esc = (s) => String(s ?? "").replace(/\|/g, "\\|");
// Counts above 2^53 do not survive JSON.parse exactly; their size in bits does.
const ulpsText = (ulps, bits) => (ulps < 2 ** 53 ? String(ulps) : `≈ 2^${bits.toFixed(1)}`);
const worstText = (w) => {
  if (!w) return "-";
  const what = w.exact_defined === false ? "exact undefined" : `exact ${w.expected}`;
  const how = w.nonfinite ? "non-finite" : w.garbage ? "garbage" : `${ulpsText(w.ulps, w.bits)} ulps`;
  return `output ${w.output}: got ${w.got}, ${what} (${how})`;
};
const libraries = [...new Set(rows.map((r) => `${r.library} ${r.version}`))];
const verdicts = {};
for (const r of rows) verdicts[r.verdict] = (verdicts[r.verdict] ?? 0) + 1;
const lines = [];
lines.push("# Conformance of shipped libraries and shaders");
lines.push("");
lines.push("Generated by `conformance/run.sh` (see conformance/README.md); do not edit by hand. Every row");
lines.push(`grades ${cases} cases per adapter (seed ${seed}), a third each regular, near-degenerate and degenerate, against`);
lines.push("the exact answer for the very same float inputs (`shadowproof cases` / `grade`, or `check` for the");
lines.push("C++ libraries built into shadowproof). Each adapter calls the library's own function.");
lines.push("");
lines.push(`**${rows.length} adapters** over ${libraries.length} library builds and drivers: ` +
           Object.entries(verdicts).sort((a, b) => b[1] - a[1]).map(([v, n]) => `${n} ${v}`).join(", ") + ".");
lines.push("");
lines.push("Verdicts: *correctly rounded* — every defined output is the exact value rounded to the type;");
lines.push(`*within k ulps* — at most k units in the last place anywhere; *unstable near degeneracies* — fine on`);
lines.push(`regular inputs, more than 2^20 ulps on nearly degenerate ones; *wrong on regular inputs* — more than`);
lines.push("2^20 ulps, a non-finite value or garbage on ordinary inputs: a defect (docs/upstream/). The");
lines.push("*undefined outputs* column counts how the adapter answers where the exact value does not exist");
lines.push("(flat view volumes, singular matrices, parallel lights): a finite number there is *garbage*.");
lines.push("The reproducer prints the exact answer for the worst case's inputs.");
lines.push("");
// The headline: adapters per library and verdict.
const verdictOrder = ["correctly rounded", "within a few ulps", "within more ulps", "unstable near degeneracies", "wrong on regular inputs"];
const bucket = (v) => (v.startsWith("within") ? (Number(v.split(" ")[1]) <= SHARP ? verdictOrder[1] : verdictOrder[2]) : v);
lines.push(`| library | adapters | ${verdictOrder.join(" | ")} |`);
lines.push(`| --- | --- | ${verdictOrder.map(() => "---").join(" | ")} |`);
for (const lib of [...new Set(rows.map((r) => r.library))]) {
  const mine = rows.filter((r) => r.library === lib);
  lines.push(`| ${esc(lib)} | ${mine.length} | ` + verdictOrder.map((v) => mine.filter((r) => bucket(r.verdict) === v).length || "").join(" | ") + " |");
}
lines.push("");
lines.push(`(*within a few ulps*: at most ${SHARP}.)`);
lines.push("");
lines.push("| library | version | function | operation | type | conventions | verdict | max ulps | non-finite / garbage | worst case | reproducer |");
lines.push("| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |");
for (const r of rows)
  lines.push(`| ${esc(r.library)} | ${esc(r.version)} | \`${esc(r.function)}\` | ${r.op} | ${r.type} | ${esc(r.conventions) || "-"} | ` +
             `${r.verdict} | ${ulpsText(r.maxUlps, r.maxBits)} | ${r.undefinedHandling} | ${esc(worstText(r.worst))} | ` +
             `${r.worst ? "`" + esc(r.worst.reproduce) + "`" : "-"} |`);
lines.push("");
writeFileSync(out, lines.join("\n"));
process.stderr.write(`wrote ${out}\n`);
