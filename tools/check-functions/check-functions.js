#!/usr/bin/env node
// Checks a student's chapter of "Computer Graphics from Scratch", written in Python or
// JavaScript, one book function at a time, against the cases our C++ tests run
// (tests/cases/NN-name.json):
//
//     node tools/check-functions/check-functions.js CHAPTER YOUR_FILE [--function NAME [--case N]]
//         [--json FILE] [--adapter FILE] [--time-limit S]
//     node tools/check-functions/check-functions.js --adapter-template [CHAPTER YOUR_FILE | python | js]
//
// YOUR_FILE is a Python module (.py), or JavaScript: a plain script, a CommonJS or ES
// module (.js, .cjs, .mjs), or a web page with the chapter's <script> (.html), as the
// book's demo pages are. Your code runs in a process of its own (runners/), which is sent
// each case's inputs and answers with what your function returned; the verdict, against
// the expected values it never sees, is made here (core/). docs/students.md says more.
// Exit status: 0 the chapter is complete (every case of every function passed), 1 it is
// incomplete (a case failed) or your file cannot be checked, 2 a wrong command line, 3 it
// is partial (every case that ran passed, but a function is not written yet or some cases
// could not run).
"use strict";

const { spawn } = require("child_process");
const crypto = require("crypto");
const fs = require("fs");
const path = require("path");
const sandbox = require("./sandbox.js");
const { definedFunctions } = require("./source_facts.js");

const ROOT = path.resolve(__dirname, "..", "..");
const CASES_DIR = path.join(ROOT, "tests", "cases");
const GRACE = 2; // seconds past a case's limit before its process is ended from outside
const MAX_LINE = 5 << 20; // characters of one answer

const USAGE =
  "usage: check-functions.js CHAPTER YOUR_FILE [--function NAME [--case N]] [--json FILE] [--adapter FILE] [--time-limit SECONDS]\n" +
  "       check-functions.js --adapter-template [CHAPTER YOUR_FILE | python | js]";
const EXIT = { complete: 0, incomplete: 1, partial: 3 };

class Usage extends Error {}

function languageOf(file) {
  if (/\.py$/i.test(file)) return "python";
  if (/\.(js|cjs|mjs|html?)$/i.test(file)) return "javascript";
  throw new Usage(
    `${file}: give a Python file (.py) or JavaScript (.js, .cjs, .mjs, or a page, .html)`,
  );
}

