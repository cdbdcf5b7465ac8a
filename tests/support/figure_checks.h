// Figures of the rasterizer chapters checked against the independent ray caster
// (ray_caster.h): what each pixel shows, and whether it sees the light.
#pragma once

#include <catch2/catch.hpp>

#include <memory>
#include <vector>

#include "cgfs/canvas.h"
#include "ray_caster.h"

namespace cgfs::test {

// The colour families of the rasterizer chapters' flat-coloured models, by which
// channels are not zero: red, green, blue, yellow, purple, cyan, and the white
// background. Light scales a colour, and clamping keeps a zero channel at zero, so a
// lit pixel keeps its model's family; a black pixel (no light) has none (-1).
inline int FamilyOf(const Rgb8& pixel) {
  const int family = (pixel.r > 0 ? 1 : 0) | (pixel.g > 0 ? 2 : 0) | (pixel.b > 0 ? 4 : 0);
  return family == 0 ? -1 : family;
}

inline int FamilyOf(const Color& color) {
  return FamilyOf(Rgb8{color.r > 0 ? std::uint8_t{1} : std::uint8_t{0},
                       color.g > 0 ? std::uint8_t{1} : std::uint8_t{0},
                       color.b > 0 ? std::uint8_t{1} : std::uint8_t{0}});
}

// The colour family of what the ray caster finds at a pixel: the triangle's colour,
// or the white background.
template <typename Scene>
int CastFamily(const Scene& scene, const CastHit& hit) {
  if (hit.instance < 0) {
    return FamilyOf(Rgb8{255, 255, 255});
  }
  const auto& model = *scene.instances[static_cast<std::size_t>(hit.instance)].model;
  return FamilyOf(model.triangles[static_cast<std::size_t>(hit.triangle)].color);
}

// How many of the pixels more than `margin` pixels from the edge of a colour family
// in the cast image show that family in `figure` (black pixels, which show no family,
// are left out of the count).
template <typename Scene>
Agreement CompareFamilies(const Scene& scene, const CastImage& cast, const Canvas& figure,
                          int margin) {
  const LabelImage families =
      LabelsOf(cast, [&](const CastHit& hit) { return CastFamily(scene, hit); });
  const int background = FamilyOf(Rgb8{255, 255, 255});
  Agreement agreement;
  for (int y = -cast.height / 2; y < cast.height / 2; ++y) {
    for (int x = -cast.width / 2; x < cast.width / 2; ++x) {
      const int drawn = FamilyOf(figure.GetPixel(x, y));
      const int cast_family = families.At(x, y);
      if (drawn < 0 || (drawn == background && cast_family == background) ||
          !families.Inside(x, y, margin)) {
        continue;  // black, both background, or near an edge
      }
      ++agreement.counted;
      agreement.agreeing += drawn == cast_family;
    }
  }
  return agreement;
}
// A colour for each instance, and the instance a colour stands for (-1 for the
// background, -2 for a colour that stands for none).
inline Color InstanceColor(int instance) {
  return {40 + 16 * instance, 200 - 12 * instance, 100};
}
inline int InstanceOf(const Rgb8& pixel) {
  if (pixel == Rgb8{255, 255, 255}) {
    return -1;
  }
  for (int k = 0; k < 10; ++k) {
    const Color c = InstanceColor(k);
    if (pixel == Rgb8{static_cast<std::uint8_t>(c.r), static_cast<std::uint8_t>(c.g),
                      static_cast<std::uint8_t>(c.b)}) {
      return k;
    }
  }
  return -2;
}

// The scene with every instance in its own flat colour (InstanceColor), lit by an
// ambient light of 1 alone, so that a pixel's colour says which instance it shows;
// textures, normal maps and reflections, where the chapter has them, left out. The
// models are kept in `models`, which must outlive the scene.
template <typename Scene, typename Model>
Scene InstanceColoredScene(const Scene& scene, std::vector<std::unique_ptr<Model>>& models) {
  Scene colored = scene;
  for (std::size_t k = 0; k < colored.instances.size(); ++k) {
    auto model = std::make_unique<Model>(*colored.instances[k].model);
    for (auto& T : model->triangles) {
      T.color = InstanceColor(static_cast<int>(k));
    }
    if constexpr (requires { model->texture; }) {
      model->texture = nullptr;
    }
    if constexpr (requires { model->normal_map; }) {
      model->normal_map = nullptr;
      model->reflective = 0;
    }
    colored.instances[k].model = model.get();
    models.push_back(std::move(model));
  }
  colored.lights = {{}};
  colored.lights[0].intensity = 1;  // the default light is ambient
  return colored;
}

// How many of the pixels more than `margin` pixels from the edge of an instance in the
// cast image, where either image shows something, show that instance in `drawn`, an
// image of InstanceColoredScene.
inline Agreement CompareInstances(const CastImage& cast, const Canvas& drawn, int margin) {
  const LabelImage instances = LabelsOf(cast, [](const CastHit& hit) { return hit.instance; });
  Agreement agreement;
  for (int y = -cast.height / 2; y < cast.height / 2; ++y) {
    for (int x = -cast.width / 2; x < cast.width / 2; ++x) {
      const int shown = InstanceOf(drawn.GetPixel(x, y));
      if ((shown == -1 && instances.At(x, y) == -1) || !instances.Inside(x, y, margin)) {
        continue;
      }
      ++agreement.counted;
      agreement.agreeing += shown == instances.At(x, y);
    }
  }
  return agreement;
}
// The face of a cube (two triangles each, in the cube model's order) a cast ray hit, as
// one number per face of every instance; -1 for nothing.
inline int CubeFaceOf(const CastHit& hit) {
  return hit.instance < 0 ? -1 : hit.instance * 6 + hit.triangle / 2;
}

// Prints an agreement as a test's context.
inline std::string Describe(const Agreement& agreement) {
  return std::to_string(agreement.agreeing) + " of " + std::to_string(agreement.counted) +
         " pixels agree (" + std::to_string(100 * agreement.Fraction()) + " %)";
}

}  // namespace cgfs::test
