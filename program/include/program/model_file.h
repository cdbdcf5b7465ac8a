// Wavefront OBJ models, read with tinyobjloader (Debian's libtinyobjloader-dev) and
// checked before a chapter sees them: --model FILE in chapters 5, 10-15 and 17.
#pragma once

#include <array>
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace cgfs {

// A model as its file gives it: triangles (polygons triangulated by tinyobjloader), in
// the file's own coordinates (OBJ's: right-handed, y up, the front facing +z).
struct ModelFile {
  struct Material {
    std::string name;
    glm::dvec3 diffuse{200, 200, 200};  // Kd, 0..255; light grey when the file gives none
    std::filesystem::path texture;      // map_Kd, beside the material library; empty: none
  };
  // A triangle's corner: indices into positions, normals and uvs; -1 where the file
  // gives none.
  struct Corner {
    int position = 0;
    int normal = -1;
    int uv = -1;
  };
  struct Face {
    std::array<Corner, 3> corners;
    int material = -1;  // index into materials; -1: none
  };

  std::vector<glm::dvec3> positions;
  std::vector<glm::dvec3> normals;
  std::vector<glm::dvec2> uvs;  // OBJ's (u, v): v = 0 at the bottom of the image
  std::vector<Face> faces;
  std::vector<Material> materials;
  // What was left out, one line each: a material library or texture that cannot be
  // read, triangles with no area. The model is drawn without them.
  std::vector<std::string> warnings;
};

// What a model file may hold, checked on its text before tinyobjloader parses it (its
// memory and time grow with these; docs/testing.md gives the peak memory each allows):
// the file's bytes; its vertices (v, vn and vt lines, each); its triangles once polygons
// are split; the corners of one polygon (tinyobjloader splits a polygon of n corners in
// up to n^3 steps); the times it changes material (usemtl; each starts a new run of
// faces); the material libraries it names (mtllib; each read once, by its real path);
// the materials of its libraries together (newmtl; tinyobjloader keeps 2.7 KB each).
inline constexpr std::size_t kMaxModelFileBytes = 128u << 20;
inline constexpr std::size_t kMaxModelVertices = 1'000'000;
inline constexpr std::size_t kMaxModelTriangles = 750'000;
inline constexpr std::size_t kMaxPolygonCorners = 1024;
inline constexpr std::size_t kMaxMaterialSwitches = 65'536;
inline constexpr std::size_t kMaxMaterialLibraries = 16;
inline constexpr std::size_t kMaxMaterials = 4096;

// How many times over the boxes of a model's triangles may cover its outline (the sum of
// the largest face of each triangle's box over pi r^2, r its bounding sphere's radius; a
// closed surface: a few). Triangles that lie on one another cannot be told apart by a ray
// tracer's hierarchy: a ray tests each layer it meets, and a rasterizer shades each. At
// this bound the slowest chapter draws a frame at the default size in under a minute
// (docs/testing.md).
inline constexpr double kMaxModelCoverage = 1000;

// Reads an OBJ file and the material libraries it names (looked for beside it). Throws
// cgfs::Error with one line for a file that cannot be read or is not such a model: not
// a regular file, too large, not text, an index of 0, past 2147483647 or out of range, a
// coordinate that is not a finite number, a name with control characters, no triangle
// with an area, triangles in more than kMaxModelCoverage layers. A material library
// that cannot be read, or holds too many materials, is a warning; so are the lines left
// out (faces of fewer than three corners, libraries named again or past the bound),
// each said once with a count.
ModelFile ReadModelFile(const std::filesystem::path& path);

// The same for text already read (the fuzz target's entry), which it takes over;
// material libraries are read only if `folder` is not empty. `path` only names the file
// in messages.
ModelFile ParseModelFile(std::string text, const std::filesystem::path& path,
                         const std::filesystem::path& folder);

}  // namespace cgfs
