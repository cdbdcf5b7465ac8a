#!/usr/bin/env node
// Checks a JavaScript chapter of "Computer Graphics from Scratch" one book function at a
// time (Node 18 or newer, no packages):
//
//     node check-functions.js CHAPTER your-module.js [--adapter your-adapter.js] [--time-limit S]
//     node check-functions.js --adapter-template
//
// CHAPTER is a chapter's number or folder name (02, 02-basic-rays). For every book
// function of the chapter that has cases in tests/cases/CHAPTER.json (the cases our C++
// tests run), the runner calls your module's export of the book's name with the book's
// parameters and prints whether it passed, failed (with the inputs, what was expected,
// what yours returned and the mistake the case catches) or is not written yet.
//
// The book's data reach your code as the default adapter below makes them: vectors and
// colours as arrays [x, y, z], 4x4 matrices as arrays of their rows, textures as
// texture[i][j] (column i, row j), spheres, lights, planes, models, transforms and scenes
// as plain objects with the book's fields (sphere.center or sphere["center"], or
// destructured, light.type === "point", plane.normal, plane.D, model.triangles[k].v,
// transform.scale), and the book's globals (Cw, Ch, Vw, Vh, d, scene, BACKGROUND_COLOR)
// set on globalThis before each case. An adapter module of yours may export any of the
// default adapter's functions to build your own types, or to hand the globals to your
// module; --adapter-template prints one to fill in (docs/students.md has an example).
//
// Your code runs in a process of its own, which this one judges from outside: it is sent
// each case's inputs and reports what your function returned; the verdict, against the
// expected values it never sees, is made here. A case that runs past the time limit
// (default 5 s), or a process that ends or says nothing more, fails, and a new process
// goes on with the next case. Exit status: 0 every case of every written function
// passed, 1 a case failed or your module does not load, 2 the command line is wrong.
// Nothing is written anywhere.
"use strict";

const fs = require("fs");
const path = require("path");
const { pathToFileURL } = require("url");
const { fork } = require("child_process");

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

// The worker: the process your code runs in. It loads your module (and adapter), says
// which of the book functions it is asked about your module has, then runs each case it
// is sent and reports what your function returned (or drew, or threw), never a verdict:
// it is sent a case's inputs only, never what is expected.

// What your function made of one case: { values }, { pixels } or { problem }.
function runCase(request, adapter, module) {
  const { case: kase, parameters, returns } = request;
  const given = decoded(kase.given ?? {});
  let canvas = null;
  if (returns === "pixels") {  // what the function draws, through the checker's PutPixel
    canvas = new Canvas(given.canvas.width, given.canvas.height);
    given.canvas.PutPixel = canvas.PutPixel;
  }
  let calls;  // one call, or several in turn on one canvas and depth buffer (kase.calls)
  try {
    adapter.setup(module, given, adapter);
    calls = (kase.calls ?? [kase.args]).map((call) => parameters.map(([name, kind]) => {
      const value = decoded(call[name]);
      return kind === "number" ? value : adapter[kind](value, adapter);
    }));
  } catch (error) {
    return { problem: `your adapter failed to build the inputs: ${where(error)}` };
  }
  let value;
  let args;
  try {
    for (args of calls) value = module[request.function](...args);
  } catch (error) {
    return { problem: `threw ${where(error)}` };
  }
  if (canvas) return { pixels: canvas.drawn() };
  if (value === undefined && returns === "triangles") value = args[0];  // CullBackFaces changes its object
  // The case's globals, and the arguments as your function was given them (after it ran).
  const arguments_ = Object.fromEntries(parameters.map(([name], i) => [name, args[i]]));
  try {
    const values = adapter.result(returns, value, { ...decoded(kase.given ?? {}), arguments: arguments_ }, adapter);
    return { values: Array.from(values, (each) => {
      if (typeof each !== "number") throw new TypeError("not a number");
      return each;
    }) };
  } catch {
    let shownValue;
    try {
      shownValue = (JSON.stringify(value) ?? String(value)).slice(0, 200);
    } catch {
      shownValue = `a ${typeof value}`;
    }
    return { problem: `returned ${shownValue}, not a ${returns}` };
  }
}

async function work(modulePath, adapterPath) {
  const send = process.send.bind(process);
  let module, adapter;
  const asked = new Promise((resolve) => process.once("message", resolve));
  try {
    const own = adapterPath ? await load(adapterPath, "your adapter") : {};
    adapter = { ...defaultAdapter, ...own };
    module = await load(modulePath, "your module");
  } catch (error) {
    send({ loadError: error.message });
    return;
  }
  const { functions } = await asked;
  send({ loaded: functions.filter((name) => typeof module[name] === "function") });
  process.on("message", (request) => {
    send({ id: request.id, ...runCase(request, adapter, module) });
  });
}

