#include "program/model_file.h"

#include <tiny_obj_loader.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <sstream>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>

#include "program/error.h"
#include "program/file_reading.h"

namespace cgfs {

namespace fs = std::filesystem;

namespace {

// A material library is text of a few lines a material.
constexpr std::uintmax_t kMaxMaterialFileBytes = 16u << 20;
// The work of splitting polygons of more than four corners, summed over the file:
// tinyobjloader's ear clipping takes up to n^3 steps for n corners.
constexpr double kMaxPolygonWork = 4.0e9;

std::string LineNumber(std::size_t line) {
  return "line " + std::to_string(line);
}

// What a file holds, counted on its text before tinyobjloader is given it, so that
// nothing too large for the machine is ever allocated or split.
struct TextCounts {
  std::size_t vertices = 0;   // v, vn and vt lines, the largest of the three
  std::size_t triangles = 0;  // what the f lines make once split
};

// A coordinate tinyobjloader would read as 0 without a word: "nan", "inf", "x". (Its
// own parser reads what it can of the rest, "3.1+e2" as 3.1, as other programs do.)
bool NotANumber(std::string_view word) {
  if (!word.empty() && (word[0] == '+' || word[0] == '-')) {
    word.remove_prefix(1);
  }
  return word.empty() || !((word[0] >= '0' && word[0] <= '9') || word[0] == '.');
}

// A face's corner "v", "v/vt", "v//vn" or "v/vt/vn" with an index 0, which OBJ has not:
// its indices count from 1 (and back from -1).
bool HasIndexZero(std::string_view corner) {
  for (std::size_t at = 0; at <= corner.size();) {
    const std::size_t slash = std::min(corner.find('/', at), corner.size());
    std::string_view index = corner.substr(at, slash - at);
    if (!index.empty() && (index[0] == '+' || index[0] == '-')) {
      index.remove_prefix(1);
    }
    if (!index.empty() && index.find_first_not_of('0') == std::string_view::npos) {
      return true;
    }
    at = slash + 1;
  }
  return false;
}

// One line, counted (a vertex, or the triangles a face makes once split), with its
// coordinates and indices checked.
void CountLine(std::string_view line, std::size_t number, std::array<std::size_t, 3>& vertices,
               TextCounts& counts, double& polygon_work, const fs::path& path) {
  std::size_t words = 0;
  std::string_view first;
  std::size_t at = 0;
  while (at < line.size()) {
    while (at < line.size() && (line[at] == ' ' || line[at] == '\t' || line[at] == '\r')) {
      ++at;
    }
    const std::size_t start = at;
    while (at < line.size() && line[at] != ' ' && line[at] != '\t' && line[at] != '\r') {
      ++at;
    }
    if (at > start) {
      const std::string_view word = line.substr(start, at - start);
      if (words == 0) {
        first = word;
      } else if ((first == "v" || first == "vn" || first == "vt") && NotANumber(word)) {
        throw Error(Quoted(path) + ", " + LineNumber(number) + ": '" + std::string(word) +
                    "' is not a number");
      } else if (first == "f" && HasIndexZero(word)) {
        throw Error(Quoted(path) + ", " + LineNumber(number) + ": '" + std::string(word) +
                    "' has an index 0 (OBJ counts from 1)");
      }
      ++words;
    }
  }
  if (first == "v") {
    ++vertices[0];
  } else if (first == "vn") {
    ++vertices[1];
  } else if (first == "vt") {
    ++vertices[2];
  } else if (first == "f" && words >= 4) {
    const std::size_t corners = words - 1;
    if (corners > kMaxPolygonCorners) {
      throw Error(Quoted(path) + ", " + LineNumber(number) + ": a polygon of " +
                  std::to_string(corners) + " corners (at most " +
                  std::to_string(kMaxPolygonCorners) + ")");
    }
    counts.triangles += corners - 2;
    if (corners > 4) {
      polygon_work += std::pow(static_cast<double>(corners), 3);
    }
  }
}

// Refuses text that is not an OBJ model's, or that would take too much to read.
TextCounts CountText(const std::string& text, const fs::path& path) {
  std::array<std::size_t, 3> vertices{};
  TextCounts counts;
  double polygon_work = 0;
  std::size_t number = 1;
  std::size_t start = 0;
  for (std::size_t at = 0; at <= text.size(); ++at) {
    // Lines end in LF, CR LF or CR alone, as tinyobjloader reads them.
    const unsigned char c = at < text.size() ? static_cast<unsigned char>(text[at]) : '\n';
    if (c == '\n' || c == '\r') {
      CountLine(std::string_view(text).substr(start, at - start), number, vertices, counts,
                polygon_work, path);
      ++number;
      if (c == '\r' && at + 1 < text.size() && text[at + 1] == '\n') {
        ++at;
      }
      start = at + 1;
    } else if ((c < 0x20 && c != '\t' && c != '\r') || c == 0x7f) {
      throw Error(Quoted(path) + ", " + LineNumber(number) +
                  (c == 0 ? ": a NUL byte: not a text OBJ file (UTF-16 is not read)"
                          : ": a control character: not a text OBJ file"));
    }
  }
  counts.vertices = std::max({vertices[0], vertices[1], vertices[2]});
  if (counts.vertices > kMaxModelVertices || counts.triangles > kMaxModelTriangles) {
    throw Error(Quoted(path) + " is too large a model: " + std::to_string(counts.vertices) +
                " vertices and " + std::to_string(counts.triangles) + " triangles (at most " +
                std::to_string(kMaxModelVertices) + " vertices and " +
                std::to_string(kMaxModelTriangles) + " triangles)");
  }
  if (polygon_work > kMaxPolygonWork) {
    throw Error(Quoted(path) + " has too many polygons of many corners to split into triangles");
  }
  return counts;
}

// OBJ files made on Windows name files with backslashes ("map_Kd .\\crate.jpg").
fs::path FileNamed(const fs::path& folder, std::string name) {
  for (char& c : name) {
    if (c == '\\') {
      c = '/';
    }
  }
  return folder / name;
}

// tinyobjloader's way to read a material library, made safe: the library is read as
// any input file is (a regular file, bounded), and one that cannot be read is a
// warning, never an error.
class MaterialLibraries final : public tinyobj::MaterialReader {
 public:
  MaterialLibraries(fs::path folder, std::vector<std::string>& warnings)
      : folder_(std::move(folder)), warnings_(warnings) {}

