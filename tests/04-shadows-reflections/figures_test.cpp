// The chapter's figures, pixel by pixel and as whole images.
#include <catch2/catch.hpp>

#include "golden.h"
#include "printing.h"
#include "scenes.h"

using cgfs::Rgb8;
using cgfs::test::CheckAgainstGolden;
using cgfs::test::RenderFigureNamed;

TEST_CASE("pinned pixels of the shadows figure", "[figures]") {
  const Canvas canvas = RenderFigureNamed(Figures(), "fig-4-4-shadows");
  // On the green sphere, both the point and the directional light are hidden by the
  // red sphere: ambient only, 255 * 0.2. Without shadows (chapter 3) it was (0, 117, 0).
  CHECK(canvas.GetPixel(-200, -100) == Rgb8{0, 51, 0});
  // With epsilon, a lit point keeps its chapter 3 colour.
  CHECK(canvas.GetPixel(0, -150) == Rgb8{171, 0, 0});
  CHECK(canvas.GetPixel(0, 100) == Rgb8{255, 255, 255});
}

TEST_CASE("without epsilon, points shadow themselves: the acne only darkens", "[figures]") {
  const cgfs::Image shadows = RenderFigureNamed(Figures(), "fig-4-4-shadows").GetImage();
  const cgfs::Image acne = RenderFigureNamed(Figures(), "shadow-acne").GetImage();
  long differing = 0;
  long brighter = 0;
  for (int row = 0; row < shadows.Height(); ++row) {
    for (int column = 0; column < shadows.Width(); ++column) {
      const Rgb8 clean = shadows.At(column, row);
      const Rgb8 speckled = acne.At(column, row);
      differing += clean != speckled;
      brighter += speckled.r > clean.r || speckled.g > clean.g || speckled.b > clean.b;
    }
  }
  CHECK(differing > 20000);  // many speckles, everywhere a light reaches
  CHECK(brighter == 0);
}

TEST_CASE("pinned pixels of the reflections figure, recursion depth 3", "[figures]") {
  const Canvas canvas = RenderFigureNamed(Figures(), "fig-4-8-reflections");
  CHECK(canvas.GetPixel(0, -150) == Rgb8{137, 0, 0});
  CHECK(canvas.GetPixel(-250, 0) == Rgb8{0, 178, 0});
  CHECK(canvas.GetPixel(250, 0) == Rgb8{0, 0, 99});
  CHECK(canvas.GetPixel(100, -250) == Rgb8{165, 20, 0});
  CHECK(canvas.GetPixel(-200, -100) == Rgb8{17, 48, 0});
  CHECK(canvas.GetPixel(-300, -300) == Rgb8{96, 145, 0});
  CHECK(canvas.GetPixel(0, 100) == Rgb8{0, 0, 0});
}

TEST_CASE("pinned pixels at recursion depth 0: shadows only, on black", "[figures]") {
  const Canvas canvas = RenderFigureNamed(Figures(), "recursion-depth-0");
  CHECK(canvas.GetPixel(-250, 0) == Rgb8{0, 255, 0});
  CHECK(canvas.GetPixel(-200, -100) == Rgb8{0, 51, 0});
  CHECK(canvas.GetPixel(0, -150) == Rgb8{171, 0, 0});
  CHECK(canvas.GetPixel(0, 100) == Rgb8{0, 0, 0});
}

TEST_CASE("depth 1 and depth 3 differ only where a reflection shows another sphere", "[figures]") {
  // A pixel can change with a deeper limit only if its ray hits a reflective
  // sphere and the mirrored ray from there hits a sphere too (a second bounce exists).
  const Scene scene = SceneReflections();
  const Canvas depth1 = RenderFigureNamed(Figures(), "fig-4-6-recursion-depth-1");
  const Canvas depth3 = RenderFigureNamed(Figures(), "fig-4-8-reflections");
  long differing = 0;
  long unexplained = 0;
  for (int x = -300; x < 300; ++x) {
    for (int y = -300; y < 300; ++y) {
      if (depth1.GetPixel(x, y) == depth3.GetPixel(x, y)) {
        continue;
      }
      ++differing;
      const Vec3 D = CanvasToViewport(x, y, depth1, scene.viewport);
      const auto [sphere, t] = ClosestIntersection({0, 0, 0}, D, 1, cgfs::kInf, scene);
      if (sphere == nullptr || sphere->reflective <= 0) {
        ++unexplained;
        continue;
      }
      const Vec3 P = t * D;
      const Vec3 R = ReflectRay(-D, glm::normalize(P - sphere->center));
      const auto [second, t2] = ClosestIntersection(P, R, scene.epsilon, cgfs::kInf, scene);
      unexplained += second == nullptr;
    }
  }
  CHECK(unexplained == 0);
  CHECK(differing > 1000);  // and they do differ: reflections of reflections
}

TEST_CASE("the book's layout moves blue to the upper left", "[figures]") {
  const Canvas demo = RenderFigureNamed(Figures(), "fig-4-8-reflections");
  const Canvas book = RenderFigureNamed(Figures(), "fig-4-8-reflections-book-layout");
  CHECK(demo.GetPixel(-250, 150) == Rgb8{0, 0, 0});
  const Rgb8 blue = book.GetPixel(-250, 150);
  CHECK(blue.b > 100);
  CHECK(blue.r < blue.b);
  CHECK(blue.g < blue.b);
}

TEST_CASE("five bounces change only pixels that three bounces already reflect", "[figures]") {
  const Canvas depth3 = RenderFigureNamed(Figures(), "fig-4-8-reflections");
  const Canvas depth5 = RenderFigureNamed(Figures(), "recursion-depth-5");
  const Canvas depth0 = RenderFigureNamed(Figures(), "recursion-depth-0");
  long differing = 0;
  for (int x = -300; x < 300; ++x) {
    for (int y = -300; y < 300; ++y) {
      if (depth3.GetPixel(x, y) != depth5.GetPixel(x, y)) {
        ++differing;
        CHECK(depth0.GetPixel(x, y) != depth3.GetPixel(x, y));  // a reflective pixel
      }
    }
  }
  CHECK(differing > 0);
}

TEST_CASE("fig-4-4-shadows matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures(), "fig-4-4-shadows");
}

TEST_CASE("shadow-acne matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures(), "shadow-acne");
}

TEST_CASE("fig-4-8-reflections matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures(), "fig-4-8-reflections");
}

TEST_CASE("fig-4-6-recursion-depth-1 matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures(), "fig-4-6-recursion-depth-1");
}

TEST_CASE("recursion-depth-0 matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures(), "recursion-depth-0");
}

TEST_CASE("recursion-depth-5 matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures(), "recursion-depth-5");
}

TEST_CASE("fig-4-8-reflections-book-layout matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures(), "fig-4-8-reflections-book-layout");
}
