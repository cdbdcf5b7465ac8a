// The adapter of perspective-projection.js: the canvas and viewport handed over with
// configure(). Vectors stay the checker's arrays.
"use strict";

module.exports = {
  setup(module, given) {
    module.configure({ canvas: given.canvas, viewport: given.viewport });
  },
};
