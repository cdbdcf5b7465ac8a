// The chapter's figures, pixel by pixel and as whole images.
#include <catch2/catch.hpp>

#include "golden.h"
#include "painters_algorithm.h"
#include "pixels.h"
#include "printing.h"
#include "scenes.h"

using cgfs::Rgb8;
using cgfs::test::ChangedPixels;
using cgfs::test::CheckAgainstGolden;
using cgfs::test::IsSameImageAs;
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

constexpr Rgb8 kSquareRed8{255, 0, 0};
constexpr Rgb8 kSquareBlue8{0, 0, 255};
constexpr Rgb8 kNoSquare8{255, 255, 255};

// A square facing the camera, 2 wide, centred on (x, y, z), as two triangles.
void AddSquare(Model& model, double x, double y, double z, const Color& color) {
  const int first = static_cast<int>(model.vertices.size());
  model.vertices.insert(
      model.vertices.end(),
      {{x - 1, y + 1, z}, {x + 1, y + 1, z}, {x + 1, y - 1, z}, {x - 1, y - 1, z}});
  model.triangles.push_back({{first, first + 1, first + 2}, color});
  model.triangles.push_back({{first, first + 2, first + 3}, color});
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

TEST_CASE("an open box is not culled, and culled as if it were closed its inside is gone",
          "[figures]") {
  const Canvas open = RenderFigureNamed(Figures(), "open-box");
  const Canvas culled = RenderFigureNamed(Figures(), "open-box-culled");
  CHECK(open.GetPixel(0, -100) == Rgb8{255, 0, 0});  // the inside of the far face
  CHECK(open.GetPixel(30, -80) == Rgb8{0, 255, 0});  // the inside of a side face
  CHECK(culled.GetPixel(0, -100) == kBackground8);
  CHECK(culled.GetPixel(30, -80) == kBackground8);
}

TEST_CASE("two overlapping squares drawn in either order: the nearer one shows", "[depth]") {
  // A red square at z = 5 (pixels -120..120) and a blue one at z = 10 (30..150).
  for (const bool red_first : {true, false}) {
    Model squares;
    squares.closed = false;
    if (red_first) {
      AddSquare(squares, 0, 0, 5, cgfs::kRed);
      AddSquare(squares, 1.5, 1.5, 10, cgfs::kBlue);
    } else {
      AddSquare(squares, 1.5, 1.5, 10, cgfs::kBlue);
      AddSquare(squares, 0, 0, 5, cgfs::kRed);
    }
    Scene scene;
    scene.instances = {{&squares, {}}};
    Canvas canvas(600, 600);
    RenderScene(scene, canvas);
    INFO((red_first ? "red first" : "blue first"));
    CHECK(canvas.GetPixel(80, 80) == kSquareRed8);     // both squares: the red, nearer one
    CHECK(canvas.GetPixel(-40, -40) == kSquareRed8);   // the red one only
    CHECK(canvas.GetPixel(135, 135) == kSquareBlue8);  // the blue one only
    CHECK(canvas.GetPixel(-150, 150) == kNoSquare8);   // neither
  }
}

TEST_CASE("the painter draws squares at different depths as the depth buffer does", "[painter]") {
  const Canvas painter = RenderFigureNamed(Figures(), "painters-algorithm");
  Canvas depth(600, 600);
  RenderScene(SceneOverlappingSquares(), depth, {.cull_back_faces = false});
  CHECK_THAT(painter.GetImage(), IsSameImageAs(depth.GetImage()));
  // In model order the far squares paint over the near ones.
  const Canvas model_order = RenderFigureNamed(Figures(), "overlapping-squares-model-order");
  CHECK(ChangedPixels(model_order, painter).size() > 1000);
}

TEST_CASE("Figure 12-2's cycle: the painter gets one crossing wrong, the depth buffer none",
          "[painter]") {
  const Canvas painter = RenderFigureNamed(Figures(), "cyclic-overlap-painters");
  const Canvas depth = RenderFigureNamed(Figures(), "cyclic-overlap-depth-buffer");
  CHECK(!ChangedPixels(painter, depth).empty());
  // Near the top, the red triangle's wide end crosses the blue one's tip.
  CHECK(depth.GetPixel(-3, 124) == Rgb8{255, 0, 0});
  CHECK(painter.GetPixel(-3, 124) == Rgb8{0, 0, 255});
}

TEST_CASE("triangles passing through each other: the painter draws one over the other",
          "[painter]") {
  const Canvas painter = RenderFigureNamed(Figures(), "intersecting-painters");
  const Canvas depth = RenderFigureNamed(Figures(), "intersecting-depth-buffer");
  CHECK(!ChangedPixels(painter, depth).empty());
  // Left of where they cross the blue triangle is in front, right of it the red one.
  CHECK(depth.GetPixel(-49, 15) == Rgb8{0, 0, 255});
  CHECK(depth.GetPixel(60, -20) == Rgb8{255, 0, 0});
  CHECK(painter.GetPixel(-49, 15) == Rgb8{255, 0, 0});
  CHECK(painter.GetPixel(60, -20) == Rgb8{255, 0, 0});
}

TEST_CASE("on Figure 10-10's cubes the centroid puts a hidden bottom over a side", "[painter]") {
  const Canvas painter = RenderFigureNamed(Figures(), "painters-algorithm-cubes");
  const Canvas depth = RenderFigureNamed(Figures(), "fig-12-4-depth-buffer");
  CHECK(depth.GetPixel(-230, -215) == Rgb8{255, 255, 0});    // instance A's left face
  CHECK(painter.GetPixel(-230, -215) == Rgb8{0, 255, 255});  // its bottom, over it
}

TEST_CASE("fig-12-1-model-order matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures(), "fig-12-1-model-order");
}

TEST_CASE("overlapping-squares-model-order matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures(), "overlapping-squares-model-order");
}

TEST_CASE("painters-algorithm matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures(), "painters-algorithm");
}

TEST_CASE("painters-algorithm-cubes matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures(), "painters-algorithm-cubes");
}

TEST_CASE("fig-12-4-depth-buffer matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures(), "fig-12-4-depth-buffer");
}

TEST_CASE("back-face-culling matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures(), "back-face-culling");
}

TEST_CASE("outlines matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures(), "outlines");
}

TEST_CASE("crossing-planes-depth-z matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures(), "crossing-planes-depth-z");
}

TEST_CASE("crossing-planes-depth-inverse-z matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures(), "crossing-planes-depth-inverse-z");
}

TEST_CASE("cyclic-overlap-painters matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures(), "cyclic-overlap-painters");
}

TEST_CASE("cyclic-overlap-depth-buffer matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures(), "cyclic-overlap-depth-buffer");
}

TEST_CASE("intersecting-painters matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures(), "intersecting-painters");
}

TEST_CASE("intersecting-depth-buffer matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures(), "intersecting-depth-buffer");
}

TEST_CASE("open-box matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures(), "open-box");
}

TEST_CASE("open-box-culled matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures(), "open-box-culled");
}

TEST_CASE("painters-algorithm-cubes-overdraw matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures(), "painters-algorithm-cubes-overdraw");
}

TEST_CASE("fig-12-4-depth-buffer-overdraw matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures(), "fig-12-4-depth-buffer-overdraw");
}

TEST_CASE("back-face-culling-overdraw matches its golden image", "[golden]") {
  CheckAgainstGolden(CGFS_CHAPTER, Figures(), "back-face-culling-overdraw");
}
