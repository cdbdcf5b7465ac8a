#!/usr/bin/env node
// Checks a JavaScript chapter of "Computer Graphics from Scratch" one book function at a
// time (Node 18 or newer, no packages):
//
//     node check-functions.js CHAPTER your-module.js [--adapter your-adapter.js] [--time-limit S]
//
// CHAPTER is a chapter's number or folder name (02, 02-basic-rays). For every book
// function of the chapter that has cases in tests/cases/CHAPTER.json (the cases our C++
// tests run), the runner calls your module's export of the book's name with the book's
// parameters and prints whether it passed, failed (with the inputs, what was expected,
// what yours returned and the mistake the case catches) or is not written yet.
//
// The book's data reach your code as the default adapter below makes them: vectors and
// colours as arrays [x, y, z], 4x4 matrices as arrays of their rows, textures as
// texture[i][j] (column i, row j), spheres, lights, planes, models and transforms as
// objects with the book's fields (sphere.center, light.type === "point", plane.normal,
// plane.D, model.triangles[k].v, transform.scale), and the book's globals (Cw, Ch,
// Vw, Vh, d, scene, BACKGROUND_COLOR) set on globalThis before each case. An adapter
// module of yours may export any of the default adapter's functions to build your own
// types, or to hand the globals to your module (docs/students.md has an example).
//
// Each case runs in a worker thread, so that one that never returns is stopped after
// the time limit (default 5 s). Exit status: 0 every case of every written function
// passed, 1 a case failed or your module does not load, 2 the command line is wrong.
// Nothing is written anywhere.
"use strict";

const fs = require("fs");
const path = require("path");
const { pathToFileURL } = require("url");
const { Worker, isMainThread, parentPort, workerData } = require("worker_threads");

const CASES_DIR = path.resolve(__dirname, "..", "..", "..", "tests", "cases");

function number(value) {
  if (value === "inf") return Infinity;
  if (value === "-inf") return -Infinity;
  return Number(value);
}

const numbers = (value) => value.map(number);

// A case's JSON with "inf" and "-inf" made numbers, so that adapters see numbers only.
function decoded(value) {
  if (value === "inf" || value === "-inf") return number(value);
  if (Array.isArray(value)) return value.map(decoded);
  if (value && typeof value === "object") {
    return Object.fromEntries(Object.entries(value).map(([key, each]) => [key, decoded(each)]));
  }
  return value;
}

// A colour channel as a canvas keeps it: clamped to 0..255, rounded half up.
function channel(value) {
  if (!(value > 0)) return 0;
  if (value >= 255) return 255;
  const whole = Math.trunc(value);
  return value - whole >= 0.5 ? whole + 1 : whole;
}

// What a drawing function puts, as a canvas of the case's size keeps it: each pixel's x
// and y truncated toward zero (docs/conventions.md), its colour clamped to 0..255 and
// rounded, the last colour put at a pixel kept, pixels outside the canvas dropped.
class Canvas {
  constructor(width, height) {
    Object.assign(this, { width, height, pixels: new Map() });
    this.PutPixel = this.PutPixel.bind(this);
  }
  PutPixel(x, y, color) {
    [x, y] = [Math.trunc(x), Math.trunc(y)];
    const inside = (v, size) => -Math.floor(size / 2) <= v && v < Math.floor(size / 2);
    if (!inside(x, this.width) || !inside(y, this.height)) return;
    this.pixels.set(`${x},${y}`, [x, y, ...Array.from(color, channel)]);
  }
  drawn() {
    return [...this.pixels.values()].sort((a, b) => a[0] - b[0] || a[1] - b[1]);
  }
}

