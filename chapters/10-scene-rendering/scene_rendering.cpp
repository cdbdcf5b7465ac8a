#include "rasterizer.h"

#include <cstdlib>
#include <utility>

// "Linear Interpolation". The book accumulates d = d + a, which drifts: after
// hundreds of steps the last value can land just below a whole number and be
// truncated one pixel short. d0 + a*k is the same function without the drift.
std::vector<double> Interpolate(int i0, double d0, int i1, double d1) {
  if (i0 == i1) {
    return {d0};
  }
  std::vector<double> values;
  const double a = (d1 - d0) / (i1 - i0);
  for (int i = i0; i <= i1; ++i) {
    values.push_back(d0 + a * (i - i0));
  }
  return values;
}

// Listing 6-2. Pick the independent variable with more distinct values, so every
// step along it draws exactly one pixel and the segment has no gaps. Interpolated
// coordinates are truncated toward zero (spec §1.1).
void DrawLine(Point P0, Point P1, const Color& color, Canvas& canvas) {
  if (std::abs(P1.x - P0.x) > std::abs(P1.y - P0.y)) {
    // The line is horizontal-ish: y = f(x). Make sure x0 < x1.
    if (P0.x > P1.x) {
      std::swap(P0, P1);
    }
    const std::vector<double> ys = Interpolate(P0.x, P0.y, P1.x, P1.y);
    for (int x = P0.x; x <= P1.x; ++x) {
      canvas.PutPixel(x, static_cast<int>(ys[x - P0.x]), color);
    }
  } else {
    // The line is vertical-ish: x = f(y). Make sure y0 < y1.
    if (P0.y > P1.y) {
      std::swap(P0, P1);
    }
    const std::vector<double> xs = Interpolate(P0.y, P0.x, P1.y, P1.x);
    for (int y = P0.y; y <= P1.y; ++y) {
      canvas.PutPixel(static_cast<int>(xs[y - P0.y]), y, color);
    }
  }
}

// "Drawing Wireframe Triangles".
void DrawWireframeTriangle(Point P0, Point P1, Point P2, const Color& color, Canvas& canvas) {
  DrawLine(P0, P1, color, canvas);
  DrawLine(P1, P2, color, canvas);
  DrawLine(P2, P0, color, canvas);
}

// Listing 7-1. For each y, x_left and x_right come from the edges: the long side
// P0-P2 on one hand, the two short sides P0-P1 and P1-P2 joined on the other.
void DrawFilledTriangle(Point P0, Point P1, Point P2, const Color& color, Canvas& canvas) {
  // Sort the points so that y0 <= y1 <= y2.
  if (P1.y < P0.y) {
    std::swap(P1, P0);
  }
  if (P2.y < P0.y) {
    std::swap(P2, P0);
  }
  if (P2.y < P1.y) {
    std::swap(P2, P1);
  }

  // Compute the x coordinates of the triangle edges, with y as the independent variable.
  std::vector<double> x01 = Interpolate(P0.y, P0.x, P1.y, P1.x);
  const std::vector<double> x12 = Interpolate(P1.y, P1.x, P2.y, P2.x);
  const std::vector<double> x02 = Interpolate(P0.y, P0.x, P2.y, P2.x);

  // Concatenate the short sides. The x at y1 ends x01 and starts x12: keep it once.
  x01.pop_back();
  std::vector<double> x012 = x01;
  x012.insert(x012.end(), x12.begin(), x12.end());

  // Determine which is left and which is right, on the middle row.
  const std::size_t m = x012.size() / 2;
  const bool long_side_is_left = x02[m] < x012[m];
  const std::vector<double>& x_left = long_side_is_left ? x02 : x012;
  const std::vector<double>& x_right = long_side_is_left ? x012 : x02;

  // Draw the horizontal segments. The ends are truncated toward zero; should
  // rounding ever put the left end right of the right one, the row stays empty.
  for (int y = P0.y; y <= P2.y; ++y) {
    const int x_l = static_cast<int>(x_left[y - P0.y]);
    const int x_r = static_cast<int>(x_right[y - P0.y]);
    for (int x = x_l; x <= x_r; ++x) {
      canvas.PutPixel(x, y, color);
    }
  }
}

// Listing 8-1. The same steps as DrawFilledTriangle, with h carried along. The
// vertices move as a whole when sorted, so each keeps its own h.
void DrawShadedTriangle(Point P0, Point P1, Point P2, const Color& color, Canvas& canvas) {
  // Sort the points so that y0 <= y1 <= y2.
  if (P1.y < P0.y) {
    std::swap(P1, P0);
  }
  if (P2.y < P0.y) {
    std::swap(P2, P0);
  }
  if (P2.y < P1.y) {
    std::swap(P2, P1);
  }

  // Compute the x coordinates and h values of the triangle edges.
  std::vector<double> x01 = Interpolate(P0.y, P0.x, P1.y, P1.x);
  std::vector<double> h01 = Interpolate(P0.y, P0.h, P1.y, P1.h);

  const std::vector<double> x12 = Interpolate(P1.y, P1.x, P2.y, P2.x);
  const std::vector<double> h12 = Interpolate(P1.y, P1.h, P2.y, P2.h);

  const std::vector<double> x02 = Interpolate(P0.y, P0.x, P2.y, P2.x);
  const std::vector<double> h02 = Interpolate(P0.y, P0.h, P2.y, P2.h);

  // Concatenate the short sides.
  x01.pop_back();
  std::vector<double> x012 = x01;
  x012.insert(x012.end(), x12.begin(), x12.end());

  h01.pop_back();
  std::vector<double> h012 = h01;
  h012.insert(h012.end(), h12.begin(), h12.end());

  // Determine which is left and which is right, by x only: h follows that choice.
  const std::size_t m = x012.size() / 2;
  const bool long_side_is_left = x02[m] < x012[m];
  const std::vector<double>& x_left = long_side_is_left ? x02 : x012;
  const std::vector<double>& h_left = long_side_is_left ? h02 : h012;
  const std::vector<double>& x_right = long_side_is_left ? x012 : x02;
  const std::vector<double>& h_right = long_side_is_left ? h012 : h02;

  // Draw the horizontal segments, interpolating h across each one.
  for (int y = P0.y; y <= P2.y; ++y) {
    const int x_l = static_cast<int>(x_left[y - P0.y]);
    const int x_r = static_cast<int>(x_right[y - P0.y]);

    const std::vector<double> h_segment =
        Interpolate(x_l, h_left[y - P0.y], x_r, h_right[y - P0.y]);
    for (int x = x_l; x <= x_r; ++x) {
      const Color shaded_color = color * h_segment[x - x_l];
      canvas.PutPixel(x, y, shaded_color);
    }
  }
}

