// The adapters `--adapter-template` prints: one to fill in, or, given a chapter file, one
// already filled in with the names that file's functions read (docs/students.md, "How the
// book's data reach your code").

import { NAMES } from "./names.mjs";

// Where a name of a student's own probably takes its value from, by its spelling; null
// when it cannot be told.
function guess(name) {
  const n = name.toLowerCase().replace(/_/g, "");
  const has = (...words) => words.some((word) => n.includes(word));
  if (has("depth")) return null;
  if (n === "viewport" || n === "canvas") return n; // an object with the case's fields
  if ((has("canvas", "screen", "image", "img") && has("width")) || ["cw", "width", "w"].includes(n))
    return "canvas.width";
  if (
    (has("canvas", "screen", "image", "img") && has("height")) ||
    ["ch", "height", "h"].includes(n)
  )
    return "canvas.height";
  if (has("viewport") && has("size")) return "viewport.size";
  if ((has("viewport") && has("width")) || n === "vw") return "viewport.width";
  if ((has("viewport") && has("height")) || n === "vh") return "viewport.height";
  if (has("projection", "plane", "distance") || ["d", "vd"].includes(n)) return "viewport.d";
  if (has("sphere")) return "scene.spheres";
  if (has("light")) return "scene.lights";
  if (has("background", "bg")) return "scene.background_color";
  if (has("camera") && has("pos", "origin")) return "camera.position";
  if (has("camera") && has("rot", "orient")) return "camera.rotation";
  return null;
}

const PYTHON_VALUES = {
  canvas: 'given["canvas"]',
  viewport: 'given["viewport"]',
  "canvas.width": 'given["canvas"]["width"]',
  "canvas.height": 'given["canvas"]["height"]',
  "viewport.size":
    'given["viewport"]["width"]  # square: the cases\' width (a case whose height differs fails)',
  "viewport.width": 'given["viewport"]["width"]',
  "viewport.height": 'given["viewport"]["height"]',
  "viewport.d": 'given["viewport"]["d"]',
  "scene.spheres": 'adapter.spheres(given["scene"].get("spheres", []))',
  "scene.lights": 'adapter.lights(given["scene"].get("lights", []))',
  "scene.background_color":
    'adapter.color(given["scene"].get("background_color", [255, 255, 255]))',
  "camera.position": 'adapter.vector(given["camera"]["position"])',
  "camera.rotation": 'adapter.rows(given["camera"]["rotation"])',
};
const JS_VALUES = {
  canvas: "given.canvas",
  viewport: "given.viewport",
  "canvas.width": "given.canvas.width",
  "canvas.height": "given.canvas.height",
  "viewport.size":
    "given.viewport.width;  // square: the cases' width (a case whose height differs fails)",
  "viewport.width": "given.viewport.width",
  "viewport.height": "given.viewport.height",
  "viewport.d": "given.viewport.d",
  "scene.spheres": "adapter.spheres(given.scene.spheres ?? [], adapter)",
  "scene.lights": "adapter.lights(given.scene.lights ?? [], adapter)",
  "scene.background_color":
    "adapter.color(given.scene.background_color ?? [255, 255, 255], adapter)",
  "camera.position": "adapter.vector(given.camera.position, adapter)",
  "camera.rotation": "adapter.rows(given.camera.rotation, adapter)",
};

// The names a chapter's functions read that are its own (not the checker's table's).
function ownNames(facts) {
  const names = new Set();
  for (const fact of Object.values(facts.functions)) {
    for (const [name, , kind] of fact.reads ?? [])
      if (kind === "data" && !(name in NAMES)) names.add(name);
    for (const { names: bound } of fact.bound ?? []) bound.forEach((name) => names.add(name));
  }
  return [...names].sort();
}

// The lines of a filled-in setup: each own name set from what the case gives, grouped
// by the part of the case it comes from.
function assignments(facts, language) {
  const python = language === "python";
  const values = python ? PYTHON_VALUES : JS_VALUES;
  const groups = new Map();
  const unknown = [];
  for (const name of ownNames(facts)) {
    const path = guess(name);
    if (!path) {
      unknown.push(name);
      continue;
    }
    const [part, field] = path.split(".");
    // Every case that gives a scene sets all of it: what it does not give is empty, so
    // that nothing of the case before stays.
    const key = part;
    if (!groups.has(key)) groups.set(key, []);
    // A list is filled in place in Python, so that a default argument bound to it sees it.
    const list = python && /^a list/.test(facts.data[name] ?? "");
    const target = list ? `module.${name}[:]` : `module.${name}`;
    groups
      .get(key)
      .push(`${target} = ${values[path]}${list ? "  # [:]: the same list, filled in place" : ""}`);
  }
  const lines = [];
  for (const [key, assigned] of groups) {
    const [part, field] = key.split(".");
    const test = python
      ? field
        ? `"${field}" in given.get("scene", {})`
        : `"${part}" in given`
      : field
        ? `given.scene?.${field} !== undefined`
        : `given.${part}`;
    lines.push(
      python ? `    if ${test}:` : `    if (${test}) {`,
      ...assigned.map((line) =>
        python ? `        ${line}` : `      ${line}${line.includes(";") ? "" : ";"}`,
      ),
    );
    if (!python) lines.push("    }");
  }
  for (const name of unknown) {
    lines.push(
      `    ${python ? "#" : "//"} your ${name} (${facts.data[name] ?? "read by your functions"}): what does it hold? Set it here if a case gives it.`,
    );
  }
  return lines;
}

const GIVEN = [
  "given.canvas    { width, height, and for drawing functions PutPixel(x, y, color) }",
  "given.viewport  { width, height, d }",
  "given.scene     { spheres: [...], lights: [...], background_color: [r, g, b] }",
  "given.camera    { position, rotation } (chapter 5), given.depth_buffer (chapter 12)",
];

