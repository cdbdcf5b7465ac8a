#include "mipmap.h"

#include <algorithm>
#include <cmath>
#include <utility>

MipmappedTexture BuildMipChain(Texture texture) {
  MipmappedTexture chain;
  chain.levels.push_back(std::move(texture));
  while (chain.levels.back().width > 1 || chain.levels.back().height > 1) {
    const Texture& above = chain.levels.back();
    Texture level{std::max(1, above.width / 2), std::max(1, above.height / 2), {}};
    for (int j = 0; j < level.height; ++j) {
      for (int i = 0; i < level.width; ++i) {
        // Texels beyond the last column or row are the last one again (Texture::At).
        level.texels.push_back((above.At(2 * i, 2 * j) + above.At(2 * i + 1, 2 * j) +
                                above.At(2 * i, 2 * j + 1) + above.At(2 * i + 1, 2 * j + 1)) /
                               4.0);
      }
    }
    chain.levels.push_back(std::move(level));
  }
  return chain;
}

double MipLevel(double rho, const MipmappedTexture& texture) {
  const double last = static_cast<double>(texture.levels.size() - 1);
  return rho > 1 ? std::min(std::log2(rho), last) : 0.0;
}

namespace {

// GetTexel at (u, v) on one level of the chain. The book puts texel (i, j) of the
// texture at the point (i, j), so (u, v) is read at (u w, v h). A smaller level's texel
// is the average of a block of the texture's texels and stands for the block's centre;
// read at (u w', v h') it would sit half a block minus half a texel away from them
// (about 2^(k-1) texels on level k). So each level is read at its own point for the
// same place on the texture: (u w' - (1 - w'/w) / 2, v h' - (1 - h'/h) / 2), which is
// (u w, v h) itself on level 0.
Color Bilinear(const Texture& level, const Texture& full, double u, double v) {
  const double shift_x = (1 - static_cast<double>(level.width) / full.width) / 2;
  const double shift_y = (1 - static_cast<double>(level.height) / full.height) / 2;
  return GetTexel(level, u * level.width - shift_x, v * level.height - shift_y);
}

}  // namespace

Color SampleTexture(const MipmappedTexture& texture, double u, double v, double rho,
                    TextureFilter filter) {
  const Texture& full = texture.levels.front();
  switch (filter) {
    case TextureFilter::kNearest:
      return GetTexelNearest(full, u * full.width, v * full.height);
    case TextureFilter::kBilinear:
      return Bilinear(full, full, u, v);
    case TextureFilter::kMipmap: {
      const auto level = static_cast<std::size_t>(std::lround(MipLevel(rho, texture)));
      return Bilinear(texture.levels[level], full, u, v);
    }
    case TextureFilter::kTrilinear: {
      // The two levels around log2(rho), weighted by where it falls between them.
      const double L = MipLevel(rho, texture);
      const auto lower = static_cast<std::size_t>(std::floor(L));
      const std::size_t upper = std::min(lower + 1, texture.levels.size() - 1);
      const double weight = L - std::floor(L);
      return (1 - weight) * Bilinear(texture.levels[lower], full, u, v) +
             weight * Bilinear(texture.levels[upper], full, u, v);
    }
  }
  return full.At(0, 0);
}
