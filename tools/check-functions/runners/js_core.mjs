// The heart of the JavaScript runner, wherever the student's code runs: in a Node.js
// process (js_runner.mjs, for the command line) or in a Web Worker of a chapter's page
// (js_worker.mjs). What a chapter defines and reads, the case's data built and put where
// it reads them, a case run and its answer made plain data. Nothing here judges: the
// runner is never told what a case expects (tools/check-functions/core judges).
// An environment gives the parser (acorn and acorn-globals, useParser) and, to each
// ChapterBase, the function that evaluates code in the chapter's global scope.

let acorn = null;
let findGlobals = null;

// The parser: acorn, and acorn-globals (which finds the global names a program reads).
export function useParser(acornModule, findGlobalsFunction) {
  acorn = acornModule;
  findGlobals = findGlobalsFunction;
}

export const MAX_ITEMS = 200_000; // numbers, strings and lists in one answer
export const MAX_ANSWER = 4 << 20; // characters of one answer
const MAX_PIXELS = 100_000; // PutPixel calls one case may make
// The names a chapter finds in its global scope before it runs: not its own.
const BUILTINS = new Set([
  ...Object.getOwnPropertyNames(globalThis),
  "require",
  "module",
  "exports",
  "__filename",
  "__dirname",
  "undefined",
  "arguments",
  "this",
  "window",
  "document",
  "Image",
  "requestAnimationFrame",
  "alert",
  "self",
  "postMessage",
  "importScripts",
  "onmessage",
]);

export class LoadError extends Error {}

// The names errors give the student's files, where they ran under another (a chapter
// page runs the reader's code from a Blob's address): address -> name.
const sourceNames = new Map();
export function nameSource(address, name) {
  sourceNames.set(address, name);
}

// An error in one line, at the last line of the student's code it went through (a stack
// line that names none of `ours`).
export function oneLine(error, ours = []) {
  for (const [address, name] of sourceNames) {
    if (error && typeof error === "object" && typeof error.stack === "string")
      error.stack = error.stack.replaceAll(address, name);
  }
  if (!(error instanceof Error) && !(error && typeof error === "object" && "stack" in error)) {
    return `${typeof error} ${String(error).slice(0, 200)}`;
  }
  const line = String(error.stack ?? "")
    .split("\n")
    .find(
      (each) =>
        /:\d+:\d+\)?$/.test(each) &&
        !ours.some((dir) => each.includes(dir)) &&
        !each.includes("node:"),
    );
  const place = line
    ? ` (at ${line
        .replace(/^.*\(|^\s*at /g, "")
        .replace(/:\d+\)?$/, "")
        .replace(/^.*\//, "")})`
    : "";
  return `${error.name}: ${String(error.message).split("\n")[0]}${place}`;
}

export function syntaxError(error, filename, lineOffset) {
  const line = (error.loc?.line ?? 0) + lineOffset;
  return new LoadError(
    `SyntaxError: ${error.message.replace(/ \(\d+:\d+\)$/, "")} (at ${filename.replace(/^.*\//, "")}:${line})`,
  );
}

// The top-level declarations of a script or module: name -> { kind, source }, kind one of
// "function", "class", "data", "import".
export function declarations(program, code) {
  const found = new Map();
  const declare = (pattern, kind, source) => {
    if (!pattern) return;
    if (pattern.type === "Identifier") found.set(pattern.name, { kind, source });
    else if (pattern.type === "ObjectPattern")
      pattern.properties.forEach((p) => declare(p.value ?? p.argument, "data"));
    else if (pattern.type === "ArrayPattern") pattern.elements.forEach((p) => declare(p, "data"));
    else if (pattern.type === "AssignmentPattern") declare(pattern.left, kind, source);
    else if (pattern.type === "RestElement") declare(pattern.argument, "data");
  };
  const text = (node) => code.slice(node.start, node.end);
  for (let node of program.body) {
    if (node.type === "ExportNamedDeclaration" || node.type === "ExportDefaultDeclaration")
      node = node.declaration ?? node;
    if (node.type === "FunctionDeclaration") declare(node.id, "function", text(node));
    else if (node.type === "ClassDeclaration") declare(node.id, "class");
    else if (node.type === "ImportDeclaration")
      node.specifiers.forEach((s) => declare(s.local, "import"));
    else if (node.type === "VariableDeclaration") {
      for (const each of node.declarations) {
        const init = each.init;
        const isFunction = init && /^(FunctionExpression|ArrowFunctionExpression)$/.test(init.type);
        const isRequire = init?.type === "CallExpression" || init?.type === "MemberExpression";
        declare(
          each.id,
          isFunction
            ? "function"
            : init?.type === "ClassExpression"
              ? "class"
              : isRequire
                ? "import"
                : "data",
          isFunction ? text(init) : undefined,
        );
      }
    }
  }
  return found;
}

