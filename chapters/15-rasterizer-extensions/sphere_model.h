// Chapter 13, "Normals": a model whose normals are not its triangles' normals.
#pragma once

#include "scene.h"

// A unit sphere centred on the origin, every triangle of one colour, divs rings of
// divs vertices each from the south pole (y = -1) to the north pole (y = 1), equally
// spaced in y. Each corner's normal is its vertex's position, the true normal of the
// sphere there. Triangles are wound clockwise as seen from outside. For divs = 15:
// 240 vertices, 450 triangles, 30 of them degenerate at the poles (their corners on
// a pole coincide), so 420 real ones.
Model GenerateSphere(int divs, const Color& color);
