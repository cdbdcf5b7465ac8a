// Chapter 3, "Light": renders the chapter's figures into out/03-light/.
#include "cgfs/chapter_main.h"
#include "raytracer.h"

int main(int argc, char** argv) {
  cgfs::ChapterProgram program(
      "03-light",
      "Chapter 3, Light: ambient, point and directional lights, diffuse and specular reflection.");
  return program.Run(argc, argv, [] { return Figures(); });
}
