#include "program/model_file.h"

#include <tiny_obj_loader.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <set>
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

// A material library is text of a few lines a material (kMaxMaterials of them).
constexpr std::uintmax_t kMaxMaterialFileBytes = 16u << 20;
// The work of splitting polygons of more than four corners, summed over the file:
// tinyobjloader's ear clipping takes up to n^3 steps for n corners.
constexpr double kMaxPolygonWork = 4.0e9;

std::string LineNumber(std::size_t line) {
  return "line " + std::to_string(line);
}

// What a file holds, counted on its text as it is made ready for tinyobjloader, so that
// nothing too large for the machine is ever allocated or split.
struct TextCounts {
  std::array<std::size_t, 3> vertices{};  // v, vn and vt lines
  std::size_t triangles = 0;              // what the f lines make once split
  std::size_t material_switches = 0;      // usemtl lines that change the material
  std::size_t short_faces = 0;            // f lines of fewer than three corners, left out
  std::size_t repeated_libraries = 0;     // mtllib lines naming a library already named
  std::size_t libraries_past_bound = 0;   // mtllib lines past kMaxMaterialLibraries
  double polygon_work = 0;
  std::string material;             // the last usemtl kept
  std::set<std::string> libraries;  // the mtllib lines kept, by what they name
};

// A coordinate tinyobjloader would read as 0 without a word: "nan", "inf", "x". (Its
// own parser reads what it can of the rest, "3.1+e2" as 3.1, as other programs do.)
bool NotANumber(std::string_view word) {
  if (!word.empty() && (word[0] == '+' || word[0] == '-')) {
    word.remove_prefix(1);
  }
  return word.empty() || !((word[0] >= '0' && word[0] <= '9') || word[0] == '.');
}

// A face's corner "v", "v/vt", "v//vn" or "v/vt/vn", checked: OBJ has no index 0 (its
// indices count from 1, and back from -1), and tinyobjloader reads an index into an int,
// so one past 2147483647 would wrap to another vertex.
void CheckCorner(std::string_view corner, const fs::path& path, std::size_t number) {
  const auto refuse = [&](const std::string& what) {
    throw Error(Quoted(path) + ", " + LineNumber(number) + ": '" + std::string(corner) + "' " +
                what);
  };
  for (std::size_t at = 0; at <= corner.size();) {
    const std::size_t slash = std::min(corner.find('/', at), corner.size());
    std::string_view index = corner.substr(at, slash - at);
    if (!index.empty() && (index[0] == '+' || index[0] == '-')) {
      index.remove_prefix(1);
    }
    const std::size_t first = std::min(index.find_first_not_of('0'), index.size());
    const std::string_view digits = index.substr(first);
    if (!index.empty() && digits.empty()) {
      refuse("has an index 0 (OBJ counts from 1)");
    }
    if (digits.size() > 10 || (digits.size() == 10 && digits > "2147483647")) {
      refuse("has an index past 2147483647");
    }
    at = slash + 1;
  }
}

// What parts a line's words, as tinyobjloader reads them.
bool IsSpace(char c) {
  return c == ' ' || c == '\t' || c == '\r';
}

// The line's words (at most `most`; the rest of the line is one more word).
std::vector<std::string_view> Words(std::string_view line, std::size_t most) {
  std::vector<std::string_view> words;
  std::size_t at = 0;
  while (at < line.size()) {
    while (at < line.size() && IsSpace(line[at])) {
      ++at;
    }
    if (at == line.size()) {
      break;
    }
    if (words.size() == most) {
      std::size_t end = line.size();
      while (end > at && IsSpace(line[end - 1])) {
        --end;
      }
      words.push_back(line.substr(at, end - at));
      break;
    }
    const std::size_t start = at;
    while (at < line.size() && !IsSpace(line[at])) {
      ++at;
    }
    words.push_back(line.substr(start, at - start));
  }
  return words;
}

