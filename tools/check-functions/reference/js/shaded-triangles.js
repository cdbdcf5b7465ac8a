// cases: 08 (tests/cases/08-shaded-triangles.json)
// Chapter 8, "Shaded Triangles", in plain JavaScript, as the book writes it: the
// checker's reference (tools/check-functions). DrawShadedTriangle (Listing 8-1): each
// vertex has an intensity h, interpolated along the edges and across each row.
"use strict";

const { Interpolate } = require("./lines.js");

let PutPixel = () => { throw new Error("your canvas goes here"); };


// Listing 8-1: Listing 7-1 with h carried along.
function DrawShadedTriangle(P0, P1, P2, color) {
  // Sort the points so that y0 <= y1 <= y2
  if (P1.y < P0.y) [P1, P0] = [P0, P1];
  if (P2.y < P0.y) [P2, P0] = [P0, P2];
  if (P2.y < P1.y) [P2, P1] = [P1, P2];

  // Compute the x coordinates and h values of the triangle edges
  const x01 = Interpolate(P0.y, P0.x, P1.y, P1.x);
  const h01 = Interpolate(P0.y, P0.h, P1.y, P1.h);
  const x12 = Interpolate(P1.y, P1.x, P2.y, P2.x);
  const h12 = Interpolate(P1.y, P1.h, P2.y, P2.h);
  const x02 = Interpolate(P0.y, P0.x, P2.y, P2.x);
  const h02 = Interpolate(P0.y, P0.h, P2.y, P2.h);

  // Concatenate the short sides
  x01.pop();
  const x012 = x01.concat(x12);
  h01.pop();
  const h012 = h01.concat(h12);

  // Determine which is left and which is right
  const m = Math.floor(x012.length / 2);
  const [x_left, h_left, x_right, h_right] =
    x02[m] < x012[m] ? [x02, h02, x012, h012] : [x012, h012, x02, h02];

  // Draw the horizontal segments
  for (let y = P0.y; y <= P2.y; y++) {
    const x_l = Math.trunc(x_left[y - P0.y]);
    const x_r = Math.trunc(x_right[y - P0.y]);
    const h_segment = Interpolate(x_l, h_left[y - P0.y], x_r, h_right[y - P0.y]);
    for (let x = x_l; x <= x_r; x++) {
      PutPixel(x, y, color.map((channel) => channel * h_segment[x - x_l]));
    }
  }
}

module.exports = { DrawShadedTriangle };
