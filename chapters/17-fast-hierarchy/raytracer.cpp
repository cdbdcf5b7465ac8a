#include "raytracer.h"

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "parallel.h"

// Listing 2-3, "Canvas to Viewport": scale pixel units to viewport units; the viewport
// lies at z = d.
Vec3 CanvasToViewport(double x, double y, const Canvas& canvas, const Viewport& viewport) {
  return {x * viewport.width / canvas.Width(), y * viewport.height / canvas.Height(),
          viewport.distance};
}

void PrepareScene(Scene& scene, const Optimizations& optimizations) {
  scene.optimizations = optimizations;
  if (optimizations.cache) {
    for (std::shared_ptr<Object>& object : scene.objects) {
      if (std::shared_ptr<Object> prepared = object->Prepared(scene.camera.position)) {
        object = std::move(prepared);
      }
    }
  }
  // A hierarchy that is a single leaf (a handful of objects) would only put a call
  // in front of the plain loop: such a scene is searched without one.
  scene.bvh = nullptr;
  if (optimizations.bvh) {
    auto bvh = std::make_shared<const Bvh>(scene.objects);
    if (bvh->NodeCount() > 1) {
      scene.bvh = std::move(bvh);
    }
  }
}

Ray MakeRay(const Vec3& O, const Vec3& D, const Scene& scene) {
  return Ray(O, D, O == scene.camera.position);  // the spheres' cached <CO,CO> hold for it
}

// Listing 4-1, now over any object: keep the nearest hit inside [t_min, t_max].
Hit ClosestIntersection(const Vec3& O, const Vec3& D, double t_min, double t_max,
                        const Scene& scene) {
  const Ray ray = MakeRay(O, D, scene);
  if (scene.bvh != nullptr) {
    int object = -1;
    Hit closest = scene.bvh->Closest(ray, t_min, t_max, object);
    closest.object = object;
    return closest;
  }
  Hit closest;
  for (int i = 0; i < static_cast<int>(scene.objects.size()); ++i) {
    const Hit hit = scene.objects[i]->Intersect(ray, t_min, t_max);
    if (hit.t < closest.t) {
      closest = hit;
      closest.object = i;
    }
  }
  return closest;
}

bool AnyIntersection(const Vec3& O, const Vec3& D, double t_min, double t_max, const Scene& scene,
                     int& object) {
  const Ray ray = MakeRay(O, D, scene);
  if (scene.bvh != nullptr) {
    return scene.bvh->Any(ray, t_min, t_max, object);
  }
  for (int i = 0; i < static_cast<int>(scene.objects.size()); ++i) {
    if (scene.objects[i]->Intersect(ray, t_min, t_max).t < cgfs::kInf) {
      object = i;
      return true;
    }
  }
  object = -1;
  return false;
}

namespace {

// Whether scene object `object` is hit in [t_min, t_max]: through the hierarchy's copy
// of it when there is one, which lies next to the objects near it in memory.
bool Hits(int object, const Ray& ray, double t_min, double t_max, const Scene& scene) {
  return scene.bvh != nullptr ? scene.bvh->Hits(object, ray, t_min, t_max)
                              : scene.objects[object]->Intersect(ray, t_min, t_max).t < cgfs::kInf;
}

}  // namespace

// "Shadow Optimizations". Without them this is Listing 4-3's test: is there a
// closest intersection at all? Each thread remembers its own last blockers, so the
// threads never share anything they write; a remembered index is only a guess to
// try first, which is why a stale one (from another scene) is harmless.
bool IsInShadow(const Vec3& P, const Vec3& L, double t_max, int light_index, const Scene& scene) {
  const Optimizations& optimizations = scene.optimizations;
  thread_local std::vector<int> last_blocker;
  if (optimizations.shadow_coherence) {
    if (light_index >= static_cast<int>(last_blocker.size())) {
      last_blocker.resize(light_index + 1, -1);
    }
    const int blocker = last_blocker[light_index];
    if (blocker >= 0 && blocker < static_cast<int>(scene.objects.size()) &&
        Hits(blocker, MakeRay(P, L, scene), scene.epsilon, t_max, scene)) {
      return true;
    }
  }
  int object = -1;
  bool blocked = false;
  if (optimizations.shadow_any_hit) {
    blocked = AnyIntersection(P, L, scene.epsilon, t_max, scene, object);
  } else {
    object = ClosestIntersection(P, L, scene.epsilon, t_max, scene).object;
    blocked = object >= 0;
  }
  if (optimizations.shadow_coherence && blocked) {
    last_blocker[light_index] = object;
  }
  return blocked;
}

// "Rendering with Reflections". N must have unit length; R may have any length,
// and the result has the same length as R.
Vec3 ReflectRay(const Vec3& R, const Vec3& N) {
  return 2.0 * N * glm::dot(N, R) - R;
}

// Listing 4-3. L points from P towards the light and is not normalised; the
// cosines divide by the lengths instead.
double ComputeLighting(const Vec3& P, const Vec3& N, const Vec3& V, double s, const Scene& scene) {
  double i = 0.0;
  for (int light_index = 0; light_index < static_cast<int>(scene.lights.size()); ++light_index) {
    const Light& light = scene.lights[light_index];
    if (light.type == LightType::kAmbient) {
      i += light.intensity;
      continue;
    }
    Vec3 L;
    double t_max = 0;
    if (light.type == LightType::kPoint) {
      L = light.position - P;
      t_max = 1;  // the light itself is at P + 1*L: what lies beyond it casts no shadow
    } else {
      L = light.direction;
      t_max = cgfs::kInf;
    }

    // "Rendering with Shadows": is anything between P and the light?
    if (IsInShadow(P, L, t_max, light_index, scene)) {
      continue;
    }

    // "Diffuse Reflection": I * cos(angle between N and L); light from behind adds nothing.
    const double n_dot_l = glm::dot(N, L);
    if (n_dot_l > 0) {
      i += light.intensity * n_dot_l / (glm::length(N) * glm::length(L));
    }

    // "Specular Reflection": I * cos(angle between R and V)^s, with R the mirror
    // image of L about N. As in the book, this is not guarded by n_dot_l > 0.
    if (s != -1) {
      const Vec3 R = ReflectRay(L, N);
      const double r_dot_v = glm::dot(R, V);
      if (r_dot_v > 0) {
        i += light.intensity * std::pow(r_dot_v / (glm::length(R) * glm::length(V)), s);
      }
    }
  }
  return i;
}

