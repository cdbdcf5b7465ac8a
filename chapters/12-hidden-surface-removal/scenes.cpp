#include "scenes.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "program/cost_view.h"

// "Representing a Cube" (Figure 10-1): vertices A..H are 0..7.
const Model& CubeModel() {
  static const Model cube{
      {
          {1, 1, 1},
          {-1, 1, 1},
          {-1, -1, 1},
          {1, -1, 1},
          {1, 1, -1},
          {-1, 1, -1},
          {-1, -1, -1},
          {1, -1, -1},
      },
      {
          {{0, 1, 2}, cgfs::kRed},
          {{0, 2, 3}, cgfs::kRed},  // z = +1
          {{4, 0, 3}, cgfs::kGreen},
          {{4, 3, 7}, cgfs::kGreen},  // x = +1
          {{5, 4, 7}, cgfs::kBlue},
          {{5, 7, 6}, cgfs::kBlue},  // z = -1
          {{1, 5, 6}, cgfs::kYellow},
          {{1, 6, 2}, cgfs::kYellow},  // x = -1
          {{4, 5, 1}, cgfs::kPurple},
          {{4, 1, 0}, cgfs::kPurple},  // y = +1
          {{2, 6, 7}, cgfs::kCyan},
          {{2, 7, 3}, cgfs::kCyan},  // y = -1
      },
  };
  return cube;
}

// "Back Face Culling", Figure 12-10: a cube with one face taken away is not closed.
const Model& OpenBoxModel() {
  static const Model box = [] {
    Model open = CubeModel();
    std::erase_if(open.triangles, [](const Triangle& T) { return T.color == cgfs::kBlue; });
    open.closed = false;
    return open;
  }();
  return box;
}

// Figure 10-10: the instances scaled and rotated, seen from a camera moved back
// and to the left and turned 30 degrees to the right. Also the scene of
// chapters 11 to 14.
Scene SceneTransformedCubes() {
  Scene scene;
  scene.camera = {{-3, 1, 2}, MakeOYRotationMatrix(-30)};
  scene.instances = {
      {&CubeModel(), {0.75, glm::dmat4(1.0), {-1.5, 0, 7}}},
      {&CubeModel(), {1, MakeOYRotationMatrix(195), {1.25, 2.5, 7.5}}},
  };
  return scene;
}

// "Painter's Algorithm": four squares one behind the other, each partly hiding the
// next, listed nearest first, so that drawn in model order each is painted over by
// the one behind it.
Scene SceneOverlappingSquares() {
  static const Model squares = [] {
    Model model;
    model.closed = false;
    const Color colors[4] = {cgfs::kRed, cgfs::kGreen, cgfs::kBlue, cgfs::kYellow};
    for (int k = 0; k < 4; ++k) {
      const Vec3 center(-1.0 + 0.8 * k, -0.6 + 0.4 * k, 4 + k);
      const int first = static_cast<int>(model.vertices.size());
      for (const glm::dvec2 corner :
           {glm::dvec2(-1, 1), glm::dvec2(1, 1), glm::dvec2(1, -1), glm::dvec2(-1, -1)}) {
        model.vertices.push_back(center + Vec3(0.8 * corner, 0));
      }
      model.triangles.push_back({{first, first + 1, first + 2}, colors[k]});
      model.triangles.push_back({{first, first + 2, first + 3}, colors[k]});
    }
    return model;
  }();
  Scene scene;
  scene.instances = {{&squares, {}}};
  return scene;
}

// Figure 12-2: three thin triangles around the centre. Each is near the camera
// (z = 4) at its wide end and far (z = 6) at its tip, and its tip crosses the wide
// end of the next one, so each lies over the previous one: 1 over 0, 2 over 1, and
// 0 over 2. Their centroids are all at z = 14/3: the painter keeps the list order.
Scene SceneCyclicOverlap() {
  static const Model triangles = [] {
    Model model;
    model.closed = false;
    const Color colors[3] = {cgfs::kRed, cgfs::kGreen, cgfs::kBlue};
    for (int k = 0; k < 3; ++k) {
      // The corners of an equilateral triangle of radius 1.6 around the view axis.
      const auto corner = [](int i) {
        const double angle = (90.0 + 120.0 * i) * std::numbers::pi / 180;
        return glm::dvec2(std::cos(angle), std::sin(angle)) * 1.1;
      };
      const glm::dvec2 from = corner(k);
      const glm::dvec2 to = corner(k + 1);
      const glm::dvec2 along = to - from;
      const glm::dvec2 across = glm::normalize(glm::dvec2(-along.y, along.x)) * 0.4;
      const glm::dvec2 wide_end = from - 0.3 * along;
      const glm::dvec2 tip = to + 0.5 * along;
      const int first = static_cast<int>(model.vertices.size());
      model.vertices.push_back({wide_end + across, 4});
      model.vertices.push_back({wide_end - across, 4});
      model.vertices.push_back({tip, 6});
      model.triangles.push_back({{first, first + 1, first + 2}, colors[k]});
    }
    return model;
  }();
  Scene scene;
  scene.instances = {{&triangles, {}}};
  return scene;
}

