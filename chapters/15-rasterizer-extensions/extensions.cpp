#include "extensions.h"

#include <algorithm>
#include <memory>

#include "normal_mapping.h"
#include "scene_rendering.h"

namespace {

// The maps the stages on read: "Environment Mapping", a cube map around each reflective
// instance (indexed like the instances); "Shadow Mapping", one shadow map per light.
Maps RenderMaps(const Scene& scene, const Extensions& extensions) {
  Maps maps;
  maps.environments.resize(scene.instances.size());
  for (std::size_t k = 0; k < scene.instances.size(); ++k) {
    const Instance& I = scene.instances[k];
    if (extensions.environment_mapping && I.model->reflective > 0) {
      maps.environments[k] =
          RenderCubeMap(scene, I.transform.translation, extensions.cube_map_size);
    }
  }
  if (extensions.shadows == Shadows::kShadowMaps) {
    for (const Light& light : scene.lights) {
      maps.shadow_maps.push_back(RenderShadowMap(scene, light, extensions.shadow_mapping));
    }
  }
  return maps;
}

// The stages' steps in a triangle's Phong shading: its normal bent by its model's normal
// map ("Normal Mapping"), the light each shadow map lets reach the point ("Shadow
// Mapping"), then the reflection mixed in ("Environment Mapping"). A stage that is off
// has nothing to add: no map.
class Stages final : public PhongSteps {
 public:
  Stages(const Texture* normal_map, const std::array<ShadedCorner, 3>& corners,
         std::vector<const ShadowMap*> shadow_maps, const CubeMap* environment, double reflective,
         bool first_pass, const glm::dmat4& camera_to_world)
      : normal_map_(normal_map),
        shadow_maps_(std::move(shadow_maps)),
        environment_(environment),
        reflective_(reflective),
        first_pass_(first_pass),
        camera_to_world_(camera_to_world) {
    if (normal_map_) {
      tangents_ =
          ComputeTangentBasis({corners[0].position, corners[1].position, corners[2].position},
                              {corners[0].uv, corners[1].uv, corners[2].uv});
    }
  }

  void Before(PhongPixel& pixel) const override {
    pixel.N = BendNormal(pixel.N, normal_map_, pixel.uv, tangents_);
    LightVisibilities(pixel.P, pixel.N, shadow_maps_, camera_to_world_, pixel.visibility);
  }

  Color After(const PhongPixel& pixel, const Color& lit) const override {
    return MixReflection(lit, pixel.P, pixel.N, environment_, reflective_, first_pass_,
                         camera_to_world_);
  }

 private:
  const Texture* normal_map_;
  TangentBasis tangents_;
  std::vector<const ShadowMap*> shadow_maps_;
  const CubeMap* environment_;
  double reflective_;
  bool first_pass_;
  glm::dmat4 camera_to_world_;
};

// The stages' steps for each triangle the camera's view draws, from the maps.
ViewDrawing WithStages(const Scene& scene, const Maps& maps, const Extensions& extensions) {
  const glm::dmat4 camera_to_world =
      glm::inverse(MakeCameraMatrix(scene.camera.position, scene.camera.orientation));
  ViewDrawing drawing;
  drawing.multipass_lighting = extensions.multipass_lighting;
  if (extensions.shadows == Shadows::kShadowVolumes) {
    drawing.shadow_volumes = extensions.shadow_volume_counting;
  }
  const bool any_map = !maps.shadow_maps.empty() ||
                       std::any_of(maps.environments.begin(), maps.environments.end(),
                                   [](const auto& environment) { return environment.has_value(); });
  if (!extensions.normal_mapping && !any_map) {
    return drawing;  // no stage adds anything to the shading
  }
  drawing.phong_steps = [&scene, &maps, extensions, camera_to_world](const TriangleInView& drawn) {
    const Model& model = *scene.instances[drawn.instance].model;
    std::vector<const ShadowMap*> shadow_maps;
    for (const std::size_t k : drawn.lights) {
      if (!maps.shadow_maps.empty()) {
        shadow_maps.push_back(&maps.shadow_maps[k]);
      }
    }
    const std::optional<CubeMap>& environment = maps.environments[drawn.instance];
    return std::make_unique<Stages>(extensions.normal_mapping ? model.normal_map : nullptr,
                                    drawn.corners, std::move(shadow_maps),
                                    environment ? &*environment : nullptr, model.reflective,
                                    drawn.first_pass, camera_to_world);
  };
  return drawing;
}

}  // namespace

// "The Clipping Pipeline": model space to camera space with one matrix per
// instance, then clipping, then projection. Clipping happens in camera space, where
// the clipping volume does not depend on the camera. What survives lies beyond the
// near plane, so RenderObject (Listing 10-1) can project and draw it. "Extending the
// Rasterizer": first the maps the stages read, each made by rendering the scene from
// elsewhere, then the view from the camera, in one pass or in passes.
void RenderScene(const Scene& scene, Canvas& canvas, const Shading& shading,
                 const Extensions& extensions) {
  const Maps maps = RenderMaps(scene, extensions);
  RenderView(scene, ClippingPlanes(scene.viewport.distance), canvas, shading,
             WithStages(scene, maps, extensions));
}
