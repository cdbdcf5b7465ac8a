#include "scene.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/trigonometric.hpp>

// Listing 10-4. Rotation and scale act about the model's origin, so translation comes last.
Vec3 ApplyTransform(const Vec3& vertex, const Transform& transform) {
  const Vec3 scaled = vertex * transform.scale;
  const Vec3 rotated = Vec3(transform.rotation * glm::dvec4(scaled, 0.0));
  const Vec3 translated = rotated + transform.translation;
  return translated;
}

// "The Transform Matrix": M_model = I_T * I_R * I_S, so the scale acts first.
glm::dmat4 MakeTransformMatrix(const Transform& transform) {
  return MakeTranslationMatrix(transform.translation) * transform.rotation *
         MakeScalingMatrix(transform.scale);
}

// "The Transform Matrix": M_camera = C_R^-1 * C_T^-1.
glm::dmat4 MakeCameraMatrix(const Vec3& position, const glm::dmat4& orientation) {
  return glm::transpose(orientation) * MakeTranslationMatrix(-position);
}

// The orientation takes the camera's directions to the scene's, so both turns act on
// them first, the yaw last. MakeOYRotationMatrix turns to the left for positive angles;
// the book has no rotation about X, so the pitch is GLM's, negated to turn +Z up.
Camera MovedCamera(const Camera& camera, const cgfs::View& view) {
  Camera moved;
  moved.position = camera.position + Vec3(camera.orientation * glm::dvec4(view.move, 0.0));
  const glm::dmat4 pitch = glm::rotate(glm::dmat4(1.0), glm::radians(-view.pitch), Vec3(1, 0, 0));
  moved.orientation = camera.orientation * MakeOYRotationMatrix(view.yaw) * pitch;
  return moved;
}
