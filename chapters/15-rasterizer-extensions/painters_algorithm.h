// Chapter 12, "Painter's Algorithm". The book describes it in prose only; the names
// here are the project's.
#pragma once

#include <array>
#include <vector>

#include "clipping.h"

// A triangle taken out of its instance: its three vertices in camera space, in the
// triangle's order, and its colour.
struct SceneTriangle {
  std::array<Vec3, 3> vertices;
  Color color{0, 0, 0};
};

// Every triangle of every instance, in camera space, instance by instance in model
// order. The painter needs this whole list before it can draw anything.
std::vector<SceneTriangle> CollectTriangles(const CameraSpaceScene& scene);

// How far the painter considers a triangle to be: the book does not say; this is
// the camera-space z of its centroid.
double PaintersDepth(const SceneTriangle& triangle);

// Back to front: decreasing PaintersDepth. Triangles at the same depth keep their
// order in the list (a stable sort), so the result never depends on the library.
void SortBackToFront(std::vector<SceneTriangle>& triangles);

// "Painter's Algorithm": every triangle of the scene, farthest first, each drawn
// with DrawFilledTriangle over what is already there.
void PaintersAlgorithm(const CameraSpaceScene& scene, Canvas& canvas, const Viewport& viewport);
