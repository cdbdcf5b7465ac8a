// A failed case as code to paste into the student's own REPL: the case's canvas,
// viewport and scene set under the book's names, and the call with the case's inputs,
// in Python or JavaScript, so that a student can print inside their function and call it
// again on exactly what the checker gave it.

import { NAMES } from "./names.mjs";

const VECTOR_FIELDS = new Set([
  "center",
  "position",
  "direction",
  "normal",
  "translation",
  "T",
  "B",
]);

// Python: vectors as named tuples V(x, y, z) (with .x, as the checker gives them),
// points P(x, y, h), records as SimpleNamespace R(...) (with .field), other lists as tuples.
function python(value, kind) {
  if (value === "inf") return 'float("inf")';
  if (value === "-inf") return '-float("inf")';
  if (typeof value === "number") return String(value);
  if (typeof value === "string") return JSON.stringify(value);
  if (typeof value === "boolean") return value ? "True" : "False";
  if (Array.isArray(value)) {
    if (kind === "vector" && value.length === 3)
      return `V(${value.map((each) => python(each)).join(", ")})`;
    if (kind === "point") return `P(${value.map((each) => python(each)).join(", ")})`;
    const items = value.map((each) => python(each, kind === "vectors" ? "vector" : undefined));
    return kind === "vectors" || value.some((each) => typeof each === "object")
      ? `[${items.join(", ")}]`
      : `(${items.join(", ")}${items.length === 1 ? "," : ""})`;
  }
  if (value && typeof value === "object") {
    const fields = Object.entries(value).map(
      ([key, each]) =>
        `${key}=${python(each, VECTOR_FIELDS.has(key) ? "vector" : key === "vertices" ? "vectors" : undefined)}`,
    );
    return `R(${fields.join(", ")})`;
  }
  return "None";
}

function javascript(value) {
  if (value === "inf") return "Infinity";
  if (value === "-inf") return "-Infinity";
  if (Array.isArray(value)) return `[${value.map(javascript).join(", ")}]`;
  if (value && typeof value === "object") {
    return `{ ${Object.entries(value)
      .map(
        ([key, each]) =>
          `${/^[A-Za-z_$][\w$]*$/.test(key) ? key : JSON.stringify(key)}: ${javascript(each)}`,
      )
      .join(", ")} }`;
  }
  return JSON.stringify(value);
}

// The kinds of record whose fields the checker also gives under the demos' names.
const ALIASED = new Set(["plane", "triangle"]);

// The demos' names the case's code read, as the runner reports them ({ distance: ["D"],
// v0: ["v", 0] }: the book's field each reads, and an index into it), as [name, field,
// index]; nothing the report does not expect from the student's process.
function demosFieldsOf(reported) {
  if (!reported || typeof reported !== "object" || Array.isArray(reported)) return [];
  return Object.entries(reported)
    .filter(
      ([name, read]) =>
        /^[A-Za-z_]\w*$/.test(name) &&
        Array.isArray(read) &&
        typeof read[0] === "string" &&
        (read.length === 1 || (read.length === 2 && Number.isInteger(read[1]))),
    )
    .map(([name, [field, index]]) => [name, field, index]);
}

// A plane, a triangle or a model's triangles with the demos' names the case's code read
// (`read`) as fields of their own, so that the pasted call gives what the checker gave.
function withDemosNames(value, kind, read) {
  if (!read.length || !value || typeof value !== "object" || Array.isArray(value)) return value;
  if (kind === "model" && Array.isArray(value.triangles))
    return {
      ...value,
      triangles: value.triangles.map((each) => withDemosNames(each, "triangle", read)),
    };
  if (!ALIASED.has(kind)) return value;
  const copied = read
    .filter(([name, field]) => field in value && !(name in value))
    .map(([name, field, index]) => [
      name,
      index === undefined ? value[field] : value[field]?.[index],
    ]);
  return { ...value, ...Object.fromEntries(copied) };
}

// The book's names the case gives, as [name, value, kind].
function settings(given) {
  const found = [];
  for (const [name, spec] of Object.entries(NAMES)) {
    if (spec.dialect !== "book") continue;
    const value = spec.path
      .split(".")
      .reduce((at, key) => (at && typeof at === "object" ? at[key] : undefined), given);
    if (value !== undefined) found.push([name, value, spec.kind ?? "number"]);
  }
  return found;
}

