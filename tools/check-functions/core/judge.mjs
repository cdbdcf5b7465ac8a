// How an answer is judged: what a student's function returned (plain data, as a runner
// sends it) read as the numbers a case expects, and compared with them within the case's
// tolerance. Nothing here runs a student's code; the runner that does is never told what
// a case expects.

const num = (value) =>
  value === "inf" ? Infinity : value === "-inf" ? -Infinity : value === "nan" ? NaN : value;
const isNum = (value) =>
  typeof value === "number" || value === "inf" || value === "-inf" || value === "nan";
const nums = (values) => (Array.isArray(values) && values.every(isNum) ? values.map(num) : null);

// Three numbers: an array of three, or a record with the fields named (and others).
function triple(value, fields) {
  if (Array.isArray(value)) return value.length === 3 ? nums(value) : null;
  if (value && typeof value === "object" && fields.every((f) => isNum(value[f])))
    return fields.map((f) => num(value[f]));
  return null;
}

const vector = (value) => triple(value, ["x", "y", "z"]);
const color = (value) => triple(value, ["r", "g", "b"]) ?? triple(value, ["x", "y", "z"]);

// A 4x4 matrix as the book writes it, row by row: four rows of four, or the demos'
// Mat4x4 ({data: rows}).
function matrix(value) {
  const rows = value && !Array.isArray(value) && typeof value === "object" ? value.data : value;
  if (!Array.isArray(rows) || rows.length !== 4) return null;
  const flat = rows.every((row) => Array.isArray(row) && row.length === 4)
    ? nums(rows.flat())
    : null;
  return flat;
}

// A triangle's three indices: [i, j, k], or a record with v (the book's), or indexes or
// v0, v1 and v2 (the demos').
function indices(triangle) {
  const spread = triangle?.v0 === undefined ? undefined : [triangle.v0, triangle.v1, triangle.v2];
  const each = Array.isArray(triangle) ? triangle : (triangle?.v ?? triangle?.indexes ?? spread);
  return Array.isArray(each) && each.length === 3 && each.every((i) => Number.isInteger(i))
    ? each
    : null;
}

function triangles(value) {
  const list = Array.isArray(value) ? value : value?.triangles;
  if (!Array.isArray(list)) return null;
  const found = list.map(indices);
  return found.every(Boolean) ? found.flat() : null;
}

// Which sphere of the case's scene a returned sphere is: the one with its centre and
// radius; -1 for none.
function sphereIndex(sphere, kase) {
  if (sphere === null) return -1;
  const center = vector(sphere?.center);
  if (!center || !isNum(sphere.radius)) return null;
  const spheres = kase.given?.scene?.spheres ?? [];
  const index = spheres.findIndex(
    (each) => each.center.every((v, i) => v === center[i]) && each.radius === num(sphere.radius),
  );
  return index < 0 ? null : index;
}

