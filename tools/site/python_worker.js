// The Web Worker a reader's Python runs in on a chapter's page: Pyodide, the CPython of
// npm's package `pyodide` compiled to WebAssembly, with the checker's own runner
// (tools/check-functions/runners/python_runner.py) in it. Nothing is fetched: the page
// sends Pyodide's files (vendor/pyodide.js, made by scripts/site) with `init`, and any
// other request Pyodide makes is refused. A classic worker, for a page opened from a
// file may start no other from a Blob: Pyodide's two ES modules come as scripts (made
// by scripts/site with esbuild), and its loader, which refuses a classic worker because
// it would import its runtime as a module, is given that runtime instead
// (createPyodideModule) and loaded with importScripts hidden from its test. Messages
// { id, op, ... }, answered { id, ... }, as js_worker.mjs's:
//   init { assets, runner }                  Pyodide started, the runner imported;
//                                            { progress } messages meanwhile
//   declare { code }                         the functions the code defines, from its
//                                            syntax, before any of it runs
//   load { code, file, functions, names }    the chapter's account of itself, or why not
//   case { request }                         what the function made of one case
//   draw { recipe, kinds }                   a figure drawn with the reader's functions;
//                                            { progress } and, for a ray-traced one,
//                                            { preview }: a quarter-resolution picture
// The page ends the worker when a case or a draw runs too long.
"use strict";

let pyodide = null;
let runner = null;

// Pyodide's files, answered from what the page sent; nothing else is to be had.
function offlineFetch(files) {
  return async (address) => {
    const name = String(address?.url ?? address)
      .split("/")
      .pop();
    if (name in files) {
      return new Response(files[name], {
        headers: {
          "Content-Type": name.endsWith(".wasm") ? "application/wasm" : "application/octet-stream",
        },
      });
    }
    throw new TypeError(`${address}: the page's Python has no network`);
  };
}

const scriptAddress = (text) => URL.createObjectURL(new Blob([text], { type: "text/javascript" }));

// Pyodide's runtime (CGFS_PYODIDE_ASM) and loader (CGFS_PYODIDE_LOADER), as scripts.
function loadPyodideScripts({ asm, loader }) {
  const load = self.importScripts;
  load.call(self, scriptAddress(asm));
  self.importScripts = () => {
    throw new Error("a classic worker, given its runtime");
  };
  try {
    load.call(self, scriptAddress(loader));
  } finally {
    self.importScripts = load;
  }
}

// Base64 text as bytes (a worker's own work: the page's thread stays free).
function decoded(base64) {
  const text = atob(base64);
  const bytes = new Uint8Array(text.length);
  for (let i = 0; i < text.length; ++i) bytes[i] = text.charCodeAt(i);
  return bytes.buffer;
}

const operations = {
  async init({ assets, runner: runnerText }) {
    const start = performance.now();
    postMessage({ progress: 0.05 });
    self.fetch = offlineFetch({
      "pyodide.asm.wasm": decoded(assets.wasm),
      "python_stdlib.zip": decoded(assets.stdlib),
    });
    postMessage({ progress: 0.3 });
    loadPyodideScripts(assets);
    postMessage({ progress: 0.4 });
    pyodide = await CGFS_PYODIDE_LOADER.loadPyodide({
      indexURL: "https://pyodide.invalid/",
      stdLibURL: "https://pyodide.invalid/python_stdlib.zip",
      lockFileContents: assets.lock,
      createPyodideModule: CGFS_PYODIDE_ASM.default,
      stdout: () => {},
      stderr: () => {},
    });
    pyodide.FS.mkdirTree("/home/pyodide/runner");
    pyodide.FS.writeFile("/home/pyodide/runner/python_runner.py", runnerText);
    pyodide.runPython(
      "import sys\nsys.path.insert(0, '/home/pyodide/runner')\nimport python_runner",
    );
    postMessage({ progress: 0.9 });
    runner = pyodide.pyimport("python_runner");
    return { ready: true, milliseconds: performance.now() - start };
  },
  declare({ code }) {
    return { declared: JSON.parse(runner.page_declare(code)) };
  },
  load({ code, file, functions, names }) {
    return JSON.parse(
      runner.page_load(code, file, JSON.stringify(functions), JSON.stringify(names)),
    );
  },
  case({ request }) {
    return JSON.parse(runner.page_case(JSON.stringify(request)));
  },
  draw({ recipe, kinds }) {
    const drawn = runner.page_draw(
      JSON.stringify(recipe),
      JSON.stringify(kinds),
      (fraction) => postMessage({ progress: fraction }),
      (pixels) => {
        const bytes = new Uint8ClampedArray(pixels.toJs());
        pixels.destroy();
        postMessage({ preview: bytes }, [bytes.buffer]);
      },
    );
    if (typeof drawn === "string") return { problem: drawn };
    const pixels = new Uint8ClampedArray(drawn.toJs());
    drawn.destroy();
    const { width, height } = recipe.given.canvas;
    const notes = JSON.parse(runner.page_draw_notes());
    return { answer: { pixels, width, height, notes }, transfer: [pixels.buffer] };
  },
};

onmessage = async ({ data }) => {
  let result;
  try {
    result = await operations[data.op](data);
  } catch (error) {
    result = {
      unreadable: `the page's Python failed: ${String(error?.message ?? error)
        .trim()
        .split("\n")
        .pop()}`,
    };
  }
  const { answer, transfer = [] } = result.answer ? result : { answer: result };
  postMessage({ ...answer, id: data.id }, transfer);
};