const defaultAdapter = {
  vector: (value) => numbers(value),
  point: ([x, y, h = 1]) => ({ x, y, h }),  // h: chapter 8's intensity
  color: (value) => numbers(value),
  matrix: (rows) => rows.map(numbers),  // a 4x4 matrix as the book writes it: its rows
  vectors: (value, adapter) => value.map((each) => adapter.vector(each, adapter)),
  plane: (value, adapter) => ({ normal: adapter.vector(value.normal, adapter), D: number(value.D) }),
  booleans: (value) => value.map(Boolean),
  // A triangle's tangent T and bitangent B (chapter 15's normal mapping).
  tangent_basis: (value, adapter) => ({ T: adapter.vector(value.T, adapter), B: adapter.vector(value.B, adapter) }),
  // A triangle of a model: v, three indices into its vertex list, and color.
  triangle: (value, adapter) => ({ v: [...value.v], color: adapter.color(value.color, adapter) }),
  // A model: its vertices and its triangles.
  model(value, adapter) {
    return {
      vertices: adapter.vectors(value.vertices, adapter),
      triangles: value.triangles.map((each) => adapter.triangle(each, adapter)),
    };
  },
  // A texture as the book reads it: texture[i][j] the texel in column i, row j (rows from
  // the top), with its width and height.
  texture(value, adapter) {
    const { width, height } = value;
    const columns = Array.from({ length: width }, (_, i) =>
      Array.from({ length: height }, (_, j) => adapter.color(value.texels[j * width + i], adapter)));
    return Object.assign(columns, { width, height });
  },
  transform(value, adapter) {
    return {
      scale: number(value.scale), rotation: adapter.matrix(value.rotation, adapter),
      translation: adapter.vector(value.translation, adapter),
    };
  },
  sphere(value, adapter) {
    return {
      center: adapter.vector(value.center), radius: number(value.radius),
      color: adapter.color(value.color), specular: number(value.specular ?? -1),
      reflective: number(value.reflective ?? 0),
    };
  },
  light(value, adapter) {
    return {
      type: value.type, intensity: number(value.intensity),
      position: adapter.vector(value.position ?? [0, 0, 0]),
      direction: adapter.vector(value.direction ?? [0, 0, 0]),
    };
  },
  scene(value, adapter) {
    return {
      spheres: (value.spheres ?? []).map((each) => adapter.sphere(each, adapter)),
      lights: (value.lights ?? []).map((each) => adapter.light(each, adapter)),
      background_color: adapter.color(value.background_color ?? [255, 255, 255]),
    };
  },
  // Sets the book's globals that a case gives; for a drawing function, PutPixel is the
  // checker's (given.canvas.PutPixel).
  setup(module, given, adapter) {
    if (given.canvas) {
      [globalThis.Cw, globalThis.Ch] = [given.canvas.width, given.canvas.height];
      if (given.canvas.PutPixel) globalThis.PutPixel = given.canvas.PutPixel;
    }
    if (given.viewport) {
      [globalThis.Vw, globalThis.Vh] = [number(given.viewport.width), number(given.viewport.height)];
      globalThis.d = number(given.viewport.d);
    }
    if (given.scene) {
      globalThis.scene = adapter.scene(given.scene, adapter);
      globalThis.BACKGROUND_COLOR = globalThis.scene.background_color;
    }
    if (given.depth_buffer === "empty") {  // chapter 12: 0 is 1/z infinitely far; [x][y], x, y >= 0
      globalThis.depth_buffer = Array.from({ length: given.canvas.width }, () => new Array(given.canvas.height).fill(0));
    }
    if (given.camera) {  // chapter 5: its rotation a 3x3 matrix, row by row
      globalThis.camera = { position: adapter.vector(given.camera.position), rotation: given.camera.rotation };
    }
  },
  // Your function's result as the list of numbers the case expects: a number, a vector
  // or colour, two roots, or ClosestIntersection's sphere (by its index in the case's
  // scene, -1 for none) and t.
  result(kind, value, given, adapter) {
    if (kind === "number") return [Number(value)];
    if (kind === "numbers") return Array.from(value, Number);
    if (kind === "canvas_point") {  // as a canvas takes it: truncated toward zero
      const [x, y] = "x" in value ? [value.x, value.y] : value;
      return [Math.trunc(x), Math.trunc(y)];
    }
    if (kind === "matrix") {  // row by row, as the book writes it
      if (!Array.isArray(value) || !value.every(Array.isArray)) throw new TypeError("not a list of rows");
      return value.flat().map(Number);
    }
    if (kind === "boolean") {
      if (typeof value !== "boolean") throw new TypeError("not true or false");
      return [Number(value)];
    }
    if (kind === "triangles") {  // a model (its triangles) or a list of triangles: their indices
      const triangles = Array.isArray(value) ? value : value.triangles;
      return triangles.flatMap((each) => Array.from(Array.isArray(each) ? each : each.v, Number));
    }
    if (kind === "corners") {  // each triangle's corners, its indices looked up in the vertex
      const { vertices } = given.arguments;  // list the function was given
      return value.flatMap((each) => Array.from(Array.isArray(each) ? each : each.v,
        (i) => adapter.result("vector", vertices[i], given, adapter)).flat());
    }
    if (kind === "bounding_sphere") {  // its centre, then its radius
      const [center, radius] = Array.isArray(value) ? value : [value.center, value.radius];
      return [...adapter.result("vector", center, given, adapter), Number(radius)];
    }
    if (kind === "vector_or_none") return value === null || value === undefined ? [] : adapter.result("vector", value, given, adapter);
    if (kind === "closest") {
      const [sphere, t] = value;
      return [adapter.indexOf(sphere, given, adapter), Number(t)];
    }
    if (value && ["x", "y", "z"].every((axis) => axis in value)) value = [value.x, value.y, value.z];
    if (!value || typeof value[Symbol.iterator] !== "function") throw new TypeError("not a list");
    return Array.from(value, (each) => {
      if (typeof each !== "number") throw new TypeError("not a number");
      return each;
    });
  },
};