// Listing 9-1. Scale viewport units to pixels.
Point ViewportToCanvas(double x, double y, const Canvas& canvas, const Viewport& viewport) {
  return {static_cast<int>(x * canvas.Width() / viewport.width),
          static_cast<int>(y * canvas.Height() / viewport.height)};
}

// Listing 9-1, "Finding P'": similar triangles give P'x = Px * d / Pz, P'y = Py * d / Pz.
std::optional<Point> ProjectVertex(const Vec3& v, const Canvas& canvas, const Viewport& viewport) {
  const double d = viewport.distance;
  if (v.z < d) {
    return std::nullopt;  // no division by zero, and no points behind the camera
  }
  return ViewportToCanvas(v.x * d / v.z, v.y * d / v.z, canvas, viewport);
}

// Listing 10-1.
void RenderTriangle(const Triangle& triangle, const std::vector<std::optional<Point>>& projected,
                    Canvas& canvas) {
  const std::optional<Point>& P0 = projected[triangle.v[0]];
  const std::optional<Point>& P1 = projected[triangle.v[1]];
  const std::optional<Point>& P2 = projected[triangle.v[2]];
  if (P0 && P1 && P2) {
    DrawWireframeTriangle(*P0, *P1, *P2, triangle.color, canvas);
  }
}

// Listing 10-1.
void RenderObject(const std::vector<Vec3>& vertices, const std::vector<Triangle>& triangles,
                  Canvas& canvas, const Viewport& viewport) {
  std::vector<std::optional<Point>> projected;
  for (const Vec3& V : vertices) {
    projected.push_back(ProjectVertex(V, canvas, viewport));
  }
  for (const Triangle& T : triangles) {
    RenderTriangle(T, projected, canvas);
  }
}

// Listing 10-4. Rotation and scale act about the model's origin, so translation comes last.
Vec3 ApplyTransform(const Vec3& vertex, const Transform& transform) {
  const Vec3 scaled = vertex * transform.scale;
  const Vec3 rotated = Vec3(transform.rotation * glm::dvec4(scaled, 0.0));
  const Vec3 translated = rotated + transform.translation;
  return translated;
}

// Listing 10-3.
void RenderInstance(const Instance& instance, Canvas& canvas, const Viewport& viewport) {
  std::vector<std::optional<Point>> projected;
  const Model& model = *instance.model;
  for (const Vec3& V : model.vertices) {
    const Vec3 V_transformed = ApplyTransform(V, instance.transform);
    projected.push_back(ProjectVertex(V_transformed, canvas, viewport));
  }
  for (const Triangle& T : model.triangles) {
    RenderTriangle(T, projected, canvas);
  }
}

// "The Transform Matrix": M_model = I_T * I_R * I_S, so the scale acts first.
glm::dmat4 MakeTransformMatrix(const Transform& transform) {
  return cgfs::MakeTranslationMatrix(transform.translation) * transform.rotation *
         cgfs::MakeScalingMatrix(transform.scale);
}

// "The Transform Matrix": M_camera = C_R^-1 * C_T^-1.
glm::dmat4 MakeCameraMatrix(const Vec3& position, const glm::dmat4& orientation) {
  return glm::transpose(orientation) * cgfs::MakeTranslationMatrix(-position);
}

// Listing 10-5. Vertices are points: w = 1.
void RenderModel(const Model& model, const glm::dmat4& transform, Canvas& canvas,
                 const Viewport& viewport) {
  std::vector<std::optional<Point>> projected;
  for (const Vec3& V : model.vertices) {
    projected.push_back(
        ProjectVertex(cgfs::ToCartesian(transform * glm::dvec4(V, 1.0)), canvas, viewport));
  }
  for (const Triangle& T : model.triangles) {
    RenderTriangle(T, projected, canvas);
  }
}

// Listing 10-5. One matrix per instance takes its vertices from model space all
// the way to camera space.
void RenderScene(const Scene& scene, Canvas& canvas) {
  const glm::dmat4 M_camera = MakeCameraMatrix(scene.camera.position, scene.camera.orientation);
  for (const Instance& I : scene.instances) {
    const glm::dmat4 M = M_camera * MakeTransformMatrix(I.transform);
    RenderModel(*I.model, M, canvas, scene.viewport);
  }
}