// The functions a script or module defines at its top level, read from its syntax tree
// before any of it runs: name -> { count, required, more, empty } (empty: a body with
// nothing in it, as a page's starter leaves it: not written yet).
export function declaredFunctions(program) {
  const found = new Map();
  const describe = (node) => {
    const { names, required, more } = parametersOf(node);
    const empty = node.body.type === "BlockStatement" && node.body.body.length === 0;
    return { count: names.length, required, more, empty };
  };
  for (let node of program.body) {
    if (node.type === "ExportNamedDeclaration" && node.declaration) node = node.declaration;
    if (node.type === "FunctionDeclaration" && node.id) found.set(node.id.name, describe(node));
    if (node.type !== "VariableDeclaration") continue;
    for (const each of node.declarations) {
      if (
        each.id.type === "Identifier" &&
        /^(FunctionExpression|ArrowFunctionExpression)$/.test(each.init?.type)
      ) {
        found.set(each.id.name, describe(each.init));
      }
    }
  }
  return found;
}

// A script's top-level `const`s made `let` (the same length, so that lines and columns
// stay), so that the checker can set them before each case.
export function constsMadeLet(program, code) {
  let result = code;
  for (let node of program.body) {
    if (node.type === "ExportNamedDeclaration" && node.declaration) node = node.declaration;
    if (node.type === "VariableDeclaration" && node.kind === "const") {
      result = result.slice(0, node.start) + "let  " + result.slice(node.start + 5);
    }
  }
  return result;
}

// An ES module's source made settable from outside, as a script's is: its `const`s made
// `let`, and two functions appended that read and set its top-level variables by name.
export function moduleMadeSettable(program, code) {
  const names = [];
  for (let node of program.body) {
    if (node.type === "ExportNamedDeclaration" && node.declaration) node = node.declaration;
    if (node.type !== "VariableDeclaration") continue;
    for (const each of node.declarations)
      if (each.id.type === "Identifier") names.push(each.id.name);
  }
  const cases = (body) =>
    names.map((name) => `case ${JSON.stringify(name)}: ${body(name)}`).join(" ");
  return `${constsMadeLet(program, code)}
;export function ${SETTER}(name, value) { switch (name) { ${cases((name) => `${name} = value; return true;`)} } return false; }
export function ${GETTER}(name) { switch (name) { ${cases((name) => `return ${name};`)} } return undefined; }
`;
}
export const SETTER = "__cgfsSet",
  GETTER = "__cgfsGet";

export const parse = (code, sourceType) =>
  acorn.parse(code, { ecmaVersion: "latest", sourceType, allowHashBang: true });

// The chapter as loaded: its kind ("script": plain scripts, CommonJS files, a page's
// scripts, every top-level name in reach; "module": an ES module, only its exports), its
// declarations, and what it exports. `evaluate` runs code in the chapter's global scope.
export class ChapterBase {
  constructor(file, evaluate) {
    Object.assign(this, { file, evaluate, declared: new Map(), kind: "script", exports: {} });
  }

  // A script's declarations, once it has run (or before: they are hoisted).
  declare(program, code) {
    for (const [name, each] of declarations(program, code)) this.declared.set(name, each);
  }

  // What a name holds now: a top-level binding of a script, or an export or global.
  value(name) {
    if (this.kind === "script") {
      try {
        return this.evaluate(`typeof ${name} === "undefined" ? undefined : ${name}`);
      } catch {
        return undefined; // a \`let\` read before its line ran
      }
    }
    if (this.settable?.has(name)) return this.settable.get(name);
    return name in this.exports ? this.exports[name] : globalThis[name];
  }

  assign(name, value) {
    globalThis.__cgfsValue = value;
    try {
      if (this.kind === "script") this.evaluate(`${name} = globalThis.__cgfsValue`);
      else if (!this.settable?.set(name, value)) globalThis[name] = value;
    } finally {
      delete globalThis.__cgfsValue;
    }
  }

