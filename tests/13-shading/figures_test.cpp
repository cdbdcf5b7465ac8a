// The chapter's figures, pixel by pixel and as whole images.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdlib>
#include <string>
#include <vector>

#include "golden.h"
#include "printing.h"
#include "scenes.h"

using cgfs::Rgb8;
using cgfs::test::CheckAgainstGolden;
using cgfs::test::RenderFigureNamed;

TEST_CASE("the figures: every shading model x normals x lighting terms, and the book's",
          "[figures]") {
  std::vector<std::string> names;
  for (const cgfs::Figure& figure : Figures()) {
    names.push_back(figure.name);
  }
  CHECK(names.size() == 21);
  for (const char* name :
       {"fig-13-1-flat-triangle-normals-diffuse-specular", "flat-model-normals-specular",
        "fig-13-3-gouraud-triangle-normals-diffuse-specular",
        "fig-13-6-gouraud-model-normals-diffuse-specular", "phong-triangle-normals-diffuse",
        "fig-13-9-phong-model-normals-diffuse-specular", "fig-13-7-close-light-gouraud",
        "fig-13-10-close-light-phong", "fig-13-11-raytracer-spheres"}) {
    CHECK(std::find(names.begin(), names.end(), name) != names.end());
  }
}

TEST_CASE("figure 13-1: the green face's two triangles are lit differently", "[figures]") {
  // Flat shading with a point light: each triangle is lit at its own centroid.
  const Canvas canvas =
      RenderFigureNamed(Figures(), "fig-13-1-flat-triangle-normals-diffuse-specular");
  CHECK(canvas.GetPixel(-35, 210) == Rgb8{0, 144, 0});
  CHECK(canvas.GetPixel(-40, 50) == Rgb8{0, 146, 0});
}

TEST_CASE("the sphere's highlight: sharp with Phong, blurred by Gouraud, lost when flat",
          "[figures]") {
  // At the brightest pixel of the Phong sphere, (196, -137).
  const auto green = [](const char* figure) {
    return int{RenderFigureNamed(Figures(), figure).GetPixel(196, -137).g};
  };
  CHECK(green("fig-13-9-phong-model-normals-diffuse-specular") == 255);
  CHECK(green("fig-13-6-gouraud-model-normals-diffuse-specular") == 255);
  CHECK(green("fig-13-3-gouraud-triangle-normals-diffuse-specular") == 204);
  CHECK(green("fig-13-1-flat-triangle-normals-diffuse-specular") == 204);
}

TEST_CASE("figures 13-7 and 13-10: Gouraud misses the light close to the face, Phong finds it",
          "[figures]") {
  const Canvas gouraud = RenderFigureNamed(Figures(), "fig-13-7-close-light-gouraud");
  const Canvas phong = RenderFigureNamed(Figures(), "fig-13-10-close-light-phong");
  CHECK(gouraud.GetPixel(-150, 0) == Rgb8{0, 170, 0});
  CHECK(phong.GetPixel(-150, 0) == Rgb8{0, 255, 0});
  CHECK(phong.GetPixel(270, 0) == Rgb8{51, 51, 0});  // the marker: ambient light only
}

TEST_CASE("figure 13-11 agrees with the ray tracer's Figure 3-16 where it is pinned", "[figures]") {
  // Chapter 3's pinned pixels (docs of 03-light). The spheres here are 420 flat
  // triangles each, so their normals, and the light, are a little off.
  const Canvas canvas = RenderFigureNamed(Figures(), "fig-13-11-raytracer-spheres");
  const struct {
    int x, y;
    Rgb8 ray_traced;
  } pinned[] = {{0, -150, {171, 0, 0}},      {-250, 0, {0, 255, 0}},   {250, 0, {0, 0, 141}},
                {-300, -300, {161, 161, 0}}, {100, -250, {181, 0, 0}}, {-200, -100, {0, 117, 0}},
                {0, 0, {127, 0, 0}},         {0, 100, {255, 255, 255}}};
  for (const auto& [x, y, ray_traced] : pinned) {
    const Rgb8 rasterized = canvas.GetPixel(x, y);
    INFO("(" << x << ", " << y << "): " << Catch::Detail::stringify(rasterized) << " against "
             << Catch::Detail::stringify(ray_traced));
    CHECK(std::abs(rasterized.r - ray_traced.r) <= 8);
    CHECK(std::abs(rasterized.g - ray_traced.g) <= 8);
    CHECK(std::abs(rasterized.b - ray_traced.b) <= 8);
  }
}

TEST_CASE("flat-triangle-normals-diffuse matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures(), "flat-triangle-normals-diffuse");
}

TEST_CASE("flat-triangle-normals-specular matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures(), "flat-triangle-normals-specular");
}

TEST_CASE("fig-13-1-flat-triangle-normals-diffuse-specular matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures(), "fig-13-1-flat-triangle-normals-diffuse-specular");
}

TEST_CASE("flat-model-normals-diffuse matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures(), "flat-model-normals-diffuse");
}

TEST_CASE("flat-model-normals-specular matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures(), "flat-model-normals-specular");
}

TEST_CASE("flat-model-normals-diffuse-specular matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures(), "flat-model-normals-diffuse-specular");
}

TEST_CASE("gouraud-triangle-normals-diffuse matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures(), "gouraud-triangle-normals-diffuse");
}

TEST_CASE("gouraud-triangle-normals-specular matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures(), "gouraud-triangle-normals-specular");
}

TEST_CASE("fig-13-3-gouraud-triangle-normals-diffuse-specular matches its golden image",
          "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures(), "fig-13-3-gouraud-triangle-normals-diffuse-specular");
}

TEST_CASE("gouraud-model-normals-diffuse matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures(), "gouraud-model-normals-diffuse");
}

TEST_CASE("gouraud-model-normals-specular matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures(), "gouraud-model-normals-specular");
}

TEST_CASE("fig-13-6-gouraud-model-normals-diffuse-specular matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures(), "fig-13-6-gouraud-model-normals-diffuse-specular");
}

TEST_CASE("phong-triangle-normals-diffuse matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures(), "phong-triangle-normals-diffuse");
}

TEST_CASE("phong-triangle-normals-specular matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures(), "phong-triangle-normals-specular");
}

TEST_CASE("phong-triangle-normals-diffuse-specular matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures(), "phong-triangle-normals-diffuse-specular");
}

TEST_CASE("phong-model-normals-diffuse matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures(), "phong-model-normals-diffuse");
}

TEST_CASE("phong-model-normals-specular matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures(), "phong-model-normals-specular");
}

TEST_CASE("fig-13-9-phong-model-normals-diffuse-specular matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures(), "fig-13-9-phong-model-normals-diffuse-specular");
}

TEST_CASE("fig-13-7-close-light-gouraud matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures(), "fig-13-7-close-light-gouraud");
}

TEST_CASE("fig-13-10-close-light-phong matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures(), "fig-13-10-close-light-phong");
}

TEST_CASE("fig-13-11-raytracer-spheres matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures(), "fig-13-11-raytracer-spheres");
}
