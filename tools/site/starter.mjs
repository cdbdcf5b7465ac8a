// What a chapter page's editor opens on (yourcode.js): the chapter's functions under the
// book's names and parameters with nothing in their bodies (not written yet, to the
// checker), a note of what the page gives them, and, when the reader wrote the chapter
// before, their code carried forward with this chapter's new functions added to it.

import { NAMES, namesOf, partsGiven } from "../check-functions/core/names.mjs";
import { sections } from "../check-functions/core/plan.mjs";

// How the checker gives a chapter's values, in each language (docs/students.md).
const SHAPES = {
  javascript: {
    vector:
      "vectors are arrays [x, y, z] (or your own Vec3, Vector or Vertex, made with (x, y, z))",
    color: "colours are arrays [r, g, b]",
    point: "canvas points are {x, y, h} (h: the intensity, 1 unless chapter 8 gives one)",
    sphere: "a sphere is {center, radius, color, specular, reflective}",
    light:
      'a light is {type: "ambient", "point" or "directional", intensity, position or direction}',
    matrix: "a matrix is an array of its rows",
    transform: "a transform is {scale, rotation (a 4x4 matrix), translation}",
    triangle: "a triangle is {v: [i, j, k] (indices into the vertices), color}",
    plane: "a plane is {normal, D}",
    texture: "texture[i][j] is the texel in column i, row j; texture.width and texture.height",
  },
  python: {
    vector:
      "vectors are named tuples Vector(x, y, z): v.x or v[0] (numpy arrays if your module imports numpy)",
    color: "colours are tuples (r, g, b)",
    point:
      "canvas points are named tuples Point(x, y, h) (h: the intensity, 1 unless chapter 8 gives one)",
    sphere: "a sphere has .center, .radius, .color, .specular and .reflective",
    light:
      'a light has .type ("ambient", "point" or "directional"), .intensity, and .position or .direction',
    matrix: "a matrix is a list of its rows",
    transform: "a transform has .scale, .rotation (a 4x4 matrix) and .translation",
    triangle: "a triangle has .v (three indices into the vertices) and .color",
    plane: "a plane has .normal and .D",
    texture: "texture[i][j] is the texel in column i, row j; texture.width and texture.height",
  },
};
const KIND_SHAPES = {
  vectors: ["vector"],
  model: ["vector", "triangle", "color"],
  spheres: ["sphere"],
  scene: ["sphere", "light", "color"],
  tangent_basis: ["vector"],
};

// The file a chapter's code is kept in: basic-rays.js, basic_rays.py (the command line's
// checker takes either unchanged).
export function fileName(chapter, language) {
  const name = chapter.slice(3);
  return language === "python" ? `${name.replaceAll("-", "_")}.py` : `${name}.js`;
}

// The chapter the reader's code for `chapter` carries forward: the latest one it keeps.
export function previousChapter(chapter, files) {
  const kept = Object.keys(files[chapter].keeps ?? {}).sort();
  return kept.at(-1) ?? null;
}

// The line (from 0) where `code` defines a top-level function `name` (a declaration, or
// a name given a function), or -1.
export function definitionLine(code, name, language) {
  const pattern =
    language === "python"
      ? `^def\\s+${name}\\s*\\(`
      : `^(?:export\\s+)?(?:async\\s+)?(?:function\\s*\\*?\\s*${name}\\s*\\(|(?:const|let|var)\\s+${name}\\s*=)`;
  const found = new RegExp(pattern, "m").exec(code);
  return found ? code.slice(0, found.index).split("\n").length - 1 : -1;
}

// Whether `code` defines a top-level function `name`.
export const defines = (code, name, language) => definitionLine(code, name, language) >= 0;

function comment(lines, language) {
  const mark = language === "python" ? "#" : "//";
  return lines.map((line) => (line ? `${mark} ${line}` : mark)).join("\n");
}

// Words wrapped to lines of at most `width` characters.
function wrapped(text, width = 70) {
  const lines = [""];
  for (const word of text.split(/\s+/).filter(Boolean)) {
    if (lines.at(-1).length + word.length + 1 > width && lines.at(-1)) lines.push("");
    lines[lines.length - 1] += (lines.at(-1) ? " " : "") + word;
  }
  return lines;
}