// Builders of the chapter's own types: a class of three parameters named like a vector
// or a colour (Vec3(x, y, z), Color(r, g, b)) becomes the adapter's vector or color.
function typeLines(facts, language) {
  const python = language === "python";
  const lines = [];
  const used = [];
  for (const [name, params] of Object.entries(facts?.classes ?? {})) {
    if (params.length !== 3) continue;
    const named = params.join(",");
    const kind =
      /col/i.test(name) || named === "r,g,b"
        ? "color"
        : /vec|vert|point|v3/i.test(name) || named === "x,y,z"
          ? "vector"
          : null;
    if (!kind || lines.some((line) => line.includes(`${kind}(`) || line.includes(`${kind}:`)))
      continue;
    lines.push(
      python
        ? `def ${kind}(value):  # your ${name}\n    return ${name}(*value)\n`
        : `  ${kind}: ([a, b, c]) => new ${name}(a, b, c),  // your ${name}`,
    );
    used.push(name);
  }
  return { lines, used };
}

function pythonTemplate(filled, types = [], imports = "") {
  return `# An adapter for check-functions.js (docs/students.md, "How the book's data reach your
# code"): give it with --adapter. Define only what your module needs; each function here
# takes the place of the checker's own of the same name.
${imports}

def setup(module, given, adapter):
    """Called before each case with what the case gives (as dicts and lists):
${GIVEN.map((line) => `      ${line.replace(/given\.(\w+)/g, 'given["$1"]')}`).join("\n")}
    The checker has set the book's names already (Cw, Ch, Vw, Vh, d, scene,
    BACKGROUND_COLOR, PutPixel...), and the demos' (spheres, lights, viewport_size...)
    where your module reads them: set the names of your own here. adapter builds the
    book's records (fields read as sphere.radius or sphere["radius"]):
    adapter.spheres(...), adapter.lights(...), adapter.color(...), adapter.vector(...);
    make your own types here if your code needs them."""
${
  filled ??
  `    # For example, a canvas of your own:
    # if "canvas" in given:
    #     module.CANVAS_WIDTH = given["canvas"]["width"]
    #     module.CANVAS_HEIGHT = given["canvas"]["height"]
    pass`
}


${
  types.length
    ? `# Your own types, which your functions take (each gets the case's JSON value):\n${types.join("\n\n")}`
    : `# Your own types, if your functions take them (each gets the case's JSON value):
# def vector(value):
#     return MyVector(*value)
# def sphere(value):
#     return MySphere(center=value["center"], radius=value["radius"], color=value["color"])
`
}`;
}

function jsTemplate(filled, types = [], esm = null) {
  return `// An adapter for check-functions.js (docs/students.md, "How the book's data reach your
// code"): give it with --adapter. Export only what your chapter needs; each function here
// takes the place of the checker's own of the same name.${
    esm
      ? `
// Your chapter is an ES module: save this as an .mjs file beside it.
${esm}
export default {`
      : `
"use strict";

module.exports = {`
  }
  // Called before each case, with your chapter as \`module\` (its exports, or for a plain
  // script its top-level names: module.Cw = 600 sets its Cw) and what the case gives:
${GIVEN.map((line) => `  //   ${line}`).join("\n")}
  // The checker has set the book's names already (Cw, Ch, Vw, Vh, d, scene, PutPixel...),
  // and the demos' (canvas.width, viewport_size, spheres, lights...) where your chapter
  // reads them: set the names of your own here. \`adapter\` builds the book's objects
  // (adapter.scene(given.scene, adapter), adapter.vector(...)).
  setup(module, given, adapter) {
${
  filled ??
  `    // For example, a canvas of your own:
    // if (given.canvas) {
    //   module.canvasWidth = given.canvas.width;
    //   module.canvasHeight = given.canvas.height;
    // }`
}
  },
${
  types.length
    ? `  // Your own types, which your functions take (each gets the case's JSON value):\n${types.join("\n")}`
    : `  // Your own types, if your functions take them (each gets the case's JSON value):
  // vector: ([x, y, z]) => new Vec3(x, y, z),`
}
};
`;
}

// The template, filled in when the facts of a chapter file (named `file`) are given.
export function adapterTemplate(language, facts = null, file = "") {
  const python = language === "python";
  let filled = null;
  if (facts) {
    let lines = assignments(facts, language);
    if (!python && facts.reachable === "exports" && lines.length) {
      // An ES module's own names cannot be set from outside: through a function it exports.
      lines = [
        "    // Your ES module's own names are out of reach from here: export a function that sets",
        "    // them (declared with let), and call it here, chapter.configure(given) say. What each gets:",
        ...lines
          .filter((line) => /module\./.test(line))
          .map((line) => `    //   ${line.trim().replace(/^module\./, "")}`),
      ];
    }
    filled = (
      lines.length
        ? lines
        : [
            `    ${python ? "#" : "//"} your functions read no names of their own: the checker's defaults reach them`,
          ]
    ).join("\n");
    if (python && lines.every((line) => /^\s*#/.test(line))) filled += "\n    pass";
  }
  const { lines: types, used } = typeLines(facts, language);
  const stem = file.replace(/^.*\//, "").replace(/\.[^.]*$/, "");
  if (python)
    return pythonTemplate(
      filled,
      types,
      used.length ? `\nfrom ${stem} import ${used.join(", ")}\n` : "",
    );
  const esm =
    facts?.reachable === "exports"
      ? `import ${used.length ? `{ ${used.join(", ")} } ` : "* as chapter "}from "./${file.replace(/^.*\//, "")}";`
      : null;
  return jsTemplate(filled, types, esm);
}
