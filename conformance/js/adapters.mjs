// Adapters that grade JavaScript libraries through shadowproof's JSON-lines protocol
// (docs/protocol.md): each one reads a case file written by `shadowproof cases`, calls the
// library's OWN function on the inputs (read exactly from the "numbers" object: shortest
// round-trip JSON numbers) and writes one output line per case. Nothing here re-types a
// library's formula: inputs are only copied into the library's own types (exact), outputs
// copied out of its own arrays (exact widening of Float32Array entries), and where a library
// reports failure by returning null, every output is written as null (non-finite).
//
//   node adapters.mjs list                       the adapters as JSON lines
//   node adapters.mjs run NAME cases.jsonl       outputs as JSON lines on stdout
//   node adapters.mjs batch jobs.json            [{"name", "cases", "outputs"}, ...] in one process
//
// Each adapter declares the operation, the float type, and the conventions the case file
// must be written in (`shadowproof cases --convention ...`, and `grade` reads them back from
// the lines). conformance/run.sh drives them all.
import { createRequire } from "node:module";
import { readFileSync, writeFileSync } from "node:fs";

const require = createRequire(import.meta.url);
const here = new URL(".", import.meta.url);
// Read from node_modules directly: some packages do not export their package.json.
const version = (name) => JSON.parse(readFileSync(new URL(`node_modules/${name}/package.json`, here), "utf8")).version;

// ------------------------------------------------------------------------------------------
// Libraries

const glMatrix = require("gl-matrix");
const THREE = await import("three");
const { ShadowMesh } = await import("three/addons/objects/ShadowMesh.js");
const wgpu = await import("wgpu-matrix");
const BABYLON = await import("@babylonjs/core/Maths/math.vector.js");
const { Plane: BabylonPlane } = await import("@babylonjs/core/Maths/math.plane.js");

const COLUMN = "layout=column-major";

// gl-matrix stores matrices in ARRAY_TYPE (Float32Array by default, a plain Array of doubles
// after setMatrixArrayType(Array)); the type is set per adapter before it runs.
function glm(type) {
  glMatrix.glMatrix.setMatrixArrayType(type === "f32" ? Float32Array : Array);
  return glMatrix;
}

// Babylon's Matrix stores Float32Array unless PerformanceConfigurator.MatrixUse64Bits is set
// before matrices are made; it stores m[] as rows of a row-vector matrix, which is the same
// memory as column-major storage with column vectors.
async function babylon(type) {
  const { PerformanceConfigurator } = await import("@babylonjs/core/Engines/performanceConfigurator.js");
  PerformanceConfigurator.SetMatrixPrecision(type === "f64");
  return BABYLON;
}

// ------------------------------------------------------------------------------------------
// The adapters: one per (library function, float type, conventions).

const adapters = [];
function add(library, fn, op, types, conventions, make) {
  for (const type of types)
    adapters.push({
      name: `${library}:${fn}:${type}${conventions.suffix ?? ""}`,
      library,
      version: version(library === "babylon" ? "@babylonjs/core" : library),
      function: fn,
      op,
      type,
      conventions: conventions.list,
      make: () => make(type),
    });
}
const conv = (list, suffix) => ({ list, suffix });

// gl-matrix 3.4: column-major, column vectors, right-handed.
for (const [fn, depth, infinite] of [
  ["mat4.perspective", "gl", false],
  ["mat4.perspectiveZO", "d3d", false],
]) {
  add("gl-matrix", fn, "perspective-fov", ["f32", "f64"], conv([COLUMN, `depth=${depth}`]), (t) => {
    const { mat4 } = glm(t);
    const f = mat4[fn.split(".")[1]];
    return ({ camera: [fovy, aspect, n, far] }) => f(mat4.create(), fovy, aspect, n, far);
  });
  add("gl-matrix", fn, "perspective-fov-infinite", ["f32", "f64"], conv([COLUMN, `depth=${depth}`], "-infinite"), (t) => {
    const { mat4 } = glm(t);
    const f = mat4[fn.split(".")[1]];
    return ({ camera: [fovy, aspect, n] }) => f(mat4.create(), fovy, aspect, n, Infinity);
  });
}
for (const [fn, depth] of [["mat4.ortho", "gl"], ["mat4.orthoZO", "d3d"]])
  add("gl-matrix", fn, "ortho", ["f32", "f64"], conv([COLUMN, `depth=${depth}`]), (t) => {
    const { mat4 } = glm(t);
    const f = mat4[fn.split(".")[1]];
    return ({ box: [l, r, b, top, n, far] }) => f(mat4.create(), l, r, b, top, n, far);
  });