// What a function returned, as the list of numbers its case expects; null when it is
// not what the book's function returns. `answer` is the runner's: `returned`, and for
// functions that change their arguments, `arguments` after the call.
export function numbersOf(kind, answer, kase, parameters) {
  const value = answer.returned;
  switch (kind) {
    case "number":
      return isNum(value) ? [num(value)] : null;
    case "numbers":
    case "roots":
      return nums(value);
    case "vector":
      return vector(value);
    case "color":
      return color(value);
    case "vector_or_none":
      return value === null ? [] : vector(value);
    case "boolean":
      return typeof value === "boolean" ? [Number(value)] : null;
    case "canvas_point": {
      const point = Array.isArray(value) && value.length >= 2 ? value : [value?.x, value?.y];
      return isNum(point[0]) && isNum(point[1])
        ? point.slice(0, 2).map((v) => (Number.isFinite(num(v)) ? Math.trunc(num(v)) : num(v)))
        : null;
    }
    case "matrix":
      return matrix(value);
    case "triangles": // a list of triangles or a model; none returned: the model it changed
      return triangles(value === null && answer.arguments ? answer.arguments[0] : value);
    case "corners": {
      // each triangle's corners, looked up in the vertex list after the call; the
      // triangles returned, or (none returned) those appended to an output list
      const after = (found) => answer.arguments?.[parameters.findIndex(found)];
      const vertices = after(([name]) => name === "vertices");
      const output = after(([, kind]) => kind === "output");
      const list = triangles(value === null && output ? output : value);
      if (!list || !Array.isArray(vertices)) return null;
      const corners = list.map((i) => vector(vertices[i]));
      return corners.every(Boolean) ? corners.flat() : null;
    }
    case "bounding_sphere": {
      const [center, radius] = Array.isArray(value) ? value : [value?.center, value?.radius];
      const c = vector(center);
      return c && isNum(radius) ? [...c, num(radius)] : null;
    }
    case "closest": {
      // the book's pair (sphere, t), or the demos' null for a miss
      if (value === null) return [-1, Infinity];
      if (!Array.isArray(value) || value.length !== 2 || !isNum(value[1])) return null;
      const index = typeof value[0] === "number" ? value[0] : sphereIndex(value[0], kase);
      return index === null ? null : [index, num(value[1])];
    }
    default:
      return null;
  }
}

// The kinds, as a report names them ("returned 'white', not a colour").
const KIND_NAMES = {
  number: "number",
  numbers: "list of numbers",
  roots: "pair of numbers",
  vector: "vector",
  color: "colour",
  vector_or_none: "vector or none",
  boolean: "yes or no (true or false)",
  canvas_point: "canvas point",
  matrix: "4x4 matrix (four rows of four)",
  triangles: "list of triangles",
  corners: "list of triangles",
  bounding_sphere: "bounding sphere (centre and radius)",
  closest: "pair (a sphere of the scene, t)",
};

// ---- Drawing functions: what they put, kept as a canvas keeps it ----------------------

// A colour channel as a canvas keeps it: clamped to 0..255, rounded half up.
function channel(value) {
  if (!(value > 0)) return 0;
  if (value >= 255) return 255;
  const whole = Math.trunc(value);
  return value - whole >= 0.5 ? whole + 1 : whole;
}

// The pixels a list of PutPixel calls leaves on a canvas of the case's size: x and y
// truncated toward zero (docs/conventions.md), colours clamped and rounded, the last
// colour put at a pixel kept, pixels outside the canvas dropped; null when a call is not
// PutPixel(x, y, color) with numbers.
export function drawnPixels(calls, canvas) {
  const kept = new Map();
  const half = (size) => Math.floor(size / 2);
  for (const call of calls) {
    if (!Array.isArray(call) || call.length !== 3) return null;
    const [x, y] = [num(call[0]), num(call[1])].map((v) =>
      typeof v === "number" ? Math.trunc(v) : NaN,
    );
    const rgb = color(call[2]);
    if (!Number.isFinite(x) || !Number.isFinite(y) || !rgb) return null;
    if (
      -half(canvas.width) <= x &&
      x < half(canvas.width) &&
      -half(canvas.height) <= y &&
      y < half(canvas.height)
    ) {
      kept.set(`${x},${y}`, [x, y, ...rgb.map(channel)]);
    }
  }
  return [...kept.values()].sort((a, b) => a[0] - b[0] || a[1] - b[1]);
}

const PIXEL_LEVELS = 1; // how far a drawn pixel's channel may be from ours