function parse(argv) {
  const options = {};
  const positional = [];
  const value = (i) => {
    if (i >= argv.length || argv[i].startsWith("--"))
      throw new Usage(`${argv[i - 1]} needs a value (${USAGE.split("\n")[0]})`);
    return argv[i];
  };
  for (let i = 0; i < argv.length; ++i) {
    if (argv[i] === "--adapter") options.adapter = value(++i);
    else if (argv[i] === "--time-limit") options.timeLimit = Number(value(++i));
    else if (argv[i] === "--function") options.function = value(++i);
    else if (argv[i] === "--case") options.case = value(++i);
    else if (argv[i] === "--json") options.json = argv[++i] === "-" ? "-" : value(i);
    else if (argv[i] === "--adapter-template") options.template = true;
    else if (argv[i] === "--help" || argv[i] === "-h") options.help = true;
    else if (argv[i].startsWith("-") && argv[i] !== "-")
      throw new Usage(`unknown option ${argv[i]} (${USAGE.split("\n")[0]})`);
    else positional.push(argv[i]);
  }
  if (options.help) return options;
  if (options.template) {
    if (positional.length === 1 && /^(python|js|javascript)$/.test(positional[0])) {
      options.templateLanguage = positional[0] === "python" ? "python" : "javascript";
      return options;
    }
    if (positional.length !== 0 && positional.length !== 2)
      throw new Usage(
        `--adapter-template takes a chapter and your file, or python or js (${USAGE.split("\n")[1].trim()})`,
      );
  } else if (positional.length !== 2) {
    throw new Usage(`give a chapter and your file (${USAGE.split("\n")[0]})`);
  }
  [options.chapter, options.module] = positional;
  if (options.timeLimit !== undefined && !(options.timeLimit > 0 && options.timeLimit <= 3600))
    throw new Usage("--time-limit: give more than 0 and at most 3600 seconds");
  if (options.case !== undefined && options.function === undefined)
    throw new Usage("--case needs --function NAME: the function whose case it is");
  if (options.case !== undefined && !/^([0-9]{2}:)?[1-9][0-9]{0,3}$/.test(options.case)) {
    throw new Usage(
      `--case ${options.case}: give a case's number (4), or an earlier chapter's and its number (02:4)`,
    );
  }
  if (options.function !== undefined && !/^[A-Za-z_][A-Za-z0-9_]{0,63}$/.test(options.function))
    throw new Usage(`--function ${options.function}: give a book function's name`);
  if (options.json !== undefined && options.json !== "-") {
    const target = path.resolve(options.json);
    let stat = null;
    try {
      stat = fs.statSync(target);
    } catch {
      if (!fs.existsSync(path.dirname(target)))
        throw new Usage(`--json ${options.json}: no folder ${path.dirname(target)}`);
    }
    if (stat && !stat.isFile()) throw new Usage(`--json ${options.json}: not a file`);
    const same = (file) => {
      try {
        const other = fs.statSync(file);
        return stat && other.dev === stat.dev && other.ino === stat.ino;
      } catch {
        return false;
      }
    };
    if (
      [options.module, options.adapter].filter(Boolean).some(same) ||
      /\.(py|js|cjs|mjs|html?)$/i.test(target)
    ) {
      throw new Usage(
        `--json ${options.json}: that is code, not a results file; give another name (results.json)`,
      );
    }
  }
  for (const file of [options.module, options.adapter]) {
    if (file === undefined) continue;
    let stat;
    try {
      stat = fs.statSync(file);
    } catch {
      throw new Usage(`${file}: no such file`);
    }
    if (!stat.isFile()) throw new Usage(`${file}: not a file`);
  }
  if (options.module) options.language = languageOf(options.module);
  // Real paths from here on: what is bound into the sandbox, hidden or compared is the
  // file itself, however it was reached (a symbolic link in the path, a relative name).
  options.shownModule = options.module;
  if (options.module) options.module = sandbox.real(options.module);
  if (options.adapter) options.adapter = sandbox.real(options.adapter);
  if (options.adapter && languageOf(options.adapter) !== options.language) {
    throw new Usage(
      `${options.adapter}: an adapter is in your chapter's language (${options.language})`,
    );
  }
  // The sandbox gives the code its own folder: the root folder would be the whole system.
  for (const file of [options.module, options.adapter].filter(Boolean)) {
    if (path.dirname(file) === "/")
      throw new Usage(
        `${file}: put your chapter in a folder of its own (its folder, /, would give your code the whole file system)`,
      );
  }
  return options;
}

// Where Debian (or npm) keeps acorn, which the JavaScript runner parses chapters with.
function nodePath() {
  const candidates = ["/usr/share/nodejs", "/usr/lib/nodejs", ...require.resolve.paths("acorn")];
  const found = candidates.filter((dir) =>
    fs.existsSync(path.join(dir, "acorn-globals", "index.js")),
  );
  if (found.length === 0)
    throw new Usage(
      "a JavaScript chapter needs acorn and acorn-globals: on Debian, sudo apt install node-acorn",
    );
  return found.join(path.delimiter);
}

// The runner's command, in the sandbox where it can run.
function command(options, seconds) {
  let run;
  if (options.language === "python") {
    const python = sandbox.pythonInterpreter();
    if (!python)
      throw new Usage("a Python chapter needs python3 (Debian: sudo apt install python3)");
    run = {
      file: python.executable,
      args: ["-B", path.join(__dirname, "runners", "python_runner.py")],
      env: { PYTHONDONTWRITEBYTECODE: "1" },
    };
  } else {
    run = {
      file: process.execPath,
      args: [
        "--max-old-space-size=2048",
        "--stack-size=4000",
        path.join(__dirname, "runners", "js_runner.mjs"),
      ],
      env: { NODE_PATH: nodePath() },
    };
  }
  if (sandbox.why()) return run;
  const folders = [
    ...new Set([options.module, options.adapter].filter(Boolean).map((file) => path.dirname(file))),
  ];
  const modulePaths = options.language === "python" ? [] : run.env.NODE_PATH.split(path.delimiter);
  const sandboxedRun = sandbox.sandboxed(run, {
    language: options.language,
    folders,
    seconds,
    modulePaths,
  });
  if (sandboxedRun.refused) throw new Usage(sandboxedRun.refused);
  return sandboxedRun;
}

// The student's code in a process of its own, spoken to through two pipes (its file
// descriptors 3 and 4); a case at a time, each answer checked to be the answer to that
// case; a process that does not answer in time is ended, and a new one takes over.
class ProcessRunner {
  constructor(options, totalCases) {
    Object.assign(this, { options, language: options.language, process: null, id: 0 });
    this.started = Date.now();
    this.sandboxes = new Set(); // the first process of every sandbox started (its PID outside)
    this.bound = (totalCases * options.timeLimit + options.loadLimit) * 1000;
    this.totalCases = totalCases;
  }

