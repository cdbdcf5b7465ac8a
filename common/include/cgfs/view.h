// A figure's camera moved away from where the chapter puts it (the chapter program's
// --window and --view): first `move` along the camera's own right, up and forward axes,
// then turned `yaw` degrees to the left and `pitch` degrees up. All zero is the
// chapter's own view. Each chapter with a camera has a MovedCamera(camera, view).
#pragma once

#include <glm/vec3.hpp>

namespace cgfs {

struct View {
  glm::dvec3 move{0, 0, 0};
  double yaw = 0;
  double pitch = 0;
  friend bool operator==(const View&, const View&) = default;
};

}  // namespace cgfs
