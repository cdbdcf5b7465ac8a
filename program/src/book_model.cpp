#include "program/book_model.h"

#include <algorithm>
#include <map>
#include <system_error>
#include <utility>

#include <glm/geometric.hpp>

#include "program/error.h"
#include "program/image_files.h"

namespace cgfs {

namespace {

// OBJ's right-handed coordinates in the book's left-handed ones.
glm::dvec3 BookCoordinates(const glm::dvec3& v) {
  return {v.x, v.y, -v.z};
}

// Every edge used once in each direction: a surface without holes, consistently wound.
bool IsClosed(const BookModel& model) {
  std::vector<std::pair<int, int>> edges;  // (from, to) of every triangle, sorted
  edges.reserve(3 * model.triangles.size());
  for (const BookModel::Triangle& triangle : model.triangles) {
    for (std::size_t k = 0; k < 3; ++k) {
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

// A triangle of the file, its corners already the other way round, in the book's
// coordinates.
BookModel::Triangle BookTriangle(const ModelFile& file, const ModelFile::Face& face,
                                 const std::vector<glm::dvec3>& vertices) {
  const std::array<ModelFile::Corner, 3> corners = {face.corners[0], face.corners[2],
                                                    face.corners[1]};
  BookModel::Triangle triangle;
  triangle.material = face.material;
  triangle.color = face.material >= 0
                       ? file.materials[static_cast<std::size_t>(face.material)].diffuse
                       : ModelFile::Material{}.diffuse;
  for (std::size_t k = 0; k < 3; ++k) {
    triangle.v[k] = corners[k].position;
  }
  const glm::dvec3& A = vertices[static_cast<std::size_t>(triangle.v[0])];
  const glm::dvec3 own =
      glm::normalize(glm::cross(vertices[static_cast<std::size_t>(triangle.v[1])] - A,
                                vertices[static_cast<std::size_t>(triangle.v[2])] - A));
  for (std::size_t k = 0; k < 3; ++k) {
    const int given = corners[k].normal;
    const glm::dvec3 normal =
        given >= 0 ? BookCoordinates(file.normals[static_cast<std::size_t>(given)]) : glm::dvec3(0);
    triangle.normals[k] = glm::length(normal) > 0 ? glm::normalize(normal) : own;
    if (corners[k].uv >= 0) {
      const glm::dvec2& uv = file.uvs[static_cast<std::size_t>(corners[k].uv)];
      triangle.uvs[k] = {uv.x, 1 - uv.y};
    }
  }
  return triangle;
}

}  // namespace

BookModel InBookCoordinates(const ModelFile& file) {
  BookModel model;
  for (const glm::dvec3& position : file.positions) {
    model.vertices.push_back(BookCoordinates(position));
  }
  for (const ModelFile::Face& face : file.faces) {
    model.triangles.push_back(BookTriangle(file, face, model.vertices));
  }
  model.closed = IsClosed(model);
  model.materials = file.materials;
  return model;
}

BookModel ReadBookModel(const std::filesystem::path& path) {
  const ModelFile file = ReadModelFile(path);
  for (const std::string& warning : file.warnings) {
    Warn(path.string() + ": " + warning);
  }
  return InBookCoordinates(file);
}

std::vector<BookModel> SplitModel(const BookModel& model, const std::vector<std::size_t>& part_of,
                                  std::size_t parts) {
  std::vector<std::vector<std::size_t>> triangles_of(parts);  // each part's triangles
  for (std::size_t t = 0; t < model.triangles.size(); ++t) {
    triangles_of[part_of[t]].push_back(t);
  }
  // The number a vertex of the model has in the part being made, -1: none yet. One list
  // for all the parts, set back after each: memory for the vertices once, not per part.
  std::vector<int> own(model.vertices.size(), -1);
  std::vector<BookModel> split(parts);
  for (std::size_t p = 0; p < parts; ++p) {
    BookModel& part = split[p];
    part.closed = model.closed;
    for (const std::size_t t : triangles_of[p]) {
      BookModel::Triangle triangle = model.triangles[t];
      for (int& v : triangle.v) {
        int& number = own[static_cast<std::size_t>(v)];
        if (number < 0) {
          number = static_cast<int>(part.vertices.size());
          part.vertices.push_back(model.vertices[static_cast<std::size_t>(v)]);
        }
        v = number;
      }
      part.triangles.push_back(triangle);
    }
    for (const std::size_t t : triangles_of[p]) {
      for (const int v : model.triangles[t].v) {
        own[static_cast<std::size_t>(v)] = -1;
      }
    }
  }
  return split;
}

Image ReadTextureImage(const std::filesystem::path& path, int max_side) {
  Image image = ReadImage(path);
  if (image.Width() > max_side || image.Height() > max_side) {
    throw Error("'" + path.string() + "' is " + std::to_string(image.Width()) + "x" +
                std::to_string(image.Height()) + ", too large for a texture (at most " +
                std::to_string(max_side) + " a side)");
  }
  return image;
}

namespace {

// One texture file as the model's materials share it: read once, by its real path.
struct SharedImage {
  std::shared_ptr<const Image> image;  // none: it could not be used
  std::string why_not;                 // the warning's words, if so
  std::string first_material;
  std::size_t materials = 0;
};

}  // namespace

std::vector<std::shared_ptr<const Image>> MaterialImages(
    const std::vector<ModelFile::Material>& materials, const std::string& name, int max_side,
    std::size_t max_texels) {
  std::map<std::filesystem::path, SharedImage> files;
  std::vector<std::filesystem::path> order;  // the files in the order materials name them
  std::size_t texels = 0;
  std::vector<std::shared_ptr<const Image>> images;
  for (const ModelFile::Material& material : materials) {
    if (material.texture.empty()) {
      images.emplace_back();
      continue;
    }
    std::error_code not_there;
    const std::filesystem::path real =
        std::filesystem::weakly_canonical(material.texture, not_there);
    auto [shared, first] = files.try_emplace(not_there ? material.texture : real);
    if (first) {
      order.push_back(shared->first);
      shared->second.first_material = material.name;
      try {
        Image image = ReadTextureImage(material.texture, max_side);
        const auto size =
            static_cast<std::size_t>(image.Width()) * static_cast<std::size_t>(image.Height());
        if (texels + size > max_texels) {
          shared->second.why_not = "'" + material.texture.string() +
                                   "' would take the model's textures past " +
                                   std::to_string(max_texels) + " texels";
        } else {
          texels += size;
          shared->second.image = std::make_shared<const Image>(std::move(image));
        }
      } catch (const Error& error) {
        shared->second.why_not = error.what();
      }
    }
    ++shared->second.materials;
    images.push_back(shared->second.image);
  }
  for (const std::filesystem::path& each : order) {
    const SharedImage& shared = files[each];
    if (!shared.why_not.empty()) {
      const std::string more =
          shared.materials > 1 ? " (and " + std::to_string(shared.materials - 1) + " more)" : "";
      Warn(name + ": material " + shared.first_material + more + ": " + shared.why_not +
           "; drawn in its colour");
    }
  }
  return images;
}

std::vector<PaintedPart> PaintedParts(const BookModel& model,
                                      const std::vector<std::shared_ptr<const Image>>& by_material,
                                      const std::shared_ptr<const Image>& everywhere) {
  std::map<const Image*, std::size_t> part_of_texture;
  std::vector<std::shared_ptr<const Image>> textures;  // each part's
  std::vector<std::size_t> part_of;                    // each triangle's part
  for (const BookModel::Triangle& T : model.triangles) {
    const std::shared_ptr<const Image>& texture =
        everywhere || T.material < 0 ? everywhere
                                     : by_material[static_cast<std::size_t>(T.material)];
    const auto [part, first] = part_of_texture.try_emplace(texture.get(), textures.size());
    if (first) {
      textures.push_back(texture);
    }
    part_of.push_back(part->second);
  }
  std::vector<PaintedPart> parts;
  for (BookModel& part : SplitModel(model, part_of, textures.size())) {
    parts.push_back({std::move(part), textures[parts.size()]});
  }
  return parts;
}

}  // namespace cgfs