// Which sphere of the case's scene yours is (-1 for none): the one with its centre
// and radius.
defaultAdapter.indexOf = function (sphere, given, adapter) {
  if (sphere === null || sphere === undefined) return -1;
  const center = adapter.result("vector", sphere.center, given, adapter);
  const index = given.scene.spheres.findIndex((each) =>
    each.center.every((v, i) => v === center[i]) && each.radius === sphere.radius);
  if (index < 0) throw new TypeError("not a sphere of the scene");
  return index;
};

class Usage extends Error {}

// An error in one line, at the last line of the student's code it went through.
function where(error) {
  if (!(error instanceof Error)) return `${typeof error} ${String(error)}`;
  const line = (error.stack ?? "").split("\n").find((each) => /at .*:\d+:\d+\)?$/.test(each) &&
    !each.includes(__filename) && !each.includes("node:"));
  const place = line ? ` (at ${path.basename(line.replace(/^.*\(|^\s*at /g, "").replace(/:\d+\)?$/, ""))})` : "";
  return `${error.name}: ${String(error.message).split("\n")[0]}${place}`;
}

async function load(file, what) {
  try {
    const loaded = await import(pathToFileURL(path.resolve(file)).href);
    return loaded.default && typeof loaded.default === "object" ? { ...loaded.default, ...loaded } : loaded;
  } catch (error) {
    throw Object.assign(new Error(`${what} ${file} does not load: ${where(error)}`), { load: true });
  }
}

const shown = (values) => `[${values.map((v) => Number.isFinite(v) ? +v.toPrecision(10) : v).join(", ")}]`;

// null when a drawing function put exactly the pixels expected, else which differ.
function pixelDifferences(drawn, expected) {
  const key = ([x, y]) => `${x},${y}`;
  const yours = new Map(drawn.map((p) => [key(p), p]));
  const ours = new Map(expected.map((p) => [key(p), p]));
  const same = (a, b) => a.slice(2).every((c, i) => c === b[i + 2]);
  const lines = [];
  for (const [what, pixels] of [
    ["missing", [...ours.values()].filter((p) => !yours.has(key(p)))],
    ["extra", [...yours.values()].filter((p) => !ours.has(key(p)))],
    ["of another colour", [...ours.values()].filter((p) => yours.has(key(p)) && !same(yours.get(key(p)), p))],
  ]) {
    if (pixels.length === 0) continue;
    const listed = pixels.slice(0, 8).map((p) => `(${p[0]}, ${p[1]})` + (what === "of another colour"
      ? ` yours (${yours.get(key(p)).slice(2).join(", ")}) ours (${p.slice(2).join(", ")})` : "")).join(", ");
    lines.push(`${pixels.length} pixels ${what}: ${listed}${pixels.length > 8 ? ` and ${pixels.length - 8} more` : ""}`);
  }
  return lines.length ? lines.join("\n      ") : null;
}

