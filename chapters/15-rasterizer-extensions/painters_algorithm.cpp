#include "painters_algorithm.h"

#include <algorithm>

std::vector<SceneTriangle> CollectTriangles(const CameraSpaceScene& scene) {
  std::vector<SceneTriangle> triangles;
  for (const CameraSpaceInstance& I : scene.instances) {
    for (const Triangle& T : I.model.triangles) {
      triangles.push_back(
          {{I.model.vertices[T.v[0]], I.model.vertices[T.v[1]], I.model.vertices[T.v[2]]},
           T.color});
    }
  }
  return triangles;
}

double PaintersDepth(const SceneTriangle& triangle) {
  return (triangle.vertices[0].z + triangle.vertices[1].z + triangle.vertices[2].z) / 3;
}

// n log n comparisons: twice the triangles take more than twice the time.
void SortBackToFront(std::vector<SceneTriangle>& triangles) {
  std::stable_sort(triangles.begin(), triangles.end(),
                   [](const SceneTriangle& a, const SceneTriangle& b) {
                     return PaintersDepth(a) > PaintersDepth(b);
                   });
}

// "Painter's Algorithm": paint the background first and the foreground over it.
void PaintersAlgorithm(const CameraSpaceScene& scene, Canvas& canvas, const Viewport& viewport) {
  std::vector<SceneTriangle> triangles = CollectTriangles(scene);
  SortBackToFront(triangles);
  for (const SceneTriangle& T : triangles) {
    DrawFilledTriangle(ProjectVertex(T.vertices[0], canvas, viewport),
                       ProjectVertex(T.vertices[1], canvas, viewport),
                       ProjectVertex(T.vertices[2], canvas, viewport), T.color, canvas);
  }
}
