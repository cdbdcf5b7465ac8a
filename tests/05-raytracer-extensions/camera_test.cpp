// Listing 5-1: the camera.
#include <catch2/catch.hpp>

#include <thread>

#include <glm/geometric.hpp>

#include "cases.h"
#include "checks.h"
#include "golden.h"
#include "printing.h"
#include "program/image_files.h"
#include "scenes.h"

using cgfs::Rgb8;
using cgfs::test::CheckNear;
using cgfs::test::GoldenFile;
using cgfs::test::IsSameImageAs;
using cgfs::test::RenderFigureNamed;

TEST_CASE("CameraRayDirection: the cases of 05-raytracer-extensions.json", "[equations]") {
  using cgfs::test::ToNumber;
  for (const cgfs::test::FunctionCase& c :
       cgfs::test::CasesOf("05-raytracer-extensions.json", "CameraRayDirection")) {
    INFO(c.Describe());
    const nlohmann::json& size = c.given.at("canvas");
    const nlohmann::json& viewport = c.given.at("viewport");
    const nlohmann::json& camera = c.given.at("camera");
    Scene scene;
    scene.viewport = {ToNumber(viewport.at("width")), ToNumber(viewport.at("height")),
                      ToNumber(viewport.at("d"))};
    scene.camera.position = cgfs::test::ToVector(camera.at("position"));
    for (int row = 0; row < 3; ++row) {  // the case's rows; GLM keeps columns
      for (int column = 0; column < 3; ++column) {
        scene.camera.rotation[column][row] = ToNumber(camera.at("rotation").at(row).at(column));
      }
    }
    const Canvas canvas(size.at("width").get<int>(), size.at("height").get<int>());
    CHECK_THAT(cgfs::test::AsNumbers(CameraRayDirection(ToNumber(c.args.at("x")),
                                                        ToNumber(c.args.at("y")), canvas, scene)),
               cgfs::test::MatchesCase(c));
  }
}

TEST_CASE("pinned pixels of Figure 5-1, the camera at (3, 0, 1) turned 45 degrees", "[figures]") {
  const Canvas canvas = RenderFigureNamed(Figures({}), "fig-5-1-camera");
  CHECK(canvas.GetPixel(0, -150) == Rgb8{90, 4, 9});
  CHECK(canvas.GetPixel(-250, 0) == Rgb8{0, 94, 0});
  CHECK(canvas.GetPixel(250, 0) == Rgb8{0, 0, 135});
  CHECK(canvas.GetPixel(-200, -100) == Rgb8{163, 0, 0});
  CHECK(canvas.GetPixel(100, -250) == Rgb8{68, 68, 0});
  CHECK(canvas.GetPixel(0, 0) == Rgb8{0, 0, 0});
  CHECK(canvas.GetPixel(0, 100) == Rgb8{0, 0, 0});
}

TEST_CASE("RenderScene with the camera at the origin draws chapter 4's Figure 4-8 exactly",
          "[figures]") {
  // Everything the chapter adds (objects behind an interface, the camera, the
  // switches) leaves the old picture as it was, byte for byte.
  Canvas canvas(600, 600);
  RenderScene(SceneReflections(), 3, canvas, AllOptimizations());
  CHECK_THAT(
      canvas.GetImage(),
      IsSameImageAs(cgfs::ReadImage(GoldenFile("04-shadows-reflections", "fig-4-8-reflections"))));
}

TEST_CASE("PrepareScene caches in copies: the scene it was copied from is left as it was",
          "[optimizations]") {
  const Scene scene = SceneCamera();
  Scene prepared = scene;
  PrepareScene(prepared, AllOptimizations());
  REQUIRE(prepared.objects.size() == scene.objects.size());
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    const auto* original = dynamic_cast<const Sphere*>(scene.objects[i].get());
    const auto* copy = dynamic_cast<const Sphere*>(prepared.objects[i].get());
    REQUIRE(original != nullptr);
    REQUIRE(copy != nullptr);
    CHECK(copy != original);
    CHECK(original->cache.camera_CO_dot_CO == 0);  // never written
    const Vec3 CO = prepared.camera.position - copy->center;
    CHECK(copy->cache.camera_CO_dot_CO == glm::dot(CO, CO));
  }
}

TEST_CASE("two renders of one scene from two cameras at once draw what each draws alone",
          "[optimizations]") {
  // They share the scene's objects; each caches the <CO,CO> of its own camera.
  const Scene from_here = SceneCamera();
  Scene from_there = from_here;
  from_there.camera = Camera{};  // the origin, looking down +z
  Optimizations cached;
  cached.cache = true;
  Canvas here_alone(100, 100), there_alone(100, 100), here(100, 100), there(100, 100);
  RenderScene(from_here, 3, here_alone, cached);
  RenderScene(from_there, 3, there_alone, cached);
  std::thread other([&] { RenderScene(from_there, 3, there, cached); });
  RenderScene(from_here, 3, here, cached);
  other.join();
  CHECK_THAT(here.GetImage(), IsSameImageAs(here_alone.GetImage()));
  CHECK_THAT(there.GetImage(), IsSameImageAs(there_alone.GetImage()));
  CHECK_FALSE(here.GetImage() == there.GetImage());
}

TEST_CASE("MovedCamera: along the camera's own axes, then turned left and up", "[equations]") {
  const Camera straight;  // at the origin, looking down +z
  // Turned 90 degrees to the left the camera looks down -x; 90 degrees up, down +y.
  CheckNear(MovedCamera(straight, {{0, 0, 0}, 90, 0}).rotation * Vec3{0, 0, 1}, {-1, 0, 0});
  CheckNear(MovedCamera(straight, {{0, 0, 0}, 0, 90}).rotation * Vec3{0, 0, 1}, {0, 1, 0});
  // Figure 5-1's camera at (3, 0, 1) looks towards the spheres, along (-0.7071, 0, 0.7071);
  // its right is (0.7071, 0, 0.7071): one step forward, or one to the right, goes there.
  const Camera turned = SceneCamera().camera;
  CheckNear(MovedCamera(turned, {{0, 0, 1}, 0, 0}).position, {2.2929, 0, 1.7071}, 1e-4);
  CheckNear(MovedCamera(turned, {{1, 0, 0}, 0, 0}).position, {3.7071, 0, 1.7071}, 1e-4);
  // No view, no move.
  CheckNear(MovedCamera(turned, {}).position, turned.position);
}
