// Chapter 5's optimisations, each alone and all together, timed with Google
// Benchmark (run by scripts/benchmark, which also plots the sphere fields). Built twice:
// as benchmark-05 on chapter 5, whose hierarchy is the plain one, and as benchmark-17 on
// chapter 17, the same chapter with the tuned hierarchy; CGFS_HIERARCHY names which.
//
//   Camera/<switches>                Figure 5-1 at 600x600
//   SphereField/<count>/bvh          the sphere fields at 600x600, one thread
//   SphereFieldSmall/<count>/<bvh>   the same at 150x150, where the plain loop can
//                                    still be timed at 10 000 spheres
//   BvhBuild/<count>/<hierarchy>     building the hierarchy over a sphere field
//   SphereFieldPrimary/<count>/...   only the primary rays at 600x600, one thread:
//                                    the chapter's hierarchy (plain or tuned), and
//                                    Embree's where it is installed (in both programs)
//   MeshPrimary/<mesh>/...           the same on triangle meshes: tori of 10 000,
//                                    100 000 and 1 000 000 triangles, and the Wuson
//                                    of assimp-testmodels (3 732) where installed
//   MeshBuild/<mesh>/<hierarchy>     building the hierarchy over a mesh
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <map>
#include <memory>
#include <mutex>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <glm/mat3x3.hpp>

#include "benchmark_main.h"
#include "bvh.h"
#include "cgfs/tally.h"
#include "meshes.h"
#include "options.h"
#include "program/book_model.h"
#include "raytracer.h"
#include "sampling.h"
#include "scenes.h"

#if CGFS_HAVE_EMBREE
#include <embree3/rtcore.h>
#endif

