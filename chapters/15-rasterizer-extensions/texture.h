// Chapter 14, "Textures": images painted onto triangles, and GetTexel.
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

#include "cgfs/color.h"
#include "cgfs/image.h"

using cgfs::Color;

// "Painting a Crate": a 2-D array of texels. A point of the texture is (u, v), both in
// [0, 1] whatever its size, with (0, 0) at the top-left, u to the right and v down;
// (u, v) is texel (u * width, v * height).
struct Texture {
  int width = 0;
  int height = 0;
  std::vector<Color> texels;  // row by row from the top

  // The texel in column i, row j, both clamped to the texture: the book's texture[i][j].
  // Here, in the header, so that the filters' four or eight reads per pixel are inlined.
  const Color& At(int i, int j) const {
    i = std::clamp(i, 0, width - 1);
    j = std::clamp(j, 0, height - 1);
    return texels[static_cast<std::size_t>(j) * static_cast<std::size_t>(width) +
                  static_cast<std::size_t>(i)];
  }
};

// The image's pixels as texels, its top row first.
Texture TextureFromImage(const cgfs::Image& image);

// The project's stand-in for the book's crate photograph: a wooden crate side of
// size x size texels, drawn in code (planks, a frame, a diagonal brace, nails).
Texture MakeCrateTexture(int size);

// A size x size checkerboard of `cell` x `cell` squares, `a` at the top-left.
Texture MakeCheckerboard(int size, int cell, const Color& a, const Color& b);

// "Painting a Crate": the texel that contains (tx, ty) = (u * width, v * height),
// texture[floor(tx)][floor(ty)], clamped (u = 1 gives tx = width, one past the last).
Color GetTexelNearest(const Texture& texture, double tx, double ty);

// "Bilinear Filtering": the four texels around (tx, ty) blended by its fractional
// parts. The texel (i, j) sits at the integer point (i, j); beyond the last column
// or row the last one is used again.
Color GetTexel(const Texture& texture, double tx, double ty);