// The lines that say which pixels differ; null when none do.
function pixelDifferences(drawn, expected) {
  const key = ([x, y]) => `${x},${y}`;
  const yours = new Map(drawn.map((p) => [key(p), p]));
  const ours = new Map(expected.map((p) => [key(p), p]));
  // A colour within one level of ours is ours: the same product computed in another
  // order (d0 + (d1 - d0)(i - i0)/(i1 - i0) for d0 + a(i - i0)) may round the other way
  // at an exact half.
  const same = (a, b) => a.slice(2).every((c, i) => Math.abs(c - b[i + 2]) <= PIXEL_LEVELS);
  const lines = [];
  for (const [what, pixels] of [
    ["missing", [...ours.values()].filter((p) => !yours.has(key(p)))],
    ["extra", [...yours.values()].filter((p) => !ours.has(key(p)))],
    [
      "of another colour",
      [...ours.values()].filter((p) => yours.has(key(p)) && !same(yours.get(key(p)), p)),
    ],
  ]) {
    if (pixels.length === 0) continue;
    const listed = pixels
      .slice(0, 8)
      .map(
        (p) =>
          `(${p[0]}, ${p[1]})` +
          (what === "of another colour"
            ? ` yours (${yours.get(key(p)).slice(2).join(", ")}) ours (${p.slice(2).join(", ")})`
            : ""),
      )
      .join(", ");
    lines.push(
      `${pixels.length} pixels ${what}: ${listed}${pixels.length > 8 ? ` and ${pixels.length - 8} more` : ""}`,
    );
  }
  return lines.length ? lines : null;
}

// ---- The verdict ----------------------------------------------------------------------

// Numbers as the cases write them: 0.75, not 0.75000000000000001; 255, not 255.0.
export const shown = (values) =>
  `[${values.map((v) => (Number.isFinite(v) ? String(+v.toPrecision(10)) : String(v))).join(", ")}]`;

function expectedNumbers(expected) {
  if (expected === null) return [];
  return [expected].flat(Infinity).map((v) => (typeof v === "boolean" ? Number(v) : num(v)));
}

// A value as the report shows what was returned: its JSON, cut short.
function showValue(value) {
  const text = JSON.stringify(value) ?? String(value);
  return text.length > 200 ? `${text.slice(0, 200)}...` : text;
}

// An answer's shape: what a runner may say, each field of its kind; anything else is
// not an answer (a process that lies about what it is: a failed case, never a crash).
const ANSWER_FIELDS = {
  timeout: "boolean",
  ended: "string",
  unreadable: "string",
  raised: "string",
  adapter_failed: "string",
  garbled: "string",
  limit: "number",
  id: "number",
  nonce: "string",
  stopped: "boolean",
  printed: "string",
  printed_cut: "boolean",
};
function wellFormed(answer) {
  if (!answer || typeof answer !== "object" || Array.isArray(answer)) return false;
  if (
    "placed" in answer &&
    !(Array.isArray(answer.placed) && answer.placed.every((n) => typeof n === "string"))
  )
    return false;
  if ("pixels" in answer && !Array.isArray(answer.pixels)) return false;
  if ("arguments" in answer && !Array.isArray(answer.arguments)) return false;
  return Object.entries(ANSWER_FIELDS).every(
    ([name, kind]) => !(name in answer) || typeof answer[name] === kind,
  );
}

// What happened in a case that did not answer with a value.
function failureOf(answer, language, adapterGiven) {
  if (!wellFormed(answer)) return "answered with something that is not an answer";
  if (answer.timeout) return `did not return within ${answer.limit} s`;
  if (answer.ended)
    return `ended the process it ran in (exit ${answer.ended}) instead of returning`;
  if (answer.unreadable) return answer.unreadable;
  if (answer.raised) return `${language === "python" ? "raised" : "threw"} ${answer.raised}`;
  if (answer.adapter_failed) {
    return adapterGiven
      ? `your adapter failed to build the inputs: ${answer.adapter_failed}`
      : `the case's inputs could not be made for your code: ${answer.adapter_failed}`;
  }
  if (answer.garbled) return answer.garbled;
  if (!("returned" in answer) && !("pixels" in answer))
    return "answered with something that is not an answer";
  return null;
}

// ---- The slip behind a wrong answer ---------------------------------------------------