namespace {

struct Switches {
  std::string name;
  Optimizations optimizations;
};

// The switches as --optimizations spells them, each alone, and some together.
std::vector<Switches> EachSwitch() {
  std::vector<Switches> switches;
  const std::vector<std::vector<std::string>> lists = {
      {"none"},
      {"threads"},
      {"cache"},
      {"shadow-any-hit"},
      {"shadow-coherence"},
      {"shadow-any-hit", "shadow-coherence"},
      {"bvh"},
      {"subsampling"},
      {"cache", "shadow-any-hit", "shadow-coherence", "bvh"},
      {"all"}};
  for (const std::vector<std::string>& names : lists) {
    std::string name;
    for (const std::string& each : names) {
      name += (name.empty() ? "" : ",") + each;
    }
    switches.push_back({name, OptimizationsNamed(names)});
  }
  return switches;
}

void Render(benchmark::State& state, const Scene& scene, int side,
            const Optimizations& optimizations) {
  Canvas canvas(side, side);
  for (auto _ : state) {
    RenderSceneAsChosen(scene, 3, canvas, optimizations);
    benchmark::DoNotOptimize(canvas);
  }
  state.counters["pixels/s"] = benchmark::Counter(static_cast<double>(side) * side,
                                                  benchmark::Counter::kIsIterationInvariantRate);
}

// Only the primary rays: the closest hit for every pixel, no shading. Then, untimed, the
// work behind them: the box and object tests of a ray, on average (the hierarchy's
// tally, as its cost view counts them).
void TracePrimaryRays(benchmark::State& state, const Scene& scene, int side) {
  Scene prepared = scene;
  Optimizations bvh;
  bvh.bvh = true;
  bvh.cache = true;
  PrepareScene(prepared, bvh);
  const Canvas canvas(side, side);
  const auto trace = [&] {
    long hits = 0;
    for (int x = -side / 2; x < side / 2; ++x) {
      for (int y = -side / 2; y < side / 2; ++y) {
        const Vec3 D = CameraRayDirection(x, y, canvas, prepared);
        hits +=
            ClosestIntersection(prepared.camera.position, D, 1, cgfs::kInf, prepared).object >= 0;
      }
    }
    return hits;
  };
  for (auto _ : state) {
    benchmark::DoNotOptimize(trace());
  }
  const double rays = static_cast<double>(side) * side;
  state.counters["rays/s"] =
      benchmark::Counter(rays, benchmark::Counter::kIsIterationInvariantRate);
  for (const cgfs::Counter* counter : {&kBoxTests, &kObjectTests}) {
    const cgfs::Tallying tally(*counter, side, side);
    trace();
    state.counters[std::string(counter->name) + "/ray"] = static_cast<double>(tally.Total()) / rays;
  }
}

// The meshes of MeshPrimary, as --model places a model (SceneModel), without the ground
// sphere: triangles alone, as Embree is given them.
constexpr char kWuson[] = "/usr/share/assimp/models/OBJ/WusonOBJ.obj";

std::vector<Triangle> MeshTriangles(const std::string& name) {
  if (name == "wuson") {
    return TrianglesFromFile(cgfs::InBookCoordinates(cgfs::ReadModelFile(kWuson)));
  }
  // Two triangles per step along the ring and around the tube: 100 x 50, 400 x 125 and
  // 1 000 x 500 steps make the 10 000, 100 000 and 1 000 000 triangles of the names.
  const int around = name == "torus-10000" ? 100 : name == "torus-100000" ? 400 : 1000;
  const int across = name == "torus-100000" ? 125 : around / 2;
  // Tilted 55 degrees about x, as the chapter's torus-mesh figure is, so that the camera
  // looks into its hole.
  const double angle = -55 * std::numbers::pi / 180;
  const glm::dmat3 tilt(1, 0, 0, 0, std::cos(angle), std::sin(angle), 0, -std::sin(angle),
                        std::cos(angle));
  std::vector<Triangle> tilted;
  for (const Triangle& T : TorusMesh(1.6, 0.55, around, across, {255, 120, 40})) {
    tilted.push_back(Triangle{tilt * T.A, tilt * T.B, tilt * T.C, T.surface.color});
  }
  // Measured under its name, so it must have the count the name says.
  if (std::to_string(tilted.size()) != name.substr(name.find('-') + 1)) {
    throw std::logic_error(name + " has " + std::to_string(tilted.size()) + " triangles");
  }
  return tilted;
}

// Made on first use and kept (a million triangles take a second to make).
const Scene& MeshScene(const std::string& name) {
  static std::mutex mutex;
  static std::map<std::string, std::unique_ptr<Scene>> scenes;
  const std::lock_guard<std::mutex> lock(mutex);
  std::unique_ptr<Scene>& scene = scenes[name];
  if (!scene) {
    scene = std::make_unique<Scene>(SceneModel(MeshTriangles(name)));
    scene->objects.pop_back();  // the ground
  }
  return *scene;
}

std::vector<std::string> MeshNames() {
  std::vector<std::string> names = {"torus-10000", "torus-100000", "torus-1000000"};
  if (std::filesystem::exists(kWuson)) {
    names.insert(names.begin(), "wuson");
  } else if (std::string(CGFS_HIERARCHY) == "plain") {
    std::fprintf(stderr,
                 "benchmark-05: no %s (Debian assimp-testmodels): MeshPrimary/wuson "
                 "is skipped\n",
                 kWuson);
  }
  return names;
}

#if CGFS_HAVE_EMBREE
// Embree's device and scene, released together.
struct EmbreeScene {
  RTCDevice device = rtcNewDevice("threads=1");
  RTCScene scene = rtcNewScene(device);
  EmbreeScene() = default;
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;
  ~EmbreeScene() {
    rtcReleaseScene(scene);
    rtcReleaseDevice(device);
  }
};

// The scene's triangles as one Embree triangle mesh (three single-precision vertices
// each, unshared).
void AddTriangles(const Scene& scene, EmbreeScene& embree) {
  std::vector<const Triangle*> triangles;
  for (const auto& object : scene.objects) {
    if (const auto* triangle = dynamic_cast<const Triangle*>(object.get())) {
      triangles.push_back(triangle);
    }
  }
  RTCGeometry geometry = rtcNewGeometry(embree.device, RTC_GEOMETRY_TYPE_TRIANGLE);
  auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0,
                                                               RTC_FORMAT_FLOAT3, 3 * sizeof(float),
                                                               3 * triangles.size()));
  auto* indices = static_cast<unsigned*>(
      rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                              3 * sizeof(unsigned), triangles.size()));
  for (std::size_t i = 0; i < triangles.size(); ++i) {
    const Vec3* corners[3] = {&triangles[i]->A, &triangles[i]->B, &triangles[i]->C};
    for (std::size_t k = 0; k < 3; ++k) {
      for (std::size_t axis = 0; axis < 3; ++axis) {
        vertices[9 * i + 3 * k + axis] = static_cast<float>((*corners[k])[static_cast<int>(axis)]);
      }
      indices[3 * i + k] = static_cast<unsigned>(3 * i + k);
    }
  }
  rtcCommitGeometry(geometry);
  rtcAttachGeometry(embree.scene, geometry);
  rtcReleaseGeometry(geometry);
}

