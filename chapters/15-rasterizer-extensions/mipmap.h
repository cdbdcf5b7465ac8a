// Chapter 14, "Mipmapping" and "Trilinear Filtering" (prose only in the book).
#pragma once

#include <vector>

#include "texture.h"

// "Mipmapping": the texture and its smaller copies, made once when the texture is
// loaded. Level 0 is the texture; each next level is half as wide and half as high
// (rounded down, at least 1), each texel the average of a 2x2 block of the level
// before (at an odd last row or column, of the texels there are). The last is 1x1.
// All levels together hold 4/3 of the texels of the first.
struct MipmappedTexture {
  std::vector<Texture> levels;
};

MipmappedTexture BuildMipChain(Texture texture);

// "Mipmapping": for rho texels per pixel, the level whose texels are about one
// pixel each, log2(rho), clamped to the chain: 0 when the texture is magnified.
double MipLevel(double rho, const MipmappedTexture& texture);

// How texels are read (Figure 14-11 shows each on a texture made too small).
enum class TextureFilter {
  kNearest,    // "Painting a Crate": the one texel (u, v) falls in
  kBilinear,   // "Bilinear Filtering": GetTexel on the full-size texture
  kMipmap,     // "Mipmapping": GetTexel on the level nearest to log2(rho)
  kTrilinear,  // "Trilinear Filtering": GetTexel on the two levels around it, blended
};

// The colour of the texture at (u, v), where one pixel covers rho texels of the
// full-size texture. Every level is read at the same place of the texture: its texels
// stand for the centres of the blocks of level-0 texels they average.
Color SampleTexture(const MipmappedTexture& texture, double u, double v, double rho,
                    TextureFilter filter);
