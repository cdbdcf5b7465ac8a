// cases: 09 (tests/cases/09-perspective-projection.json)
// Chapter 9, "Perspective Projection", in plain JavaScript, as the book writes it: the
// checker's reference (tools/check-functions). ViewportToCanvas and ProjectVertex
// (Listing 9-1).
"use strict";

let Cw = 600, Ch = 600;
let Vw = 1, Vh = 1, d = 1;


function ViewportToCanvas(x, y) {
  return { x: x * Cw / Vw, y: y * Ch / Vh };
}

function ProjectVertex(v) {
  return ViewportToCanvas(v[0] * d / v[2], v[1] * d / v[2]);
}

module.exports = { ViewportToCanvas, ProjectVertex };
