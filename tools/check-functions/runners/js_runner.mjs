// The process a student's JavaScript chapter runs in, for the function checker
// (tools/check-functions/check-functions.js, docs/students.md).
//
// It loads the chapter (a plain script, a CommonJS or ES module, or a web page with the
// chapter's <script>, as the book's demo pages are), says what it finds there (the book's
// functions, their parameters, the top-level names each reads), then runs one case at a
// time: it builds the case's inputs, puts the case's canvas, viewport and scene where the
// chapter reads them, calls the function and answers with what it returned, as plain
// data (js_core.mjs, which the chapter pages' Web Worker shares). It is never told what a
// case expects and decides nothing: the checker judges every answer in a process of its
// own.
//
// Messages are JSON lines: requests on file descriptor 3, answers on 4. A plain script
// or page runs as a browser runs it, in this process's global scope, so that its
// top-level `let` and `const` (made `let`) can be set before each case; a case runs
// under a time limit that ends even an endless loop without losing the loaded chapter.

import fs from "node:fs";
import Module, { createRequire } from "node:module";
import net from "node:net";
import path from "node:path";
import readline from "node:readline";
import { pathToFileURL } from "node:url";
import util from "node:util";
import vm from "node:vm";
import {
  ChapterBase,
  GETTER,
  LoadError,
  MAX_ANSWER,
  SETTER,
  constsMadeLet,
  declarations,
  defaultAdapter,
  factsOf,
  helpers,
  moduleMadeSettable,
  oneLine,
  parse,
  runCase,
  syntaxError,
  useParser,
} from "./js_core.mjs";
import { pageScripts } from "./js_page.mjs";
import { installPage } from "./page_stand_in.mjs";

const require = createRequire(import.meta.url);
useParser(require("acorn"), require("acorn-globals"));
const RUNNER_DIR = path.dirname(new URL(import.meta.url).pathname);
const MAX_PRINTED = 4000; // characters of what one case printed, kept for the report

// The chapter, loaded from its file in this process's global scope.
class Chapter extends ChapterBase {
  constructor(file) {
    super(path.resolve(file), (code) => vm.runInThisContext(code));
  }

  async load() {
    const source = fs.readFileSync(this.file, "utf8");
    if (/\.html?$/i.test(this.file)) {
      installPage(source);
      for (const script of pageScripts(source, this.file)) this.runScript(script);
      return;
    }
    let program;
    try {
      program = this.file.endsWith(".mjs") ? null : parse(source, "script");
    } catch (scriptError) {
      try {
        program = parse(source, "module");
      } catch {
        throw syntaxError(scriptError, this.file, 0);
      }
      program = null;
    }
    if (program === null) {
      this.kind = "module";
      try {
        this.declared = declarations(parse(source, "module"), source);
      } catch (error) {
        throw syntaxError(error, this.file, 0);
      }
      // Through the module hook where Node.js has one (20.6 and newer): its top-level
      // variables settable; else as it is, its own names out of reach.
      const url = pathToFileURL(this.file).href;
      if (typeof Module.register === "function") {
        Module.register("./module_hook.mjs", import.meta.url, {
          data: { url, source: moduleMadeSettable(parse(source, "module"), source) },
        });
      }
      const { [SETTER]: set, [GETTER]: get, ...loaded } = await import(url);
      if (set && get) {
        this.settable = { has: (name) => this.declared.get(name)?.kind === "data", get, set };
      }
      this.exports =
        loaded.default && typeof loaded.default === "object"
          ? { ...loaded.default, ...loaded }
          : loaded;
      return;
    }
    // A script written for a page (it reaches for document) gets the page's stand-in.
    if (/\bdocument\s*\.|\bwindow\s*\./.test(source)) installPage("");
    this.runScript({ code: source, line: 0, filename: this.file, program });
  }

  // One script in this process's global scope, with what a CommonJS file expects.
  runScript({ code, line, filename, program }) {
    try {
      program ??= parse(code, "script");
    } catch (error) {
      throw syntaxError(error, filename, line);
    }
    this.declare(program, code);
    const module = {
      exports: this.exports,
      id: filename,
      filename,
      loaded: false,
      children: [],
      paths: [],
    };
    module.require = createRequire(filename);
    Object.assign(globalThis, {
      module,
      exports: module.exports,
      require: module.require,
      __filename: filename,
      __dirname: path.dirname(filename),
    });
    vm.runInThisContext(constsMadeLet(program, code), { filename, lineOffset: line });
    this.exports = module.exports;
  }
}

// ---- The loop -------------------------------------------------------------------------

async function loadAdapter(file, chapter) {
  const resolved = path.resolve(file);
  if (/\.mjs$/.test(resolved)) return (await import(pathToFileURL(resolved).href)).default ?? {};
  // The adapter's require of the chapter's file is the chapter as loaded here.
  const cached = new Module(chapter.file);
  Object.assign(cached, { filename: chapter.file, loaded: true, exports: chapter.asModule() });
  Module._cache[chapter.file] = cached;
  const loaded = createRequire(resolved)(resolved);
  return loaded && typeof loaded === "object" ? loaded : {};
}