// null when the case passes, else what went wrong, in one line.
function runCase(entry, kase, adapter, module) {
  let args;
  const given = decoded(kase.given ?? {});
  let canvas = null;
  if (entry.returns === "pixels") {  // what the function draws, through the checker's PutPixel
    canvas = new Canvas(given.canvas.width, given.canvas.height);
    given.canvas.PutPixel = canvas.PutPixel;
  }
  let calls;  // one call, or several in turn on one canvas and depth buffer (kase.calls)
  try {
    adapter.setup(module, given, adapter);
    calls = (kase.calls ?? [kase.args]).map((call) => entry.parameters.map(([name, kind]) => {
      const value = decoded(call[name]);
      return kind === "number" ? value : adapter[kind](value, adapter);
    }));
  } catch (error) {
    return `your adapter failed to build the inputs: ${where(error)}`;
  }
  let value;
  try {
    for (args of calls) value = module[entry.function](...args);
  } catch (error) {
    return `threw ${where(error)}`;
  }
  if (canvas) return pixelDifferences(canvas.drawn(), kase.expected);
  if (value === undefined && entry.returns === "triangles") value = args[0];  // CullBackFaces changes its object
  // The case's globals, and the arguments as your function was given them (after it ran).
  const arguments_ = Object.fromEntries(entry.parameters.map(([name], i) => [name, args[i]]));
  let actual;
  try {
    actual = adapter.result(entry.returns, value, { ...decoded(kase.given ?? {}), arguments: arguments_ }, adapter);
  } catch {
    return `returned ${JSON.stringify(value) ?? String(value)}, not a ${entry.returns}`;
  }
  // Every number expected, lists within lists flattened in order; true and false are 1 and 0.
  const expected = kase.expected === null ? [] : [decoded(kase.expected)].flat(Infinity).map(Number);
  // As a canvas truncates pixel coordinates.
  if (kase.compare === "truncated") actual = actual.map((v) => (Number.isFinite(v) ? Math.trunc(v) : v));
  const tolerance = kase.tolerance;
  const near = (a, e) => (Number.isFinite(e) ? Math.abs(a - e) <= tolerance : a === e);
  if (actual.length === expected.length && actual.every((a, i) => near(a, expected[i]))) return null;
  return `returned ${shown(actual)}${kase.compare ? " (truncated)" : ""}, expected ${shown(expected)}${tolerance ? ` (within ${tolerance})` : ""}`;
}

// The worker: loads the module and the adapter, runs the cases from `start` on, and
// posts each verdict.
async function work() {
  const { file, module: modulePath, adapter: adapterPath, start } = workerData;
  const cases = JSON.parse(fs.readFileSync(file, "utf8"));
  let module, adapter;
  try {
    const own = adapterPath ? await load(adapterPath, "your adapter") : {};
    adapter = { ...defaultAdapter, ...own };
    module = await load(modulePath, "your module");
  } catch (error) {
    parentPort.postMessage({ loadError: error.message });
    return;
  }
  let index = 0;
  for (const entry of cases.functions) {
    for (const kase of entry.cases) {
      if (index++ < start) continue;
      const written = typeof module[entry.function] === "function";
      parentPort.postMessage({ index: index - 1, problem: written ? runCase(entry, kase, adapter, module) : undefined, written });
    }
  }
  parentPort.postMessage({ done: true });
}

