#include "multipass_lighting.h"

AccumulationBuffer::AccumulationBuffer(const Canvas& canvas) : sums_(canvas, Sum{}) {}

void AccumulationBuffer::BeginPass() {
  ++pass_;
}

void AccumulationBuffer::Set(int x, int y, const Color& color) {
  if (Sum* sum = sums_.Find(x, y)) {
    *sum = {color, pass_};
  }
}

bool AccumulationBuffer::CanAdd(int x, int y) const {
  const Sum* sum = sums_.Find(x, y);
  return sum && sum->last_pass != pass_;
}

bool AccumulationBuffer::Add(int x, int y, const Color& color) {
  Sum* sum = sums_.Find(x, y);
  if (!sum || sum->last_pass == pass_) {
    return false;
  }
  sum->color += color;
  sum->last_pass = pass_;
  return true;
}

void AccumulationBuffer::WriteTo(Canvas& canvas) const {
  for (int y = -canvas.Height() / 2; y < canvas.Height() / 2; ++y) {
    for (int x = -canvas.Width() / 2; x < canvas.Width() / 2; ++x) {
      const Sum* sum = sums_.Find(x, y);
      if (sum && sum->last_pass >= 0) {
        canvas.PutPixel(x, y, sum->color);
      }
    }
  }
}

bool PassFrame::TestAndSet(int x, int y, double inv_z) {
  if (first) {
    return depth_buffer.TestAndSet(x, y, inv_z);
  }
  return depth_buffer.Holds(x, y, inv_z) && stencil.At(x, y) == 0 && sum.CanAdd(x, y);
}

void PassFrame::Write(int x, int y, const Color& color) {
  if (first) {
    sum.Set(x, y, color);
  } else {
    sum.Add(x, y, color);
  }
}

namespace {

// The stencil cleared, then every shadow volume the closed occluders cast from `light`
// (in camera space, like `unclipped`) counted into it.
void MarkShadowVolumes(const CameraSpaceScene& unclipped, const Light& light,
                       const std::vector<Plane>& planes, ShadowVolumeCounting counting,
                       const Frame& frame, StencilBuffer& stencil) {
  stencil.Clear();
  for (const CameraSpaceInstance& I : unclipped.instances) {
    if (I.model.closed) {
      MarkShadowVolume(BuildShadowVolume(I.model, light), planes, frame.canvas, frame.viewport,
                       frame.depth_buffer, stencil, counting);
    }
  }
}

}  // namespace

void RenderInPasses(const Scene& scene, const std::vector<Plane>& planes, const Shading& shading,
                    const std::optional<ShadowVolumeCounting>& counting, Frame& frame,
                    PhongSteps& steps) {
  const glm::dmat4 M_camera = MakeCameraMatrix(scene.camera.position, scene.camera.orientation);
  const CameraSpaceScene unclipped = SceneInView(scene, M_camera);
  const std::vector<Light> lights = TransformLights(scene.lights, M_camera);
  AccumulationBuffer sum(frame.canvas);
  StencilBuffer stencil(frame.canvas);
  PassFrame first(frame, sum, true, stencil);
  RenderView(scene, planes, shading, {LightsOfPass::Which::kAmbient}, first, steps);

  for (std::size_t k = 0; k < lights.size(); ++k) {
    if (lights[k].type == LightType::kAmbient) {
      continue;
    }
    if (counting) {
      MarkShadowVolumes(unclipped, lights[k], planes, *counting, frame, stencil);
    }
    sum.BeginPass();
    PassFrame pass(frame, sum, false, stencil);
    RenderView(scene, planes, shading, {LightsOfPass::Which::kOne, k}, pass, steps);
  }
  sum.WriteTo(frame.canvas);
}
