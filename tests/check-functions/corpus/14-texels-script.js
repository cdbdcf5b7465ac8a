// Chapter 14's texel look-ups as a plain script in an older style: var, loops over the
// channels, an explicit clamp of each index. Written for the checker's corpus
// (tests/check-functions/check_corpus.mjs).
function texelAt(texture, i, j) {
  if (i > texture.width - 1) i = texture.width - 1;
  if (j > texture.height - 1) j = texture.height - 1;
  return texture[i][j];
}

function GetTexelNearest(texture, tx, ty) {
  return texelAt(texture, Math.floor(tx), Math.floor(ty));
}

function GetTexel(texture, tx, ty) {
  var i = Math.floor(tx), j = Math.floor(ty);
  var fx = tx - i, fy = ty - j;
  var tl = texelAt(texture, i, j), tr = texelAt(texture, i + 1, j);
  var bl = texelAt(texture, i, j + 1), br = texelAt(texture, i + 1, j + 1);
  var color = [];
  for (var c = 0; c < 3; c++) {
    var top = tl[c] * (1 - fx) + tr[c] * fx;
    var bottom = bl[c] * (1 - fx) + br[c] * fx;
    color.push(top * (1 - fy) + bottom * fy);
  }
  return color;
}
