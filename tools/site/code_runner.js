// Where a reader's code runs on a chapter's page (yourcode.js): a Web Worker of its own,
// JavaScript (CGFS_SOURCES.jsWorker, tools/check-functions/runners/js_worker.mjs bundled)
// or Python (CGFS_SOURCES.pythonWorker, python_worker.js, with Pyodide's files from
// vendor/pyodide.js, loaded only when Python is first wanted). Each check and each draw
// gets a worker no code of the reader's has run in yet: its first answer, the functions
// the code defines read from its syntax, is the page's own, and the account the code
// then gives of itself is held against it, as the command line's checker holds a
// process's. A case that runs past its time limit ends its worker; the next case gets a
// new one. PageRunner is the runner the checker's core (vendor/check.js) drives, as the
// command line's ProcessRunner is.
"use strict";

const kSiteRoot = new URL(".", document.currentScript.src);

// Pyodide's files, from vendor/pyodide.js (a script, which a page opened from a file may
// load where it may not fetch), as its base64 text: each Python worker decodes the
// binaries itself, off the page's thread (decoded here, 18 MB froze the page for
// seconds). The script's global is emptied once read (a `var` cannot be deleted).
let pyodideAssets = null;
function loadPyodideAssets() {
  pyodideAssets ??= new Promise((resolve, reject) => {
    const script = document.createElement("script");
    script.src = new URL("vendor/pyodide.js", kSiteRoot).href;
    script.onerror = () =>
      reject(new Error("vendor/pyodide.js could not be loaded: build the site with scripts/site"));
    script.onload = () => {
      resolve(self.CGFS_PYODIDE);
      self.CGFS_PYODIDE = undefined;
    };
    document.head.append(script);
  });
  return pyodideAssets;
}

const workerAddress = (text) => URL.createObjectURL(new Blob([text], { type: "text/javascript" }));

// One worker: requests answered one at a time, each within its limit (seconds) or the
// worker is ended. `onProgress(fraction)` hears a draw's progress.
class CodeWorker {
  // onProgress(fraction): how far Python's start has come.
  static async start(language, onProgress) {
    const worker = new CodeWorker(language, onProgress);
    if (language === "python") {
      const answer = await worker.request(
        { op: "init", assets: await loadPyodideAssets(), runner: CGFS_SOURCES.pythonRunner },
        300,
      );
      if (!answer.ready) {
        worker.end();
        throw new Error(
          `Python could not be started: ${answer.unreadable ?? "it took more than 300 s"}`,
        );
      }
    }
    return worker;
  }

  constructor(language, onProgress = () => {}) {
    CodeWorker.addresses ??= {
      javascript: workerAddress(CGFS_SOURCES.jsWorker),
      python: workerAddress(CGFS_SOURCES.pythonWorker),
    };
    this.worker = new Worker(CodeWorker.addresses[language]);
    this.next = 1;
    this.waiting = null;
    this.onProgress = onProgress;
    this.onPreview = () => {};
    this.worker.onmessage = ({ data }) => {
      if ("progress" in data) this.onProgress(data.progress);
      else if ("preview" in data) this.onPreview(data.preview);
      else if (this.waiting?.id === data.id) this.waiting.resolve(data);
    };
  }

  get alive() {
    return this.worker !== null;
  }

  // The answer, or { timeout: true } when there was none within `seconds` (the worker
  // is ended then).
  request(message, seconds) {
    if (!this.alive) return Promise.resolve({ timeout: true });
    const id = this.next++;
    return new Promise((resolve) => {
      const timer = setTimeout(() => {
        this.waiting = null;
        this.end();
        resolve({ timeout: true });
      }, seconds * 1000);
      this.waiting = {
        id,
        resolve: (answer) => {
          clearTimeout(timer);
          this.waiting = null;
          resolve(answer);
        },
      };
      this.worker.postMessage({ ...message, id });
    });
  }

  end() {
    this.worker?.terminate();
    this.worker = null;
    this.waiting?.resolve({ cancelled: true });
  }
}

// Fresh workers made ready ahead: Python's take seconds to start, so two are kept ready
// (a check clicked again at once takes the second), started one after the other;
// JavaScript's start at once. Whoever waits for one that is still starting hears how far
// its start has come (onStarting(fraction)).
class WorkerSupply {
  constructor(language) {
    this.language = language;
    this.ready = []; // { promise, listener }: the workers ready or starting, the oldest first
    this.starting = false;
    this.target = language === "python" ? 2 : 1;
  }

  // Starts workers until `target` are ready or starting, one at a time.
  fill() {
    if (this.starting || this.ready.length >= this.target) return;
    const entry = { listener: null };
    entry.promise = CodeWorker.start(this.language, (fraction) => entry.listener?.(fraction));
    this.starting = true;
    this.ready.push(entry);
    const started = () => {
      this.starting = false;
      this.fill();
    };
    entry.promise.then(
      () => {
        entry.done = true;
        started();
      },
      () => {
        this.ready = this.ready.filter((each) => each !== entry);
        started();
      },
    );
  }

  // Python started ahead, as soon as the reader chooses it.
  warm(onStarting = () => {}) {
    this.fill();
    this.ready[0].listener = onStarting;
    this.ready[0].promise.then(
      () => onStarting(1),
      () => {},
    );
  }

