#include "seeds.h"

#include <stb_image_write.h>

#include "cgfs/image.h"
#include "program/image_files.h"

namespace cgfs::fuzz {

namespace {

void Append(void* context, void* data, int size) {
  static_cast<std::string*>(context)->append(static_cast<const char*>(data),
                                             static_cast<std::size_t>(size));
}

// A w x h image of `channels` channels, a gradient with a square in it.
std::vector<unsigned char> Pixels(int w, int h, int channels) {
  std::vector<unsigned char> pixels;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      for (int c = 0; c < channels; ++c) {
        const bool square = x > w / 4 && x < 3 * w / 4 && y > h / 4 && y < 3 * h / 4;
        pixels.push_back(static_cast<unsigned char>(square ? 255 - 40 * c : 16 * x + 8 * y + c));
      }
    }
  }
  return pixels;
}

std::string Png(int w, int h, int channels) {
  std::string bytes;
  const std::vector<unsigned char> pixels = Pixels(w, h, channels);
  stbi_write_png_to_func(Append, &bytes, w, h, channels, pixels.data(), w * channels);
  return bytes;
}

std::string Jpeg(int w, int h, int quality) {
  std::string bytes;
  const std::vector<unsigned char> pixels = Pixels(w, h, 3);
  stbi_write_jpg_to_func(Append, &bytes, w, h, 3, pixels.data(), quality);
  return bytes;
}

}  // namespace

std::vector<std::pair<std::string, std::string>> MakeSeeds() {
  const std::vector<unsigned char> rgb = Pixels(6, 4, 3);
  const Image image(6, 4, std::vector<std::uint8_t>(rgb.begin(), rgb.end()));
  return {
      {"rgb.png", Png(8, 8, 3)},
      {"grey.png", Png(5, 7, 1)},
      {"grey-alpha.png", Png(4, 4, 2)},
      {"rgba.png", Png(9, 3, 4)},
      {"small.jpg", Jpeg(16, 16, 90)},
      {"odd.jpg", Jpeg(13, 7, 40)},
      {"binary.ppm", EncodeImage(image, "binary.ppm")},
      {"plain.ppm", "P3\n# a comment\n2 2\n255\n255 0 0  0 255 0\n0 0 255  255 255 255\n"},
  };
}

}  // namespace cgfs::fuzz