// A red triangle facing the camera at z = 5 and a blue one tilted through it, near
// (z = 3.5) on the left and far (z = 6.5) on the right: blue is in front left of
// x = 0 and behind right of it. The painter draws one wholly over the other.
Scene SceneIntersectingTriangles() {
  static const Model triangles{
      {{-2, -1.4, 5}, {0, 1.8, 5}, {2, -1.4, 5}, {-2, 0.6, 3.5}, {2, 1.2, 6.5}, {1.6, -1.8, 6.2}},
      {{{0, 1, 2}, cgfs::kRed}, {{3, 4, 5}, cgfs::kBlue}},
      false,
  };
  Scene scene;
  scene.instances = {{&triangles, {}}};
  return scene;
}

// A red floor at y = -1 from z = 2 to z = 40, and a shorter blue ramp from z = 5 to
// z = 12 rising 0.3 per unit of depth through it: under the floor before z = 8,
// over it beyond. Each is a quad of two triangles. The two quads have different
// depths at their corners, so interpolating z (instead of 1/z) errs differently on
// each, and the crossing moves.
Scene SceneCrossingPlanes() {
  static const Model planes{
      {
          {-3, -1, 2},
          {3, -1, 2},
          {3, -1, 40},
          {-3, -1, 40},
          {-1.5, -1 - 0.3 * 3, 5},
          {1.5, -1 - 0.3 * 3, 5},
          {1.5, -1 + 0.3 * 4, 12},
          {-1.5, -1 + 0.3 * 4, 12},
      },
      {
          {{0, 3, 2}, cgfs::kRed},
          {{0, 2, 1}, cgfs::kRed},
          {{4, 7, 6}, cgfs::kBlue},
          {{4, 6, 5}, cgfs::kBlue},
      },
      false,
  };
  Scene scene;
  scene.instances = {{&planes, {}}};
  return scene;
}

// The box's opening (its missing z = -1 face) faces the camera, turned 30 degrees;
// the camera is above the box, so it sees the top from outside and, through the
// opening, the inside of the far, side and bottom faces, whose outsides face away.
Scene SceneOpenBox() {
  Scene scene;
  scene.instances = {{&OpenBoxModel(), {1, MakeOYRotationMatrix(30), {0, -1.5, 7}}}};
  return scene;
}

Scene SceneOpenBoxSaidClosed() {
  static const Model box_said_closed = [] {
    Model model = OpenBoxModel();
    model.closed = true;
    return model;
  }();
  Scene scene = SceneOpenBox();
  scene.instances[0].model = &box_said_closed;
  return scene;
}

Scene SceneModel(const Model& model) {
  Vec3 low = model.vertices.front();
  Vec3 high = low;
  for (const Vec3& vertex : model.vertices) {
    low = glm::min(low, vertex);
    high = glm::max(high, vertex);
  }
  const Vec3 centre = (low + high) / 2.0;
  double radius = 0;
  for (const Vec3& vertex : model.vertices) {
    radius = std::max(radius, glm::length(vertex - centre));
  }
  Scene scene;
  scene.instances = {{&model, {1 / radius, glm::dmat4(1.0), Vec3(0, 0, 3) - centre / radius}}};
  return scene;
}

namespace {

// A figure of a scene, drawn by RenderScene with `method`, whose camera --window and
// --view can move.
cgfs::Figure SceneFigure(const std::string& name, const std::string& caption,
                         std::function<Scene()> scene, const HiddenSurfaceRemoval& method) {
  return {name, caption, [scene, method](Canvas& canvas) { RenderScene(scene(), canvas, method); },
          [scene, method](Canvas& canvas, const cgfs::View& view) {
            Scene moved = scene();
            moved.camera = MovedCamera(moved.camera, view);
            RenderScene(moved, canvas, method);
          }};
}

// The overdraw of a figure: how many times RenderScene with `method` writes each
// pixel (the canvas's PutPixel calls, cgfs/tally.h), drawn through the cost ramp from 0
// to `scale_max` (program/cost_view.h); the cost view of the figure named `figure`.
cgfs::Figure OverdrawFigure(const std::string& figure, const std::string& caption,
                            std::function<Scene()> scene, const HiddenSurfaceRemoval& method,
                            cgfs::Count scale_max) {
  const cgfs::CostView cost;
  const auto draw = [method, scale_max, cost](const Scene& drawn, Canvas& canvas) {
    std::vector<cgfs::Count> writes;
    {
      const cgfs::Tallying tallying(cgfs::kPixelsPut, canvas.Width(), canvas.Height());
      RenderScene(drawn, canvas, method);
      writes = tallying.PerPixel();
    }
    cost.Draw(canvas, writes, scale_max);
  };
  cgfs::Figure overdraw{figure + "-overdraw", caption,
                        [scene, draw](Canvas& canvas) { draw(scene(), canvas); },
                        [scene, draw](Canvas& canvas, const cgfs::View& view) {
                          Scene moved = scene();
                          moved.camera = MovedCamera(moved.camera, view);
                          draw(moved, canvas);
                        }};
  overdraw.measured = cost.Measured();
  return overdraw;
}

// The reader's model with the depth buffer (back faces culled if it is closed), and
// with its triangles' edges outlined.
std::vector<cgfs::Figure> ModelFigures(const ChapterSettings& settings) {
  const std::shared_ptr<const Model> model = settings.model;
  const std::string about = settings.model_name + ", " + std::to_string(model->triangles.size()) +
                            " triangles, " +
                            (model->closed ? "closed: back faces culled" : "not closed");
  const std::function<Scene()> scene = [model] { return SceneModel(*model); };
  return {SceneFigure("model", about + ", the depth buffer", scene, {}),
          SceneFigure("model-outlines", about + ", each triangle's edges outlined", scene,
                      {.outlines = true})};
}

}  // namespace

