// A chapter's check from start to end, and what its report says: for each book function,
// passed, not written yet, or failed with each failed case (what it catches, its inputs,
// what was expected and what came back). Before a function's failed cases, the line that
// says why they may not be mistakes at all: the case's canvas, viewport or scene never
// reached the code, a default argument was bound before any case began, or the function
// takes another listing's parameters. One core for the command line and the web page:
// `runner` is theirs (a process in a sandbox, or a Web Worker).

import { demosAnswer, outcome } from "./judge.mjs";
import { NAMES, PARTS, namesOf, partsGiven, partsOf } from "./names.mjs";
import { casesFor, functionsOf, sections, signatureFor } from "./plan.mjs";
import { readyCall } from "./ready_call.mjs";

// What a case's record keeps of what the student's code printed, and what the text
// report shows of it.
const PRINTED_KEPT = 4000,
  PRINTED_SHOWN = 8;

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
  if (entry.returns === "pixels")
    return ["PutPixel", ...(kase.given?.depth_buffer ? ["depth buffer"] : [])];
  return partsGiven(kase.given);
}

// The names a function reads that are the chapter's own, not the checker's table's, and
// the table's names an ES module declares itself (out of the checker's reach).
function ownNames(fact, facts) {
  const own = [];
  for (const [name, , kind] of fact.reads ?? []) {
    if (!(name in NAMES) && kind === "data") own.push(name);
    else if (name in NAMES && facts.reachable === "exports" && facts.defined.includes(name))
      own.push(name);
  }
  return own;
}