// Listing 4-4: light the closest hit, then mix in what is seen in its reflection
// and through it.
Color TraceRay(const Vec3& O, const Vec3& D, double t_min, double t_max, int recursion_depth,
               const Scene& scene, double medium_index) {
  cgfs::Tally(kTracedRays);
  const Hit closest = ClosestIntersection(O, D, t_min, t_max, scene);
  if (closest.primitive == nullptr) {
    return scene.background_color;
  }
  return ColorAtHit(O, D, closest, recursion_depth, scene, medium_index);
}

Color ColorAtHit(const Vec3& O, const Vec3& D, const Hit& hit, int recursion_depth,
                 const Scene& scene, double medium_index) {
  const Object& object = *hit.primitive;
  const Vec3 P = O + hit.t * D;  // the intersection
  Vec3 N = object.Normal(P);     // "Supporting Other Primitives": each object knows its own
  if (hit.flip_normal) {
    N = -N;  // the inside of a CSG hole: its surface faces into the hole
  }
  // V = -D points from the surface back towards the camera.
  const Surface& surface = object.surface;
  const Color local_color = surface.color * ComputeLighting(P, N, -D, surface.specular, scene);

  // Stop at the recursion limit, or when the surface neither reflects nor lets light
  // through. Without the limit, two mirrors facing each other would recurse forever.
  const double r = surface.reflective;
  const double transparency = surface.transparency;
  if (recursion_depth <= 0 || (r <= 0 && transparency <= 0)) {
    return local_color;
  }

  Color color = local_color;
  if (r > 0) {
    // The camera sees, in the mirror, what lies along -D reflected about N.
    const Vec3 R = ReflectRay(-D, N);
    const Color reflected_color =
        TraceRay(P, R, scene.epsilon, cgfs::kInf, recursion_depth - 1, scene, medium_index);
    color = local_color * (1 - r) + reflected_color * r;
  }
  if (transparency > 0) {
    // "Transparency" and "Refraction": continue past the surface, bent by Snell's
    // law when the material on the other side has another refractive index. A ray
    // meeting the surface from outside enters the object; from inside, it leaves
    // into the air (objects are not nested in one another).
    const bool entering = glm::dot(D, N) < 0;
    const Vec3 N_facing = entering ? N : -N;
    const double next_index = entering ? surface.refractive_index : kAirIndex;
    Color through_color;
    if (next_index == medium_index) {
      through_color =
          TraceRay(P, D, scene.epsilon, cgfs::kInf, recursion_depth - 1, scene, medium_index);
    } else if (const auto T = RefractRay(D, N_facing, medium_index, next_index)) {
      through_color =
          TraceRay(P, *T, scene.epsilon, cgfs::kInf, recursion_depth - 1, scene, next_index);
    } else {
      // Total internal reflection: no light gets out; all of it is mirrored back in.
      through_color = TraceRay(P, ReflectRay(-D, N_facing), scene.epsilon, cgfs::kInf,
                               recursion_depth - 1, scene, medium_index);
    }
    color = color * (1 - transparency) + through_color * transparency;
  }
  return color;
}

// The rotation takes the viewport's directions to the scene's (Listing 5-1), so both
// turns act on them first, the yaw last.
Camera MovedCamera(const Camera& camera, const cgfs::View& view) {
  Camera moved = camera;
  moved.position = camera.position + camera.rotation * view.move;
  const glm::dmat4 turn =
      glm::rotate(glm::dmat4(1.0), glm::radians(-view.yaw), glm::dvec3(0, 1, 0)) *
      glm::rotate(glm::dmat4(1.0), glm::radians(-view.pitch), glm::dvec3(1, 0, 0));
  moved.rotation = camera.rotation * glm::dmat3(turn);
  return moved;
}

// Listing 5-1: the viewport moves and turns with the camera, so the direction
// through a pixel is the chapter-2 direction turned by the camera's rotation.
Vec3 CameraRayDirection(double x, double y, const Canvas& canvas, const Scene& scene) {
  return scene.camera.rotation * CanvasToViewport(x, y, canvas, scene.viewport);
}

// Listing 5-1. t_min = 1 keeps only what lies beyond the projection plane.
// The pixels are those of the canvas, Cw x Ch rays (not the book's inclusive loops), in
// the tiles of parallel.h, whatever the number of workers.
void RenderScene(const Scene& scene, int recursion_depth, Canvas& canvas,
                 const Optimizations& optimizations) {
  Scene prepared = scene;
  PrepareScene(prepared, optimizations);
  ForEachPixel(canvas, optimizations.threads, [&](int x, int y) {
    const Vec3 D = CameraRayDirection(x, y, canvas, prepared);
    const Color color =
        TraceRay(prepared.camera.position, D, 1, cgfs::kInf, recursion_depth, prepared);
    canvas.PutPixel(x, y, color);
  });
}