// The checker's side: a worker process at a time, judged by what it reports.

const LOAD_LIMIT = 60;  // seconds a module may take to load, apart from its cases' time limit

// A worker process on your module; resolves to { worker, written } once it has loaded,
// or rejects with a load error.
function startWorker(options, names) {
  return new Promise((resolve, reject) => {
    // What your code prints is not shown: it would break the report's lines.
    const worker = fork(__filename, ["--worker", options.module, options.adapter ?? ""], {
      stdio: ["ignore", "ignore", "ignore", "ipc"], serialization: "advanced", execArgv: [],
    });
    const fail = (message) => { clearTimeout(timer); worker.removeAllListeners(); worker.kill("SIGKILL"); reject(Object.assign(new Error(message), { load: true })); };
    const timer = setTimeout(() => fail(`your module ${options.module} does not load: still running after ${LOAD_LIMIT} s`), LOAD_LIMIT * 1000);
    worker.on("exit", (code, signal) => fail(`your module ${options.module} does not load: it ended the process (exit ${signal ? `signal ${signal}` : `status ${code}`}) while loading`));
    worker.on("error", (error) => fail(`your module ${options.module} does not load: ${error.message}`));
    worker.once("message", (message) => {
      if (message && message.loadError) { fail(String(message.loadError)); return; }
      if (!message || !Array.isArray(message.loaded)) { fail(`your module ${options.module} does not load: it said something else while loading`); return; }
      clearTimeout(timer);
      worker.removeAllListeners();
      resolve({ worker, written: new Set(message.loaded) });
    });
    worker.send({ functions: names });
  });
}

// Runs the cases on a worker at a time, starting a new one after a case that did not come
// back; each case resolves to { values } / { pixels } / { problem }.
class Session {
  constructor(options, names) {
    Object.assign(this, { options, names, worker: null, nextId: 0 });
  }
  async start() {
    ({ worker: this.worker, written: this.written } = await startWorker(this.options, this.names));
  }
  async run(entry, kase) {
    if (!this.worker) {
      try {
        await this.start();
      } catch (error) {
        return { problem: `a new process for the next cases could not load your module: ${error.message}` };
      }
    }
    const id = ++this.nextId;
    const worker = this.worker;
    const inputs = Object.fromEntries(["given", "args", "calls"].filter((key) => key in kase).map((key) => [key, kase[key]]));
    return new Promise((resolve) => {
      const done = (result, stop) => {
        clearTimeout(timer);
        worker.removeAllListeners();
        if (stop) {
          worker.kill("SIGKILL");
          this.worker = null;
        }
        resolve(result);
      };
      const timer = setTimeout(() => done({ problem: `did not return within ${this.options.timeLimit} s` }, true),
        this.options.timeLimit * 1000);
      worker.on("exit", (code, signal) => done({ problem: `ended the process it ran in (exit ${signal ? `signal ${signal}` : `status ${code}`}) instead of returning` }, true));
      worker.on("message", (message) => {
        if (!message || message.id !== id) done({ problem: "said something else than what it returned" }, true);
        else done(message, false);
      });
      try {
        worker.send({ id, function: entry.function, case: inputs, parameters: entry.parameters, returns: entry.returns });
      } catch {
        done({ problem: "ended the process it ran in instead of returning" }, true);
      }
    });
  }
  close() {
    if (this.worker) this.worker.kill("SIGKILL");
  }
}

// null when the case passes, else what went wrong.
function verdict(reply, kase, returns) {
  if ("problem" in reply) return String(reply.problem);
  if (returns === "pixels") return pixelDifferences(Array.isArray(reply.pixels) ? reply.pixels : [], kase.expected);
  let actual = reply.values;
  if (!Array.isArray(actual) || !actual.every((each) => typeof each === "number")) return "returned something that is not numbers";
  // Every number expected, lists within lists flattened in order; true and false are 1 and 0.
  const expected = kase.expected === null ? [] : [decoded(kase.expected)].flat(Infinity).map(Number);
  // As a canvas truncates pixel coordinates.
  if (kase.compare === "truncated") actual = actual.map((v) => (Number.isFinite(v) ? Math.trunc(v) : v));
  const tolerance = kase.tolerance;
  const near = (a, e) => (Number.isFinite(e) ? Math.abs(a - e) <= tolerance : a === e);
  if (actual.length === expected.length && actual.every((a, i) => near(a, expected[i]))) return null;
  return `returned ${shown(actual)}${kase.compare ? " (truncated)" : ""}, expected ${shown(expected)}${tolerance ? ` (within ${tolerance})` : ""}`;
}

// The globals each kind of a case's "given" sets on globalThis (defaultAdapter.setup).
const GLOBALS_SET = { canvas: "Cw, Ch", viewport: "Vw, Vh, d", scene: "scene, BACKGROUND_COLOR", depth_buffer: "depth_buffer", camera: "camera" };