// What a wrong answer is, recognised from the numbers alone, before any story of what the
// case was written to catch: ours in another order, rounded to whole levels, with a sign
// flipped, times one factor, or, for a drawing, ours moved by one pixel. null when it is
// none of these.
export function slipOf(kind, actual, expected, tolerance) {
  const near = (a, e) =>
    Number.isFinite(e) ? Math.abs(a - e) <= Math.max(tolerance, 1e-9 * Math.abs(e)) : a === e;
  const same = (a, b) => a.length === b.length && a.every((each, i) => near(each, b[i]));
  if (actual.length !== expected.length || actual.length === 0 || actual.length > 16) return null;
  const sorted = (values) => [...values].sort((a, b) => a - b);
  if (actual.length > 1 && same(sorted(actual), sorted(expected))) {
    return kind === "roots"
      ? "yours are our two roots in the other order: the book returns t1 = (-b + √disc) / 2a first"
      : `yours is ${shown(expected)} in another order: check the order you return them in`;
  }
  const fractional = expected.some((e) => Number.isFinite(e) && Math.abs(e - Math.round(e)) > 1e-6);
  if (kind === "color" && fractional) {
    if (
      same(
        actual,
        expected.map((e) => Math.round(e)),
      ) ||
      same(
        actual,
        expected.map((e) => Math.floor(e)),
      )
    ) {
      return (
        `yours is ours ${shown(expected)} ${same(actual, expected.map(Math.round)) ? "rounded" : "cut"} to whole levels: ` +
        "keep the colour's fractions; it is clamped and rounded only where the pixel is put"
      );
    }
  }
  const flipped = actual.map(
    (a, i) => Number.isFinite(expected[i]) && expected[i] !== 0 && near(a, -expected[i]),
  );
  if (flipped.some(Boolean) && actual.every((a, i) => flipped[i] || near(a, expected[i]))) {
    const names = kind === "color" ? ["r", "g", "b"] : ["x", "y", "z", "w"];
    if (flipped.every((each, i) => each || expected[i] === 0)) {
      return `yours is ours ${shown(expected)} with its sign flipped: a vector the other way round (P - Q for Q - P, -D for D)`;
    }
    const which = flipped
      .map((f, i) => (f ? (names[i] ?? `#${i + 1}`) : null))
      .filter(Boolean)
      .join(" and ");
    return `yours is ours ${shown(expected)} with the ${which}'s sign flipped: one sign of a formula, or a matrix transposed`;
  }
  if (
    actual.length > 1 &&
    expected.some((e) => e !== 0) &&
    same(sorted(actual.map((a) => -a)), sorted(expected))
  ) {
    return (
      `yours is ours ${shown(expected)} with its sign flipped, in another order: a vector the other way round ` +
      "(P - Q for Q - P: CO = O - C, not C - O)"
    );
  }
  const pairs = actual
    .map((a, i) => [a, expected[i]])
    .filter(([, e]) => Number.isFinite(e) && e !== 0);
  // Two different values at least (a grey is a multiple of every other grey).
  if (
    new Set(pairs.map(([, e]) => e)).size > 1 &&
    actual.every((a, i) => pairs.some(([, e]) => e === expected[i]) || near(a, expected[i]))
  ) {
    const factor = pairs[0][0] / pairs[0][1];
    if (
      Number.isFinite(factor) &&
      Math.abs(factor - 1) > 1e-6 &&
      factor !== 0 &&
      pairs.every(([a, e]) => near(a, e * factor))
    ) {
      const how =
        kind === "vector"
          ? ": a vector not normalised, or normalised where the book leaves it"
          : kind === "color"
            ? ": an intensity counted twice or not at all"
            : "";
      return `yours is ours ${shown(expected)} times ${String(+factor.toPrecision(6))}${how}`;
    }
  }
  return null;
}