// A face line: its corners checked and its triangles counted; whether it is kept (a
// face of fewer than three corners is not: it draws nothing).
bool CountFace(std::string_view line, std::size_t number, TextCounts& counts,
               const fs::path& path) {
  std::size_t corners = 0;  // the words after "f", counted before any is kept
  bool in_word = false;
  for (const char c : line) {
    corners += !IsSpace(c) && !in_word;
    in_word = !IsSpace(c);
  }
  corners -= 1;
  if (corners > kMaxPolygonCorners) {
    throw Error(Quoted(path) + ", " + LineNumber(number) + ": a polygon of " +
                std::to_string(corners) + " corners (at most " +
                std::to_string(kMaxPolygonCorners) + ")");
  }
  const std::vector<std::string_view> words = Words(line, kMaxPolygonCorners + 1);
  for (std::size_t k = 1; k < words.size(); ++k) {
    CheckCorner(words[k], path, number);
  }
  if (corners < 3) {
    ++counts.short_faces;
    return false;
  }
  counts.triangles += corners - 2;
  if (corners > 4) {
    counts.polygon_work += std::pow(static_cast<double>(corners), 3);
  }
  return true;
}

// One line, checked and counted; whether tinyobjloader is given it. It is given what
// the chapters draw: vertices, faces, materials and their libraries. Lines, points,
// groups, objects, smoothing groups and tags are not (tinyobjloader would keep each
// of them, a part, a name or a tag's values, in memory the file's size does not bound).
bool CountLine(std::string_view line, std::size_t number, TextCounts& counts,
               const fs::path& path) {
  const std::vector<std::string_view> words = Words(line, 1);
  const std::string_view first = words.empty() ? std::string_view() : words[0];
  const std::string_view rest = words.size() > 1 ? words[1] : std::string_view();
  if (first == "v" || first == "vn" || first == "vt") {
    for (const std::string_view word : Words(rest, 6)) {
      if (NotANumber(word)) {
        throw Error(Quoted(path) + ", " + LineNumber(number) + ": '" + std::string(word) +
                    "' is not a number");
      }
    }
    ++counts.vertices[first == "v" ? 0 : first == "vn" ? 1 : 2];
    return true;
  }
  if (first == "f") {
    return CountFace(line, number, counts, path);
  }
  if (first == "usemtl") {
    if (rest == counts.material) {
      return false;
    }
    counts.material = std::string(rest);
    return ++counts.material_switches <= kMaxMaterialSwitches;
  }
  if (first == "mtllib") {
    if (counts.libraries.count(std::string(rest)) > 0) {
      ++counts.repeated_libraries;
      return false;
    }
    if (counts.libraries.size() == kMaxMaterialLibraries) {
      ++counts.libraries_past_bound;
      return false;
    }
    counts.libraries.insert(std::string(rest));
    return true;
  }
  return false;
}