// The lines to paste, or [] where there is no REPL to paste them into (a page).
//   file: the student's file's name; signature: the call the checker made ({ call,
//   parameters }); kase: the case; drawing: whether the function draws through PutPixel;
//   demosFields: the demos' names the case's code read from the checker's records, as
//   the runner reported them.
export function readyCall(language, file, signature, kase, drawing, { demosFields } = {}) {
  const demosNames = demosFieldsOf(demosFields);
  const given = kase.given ?? {};
  const calls = kase.calls ?? [kase.args ?? {}];
  const name = signature.call.split("(")[0];
  // A list the function appends to (the demos' ClipTriangle): made empty before each call
  // under its parameter's name, and shown after the last.
  const outputs = signature.parameters
    .filter(([, kind]) => kind === "output")
    .map(([each]) => each);
  const argumentsOf = (call, format) =>
    signature.parameters.map(([parameter, kind, from]) =>
      kind === "output"
        ? parameter
        : format(
            from
              ? from.map((each) => call[each])
              : withDemosNames(call[parameter], kind, demosNames),
            kind,
          ),
    );
  if (language === "python") {
    const module = file.replace(/\.py$/, "");
    if (!/^[\w.-]+$/.test(module)) return [];
    const load = /^[A-Za-z_]\w*$/.test(module)
      ? `import ${module} as m`
      : `m = __import__(${JSON.stringify(module)})`;
    const lines = [
      "from collections import namedtuple; from types import SimpleNamespace as R",
      'V = namedtuple("V", "x y z"); P = namedtuple("P", "x y h", defaults=(1.0,))',
      load,
    ];
    const numbers = [];
    for (const [setting, value, kind] of settings(given)) {
      if (kind === "PutPixel") continue;
      if (kind === "number") numbers.push(`m.${setting} = ${python(value)}`);
      else if (kind === "depth_buffer")
        lines.push(
          `m.depth_buffer = [[0] * ${given.canvas.height} for _ in range(${given.canvas.width})]`,
        );
      else
        lines.push(
          `m.${setting} = ${python(value, kind === "camera" || kind === "scene" ? undefined : kind)}`,
        );
    }
    if (numbers.length) lines.splice(3, 0, numbers.join("; "));
    if (drawing) lines.push("m.PutPixel = lambda x, y, color: print(x, y, color)");
    for (const call of calls) {
      if (outputs.length) lines.push(outputs.map((each) => `${each} = []`).join("; "));
      lines.push(`m.${name}(${argumentsOf(call, python).join(", ")})`);
    }
    if (outputs.length) lines.push(outputs.join(", "));
    return lines;
  }
  if (/\.html?$/i.test(file)) return [];
  if (/\.mjs$/.test(file)) {
    const lines = [`const m = await import("./${file}");`];
    for (const call of calls) {
      if (outputs.length) lines.push(outputs.map((each) => `${each} = [];`).join(" "));
      lines.push(`m.${name}(${argumentsOf(call, javascript).join(", ")})`);
    }
    if (outputs.length) lines.push(outputs.join(", "));
    return lines;
  }
  const lines = [`.load ${file}`];
  const assignments = settings(given)
    .filter(([, , kind]) => kind !== "PutPixel")
    .map(([setting, value, kind]) =>
      kind === "depth_buffer"
        ? `depth_buffer = Array.from({ length: ${given.canvas.width} }, () => new Array(${given.canvas.height}).fill(0));`
        : `${setting} = ${javascript(value)};`,
    );
  if (assignments.length) lines.push(assignments.join(" "));
  if (drawing) lines.push("PutPixel = (x, y, color) => console.log(x, y, color);");
  for (const call of calls) {
    if (outputs.length) lines.push(outputs.map((each) => `${each} = [];`).join(" "));
    lines.push(`${name}(${argumentsOf(call, javascript).join(", ")})`);
  }
  if (outputs.length) lines.push(outputs.join(", "));
  return lines;
}
