#include "options.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <map>
#include <memory>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

#include <glm/geometric.hpp>

#include "program/arguments.h"
#include "program/error.h"
#include "program/image_files.h"
#include "program/model_file.h"

namespace {

// OBJ's right-handed coordinates in the book's left-handed ones.
Vec3 BookCoordinates(const glm::dvec3& v) {
  return {v.x, v.y, -v.z};
}

// Every edge used once in each direction: a surface without holes, consistently wound.
bool IsClosed(const Model& model) {
  std::vector<std::pair<int, int>> edges;  // (from, to) of every triangle, sorted
  edges.reserve(3 * model.triangles.size());
  for (const Triangle& triangle : model.triangles) {
    for (int k = 0; k < 3; ++k) {
      edges.emplace_back(triangle.v[k], triangle.v[(k + 1) % 3]);
    }
  }
  std::sort(edges.begin(), edges.end());
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const bool again = e + 1 < edges.size() && edges[e + 1] == edges[e];
    const std::pair<int, int> back(edges[e].second, edges[e].first);
    if (again || !std::binary_search(edges.begin(), edges.end(), back)) {
      return false;
    }
  }
  return true;
}

// The normals at a triangle's corners, taken in the triangle's order: the file's, or
// the triangle's own, (V1 - V0) x (V2 - V0) made of length 1.
std::array<Vec3, 3> CornerNormals(const cgfs::ModelFile& file,
                                  const std::array<cgfs::ModelFile::Corner, 3>& corners,
                                  const Model& model, const Triangle& triangle) {
  const Vec3& A = model.vertices[triangle.v[0]];
  const Vec3 own = glm::normalize(
      glm::cross(model.vertices[triangle.v[1]] - A, model.vertices[triangle.v[2]] - A));
  std::array<Vec3, 3> normals;
  for (int k = 0; k < 3; ++k) {
    const int given = corners[k].normal;
    const Vec3 normal =
        given >= 0 ? BookCoordinates(file.normals[static_cast<std::size_t>(given)]) : Vec3(0);
    normals[k] = glm::length(normal) > 0 ? glm::normalize(normal) : own;
  }
  return normals;
}

// One texture file as the model's materials share it: read once, by its real path.
struct SharedTexture {
  std::shared_ptr<const MipmappedTexture> texture;  // none: it could not be used
  std::string why_not;                              // the warning's words, if so
  std::string first_material;
  std::size_t materials = 0;
};

// Each material's texture (map_Kd) with its mip chain, or none where it has none, it
// cannot be read, or it would take the model's textures past kMaxModelTexels: said in
// one warning for each such file, with how many materials name it.
std::vector<std::shared_ptr<const MipmappedTexture>> MaterialTextures(const cgfs::ModelFile& file,
                                                                      const std::string& name) {
  std::map<std::filesystem::path, SharedTexture> files;
  std::vector<std::filesystem::path> order;  // the files in the order materials name them
  std::size_t texels = 0;
  std::vector<std::shared_ptr<const MipmappedTexture>> textures;
  for (const cgfs::ModelFile::Material& material : file.materials) {
    if (material.texture.empty()) {
      textures.emplace_back();
      continue;
    }
    std::error_code not_there;
    std::filesystem::path real = std::filesystem::weakly_canonical(material.texture, not_there);
    auto [shared, first] = files.try_emplace(not_there ? material.texture : real);
    if (first) {
      order.push_back(shared->first);
      shared->second.first_material = material.name;
      try {
        Texture texture = LoadTexture(material.texture);
        if (texels + texture.texels.size() > kMaxModelTexels) {
          shared->second.why_not = "'" + material.texture.string() +
                                   "' would take the model's textures past " +
                                   std::to_string(kMaxModelTexels) + " texels";
        } else {
          texels += texture.texels.size();
          shared->second.texture =
              std::make_shared<const MipmappedTexture>(BuildMipChain(std::move(texture)));
        }
      } catch (const cgfs::Error& error) {
        shared->second.why_not = error.what();
      }
    }
    ++shared->second.materials;
    textures.push_back(shared->second.texture);
  }
  for (const std::filesystem::path& each : order) {
    const SharedTexture& shared = files[each];
    if (!shared.why_not.empty()) {
      const std::string more =
          shared.materials > 1 ? " (and " + std::to_string(shared.materials - 1) + " more)" : "";
      cgfs::Warn(name + ": material " + shared.first_material + more + ": " + shared.why_not +
                 "; drawn in its colour");
    }
  }
  return textures;
}

}  // namespace