// The same spheres as Embree sphere points (x, y, z, r in single precision), the
// same primary rays, one at a time (rtcIntersect1), on one thread.
void AddSpheres(const Scene& scene, EmbreeScene& embree) {
  std::vector<const Sphere*> spheres;
  for (const auto& object : scene.objects) {
    if (const auto* sphere = dynamic_cast<const Sphere*>(object.get())) {
      spheres.push_back(sphere);
    }
  }
  RTCGeometry geometry = rtcNewGeometry(embree.device, RTC_GEOMETRY_TYPE_SPHERE_POINT);
  auto* points = static_cast<float*>(rtcSetNewGeometryBuffer(
      geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT4, 4 * sizeof(float), spheres.size()));
  for (std::size_t i = 0; i < spheres.size(); ++i) {
    points[4 * i + 0] = static_cast<float>(spheres[i]->center.x);
    points[4 * i + 1] = static_cast<float>(spheres[i]->center.y);
    points[4 * i + 2] = static_cast<float>(spheres[i]->center.z);
    points[4 * i + 3] = static_cast<float>(spheres[i]->radius);
  }
  rtcCommitGeometry(geometry);
  rtcAttachGeometry(embree.scene, geometry);
  rtcReleaseGeometry(geometry);
}

// The scene's spheres and triangles in Embree, the same primary rays, one at a time
// (rtcIntersect1), on one thread.
void TracePrimaryRaysEmbree(benchmark::State& state, const Scene& scene, int side) {
  EmbreeScene embree;
  AddSpheres(scene, embree);
  AddTriangles(scene, embree);
  rtcCommitScene(embree.scene);

  const Canvas canvas(side, side);
  RTCIntersectContext context;
  for (auto _ : state) {
    long hits = 0;
    for (int x = -side / 2; x < side / 2; ++x) {
      for (int y = -side / 2; y < side / 2; ++y) {
        const Vec3 D = CameraRayDirection(x, y, canvas, scene);
        RTCRayHit ray{};
        ray.ray.org_x = static_cast<float>(scene.camera.position.x);
        ray.ray.org_y = static_cast<float>(scene.camera.position.y);
        ray.ray.org_z = static_cast<float>(scene.camera.position.z);
        ray.ray.dir_x = static_cast<float>(D.x);
        ray.ray.dir_y = static_cast<float>(D.y);
        ray.ray.dir_z = static_cast<float>(D.z);
        ray.ray.tnear = 1;
        ray.ray.tfar = std::numeric_limits<float>::infinity();
        ray.ray.mask = ~0U;
        ray.hit.geomID = RTC_INVALID_GEOMETRY_ID;
        rtcInitIntersectContext(&context);
        rtcIntersect1(embree.scene, &context, &ray);
        hits += ray.hit.geomID != RTC_INVALID_GEOMETRY_ID;
      }
    }
    benchmark::DoNotOptimize(hits);
  }
  state.counters["rays/s"] = benchmark::Counter(static_cast<double>(side) * side,
                                                benchmark::Counter::kIsIterationInvariantRate);
}
#endif

