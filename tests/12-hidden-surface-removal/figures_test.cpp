// The chapter's figures, pixel by pixel and as whole images.
#include <catch2/catch.hpp>

#include "golden.h"
#include "pixels.h"
#include "printing.h"
#include "scenes.h"

using cgfs::Rgb8;
using cgfs::test::ChangedPixels;
using cgfs::test::CheckAgainstGolden;
using cgfs::test::RenderFigureNamed;

namespace {

constexpr Rgb8 kBackground8{255, 255, 255};

// True if a pixel next to (x, y) has another colour: (x, y) is on an edge.
bool OnAnEdge(const Canvas& canvas, int x, int y) {
  for (const auto& [dx, dy] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
    if (canvas.ToScreen(x + dx, y + dy) &&
        canvas.GetPixel(x + dx, y + dy) != canvas.GetPixel(x, y)) {
      return true;
    }
  }
  return false;
}

}  // namespace

TEST_CASE("figure 12-1: in model order the back faces paint over the front", "[figures]") {
  const Canvas model_order = RenderFigureNamed(Figures(), "fig-12-1-model-order");
  const Canvas depth = RenderFigureNamed(Figures(), "fig-12-4-depth-buffer");
  // Instance B's red front face is painted over by its yellow back face.
  CHECK(depth.GetPixel(150, 150) == Rgb8{255, 0, 0});
  CHECK(model_order.GetPixel(150, 150) == Rgb8{255, 255, 0});
  CHECK(model_order.GetPixel(0, 0) == kBackground8);
}

TEST_CASE("RenderInstance, filled, draws what RenderScene draws in model order", "[render]") {
  // Listing 10-3 with DrawFilledTriangle is Figure 12-1's method, when nothing is clipped.
  const Scene scene = SceneTwoCubes();
  Canvas by_instance(600, 600);
  for (const Instance& I : scene.instances) {
    RenderInstance(I, by_instance, scene.viewport);
  }
  Canvas by_scene(600, 600);
  RenderScene(scene, by_scene, {.draw_order = DrawOrder::kModelOrder, .cull_back_faces = false});
  CHECK(by_instance.GetImage() == by_scene.GetImage());
}

TEST_CASE("culling the back faces changes nothing but a few pixels on silhouettes", "[figures]") {
  // Where a back face meets a front face along a silhouette, rounding gives the back
  // face a pixel here and there; culled, it cannot.
  const Canvas culled = RenderFigureNamed(Figures(), "back-face-culling");
  const Canvas depth = RenderFigureNamed(Figures(), "fig-12-4-depth-buffer");
  const std::set<std::pair<int, int>> changed = ChangedPixels(culled, depth);
  int off_edges = 0;
  for (const auto& [x, y] : changed) {
    off_edges += !OnAnEdge(culled, x, y);
  }
  CHECK(changed.size() < 600);  // of 360 000
  CHECK(off_edges == 0);
}

TEST_CASE("outlines: each triangle's edges in 0.75 x its colour", "[figures]") {
  const Canvas canvas = RenderFigureNamed(Figures(), "outlines");
  const Canvas plain = RenderFigureNamed(Figures(), "back-face-culling");
  // Instance B's vertex 0, the top of the edge between its red and green faces.
  CHECK(plain.GetPixel(102, 274) != kBackground8);
  const Rgb8 corner = canvas.GetPixel(102, 274);
  CHECK((corner == Rgb8{191, 0, 0} || corner == Rgb8{0, 191, 0}));
  CHECK(canvas.GetPixel(150, 150) == Rgb8{255, 0, 0});  // inside a face: the face's colour
}

TEST_CASE("z in the depth buffer shows the ramp where it is under the floor", "[figures]") {
  const Canvas z = RenderFigureNamed(Figures(), "crossing-planes-depth-z");
  const Canvas inverse_z = RenderFigureNamed(Figures(), "crossing-planes-depth-inverse-z");
  // (0, -100) shows the floor at z = 6, where the ramp is 0.6 below it.
  CHECK(inverse_z.GetPixel(0, -100) == Rgb8{255, 0, 0});
  CHECK(z.GetPixel(0, -100) == Rgb8{0, 0, 255});
  // (0, -60) shows the floor at z = 10, where the ramp is 0.6 above it: both agree.
  CHECK(inverse_z.GetPixel(0, -60) == Rgb8{0, 0, 255});
  CHECK(z.GetPixel(0, -60) == Rgb8{0, 0, 255});
  // The true crossing is the row of z = 8 on the floor, y = -1/8 of the viewport.
  CHECK(inverse_z.GetPixel(0, -77) == Rgb8{255, 0, 0});
  CHECK(inverse_z.GetPixel(0, -73) == Rgb8{0, 0, 255});
}

TEST_CASE("an open box is not culled; culled as if closed, its inside is gone", "[figures]") {
  const Canvas open = RenderFigureNamed(Figures(), "open-box");
  const Canvas culled = RenderFigureNamed(Figures(), "open-box-culled");
  CHECK(open.GetPixel(0, -100) == Rgb8{255, 0, 0});  // the inside of the far face
  CHECK(open.GetPixel(30, -80) == Rgb8{0, 255, 0});  // the inside of a side face
  CHECK(culled.GetPixel(0, -100) == kBackground8);
  CHECK(culled.GetPixel(30, -80) == kBackground8);
}

TEST_CASE("every figure matches its golden image", "[golden]") {
  for (const cgfs::Figure& figure : Figures()) {
    DYNAMIC_SECTION(figure.name) {
      CheckAgainstGolden(CGFS_CHAPTER, Figures(), figure.name);
    }
  }
}
