// The adapter of raytracer-extensions.js: vectors as its Vec3, and the canvas, viewport
// and camera handed over with configure().
"use strict";

const { Vec3 } = require("./basic-rays.js");

module.exports = {
  vector: ([x, y, z]) => new Vec3(x, y, z),
  setup(module, given, adapter) {
    module.configure({
      canvas: given.canvas,
      viewport: given.viewport,
      camera: given.camera && { position: adapter.vector(given.camera.position), rotation: given.camera.rotation },
    });
  },
};