  // What a student's adapter gets as the chapter: an ES module's exports; for a script,
  // its exports and top-level names, module.Cw = 600 setting its Cw.
  asModule() {
    if (this.kind === "module" && !this.settable) return this.exports;
    return new Proxy(
      {},
      {
        get: (_, name) =>
          typeof name !== "string"
            ? undefined
            : name in this.exports
              ? this.exports[name]
              : this.value(name),
        has: (_, name) =>
          typeof name === "string" && (name in this.exports || this.value(name) !== undefined),
        set: (_, name, value) => {
          if (typeof name !== "string") return true;
          if (/^[A-Za-z_$][\w$]*$/.test(name)) this.assign(name, value);
          if (name in this.exports) this.exports[name] = value;
          return true;
        },
      },
    );
  }
}

// ---- What the checker is told ---------------------------------------------------------

function functionNode(source) {
  for (const wrapped of [source, `(${source})`, `({${source}})`]) {
    try {
      const program = parse(wrapped, "script");
      let node = program.body[0];
      if (node?.type === "ExpressionStatement") node = node.expression;
      if (node?.type === "ObjectExpression") node = node.properties[0]?.value;
      if (node && /Function/.test(node.type)) return { node, program };
    } catch {
      // the next wrapping
    }
  }
  return null;
}

function parametersOf(node) {
  const names = [];
  let required = 0,
    optional = false,
    more = false;
  for (const param of node.params) {
    if (param.type === "RestElement") {
      more = true;
      continue;
    }
    if (param.type === "AssignmentPattern") optional = true;
    if (!optional) required += 1;
    names.push(param.type === "Identifier" ? param.name : (param.left?.name ?? "…"));
  }
  return { names, required, more };
}

// The top-level names a function reads, through the functions of the chapter it calls:
// { reads: [[name, "", "data" | "missing"]...], complete }.
function readsOf(chapter, source, names, wanted) {
  const reads = new Map();
  const calls = new Set();
  let complete = true;
  const seen = new Set();
  const stack = [source];
  while (stack.length > 0) {
    const current = stack.pop();
    if (seen.has(current)) continue;
    seen.add(current);
    const parsed = functionNode(current);
    if (!parsed) {
      complete = false;
      continue;
    }
    for (const { name } of findGlobals(parsed.program)) {
      const declared = chapter.declared.get(name);
      const value = chapter.value(name);
      if (name in names) {
        // the checker sets it: read, never followed
        reads.set(name, value === undefined ? "missing" : "data");
        continue;
      }
      if (declared?.kind === "function") {
        stack.push(declared.source);
        if (wanted.includes(name) && declared.source !== source) calls.add(name);
        continue;
      }
      if (declared?.kind === "class" || (!declared && BUILTINS.has(name))) continue;
      if (declared?.kind === "import") {
        complete = false;
        continue;
      } // another file's: not followed
      if (typeof value === "function") {
        // A function from elsewhere (required, imported, made by a call): not followed.
        if (!/\[native code\]/.test(value.toString())) complete = false;
        continue;
      }
      // A name the chapter declares is its own data, reachable or not (an ES module's).
      reads.set(name, value === undefined && declared?.kind !== "data" ? "missing" : "data");
    }
  }
  return {
    reads: [...reads].sort().map(([name, kind]) => [name, "", kind]),
    complete,
    calls: [...calls].sort(),
  };
}

function describe(value) {
  if (value === null || value === undefined || typeof value === "boolean") return String(value);
  if (typeof value === "number") return String(value);
  if (Array.isArray(value)) return `an array of ${value.length}`;
  return `a ${typeof value === "object" ? (value.constructor?.name ?? "object") : typeof value}`;
}

