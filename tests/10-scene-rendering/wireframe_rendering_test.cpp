// Listings 10-3 and 10-5 draw the same wireframes. Chapter 10 only: from chapter 11 on,
// RenderScene clips what it draws, and Listing 10-3 has had its day.
#include <catch2/catch.hpp>

#include "printing.h"
#include "scenes.h"

using cgfs::test::IsSameImageAs;

TEST_CASE("RenderInstance and RenderScene agree when the camera is at the origin", "[render]") {
  // Listing 10-3 (ApplyTransform per vertex) and Listing 10-5 (one matrix per instance).
  const Scene scene = SceneTwoCubes();
  Canvas by_instance(600, 600);
  for (const Instance& I : scene.instances) {
    RenderInstance(I, by_instance, scene.viewport);
  }
  Canvas by_matrix(600, 600);
  RenderScene(scene, by_matrix);
  CHECK_THAT(by_instance.GetImage(), IsSameImageAs(by_matrix.GetImage()));
}