// MeshPrimary and MeshBuild for every mesh.
void RegisterMeshes() {
  for (const std::string& name : MeshNames()) {
    benchmark::RegisterBenchmark(
        ("MeshPrimary/" + name + "/" + CGFS_HIERARCHY).c_str(),
        [name](benchmark::State& state) { TracePrimaryRays(state, MeshScene(name), 600); })
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime();
#if CGFS_HAVE_EMBREE
    benchmark::RegisterBenchmark(
        ("MeshPrimary/" + name + "/embree").c_str(),
        [name](benchmark::State& state) { TracePrimaryRaysEmbree(state, MeshScene(name), 600); })
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime();
#endif
    benchmark::RegisterBenchmark(("MeshBuild/" + name + "/" + CGFS_HIERARCHY).c_str(),
                                 [name](benchmark::State& state) {
                                   const Scene& scene = MeshScene(name);
                                   for (auto _ : state) {
                                     const Bvh bvh(scene.objects);
                                     benchmark::DoNotOptimize(bvh.NodeCount());
                                   }
                                 })
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime();
  }
}

}  // namespace

void RegisterAll() {
  const auto camera = std::make_shared<Scene>(SceneCamera());
  for (const Switches& each : EachSwitch()) {
    benchmark::RegisterBenchmark(("Camera/" + each.name).c_str(),
                                 [camera, each](benchmark::State& state) {
                                   Render(state, *camera, 600, each.optimizations);
                                 })
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime();
  }

  Optimizations with_bvh = AllOptimizations();
  with_bvh.threads = 1;
  Optimizations without_bvh = with_bvh;
  without_bvh.bvh = false;
  for (const int count : {100, 1000, 10000, 100000}) {
    const auto field = std::make_shared<Scene>(SceneSphereField(count));
    const std::string n = std::to_string(count);
    benchmark::RegisterBenchmark(
        ("SphereField/" + n + "/bvh").c_str(),
        [field, with_bvh](benchmark::State& state) { Render(state, *field, 600, with_bvh); })
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime();
    benchmark::RegisterBenchmark(
        ("SphereFieldSmall/" + n + "/bvh").c_str(),
        [field, with_bvh](benchmark::State& state) { Render(state, *field, 150, with_bvh); })
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime();
    if (count <= 10000) {  // 100 000 spheres without the hierarchy: minutes per frame
      benchmark::RegisterBenchmark(("SphereFieldSmall/" + n + "/no-bvh").c_str(),
                                   [field, without_bvh](benchmark::State& state) {
                                     Render(state, *field, 150, without_bvh);
                                   })
          ->Unit(benchmark::kMillisecond)
          ->UseRealTime();
    }
    benchmark::RegisterBenchmark(("BvhBuild/" + n + "/" + CGFS_HIERARCHY).c_str(),
                                 [field](benchmark::State& state) {
                                   for (auto _ : state) {
                                     const Bvh bvh(field->objects);
                                     benchmark::DoNotOptimize(bvh.NodeCount());
                                   }
                                 })
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime();
    benchmark::RegisterBenchmark(
        ("SphereFieldPrimary/" + n + "/" + CGFS_HIERARCHY).c_str(),
        [field](benchmark::State& state) { TracePrimaryRays(state, *field, 600); })
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime();
#if CGFS_HAVE_EMBREE
    benchmark::RegisterBenchmark(
        ("SphereFieldPrimary/" + n + "/embree").c_str(),
        [field](benchmark::State& state) { TracePrimaryRaysEmbree(state, *field, 600); })
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime();
#endif
  }
  RegisterMeshes();
#if !CGFS_HAVE_EMBREE
  std::fprintf(stderr,
               "built without Embree (Debian libembree-dev), so the "
               "SphereFieldPrimary/*/embree and MeshPrimary/*/embree benchmarks are skipped\n");
#endif
}
