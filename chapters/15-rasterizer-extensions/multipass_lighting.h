// Chapter 15, "Stencil Shadows", its first step: multi-pass lighting. The scene is
// drawn once per light, each pass lit by that light alone, and the passes' colours
// are added pixel by pixel. The sum is kept in floating point and clamped once, at
// the end: clamping each pass would lose whatever light a pass had above 255.
#pragma once

#include <optional>
#include <vector>

#include "canvas_grid.h"
#include "depth_buffer.h"
#include "scene_rendering.h"
#include "shading.h"
#include "shadow_volumes.h"
#include "stencil_buffer.h"

// A floating-point colour per pixel of the canvas: the sum of the passes so far.
class AccumulationBuffer {
 public:
  explicit AccumulationBuffer(const Canvas& canvas);

  // The next pass begins: each pass adds to a pixel at most once.
  void BeginPass();

  // The first pass: (x, y) becomes `color` (a closer triangle replaces a farther one).
  void Set(int x, int y, const Color& color);

  // A later pass: `color` added to (x, y), unless this pass has already added to it
  // (two triangles that share an edge both cover the pixels on it, at the same
  // depth: only the first may count). False if it was not added.
  bool Add(int x, int y, const Color& color);

  // Whether this pass may still add to (x, y).
  bool CanAdd(int x, int y) const;

  // The sum written to the canvas, clamped there; pixels no pass drew are left as
  // they are.
  void WriteTo(Canvas& canvas) const;

 private:
  // A pixel's sum so far, and the pass that last drew it (-1: none).
  struct Sum {
    Color color{0, 0, 0};
    int last_pass = -1;
  };
  CanvasGrid<Sum> sums_;
  int pass_ = 0;
};

// A frame drawn in a pass: its colours go to the sum. The first pass depth tests and
// sets, as "Depth Buffering" does, and sets the sum. A later pass leaves the depth buffer
// as it is: it draws only where a triangle's depth is exactly what the first pass stored
// (the same triangle, rasterised again the same way, gives the same 1/z) and the stencil
// holds 0, and adds to the sum.
struct PassFrame : Frame {
  PassFrame(const Frame& frame, AccumulationBuffer& into, bool first_pass,
            const StencilBuffer& where)
      : Frame(frame.canvas, frame.depth_buffer, frame.viewport),
        sum(into),
        first(first_pass),
        stencil(where) {}

  AccumulationBuffer& sum;
  bool first;
  const StencilBuffer& stencil;

  bool TestAndSet(int x, int y, double inv_z) override;
  void Write(int x, int y, const Color& color) override;
};

// "Stencil Shadows": the view drawn in passes (RenderView, each pass with its lights)
// into `frame`. First the ambient light alone, which also fills the depth buffer; then,
// for each other light, the shadow volumes of the closed occluders counted into the
// stencil (if `counting` is given), and the scene lit by that light alone added where
// the stencil is 0. The sum is clamped once, onto the frame's canvas. A volume is cast
// by the whole occluder, seen or not: it is built from the scene before clipping.
void RenderInPasses(const Scene& scene, const std::vector<Plane>& planes, const Shading& shading,
                    const std::optional<ShadowVolumeCounting>& counting, Frame& frame,
                    PhongSteps& steps);