// The parts of a case that did not reach the function; [] when that cannot be told, or
// when the function did not return (an error is its own, whatever data it had).
function unreached(fact, facts, entry, kase, answer, adapterGiven) {
  if (
    !fact.reads ||
    !fact.complete ||
    !Array.isArray(answer.placed) ||
    !("returned" in answer || "pixels" in answer)
  )
    return [];
  const parts = needed(entry, kase);
  const shut = facts.reachable === "exports" ? new Set(facts.defined) : new Set();
  const read = fact.reads
    .map(([name]) => name)
    .filter((name) => answer.placed.includes(name) && !shut.has(name));
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
  const book = [
    ...new Set(
      missing.flatMap((part) => namesOf(part).filter((each) => NAMES[each].dialect === "book")),
    ),
  ];
  const demos = [
    ...new Set(
      missing.flatMap((part) => namesOf(part).filter((each) => NAMES[each].dialect === "demos")),
    ),
  ].flatMap((each) => (each === "canvas" ? ["canvas.width", "canvas.height"] : [each]));
  const template = `\`--adapter-template ${chapter.slice(0, 2)} ${file}\` prints one for this file`;
  if (adapterGiven) {
    return (
      `${name} reads ${own.length ? `${where} ${code(own)}` : "no name your adapter sets"}, and your adapter's setup set ` +
      `none of them: ${parts} never reached it; set the names ${name} reads (${template})`
    );
  }
  const shut = own.filter((each) => each in NAMES);
  if (shut.length > 0) {
    return (
      `${name} reads the ${code(shut)} your ES module declares, which the checker cannot set from outside, so ` +
      `${parts} never reached it: drop the declaration and read the global, or give an adapter that sets it (${template})`
    );
  }
  const theirs = `the checker sets ${code(book)} (the book's names)${demos.length ? ` and ${code(demos)} (the demos')` : ""}`;
  if (own.length > 0) {
    const reach = new Set(missing).size > 1 ? "reach" : "reaches";
    const how =
      facts.reachable === "exports"
        ? "give an adapter that sets yours through a function your ES module exports (its own names are out of reach otherwise)"
        : `give an adapter that sets yours (${template})`;
    return (
      `${name} reads ${where} ${code(own)}, so ${parts} that each case gives never ${reach} it: ${theirs}; ` +
      `use those names, or ${how}`
    );
  }
  return (
    `${name} reads none of the names through which ${parts} reach it (${theirs}), nor names of its own: ` +
    `they are fixed in it, and each case gives its own`
  );
}

// A default argument bound to a module-level name when the def ran (Python).
function boundNote(name, fact) {
  return (fact.bound ?? []).map(
    ({ parameter, default: written }) =>
      `${name}'s default \`${parameter}=${written}\` is taken once, when \`def ${name}\` runs, so what a case gives never ` +
      `reaches it: write \`${parameter}=None\` and begin ${name} with \`if ${parameter} is None: ${parameter} = ${written}\`, ` +
      `or drop the parameter and read a global inside ${name}`,
  );
}

// Where a chapter meets a case its design cannot pass, or the demos answer otherwise:
// { heading } when it cannot pass the case at all (a square viewport, the demos'
// viewport_size or a VIEWPORT_SIZE of its own, cannot be 1.5 × 1), so that the case's own
// heading, a mistake the chapter did not make, is not shown; { line } where the answer
// is the one the demos give and the case's file says they differ (an open interval).
function demosNote(fact, facts, kase, demosGave) {
  const viewport = kase.given?.viewport;
  const square = (fact.reads ?? [])
    .map(([name]) => name)
    .find((name) => /viewport_?size/i.test(name));
  if (viewport && viewport.width !== viewport.height && square) {
    const size = `this case's is ${viewport.width} × ${viewport.height}, and the book's has a width and a height (Vw, Vh)`;
    return {
      heading:
        square === "viewport_size"
          ? `this is where the demos and the book differ: the demos' viewport is square ` +
            `(viewport_size); ${size}`
          : `your viewport is square (\`${square}\`): ${size}`,
    };
  }
  return demosGave && kase.demos
    ? { line: `this is where the demos and the book differ: ${kase.demos}` }
    : {};
}

// An error that says the function expected types of its own: a method the checker's
// values lack. The name it was called on, or null.
function typeMismatch(answer, signature, language) {
  const raised = typeof answer.raised === "string" ? answer.raised : "";
  if (language === "python") {
    const found =
      /^AttributeError: '(Vector|Point|Record|tuple|list|dict|Texture|ndarray)' object has no attribute '(\w+)'/.exec(
        raised,
      );
    return found ? `.${found[2]}` : null;
  }
  const found = /^TypeError: ([A-Za-z_$][\w$]*)((?:\.[\w$]+)+) is not a function/.exec(raised);
  if (found && signature.parameters.some(([name]) => name === found[1]))
    return `${found[1]}${found[2]}`;
  // A field of its own read from the checker's scene, where it got undefined: the case
  // raised, or came back with nothing or not a number.
  const nothing = (value) =>
    value === null || value === "nan" || (Array.isArray(value) && value.some(nothing));
  return answer.absent?.length > 0 && (raised !== "" || nothing(answer.returned))
    ? `scene.${answer.absent[0]}`
    : null;
}

// The line that says the checker's values are not the function's own types.
function typeNote(name, called, { language, chapter, file }) {
  const template = `\`--adapter-template ${chapter.slice(0, 2)} ${file}\` prints one to fill in`;
  if (called.startsWith("scene."))
    return (
      `${name} reads \`${called}\`, which the checker's scene does not have: it gives the book's fields ` +
      `(spheres, lights, background_color). Give an adapter whose setup(module, given, adapter) sets your ` +
      `own, as module.${called} = ... from given.scene (${template})`
    );
  const shapes =
    language === "python"
      ? "vectors as named tuples (x, y, z), colours as tuples, spheres, lights and scenes as records of the book's fields " +
        "(numpy arrays where your module uses numpy, your Sphere where it has one)"
      : "vectors as arrays [x, y, z] (or your Vec, Vec3, Vector, Vector3 or Vertex, made with (x, y, z)), colours as " +
        "arrays (or your Color), spheres, lights and scenes as objects with the book's fields (or your Sphere)";
  return (
    `${name} calls \`${called}\`, which what the checker gives it does not have: it gives ${shapes}. Give an ` +
    `adapter whose vector(value), color(value) or sphere(value) makes your own types (${template})`
  );
}

function inputsOf(kase) {
  return JSON.stringify({ ...(kase.given ?? {}), ...(kase.args ?? { calls: kase.calls }) });
}

// One case's record, for a course's results (--json): the function, the case, its status
// (pass, fail, error, timeout, not written, not checked), what it catches, the message,
// what came back against what was expected, what the student's code printed (theirs,
// capped), and where there is one, the command that runs it alone.
function record(entry, caseFile, number, status, message, extra = {}) {
  const kase = entry.cases[number - 1];
  return {
    function: entry.function,
    caseFile,
    case: number,
    status,
    message,
    catches: kase?.catches ?? "",
    expected: kase?.expected ?? null,
    ...extra,
  };
}

// The records of a function's cases that did not run, each with why.
const notRun = (entry, caseFile, status, why, numbers = entry.cases.map((_, i) => i + 1)) =>
  numbers.map((number) => record(entry, caseFile, number, status, why));

// What a student's code printed in a case, as an answer gives it: a string, capped.
function printedOf(answer) {
  if (typeof answer.printed !== "string" || answer.printed === "") return null;
  const cut = answer.printed.length > PRINTED_KEPT;
  return { text: answer.printed.slice(0, PRINTED_KEPT), cut: cut || answer.printed_cut === true };
}

// The lines under a failed case that help with the next step: what the code printed,
// the command that runs the case alone, and the call to paste into a REPL.
function helpLines(entry, number, signature, kase, answer, context) {
  const { file, options, caseFile } = context;
  const lines = [];
  const printed = printedOf(answer);
  if (printed) {
    const shown = printed.text.replace(/\n$/, "").split("\n");
    lines.push(
      "your code printed:",
      ...shown.slice(0, PRINTED_SHOWN).map((line) => `| ${line.slice(0, 200)}`),
    );
    if (shown.length > PRINTED_SHOWN || printed.cut)
      lines.push(
        `| ... (${printed.cut ? "cut at 4000 characters" : `${shown.length - PRINTED_SHOWN} more lines`}; --json keeps it)`,
      );
  }
  if (options.rerun) lines.push(`alone: ${options.rerun(entry.function, caseFile, number)}`);
  const call = options.repl
    ? readyCall(options.language, file, signature, kase, entry.returns === "pixels", {
        demosFields: answer.demos_fields,
      })
    : [];
  if (call.length) {
    const repl = options.language === "python" ? "python3" : "node";
    lines.push(`in ${repl}, in your file's folder:`, ...call.map((line) => `  ${line}`));
  }
  return lines;
}

// Runs one function's cases; the lines of its block, whether it failed, and the records
// of its cases.
async function checkFunction(entry, fact, context) {
  const { runner, facts, file, caseFile, options } = context;
  const name = entry.function.padEnd(22);
  const wanted = (number) => !context.onlyCase || context.onlyCase === number;
  const all = entry.cases.map((_, i) => i + 1).filter(wanted);
  if (fact.forged) {
    // the process's account of the file is not the file's
    return {
      failed: true,
      lines: [`  ${name} FAILED ${all.length} of ${casesOf(all.length)}`, `    ${fact.forged}`],
      records: notRun(entry, caseFile, "error", fact.forged, all),
    };
  }
  const signature = signatureFor(entry, fact.parameters);
  if (!signature) {
    const takes = `takes ${fact.parameters.names.length} parameters (${fact.parameters.names.join(", ")})`;
    const calls = [entry, ...(entry.signatures ?? [])]
      .map((each) => `${each.call} (${each.where})`)
      .join(" or ");
    const why = `${entry.function} ${takes}; the checker calls ${calls}`;
    return {
      failed: true,
      lines: [`  ${name} FAILED ${all.length} of ${casesOf(all.length)}`, `    ${why}`],
      records: notRun(entry, caseFile, "error", why, all),
    };
  }
  const cases = casesFor(entry, signature).filter(({ number }) => wanted(number));
  const failures = [];
  const records = [];
  for (const { kase, number } of cases) {
    const answer = await runner.run({
      function: entry.function,
      parameters: signature.parameters,
      given: kase.given ?? {},
      calls: kase.calls ?? [kase.args],
      returns: entry.returns,
      drawing: entry.returns === "pixels",
      arguments: entry.returns === "triangles" || entry.returns === "corners",
    });
    if (answer.stopped) {
      const rest = cases.filter((each) => each.number >= number).map((each) => each.number);
      return {
        failed: true,
        stopped: true,
        lines: [],
        records: [
          ...records,
          ...notRun(entry, caseFile, "not checked", "the check stopped at its time bound", rest),
        ],
      };
    }
    // Judged by the parameters it was called with (an output list's place among them).
    const called = { ...entry, parameters: signature.parameters };
    const { status, lines: problem, slip } = outcome(answer, kase, called, options);
    const printed = printedOf(answer);
    records.push(
      record(entry, caseFile, number, status, problem.join("; "), {
        returned:
          "returned" in answer ? answer.returned : "pixels" in answer ? answer.pixels : null,
        printed: printed?.text ?? "",
        printedCut: printed?.cut ?? false,
        ...(status !== "pass" && options.rerun
          ? { rerun: options.rerun(entry.function, caseFile, number) }
          : {}),
      }),
    );
    if (status !== "pass")
      failures.push({
        kase,
        number,
        problem,
        answer,
        slip,
        demos: demosAnswer(answer, kase, called, options),
      });
  }
  const skipped = entry.cases
    .map((_, i) => i + 1)
    .filter((number) => wanted(number) && !cases.some((each) => each.number === number));
  if (skipped.length)
    records.push(
      ...notRun(
        entry,
        caseFile,
        "not checked",
        `yours is ${signature.call} (${signature.where}): this case calls ${entry.call}`,
        skipped,
      ),
    );
  const lines = [];
  // Another listing's parameters: which cases that leaves, and why; where it leaves them
  // all, the signature called (on a failure each case's call line names it).
  const partial = [];
  const calledAs = [];
  if (signature.call !== entry.call && skipped.length > 0) {
    partial.push(
      `    only its cases for ${signature.call} (${signature.where}): the other ${skipped.length} ` +
        `call ${entry.call} (${entry.where})`,
    );
  } else if (signature.call !== entry.call) {
    calledAs.push(`    called as ${signature.call} (${signature.where})`);
  }
  const count =
    cases.length < all.length ? `${cases.length} of ${casesOf(all.length)}` : casesOf(cases.length);
  if (failures.length === 0)
    return {
      failed: false,
      lines: [`  ${name} passed (${count})`, ...partial, ...calledAs],
      records,
    };
  lines.push(`  ${name} FAILED ${failures.length} of ${count}`, ...partial);
  // A bound default explains itself: the names a function reads come after it is fixed.
  const notes = boundNote(entry.function, fact);
  const missing = failures.flatMap(({ kase, answer }) =>
    unreached(fact, facts, entry, kase, answer, options.adapterGiven),
  );
  if (notes.length === 0 && missing.length > 0)
    notes.push(readsNote(entry.function, fact, facts, missing, { ...options, file }));
  const mismatched = failures
    .map(({ answer }) => typeMismatch(answer, signature, options.language))
    .find(Boolean);
  if (mismatched) notes.push(typeNote(entry.function, mismatched, { ...options, file }));
  lines.push(...notes.map((note) => `    ${note}`));
  for (const { kase, number, problem, answer, slip, demos: demosGave } of failures) {
    const consequence =
      fact.bound?.length ||
      unreached(fact, facts, entry, kase, answer, options.adapterGiven).length ||
      (mismatched && typeMismatch(answer, signature, options.language));
    if (notes.length > 0 && consequence) {
      lines.push(
        `    case ${number} of ${caseFile} (a consequence of the line above): ${problem.join("; ")}`,
      );
      continue;
    }
    // The slip, where the numbers show one, before what the case was written to catch.
    const demos = demosNote(fact, facts, kase, demosGave);
    const heading =
      demos.heading ??
      (slip && !demosGave ? `${slip} (this case catches: ${kase.catches})` : kase.catches);
    lines.push(
      `    case ${number} of ${caseFile}: ${heading}`,
      `      ${signature.call} with ${inputsOf(kase)}`,
      ...problem.map((line) => `      ${line}`),
      ...(demos.line ? [`      ${demos.line}`] : []),
      ...helpLines(entry, number, signature, kase, answer, context).map((line) => `      ${line}`),
    );
  }
  return { failed: true, lines, records };
}

// The line that ends a check which ran out of time: `seconds` it took, the most a check
// of `totalCases` may take ({ timeLimit, loadLimit } in seconds).
export function stoppedLine(seconds, totalCases, { timeLimit, loadLimit }) {
  return (
    `stopped after ${seconds} s, the most this check may take (${totalCases} cases × ${timeLimit} s + ` +
    `${loadLimit} s to load): the cases after this one did not run`
  );
}

// The chapter's verdict from its cases' records: "complete" (every case of every
// function passed), "partial" (every case that ran passed, but a function is not written
// yet or some cases could not run: another listing's parameters), "incomplete" (a case
// failed, or the check stopped).
export function chapterVerdict(records, stopped) {
  if (stopped || records.some((each) => ["fail", "error", "timeout"].includes(each.status)))
    return "incomplete";
  return records.some((each) => each.status !== "pass") ? "partial" : "complete";
}

// The cases a check runs: every one, or one function's (only.function), or one case of
// it (only.case: its number in the chapter's own case file, or "NN:number" in an earlier
// chapter's). The sections narrowed to them.
function narrowed(list, only) {
  if (!only?.function) return list;
  const [chapter, number] =
    only.case === undefined
      ? [null, null]
      : String(only.case).includes(":")
        ? String(only.case).split(":")
        : [list[0].chapter.slice(0, 2), only.case];
  return list
    .map((section) => ({
      ...section,
      changed: section.changed.filter((each) => each.function === only.function),
      entries: section.entries.filter(
        (entry) =>
          entry.function === only.function &&
          (chapter === null || section.chapter.startsWith(chapter)),
      ),
      onlyCase: number === null ? null : Number(number),
    }))
    .filter((section) => section.entries.length || section.changed.length);
}

// The whole check. runner: { language, load(functions, names) -> facts (or throws
// CheckError), run(request) -> answer, stoppedLine() }; only: { function, case } to run
// one function's cases or one case; rerun(function, caseFile, number): the command that
// runs one case alone, where there is one; repl: whether to show a failed case as code to
// paste into a REPL (the command line's, not a page's). Returns { lines, failed, records,
// verdict }.
export async function check({
  chapter,
  files,
  runner,
  file,
  adapterGiven = false,
  only = null,
  rerun = null,
  repl = false,
}) {
  const everything = sections(chapter, files);
  const facts = await runner.load(functionsOf(everything), NAMES);
  const own = files[chapter].functions.map((entry) => entry.function);
  if (!functionsOf(everything).some((name) => name in facts.functions)) {
    const how =
      runner.language === "python"
        ? "as functions at your module's top level"
        : "as top-level functions (a plain script or a page) or exports (module.exports = { ... })";
    throw new CheckError(
      `${file} defines none of ${chapter}'s functions (${own.join(", ")}): write them under the book's names, ${how}`,
    );
  }
  const list = narrowed(everything, only);
  if (only?.function && list.length === 0) {
    throw new CheckError(
      `${chapter} checks no function ${only.function}: its functions are ${functionsOf(everything).join(", ")}`,
    );
  }
  const options = { language: runner.language, adapterGiven, chapter, rerun, repl };
  // First every function's cases, then the report, so that a function's block can say
  // that a function it calls failed too (wherever that is reported).
  const blocks = [];
  const failedFunctions = new Map();
  let stopped = false;
  const said = new Set();
  const records = [];
  for (const section of list) {
    const context = {
      runner,
      facts,
      file,
      caseFile: `${section.chapter}.json`,
      options,
      onlyCase: section.onlyCase,
    };
    if (
      section.onlyCase &&
      !section.entries.some((entry) => section.onlyCase <= entry.cases.length)
    ) {
      throw new CheckError(
        `${section.chapter}.json has no case ${section.onlyCase} of ${only.function}`,
      );
    }
    const block = { section, results: [] };
    blocks.push(block);
    for (const { function: name, why } of section.changed) {
      if (name in facts.functions && !said.has(name)) {
        block.results.push({
          lines: [`  ${name.padEnd(22)} not checked against ${section.chapter}.json: ${why}`],
        });
      }
      said.add(name);
    }
    for (const entry of section.entries) {
      // A function with an empty body (a page's starter) is not written yet either.
      const fact = facts.functions[entry.function]?.empty
        ? undefined
        : facts.functions[entry.function];
      const numbers = entry.cases
        .map((_, i) => i + 1)
        .filter((number) => !section.onlyCase || number === section.onlyCase);
      if (stopped || !fact) {
        if (section.own && !fact) {
          block.results.push({
            lines: [`  ${entry.function.padEnd(22)} not written yet (${casesOf(numbers.length)})`],
          });
          records.push(
            ...notRun(
              entry,
              context.caseFile,
              "not written",
              `your file has no ${entry.function} yet`,
              numbers,
            ),
          );
        } else if (stopped) {
          records.push(
            ...notRun(
              entry,
              context.caseFile,
              "not checked",
              "the check stopped at its time bound",
              numbers,
            ),
          );
        }
        continue;
      }
      if (!section.own && !fact.forged && !signatureFor(entry, fact.parameters)) {
        block.results.push({
          lines: [
            `  ${entry.function.padEnd(22)} not checked against ${section.chapter}.json: yours takes ` +
              `${fact.parameters.names.length} parameters, its cases are for ${entry.call}`,
          ],
        });
        continue;
      }
      const result = await checkFunction(entry, fact, context);
      result.function = entry.function;
      block.results.push(result);
      records.push(...result.records);
      if (result.failed && !failedFunctions.has(entry.function))
        failedFunctions.set(entry.function, section.chapter);
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
  const verdict = chapterVerdict(records, stopped);
  lines.push(verdictLine(verdict, records, only));
  return { lines, failed: stopped || failedFunctions.size > 0, records, verdict };
}

// The report's last line: the chapter's verdict and its counts.
function verdictLine(verdict, records, only) {
  const count = (status) => records.filter((each) => each.status === status).length;
  const parts = [
    ["pass", "passed"],
    ["fail", "failed"],
    ["error", "raised or answered wrongly"],
    ["timeout", "ran out of time"],
    ["not written", "not written yet"],
    ["not checked", "not checked"],
  ]
    .filter(([status]) => count(status) > 0)
    .map(([status, words]) => `${count(status)} ${words}`);
  const what = only?.function
    ? `${only.function}${only.case !== undefined ? `, case ${only.case}` : ""}`
    : "chapter";
  return `${what}: ${verdict} (${casesOf(records.length)}: ${parts.join(", ")})`;
}

// A failed function's lines, with a line naming the functions of the student's it calls
// that failed too: its failures may be theirs.
function withCallees(result, facts, failedFunctions) {
  if (!result.failed || !result.function) return result.lines;
  const callees = (facts.functions[result.function]?.calls ?? []).filter((name) =>
    failedFunctions.has(name),
  );
  if (callees.length === 0) return result.lines;
  const where = callees.map((name) => `${name} (${failedFunctions.get(name)}.json)`);
  const which = callees.length > 1 ? "they fail cases" : "it fails a case";
  return [
    result.lines[0],
    `    it calls your ${listed(where)}, and ${which} too: these may follow from that; make ${callees.length > 1 ? "them" : "it"} pass first`,
    ...result.lines.slice(1),
  ];
}
