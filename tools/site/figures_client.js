// The page's side of figures_worker.js, for the chapter pages and the index: a Web Worker
// made from the chapter's figures.js text (NN/figures-source.js) and the worker's own
// (vendor/sources.js), as a Blob, which a page opened from a file may start (a worker
// from a file of its own it may not). One request at a time; a draw can be stopped by
// ending the worker (Restart), which makes a new one.
"use strict";

class FiguresWorker {
  // moduleName: the chapter module's factory (Chapter02); figuresSource: figures.js's
  // text; onProgress(fraction): a long draw's progress.
  constructor(moduleName, figuresSource, onProgress = () => {}) {
    const code = `var CGFS_MODULE = ${JSON.stringify(moduleName)};\n${figuresSource}\n${CGFS_SOURCES.figuresWorker}`;
    this.url = URL.createObjectURL(new Blob([code], { type: "text/javascript" }));
    this.onProgress = onProgress;
    this.next = 1;
    this.pending = new Map();
    this.configuration = null; // the options message the figures are made with, if any
    this.start();
  }

  start() {
    this.worker = new Worker(this.url);
    // A new worker is given the options its figures were made with before anything else
    // (its answer, id 0, is no one's).
    if (this.configuration) this.worker.postMessage({ ...this.configuration, id: 0 });
    this.worker.onmessage = ({ data }) => {
      if ("progress" in data) {
        this.onProgress(data.progress);
        return;
      }
      const resolve = this.pending.get(data.id);
      this.pending.delete(data.id);
      if (resolve) resolve(data);
    };
    this.worker.onerror = (event) => {
      for (const resolve of this.pending.values())
        resolve({ problem: event.message || "the chapter's code failed" });
      this.pending.clear();
    };
  }

  request(message, transfer = []) {
    const id = this.next++;
    return new Promise((resolve) => {
      this.pending.set(id, resolve);
      this.worker.postMessage({ ...message, id }, transfer);
    });
  }

  // Sends an options message (figures_worker.js): if its options were read, they are
  // given again to every worker made after, which starts with the chapter's own.
  async configure(message) {
    const answer = await this.request(message);
    if (!answer.problem && !answer.cancelled && answer.status === 0) this.configuration = message;
    return answer;
  }

  // Whether a request is being answered.
  get busy() {
    return this.pending.size > 0;
  }

  // Ends what the worker is doing (its requests answer { cancelled: true }) and starts
  // a new one.
  restart() {
    this.worker.terminate();
    for (const resolve of this.pending.values()) resolve({ cancelled: true });
    this.pending.clear();
    this.start();
  }
}