add("gl-matrix", "mat4.frustum", "frustum", ["f32", "f64"], conv([COLUMN, "depth=gl"]), (t) => {
  const { mat4 } = glm(t);
  return ({ box: [l, r, b, top, n, far] }) => mat4.frustum(mat4.create(), l, r, b, top, n, far);
});
add("gl-matrix", "mat4.lookAt", "look-at", ["f32", "f64"], conv([COLUMN]), (t) => {
  const { mat4 } = glm(t);
  return ({ eye, target, up }) => mat4.lookAt(mat4.create(), eye, target, up);
});
add("gl-matrix", "mat4.targetTo", "target-to", ["f32", "f64"], conv([COLUMN]), (t) => {
  const { mat4 } = glm(t);
  return ({ eye, target, up }) => mat4.targetTo(mat4.create(), eye, target, up);
});
add("gl-matrix", "mat3.normalFromMat4", "normal-matrix", ["f32", "f64"], conv([COLUMN, "matrix3-input=mat4"]), (t) => {
  const { mat3, mat4 } = glm(t);
  // Returns null (and leaves `out` alone) when the determinant is 0.
  return ({ matrix }) => mat3.normalFromMat4(mat3.create(), mat4.clone(matrix)) ?? null;
});

// wgpu-matrix 3.4: column-major, column vectors, right-handed, WebGPU depth [0, 1]; mat4 is
// Float32Array, mat4d Float64Array; mat3 is 12 floats (three columns padded to 4).
const wgpuApi = (t) => (t === "f32" ? { mat4: wgpu.mat4, mat3: wgpu.mat3 } : { mat4: wgpu.mat4d, mat3: wgpu.mat3d });
for (const [fn, depth] of [["mat4.perspective", "d3d"], ["mat4.perspectiveReverseZ", "reverse-z"]]) {
  const name = fn.split(".")[1];
  add("wgpu-matrix", fn, "perspective-fov", ["f32", "f64"], conv([COLUMN, `depth=${depth}`]), (t) => {
    const { mat4 } = wgpuApi(t);
    return ({ camera: [fovy, aspect, n, far] }) => mat4[name](fovy, aspect, n, far);
  });
  add("wgpu-matrix", fn, "perspective-fov-infinite", ["f32", "f64"], conv([COLUMN, `depth=${depth}`], "-infinite"), (t) => {
    const { mat4 } = wgpuApi(t);
    return ({ camera: [fovy, aspect, n] }) => mat4[name](fovy, aspect, n, Infinity);
  });
}
add("wgpu-matrix", "mat4.ortho", "ortho", ["f32", "f64"], conv([COLUMN, "depth=d3d"]), (t) => {
  const { mat4 } = wgpuApi(t);
  return ({ box: [l, r, b, top, n, far] }) => mat4.ortho(l, r, b, top, n, far);
});
for (const [fn, depth] of [["mat4.frustum", "d3d"], ["mat4.frustumReverseZ", "reverse-z"]]) {
  const name = fn.split(".")[1];
  add("wgpu-matrix", fn, "frustum", ["f32", "f64"], conv([COLUMN, `depth=${depth}`]), (t) => {
    const { mat4 } = wgpuApi(t);
    return ({ box: [l, r, b, top, n, far] }) => mat4[name](l, r, b, top, n, far);
  });
}
add("wgpu-matrix", "mat4.lookAt", "look-at", ["f32", "f64"], conv([COLUMN]), (t) => {
  const { mat4 } = wgpuApi(t);
  return ({ eye, target, up }) => mat4.lookAt(eye, target, up);
});
add("wgpu-matrix", "mat4.cameraAim", "target-to", ["f32", "f64"], conv([COLUMN]), (t) => {
  const { mat4 } = wgpuApi(t);
  return ({ eye, target, up }) => mat4.cameraAim(eye, target, up);
});
add("wgpu-matrix", "mat4.aim", "target-to", ["f32", "f64"], conv([COLUMN, "handedness=left"]), (t) => {
  const { mat4 } = wgpuApi(t);
  return ({ eye, target, up }) => mat4.aim(eye, target, up);
});
// wgpu-matrix has no normal-matrix function; its documented pieces are mat3.inverse and
// mat3.transpose on the padded mat3.
add("wgpu-matrix", "mat3.transpose(mat3.inverse)", "normal-matrix", ["f32", "f64"],
  conv([COLUMN, "matrix3=padded", "matrix3-input=padded"]), (t) => {
    const { mat3 } = wgpuApi(t);
    return ({ matrix }) => mat3.transpose(mat3.inverse(mat3.clone(matrix)));
  });