  start() {
    const { file, args, env, argsText, cut } = command(
      this.options,
      this.bound / 1000 + this.options.loadLimit,
    );
    this.searchCut ||= Boolean(cut);
    // In the sandbox, an empty environment, bwrap's arguments through a pipe (fd 5), and
    // the sandbox's first process said on fd 6.
    const sandboxPipes = argsText === undefined ? [] : ["pipe", "pipe"];
    const child = spawn(file, args, {
      cwd: path.dirname(this.options.module),
      detached: true,
      stdio: ["ignore", "ignore", "ignore", "pipe", "pipe", ...sandboxPipes],
      env:
        argsText === undefined
          ? { PATH: process.env.PATH, HOME: process.env.HOME ?? "/", LANG: "C.UTF-8", ...env }
          : env,
    });
    this.process = { child, buffer: "", lines: [], waiting: null, ended: null };
    if (argsText !== undefined) {
      child.stdio[5].on("error", () => {});
      child.stdio[5].end(argsText);
      let info = "";
      child.stdio[6].setEncoding("utf8");
      child.stdio[6].on("data", (chunk) => {
        info += chunk;
        const pid = /"child-pid"\s*:\s*(\d+)/.exec(info)?.[1];
        if (pid) this.sandboxes.add(Number(pid));
      });
    }
    const state = this.process;
    const wake = () => {
      const w = state.waiting;
      state.waiting = null;
      if (w) w();
    };
    child.stdio[4].setEncoding("utf8");
    child.stdio[4].on("data", (chunk) => {
      state.buffer += chunk;
      let at;
      while ((at = state.buffer.indexOf("\n")) >= 0) {
        state.lines.push(state.buffer.slice(0, at));
        state.buffer = state.buffer.slice(at + 1);
      }
      if (state.buffer.length > MAX_LINE) {
        state.lines.push(null);
        state.buffer = "";
      }
      wake();
    });
    child.stdio[3].on("error", () => {});
    child.on("error", (error) => {
      state.ended ??= `error ${error.message}`;
      wake();
    });
    child.on("exit", (status, signal) => {
      state.ended ??= signal ? `signal ${signal}` : `status ${status}`;
      wake();
    });
    child.stdio[4].on("end", wake);
  }

  // The next message, or { timeout } / { ended } / { garbled }.
  async next(seconds) {
    const state = this.process;
    const deadline = Date.now() + seconds * 1000;
    while (state.lines.length === 0 && !state.ended) {
      const left = deadline - Date.now();
      if (left <= 0) return { timeout: true };
      await new Promise((resolve) => {
        const timer = setTimeout(resolve, left);
        state.waiting = () => {
          clearTimeout(timer);
          resolve();
        };
      });
    }
    if (state.lines.length === 0) return { ended: state.ended };
    const line = state.lines.shift();
    try {
      const message = line === null ? null : JSON.parse(line);
      if (message && typeof message === "object" && !Array.isArray(message)) return message;
    } catch {
      // said below
    }
    return { garbled: "answered with something that is not an answer" };
  }

  send(message) {
    try {
      this.process.child.stdio[3].write(`${JSON.stringify(message)}\n`);
    } catch {
      // the process has ended: the next message says so
    }
  }

  stop() {
    if (!this.process) return;
    try {
      process.kill(-this.process.child.pid, "SIGKILL");
    } catch {
      // already gone
    }
    this.process.child.stdio[3].destroy();
    this.process.child.stdio[4].destroy();
    this.process = null;
  }

  // Resolves when every sandbox started is gone (its first process has ended, and the
  // kernel ends the rest of its PID namespace with it; a zombie holds nothing), its
  // cgroup empty and removed, or after 10 s.
  async gone() {
    const deadline = Date.now() + 10000;
    const running = (pid) => {
      try {
        return !/^\d+ \(.*\) Z /s.test(fs.readFileSync(`/proc/${pid}/stat`, "utf8"));
      } catch {
        return false;
      }
    };
    for (const pid of this.sandboxes) {
      while (running(pid) && Date.now() < deadline)
        await new Promise((resolve) => setTimeout(resolve, 10));
    }
    await sandbox.removeCgroup();
  }