std::vector<cgfs::Figure> Figures(const ChapterSettings& settings) {
  if (settings.model) {
    return ModelFigures(settings);
  }
  const HiddenSurfaceRemoval model_order{.draw_order = DrawOrder::kModelOrder,
                                         .cull_back_faces = false};
  const HiddenSurfaceRemoval painters{.draw_order = DrawOrder::kPaintersAlgorithm,
                                      .cull_back_faces = false};
  const HiddenSurfaceRemoval depth_z{.depth_value = DepthValue::kZ, .cull_back_faces = false};
  const HiddenSurfaceRemoval depth{.cull_back_faces = false};
  const HiddenSurfaceRemoval culled{};
  const HiddenSurfaceRemoval outlines{.outlines = true};
  // One scale for the three overdraw views, so that they compare at a glance.
  constexpr cgfs::Count kOverdrawScale = 5;
  std::vector<cgfs::Figure> figures = {
      SceneFigure("fig-12-1-model-order",
                  "Figure 10-10's cubes filled, in model order: back faces paint over front faces",
                  SceneTransformedCubes, model_order),
      SceneFigure(
          "overlapping-squares-model-order",
          "four squares listed nearest first and drawn in that order: each far one paints over",
          SceneOverlappingSquares, model_order),
      SceneFigure("painters-algorithm",
                  "the same squares drawn back to front by the painter's algorithm",
                  SceneOverlappingSquares, painters),
      SceneFigure(
          "painters-algorithm-cubes",
          "Figure 10-10's cubes by the painter: a hidden bottom face sorts in front of a side",
          SceneTransformedCubes, painters),
      SceneFigure("fig-12-4-depth-buffer", "the same cubes with the 1/z depth buffer",
                  SceneTransformedCubes, depth),
      SceneFigure(
          "back-face-culling",
          "the depth buffer with back faces culled: the same picture from half the triangles",
          SceneTransformedCubes, culled),
      SceneFigure("outlines",
                  "the culled, depth-buffered cubes with each triangle's edges outlined",
                  SceneTransformedCubes, outlines),
      SceneFigure(
          "crossing-planes-depth-z",
          "a floor and a ramp crossing far away, depth-buffered with z: the crossing is wrong",
          SceneCrossingPlanes, depth_z),
      SceneFigure("crossing-planes-depth-inverse-z",
                  "the floor and the ramp depth-buffered with 1/z: a straight crossing",
                  SceneCrossingPlanes, depth),
      SceneFigure(
          "cyclic-overlap-painters",
          "Figure 12-2, three triangles over one another in a cycle: the painter gets one wrong",
          SceneCyclicOverlap, painters),
      SceneFigure("cyclic-overlap-depth-buffer", "the same three triangles with the depth buffer",
                  SceneCyclicOverlap, depth),
      SceneFigure("intersecting-painters",
                  "two triangles passing through each other: the painter draws one over the other",
                  SceneIntersectingTriangles, painters),
      SceneFigure("intersecting-depth-buffer", "the same two triangles with the depth buffer",
                  SceneIntersectingTriangles, depth),
      SceneFigure("open-box", "an open box: not closed, so nothing is culled and its inside shows",
                  SceneOpenBox, culled),
      SceneFigure("open-box-culled",
                  "the open box culled as if it were closed: its inside faces are missing",
                  SceneOpenBoxSaidClosed, culled),
      OverdrawFigure("painters-algorithm-cubes",
                     "the painter's overdraw, pixels written per pixel on a scale to 5",
                     SceneTransformedCubes, painters, kOverdrawScale),
      OverdrawFigure("fig-12-4-depth-buffer", "the depth buffer's overdraw", SceneTransformedCubes,
                     depth, kOverdrawScale),
      OverdrawFigure("back-face-culling", "the overdraw with back faces culled",
                     SceneTransformedCubes, culled, kOverdrawScale),
  };
  for (const char* name :
       {"painters-algorithm-cubes", "fig-12-4-depth-buffer", "back-face-culling"}) {
    cgfs::SetCostView(figures, name, std::string(name) + "-overdraw");
  }
  return figures;
}
