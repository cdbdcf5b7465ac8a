// The adapter of shadows-reflections.js: vectors as its Vec3, colours as arrays, and the scene
// handed over with configure().
"use strict";

const { Vec3 } = require("./basic-rays.js");

module.exports = {
  vector: ([x, y, z]) => new Vec3(x, y, z),
  setup(module, given, adapter) {
    module.configure({ scene: given.scene && adapter.scene(given.scene, adapter) });
  },
};