  // A worker no code has run in (the oldest made ready). The supply is filled again by
  // RefillWorkers, once the check or draw is over: a worker started meanwhile would take
  // a core from it.
  async take(onProgress, onStarting = () => {}) {
    if (this.ready.length === 0) this.fill();
    const entry = this.ready.shift();
    entry.listener = onStarting;
    const worker = await entry.promise;
    entry.listener = null;
    worker.onProgress = onProgress ?? (() => {});
    return worker;
  }

  // How many workers are ready now (for the site's test).
  get readyNow() {
    return this.ready.filter((entry) => entry.done).length;
  }
}

const supplies = {};
const supplyFor = (language) => (supplies[language] ??= new WorkerSupply(language));
// After a check or a draw: workers made ready again for the next.
const refillWorkers = () => Object.values(supplies).forEach((supply) => supply.fill());

// The reader's code loaded in a fresh worker: the account it gives of itself, held
// against its syntax (read first, before any of it ran). Throws CheckError with the
// command line's words when it does not load.
async function loadInWorker(worker, { code, file, functions, names }) {
  const { CheckError, LOAD_LIMIT, heldAgainstFile, isAccount } = CGFS_CHECK;
  const declared = await worker.request({ op: "declare", code }, LOAD_LIMIT);
  const message = await worker.request({ op: "load", code, file, functions, names }, LOAD_LIMIT);
  if (message.timeout)
    throw new CheckError(`your code does not load: still running after ${LOAD_LIMIT} s`);
  if (typeof message.load_error === "string")
    throw new CheckError(message.load_error.split("\n")[0].slice(0, 500));
  const facts = message.loaded;
  if (!isAccount(facts)) {
    throw new CheckError("your code does not load: it said something else while loading");
  }
  return heldAgainstFile(
    facts,
    declared.declared ? new Map(Object.entries(declared.declared)) : null,
    functions,
  );
}

// The runner the checker's core drives: load, then a case at a time.
class PageRunner {
  // onStarting(fraction): how far Python's start has come, while the check waits for it.
  constructor({
    language,
    code,
    file,
    timeLimit,
    totalCases,
    onStatus = () => {},
    onStarting = () => {},
  }) {
    Object.assign(this, {
      language,
      code,
      file,
      timeLimit,
      totalCases,
      onStatus,
      onStarting,
      worker: null,
    });
    this.started = Date.now();
    this.bound = (totalCases * timeLimit + CGFS_CHECK.LOAD_LIMIT) * 1000;
  }

  async load(functions, names) {
    this.loadRequest = { code: this.code, file: this.file, functions, names };
    if (this.language === "python") this.onStatus("starting Python (Pyodide)…");
    this.worker = await supplyFor(this.language).take(null, this.onStarting);
    this.onStatus("checking…");
    this.started = Date.now();
    return loadInWorker(this.worker, this.loadRequest);
  }

  async run(request) {
    // Stop pressed: no case after it runs (each would take a new worker, and an endless
    // function its full time limit).
    if (this.ended || Date.now() - this.started > this.bound) return { stopped: true };
    if (!this.worker.alive) {
      // the last case ran out of time: a new worker
      this.worker = await supplyFor(this.language).take();
      try {
        await loadInWorker(this.worker, this.loadRequest);
      } catch {
        return { garbled: "a new worker for this case could not load your code" };
      }
    }
    const answer = await this.worker.request({ op: "case", request }, this.timeLimit);
    if (this.ended) return { stopped: true }; // Stop pressed while this case ran
    if (answer.timeout) return { timeout: true, limit: this.timeLimit };
    delete answer.id;
    return { ...answer, limit: this.timeLimit };
  }

  stoppedLine() {
    if (this.ended)
      return `stopped after ${Math.round((Date.now() - this.started) / 1000)} s: you pressed Stop`;
    return CGFS_CHECK.stoppedLine(Math.round((Date.now() - this.started) / 1000), this.totalCases, {
      timeLimit: this.timeLimit,
      loadLimit: CGFS_CHECK.LOAD_LIMIT,
    });
  }

  // Stop: the case running ends with its worker, and no other runs.
  end() {
    this.ended = true;
    this.worker?.end();
  }
}

// A figure drawn by the reader's functions, in a fresh worker: { pixels, width, height },
// or { problem } (one line), or { cancelled } when `cancel` was called first. `entries`:
// the case files' entry of every function the recipe may call; each is called with the
// parameters of the signature the reader's function takes (the book's, or the demos'
// CanvasToViewport(p2d)), as the check calls it.
async function drawWithCode({
  language,
  code,
  file,
  names,
  recipe,
  entries,
  seconds,
  onProgress,
  onStatus,
  onPreview = () => {},
  onStarting = () => {},
}) {
  if (language === "python") onStatus("starting Python (Pyodide)…");
  const worker = await supplyFor(language).take(onProgress, onStarting);
  worker.onPreview = onPreview;
  drawWithCode.current = worker;
  try {
    onStatus("loading your code…");
    const functions = Object.keys(entries);
    const facts = await loadInWorker(worker, { code, file, functions, names });
    const kinds = Object.fromEntries(
      functions.map((name) => {
        const signature = CGFS_CHECK.signatureFor(entries[name], facts.functions[name]?.parameters);
        return [name, (signature ?? entries[name]).parameters];
      }),
    );
    onStatus("drawing…");
    const answer = await worker.request({ op: "draw", recipe, kinds }, seconds);
    if (answer.timeout) return { problem: `still drawing after ${seconds} s` };
    return answer;
  } catch (error) {
    return { problem: error.message };
  } finally {
    worker.end();
    drawWithCode.current = null;
  }
}
drawWithCode.Cancel = () => drawWithCode.current?.end();