  async load(functions, names) {
    this.loadRequest = {
      load: { module: this.options.module, adapter: this.options.adapter, functions, names },
    };
    this.start();
    this.send(this.loadRequest);
    const message = await this.next(this.options.loadLimit);
    const { CheckError } = await import("./core/report.mjs");
    const fail = (text) => {
      this.stop();
      throw new CheckError(text);
    };
    if (message.timeout)
      fail(
        `your module ${this.options.shownModule} does not load: still running after ${this.options.loadLimit} s`,
      );
    if (message.ended)
      fail(
        `your module ${this.options.shownModule} does not load: it ended the process (exit ${message.ended}) while loading`,
      );
    if (typeof message.load_error === "string")
      fail(message.load_error.split("\n")[0].slice(0, 500));
    const facts = message.loaded;
    const { heldAgainstFile, isAccount } = await import("./core/account.mjs");
    if (!isAccount(facts)) {
      fail(
        `your module ${this.options.shownModule} does not load: it said something else while loading`,
      );
    }
    // The process's account of the file, held against what the file says of itself.
    const defined = await definedFunctions(this.options.module, this.language, {
      python: this.language === "python" ? sandbox.pythonInterpreter()?.executable : "",
      nodePath: this.language === "python" ? "" : nodePath(),
    });
    return heldAgainstFile(facts, defined, functions);
  }

  async run(request) {
    if (Date.now() - this.started > this.bound) return { stopped: true };
    if (!this.process) {
      this.start();
      this.send(this.loadRequest);
      const message = await this.next(this.options.loadLimit);
      if (!message.loaded) {
        this.stop();
        return { garbled: "a new process for this case could not load your module" };
      }
    }
    const id = ++this.id,
      nonce = crypto.randomBytes(8).toString("hex");
    const limit = this.options.timeLimit;
    this.send({ ...request, id, nonce, limit });
    const answer = await this.next(limit + GRACE);
    const ours = answer.id === id && answer.nonce === nonce;
    // The process's own answer (a case it ended on its time limit included) keeps it;
    // silence, an end or anything else ends it, and the next case gets a new one.
    if (!ours) this.stop();
    if (answer.timeout && !ours) return { timeout: true, limit };
    if ((answer.ended || answer.garbled) && !ours) return { ...answer, limit };
    if (!ours) return { garbled: "answered out of turn (not this case's answer)" };
    return { ...answer, limit };
  }

  stoppedLine() {
    return this.stopped(
      Math.round((Date.now() - this.started) / 1000),
      this.totalCases,
      this.options,
    );
  }
}

// A word of a command as a shell reads it back; a path in the home folder as ~/...
function shellWord(word) {
  const quoted = (text) => (/^[\w./:=+-]*$/.test(text) ? text : `'${text.replace(/'/g, "'\\''")}'`);
  const home = process.env.HOME;
  if (home && home !== "/" && path.isAbsolute(word) && word.startsWith(`${home}/`))
    return `~/${quoted(word.slice(home.length + 1))}`;
  return quoted(word);
}

// The results file, written whole or not at all: into a new file beside it, then renamed
// over it; standard output for "-".
function writeResults(target, text) {
  if (target === "-") {
    process.stdout.write(text);
    return;
  }
  const temporary = path.join(
    path.dirname(path.resolve(target)),
    `.${path.basename(target)}.${process.pid}.tmp`,
  );
  try {
    fs.writeFileSync(temporary, text, { flag: "wx", mode: 0o644 });
    fs.renameSync(temporary, target);
  } catch (error) {
    fs.rmSync(temporary, { force: true });
    throw new Usage(`--json ${target}: cannot write it (${error.code ?? error.message})`);
  }
}

function caseFiles() {
  const files = {};
  for (const name of fs
    .readdirSync(CASES_DIR)
    .filter((each) => each.endsWith(".json"))
    .sort()) {
    files[name.replace(/\.json$/, "")] = JSON.parse(
      fs.readFileSync(path.join(CASES_DIR, name), "utf8"),
    );
  }
  return files;
}

