// The models and scenes of the chapter's figures, and the figures themselves.
#pragma once

#include <vector>

#include "cgfs/figure.h"
#include "clipping.h"
#include "texture.h"

inline constexpr char kChapterDescription[] =
    "Chapter 15, Extending the Rasterizer: normal mapping, environment mapping, "
    "multi-pass lighting, stencil shadows, shadow mapping.";

// The cube of "Representing a Cube": edge 2, centred on the origin, each face two
// triangles of one colour, wound so that (V1 - V0) x (V2 - V0) points outwards; every
// corner's normal is its face's normal, and every face has the whole texture.
const Model& CubeModel();

// The scenes of Figures 10-3 and 10-10.
Scene SceneTwoCubes();
Scene SceneTransformedCubes();

// The lights of chapter 13's figures.
std::vector<Light> ShadingLights();

// The crate texture and its mip chain: the project's own (MakeCrateTexture(256)),
// unless UseCrateTexture gave another. Throws cgfs::Error for a texture larger than
// kMaxTextureSide a side.
void UseCrateTexture(Texture texture);
const MipmappedTexture& CrateTexture();

// Figures 14-3 and 14-5: three crates.
Scene SceneCrates();

// "Normal Mapping": a square facing the camera, 2 x 2 at z = 5, with the project's
// diamond normal map, lit by ambient light 0.2 and a point light 0.8 at (-3, 0, 4)
// (from the left) or at (3, 0, 4) (from the right).
Scene SceneNormalMappedSquare(bool light_from_left);

// "Environment Mapping": the crates on a checkered floor around a mirror sphere.
Scene SceneMirrorSphere();

// Chapter 13's scene (two cubes and a sphere, its three lights).
Scene SceneShading();

// "Stencil Shadows" and "Shadow Mapping": chapter 13's objects over a floor, lit
// by ambient light 0.2 and one point light 0.8 above and to the left.
Scene SceneShadows();

// The same objects lit by ambient light and a directional light.
Scene SceneShadowsDirectional();

// A camera standing in a shadow: a slab overhead keeps the light off it and off the
// floor around it.
Scene SceneCameraInShadow();

// Everything at once: textured crates and a mirror sphere over a normal-mapped floor,
// shadowed.
Scene SceneEverything();

// Every figure this chapter draws.
std::vector<cgfs::Figure> Figures();