// Refuses text that is not an OBJ model's, or that would take too much to read; what is
// kept of it for tinyobjloader (see CountLine) is moved to its front, each line ending in
// LF, and the rest cut off: the text is made ready where it lies, without a copy.
TextCounts PrepareText(std::string& text, const fs::path& path) {
  TextCounts counts;
  std::size_t number = 1;
  std::size_t start = 0;
  std::size_t written = 0;
  for (std::size_t at = 0; at <= text.size(); ++at) {
    // Lines end in LF, CR LF or CR alone, as tinyobjloader reads them.
    const unsigned char c = at < text.size() ? static_cast<unsigned char>(text[at]) : '\n';
    if (c == '\n' || c == '\r') {
      if (CountLine(std::string_view(text).substr(start, at - start), number, counts, path)) {
        std::copy(text.begin() + static_cast<std::ptrdiff_t>(start),
                  text.begin() + static_cast<std::ptrdiff_t>(at),
                  text.begin() + static_cast<std::ptrdiff_t>(written));
        written += at - start;
        if (written < text.size()) {
          text[written++] = '\n';
        }
      }
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
  text.resize(written);
  text.shrink_to_fit();
  const std::size_t vertices =
      std::max({counts.vertices[0], counts.vertices[1], counts.vertices[2]});
  if (vertices > kMaxModelVertices || counts.triangles > kMaxModelTriangles) {
    throw Error(Quoted(path) + " is too large a model: " + std::to_string(vertices) +
                " vertices and " + std::to_string(counts.triangles) + " triangles (at most " +
                std::to_string(kMaxModelVertices) + " vertices and " +
                std::to_string(kMaxModelTriangles) + " triangles)");
  }
  if (counts.material_switches > kMaxMaterialSwitches) {
    throw Error(Quoted(path) + " changes material " + std::to_string(counts.material_switches) +
                " times (usemtl; at most " + std::to_string(kMaxMaterialSwitches) + ")");
  }
  if (counts.polygon_work > kMaxPolygonWork) {
    throw Error(Quoted(path) + " has too many polygons of many corners to split into triangles");
  }
  return counts;
}

// What was left out of the text, said once each with its count.
void NoteLeftOut(const TextCounts& counts, ModelFile& model) {
  const auto lines = [](std::size_t n) {
    return std::to_string(n) + (n == 1 ? " line" : " lines");
  };
  if (counts.short_faces > 0) {
    model.warnings.push_back(std::to_string(counts.short_faces) +
                             (counts.short_faces == 1 ? " face" : " faces") +
                             " of fewer than three corners left out");
  }
  if (counts.repeated_libraries > 0) {
    model.warnings.push_back(lines(counts.repeated_libraries) +
                             " naming a material library already named left out (mtllib)");
  }
  if (counts.libraries_past_bound > 0) {
    model.warnings.push_back(lines(counts.libraries_past_bound) + " naming more than " +
                             std::to_string(kMaxMaterialLibraries) +
                             " material libraries left out (mtllib)");
  }
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

// How many materials a library's text defines (its newmtl lines).
std::size_t MaterialCount(const std::string& text) {
  std::size_t count = 0;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    const std::size_t first = line.find_first_not_of(" \t");
    count += first != std::string::npos && line.compare(first, 7, "newmtl ") == 0;
  }
  return count;
}

// tinyobjloader's way to read a material library, made safe: the library is read as
// any input file is (a regular file, bounded), once however many names it goes by, and
// one that cannot be read or holds too many materials is a warning, never an error.
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
    std::error_code no_such_file;
    const fs::path real = fs::weakly_canonical(path, no_such_file);
    if (!no_such_file && !read_.insert(real).second) {
      return true;  // read already, under another name
    }
    try {
      const std::string text = ReadWholeFile(path, kMaxMaterialFileBytes);
      const std::size_t count = MaterialCount(text);
      if (materials->size() + count > kMaxMaterials) {
        warnings_.push_back("material library " + Quoted(path) + " would make " +
                            std::to_string(materials->size() + count) + " materials (at most " +
                            std::to_string(kMaxMaterials) + "); drawn without its materials");
        return false;
      }
      std::istringstream stream(text);
      tinyobj::LoadMtl(names, materials, &stream, warning, error);
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
  std::set<fs::path> read_;  // the libraries read, by their real paths
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

// Whether the triangle has an area, however large its coordinates: they are scaled by
// the largest of them first (the square of 1e160 is not a double).
bool HasArea(const ModelFile& model, const ModelFile::Face& face) {
  const glm::dvec3& a = model.positions[static_cast<std::size_t>(face.corners[0].position)];
  const glm::dvec3& b = model.positions[static_cast<std::size_t>(face.corners[1].position)];
  const glm::dvec3& c = model.positions[static_cast<std::size_t>(face.corners[2].position)];
  double largest = 0;
  for (const glm::dvec3& p : {a, b, c}) {
    largest = std::max({largest, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
  }
  if (largest == 0) {
    return false;
  }
  const double area = glm::length(glm::cross(b / largest - a / largest, c / largest - a / largest));
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

// How many times over the boxes of the model's triangles cover the disc of its bounding
// sphere: the sum of the largest face of each triangle's box over pi r^2, with r the
// distance from the centre of the model's box to its farthest corner, as the chapters
// place a model. A ray tracer's hierarchy tests a triangle for every ray that enters its
// box (a long diagonal sliver's box is large); a rasterizer shades less than its box.
// A closed surface covers it a few times (the models tried: 0.6 to 9); triangles piled on
// one another, as many times as there are layers. Computed in units of the model's size
// (no area overflows).
double Coverage(const ModelFile& model) {
  glm::dvec3 low = model.positions[static_cast<std::size_t>(model.faces[0].corners[0].position)];
  glm::dvec3 high = low;
  for (const ModelFile::Face& face : model.faces) {
    for (const ModelFile::Corner& corner : face.corners) {
      low = glm::min(low, model.positions[static_cast<std::size_t>(corner.position)]);
      high = glm::max(high, model.positions[static_cast<std::size_t>(corner.position)]);
    }
  }
  const glm::dvec3 scale = glm::max(glm::abs(low), glm::abs(high));
  const double unit = std::max({scale.x, scale.y, scale.z});
  const glm::dvec3 centre = low / unit / 2.0 + high / unit / 2.0;
  double radius = 0;
  double area = 0;
  for (const ModelFile::Face& face : model.faces) {
    glm::dvec3 box_low(std::numeric_limits<double>::max());
    glm::dvec3 box_high(std::numeric_limits<double>::lowest());
    for (const ModelFile::Corner& corner : face.corners) {
      const glm::dvec3 p = model.positions[static_cast<std::size_t>(corner.position)] / unit;
      radius = std::max(radius, glm::length(p - centre));
      box_low = glm::min(box_low, p);
      box_high = glm::max(box_high, p);
    }
    const glm::dvec3 size = box_high - box_low;
    area += std::max({size.x * size.y, size.y * size.z, size.z * size.x});
  }
  return area / (std::acos(-1.0) * radius * radius);
}

// Refuses a model whose triangles lie in more layers than a frame can be drawn through
// in a minute (kMaxModelCoverage).
void CheckCoverage(const ModelFile& model, const fs::path& path) {
  const double coverage = Coverage(model);
  if (coverage > kMaxModelCoverage) {
    throw Error(Quoted(path) +
                ": its triangles lie on one another: their boxes cover the "
                "model's outline " +
                std::to_string(static_cast<long long>(coverage)) + " times over (at most " +
                std::to_string(static_cast<long long>(kMaxModelCoverage)) +
                "; a frame would take minutes)");
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

// A stream that reads a string where it lies (std::istringstream would copy it).
class StringReader final : public std::streambuf {
 public:
  explicit StringReader(std::string& text) {
    setg(text.data(), text.data(), text.data() + text.size());
  }
};

// tinyobjloader's first error line, as ours.
[[noreturn]] void FailParsing(const std::string& error, const fs::path& path) {
  std::string line = error.substr(0, error.find('\n'));
  if (line.empty()) {
    line = "not a Wavefront OBJ model";
  }
  throw Error("cannot read the model " + Quoted(path) + ": " + line);
}

}  // namespace

ModelFile ParseModelFile(std::string text, const fs::path& path, const fs::path& folder) {
  const TextCounts counts = PrepareText(text, path);
  ModelFile model;
  NoteLeftOut(counts, model);
  MaterialLibraries libraries(folder, model.warnings);
  tinyobj::attrib_t attributes;
  std::vector<tinyobj::shape_t> shapes;
  std::vector<tinyobj::material_t> materials;
  std::string warning;
  std::string error;
  StringReader reader(text);
  std::istream stream(&reader);
  if (!tinyobj::LoadObj(&attributes, &shapes, &materials, &warning, &error, &stream, &libraries,
                        /*triangulate=*/true, /*default_vcols_fallback=*/false)) {
    FailParsing(error, path);
  }
  std::string().swap(text);  // what is read is no longer needed: the peak is lower
  if (warning.find("invalid vertex index") != std::string::npos) {
    throw Error(Quoted(path) + ": a face refers to a vertex the file does not have");
  }
  TakeAttributes(attributes, path, model);
  attributes = {};
  NoteUnsplitPolygons(shapes, counts, model);
  TakeFaces(shapes, materials.size(), path, model);
  CheckCoverage(model, path);
  TakeMaterials(materials, libraries.Folder(), model);
  return model;
}

ModelFile ReadModelFile(const fs::path& path) {
  std::string text = ReadWholeFile(path, kMaxModelFileBytes);
  fs::path folder = path.parent_path();
  if (folder.empty()) {
    folder = ".";
  }
  return ParseModelFile(std::move(text), path, folder);
}

}  // namespace cgfs