async function main(argv) {
  const options = parse(argv);
  if (options.help) {
    process.stdout.write(
      `${USAGE}\n\nChecks your chapter's functions, one by one, against the cases of tests/cases/ (docs/students.md).\n`,
    );
    return 0;
  }
  const { CASE_LIMIT, LOAD_LIMIT, chapterNamed, sections } = await import("./core/plan.mjs");
  const { check, stoppedLine } = await import("./core/report.mjs");
  options.timeLimit ??= CASE_LIMIT;
  options.loadLimit = LOAD_LIMIT;
  const { adapterTemplate } = await import("./core/template.mjs");
  if (options.templateLanguage || (options.template && !options.module)) {
    process.stdout.write(adapterTemplate(options.templateLanguage ?? "python"));
    return 0;
  }
  const files = caseFiles();
  const chapter = chapterNamed(options.chapter, Object.keys(files));
  if (!chapter) {
    throw new Usage(
      `no chapter '${options.chapter}': give a number such as 02 or a folder name; there are cases for ${Object.keys(files).join(", ")}`,
    );
  }
  if (options.function !== undefined) {
    const { functionsOf } = await import("./core/plan.mjs");
    const known = functionsOf(sections(chapter, files));
    if (!known.includes(options.function))
      throw new Usage(`--function ${options.function}: ${chapter} checks ${known.join(", ")}`);
  }
  const totalCases = sections(chapter, files)
    .flatMap((s) => s.entries)
    .reduce((n, e) => n + e.cases.length, 0);
  const runner = new ProcessRunner(options, totalCases);
  runner.stopped = stoppedLine;
  running = runner;
  try {
    if (options.template) {
      const { functionsOf } = await import("./core/plan.mjs");
      const { NAMES } = await import("./core/names.mjs");
      const facts = await runner.load(functionsOf(sections(chapter, files)), NAMES);
      process.stdout.write(adapterTemplate(options.language, facts, path.basename(options.module)));
      return 0;
    }
    const started = Date.now();
    const rerun = (name, caseFile, number) => {
      const which = caseFile.startsWith(chapter)
        ? `${number}`
        : `${caseFile.slice(0, 2)}:${number}`;
      const relative = path.relative(process.cwd(), process.argv[1]);
      const checker =
        relative.startsWith("..") || path.isAbsolute(relative) ? process.argv[1] : relative;
      return (
        `node ${shellWord(checker)} ${chapter.slice(0, 2)} ${shellWord(options.shownModule)}` +
        `${options.adapter ? ` --adapter ${shellWord(options.adapter)}` : ""} --function ${name} --case ${which}`
      );
    };
    const only = options.function ? { function: options.function, case: options.case } : null;
    let result;
    try {
      result = await check({
        chapter,
        files,
        runner,
        file: path.basename(options.module),
        adapterGiven: Boolean(options.adapter),
        only,
        rerun,
        repl: true,
      });
    } catch (error) {
      // A file that cannot be checked is a result too: no case ran, the one line is its output.
      if (options.json !== undefined && error?.constructor?.name === "CheckError") {
        const { gradescopeResults } = await import("./core/results.mjs");
        writeResults(
          options.json,
          `${JSON.stringify(
            gradescopeResults(
              { records: [], verdict: "incomplete" },
              {
                chapter,
                file: path.basename(options.module),
                language: options.language,
                seconds: (Date.now() - started) / 1000,
                report: `check-functions.js: ${error.message}`,
                notes: [],
              },
            ),
            null,
            2,
          )}\n`,
        );
      }
      throw error;
    }
    const { lines } = result;
    const unsandboxed = sandbox.why();
    if (runner.searchCut) {
      lines.unshift(
        'note: your folders hold more than 200 000 entries: the search for copies of the case files stopped there (docs/students.md, "Where your code runs")',
      );
    }
    if (unsandboxed) {
      lines.unshift(
        `note: no sandbox, ${unsandboxed}: your code ran with your rights (docs/students.md, "Where your code runs")`,
      );
    }
    const limitsNote = sandbox.limitsNote();
    if (limitsNote) lines.unshift(`note: ${limitsNote} (docs/students.md, "Where your code runs")`);
    if (options.json !== "-") process.stdout.write(`${lines.join("\n")}\n`);
    if (options.json !== undefined) {
      const { gradescopeResults } = await import("./core/results.mjs");
      const results = gradescopeResults(result, {
        chapter,
        file: path.basename(options.module),
        language: options.language,
        seconds: (Date.now() - started) / 1000,
        report: lines.join("\n"),
        notes: lines.filter((line) => line.startsWith("note: ")),
      });
      writeResults(options.json, `${JSON.stringify(results, null, 2)}\n`);
    }
    return EXIT[result.verdict];
  } finally {
    runner.stop();
    await runner.gone();
  }
}

// However the checker ends (a student's Ctrl-C included), the process it started goes too.
let running = null;
process.on("exit", () => running?.stop());
for (const signal of ["SIGINT", "SIGTERM", "SIGHUP"]) {
  process.on(signal, () => {
    running?.stop();
    process.exit(130);
  });
}

main(process.argv.slice(2)).then(
  (status) => {
    process.exitCode = status;
  },
  (error) => {
    if (error instanceof Usage) {
      process.stderr.write(`check-functions.js: error: ${error.message}\n`);
      process.exitCode = 2;
    } else if (error?.constructor?.name === "CheckError") {
      process.stderr.write(`check-functions.js: ${error.message}\n`);
      process.exitCode = 1;
    } else {
      process.stderr.write(`check-functions.js: ${error?.stack ?? error}\n`);
      process.exitCode = 2;
    }
  },
);
