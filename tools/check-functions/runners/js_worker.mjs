// The Web Worker a reader's JavaScript runs in on a chapter's page (tools/site/code_runner.js):
// js_runner.mjs's counterpart there, on the same core (js_core.mjs), bundled with acorn
// by scripts/site (esbuild). The reader's code arrives as text and runs as a classic
// script in the worker's global scope (importScripts of a Blob, which keeps its top-level
// `let` and `const` in reach), or as a module where it imports or exports. It is sent a
// case's inputs, never what is expected: the page judges (tools/check-functions/core).
// Messages { id, op, ... }, answered { id, ... }:
//   declare { code }                         the functions the code defines, read from its
//                                            syntax before any of it runs (the page asks
//                                            a new worker this first, and holds the
//                                            account `load` gives against it)
//   load { code, file, functions, names }   the chapter's account of itself, or why not
//   case { request }                         what the function made of one case
//   draw { recipe, kinds }                   a figure drawn with the reader's functions
// A case or a draw that runs too long is ended by the page, which ends the worker.
import * as acorn from "acorn";
import findGlobals from "acorn-globals";
import {
  ChapterBase,
  LoadError,
  constsMadeLet,
  declarations,
  declaredFunctions,
  defaultAdapter,
  drawFigure,
  factsOf,
  helpers,
  nameSource,
  oneLine,
  parse,
  runCase,
  syntaxError,
  useParser,
} from "./js_core.mjs";
import { installPage } from "./page_stand_in.mjs";

useParser(acorn, findGlobals);

// The reader's code, run in this worker's global scope.
class PageChapter extends ChapterBase {
  constructor(file) {
    super(file, (code) => (0, eval)(code)); // global code, as a script's
  }

  async load(code) {
    let program;
    try {
      program = parse(code, "script");
    } catch (scriptError) {
      try {
        program = parse(code, "module");
      } catch {
        throw syntaxError(scriptError, this.file, 0);
      }
      this.kind = "module";
      this.declared = declarations(program, code);
      const address = URL.createObjectURL(new Blob([code], { type: "text/javascript" }));
      nameSource(address, this.file);
      this.exports = { ...(await import(address)) };
      return;
    }
    this.declare(program, code);
    // A script written for a page (it reaches for document) gets the page's stand-in; a
    // CommonJS file its module.exports, and a require that says why it cannot be had.
    if (/\bdocument\s*\.|\bwindow\s*\./.test(code)) installPage("");
    const module = { exports: {} };
    Object.assign(globalThis, {
      module,
      exports: module.exports,
      require: (name) => {
        throw new Error(
          `require("${name}"): a chapter's page runs one file, with no other files beside it`,
        );
      },
    });
    const address = URL.createObjectURL(
      new Blob([constsMadeLet(program, code)], { type: "text/javascript" }),
    );
    nameSource(address, this.file);
    importScripts(address);
    this.exports = module.exports;
  }
}

// The functions `code` defines, from its syntax alone (a script, or else a module); an
// empty account when it is neither (load says the syntax error).
function declared(code) {
  for (const sourceType of ["script", "module"]) {
    try {
      return Object.fromEntries(declaredFunctions(parse(code, sourceType)));
    } catch {
      // the other kind
    }
  }
  return {};
}

let chapter = null,
  adapter = null,
  facts = null,
  names = null;
const readNames = () =>
  new Set(Object.values(facts.functions).flatMap((f) => (f.reads ?? []).map(([name]) => name)));
const functionReads = (name) => (facts.functions[name]?.reads ?? []).map(([each]) => each);

const operations = {
  declare({ code }) {
    return { declared: declared(code) };
  },
  async load({ code, file, functions, names: table }) {
    names = table;
    chapter = new PageChapter(file);
    try {
      await chapter.load(code);
    } catch (error) {
      return {
        load_error: `your code does not load: ${error instanceof LoadError ? error.message : oneLine(error)}`,
      };
    }
    adapter = defaultAdapter(helpers(chapter));
    facts = factsOf(chapter, functions, names);
    return { loaded: facts };
  },
  case({ request }) {
    return runCase(request, chapter, adapter, names, readNames(), functionReads);
  },
  draw({ recipe, kinds }) {
    try {
      const drawn = drawFigure(recipe, chapter, adapter, names, readNames(), kinds, (fraction) =>
        postMessage({ progress: fraction }),
      );
      return { answer: drawn, transfer: [drawn.pixels.buffer] };
    } catch (error) {
      return { problem: oneLine(error) };
    }
  },
};

onmessage = async ({ data }) => {
  let result;
  try {
    result = await operations[data.op](data);
  } catch (error) {
    result = { unreadable: `the page's worker failed: ${oneLine(error)}` };
  }
  const { answer, transfer = [] } = result.answer ? result : { answer: result };
  postMessage({ ...answer, id: data.id }, transfer);
};
