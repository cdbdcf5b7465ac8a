// Chapter 9 in CommonJS with vertices as arrays (v[0], v[1], v[2]) and canvas points
// returned as [x, y]. Written for the checker's corpus
// (tests/check-functions/check_corpus.mjs).
"use strict";

let Cw = 600, Ch = 600, Vw = 1, Vh = 1, d = 1;

function ViewportToCanvas(x, y) {
  return [Math.trunc((x * Cw) / Vw), Math.trunc((y * Ch) / Vh)];
}

function ProjectVertex(v) {
  return ViewportToCanvas((v[0] * d) / v[2], (v[1] * d) / v[2]);
}

module.exports = { ViewportToCanvas, ProjectVertex };