export function factsOf(chapter, wanted, names) {
  const functions = {};
  for (const name of wanted) {
    const fn = chapter.value(name);
    if (typeof fn !== "function") continue;
    const parsed = functionNode(fn.toString());
    functions[name] = {
      parameters: parsed ? parametersOf(parsed.node) : null,
      reads: null,
      complete: false,
      bound: [],
      calls: [],
      empty: parsed?.node.body.type === "BlockStatement" && parsed.node.body.body.length === 0,
    };
    if (parsed) Object.assign(functions[name], readsOf(chapter, fn.toString(), names, wanted));
  }
  const data = {};
  for (const [name, each] of chapter.declared) {
    if (each.kind === "data") data[name] = describe(chapter.value(name));
  }
  // The chapter's own types, with what their constructors take (for an adapter's
  // vector(value) and color(value)).
  const classes = {};
  for (const [name, each] of chapter.declared) {
    const value = chapter.value(name);
    if (
      (each.kind === "class" || (each.kind === "function" && /^[A-Z]/.test(name))) &&
      typeof value === "function"
    ) {
      const source = value.toString();
      const constructor = /^class\b/.test(source)
        ? (/constructor\s*\(([^)]*)\)/.exec(source)?.[1] ?? "")
        : (/^function\s*\w*\s*\(([^)]*)\)/.exec(source)?.[1] ?? "");
      classes[name] = constructor
        .split(",")
        .map((p) => p.trim().split(/[\s=]/)[0])
        .filter(Boolean);
    }
  }
  return {
    functions,
    data,
    defined: [...chapter.declared.keys(), ...Object.keys(chapter.exports)],
    reachable: chapter.kind === "script" || chapter.settable ? "all" : "exports",
    classes,
  };
}

// ---- Building a case's data -----------------------------------------------------------

const number = (value) =>
  value === "inf" ? Infinity : value === "-inf" ? -Infinity : Number(value);
const numbers = (value) => Array.from(value, number);

export function decoded(value) {
  if (value === "inf" || value === "-inf") return number(value);
  if (Array.isArray(value)) return value.map(decoded);
  if (value && typeof value === "object")
    return Object.fromEntries(Object.entries(value).map(([k, v]) => [k, decoded(v)]));
  return value;
}

const at = (given, dotted) =>
  dotted
    .split(".")
    .reduce((value, key) => (value && typeof value === "object" ? value[key] : undefined), given);

// The chapter's own helpers, where it has them, so that a chapter in the demos' style
// gets its own Vec, Color and Pt (with their methods): each used only when what it
// makes holds the values it was given.
export function helpers(chapter) {
  const made = (names, check) => {
    for (const name of names) {
      const make = chapter.value(name);
      if (typeof make !== "function") continue;
      return (...values) => {
        let made_;
        try {
          made_ = new make(...values);
        } catch {
          return null;
        }
        return made_ && check(made_, values) ? made_ : null;
      };
    }
    return () => null;
  };
  const xyz = (v, [x, y, z]) => v.x === x && v.y === y && v.z === z;
  const rgb = (c, [r, g, b]) =>
    (c.r === r && c.g === g && c.b === b) || (c[0] === r && c[1] === g && c[2] === b);
  const light = chapter.value("Light");
  return {
    vector: made(["Vec", "Vec3", "Vector", "Vector3", "Vertex"], xyz),
    color: made(["Color"], rgb),
    point: made(["Pt", "Point"], (p, [x, y]) => p.x === x && p.y === y),
    matrix: made(["Mat4x4"], (m, [rows]) => Array.isArray(m.data) && m.data[0]?.[0] === rows[0][0]),
    sphere: made(["Sphere"], (s, [center, radius]) => s.center === center && s.radius === radius),
    lightTypes:
      light && "AMBIENT" in light
        ? { field: "ltype", value: (type) => light[type.toUpperCase()], vector: "position" }
        : chapter.value("LT_AMBIENT") !== undefined
          ? {
              field: "type",
              value: (type) => chapter.value(`LT_${type.toUpperCase()}`),
              vector: "vector",
            }
          : null,
  };
}

// An array whose items are also read and written by name (v[0] and v.x), as the book
// writes a vertex's v.x and the demos index theirs; the names are not its own keys, so
// it reads, spreads and prints as the array it is.
function named(array, names) {
  names.forEach((name, i) =>
    Object.defineProperty(array, name, {
      get() {
        return this[i];
      },
      set(value) {
        this[i] = value;
      },
      enumerable: false,
      configurable: true,
    }),
  );
  return array;
}

