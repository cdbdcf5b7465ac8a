// cases: 14 (tests/cases/14-textures.json)
// Chapter 14, "Textures", in plain JavaScript, as the book writes it: the runner's
// reference (tools/check-functions). The nearest texel ("Painting a Crate") and
// GetTexel's bilinear filtering ("Bilinear Filtering"); texture[i][j] is column i, row j,
// and a texel past the last column or row is the last one.
"use strict";

const clamp = (value, last) => Math.min(Math.max(value, 0), last);
const Texel = (texture, i, j) => texture[clamp(i, texture.width - 1)][clamp(j, texture.height - 1)];
const Mix = (a, b, t) => a.map((each, k) => each + t * (b[k] - each));

function GetTexelNearest(texture, tx, ty) {
  return Texel(texture, Math.floor(tx), Math.floor(ty));
}

function GetTexel(texture, tx, ty) {
  const i = Math.floor(tx), j = Math.floor(ty);
  const fx = tx - i, fy = ty - j;
  const TL = Texel(texture, i, j), TR = Texel(texture, i + 1, j);
  const BL = Texel(texture, i, j + 1), BR = Texel(texture, i + 1, j + 1);
  return Mix(Mix(TL, TR, fx), Mix(BL, BR, fx), fy);
}

module.exports = { GetTexelNearest, GetTexel };