// three.js 0.187: Matrix4.elements is a plain Array (doubles), column-major, column vectors,
// right-handed. WebGLCoordinateSystem = gl depth, WebGPUCoordinateSystem = d3d.
const threeDepths = [
  ["gl", THREE.WebGLCoordinateSystem, false],
  ["d3d", THREE.WebGPUCoordinateSystem, false],
  ["reverse-z", THREE.WebGPUCoordinateSystem, true],
];
for (const [depth, system, reversed] of threeDepths) {
  const suffix = depth === "gl" ? "" : `-${depth}`;
  // makePerspective(left, right, top, bottom, near, far, system, reversedDepth)
  add("three", "Matrix4.makePerspective", "frustum", ["f64"], conv([COLUMN, `depth=${depth}`], suffix), () =>
    ({ box: [l, r, b, top, n, far] }) => new THREE.Matrix4().makePerspective(l, r, top, b, n, far, system, reversed).elements);
  add("three", "Matrix4.makeOrthographic", "ortho", ["f64"], conv([COLUMN, `depth=${depth}`], suffix), () =>
    ({ box: [l, r, b, top, n, far] }) => new THREE.Matrix4().makeOrthographic(l, r, top, b, n, far, system, reversed).elements);
  // PerspectiveCamera takes its vertical field of view in degrees.
  add("three", "PerspectiveCamera", "perspective-fov", ["f64"], conv([COLUMN, `depth=${depth}`, "angle=degrees"], suffix), () =>
    ({ camera: [fovy, aspect, n, far] }) => {
      const camera = new THREE.PerspectiveCamera(fovy, aspect, n, far);
      camera.coordinateSystem = system;
      camera._reversedDepth = reversed;  // what a renderer with a reversed depth buffer sets (getter only)
      camera.updateProjectionMatrix();
      return camera.projectionMatrix.elements;
    });
}
// Matrix4.lookAt sets the rotation of the camera's placement and keeps the translation, so the
// placement is makeTranslation(eye) followed by lookAt, as Object3D.lookAt composes it.
add("three", "Matrix4.makeTranslation+lookAt", "target-to", ["f64"], conv([COLUMN]), () =>
  ({ eye, target, up }) => {
    const e = new THREE.Vector3(...eye);
    return new THREE.Matrix4().makeTranslation(e).lookAt(e, new THREE.Vector3(...target), new THREE.Vector3(...up)).elements;
  });
add("three", "Matrix3.getNormalMatrix", "normal-matrix", ["f64"], conv([COLUMN, "matrix3-input=mat4"]), () =>
  ({ matrix }) => new THREE.Matrix3().getNormalMatrix(new THREE.Matrix4().fromArray(matrix)).elements);
// ShadowMesh.update(plane, lightPosition4D): THREE.Plane(normal, constant) is n·x + constant = 0.
// Graded twice: with the plane as THREE.Plane defines it, and with the plane written n·x = d,
// the reading ShadowMesh's code makes of it (docs/upstream/three-shadowmesh-plane-constant.md).
for (const [form, suffix] of [["n.x+d=0", ""], ["n.x=d", "-plane-n.x=d"]])
  add("three", "ShadowMesh.update", "shadow-matrix", ["f64"], conv([COLUMN, `plane=${form}`], suffix), () =>
    ({ plane, light }) => {
      const mesh = new ShadowMesh(new THREE.Mesh(new THREE.BufferGeometry()));
      mesh.update(new THREE.Plane(new THREE.Vector3(plane[0], plane[1], plane[2]), plane[3]), new THREE.Vector4(...light));
      return mesh.matrix.elements;
    });