// A record that also reads and writes its fields under the demos' names (aliases: the
// demos' name -> the book's field, and an index into it where the demos spread a list),
// as a triangle's indexes (demos/raster-10.html and on) or v0, v1, v2 (raster-09) for
// its v; the aliases are not its own keys, so it spreads and prints as the book's record.
// The aliases a case's code read, each with its field (and index), for the call the
// report gives to paste into a REPL.
const demosFieldsRead = new Map();
function aliased(record, aliases) {
  for (const [alias, [field, index]] of Object.entries(aliases)) {
    Object.defineProperty(record, alias, {
      get() {
        demosFieldsRead.set(alias, index === undefined ? [field] : [field, index]);
        return index === undefined ? this[field] : this[field][index];
      },
      set(value) {
        if (index === undefined) this[field] = value;
        else this[field][index] = value;
      },
      enumerable: false,
      configurable: true,
    });
  }
  return record;
}

// The fields a case's code read from the checker's scene that it does not have (a
// scene of the student's own, `scene.background`): JavaScript gives undefined where
// Python raises, so a failing case names them as Python's AttributeError does. Reset
// for each case; not watched while a figure is drawn (a read through the watch takes
// some 45 ns, and a figure's rays make millions).
const absentReads = new Set();
let watching = false;
const NOT_FIELDS = new Set(["then", "toJSON", "constructor", "toString", "valueOf"]);
function watched(record) {
  if (!watching) return record;
  return new Proxy(record, {
    get(target, key, receiver) {
      if (typeof key === "string" && !(key in target) && !NOT_FIELDS.has(key)) absentReads.add(key);
      return Reflect.get(target, key, receiver);
    },
  });
}

// How the book's data reach the chapter, unless its adapter says otherwise: vectors and
// colours as arrays (or the chapter's Vec and Color), spheres, lights and scenes as plain
// objects with the book's fields (or the demos', for a chapter in their style).
export function defaultAdapter(made) {
  return {
    vector: (value) => made.vector(...numbers(value)) ?? named(numbers(value), ["x", "y", "z"]),
    point: ([x, y, h = 1]) =>
      made.point(number(x), number(y), number(h)) ?? { x: number(x), y: number(y), h: number(h) },
    // A canvas point as the demos' ray tracers pass it, CanvasToViewport([x, y]).
    pair: (value) => named(numbers(value), ["x", "y"]),
    color: (value) => made.color(...numbers(value)) ?? named(numbers(value), ["r", "g", "b"]),
    matrix: (rows) => made.matrix(rows.map(numbers)) ?? rows.map(numbers),
    rows: (rows) => rows.map(numbers),
    vectors: (value, adapter) => value.map((each) => adapter.vector(each, adapter)),
    plane: (value, adapter) =>
      aliased(
        { normal: adapter.vector(value.normal, adapter), D: number(value.D) },
        { distance: ["D"] },
      ),
    booleans: (value) => value.map(Boolean),
    tangent_basis: (value, adapter) => ({
      T: adapter.vector(value.T, adapter),
      B: adapter.vector(value.B, adapter),
    }),
    triangle: (value, adapter) =>
      aliased(
        { v: [...value.v], color: adapter.color(value.color, adapter) },
        { indexes: ["v"], v0: ["v", 0], v1: ["v", 1], v2: ["v", 2] },
      ),
    // A list the function appends its results to (the demos' ClipTriangle(triangle, plane,
    // triangles, vertices)): empty.
    output: () => [],
    model: (value, adapter) => ({
      vertices: adapter.vectors(value.vertices, adapter),
      triangles: value.triangles.map((each) => adapter.triangle(each, adapter)),
    }),
    // texture[i][j]: the texel in column i, row j (rows from the top).
    texture(value, adapter) {
      const { width, height } = value;
      const columns = Array.from({ length: width }, (_, i) =>
        Array.from({ length: height }, (_, j) =>
          adapter.color(value.texels[j * width + i], adapter),
        ),
      );
      return Object.assign(columns, { width, height });
    },
    transform: (value, adapter) => ({
      scale: number(value.scale),
      rotation: adapter.matrix(value.rotation, adapter),
      translation: adapter.vector(value.translation, adapter),
    }),
    // A sphere: the chapter's own Sphere(center, radius, color, specular, reflective),
    // the demos' order, where it has one that keeps them; else a plain object.
    sphere(value, adapter) {
      const fields = [
        adapter.vector(value.center, adapter),
        number(value.radius),
        adapter.color(value.color, adapter),
        number(value.specular ?? -1),
        number(value.reflective ?? 0),
      ];
      return (
        made.sphere(...fields) ?? {
          center: fields[0],
          radius: fields[1],
          color: fields[2],
          specular: fields[3],
          reflective: fields[4],
        }
      );
    },
    // A light with its type's fields only (an ambient light has no position or direction),
    // or as the demos make it: Light.POINT in ltype and the direction in position.
    light(value, adapter) {
      const where = value.position ?? value.direction;
      if (made.lightTypes) {
        const light = {
          [made.lightTypes.field]: made.lightTypes.value(value.type),
          intensity: number(value.intensity),
        };
        if (where) light[made.lightTypes.vector] = adapter.vector(where, adapter);
        return light;
      }
      const light = { type: value.type, intensity: number(value.intensity) };
      for (const field of ["position", "direction"])
        if (value[field]) light[field] = adapter.vector(value[field], adapter);
      return light;
    },
    spheres: (value, adapter) => value.map((each) => adapter.sphere(each, adapter)),
    lights: (value, adapter) => value.map((each) => adapter.light(each, adapter)),
    scene: (value, adapter) =>
      watched({
        spheres: adapter.spheres(value.spheres ?? [], adapter),
        lights: adapter.lights(value.lights ?? [], adapter),
        background_color: adapter.color(value.background_color ?? [255, 255, 255], adapter),
      }),
    camera: (value, adapter) => ({
      position: adapter.vector(value.position, adapter),
      rotation: adapter.rows(value.rotation, adapter),
    }),
    // Chapter 12's buffer, depth_buffer[x][y] with x and y from 0: 0 is 1/z infinitely far.
    depth_buffer: (canvas) =>
      Array.from({ length: canvas.width }, () => new Array(canvas.height).fill(0)),
  };
}

