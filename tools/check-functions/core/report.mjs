// A chapter's check from start to end, and what its report says: for each book function,
// passed, not written yet, or failed with each failed case (what it catches, its inputs,
// what was expected and what came back). Before a function's failed cases, the line that
// says why they may not be mistakes at all: the case's canvas, viewport or scene never
// reached the code, a default argument was bound before any case began, or the function
// takes another listing's parameters. One core for the command line and the web page:
// `runner` is theirs (a process in a sandbox, or a Web Worker).

import { verdict } from "./judge.mjs";
import { NAMES, PARTS, namesOf, partsGiven, partsOf } from "./names.mjs";
import { casesFor, functionsOf, sections, signatureFor } from "./plan.mjs";

// The chapter cannot be checked at all (it does not load, or defines none of the
// chapter's functions): one line.
export class CheckError extends Error {}

const code = (names) => listed(names.map((name) => `\`${name}\``));
const casesOf = (count) => `${count} ${count === 1 ? "case" : "cases"}`;
function listed(items) {
  if (items.length <= 1) return items.join("");
  return `${items.slice(0, -1).join(", ")} and ${items.at(-1)}`;
}

// The parts of a case a function needs: what it draws through PutPixel (and the depth
// buffer) for a drawing function, else what the case gives.
function needed(entry, kase) {
  if (entry.returns === "pixels") return ["PutPixel", ...(kase.given?.depth_buffer ? ["depth buffer"] : [])];
  return partsGiven(kase.given);
}

// The names a function reads that are the chapter's own, not the checker's table's, and
// the table's names an ES module declares itself (out of the checker's reach).
function ownNames(fact, facts) {
  const own = [];
  for (const [name, , kind] of fact.reads ?? []) {
    if (!(name in NAMES) && kind === "data") own.push(name);
    else if (name in NAMES && facts.reachable === "exports" && facts.defined.includes(name)) own.push(name);
  }
  return own;
}

// The parts of a case that did not reach the function; [] when that cannot be told, or
// when the function did not return (an error is its own, whatever data it had).
function unreached(fact, facts, entry, kase, answer, adapterGiven) {
  if (!fact.reads || !fact.complete || !Array.isArray(answer.placed) || !("returned" in answer || "pixels" in answer)) return [];
  const parts = needed(entry, kase);
  const shut = facts.reachable === "exports" ? new Set(facts.defined) : new Set();
  const read = fact.reads.map(([name]) => name).filter((name) => answer.placed.includes(name) && !shut.has(name));
  // An adapter that set any name the function reads is trusted with every part.
  if (adapterGiven && read.some((name) => !(name in NAMES))) return [];
  const reached = new Set(read.flatMap(partsOf));
  return parts.filter((part) => !reached.has(part));
}

