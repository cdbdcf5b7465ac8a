#include "program/camera_controls.h"

#include <algorithm>
#include <cstddef>

namespace cgfs {

// What one press of each key adds to the view, in CameraKey's order: a step along the
// camera's axes, or a turn about them.
constexpr View kPresses[] = {
    {{0, 0, kCameraStep}, 0, 0}, {{0, 0, -kCameraStep}, 0, 0},  // forward, back
    {{kCameraStep, 0, 0}, 0, 0}, {{-kCameraStep, 0, 0}, 0, 0},  // right, left
    {{0, kCameraStep, 0}, 0, 0}, {{0, -kCameraStep, 0}, 0, 0},  // up, down
    {{0, 0, 0}, kCameraTurn, 0}, {{0, 0, 0}, -kCameraTurn, 0},  // turn left, right
    {{0, 0, 0}, 0, kCameraTurn}, {{0, 0, 0}, 0, -kCameraTurn},  // look up, down
};

View Moved(View view, CameraKey key) {
  const View& press = kPresses[static_cast<std::size_t>(key)];
  return {view.move + press.move, view.yaw + press.yaw, view.pitch + press.pitch};
}

View Dragged(View view, int right, int down) {
  view.yaw -= right * kMouseTurn;
  view.pitch -= down * kMouseTurn;
  return view;
}

int PreviewSide(int side) {
  return std::max(2, side / 4 * 2);
}

}  // namespace cgfs
