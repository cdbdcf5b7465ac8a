// The names through which a case's data reach a student's chapter: the globals of the
// book's pseudocode (Cw, Ch, Vw, Vh, d, scene...) and the names of the author's demo
// pages (canvas.width, viewport_size, projection_plane_z, spheres, lights...). Before each
// case a runner sets every name below that the case gives: the book's always, the demos'
// where the chapter defines or reads them. `path` is where the value is in the case's
// "given", `kind` how a runner builds it (a number when absent), `part` what a report
// calls it, `empty` its value when the case gives the record around it but not it. One table, sent to every runner, so that what is set and what a report says
// was set cannot disagree.

export const NAMES = {
  Cw: { path: "canvas.width", part: "canvas", dialect: "book" },
  Ch: { path: "canvas.height", part: "canvas", dialect: "book" },
  Vw: { path: "viewport.width", part: "viewport", dialect: "book" },
  Vh: { path: "viewport.height", part: "viewport", dialect: "book" },
  d: { path: "viewport.d", part: "viewport", dialect: "book" },
  scene: { path: "scene", kind: "scene", part: "scene", dialect: "book" },
  BACKGROUND_COLOR: {
    path: "scene.background_color",
    kind: "color",
    part: "background",
    dialect: "book",
  },
  camera: { path: "camera", kind: "camera", part: "camera", dialect: "book" },
  depth_buffer: {
    path: "depth_buffer",
    kind: "depth_buffer",
    part: "depth buffer",
    dialect: "book",
  },
  PutPixel: { path: "canvas.PutPixel", kind: "PutPixel", part: "PutPixel", dialect: "book" },
  // The demos' (demos/raytracer-0N.html, demos/raster-NN.html in the book's repository).
  // The book's canvas.PutPixel(x, y, color) and the demos' canvas.width: a canvas object
  // of the chapter's gets the case's size and the checker's PutPixel.
  canvas: {
    path: "canvas",
    kind: "canvas",
    part: "canvas",
    parts: ["canvas", "PutPixel"],
    dialect: "demos",
  },
  viewport_size: { path: "viewport.width", part: "viewport", dialect: "demos", square: true },
  projection_plane_z: { path: "viewport.d", part: "viewport", dialect: "demos" },
  // A case that gives a scene without spheres or lights has none: [] (not the last case's).
  spheres: { path: "scene.spheres", kind: "spheres", part: "spheres", dialect: "demos", empty: [] },
  lights: { path: "scene.lights", kind: "lights", part: "lights", dialect: "demos", empty: [] },
  background_color: {
    path: "scene.background_color",
    kind: "color",
    part: "background",
    dialect: "demos",
  },
  camera_position: { path: "camera.position", kind: "vector", part: "camera", dialect: "demos" },
  camera_rotation: { path: "camera.rotation", kind: "rows", part: "camera", dialect: "demos" },
};

// The parts of a case's given, as a report names them, and the book's part each covers:
// the book's `scene` holds the spheres, the lights and the background.
export const PARTS = {
  canvas: "the canvas's size",
  viewport: "the viewport",
  scene: "the scene",
  spheres: "the spheres",
  lights: "the lights",
  background: "the background colour",
  camera: "the camera",
  "depth buffer": "the depth buffer",
  PutPixel: "PutPixel",
};
const COVERS = { scene: ["scene", "spheres", "lights", "background"] };

// The parts a case gives: the scene's as its spheres, lights and background.
export function partsGiven(given = {}) {
  const parts = [];
  for (const key of Object.keys(given)) {
    if (key === "scene") {
      for (const [field, part] of [
        ["spheres", "spheres"],
        ["lights", "lights"],
        ["background_color", "background"],
      ]) {
        if (field in given.scene) parts.push(part);
      }
    } else if (key === "depth_buffer") {
      parts.push("depth buffer");
    } else if (key in PARTS) {
      parts.push(key);
    }
  }
  return parts;
}

// Which parts a name brings.
export function partsOf(name) {
  const part = NAMES[name]?.part;
  return NAMES[name]?.parts ?? (part ? (COVERS[part] ?? [part]) : []);
}

// The table's names that bring a part, book's first.
export function namesOf(part) {
  return Object.keys(NAMES).filter((name) => partsOf(name).includes(part));
}
