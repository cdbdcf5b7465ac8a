// The cost views (cost.h): their counts against counts made another way, and what they
// draw and say of them (their golden images: figures_test.cpp).
#include <catch2/catch.hpp>

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include "cost.h"
#include "cost_checks.h"
#include "golden.h"
#include "printing.h"
#include "refraction.h"
#include "sampling.h"
#include "scenes.h"

using cgfs::test::CheckDrawn;
using cgfs::test::FindFigure;
using cgfs::test::Max;
using cgfs::test::Spaced;
using cgfs::test::Total;

TEST_CASE("Spaced writes numbers as the captions do", "[cost]") {
  CHECK(Spaced(7) == "7");
  CHECK(Spaced(1000) == "1 000");
  CHECK(Spaced(3600000000) == "3 600 000 000");
}

TEST_CASE("without the hierarchy every camera ray tests all 10 000 spheres and the ground",
          "[cost]") {
  Optimizations loop;
  const Canvas canvas(600, 600);
  const TestsPerPixel tests = PrimaryRayTests(SceneSphereField(10000), canvas, loop);
  // 10 001 objects (the spheres and the ground) for each of 600 x 600 rays, no boxes.
  CHECK(Total(tests.objects) == 10001L * 600 * 600);
  CHECK(Max(tests.objects) == 10001);
  CHECK(Total(tests.boxes) == 0);
  CheckDrawn(Figures({}), "sphere-field-10000-tests-without-hierarchy", tests.objects, 10001);
}

TEST_CASE("through the hierarchy, the tests per camera ray are those of its own search", "[cost]") {
  Optimizations hierarchy;
  hierarchy.bvh = true;
  hierarchy.threads = 4;  // the pixels drawn by several threads, each counted at its own
  Scene scene = SceneSphereField(10000);
  const Canvas canvas(600, 600);
  const TestsPerPixel tests = PrimaryRayTests(scene, canvas, hierarchy);
  // The same searches made here, ray by ray on this thread, each counted alone.
  PrepareScene(scene, hierarchy);
  REQUIRE(scene.bvh != nullptr);
  const auto tests_of_ray = [&](const cgfs::Counter& counter, int x, int y) {
    const cgfs::Tallying tallying(counter, 0, 0);
    int object = -1;
    scene.bvh->Closest(
        MakeRay(scene.camera.position, CameraRayDirection(x, y, canvas, scene), scene), 1,
        cgfs::kInf, object);
    return tallying.Total();
  };
  std::vector<cgfs::Count> boxes(600 * 600), objects(600 * 600), both(600 * 600);
  for (int x = -300; x < 300; ++x) {
    for (int y = -300; y < 300; ++y) {
      const std::size_t pixel = static_cast<std::size_t>((299 - y) * 600 + (x + 300));
      boxes[pixel] = tests_of_ray(kBoxTests, x, y);
      objects[pixel] = tests_of_ray(kObjectTests, x, y);
      both[pixel] = boxes[pixel] + objects[pixel];
    }
  }
  CHECK(tests.boxes == boxes);
  CHECK(tests.objects == objects);
  // Every ray tests at least the root's box, and a ray that hits something tested it.
  CHECK(*std::min_element(tests.boxes.begin(), tests.boxes.end()) >= 1);
  CheckDrawn(Figures({}), "sphere-field-10000-tests", both, 10001);
  UNSCOPED_INFO("boxes " << Total(boxes) << ", objects " << Total(objects));
}

TEST_CASE("subsampling searches the scene for the even pixels and where neighbours disagree",
          "[cost]") {
  // Worked apart from the renderer: what the traced pixels' camera rays hit, and the
  // rule of sampling.h for each pixel in between.
  const Scene scene = SceneThinWires();
  Scene prepared = scene;
  PrepareScene(prepared, AllOptimizations());
  const Canvas canvas(600, 600);
  const auto hit_at = [&](int x, int y) {
    if (x < -300 || x >= 300 || y < -300 || y >= 300) {
      return -3;
    }
    const Vec3 D = CameraRayDirection(x, y, canvas, prepared);
    return ClosestIntersection(prepared.camera.position, D, 1, cgfs::kInf, prepared).object;
  };
  std::vector<cgfs::Count> searches(600 * 600, 0);
  for (int x = -300; x < 300; ++x) {
    for (int y = -300; y < 300; ++y) {
      const int dx = (x + 300) % 2, dy = (y + 300) % 2;
      cgfs::Count searched = 1;
      if (dx != 0 || dy != 0) {
        const int a = hit_at(x - dx, y - dy), b = hit_at(x + dx, y - dy),
                  c = hit_at(x - dx, y + dy), d = hit_at(x + dx, y + dy);
        const bool agree = a == b && b == c && c == d && a != -3;
        const bool hits_it =
            agree && a >= 0 &&
            prepared.objects[a]
                    ->Intersect(MakeRay(prepared.camera.position,
                                        CameraRayDirection(x, y, canvas, prepared), prepared),
                                1, cgfs::kInf)
                    .primitive != nullptr;
        searched = (agree && a == -1) || hits_it ? 0 : 1;
      }
      searches[(299 - y) * 600 + (x + 300)] = searched;
    }
  }
  Canvas image(600, 600);
  const std::vector<cgfs::Count> counted = CountedPerPixel(
      kCameraRays, image, [&] { RenderSceneSubsampled(scene, 0, image, AllOptimizations()); });
  CHECK(counted == searches);
  CHECK(Total(searches) >= 300 * 300);
  CheckDrawn(Figures({}), "subsampling-thin-wires-searches", searches, 1);
}

