#include "options.h"

#include <algorithm>
#include <array>
#include <map>
#include <memory>
#include <string>
#include <utility>

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
  std::map<std::pair<int, int>, int> edges;  // (from, to) -> how many triangles go so
  for (const Triangle& triangle : model.triangles) {
    for (int k = 0; k < 3; ++k) {
      ++edges[{triangle.v[k], triangle.v[(k + 1) % 3]}];
    }
  }
  for (const auto& [edge, count] : edges) {
    const auto back = edges.find({edge.second, edge.first});
    if (count != 1 || back == edges.end() || back->second != 1) {
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

// Each material's texture (map_Kd) with its mip chain, or none where it has none or it
// cannot be read (said in a warning).
std::vector<std::shared_ptr<const MipmappedTexture>> MaterialTextures(const cgfs::ModelFile& file,
                                                                      const std::string& name) {
  std::vector<std::shared_ptr<const MipmappedTexture>> textures;
  for (const cgfs::ModelFile::Material& material : file.materials) {
    std::shared_ptr<const MipmappedTexture> texture;
    if (!material.texture.empty()) {
      try {
        texture =
            std::make_shared<const MipmappedTexture>(BuildMipChain(LoadTexture(material.texture)));
      } catch (const cgfs::Error& error) {
        cgfs::Warn(name + ": material " + material.name + ": " + error.what() +
                   "; drawn in its colour");
      }
    }
    textures.push_back(texture);
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

std::vector<Model> PaintedParts(const Model& model, const cgfs::ModelFile& file,
                                const std::vector<const MipmappedTexture*>& by_material,
                                const MipmappedTexture* everywhere) {
  std::vector<Model> parts;  // in the order their textures first appear
  for (std::size_t t = 0; t < model.triangles.size(); ++t) {
    const int material = file.faces[t].material;
    const MipmappedTexture* texture = everywhere != nullptr ? everywhere
                                      : material >= 0
                                          ? by_material[static_cast<std::size_t>(material)]
                                          : nullptr;
    auto part = std::find_if(parts.begin(), parts.end(),
                             [texture](const Model& each) { return each.texture == texture; });
    if (part == parts.end()) {
      Model painted = model;
      painted.triangles.clear();
      painted.texture = texture;
      part = parts.insert(parts.end(), std::move(painted));
    }
    part->triangles.push_back(model.triangles[t]);
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
