// The models and scenes of the chapter's figures, and the figures themselves.
#pragma once

#include <memory>
#include <vector>

#include "clipping.h"
#include "options.h"
#include "program/figure.h"
#include "scene_rendering.h"
#include "texture.h"

inline constexpr char kChapterDescription[] =
    "Chapter 14, Textures: texture mapping, perspective-correct interpolation, bilinear "
    "filtering, mipmapping, trilinear filtering.";

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

// Figures 14-3 and 14-5: three crates, each an instance of `crate`.
Scene SceneCrates(const Model& crate);
// Figures 14-7 and 14-8: one crate up close.
Scene SceneCrateCloseUp(const Model& crate);
// Figure 14-11: a one-texel checkerboard on a small square and on a floor.
Scene SceneMinifiedCheckerboard();

// A model of the reader's own (--model) seen from a camera at the origin: scaled and
// moved so that its bounding sphere has radius 1 and its centre 3 units ahead, lit by the lights of
// chapter 13's figures; each part of it (one Model per texture, see options.h) placed alike.
Scene SceneModel(const std::vector<Model>& parts);

// Every figure this chapter draws, made with `settings`; with a model in them, only the
// figures of it.
std::vector<cgfs::Figure> Figures(const ChapterSettings& settings = {});
