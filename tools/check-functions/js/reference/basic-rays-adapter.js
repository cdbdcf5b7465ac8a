// The adapter of basic-rays.js: the book's vectors as its Vec3, and the book's globals
// handed to it with configure() (they live inside that module, out of the runner's
// reach). Everything else is the runner's default.
"use strict";

const { Vec3 } = require("./basic-rays.js");

module.exports = {
  vector: ([x, y, z]) => new Vec3(x, y, z),
  setup(module, given, adapter) {
    module.configure({
      canvas: given.canvas,
      viewport: given.viewport,
      scene: given.scene && adapter.scene(given.scene, adapter),
    });
  },
};