// The line that says which globals the checker set, when a failed case set any.
function globalsNote(failures) {
  const kinds = Object.keys(GLOBALS_SET).filter((kind) => failures.some(({ kase }) => kase.given && kind in kase.given));
  if (kinds.length === 0) return null;
  return `    note: the checker set ${kinds.map((kind) => GLOBALS_SET[kind]).join(", ")} on globalThis before these cases; ` +
    "if your module keeps its own, give an adapter (docs/students.md, \"How the book's data reach your code\"; " +
    "--adapter-template prints one to fill in)";
}

const ADAPTER_TEMPLATE = `// An adapter for check-functions.js (docs/students.md, "How the book's data reach your
// code"): give it with --adapter. Export only what your module needs; each function here
// takes the place of the checker's own of the same name.
const mine = require("./raytracer.js");  // your module: the one you give the checker

module.exports = {
  // Called before each case, with what the case sets as the book's globals:
  //   given.canvas    { width, height, and for drawing functions PutPixel(x, y, color) }
  //   given.viewport  { width, height, d }
  //   given.scene     { spheres: [...], lights: [...], background_color: [r, g, b] }
  // Put them where your module reads them: a module whose globals are its own
  // (const Cw = 600) exports a function that sets them, called here.
  setup(module, given, adapter) {
    mine.configure({
      canvas: given.canvas,
      viewport: given.viewport,
      scene: given.scene && adapter.scene(given.scene, adapter),
    });
  },
  // Your own types, if your functions take them (each gets the case's JSON value):
  // vector: ([x, y, z]) => new Vec3(x, y, z),
};
`;

function parse(argv) {
  const options = { timeLimit: 5 };
  const positional = [];
  const value = (i) => {
    if (i >= argv.length || argv[i].startsWith("--")) throw new Usage(`${argv[i - 1]} needs a value (usage: CHAPTER MODULE [--adapter FILE] [--time-limit SECONDS])`);
    return argv[i];
  };
  for (let i = 0; i < argv.length; ++i) {
    if (argv[i] === "--adapter") options.adapter = value(++i);
    else if (argv[i] === "--time-limit") options.timeLimit = Number(value(++i));
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
  if (process.argv.length === 3 && process.argv[2] === "--adapter-template") {
    process.stdout.write(ADAPTER_TEMPLATE);
    return 0;
  }
  const options = parse(process.argv.slice(2));
  const files = fs.readdirSync(CASES_DIR).filter((name) => name.endsWith(".json")).sort();
  const have = files.map((f) => f.replace(/\.json$/, "")).join(", ");
  if (!/^[0-9]{2}(-[a-z0-9-]+)?$/.test(options.chapter)) {
    throw new Usage(`no chapter '${options.chapter}': give a number such as 02 or a folder name; there are cases for ${have}`);
  }
  const matches = files.filter((name) => name.startsWith(options.chapter));
  if (matches.length !== 1) throw new Usage(`no cases for chapter '${options.chapter}'; there are cases for ${have}`);
  const cases = JSON.parse(fs.readFileSync(path.join(CASES_DIR, matches[0]), "utf8"));
  const session = new Session(options, cases.functions.map((entry) => entry.function));
  await session.start();
  const lines = [`${cases.chapter}: ${path.basename(options.module)}, the book's functions one by one`];
  let failed = false;
  try {
    for (const entry of cases.functions) {
      const name = entry.function.padEnd(22);
      if (!session.written.has(entry.function)) {
        lines.push(`  ${name} not written yet (${entry.cases.length} cases)`);
        continue;
      }
      const failures = [];
      for (const [i, kase] of entry.cases.entries()) {
        const problem = verdict(await session.run(entry, kase), kase, entry.returns);
        if (problem) failures.push({ kase, number: i + 1, problem });
      }
      if (failures.length === 0) {
        lines.push(`  ${name} passed (${entry.cases.length} cases)`);
        continue;
      }
      failed = true;
      lines.push(`  ${name} FAILED ${failures.length} of ${entry.cases.length} cases`);
      for (const { kase, number: n, problem } of failures) {
        lines.push(`    case ${n} of ${matches[0]}: ${kase.catches}`);
        lines.push(`      ${entry.call} with ${JSON.stringify({ ...(kase.given ?? {}), ...(kase.args ?? { calls: kase.calls }) })}`);
        lines.push(`      ${problem}`);
      }
      const note = globalsNote(failures);
      if (note) lines.push(note);
    }
  } finally {
    session.close();
  }
  console.log(lines.join("\n"));
  return failed ? 1 : 0;
}

if (process.argv[2] === "--worker" && process.send) {
  work(process.argv[3], process.argv[4]);
} else {
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
}
