// An independent check of the rasterizer chapters' figures: a small ray caster that
// shares nothing with the chapters' code but the scene's data (models, instances, the
// camera, the lights). It says which triangle each pixel shows, and whether the point
// there sees a light; tests compare the figures with that.
//
// Conventions, the book's and the chapters': pixel (x, y) of a Cw x Ch canvas shows the
// direction through canvas point (x, y), (x Vw/Cw, y Vh/Ch, d) in camera space (chapter
// 2's CanvasToViewport), turned by the camera's orientation (chapter 5); what is nearer
// the camera than the projection plane (t < 1 along that ray) is clipped away, and a
// closed model is seen from outside only (its back faces culled, chapter 12).
#pragma once

#include <cmath>
#include <functional>
#include <limits>
#include <optional>
#include <vector>

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

namespace cgfs::test {

// A triangle of the scene in world space, and where it comes from.
struct CastTriangle {
  glm::dvec3 a, b, c;
  int instance = -1;  // its instance's index in the scene
  int triangle = -1;  // its index in the instance's model
  bool closed = false;
};

// A sphere around an instance's triangles, to skip them quickly.
struct CastBounds {
  glm::dvec3 centre{0, 0, 0};
  double radius = 0;
  std::size_t first = 0;  // its triangles: [first, last) of CastScene::triangles
  std::size_t last = 0;
};

struct CastScene {
  std::vector<CastTriangle> triangles;
  std::vector<CastBounds> instances;
};

// What a ray hits first: the triangle, the distance along the ray (in units of its
// direction), the point, and the triangle's unit normal there ((b - a) x (c - a)).
struct CastHit {
  int instance = -1;
  int triangle = -1;
  double t = std::numeric_limits<double>::infinity();
  glm::dvec3 point{0, 0, 0};
  glm::dvec3 normal{0, 0, 0};
};

// Moller and Trumbore's ray-triangle test, in double precision: the t where O + tD
// meets the triangle's inside (front or back), if it does.
std::optional<double> MeetsTriangle(const CastTriangle& T, const glm::dvec3& O,
                                    const glm::dvec3& D);

// The first triangle O + tD meets with t_min < t < t_max, closed models' back faces
// left out when `cull_back_faces`; nothing if none.
std::optional<CastHit> Cast(const CastScene& scene, const glm::dvec3& O, const glm::dvec3& D,
                            double t_min, double t_max, bool cull_back_faces);

// A camera as the chapters' scenes have it.
struct CastCamera {
  glm::dvec3 position{0, 0, 0};
  glm::dmat3 orientation{1.0};
  double viewport_width = 1;
  double viewport_height = 1;
  double distance = 1;
};

// What every pixel of a width x height canvas shows, row by row from the top (the
// image's order). Pixels that show nothing have instance -1.
struct CastImage {
  int width = 0;
  int height = 0;
  std::vector<CastHit> hits;

  // Canvas coordinates, as PutPixel takes them.
  const CastHit& At(int x, int y) const {
    return hits[static_cast<std::size_t>(height / 2 - y - 1) * static_cast<std::size_t>(width) +
                static_cast<std::size_t>(width / 2 + x)];
  }
};

CastImage CastCameraImage(const CastScene& scene, const CastCamera& camera, int width, int height);

// Whether anything of the scene lies between point P and a point light at
// `light_position` (directional: anywhere along `light_direction` from P). Rays start a
// millionth of a unit towards the light, so that P's own surface does not count.
bool LightBlocked(const CastScene& scene, const glm::dvec3& P, const glm::dvec3& light_position);
bool DirectionalLightBlocked(const CastScene& scene, const glm::dvec3& P,
                             const glm::dvec3& light_direction);

// A label for every pixel of a cast image: what it shows, at the grain a check needs
// (an instance, a colour, lit or not), in the same order as the image.
struct LabelImage {
  int width = 0;
  int height = 0;
  std::vector<int> labels;

  int At(int x, int y) const {
    return labels[static_cast<std::size_t>(height / 2 - y - 1) * static_cast<std::size_t>(width) +
                  static_cast<std::size_t>(width / 2 + x)];
  }
  // Whether every pixel within `margin` of (x, y) has the label of (x, y): (x, y) is
  // away from every edge of what it shows.
  bool Inside(int x, int y, int margin) const;
};
LabelImage LabelsOf(const CastImage& cast, const std::function<int(const CastHit&)>& label);

// How many pixels a check passes, of how many it was made on.
struct Agreement {
  long counted = 0;
  long agreeing = 0;
  double Fraction() const {
    return counted == 0 ? 0 : static_cast<double>(agreeing) / static_cast<double>(counted);
  }
};

// The scene of a rasterizer chapter (10 to 15) as the ray caster sees it: every
// triangle of every instance placed by its own transform (scaled, turned, moved, as
// Listing 10-4 says), and its camera.
template <typename Scene>
CastScene CastSceneOf(const Scene& scene) {
  CastScene cast;
  for (std::size_t k = 0; k < scene.instances.size(); ++k) {
    const auto& I = scene.instances[k];
    const glm::dmat3 rotation(I.transform.rotation);
    const auto place = [&](const glm::dvec3& v) {
      return rotation * (v * I.transform.scale) + I.transform.translation;
    };
    CastBounds bounds;
    bounds.first = cast.triangles.size();
    for (std::size_t t = 0; t < I.model->triangles.size(); ++t) {
      const auto& T = I.model->triangles[t];
      const auto& V = I.model->vertices;
      cast.triangles.push_back({place(V[static_cast<std::size_t>(T.v[0])]),
                                place(V[static_cast<std::size_t>(T.v[1])]),
                                place(V[static_cast<std::size_t>(T.v[2])]), static_cast<int>(k),
                                static_cast<int>(t), I.model->closed});
    }
    bounds.last = cast.triangles.size();
    glm::dvec3 sum(0, 0, 0);
    for (std::size_t t = bounds.first; t < bounds.last; ++t) {
      sum += cast.triangles[t].a + cast.triangles[t].b + cast.triangles[t].c;
    }
    bounds.centre = sum / (3.0 * static_cast<double>(bounds.last - bounds.first));
    for (std::size_t t = bounds.first; t < bounds.last; ++t) {
      for (const glm::dvec3& p : {cast.triangles[t].a, cast.triangles[t].b, cast.triangles[t].c}) {
        bounds.radius = std::max(bounds.radius, glm::length(p - bounds.centre));
      }
    }
    cast.instances.push_back(bounds);
  }
  return cast;
}

template <typename Scene>
CastCamera CastCameraOf(const Scene& scene) {
  return {scene.camera.position, glm::dmat3(scene.camera.orientation), scene.viewport.width,
          scene.viewport.height, scene.viewport.distance};
}

}  // namespace cgfs::test