// Runs every case, a worker at a time; a case past the time limit stops its worker,
// and a new one goes on from the next case. Resolves to the verdicts, by case index.
function runAll(file, options, count) {
  return new Promise((resolve, reject) => {
    const verdicts = [];
    const startWorker = (start) => {
      const worker = new Worker(__filename, {
        workerData: { file, module: options.module, adapter: options.adapter, start },
      });
      let timer;
      const arm = (limit) => {
        clearTimeout(timer);
        timer = setTimeout(() => {
          worker.terminate();
          const index = verdicts.length;
          verdicts.push({ written: true, problem: `did not return within ${options.timeLimit} s` });
          if (index + 1 < count) startWorker(index + 1); else resolve(verdicts);
        }, limit * 1000);
      };
      arm(Math.max(60, options.timeLimit));  // loading the module
      worker.on("message", (message) => {
        if (message.loadError) { clearTimeout(timer); reject(Object.assign(new Error(message.loadError), { load: true })); return; }
        if (message.done) { clearTimeout(timer); resolve(verdicts); return; }
        verdicts[message.index] = message;
        arm(options.timeLimit);
      });
      worker.on("error", (error) => { clearTimeout(timer); reject(Object.assign(new Error(`your module failed: ${where(error)}`), { load: true })); });
    };
    startWorker(0);
  });
}

function parse(argv) {
  const options = { timeLimit: 5 };
  const positional = [];
  for (let i = 0; i < argv.length; ++i) {
    if (argv[i] === "--adapter") options.adapter = argv[++i];
    else if (argv[i] === "--time-limit") options.timeLimit = Number(argv[++i]);
    else if (argv[i].startsWith("-")) throw new Usage(`unknown option ${argv[i]} (usage: CHAPTER MODULE [--adapter FILE] [--time-limit SECONDS])`);
    else positional.push(argv[i]);
  }
  if (positional.length !== 2) throw new Usage("give a chapter and your module: CHAPTER MODULE [--adapter FILE] [--time-limit SECONDS]");
  [options.chapter, options.module] = positional;
  if (!(options.timeLimit > 0 && options.timeLimit <= 3600)) throw new Usage("--time-limit: give 0 to 3600 seconds");
  for (const file of [options.module, options.adapter]) {
    if (file !== undefined && !(fs.existsSync(file) && fs.statSync(file).isFile())) throw new Usage(`${file}: no such file`);
  }
  return options;
}

async function main() {
  const options = parse(process.argv.slice(2));
  const files = fs.readdirSync(CASES_DIR).filter((name) => name.endsWith(".json")).sort();
  const matches = files.filter((name) => name.startsWith(options.chapter));
  if (options.chapter.length < 2 || matches.length !== 1) {
    throw new Usage(`no cases for chapter '${options.chapter}'; there are cases for ${files.map((f) => f.replace(/\.json$/, "")).join(", ")}`);
  }
  const file = path.join(CASES_DIR, matches[0]);
  const cases = JSON.parse(fs.readFileSync(file, "utf8"));
  const count = cases.functions.reduce((sum, entry) => sum + entry.cases.length, 0);
  const verdicts = await runAll(file, options, count);
  console.log(`${cases.chapter}: ${path.basename(options.module)}, the book's functions one by one`);
  let index = 0;
  let failed = false;
  for (const entry of cases.functions) {
    const mine = entry.cases.map((kase, i) => ({ kase, number: i + 1, ...verdicts[index++] }));
    const name = entry.function.padEnd(22);
    if (!mine.every((each) => each.written)) {
      console.log(`  ${name} not written yet (${mine.length} cases)`);
      continue;
    }
    const failures = mine.filter((each) => each.problem);
    if (failures.length === 0) {
      console.log(`  ${name} passed (${mine.length} cases)`);
      continue;
    }
    failed = true;
    console.log(`  ${name} FAILED ${failures.length} of ${mine.length} cases`);
    for (const { kase, number: n, problem } of failures) {
      console.log(`    case ${n} of ${matches[0]}: ${kase.catches}`);
      console.log(`      ${entry.call} with ${JSON.stringify({ ...(kase.given ?? {}), ...(kase.args ?? { calls: kase.calls }) })}`);
      console.log(`      ${problem}`);
    }
  }
  return failed ? 1 : 0;
}

if (isMainThread) {
  main().then((status) => { process.exitCode = status; }, (error) => {
    if (error instanceof Usage) {
      console.error(`check-functions.js: error: ${error.message}`);
      process.exitCode = 2;
    } else if (error.load) {
      console.error(`check-functions.js: ${error.message}`);
      process.exitCode = 1;
    } else {
      console.error(`check-functions.js: ${where(error)}`);
      process.exitCode = 2;
    }
  });
} else {
  work();
}
