// The scenes of the chapter's figures, and the figures themselves.
#pragma once

#include <vector>

#include "options.h"
#include "program/figure.h"
#include "raytracer.h"

inline constexpr char kChapterDescription[] =
    "Chapter 5, Extending the Raytracer: a camera that moves and turns, faster rendering, "
    "triangles, CSG, transparency, refraction, sub- and supersampling.";

// Figures 4-7 and 4-8: chapter 4's reflective spheres on black, seen from the origin.
Scene SceneReflections();
// Figure 5-1: the same, seen from (3, 0, 1) with the camera turned 45° about Y.
Scene SceneCamera();
// `count` small spheres from a fixed seed over chapter 4's yellow ground, lit by
// chapter 4's lights.
Scene SceneSphereField(int count);
// Triangles among the spheres: a mirror pyramid behind chapter 4's spheres.
Scene SceneTriangles();
// A torus of 102 400 triangles over the ground.
Scene SceneTorusMesh();
// Ten slightly leaning wires from half a pixel to five pixels wide, for subsampling to lose.
Scene SceneThinWires();
// Constructive solid geometry: union, intersection and difference of the same two
// spheres, side by side.
Scene SceneCsgOperations();
// The book's examples: a lens (two spheres intersected), the "Death Star" (a sphere
// with a smaller one taken out), and a nested solid ((A ∪ B) − C) ∩ D.
Scene SceneCsgLens();
Scene SceneCsgDeathStar();
Scene SceneCsgNested();
// Chapter 4's spheres with the red one see-through (no bending: refractive index 1).
Scene SceneTransparency();
// A glass sphere (refractive index 1.5) in front of chapter 4's spheres.
Scene SceneGlassSphere();
// A glass lens (the CSG lens) held in front of a wall of small spheres: a magnifying glass.
Scene SceneMagnifyingGlass();

// A model of the reader's own (--model), in front of the camera on a ground, lit by
// the chapter's lights.
Scene SceneModel(const std::vector<Triangle>& triangles);

// Every figure this chapter draws, made with `settings`; with a model in them, only the
// figures of it.
std::vector<cgfs::Figure> Figures(const ChapterSettings& settings);
