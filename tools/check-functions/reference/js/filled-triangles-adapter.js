// The adapter of filled-triangles.js: the checker's PutPixel handed over with configure().
"use strict";

module.exports = {
  setup(module, given) {
    module.configure({ PutPixel: given.canvas?.PutPixel });
  },
};