void AddChapterOptions(CLI::App& app, ChapterSettings& settings) {
  auto file = std::make_shared<std::string>();
  auto texture_file = std::make_shared<std::string>();
  cgfs::AddTextOption(app, "model", *file,
                      "a Wavefront OBJ model to draw instead of the chapter's figures (the "
                      "figure 'model', in front of the camera)",
                      "FILE.obj");
  cgfs::AddTextOption(app, "texture", *texture_file,
                      "a PNG, JPEG or PPM image (at most 2048 pixels a side) to paint on the "
                      "crates, or on the model, instead of the project's own crate texture",
                      "FILE");
  cgfs::AfterParsing(app, [file, texture_file, &settings] {
    if (!texture_file->empty()) {
      settings.crate_texture =
          std::make_shared<const MipmappedTexture>(BuildMipChain(LoadTexture(*texture_file)));
    }
    if (file->empty()) {
      return;
    }
    const cgfs::ModelFile model = cgfs::ReadModelFile(*file);
    for (const std::string& warning : model.warnings) {
      cgfs::Warn(*file + ": " + warning);
    }
    settings.model_textures = MaterialTextures(model, *file);
    std::vector<const MipmappedTexture*> by_material;
    for (const auto& texture : settings.model_textures) {
      by_material.push_back(texture.get());
    }
    settings.model = std::make_shared<const std::vector<Model>>(
        PaintedParts(ModelFromFile(model), model, by_material, settings.crate_texture.get()));
    settings.model_name = std::filesystem::path(*file).filename().string();
  });
}

Model ModelFromFile(const cgfs::ModelFile& file) {
  Model model;
  for (const glm::dvec3& position : file.positions) {
    model.vertices.push_back(BookCoordinates(position));
  }
  for (const cgfs::ModelFile::Face& face : file.faces) {
    // Its corners the other way round (see options.h).
    const std::array<cgfs::ModelFile::Corner, 3> corners = {face.corners[0], face.corners[2],
                                                            face.corners[1]};
    const Color color = face.material >= 0
                            ? file.materials[static_cast<std::size_t>(face.material)].diffuse
                            : cgfs::ModelFile::Material{}.diffuse;
    Triangle triangle{{corners[0].position, corners[1].position, corners[2].position}, color};
    triangle.normals = CornerNormals(file, corners, model, triangle);
    for (int k = 0; k < 3; ++k) {
      if (corners[k].uv >= 0) {
        const glm::dvec2& uv = file.uvs[static_cast<std::size_t>(corners[k].uv)];
        triangle.uvs[k] = {uv.x, 1 - uv.y};
      }
    }
    model.triangles.push_back(triangle);
  }
  model.closed = IsClosed(model);
  return model;
}

std::vector<Model> PaintedParts(Model model, const cgfs::ModelFile& file,
                                const std::vector<const MipmappedTexture*>& by_material,
                                const MipmappedTexture* everywhere) {
  // The geometry apart; what is left of `model` is what every part has of it.
  const std::vector<Vec3> vertices = std::exchange(model.vertices, {});
  const std::vector<Triangle> triangles = std::exchange(model.triangles, {});
  std::vector<Model> parts;  // in the order their textures first appear
  std::map<const MipmappedTexture*, std::size_t> part_of;  // a texture -> its part
  std::vector<std::vector<std::size_t>> triangles_of;      // a part -> its triangles
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    const int material = file.faces[t].material;
    const MipmappedTexture* texture = everywhere != nullptr ? everywhere
                                      : material >= 0
                                          ? by_material[static_cast<std::size_t>(material)]
                                          : nullptr;
    const auto [part, first] = part_of.try_emplace(texture, parts.size());
    if (first) {
      parts.push_back(model);
      parts.back().texture = texture;
      triangles_of.emplace_back();
    }
    triangles_of[part->second].push_back(t);
  }
  // Each part keeps only the vertices its triangles use, numbered anew.
  std::vector<int> own(vertices.size(), -1);  // a vertex of the model's -> the part's
  for (std::size_t p = 0; p < parts.size(); ++p) {
    for (const std::size_t t : triangles_of[p]) {
      Triangle triangle = triangles[t];
      for (int& v : triangle.v) {
        int& index = own[static_cast<std::size_t>(v)];
        if (index < 0) {
          index = static_cast<int>(parts[p].vertices.size());
          parts[p].vertices.push_back(vertices[static_cast<std::size_t>(v)]);
        }
        v = index;
      }
      parts[p].triangles.push_back(triangle);
    }
    for (const std::size_t t : triangles_of[p]) {
      for (const int v : triangles[t].v) {
        own[static_cast<std::size_t>(v)] = -1;
      }
    }
  }
  return parts;
}

Texture LoadTexture(const std::filesystem::path& path) {
  const cgfs::Image image = cgfs::ReadImage(path);
  if (image.Width() > kMaxTextureSide || image.Height() > kMaxTextureSide) {
    throw cgfs::Error("'" + path.string() + "' is " + std::to_string(image.Width()) + "x" +
                      std::to_string(image.Height()) + ", too large for a texture (at most " +
                      std::to_string(kMaxTextureSide) + " a side)");
  }
  return TextureFromImage(image);
}
