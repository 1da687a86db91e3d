// The 3D view's camera: it orbits a target (yaw about the vertical z axis, pitch above the
// horizon) from a distance, and draws in the GPU's frame, where the mesh shown is centred and
// one long (its box's diagonal): single precision keeps the mesh's shape at any size or place.
#pragma once

#include "mesh.h"

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <string>
#include <utility>
#include <vector>

namespace lloydscope {

inline glm::vec3 glmOf(const Vec3& p) { return glm::vec3(p.x(), p.y(), p.z()); }

// Where the GPU has the mesh: its points less `origin`, over `scale`.
struct GpuFrame {
  Vec3 origin = Vec3::Zero();
  double scale = 1;
  // The frame of the box lo..hi: its centre, its diagonal (1 where the box is a point).
  static GpuFrame ofBox(const Vec3& lo, const Vec3& hi);
  Vec3 to(const Vec3& p) const { return (p - origin) / scale; }
  Vec3 from(const glm::vec3& p) const;
};

struct OrbitCamera {
  float yaw = -1.2f, pitch = 0.75f;  // the view a mesh opens in: from the front, a little above
  float distance = 2.5f;             // from the target, in the mesh's units
  Vec3 target = Vec3::Zero();

  // "yaw pitch distance x y z", to save a view and restore it (parse).
  std::string text() const;
  // Throws Error on anything but six finite numbers with a distance above 0; the pitch is
  // clamped as orbit() clamps it.
  static OrbitCamera parse(const std::string& text);

  // The unit vector from the target to the eye.
  glm::vec3 towardsEye() const;
  // A drag of the mouse by (dx, dy) pixels: around the target, never over the pole.
  void orbit(float dx, float dy);
  // The wheel's `clicks`, within 0.3..20 times `meshSize`: closer, the eye went inside the mesh
  // and the pane was empty; farther, the mesh was a dot. A distance already outside the range
  // (a view pasted) is not pushed farther out, nor jumps into it.
  void zoom(float clicks, double meshSize);
  // Looks at the middle of the box lo..hi from the opening direction, from as far as its diagonal
  // (fittingDistance() then gives the distance for the pane's shape).
  void lookAtBox(const Vec3& lo, const Vec3& hi);
  // The distance from which every point is inside a pane width x height, with a margin,
  // looking at the target from the camera's direction: a long shape seen across (a
  // triceratops) fits too, which a distance from its bounding box alone did not make sure of.
  float fittingDistance(const std::vector<Vec3>& points, float width, float height) const;

  // The view-projection matrix (Vulkan clip space) and the eye, both in `gpu`'s frame, for a
  // pane width x height whose `top` pixels (a label's band) the view is centred and fitted
  // under: it draws over the whole pane, but its centre and 40 degrees are the pane's under the
  // band.
  std::pair<glm::mat4, glm::vec3> matrices(const GpuFrame& gpu, float width, float height, float top) const;
};

}  // namespace lloydscope