// The line that says why a function's cases could not see their data; null when they could.
function readsNote(name, fact, facts, missing, { adapterGiven, language, chapter, file }) {
  const parts = listed([...new Set(missing)].map((part) => PARTS[part]));
  const where = language === "python" ? "your module's" : "your";
  const own = ownNames(fact, facts);
  const book = [...new Set(missing.flatMap((part) => namesOf(part).filter((each) => NAMES[each].dialect === "book")))];
  const demos = [...new Set(missing.flatMap((part) => namesOf(part).filter((each) => NAMES[each].dialect === "demos")))]
    .flatMap((each) => (each === "canvas" ? ["canvas.width", "canvas.height"] : [each]));
  const template = `\`--adapter-template ${chapter.slice(0, 2)} ${file}\` prints one for this file`;
  if (adapterGiven) {
    return `${name} reads ${own.length ? `${where} ${code(own)}` : "no name your adapter sets"}, and your adapter's setup set ` +
      `none of them: ${parts} never reached it; set the names ${name} reads (${template})`;
  }
  const shut = own.filter((each) => each in NAMES);
  if (shut.length > 0) {
    return `${name} reads the ${code(shut)} your ES module declares, which the checker cannot set from outside, so ` +
      `${parts} never reached it: drop the declaration and read the global, or give an adapter that sets it (${template})`;
  }
  const theirs = `the checker sets ${code(book)} (the book's names)${demos.length ? ` and ${code(demos)} (the demos')` : ""}`;
  if (own.length > 0) {
    const reach = new Set(missing).size > 1 ? "reach" : "reaches";
    const how = facts.reachable === "exports"
      ? "give an adapter that sets yours through a function your ES module exports (its own names are out of reach otherwise)"
      : `give an adapter that sets yours (${template})`;
    return `${name} reads ${where} ${code(own)}, so ${parts} that each case gives never ${reach} it: ${theirs}; ` +
      `use those names, or ${how}`;
  }
  return `${name} reads none of the names through which ${parts} reach it (${theirs}), nor names of its own: ` +
    `they are fixed in it, and each case gives its own`;
}

// A default argument bound to a module-level name when the def ran (Python).
function boundNote(name, fact) {
  return (fact.bound ?? []).map(({ parameter, default: written }) =>
    `${name}'s default \`${parameter}=${written}\` is taken once, when \`def ${name}\` runs, so what a case gives never ` +
    `reaches it: write \`${parameter}=None\` and begin ${name} with \`if ${parameter} is None: ${parameter} = ${written}\`, ` +
    `or drop the parameter and read a global inside ${name}`);
}

// Where a chapter meets a case its design cannot pass, or the demos answer otherwise:
// { heading } when it cannot pass the case at all (a square viewport, the demos'
// viewport_size or a VIEWPORT_SIZE of its own, cannot be 1.5 × 1), so that the case's own
// heading, a mistake the chapter did not make, is not shown; { line } for a chapter in
// the demos' style where the case's file says the demos differ (an open interval).
function demosNote(fact, facts, kase) {
  const viewport = kase.given?.viewport;
  const square = (fact.reads ?? []).map(([name]) => name).find((name) => /viewport_?size/i.test(name));
  if (viewport && viewport.width !== viewport.height && square) {
    const size = `this case's is ${viewport.width} × ${viewport.height}, and the book's has a width and a height (Vw, Vh)`;
    return { heading: square === "viewport_size" ? `this is where the demos and the book differ: the demos' viewport is square ` +
      `(viewport_size); ${size}` : `your viewport is square (\`${square}\`): ${size}` };
  }
  const demoStyle = (fact.reads ?? []).some(([name]) => NAMES[name]?.dialect === "demos") ||
    facts.defined.some((name) => NAMES[name]?.dialect === "demos");
  return demoStyle && kase.demos ? { line: `this is where the demos and the book differ: ${kase.demos}` } : {};
}

// An error that says the function expected types of its own: a method the checker's
// values lack. The name it was called on, or null.
function typeMismatch(answer, signature, language) {
  const raised = typeof answer.raised === "string" ? answer.raised : "";
  if (language === "python") {
    const found = /^AttributeError: '(Vector|Point|Record|tuple|list|dict|Texture|ndarray)' object has no attribute '(\w+)'/.exec(raised);
    return found ? `.${found[2]}` : null;
  }
  const found = /^TypeError: ([A-Za-z_$][\w$]*)((?:\.[\w$]+)+) is not a function/.exec(raised);
  return found && signature.parameters.some(([name]) => name === found[1]) ? `${found[1]}${found[2]}` : null;
}

// The line that says the checker's values are not the function's own types.
function typeNote(name, called, { language, chapter, file }) {
  const shapes = language === "python"
    ? "vectors as named tuples (x, y, z), colours as tuples, spheres, lights and scenes as records of the book's fields " +
      "(numpy arrays where your module uses numpy, your Sphere where it has one)"
    : "vectors as arrays [x, y, z] (or your Vec, Vec3, Vector, Vector3 or Vertex, made with (x, y, z)), colours as " +
      "arrays (or your Color), spheres, lights and scenes as objects with the book's fields (or your Sphere)";
  return `${name} calls \`${called}\`, which what the checker gives it does not have: it gives ${shapes}. Give an ` +
    `adapter whose vector(value), color(value) or sphere(value) makes your own types (\`--adapter-template ${chapter.slice(0, 2)} ${file}\` ` +
    "prints one to fill in)";
}

function inputsOf(kase) {
  return JSON.stringify({ ...(kase.given ?? {}), ...(kase.args ?? { calls: kase.calls }) });
}

// Runs one function's cases; the lines of its block and whether it failed.
async function checkFunction(entry, fact, context) {
  const { runner, facts, file, caseFile, options } = context;
  const name = entry.function.padEnd(22);
  if (fact.forged) {  // the process's account of the file is not the file's
    return { failed: true, lines: [`  ${name} FAILED ${entry.cases.length} of ${casesOf(entry.cases.length)}`, `    ${fact.forged}`] };
  }
  const signature = signatureFor(entry, fact.parameters);
  if (!signature) {
    const takes = `takes ${fact.parameters.names.length} parameters (${fact.parameters.names.join(", ")})`;
    const calls = [entry, ...(entry.signatures ?? [])].map((each) => `${each.call} (${each.where})`).join(" or ");
    return { failed: true, lines: [`  ${name} FAILED ${entry.cases.length} of ${casesOf(entry.cases.length)}`,
      `    ${entry.function} ${takes}; the checker calls ${calls}`] };
  }
  const cases = casesFor(entry, signature);
  const failures = [];
  for (const { kase, number } of cases) {
    const answer = await runner.run({
      function: entry.function, parameters: signature.parameters, given: kase.given ?? {},
      calls: kase.calls ?? [kase.args], returns: entry.returns, drawing: entry.returns === "pixels",
      arguments: entry.returns === "triangles" || entry.returns === "corners",
    });
    if (answer.stopped) return { failed: true, stopped: true, lines: [] };
    const problem = verdict(answer, kase, entry, options);
    if (problem) failures.push({ kase, number, problem, answer });
  }
  const lines = [];
  // Another listing's parameters: which cases that leaves, and why.
  const partial = [];
  if (signature.call !== entry.call && cases.length < entry.cases.length) {
    partial.push(`    only its cases for ${signature.call} (${signature.where}): the other ${entry.cases.length - cases.length} ` +
      `call ${entry.call} (${entry.where})`);
  } else if (signature.call !== entry.call) {
    partial.push(`    called as ${signature.call} (${signature.where})`);
  }
  const count = cases.length < entry.cases.length ? `${cases.length} of ${casesOf(entry.cases.length)}` : casesOf(cases.length);
  if (failures.length === 0) return { failed: false, lines: [`  ${name} passed (${count})`, ...partial] };
  lines.push(`  ${name} FAILED ${failures.length} of ${count}`, ...partial);
  // A bound default explains itself: the names a function reads come after it is fixed.
  const notes = boundNote(entry.function, fact);
  const missing = failures.flatMap(({ kase, answer }) => unreached(fact, facts, entry, kase, answer, options.adapterGiven));
  if (notes.length === 0 && missing.length > 0) notes.push(readsNote(entry.function, fact, facts, missing, { ...options, file }));
  const mismatched = failures.map(({ answer }) => typeMismatch(answer, signature, options.language)).find(Boolean);
  if (mismatched) notes.push(typeNote(entry.function, mismatched, { ...options, file }));
  lines.push(...notes.map((note) => `    ${note}`));
  for (const { kase, number, problem, answer } of failures) {
    const consequence = fact.bound?.length || unreached(fact, facts, entry, kase, answer, options.adapterGiven).length ||
      (mismatched && typeMismatch(answer, signature, options.language));
    if (notes.length > 0 && consequence) {
      lines.push(`    case ${number} of ${caseFile} (a consequence of the line above): ${problem.join("; ")}`);
      continue;
    }
    const demos = demosNote(fact, facts, kase);
    lines.push(`    case ${number} of ${caseFile}: ${demos.heading ?? kase.catches}`, `      ${signature.call} with ${inputsOf(kase)}`,
      ...problem.map((line) => `      ${line}`), ...(demos.line ? [`      ${demos.line}`] : []));
  }
  return { failed: true, lines };
}

// The line that ends a check which ran out of time: `seconds` it took, the most a check
// of `totalCases` may take ({ timeLimit, loadLimit } in seconds).
export function stoppedLine(seconds, totalCases, { timeLimit, loadLimit }) {
  return `stopped after ${seconds} s, the most this check may take (${totalCases} cases × ${timeLimit} s + ` +
    `${loadLimit} s to load): the cases after this one did not run`;
}

// The whole check. runner: { language, load(functions, names) -> facts (or throws
// CheckError), run(request) -> answer, stoppedLine() }. Returns { lines, failed }.
export async function check({ chapter, files, runner, file, adapterGiven = false }) {
  const list = sections(chapter, files);
  const facts = await runner.load(functionsOf(list), NAMES);
  const own = files[chapter].functions.map((entry) => entry.function);
  if (!functionsOf(list).some((name) => name in facts.functions)) {
    const how = runner.language === "python" ? "as functions at your module's top level"
      : "as top-level functions (a plain script or a page) or exports (module.exports = { ... })";
    throw new CheckError(`${file} defines none of ${chapter}'s functions (${own.join(", ")}): write them under the book's names, ${how}`);
  }
  const options = { language: runner.language, adapterGiven, chapter };
  // First every function's cases, then the report, so that a function's block can say
  // that a function it calls failed too (wherever that is reported).
  const blocks = [];
  const failedFunctions = new Map();
  let stopped = false;
  const said = new Set();
  for (const section of list) {
    const context = { runner, facts, file, caseFile: `${section.chapter}.json`, options };
    const block = { section, results: [] };
    blocks.push(block);
    for (const { function: name, why } of section.changed) {
      if (name in facts.functions && !said.has(name)) {
        block.results.push({ lines: [`  ${name.padEnd(22)} not checked against ${section.chapter}.json: ${why}`] });
      }
      said.add(name);
    }
    for (const entry of section.entries) {
      // A function with an empty body (a page's starter) is not written yet either.
      const fact = facts.functions[entry.function]?.empty ? undefined : facts.functions[entry.function];
      if (stopped || !fact) {
        if (section.own && !fact) block.results.push({ lines: [`  ${entry.function.padEnd(22)} not written yet (${casesOf(entry.cases.length)})`] });
        continue;
      }
      if (!section.own && !fact.forged && !signatureFor(entry, fact.parameters)) {
        block.results.push({ lines: [`  ${entry.function.padEnd(22)} not checked against ${section.chapter}.json: yours takes ` +
          `${fact.parameters.names.length} parameters, its cases are for ${entry.call}`] });
        continue;
      }
      const result = await checkFunction(entry, fact, context);
      result.function = entry.function;
      block.results.push(result);
      if (result.failed && !failedFunctions.has(entry.function)) failedFunctions.set(entry.function, section.chapter);
      if (result.stopped) stopped = true;
    }
  }
  const lines = [`${chapter}: ${file}, the book's functions one by one`];
  for (const { section, results } of blocks) {
    const shown = results.flatMap((result) => withCallees(result, facts, failedFunctions));
    if (!section.own && shown.length > 0) lines.push(`${section.chapter}, as ${chapter} keeps it:`);
    lines.push(...shown);
  }
  if (stopped) lines.push(runner.stoppedLine());
  return { lines, failed: stopped || failedFunctions.size > 0 };
}

// A failed function's lines, with a line naming the functions of the student's it calls
// that failed too: its failures may be theirs.
function withCallees(result, facts, failedFunctions) {
  if (!result.failed || !result.function) return result.lines;
  const callees = (facts.functions[result.function]?.calls ?? []).filter((name) => failedFunctions.has(name));
  if (callees.length === 0) return result.lines;
  const where = callees.map((name) => `${name} (${failedFunctions.get(name)}.json)`);
  const which = callees.length > 1 ? "they fail cases" : "it fails a case";
  return [result.lines[0], `    it calls your ${listed(where)}, and ${which} too: these may follow from that; make ${callees.length > 1 ? "them" : "it"} pass first`,
    ...result.lines.slice(1)];
}