// The names of the checker's table the case gives, set where the chapter reads them.
function place(chapter, names, given, adapter, readNames) {
  const placed = [];
  for (const [name, spec] of Object.entries(names)) {
    let value = at(given, spec.path);
    if (
      (value === undefined || value === null) &&
      spec.empty &&
      at(given, spec.path.split(".").slice(0, -1).join("."))
    )
      value = spec.empty;
    if (value === undefined || value === null) continue;
    if (spec.dialect !== "book" && !chapter.declared.has(name) && !readNames.has(name)) continue;
    const kind = spec.kind ?? "number";
    if (kind === "canvas") {
      // The demos' canvas.width, and the book's canvas.PutPixel(x, y, color) in a drawing case.
      const fields = {
        width: value.width,
        height: value.height,
        ...(value.PutPixel ? { PutPixel: value.PutPixel } : {}),
      };
      const canvas = chapter.value("canvas");
      if (canvas && typeof canvas === "object") Object.assign(canvas, fields);
      else chapter.assign(name, fields);
    } else if (kind === "scene" && Array.isArray(chapter.value(name))) {
      chapter.assign(name, adapter.spheres(value.spheres ?? [], adapter)); // a scene kept as the list of its spheres
    } else {
      chapter.assign(
        name,
        kind === "number"
          ? number(value)
          : kind === "PutPixel"
            ? value
            : kind === "depth_buffer"
              ? adapter.depth_buffer(given.canvas, adapter)
              : adapter[kind](value, adapter),
      );
    }
    placed.push(name);
  }
  return placed;
}

// ---- A case ---------------------------------------------------------------------------

// Answers as plain data: numbers, strings, lists and records of the fields a value has,
// nothing of the student's types; infinities and NaN as the strings JSON lacks them for.
const FIELDS = [
  "x",
  "y",
  "z",
  "w",
  "h",
  "r",
  "g",
  "b",
  "center",
  "radius",
  "v",
  "indexes",
  "v0",
  "v1",
  "v2",
  "data",
  "triangles",
  "vertices",
  "color",
];
export function plain(value, budget, depth = 0) {
  if (--budget.left < 0 || depth > 12) throw new RangeError("too large");
  if (value === null || value === undefined) return null;
  if (typeof value === "number")
    return Number.isFinite(value)
      ? value
      : Number.isNaN(value)
        ? "nan"
        : value > 0
          ? "inf"
          : "-inf";
  if (typeof value === "boolean") return value;
  if (typeof value === "string") return value.slice(0, 200);
  if (typeof value === "bigint") return Number(value);
  if (typeof value !== "object") return `a ${typeof value}`;
  if (Array.isArray(value) || ArrayBuffer.isView(value)) {
    if (value.length > MAX_ITEMS) throw new RangeError("too large");
    return Array.from(value, (each) => plain(each, budget, depth + 1));
  }
  const fields = {};
  for (const key of Object.keys(value).slice(0, 1000)) {
    if (typeof value[key] !== "function") fields[key] = plain(value[key], budget, depth + 1);
  }
  for (const key of FIELDS) {
    if (!(key in fields) && key in value && typeof value[key] !== "function")
      fields[key] = plain(value[key], budget, depth + 1);
  }
  if (Object.keys(fields).length === 0 && typeof value[Symbol.iterator] === "function") {
    const items = [];
    for (const each of value) {
      if (items.length >= MAX_ITEMS) throw new RangeError("too large");
      items.push(plain(each, budget, depth + 1));
    }
    return items;
  }
  return fields;
}

