#include "program/camera_controls.h"

#include <algorithm>

namespace cgfs {

View Moved(View view, CameraKey key) {
  switch (key) {
    case CameraKey::kForward:
      view.move.z += kCameraStep;
      break;
    case CameraKey::kBack:
      view.move.z -= kCameraStep;
      break;
    case CameraKey::kRight:
      view.move.x += kCameraStep;
      break;
    case CameraKey::kLeft:
      view.move.x -= kCameraStep;
      break;
    case CameraKey::kUp:
      view.move.y += kCameraStep;
      break;
    case CameraKey::kDown:
      view.move.y -= kCameraStep;
      break;
    case CameraKey::kTurnLeft:
      view.yaw += kCameraTurn;
      break;
    case CameraKey::kTurnRight:
      view.yaw -= kCameraTurn;
      break;
    case CameraKey::kLookUp:
      view.pitch += kCameraTurn;
      break;
    case CameraKey::kLookDown:
      view.pitch -= kCameraTurn;
      break;
  }
  return view;
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
