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
// Verdicts: the oracle's own (docs/verdicts.md), per input class in the `--json` reports of
// `grade` and `check`; an adapter's is the worst over its classes, with the classes where it
// occurs when it is worse than stable (an ill-conditioned input answered within its
// conditioning is correct, whatever its ulps).

const VERDICTS = ["exact", "faithful", "stable", "unstable", "range", "wrong", "nonfinite", "garbage"];
const CLASSES = ["regular", "near-degenerate", "degenerate"];
const rank = (v) => VERDICTS.indexOf(v);

function verdict(byClass) {
  const graded = CLASSES.filter((c) => byClass[c]);
  if (graded.length === 0) throw new Error("a report without any input class");
  for (const c of graded)
    if (rank(byClass[c].verdict) < 0) throw new Error(`class ${c} has no verdict (${byClass[c].verdict})`);
  const worst = VERDICTS[Math.max(...graded.map((c) => rank(byClass[c].verdict)))];
  const where = rank(worst) > rank("stable") ? graded.filter((c) => byClass[c].verdict === worst) : [];
  return { worst, where };
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

// The worst case over all classes: the worst verdict, then the largest finite error (non-finite
// and garbage answers have their own column).
function worstCase(byClass) {
  let worst = null;
  for (const c of CLASSES) {
    const s = byClass[c];
    if (!s || !Array.isArray(s.worst)) continue;
    for (const w of s.worst) {
      const score = rank(w.verdict) * 10000 + (w.output.nonfinite || w.output.garbage ? -1 : (w.output.bits ?? 0));
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

function addRow(row, byClass) {
  const summaries = CLASSES.map((c) => byClass[c]).filter(Boolean);
  const { worst, where } = verdict(byClass);
  rows.push({ ...row, verdict: worst, where, undefinedHandling: undefinedHandling(byClass), worst: worstCase(byClass),
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
             conventions: a.conventions.join(", ") }, gradeFile(j.cases, j.outputs).by_class);
  }
}

// C++ libraries built into shadowproof: the engines, not shadowproof's own seed routines. One
// class at a time, a third of the cases each, as `shadowproof cases` draws them; one `check` per
// class grades every engine (each implementation's cases depend on it alone, not on the others
// graded with it).
const engines = /^(glm|eigen|irrlicht|ogre|qt|osg)-/;
const engineNames = run(shadowproof, ["check", "--list"]).trim().split("\n").filter((n) => engines.test(n));
const engineRuns = new Map(engineNames.map((name) => [name, { byClass: {}, first: null }]));
for (const cls of CLASSES) {
  const doc = JSON.parse(run(shadowproof, ["check", "--impl", engineNames.join(","), "--class", cls, "--cases",
                                           String(Math.max(1, Math.round(cases / CLASSES.length))), "--seed", seed,
                                           "--json"], { okStatus: [0, 1] }));
  if (doc.results.length !== engineNames.length)
    throw new Error(`check graded ${doc.results.length} engines, not ${engineNames.length}`);
  for (const r of doc.results) {
    const e = engineRuns.get(r.impl);
    e.byClass[cls] = r.by_class[cls];
    e.first ??= r;
  }
}
for (const name of engineNames) {
  const { byClass, first } = engineRuns.get(name);
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
         byClass);
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
           gradeFile(casesPath, outputsPath).by_class);
  }
}
rmSync(work, { recursive: true, force: true });

// ------------------------------------------------------------------------------------------
// The table

const count = (pred) => rows.filter(pred).length;
const defect = (r) => rank(r.verdict) >= rank("wrong") && r.where.includes("regular");
process.stderr.write(`graded ${rows.length} adapters: ${count((r) => r.verdict === "exact")} exact, ` +
                     `${count(defect)} wrong, non-finite or garbage on regular inputs\n`);
if (!out) process.exit(0);

const esc = (s) => String(s ?? "").replace(/\|/g, "\\|");
// Counts above 2^53 do not survive JSON.parse exactly; their size in bits does.
const ulpsText = (ulps, bits) => (ulps < 2 ** 53 ? String(ulps) : `≈ 2^${bits.toFixed(1)}`);
const worstText = (w) => {
  if (!w) return "-";
  const o = w.output;
  const what = o.expected == null ? "exact undefined" : `exact ${o.expected}`;
  const how = o.nonfinite ? "non-finite" : o.garbage ? "garbage" : `${ulpsText(o.ulps, o.bits)} ulps`;
  return `${w.verdict}, ${w.class}: ${o.name} got ${o.got}, ${what} (${how})`;
};
const verdictText = (r) => (r.where.length ? `${r.verdict} (${r.where.join(", ")})` : r.verdict);
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
           VERDICTS.filter((v) => verdicts[v]).map((v) => `${verdicts[v]} ${v}`).join(", ") +
           `; ${count(defect)} wrong, non-finite or garbage on regular inputs.`);
lines.push("");
lines.push("Verdicts are the oracle's ([verdicts.md](verdicts.md)), the worst over an adapter's cases:");
lines.push("*exact* — every defined output is the exact value correctly rounded; *faithful* — within 1 ulp;");
lines.push("*stable* — the error is within what the problem's own conditioning allows (c·u·κ): a correct");
lines.push("answer for the float inputs given, however many ulps; *unstable* — more error than the conditioning");
lines.push("explains: the formula loses accuracy; *range* — an intermediate over- or underflows the format;");
lines.push("*wrong* — beyond any conditioning; *nonfinite* — NaN or Inf where the exact value is finite;");
lines.push("*garbage* — a finite number where no exact value exists. For a verdict worse than stable, the");
lines.push("input classes where it occurs follow it; wrong, non-finite or garbage on regular inputs is a defect");
lines.push("(docs/upstream/). The *non-finite / garbage* column counts NaN or Inf outputs where the exact");
lines.push("value is finite and finite outputs where it does not exist (flat view volumes, singular matrices,");
lines.push("parallel lights). The reproducer prints the exact answer for the worst case's inputs.");
lines.push("");
// The headline: adapters per library and verdict.
lines.push(`| library | adapters | ${VERDICTS.join(" | ")} |`);
lines.push(`| --- | --- | ${VERDICTS.map(() => "---").join(" | ")} |`);
for (const lib of [...new Set(rows.map((r) => r.library))]) {
  const mine = rows.filter((r) => r.library === lib);
  lines.push(`| ${esc(lib)} | ${mine.length} | ` + VERDICTS.map((v) => mine.filter((r) => r.verdict === v).length || "").join(" | ") + " |");
}
lines.push("");
lines.push("| library | version | function | operation | type | conventions | verdict | max ulps | non-finite / garbage | worst case | reproducer |");
lines.push("| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |");
for (const r of rows)
  lines.push(`| ${esc(r.library)} | ${esc(r.version)} | \`${esc(r.function)}\` | ${r.op} | ${r.type} | ${esc(r.conventions) || "-"} | ` +
             `${verdictText(r)} | ${ulpsText(r.maxUlps, r.maxBits)} | ${r.undefinedHandling} | ${esc(worstText(r.worst))} | ` +
             `${r.worst ? "`" + esc(r.worst.reproduce) + "`" : "-"} |`);
lines.push("");
writeFileSync(out, lines.join("\n"));
process.stderr.write(`wrote ${out}\n`);