// A call's arguments, each built by its parameter's kind from the case's value (or, for
// a parameter made of several, `from`, from theirs: the demos' p2d from x and y).
function argumentsOf(parameters, call, adapter) {
  return parameters.map(([name, kind, from]) => {
    const value = decoded(from ? from.map((each) => call[each]) : call[name]);
    return kind === "number" ? number(value) : adapter[kind](value, adapter);
  });
}

// What the function made of one case: { returned, arguments, pixels, placed }, or
// { raised } / { adapter_failed }.
export function runCase(request, chapter, adapter, names, readNames, functionReads, ours = []) {
  const given = decoded(request.given ?? {});
  let pixels = null;
  if (request.drawing) {
    pixels = [];
    given.canvas.PutPixel = (x, y, color) => {
      if (pixels.length >= MAX_PIXELS)
        throw new RangeError(`more than ${MAX_PIXELS} PutPixel calls`);
      pixels.push([x, y, color]);
    };
  }
  let placed, calls;
  try {
    watching = true; // the scene this case's values make is watched
    placed = place(chapter, names, given, adapter, readNames);
    if (adapter.setup)
      placed.push(...setUpByAdapter(chapter, adapter, given, functionReads(request.function)));
    calls = request.calls.map((call) => argumentsOf(request.parameters, call, adapter));
  } catch (error) {
    if (error?.code === "ERR_SCRIPT_EXECUTION_TIMEOUT") throw error;
    return { adapter_failed: oneLine(error, ours) };
  } finally {
    watching = false;
  }
  const fn = chapter.value(request.function);
  let value,
    args = [];
  const whatItRead = () => ({
    ...(absentReads.size > 0 ? { absent: [...absentReads].slice(0, 5) } : {}),
    ...(demosFieldsRead.size > 0
      ? { demos_fields: Object.fromEntries([...demosFieldsRead].sort()) }
      : {}),
  });
  absentReads.clear(); // what the function reads, not the adapter's setup
  demosFieldsRead.clear();
  try {
    for (args of calls) value = fn(...args);
  } catch (error) {
    if (error?.code === "ERR_SCRIPT_EXECUTION_TIMEOUT") throw error;
    return { raised: oneLine(error, ours), placed, ...whatItRead() };
  }
  const answer = { placed, returned: value, ...whatItRead() };
  if (pixels) answer.pixels = pixels;
  if (adapter.result) {
    try {
      answer.returned = adapter.result(request.returns, value, given, adapter);
    } catch (error) {
      return { adapter_failed: `your adapter's result: ${oneLine(error, ours)}` };
    }
  }
  if (request.arguments) answer.arguments = args;
  return plain(answer, { left: MAX_ITEMS });
}

// An adapter's setup, after the checker's names are set; the names the function reads
// that it set.
function setUpByAdapter(chapter, adapter, given, readNames) {
  const fingerprint = (name) => {
    const value = chapter.value(name);
    return Array.isArray(value)
      ? [value, ...value]
      : value && typeof value === "object"
        ? [value, ...Object.values(value)]
        : [value];
  };
  // A number or string is boxed while setup runs, so that setting it again to the same
  // value (600 for 600) is seen as set; one left as it was is unboxed.
  const boxed = new Map();
  for (const name of readNames) {
    const value = chapter.value(name);
    if (typeof value === "number" || typeof value === "string") {
      const box = Object(value);
      chapter.assign(name, box);
      boxed.set(name, [box, value]);
    }
  }
  const before = new Map([...readNames].map((name) => [name, fingerprint(name)]));
  try {
    adapter.setup(chapter.asModule(), given, adapter);
  } finally {
    for (const [name, [box, value]] of boxed) {
      if (chapter.value(name) === box) chapter.assign(name, value);
      else boxed.set(name, null); // set by the setup
    }
  }
  return [...readNames].filter((name) => {
    if (boxed.has(name)) return boxed.get(name) === null;
    const now = fingerprint(name),
      then = before.get(name);
    return now.length !== then.length || now.some((each, i) => each !== then[i]);
  });
}

