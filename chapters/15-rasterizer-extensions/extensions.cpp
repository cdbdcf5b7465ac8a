#include "extensions.h"

#include "multipass_lighting.h"
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

// The stages' steps in Phong shading, one object for the whole render: the normal bent
// by the model's normal map ("Normal Mapping"), the light each shadow map of the pass's
// lights lets reach the point ("Shadow Mapping"), then the reflection mixed in
// ("Environment Mapping"). A stage that is off has nothing to add: no map.
class Stages final : public PhongSteps {
 public:
  Stages(const Scene& scene, const Maps& maps, const Extensions& extensions)
      : scene_(scene),
        maps_(maps),
        normal_mapping_(extensions.normal_mapping),
        camera_to_world_(
            glm::inverse(MakeCameraMatrix(scene.camera.position, scene.camera.orientation))) {}

  void BeginInstance(std::size_t instance, const LightsOfPass& pass) override {
    const Model& model = *scene_.instances[instance].model;
    normal_map_ = normal_mapping_ ? model.normal_map : nullptr;
    const std::optional<CubeMap>& environment = maps_.environments[instance];
    environment_ = environment ? &*environment : nullptr;
    reflective_ = model.reflective;
    first_pass_ = pass.First();
    shadow_maps_.clear();
    for (std::size_t k = 0; k < maps_.shadow_maps.size(); ++k) {
      if (pass.Includes(k, scene_.lights[k])) {
        shadow_maps_.push_back(&maps_.shadow_maps[k]);
      }
    }
  }

  void BeginTriangle(const std::array<ShadedCorner, 3>& corners) override {
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
  const Scene& scene_;
  const Maps& maps_;
  bool normal_mapping_;
  glm::dmat4 camera_to_world_;
  // The instance being drawn, and the pass.
  const Texture* normal_map_ = nullptr;
  std::vector<const ShadowMap*> shadow_maps_;
  const CubeMap* environment_ = nullptr;
  double reflective_ = 0;
  bool first_pass_ = true;
  // The triangle being drawn.
  TangentBasis tangents_;
};

}  // namespace

// "Extending the Rasterizer": first the maps the stages read, each made by drawing the
// scene from elsewhere, then the view from the camera through the clipping volume, in
// one pass or in passes, into one depth-buffered frame.
void RenderScene(const Scene& scene, Canvas& canvas, const Shading& shading,
                 const Extensions& extensions) {
  const Maps maps = RenderMaps(scene, extensions);
  Stages stages(scene, maps, extensions);
  DepthBuffer depth_buffer(canvas, DepthValue::kInverseZ);
  Frame frame(canvas, depth_buffer, scene.viewport);
  const std::vector<Plane> planes = ClippingPlanes(scene.viewport.distance);
  if (extensions.multipass_lighting || extensions.shadows == Shadows::kShadowVolumes) {
    std::optional<ShadowVolumeCounting> counting;
    if (extensions.shadows == Shadows::kShadowVolumes) {
      counting = extensions.shadow_volume_counting;
    }
    RenderInPasses(scene, planes, shading, counting, frame, stages);
  } else {
    RenderView(scene, planes, shading, {}, frame, stages);
  }
}
