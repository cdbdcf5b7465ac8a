// cases: 07 (tests/cases/07-filled-triangles.json)
// Chapter 7, "Filled Triangles", in plain JavaScript, as the book writes it: the
// checker's reference (tools/check-functions). DrawWireframeTriangle and
// DrawFilledTriangle (Listing 7-1), drawing with the canvas configure() gives.
"use strict";

const lines = require("./lines.js");
const { Interpolate } = lines;

let PutPixel = () => { throw new Error("your canvas goes here"); };

function configure(given) {
  if (given.PutPixel) PutPixel = given.PutPixel;
  lines.configure(given);
}

function DrawWireframeTriangle(P0, P1, P2, color) {
  lines.DrawLine(P0, P1, color);
  lines.DrawLine(P1, P2, color);
  lines.DrawLine(P2, P0, color);
}

// Listing 7-1: for each row, from the long side to the two short ones.
function DrawFilledTriangle(P0, P1, P2, color) {
  // Sort the points so that y0 <= y1 <= y2
  if (P1.y < P0.y) [P1, P0] = [P0, P1];
  if (P2.y < P0.y) [P2, P0] = [P0, P2];
  if (P2.y < P1.y) [P2, P1] = [P1, P2];

  // Compute the x coordinates of the triangle edges
  const x01 = Interpolate(P0.y, P0.x, P1.y, P1.x);
  const x12 = Interpolate(P1.y, P1.x, P2.y, P2.x);
  const x02 = Interpolate(P0.y, P0.x, P2.y, P2.x);

  // Concatenate the short sides
  x01.pop();
  const x012 = x01.concat(x12);

  // Determine which is left and which is right
  const m = Math.floor(x012.length / 2);
  const [x_left, x_right] = x02[m] < x012[m] ? [x02, x012] : [x012, x02];

  // Draw the horizontal segments
  for (let y = P0.y; y <= P2.y; y++) {
    for (let x = Math.trunc(x_left[y - P0.y]); x <= Math.trunc(x_right[y - P0.y]); x++) {
      PutPixel(x, y, color);
    }
  }
}

module.exports = { configure, DrawWireframeTriangle, DrawFilledTriangle };