function stub(entry, language) {
  const parameters = entry.parameters.map(([name]) => name).join(", ");
  const where = comment(wrapped(`${entry.call}: ${entry.where}`), language);
  return language === "python"
    ? `${where}\ndef ${entry.function}(${parameters}):\n    pass\n`
    : `${where}\nfunction ${entry.function}(${parameters}) {\n}\n`;
}

// What the page gives a chapter's functions: the book's globals its cases set, and the
// shapes of the values they get.
function givenNote(chapter, files, language) {
  const list = sections(chapter, files);
  const entries = list.flatMap((section) => section.entries);
  const parts = new Set(
    entries.flatMap((entry) => entry.cases.flatMap((kase) => partsGiven(kase.given))),
  );
  if (entries.some((entry) => entry.returns === "pixels")) parts.add("PutPixel");
  const globals = [...parts].flatMap((part) =>
    namesOf(part).filter((name) => NAMES[name].dialect === "book"),
  );
  const kinds = new Set(entries.flatMap((entry) => entry.parameters.map(([, kind]) => kind)));
  if (parts.has("spheres")) kinds.add("sphere");
  if (parts.has("lights")) kinds.add("light");
  const shapes = [...kinds]
    .flatMap((kind) => KIND_SHAPES[kind] ?? [kind])
    .filter((kind, i, all) => all.indexOf(kind) === i);
  const said = shapes.map((kind) => SHAPES[language][kind]).filter(Boolean);
  const set = globals.length
    ? `Before each case, and each figure you draw, the page sets the book's globals ${[...new Set(globals)].join(", ")}.`
    : "";
  const values = said.length ? `${said.join("; ")}.` : "";
  return `${set} ${values.charAt(0).toUpperCase()}${values.slice(1)}`.trim();
}

// A new starter for the chapter: every function its check covers, the chapter's own first.
export function freshStarter(chapter, files, language, title) {
  const head = comment(
    [
      ...wrapped(
        `${title}: your own code, beside ours. Write each function under the book's name; "Check" runs the ` +
          `chapter's cases on it, "Draw" draws a figure with it. A function with nothing in its body is not written yet.`,
      ),
      "",
      ...wrapped(givenNote(chapter, files, language)),
    ],
    language,
  );
  const blocks = [];
  const seen = new Set();
  for (const section of sections(chapter, files)) {
    const entries = section.entries.filter((entry) => !seen.has(entry.function));
    if (entries.length === 0) continue;
    entries.forEach((entry) => seen.add(entry.function));
    if (!section.own)
      blocks.push(comment([`From ${section.chapter}, which this chapter keeps:`], language));
    blocks.push(...entries.map((entry) => stub(entry, language)));
  }
  const gap = language === "python" ? "\n\n" : "\n";
  return `${head}\n${language === "python" ? "\nimport math\n\n" : ""}\n${blocks.join(gap)}`;
}

// The reader's code of the chapter before, carried forward: this chapter's functions it
// does not define yet added at its end, and a note of those this chapter changes.
export function carriedForward(chapter, previousCode, files, language, title) {
  const own = files[chapter].functions;
  const changed = own.filter((entry) => defines(previousCode, entry.function, language));
  const added = own.filter((entry) => !defines(previousCode, entry.function, language));
  const notes = [
    ...wrapped(`${title}: carried forward from your ${previousChapter(chapter, files)}.`),
  ];
  if (changed.length) {
    const why = Object.values(files[chapter].changes ?? {}).reduce(
      (all, each) => ({ ...all, ...each }),
      {},
    );
    for (const entry of changed) {
      notes.push(
        ...wrapped(
          `This chapter changes your ${entry.function} above (${entry.call}: ${entry.where})` +
            (why[entry.function] ? `: ${why[entry.function]}.` : "."),
        ),
      );
    }
  }
  const blocks = added.map((entry) => stub(entry, language));
  const gap = language === "python" ? "\n\n" : "\n";
  return `${previousCode.trimEnd()}\n\n\n${comment(notes, language)}\n${blocks.length ? `\n${blocks.join(gap)}` : ""}`;
}
