// How keys and the mouse move a camera (program/camera_controls.h).
#include <catch2/catch.hpp>

#include <string>

#include "program/camera_controls.h"
#include "program/figure.h"

using cgfs::CameraKey;
using cgfs::View;

TEST_CASE("a key moves the camera a quarter unit along its own axes, or turns it 5 degrees",
          "[camera]") {
  View view = cgfs::Moved(cgfs::Moved(View{}, CameraKey::kForward), CameraKey::kForward);
  view = cgfs::Moved(view, CameraKey::kLeft);
  view = cgfs::Moved(view, CameraKey::kUp);
  CHECK(view.move.x == -0.25);
  CHECK(view.move.y == 0.25);
  CHECK(view.move.z == 0.5);
  view = cgfs::Moved(cgfs::Moved(view, CameraKey::kTurnLeft), CameraKey::kLookDown);
  CHECK(view.yaw == 5);
  CHECK(view.pitch == -5);
  CHECK(cgfs::Moved(cgfs::Moved(view, CameraKey::kBack), CameraKey::kForward) == view);
}

TEST_CASE("dragging 20 pixels to the right turns the camera 5 degrees to the right", "[camera]") {
  // Up Up Q Q, then 20 pixels of drag: the window test's walk, whose view is 0,0,0.5,5,0.
  View view{};
  for (CameraKey key :
       {CameraKey::kForward, CameraKey::kForward, CameraKey::kTurnLeft, CameraKey::kTurnLeft}) {
    view = cgfs::Moved(view, key);
  }
  view = cgfs::Dragged(view, 20, 0);
  CHECK(view == View{{0, 0, 0.5}, 5, 0});
  CHECK(cgfs::Dragged(View{}, 0, -8).pitch == 2);
}

TEST_CASE("frames drawn while moving are half the size, and even", "[camera]") {
  CHECK(cgfs::PreviewSide(600) == 300);
  CHECK(cgfs::PreviewSide(512) == 256);
  CHECK(cgfs::PreviewSide(302) == 150);
  CHECK(cgfs::PreviewSide(2) == 2);
}

TEST_CASE("a view is written in the fewest digits that read back as the same view", "[camera]") {
  const auto round_trip = [](const View& view) {
    const std::string text = cgfs::FormatView(view);
    INFO(text);
    CHECK(cgfs::ParseView(text) == view);
    return text;
  };
  CHECK(round_trip(View{{2.2, 0.5, 1.2}, 51, -10}) == "2.2,0.5,1.2,51,-10");
  CHECK(round_trip(View{{0, 0, 0.5}, 5, 0}) == "0,0,0.5,5,0");
  CHECK(round_trip(View{{100, 1000, 999.9999999}, 360, 12345.678}) ==
        "100,1000,999.9999999,360,12345.678");
  // Where every digit is needed, every digit is written.
  CHECK(round_trip(View{{0.1 + 0.2, 1e-7, -999999.5}, 0, 0}) ==
        "0.30000000000000004,1e-07,-999999.5,0,0");
}