  bool operator()(const std::string& name, std::vector<tinyobj::material_t>* materials,
                  std::map<std::string, int>* names, std::string* warning,
                  std::string* error) override {
    if (folder_.empty()) {
      return false;
    }
    const fs::path path = FileNamed(folder_, name);
    try {
      std::istringstream text(ReadWholeFile(path, kMaxMaterialFileBytes));
      tinyobj::LoadMtl(names, materials, &text, warning, error);
      folders_.push_back(path.parent_path());
      return true;
    } catch (const Error& cannot_read) {
      warnings_.push_back(std::string("material library: ") + cannot_read.what() +
                          "; drawn without its materials");
      return false;
    }
  }

  // The folder of the library the materials came from (a texture is named from it).
  fs::path Folder() const { return folders_.empty() ? folder_ : folders_.front(); }

 private:
  fs::path folder_;
  std::vector<std::string>& warnings_;
  std::vector<fs::path> folders_;
};

bool Finite(const std::vector<double>& values) {
  for (const double value : values) {
    if (!std::isfinite(value)) {
      return false;
    }
  }
  return true;
}

// The file's numbers, checked: every coordinate a finite number.
void TakeAttributes(const tinyobj::attrib_t& attributes, const fs::path& path, ModelFile& model) {
  if (!Finite(attributes.vertices) || !Finite(attributes.normals) ||
      !Finite(attributes.texcoords)) {
    throw Error(Quoted(path) + " has a coordinate that is not a finite number");
  }
  const auto& v = attributes.vertices;
  for (std::size_t i = 0; i + 2 < v.size(); i += 3) {
    model.positions.emplace_back(v[i], v[i + 1], v[i + 2]);
  }
  const auto& n = attributes.normals;
  for (std::size_t i = 0; i + 2 < n.size(); i += 3) {
    model.normals.emplace_back(n[i], n[i + 1], n[i + 2]);
  }
  const auto& t = attributes.texcoords;
  for (std::size_t i = 0; i + 1 < t.size(); i += 2) {
    model.uvs.emplace_back(t[i], t[i + 1]);
  }
}

int CheckedIndex(int index, std::size_t count, bool optional, const char* what,
                 const fs::path& path) {
  if (optional && index == -1) {
    return -1;
  }
  if (index < 0 || static_cast<std::size_t>(index) >= count) {
    throw Error(Quoted(path) + ": a face refers to " + what + " " +
                std::to_string(static_cast<long long>(index) + 1) + " of " + std::to_string(count));
  }
  return index;
}

bool HasArea(const ModelFile& model, const ModelFile::Face& face) {
  const glm::dvec3& a = model.positions[static_cast<std::size_t>(face.corners[0].position)];
  const glm::dvec3& b = model.positions[static_cast<std::size_t>(face.corners[1].position)];
  const glm::dvec3& c = model.positions[static_cast<std::size_t>(face.corners[2].position)];
  const double area = glm::length(glm::cross(b - a, c - a));
  return area > 0 && std::isfinite(area);
}

// Every shape's triangles, each index checked; triangles without an area left out.
void TakeFaces(const std::vector<tinyobj::shape_t>& shapes, std::size_t materials,
               const fs::path& path, ModelFile& model) {
  std::size_t without_area = 0;
  for (const tinyobj::shape_t& shape : shapes) {
    const tinyobj::mesh_t& mesh = shape.mesh;
    for (std::size_t f = 0; f < mesh.num_face_vertices.size(); ++f) {
      ModelFile::Face face;
      for (std::size_t k = 0; k < 3; ++k) {
        const tinyobj::index_t& index = mesh.indices[3 * f + k];
        face.corners[k] = {
            CheckedIndex(index.vertex_index, model.positions.size(), false, "vertex", path),
            CheckedIndex(index.normal_index, model.normals.size(), true, "normal", path),
            CheckedIndex(index.texcoord_index, model.uvs.size(), true, "texture coordinate", path)};
      }
      const int material = f < mesh.material_ids.size() ? mesh.material_ids[f] : -1;
      face.material =
          material >= 0 && static_cast<std::size_t>(material) < materials ? material : -1;
      if (HasArea(model, face)) {
        model.faces.push_back(face);
      } else {
        ++without_area;
      }
    }
  }
  if (model.faces.empty()) {
    throw Error(Quoted(path) + (without_area > 0 ? " has no triangle with an area"
                                                 : " has no faces (points and lines are "
                                                   "not drawn)"));
  }
  if (without_area > 0) {
    model.warnings.push_back(std::to_string(without_area) +
                             (without_area == 1 ? " triangle" : " triangles") +
                             " without an area left out");
  }
}

void TakeMaterials(const std::vector<tinyobj::material_t>& materials, const fs::path& folder,
                   ModelFile& model) {
  for (const tinyobj::material_t& material : materials) {
    ModelFile::Material taken;
    taken.name = material.name;
    const glm::dvec3 diffuse(material.diffuse[0], material.diffuse[1], material.diffuse[2]);
    if (std::isfinite(diffuse.x) && std::isfinite(diffuse.y) && std::isfinite(diffuse.z)) {
      taken.diffuse = glm::clamp(diffuse, 0.0, 1.0) * 255.0;
    }
    if (!material.diffuse_texname.empty()) {
      taken.texture = FileNamed(folder, material.diffuse_texname);
    }
    model.materials.push_back(taken);
  }
}

// tinyobjloader (2.0.0rc10) splits a polygon of more than four corners by clipping ears,
// and gives up on some concave ones part of the way: what it did not make is said.
void NoteUnsplitPolygons(const std::vector<tinyobj::shape_t>& shapes, const TextCounts& counts,
                         ModelFile& model) {
  std::size_t made = 0;
  for (const tinyobj::shape_t& shape : shapes) {
    made += shape.mesh.num_face_vertices.size();
  }
  if (made < counts.triangles) {
    model.warnings.push_back("tinyobjloader split its polygons into " + std::to_string(made) +
                             " of the " + std::to_string(counts.triangles) +
                             " triangles they make: " + std::to_string(counts.triangles - made) +
                             " not drawn");
  }
}

// tinyobjloader's first error line, as ours.
[[noreturn]] void FailParsing(const std::string& error, const fs::path& path) {
  std::string line = error.substr(0, error.find('\n'));
  if (line.empty()) {
    line = "not a Wavefront OBJ model";
  }
  throw Error("cannot read the model " + Quoted(path) + ": " + line);
}

}  // namespace

ModelFile ParseModelFile(const std::string& text, const fs::path& path, const fs::path& folder) {
  const TextCounts counts = CountText(text, path);
  ModelFile model;
  MaterialLibraries libraries(folder, model.warnings);
  tinyobj::attrib_t attributes;
  std::vector<tinyobj::shape_t> shapes;
  std::vector<tinyobj::material_t> materials;
  std::string warning;
  std::string error;
  std::istringstream stream(text);
  if (!tinyobj::LoadObj(&attributes, &shapes, &materials, &warning, &error, &stream, &libraries,
                        /*triangulate=*/true, /*default_vcols_fallback=*/false)) {
    FailParsing(error, path);
  }
  if (warning.find("invalid vertex index") != std::string::npos) {
    throw Error(Quoted(path) + ": a face refers to a vertex the file does not have");
  }
  TakeAttributes(attributes, path, model);
  NoteUnsplitPolygons(shapes, counts, model);
  TakeFaces(shapes, materials.size(), path, model);
  TakeMaterials(materials, libraries.Folder(), model);
  return model;
}

ModelFile ReadModelFile(const fs::path& path) {
  const std::string text = ReadWholeFile(path, kMaxModelFileBytes);
  fs::path folder = path.parent_path();
  if (folder.empty()) {
    folder = ".";
  }
  return ParseModelFile(text, path, folder);
}

}  // namespace cgfs
