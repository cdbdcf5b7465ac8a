// The models and scenes of the chapter's figures, and the figures themselves.
#pragma once

#include <memory>
#include <vector>

#include "cgfs/tally.h"
#include "clipping.h"
#include "extensions.h"
#include "options.h"
#include "program/figure.h"
#include "texture.h"

inline constexpr char kChapterDescription[] =
    "Chapter 15, Extending the Rasterizer: normal mapping, environment mapping, "
    "multi-pass lighting, stencil shadows, shadow mapping.";

// The cube of "Representing a Cube": edge 2, centred on the origin, each face two
// triangles of one colour, wound so that (V1 - V0) x (V2 - V0) points outwards; every
// corner's normal is its face's normal, and every face has the whole texture.
const Model& CubeModel();

// The scene of Figure 10-10.
Scene SceneTransformedCubes();

// The lights of chapter 13's figures.
std::vector<Light> ShadingLights();

// The crate texture and its mip chain: the one the settings give (--texture), or the
// project's own, MakeCrateTexture(256).
std::shared_ptr<const MipmappedTexture> CrateTexture(const ChapterSettings& settings);

// The cube model with `texture` on every face.
Model TexturedCube(const MipmappedTexture& texture);

// Chapter 14's three crates, each an instance of `crate`.
Scene SceneCrates(const Model& crate);

// "Normal Mapping" (Figure 15-1): a square of stone tiles facing the camera, 2 x 2 at
// z = 5, with the project's diamond normal map, lit by ambient light 0.2 and a point
// light 0.8 at (-3, 0, 4) (from the left) or at (3, 0, 4) (from the right).
Scene SceneNormalMappedSquare(bool light_from_left);

// The project's normal map: size x size texels of bumps x bumps diamond-shaped
// pyramids on a flat ground, encoded as normal_mapping.h's DecodeNormal reads it.
Texture MakeDiamondNormalMap(int size, int bumps);

// Its colour texture: the diamonds as stone tiles, a little lighter and darker in turn,
// and the ground between them as darker grout, texel for texel where the normal map
// has its bumps and its ground.
Texture MakeDiamondTiles(int size, int bumps);

// The normal map of Figure 15-1, and its colour texture.
const Texture& DiamondNormalMap();
const MipmappedTexture& DiamondTiles();

// "Environment Mapping": the crates on a checkered floor around a mirror sphere.
Scene SceneMirrorSphere(const Model& crate);

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

// Figure 15-4: one cube over a floor at y = -1, seen from above, lit by ambient light
// 0.2 and a point light 0.8 above and to the left; the cube is the first instance, the
// point light the last light.
Scene SceneCubeOverFloor();

// Everything at once: textured crates and a mirror sphere over a normal-mapped floor,
// shadowed.
Scene SceneEverything(const Model& crate);

// For the shadow map's cost view: given the entry each pixel reads (-1: none), how many
// pixels read each pixel's entry (-1 where it reads none).
std::vector<cgfs::Count> PixelsSharingEntry(const std::vector<cgfs::Count>& entries);

// A model of the reader's own (--model) seen from a camera at the origin: scaled and
// moved so that its bounding sphere has radius 1 and its centre 3 units ahead; each
// part of it (one Model per texture, see options.h) placed alike, on a floor at its
// lowest point, lit by an ambient light and a point light above and to the left.
Scene SceneModel(const std::vector<Model>& parts);

// Every figure this chapter draws, made with `settings`; with a model in them, only the
// figures of it.
std::vector<cgfs::Figure> Figures(const ChapterSettings& settings = {});