// ---- A figure drawn with the chapter's own functions (a chapter page's Draw) --------

// A colour channel as a canvas keeps it: clamped to 0..255, rounded half up.
const channel = (value) => (!(value > 0) ? 0 : value >= 255 ? 255 : Math.floor(value + 0.5));

// Draws a figure (tools/site/drawings.json) with the chapter's functions: its canvas,
// viewport and scene put where the chapter reads them, as a case's are, then a ray per
// pixel through the chapter's TraceRay, or calls to its drawing functions, each argument
// built as the cases build it (`kinds`: a function's parameters and their kinds) or the
// value a call of the chapter's returned. RGBA pixels, white where nothing was put.
export function drawFigure(recipe, chapter, adapter, names, readNames, kinds, progress = () => {}) {
  const { width, height } = recipe.given.canvas;
  const pixels = new Uint8ClampedArray(width * height * 4).fill(255);
  const put = (x, y, color) => {
    const [column, row] = [
      Math.floor(width / 2) + Math.trunc(x),
      Math.floor(height / 2) - Math.trunc(y) - 1,
    ];
    if (!(column >= 0 && column < width && row >= 0 && row < height)) return;
    const rgb =
      Array.isArray(color) || ArrayBuffer.isView(color) ? color : [color?.r, color?.g, color?.b];
    pixels.set(
      [channel(rgb[0]), channel(rgb[1]), channel(rgb[2]), 255],
      (row * width + column) * 4,
    );
  };
  const given = decoded(recipe.given);
  given.canvas = { ...given.canvas, PutPixel: put };
  const notes = [];
  place(chapter, names, given, adapter, readNames);
  const theirs = (name) => {
    const fn = chapter.value(name);
    if (typeof fn !== "function") throw new Error(`${name} is not written yet`);
    return fn;
  };
  if (recipe.rays) {
    const { origin, direction, t_min: tMin, recursion_depth: depth } = recipe.rays;
    const trace = theirs("TraceRay");
    // The book's (x, y) straight through; another signature's (the demos' p2d) built as
    // its cases are, from x and y.
    const own = theirs(direction);
    const pixel = kinds[direction];
    const through =
      !pixel || pixel.every(([, kind, from]) => kind === "number" && !from)
        ? own
        : (x, y) => own(...argumentsOf(pixel, { x, y }, adapter));
    const O = adapter.vector(origin, adapter);
    for (let x = -Math.floor(width / 2); x < Math.ceil(width / 2); ++x) {
      for (let y = -Math.floor(height / 2); y < Math.ceil(height / 2); ++y) {
        const D = through(x, y);
        put(
          x,
          y,
          depth === undefined ? trace(O, D, tMin, Infinity) : trace(O, D, tMin, Infinity, depth),
        );
      }
      if (x % 20 === 0) progress((x + width / 2) / width);
    }
  } else {
    const call = (name, args) =>
      theirs(name)(
        ...(kinds[name] ?? []).map(([parameter, kind]) => {
          const value = args[parameter];
          if (!(value && typeof value === "object" && "call" in value)) {
            return kind === "number" ? number(value) : adapter[kind](decoded(value), adapter);
          }
          const made = call(value.call, value.args);
          if (kind === "point") notes.push(...fractionNote(value.call, made, notes));
          return made;
        }),
      );
    for (const [name, args] of recipe.calls) call(name, args);
  }
  return { pixels, width, height, notes };
}

// The line that says a function of the reader's made a canvas point that is not a whole
// pixel, once: its drawing functions then draw from other end points than ours.
function fractionNote(name, point, notes) {
  const [x, y] = Array.isArray(point) ? point : [point?.x, point?.y];
  if (notes.length > 0 || (Number.isInteger(x) && Number.isInteger(y))) return [];
  return [
    `your ${name} returned the canvas point (${x}, ${y}): ours are whole pixels, truncated toward zero ` +
      '(docs/conventions.md, "Rounding in the rasterizer"), and your drawing functions draw from other end points',
  ];
}