TEST_CASE("adaptive supersampling traces 1 ray, or 1 + 16 where it subdivides", "[cost]") {
  Canvas image(600, 600);
  cgfs::Count subdivided = 0;
  const std::vector<cgfs::Count> rays = CountedPerPixel(kCameraRays, image, [&] {
    subdivided = RenderSceneAdaptive(SceneCamera(), 3, image, AllOptimizations());
  });
  CHECK(Total(rays) == 600L * 600 + 16 * subdivided);
  CHECK(std::count(rays.begin(), rays.end(), 17L) == subdivided);
  CHECK(std::count(rays.begin(), rays.end(), 1L) == 600L * 600 - subdivided);
  CheckDrawn(Figures({}), "supersampling-adaptive-rays", rays, 17);
}

namespace {

// The rays a camera ray becomes, counted apart from TraceRay along the book's rules
// ("Reflections", "Transparency", "Refraction"): one for the ray itself, then, where it
// hits a surface and bounces are left, one reflected ray if the surface reflects and
// one sent through (bent, or mirrored back inside past the critical angle) if it is
// transparent.
cgfs::Count RaysOf(const Vec3& O, const Vec3& D, double t_min, int depth, const Scene& scene,
                   double medium) {
  const Hit hit = ClosestIntersection(O, D, t_min, cgfs::kInf, scene);
  if (hit.primitive == nullptr) {
    return 1;
  }
  const Surface& surface = hit.primitive->surface;
  if (depth <= 0 || (surface.reflective <= 0 && surface.transparency <= 0)) {
    return 1;
  }
  const Vec3 P = O + hit.t * D;
  const Vec3 N = hit.flip_normal ? -hit.primitive->Normal(P) : hit.primitive->Normal(P);
  cgfs::Count rays = 1;
  if (surface.reflective > 0) {
    rays += RaysOf(P, ReflectRay(-D, N), scene.epsilon, depth - 1, scene, medium);
  }
  if (surface.transparency > 0) {
    const bool entering = glm::dot(D, N) < 0;
    const Vec3 N_facing = entering ? N : -N;
    const double next = entering ? surface.refractive_index : kAirIndex;
    const auto T = next == medium ? std::optional(D) : RefractRay(D, N_facing, medium, next);
    rays += T ? RaysOf(P, *T, scene.epsilon, depth - 1, scene, *T == D ? medium : next)
              : RaysOf(P, ReflectRay(-D, N_facing), scene.epsilon, depth - 1, scene, medium);
  }
  return rays;
}

}  // namespace

TEST_CASE("the rays traced per pixel are the rays the book's rules spawn", "[cost]") {
  const struct {
    const char* figure;
    Scene (*scene)();
    int depth;
  } views[] = {{"transparency-rays", SceneTransparency, 3},
               {"refraction-glass-sphere-rays", SceneGlassSphere, 5},
               {"refraction-magnifying-glass-rays", SceneMagnifyingGlass, 5}};
  const Canvas canvas(600, 600);
  for (const auto& view : views) {
    INFO(view.figure);
    const std::vector<cgfs::Count> rays =
        TracedRays(view.scene(), view.depth, canvas, AllOptimizations());
    Scene scene = view.scene();
    PrepareScene(scene, Optimizations{});
    cgfs::Count wrong = 0;
    for (int x = -300; x < 300; x += 3) {
      for (int y = -300; y < 300; y += 3) {
        const Vec3 D = CameraRayDirection(x, y, canvas, scene);
        wrong += rays[static_cast<std::size_t>((299 - y) * 600 + (x + 300))] !=
                 RaysOf(scene.camera.position, D, 1, view.depth, scene, kAirIndex);
      }
    }
    CHECK(wrong == 0);
    CHECK(Max(rays) <= (2L << view.depth) - 1);  // two rays a bounce at most
    CheckDrawn(Figures({}), view.figure, rays, 25);
  }
}

TEST_CASE("the C key's pairs: each cost view belongs to a figure of the chapter", "[cost]") {
  const std::vector<cgfs::Figure> figures = Figures({});
  CHECK(FindFigure(figures, "sphere-field-10000").cost_view == "sphere-field-10000-tests");
  CHECK(FindFigure(figures, "subsampling-thin-wires").cost_view ==
        "subsampling-thin-wires-searches");
  CHECK(FindFigure(figures, "supersampling-adaptive").cost_view == "supersampling-adaptive-rays");
  CHECK(FindFigure(figures, "transparency").cost_view == "transparency-rays");
}