// Babylon.js 9: m[] is column-major with column vectors (see babylon() above); LH and RH
// variants; halfZRange = true maps depth to [0, 1] (d3d), false to [−1, 1] (gl).
const V3 = (v) => new BABYLON.Vector3(v[0], v[1], v[2]);
const babylonOut = (m) => Array.from(m.m);
for (const [hand, H] of [["left", "LH"], ["right", "RH"]])
  for (const [depth, half] of [["gl", false], ["d3d", true]]) {
    const hs = `handedness=${hand}`;
    const suffix = depth === "gl" ? "" : "-halfZRange";
    add("babylon", `Matrix.PerspectiveFov${H}`, "perspective-fov", ["f32", "f64"], conv([COLUMN, hs, `depth=${depth}`], suffix), async (t) => {
      const B = await babylon(t);
      return ({ camera: [fovy, aspect, n, far] }) => babylonOut(B.Matrix[`PerspectiveFov${H}`](fovy, aspect, n, far, half));
    });
    // zfar = 0 means an infinite far plane.
    add("babylon", `Matrix.PerspectiveFov${H}(zfar=0)`, "perspective-fov-infinite", ["f32", "f64"], conv([COLUMN, hs, `depth=${depth}`], suffix), async (t) => {
      const B = await babylon(t);
      return ({ camera: [fovy, aspect, n] }) => babylonOut(B.Matrix[`PerspectiveFov${H}`](fovy, aspect, n, 0, half));
    });
    add("babylon", `Matrix.OrthoOffCenter${H}`, "ortho", ["f32", "f64"], conv([COLUMN, hs, `depth=${depth}`], suffix), async (t) => {
      const B = await babylon(t);
      return ({ box: [l, r, b, top, n, far] }) => babylonOut(B.Matrix[`OrthoOffCenter${H}`](l, r, b, top, n, far, half));
    });
    if (H === "LH") {
      // The width and height builders.
      add("babylon", "Matrix.OrthoLH", "ortho-size", ["f32", "f64"], conv([COLUMN, hs, `depth=${depth}`], suffix), async (t) => {
        const B = await babylon(t);
        return ({ size: [w, h, n, far] }) => babylonOut(B.Matrix.OrthoLH(w, h, n, far, half));
      });
      add("babylon", "Matrix.PerspectiveLH", "perspective-size", ["f32", "f64"], conv([COLUMN, hs, `depth=${depth}`], suffix), async (t) => {
        const B = await babylon(t);
        return ({ size: [w, h, n, far] }) => babylonOut(B.Matrix.PerspectiveLH(w, h, n, far, half));
      });
    }
  }
for (const [hand, H] of [["left", "LH"], ["right", "RH"]])
  add("babylon", `Matrix.LookAt${H}`, "look-at", ["f32", "f64"], conv([COLUMN, `handedness=${hand}`]), async (t) => {
    const B = await babylon(t);
    return ({ eye, target, up }) => babylonOut(B.Matrix[`LookAt${H}`](V3(eye), V3(target), V3(up)));
  });
// Plane(a, b, c, d) is a x + b y + c z + d = 0; Reflection normalises it first.
add("babylon", "Matrix.Reflection", "reflection-matrix", ["f32", "f64"], conv([COLUMN]), async (t) => {
  const B = await babylon(t);
  return ({ plane }) => babylonOut(B.Matrix.Reflection(new BabylonPlane(plane[0], plane[1], plane[2], plane[3])));
});
add("babylon", "Matrix.toNormalMatrix", "normal-matrix", ["f32", "f64"], conv([COLUMN, "matrix3=mat4", "matrix3-input=mat4"]), async (t) => {
  const B = await babylon(t);
  return ({ matrix }) => {
    const result = new B.Matrix();
    B.Matrix.FromArray(matrix).toNormalMatrix(result);
    return babylonOut(result);
  };
});

// ------------------------------------------------------------------------------------------
// The protocol

// Non-finite numbers have no JSON spelling: the protocol takes "nan", "inf", "-inf" (and null).
function jsonNumber(x) {
  if (x === null || x === undefined) return null;
  if (Number.isNaN(x)) return "nan";
  if (x === Infinity) return "inf";
  if (x === -Infinity) return "-inf";
  return x;
}

async function outputLines(name, path) {
  const adapter = adapters.find((a) => a.name === name);
  if (!adapter) throw new Error(`no adapter named ${name} (node adapters.mjs list)`);
  const call = await adapter.make();
  const lines = [];
  for (const line of readFileSync(path, "utf8").split("\n")) {
    if (!line.trim()) continue;
    const c = JSON.parse(line);
    const result = call(c.numbers);
    const count = c.op === "normal-matrix" ? ({ packed: 9, padded: 12, mat4: 16 })[c.conventions?.matrix3 ?? "packed"] : 16;
    const output = result === null ? new Array(count).fill(null) : Array.from(result, jsonNumber);
    lines.push(JSON.stringify({ id: c.id, output }));
  }
  return lines.join("\n") + "\n";
}

const [command, name, path] = process.argv.slice(2);
if (command === "list") {
  for (const a of adapters) {
    const { make, ...rest } = a;
    process.stdout.write(JSON.stringify(rest) + "\n");
  }
} else if (command === "run" && name && path) {
  process.stdout.write(await outputLines(name, path));
} else if (command === "batch" && name) {
  // One process for many adapters: a JSON array of {"name", "cases", "outputs"} file paths.
  for (const job of JSON.parse(readFileSync(name, "utf8"))) writeFileSync(job.outputs, await outputLines(job.name, job.cases));
} else {
  process.stderr.write("usage: node adapters.mjs list | run NAME cases.jsonl | batch jobs.json\n");
  process.exit(2);
}
