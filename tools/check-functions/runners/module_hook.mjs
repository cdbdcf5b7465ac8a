// A module customisation hook (node:module's register, Node.js 20.6 and newer) through
// which js_runner.mjs loads a student's ES module: the source it is given for that one
// file, which is the student's with its top-level `const`s made `let` and a function
// that sets them, so that a case's canvas and scene reach an ES module as they reach a
// script. Every other module loads as it would.
let chapter = null;

export async function initialize(data) {
  chapter = data;
}

export async function load(url, context, nextLoad) {
  if (chapter && url === chapter.url)
    return { format: "module", source: chapter.source, shortCircuit: true };
  return nextLoad(url, context);
}
