// A stand-in for the page a chapter written for the browser expects (document and its
// canvas, a 2D context, Image, window), enough for the book's own demo pages
// (demos/raytracer-0N.html, demos/raster-NN.html) to load where there is no page: in
// the checker's Node.js process (js_runner.mjs) and in a chapter page's Web Worker
// (js_worker.mjs). What they draw goes nowhere; in a case, the checker's PutPixel takes
// the place of theirs.

// Anything: a function that does nothing and returns another such, with every property
// one too, so that a page's buttons, inputs and styles can be touched without effect.
function anything() {
  const target = function () {};
  return new Proxy(target, {
    get: (_, key) => (key === Symbol.toPrimitive ? () => "" : key === "value" ? "" : anything()),
    apply: () => anything(),
    construct: () => anything(),
    set: () => true,
  });
}

function context2d() {
  const imageData = (width, height) => ({
    width,
    height,
    data: new Uint8ClampedArray(Math.max(0, width * height * 4)),
  });
  const known = {
    getImageData: (x, y, width, height) => imageData(width, height),
    createImageData: (width, height) => imageData(width, height),
  };
  return new Proxy(known, { get: (target, key) => target[key] ?? (() => {}) });
}

// The canvas element, its size as the page's <canvas> gives it.
function canvasElement(html) {
  const tag = /<canvas\b[^>]*>/i.exec(html)?.[0] ?? "";
  const size = (name) =>
    Number(new RegExp(`\\b${name}\\s*=\\s*["']?(\\d+)`, "i").exec(tag)?.[1] ?? 600);
  const context = context2d();
  return {
    width: size("width"),
    height: size("height"),
    style: {},
    getContext: () => context,
    addEventListener() {},
    removeEventListener() {},
    getBoundingClientRect: () => ({ left: 0, top: 0 }),
  };
}

export function installPage(html) {
  const canvas = canvasElement(html);
  const elements = new Map();
  const element = (id) => {
    if (/canvas/i.test(id)) return canvas;
    if (!elements.has(id)) elements.set(id, anything());
    return elements.get(id);
  };
  globalThis.window = globalThis;
  globalThis.document = {
    getElementById: element,
    querySelector: (selector) => (/canvas/i.test(selector) ? canvas : anything()),
    querySelectorAll: () => [],
    getElementsByTagName: (tag) => (/canvas/i.test(tag) ? [canvas] : []),
    createElement: (tag) => (/canvas/i.test(tag) ? canvasElement("") : anything()),
    addEventListener() {},
    body: anything(),
  };
  // An image that never loads: a page's textures stay empty.
  globalThis.Image = function Image() {
    return new Proxy(
      { width: 0, height: 0 },
      {
        get: (target, key) => (key in target ? target[key] : anything()),
        set: (target, key, value) => {
          target[key] = value;
          return true;
        },
      },
    );
  };
  globalThis.requestAnimationFrame = () => 0;
  globalThis.alert = () => {};
}