// The one-pixel shift that makes a drawing ours, said; null when there is none.
function pixelShift(drawn, expected) {
  if (drawn.length !== expected.length || drawn.length === 0) return null;
  const key = (p) => p.join(",");
  const ours = new Set(expected.map(key));
  for (const [dx, dy, words] of [
    [1, 0, "one column right"],
    [-1, 0, "one column left"],
    [0, 1, "one row up"],
    [0, -1, "one row down"],
  ]) {
    if (drawn.every(([x, y, ...rgb]) => ours.has(key([x - dx, y - dy, ...rgb])))) {
      return `your pixels are ours moved ${words}: check where x and y are rounded, and each loop's first and last value`;
    }
  }
  return null;
}

// A case's status, as a course's results name it: "pass", "fail" (a value other than
// ours), "error" (it raised, or answered with something that is not an answer) or
// "timeout"; with the lines that say what went wrong, and the slip when one is
// recognised.
export function outcome(answer, kase, entry, options) {
  const lines = verdict(answer, kase, entry, options);
  if (!lines) return { status: "pass", lines: [] };
  if (wellFormed(answer) && answer.timeout) return { status: "timeout", lines };
  if (failureOf(answer, options.language, options.adapterGiven)) return { status: "error", lines };
  let slip = null;
  if (entry.returns === "pixels") {
    const drawn = Array.isArray(answer.pixels)
      ? drawnPixels(answer.pixels, kase.given.canvas)
      : null;
    slip = drawn && pixelShift(drawn, kase.expected);
  } else {
    const actual = numbersOf(entry.returns, answer, kase, entry.parameters);
    if (actual && !["closest", "triangles", "corners"].includes(entry.returns)) {
      slip = slipOf(entry.returns, actual, expectedNumbers(kase.expected), kase.tolerance ?? 0);
    }
  }
  return { status: "fail", lines, slip };
}

// Whether the answer is the one the book's demo pages give (a case's demos_expected),
// where the case says they differ from the book.
export function demosAnswer(answer, kase, entry, options) {
  return (
    kase.demos_expected !== undefined &&
    !verdict(answer, { ...kase, expected: kase.demos_expected }, entry, options)
  );
}

// null when the case passes, else the lines that say what went wrong.
export function verdict(answer, kase, entry, { language, adapterGiven }) {
  const failure = failureOf(answer, language, adapterGiven);
  if (failure) return [failure];
  if (entry.returns === "pixels") {
    const drawn = Array.isArray(answer.pixels)
      ? drawnPixels(answer.pixels, kase.given.canvas)
      : null;
    if (drawn === null)
      return [
        "called PutPixel with something other than (x, y, color), x and y numbers and color three numbers",
      ];
    return pixelDifferences(drawn, kase.expected);
  }
  const actual = numbersOf(entry.returns, answer, kase, entry.parameters);
  if (actual === null) {
    return [
      `returned ${showValue(answer.returned)}, not a ${KIND_NAMES[entry.returns] ?? entry.returns}`,
    ];
  }
  const expected = expectedNumbers(kase.expected);
  const truncated = kase.compare === "truncated";
  const compared = truncated ? actual.map((v) => (Number.isFinite(v) ? Math.trunc(v) : v)) : actual;
  const near = (a, e) => (Number.isFinite(e) ? Math.abs(a - e) <= kase.tolerance : a === e);
  if (compared.length === expected.length && compared.every((a, i) => near(a, expected[i])))
    return null;
  const tolerance = kase.tolerance < 1e-4 ? kase.tolerance.toExponential() : String(kase.tolerance);
  // One number is said as one number (0.5), not as a list of one ([0.5]).
  const say = (values) =>
    !Array.isArray(kase.expected) && values.length === 1
      ? shown(values).slice(1, -1)
      : shown(values);
  return [
    `returned ${say(compared)}${truncated ? " (truncated)" : ""}, expected ${say(expected)}` +
      (kase.tolerance ? ` (within ${tolerance})` : ""),
  ];
}
