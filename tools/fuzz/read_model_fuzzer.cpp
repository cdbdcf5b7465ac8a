// The fuzz target of the model reader (program/model_file.h, tinyobjloader behind it):
// any text must give a model whose every index is in range, or one cgfs::Error, never
// a crash, a hang, a leak or an allocation past the limits. No material library is
// read (the folder is empty). Built with libFuzzer by scripts/fuzz (clang, the `fuzz`
// preset), from the models in tests/models/ as seeds.
#include <cstddef>
#include <cstdint>
#include <string>

#include "program/error.h"
#include "program/model_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    const cgfs::ModelFile model =
        cgfs::ParseModelFile(std::string(reinterpret_cast<const char*>(data), size), "input", "");
    for (const cgfs::ModelFile::Face& face : model.faces) {
      for (const cgfs::ModelFile::Corner& corner : face.corners) {
        if (corner.position < 0 ||
            static_cast<std::size_t>(corner.position) >= model.positions.size() ||
            corner.normal >= static_cast<int>(model.normals.size()) ||
            corner.uv >= static_cast<int>(model.uvs.size())) {
          __builtin_trap();  // an index the reader should have refused
        }
      }
    }
  } catch (const cgfs::Error&) {
    // A one-line refusal is the right answer to bad text.
  }
  return 0;
}
