// Wavefront OBJ models (program/model_file.h): what a file gives, and one clear line
// for every file that is not a model, or too much of one, before memory is taken.
#include <catch2/catch.hpp>

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "program/error.h"
#include "program/model_file.h"
#include "temporary_folder.h"

namespace fs = std::filesystem;
using cgfs::ModelFile;
using cgfs::ReadModelFile;

namespace {

fs::path ModelFolder() {
  return cgfs::test::TemporaryFolder("cgfs-model-file-test");
}

fs::path Written(const fs::path& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

// A unit square in z = 0 of two triangles, then whatever `more` adds.
std::string Square(const std::string& more = "") {
  return "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3\nf 1 3 4\n" + more;
}

// The message ReadModelFile refuses `text` with; empty if it reads it.
std::string Refusal(const std::string& text) {
  const fs::path file = Written(ModelFolder() / "model.obj", text);
  try {
    ReadModelFile(file);
    return "";
  } catch (const cgfs::Error& error) {
    return error.what();
  }
}

}  // namespace

TEST_CASE("a model file gives its triangles, normals, texture coordinates and materials") {
  const fs::path folder = ModelFolder();
  Written(folder / "look.mtl", "newmtl red\nKd 1 0 0\nmap_Kd .\\crate.png\n");
  const ModelFile model = ReadModelFile(Written(folder / "quad.obj",
                                                "mtllib look.mtl\n"
                                                "v 0 0 0\nv 2 0 0\nv 2 1 0\nv 0 1 0\n"
                                                "vn 0 0 1\nvt 0 0\nvt 1 1\n"
                                                "usemtl red\nf 1/1/1 2/2/1 3/2/1 4/1/1\n"));
  CHECK(model.positions.size() == 4);
  CHECK(model.positions[1] == glm::dvec3(2, 0, 0));
  REQUIRE(model.faces.size() == 2);  // the quad split by tinyobjloader
  CHECK(model.faces[0].corners[0].position == 0);
  CHECK(model.faces[0].corners[0].normal == 0);
  CHECK(model.faces[0].corners[1].uv == 1);
  CHECK(model.uvs[1] == glm::dvec2(1, 1));
  REQUIRE(model.materials.size() == 1);
  CHECK(model.faces[1].material == 0);
  CHECK(model.materials[0].diffuse == glm::dvec3(255, 0, 0));
  CHECK(model.materials[0].texture == folder / "./crate.png");  // Windows' \ read as /
  CHECK(model.warnings.empty());
}

TEST_CASE("lines may end in CR LF or CR alone") {
  std::string crlf = Square();
  std::string cr = Square();
  for (std::size_t at = crlf.find('\n'); at != std::string::npos; at = crlf.find('\n', at + 2)) {
    crlf.insert(at, "\r");
  }
  std::replace(cr.begin(), cr.end(), '\n', '\r');
  CHECK(ReadModelFile(Written(ModelFolder() / "crlf.obj", crlf)).faces.size() == 2);
  CHECK(ReadModelFile(Written(ModelFolder() / "cr.obj", cr)).faces.size() == 2);
  CHECK_THAT(Refusal("v 0 0 0\r\nv nan 0 0\r\n"), Catch::Contains("line 2: 'nan'"));
}

TEST_CASE("a model without materials is light grey, and its missing pieces are warnings") {
  const ModelFile plain = ReadModelFile(Written(ModelFolder() / "plain.obj", Square()));
  CHECK(plain.faces[0].material == -1);
  CHECK(plain.faces[0].corners[0].normal == -1);
  CHECK(plain.faces[0].corners[0].uv == -1);

  const ModelFile without =
      ReadModelFile(Written(ModelFolder() / "m.obj", Square("mtllib nowhere.mtl\n")));
  REQUIRE(without.warnings.size() == 1);
  CHECK_THAT(without.warnings[0],
             Catch::Contains("nowhere.mtl") && Catch::Contains("drawn without its materials"));
  const ModelFile flat = ReadModelFile(
      Written(ModelFolder() / "f.obj", Square("v 0 0 0\nv 1 1 1\nv 2 2 2\nf 5 6 7\n")));
  CHECK(flat.faces.size() == 2);
  REQUIRE(flat.warnings.size() == 1);
  CHECK(flat.warnings[0] == "1 triangle without an area left out");
}

TEST_CASE("triangles tinyobjloader does not make of a polygon are said") {
  // A square's corners three times round: 12 corners make 10 triangles; tinyobjloader
  // (2.0.0rc10) gives up after 3, as on some concave polygons.
  const ModelFile model =
      ReadModelFile(Written(ModelFolder() / "round.obj",
                            "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4 1 2 3 4 1 2 3 4\n"));
  CHECK(model.faces.size() == 3);
  REQUIRE(model.warnings.size() == 1);
  CHECK(model.warnings[0] ==
        "tinyobjloader split its polygons into 3 of the 10 triangles they make: 7 not drawn");
}

TEST_CASE("a material library that is a device, a FIFO or a folder is a warning, never read") {
  const fs::path folder = ModelFolder();
  REQUIRE(::mkfifo((folder / "fifo.mtl").c_str(), 0600) == 0);
  fs::create_directory(folder / "folder.mtl");
  for (const std::string library : {"/dev/zero", "fifo.mtl", "folder.mtl"}) {
    const ModelFile model =
        ReadModelFile(Written(folder / "m.obj", Square("mtllib " + library + "\n")));
    REQUIRE(model.warnings.size() == 1);
    CHECK_THAT(model.warnings[0], Catch::Contains("drawn without its materials"));
  }
}

TEST_CASE("files that are not models are refused in one line") {
  CHECK_THAT(Refusal(""), Catch::Contains("has no faces"));
  CHECK_THAT(Refusal("v 0 0 0\nv 1 0 0\nv 0 1 0\np 1 2 3\nl 1 2\n"),
             Catch::Contains("has no faces (points and lines are not drawn)"));
  CHECK_THAT(Refusal("v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n"),
             Catch::Contains("no triangle with an area"));
  CHECK_THAT(Refusal(Square("f 1 2 9\n")), Catch::Contains("a face refers to vertex 9 of 4"));
  CHECK_THAT(Refusal(Square("f 1 2 -9\n")), Catch::Contains("a face refers to vertex"));
  CHECK_THAT(Refusal(Square("f 1 2 3 9\n")), Catch::Contains("a vertex the file does not have"));
  CHECK_THAT(Refusal(Square("f 0 1 2\n")),
             Catch::Contains("line 7: '0' has an index 0 (OBJ counts from 1)"));
  CHECK_THAT(Refusal(Square("f 1/0 2/1 3/1\n")), Catch::Contains("'1/0' has an index 0"));
  CHECK_THAT(Refusal(Square("f 1//-0 2 3\n")), Catch::Contains("'1//-0' has an index 0"));
  CHECK_THAT(Refusal(Square("f 1/5 2/5 3/5\n")), Catch::Contains("texture coordinate 5 of 0"));
  CHECK_THAT(Refusal(Square("f 1//2 2//2 3//2\n")), Catch::Contains("normal 2 of 0"));
  CHECK_THAT(Refusal("v nan 0 0\n" + Square()), Catch::Contains("line 1: 'nan' is not a number"));
  CHECK_THAT(Refusal("v 1e999 0 0\n" + Square()), Catch::Contains("not a finite number"));
  CHECK_THAT(Refusal(Square("vn -inf 0 0\n")), Catch::Contains("'-inf' is not a number"));
  CHECK_THAT(Refusal(Square("vt 1e400 0\n")), Catch::Contains("not a finite number"));
  CHECK_THAT(Refusal(Square("usemtl a\x1b[31mred\n")),
             Catch::Contains("line 7: a control character"));
  CHECK_THAT(Refusal(std::string("\xfe\xff\0v\0 \0001", 8)),
             Catch::Contains("a NUL byte: not a text OBJ file (UTF-16 is not read)"));
}

TEST_CASE("a model too large for the machine is refused from its text, before it is parsed") {
  std::string corners = "f";
  for (std::size_t k = 1; k <= cgfs::kMaxPolygonCorners + 1; ++k) {
    corners += " " + std::to_string(k);
  }
  CHECK_THAT(Refusal(corners + "\n"), Catch::Contains("a polygon of 1025 corners (at most 1024)"));
  // 750 001 triangles in 6 MB: refused by counting, not by parsing.
  std::string many;
  many.reserve(8u << 20);
  for (std::size_t k = 0; k <= cgfs::kMaxModelTriangles; ++k) {
    many += "f 1 2 3\n";
  }
  CHECK_THAT(Refusal(Square(many)),
             Catch::Contains("too large a model") && Catch::Contains("750003 triangles"));
  std::string switches = "mtllib none.mtl\n";
  for (std::size_t k = 0; k <= cgfs::kMaxMaterialSwitches; ++k) {
    switches += k % 2 == 0 ? "usemtl a\nf 1 2 3\n" : "usemtl b\nf 1 2 3\n";
  }
  CHECK_THAT(Refusal(Square(switches)),
             Catch::Contains("changes material 65537 times (usemtl; at most 65536)"));
  // A file larger than kMaxModelFileBytes, stated by its size: never read.
  const fs::path huge = ModelFolder() / "huge.obj";
  Written(huge, "");
  fs::resize_file(huge, std::uintmax_t{10} << 30);  // 10 GB, sparse
  CHECK_THROWS_WITH(ReadModelFile(huge), Catch::Contains("is too large: more than"));
}

TEST_CASE("an index past 2147483647 is refused, never wrapped to another vertex") {
  CHECK_THAT(Refusal(Square("f 1 2 4294967299\n")),
             Catch::Contains("line 7: '4294967299' has an index past 2147483647"));
  CHECK_THAT(Refusal(Square("f 1 2 99999999999\n")), Catch::Contains("index past 2147483647"));
  CHECK_THAT(Refusal(Square("f 1/2147483648 2 3\n")), Catch::Contains("index past 2147483647"));
  CHECK_THAT(Refusal(Square("f 1 2 -2147483648\n")), Catch::Contains("index past 2147483647"));
  CHECK_THAT(Refusal(Square("f 1 2 2147483647\n")),
             Catch::Contains("a face refers to vertex 2147483647 of 4"));
  CHECK_THAT(Refusal(Square("f 1 2 0000000000003\n")), Catch::Equals(""));  // leading zeros
}

TEST_CASE("what the chapters do not draw is not kept, and what is left out is said once") {
  const fs::path folder = ModelFolder();
  const ModelFile model = ReadModelFile(
      Written(folder / "kinds.obj", Square("f 1\nf 1 2\nf\nl 1 2 3\np 1 2\nt a 8192/8192/8192\n"
                                           "g a b c\no thing\ns 1\nvw 1 0 0.5\ncstype bezier\n")));
  CHECK(model.faces.size() == 2);
  CHECK(model.warnings == std::vector<std::string>{"3 faces of fewer than three corners left out"});

  Written(folder / "look.mtl", "newmtl red\nKd 1 0 0\n");
  std::string libraries = "mtllib look.mtl\nmtllib look.mtl\nmtllib ./look.mtl\n";
  for (int k = 0; k < 16; ++k) {  // 18 libraries named: 2 past the bound
    libraries += "mtllib other" + std::to_string(k) + ".mtl\n";
  }
  const ModelFile named = ReadModelFile(Written(folder / "named.obj", libraries + Square()));
  CHECK(named.materials.size() == 1);  // look.mtl read once, whatever it is called
  CHECK(std::count(named.warnings.begin(), named.warnings.end(),
                   "1 line naming a material library already named left out (mtllib)") == 1);
  CHECK(std::count(named.warnings.begin(), named.warnings.end(),
                   "2 lines naming more than 16 material libraries left out (mtllib)") == 1);

  std::string crowded;
  for (std::size_t k = 0; k <= cgfs::kMaxMaterials; ++k) {
    crowded += "newmtl m" + std::to_string(k) + "\n";
  }
  Written(folder / "crowded.mtl", crowded);
  const ModelFile many =
      ReadModelFile(Written(folder / "many.obj", "mtllib crowded.mtl\n" + Square()));
  CHECK(many.materials.empty());
  REQUIRE(many.warnings.size() == 1);
  CHECK_THAT(many.warnings[0], Catch::Contains("would make 4097 materials (at most 4096)"));
}

TEST_CASE("coordinates near the largest double are a model; triangles piled up are refused") {
  const ModelFile huge = ReadModelFile(
      Written(ModelFolder() / "huge.obj", "v 0 0 0\nv 1e300 0 0\nv 0 1e300 0\nf 1 2 3\n"));
  CHECK(huge.faces.size() == 1);
  // A closed surface covers its outline a few times: the unit square's two triangles,
  // their boxes each the square, 2 / (pi 0.5) = 1.27.
  CHECK(ReadModelFile(Written(ModelFolder() / "square.obj", Square())).faces.size() == 2);
  std::string piled = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  for (int k = 0; k < 1571; ++k) {  // each box 1 / (pi 0.5) = 0.637 of the outline
    piled += "f 1 2 3\n";
  }
  CHECK_THAT(Refusal(piled), Catch::Contains("their boxes cover the model's outline 1000 times "
                                             "over (at most 1000; a frame would take minutes)"));
  piled.resize(piled.size() - 16);  // 1569 of them: 998.8 times
  CHECK_THAT(Refusal(piled), Catch::Equals(""));
}

TEST_CASE("a path that is not a regular file is refused in one line") {
  const fs::path folder = ModelFolder();
  REQUIRE(::mkfifo((folder / "fifo.obj").c_str(), 0600) == 0);
  fs::create_symlink(folder / "loop.obj", folder / "loop.obj");
  CHECK_THROWS_WITH(ReadModelFile("/dev/zero"), Catch::Contains("not a regular file"));
  CHECK_THROWS_WITH(ReadModelFile(folder / "fifo.obj"), Catch::Contains("not a regular file"));
  CHECK_THROWS_WITH(ReadModelFile(folder), Catch::Contains("it is a directory"));
  CHECK_THROWS_WITH(ReadModelFile(folder / "loop.obj"), Catch::Contains("cannot read"));
  CHECK_THROWS_WITH(ReadModelFile(folder / "missing.obj"), Catch::Contains("cannot read"));
}