// What a case prints (console's methods, process.stdout and stderr), kept while it runs
// in place of the output (the first MAX_PRINTED characters).
function capturePrinting() {
  let text = "";
  const keep = (more) => {
    if (text.length <= MAX_PRINTED) text += more.slice(0, MAX_PRINTED + 1 - text.length);
  };
  const methods = ["log", "info", "debug", "warn", "error", "trace"];
  const saved = {
    console: methods.map((name) => console[name]),
    out: process.stdout.write,
    err: process.stderr.write,
  };
  for (const name of methods) console[name] = (...values) => keep(`${util.format(...values)}\n`);
  process.stdout.write = process.stderr.write = (chunk) => {
    keep(typeof chunk === "string" ? chunk : Buffer.from(chunk).toString("utf8"));
    return true;
  };
  return {
    stop() {
      methods.forEach((name, i) => {
        console[name] = saved.console[i];
      });
      Object.assign(process.stdout, { write: saved.out });
      Object.assign(process.stderr, { write: saved.err });
    },
    printed: () =>
      text ? { printed: text.slice(0, MAX_PRINTED), printed_cut: text.length > MAX_PRINTED } : {},
  };
}

function send(message) {
  let text;
  try {
    text = JSON.stringify(message);
  } catch {
    text = JSON.stringify({
      id: message.id,
      nonce: message.nonce,
      unreadable: "returned something that cannot be sent",
    });
  }
  if (text.length > MAX_ANSWER)
    text = JSON.stringify({
      id: message.id,
      nonce: message.nonce,
      unreadable: "returned something too large to send",
    });
  fs.writeSync(4, `${text}\n`);
}

async function main() {
  // The requests' pipe read by the event loop (a net.Socket), not by a thread of libuv's
  // pool blocked in read(): Node.js joins that pool as it exits, so a chapter's
  // process.exit() while it waits would hang until the checker's load limit.
  const lines = readline.createInterface({
    input: new net.Socket({ fd: 3, readable: true, writable: false }),
    crlfDelay: Infinity,
  });
  const requests = lines[Symbol.asyncIterator]();
  const { load } = JSON.parse((await requests.next()).value);
  const chapter = new Chapter(load.module);
  // As if imported by another program, with no arguments and nothing of the checker's:
  // an ES module's main guard (process.argv[1] === fileURLToPath(import.meta.url)) and a
  // CommonJS one (require.main === module) both stay shut.
  process.argv = [process.argv[0], "check-functions"];
  let facts, adapter;
  try {
    try {
      await chapter.load();
    } catch (error) {
      const writes = ["EROFS", "EACCES", "EPERM"].includes(error?.code)
        ? ": it writes a file as it loads, which it may not here; keep that under if (require.main === module) " +
          "(CommonJS) or if (process.argv[1] === fileURLToPath(import.meta.url)) (an ES module)"
        : "";
      throw error instanceof LoadError
        ? error
        : new LoadError(oneLine(error, [RUNNER_DIR]) + writes);
    }
    const own = load.adapter
      ? await loadAdapter(load.adapter, chapter).catch((error) => {
          throw new LoadError(
            `your adapter ${load.adapter} does not load: ${oneLine(error, [RUNNER_DIR])}`,
          );
        })
      : {};
    adapter = { ...defaultAdapter(helpers(chapter)), ...own };
    facts = factsOf(chapter, load.functions, load.names);
  } catch (error) {
    const text =
      error instanceof LoadError && error.message.startsWith("your adapter")
        ? error.message
        : `your module ${load.module} does not load: ${error.message}`;
    send({ load_error: text });
    return;
  }
  send({ loaded: facts });
  // What the chapter does on its own later (a page's timers drawing its scene) is not a
  // case: an error there is the page's, and ends nothing.
  process.on("uncaughtException", () => {});
  process.on("unhandledRejection", () => {});
  const readNames = new Set(
    Object.values(facts.functions).flatMap((f) => (f.reads ?? []).map(([name]) => name)),
  );
  const functionReads = (name) => (facts.functions[name]?.reads ?? []).map(([each]) => each);
  for (let next = await requests.next(); !next.done; next = await requests.next()) {
    const request = JSON.parse(next.value);
    let answer;
    globalThis.__cgfsCase = () =>
      runCase(request, chapter, adapter, load.names, readNames, functionReads, [RUNNER_DIR]);
    const printing = capturePrinting();
    try {
      answer = vm.runInThisContext("globalThis.__cgfsCase()", {
        timeout: Math.round(request.limit * 1000),
      });
    } catch (error) {
      answer =
        error?.code === "ERR_SCRIPT_EXECUTION_TIMEOUT"
          ? { timeout: true }
          : {
              unreadable: `returned something that cannot be sent (${oneLine(error, [RUNNER_DIR])})`,
            };
    } finally {
      printing.stop();
    }
    send({ ...answer, ...printing.printed(), id: request.id, nonce: request.nonce });
  }
  process.exit(0);
}

main();
