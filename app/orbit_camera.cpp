#include "orbit_camera.h"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace lloydscope {

namespace {
constexpr float kLowestPitch = -1.5f, kHighestPitch = 1.5f;  // radians: short of the poles
constexpr float kFieldOfViewDeg = 40.0f;
}  // namespace

GpuFrame GpuFrame::ofBox(const Vec3& lo, const Vec3& hi) {
  const double diagonal = (hi - lo).norm();
  return {0.5 * (lo + hi), diagonal > 0 ? diagonal : 1.0};
}

Vec3 GpuFrame::from(const glm::vec3& p) const { return origin + scale * Vec3(p.x, p.y, p.z); }

std::string OrbitCamera::text() const {
  char text[160];
  std::snprintf(text, sizeof text, "%.4f %.4f %.6g %.6g %.6g %.6g", yaw, pitch, distance, target.x(), target.y(),
                target.z());
  return text;
}

OrbitCamera OrbitCamera::parse(const std::string& text) {
  OrbitCamera c;
  double x, y, z;
  char rest;
  if (std::sscanf(text.c_str(), "%f %f %f %lf %lf %lf %c", &c.yaw, &c.pitch, &c.distance, &x, &y, &z, &rest) != 6 ||
      !std::isfinite(c.yaw) || !std::isfinite(c.pitch) || !(c.distance > 0) || !std::isfinite(c.distance) ||
      !std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z))
    // Finite in single precision: a distance of 1e308 is read as infinite, and was refused as if
    // it were not above 0.
    throw Error("camera \"" + text + "\": expected \"yaw pitch distance x y z\" (six finite numbers, the angles "
                "and the distance in single precision, distance > 0)");
  c.pitch = std::clamp(c.pitch, kLowestPitch, kHighestPitch);
  c.target = Vec3(x, y, z);
  return c;
}

glm::vec3 OrbitCamera::towardsEye() const {
  return glm::vec3(std::cos(pitch) * std::cos(yaw), std::cos(pitch) * std::sin(yaw), std::sin(pitch));
}

void OrbitCamera::orbit(float dx, float dy) {
  yaw -= dx * 0.01f;
  pitch = std::clamp(pitch + dy * 0.01f, kLowestPitch, kHighestPitch);
}

void OrbitCamera::zoom(float clicks, double meshSize) {
  const float size = static_cast<float>(meshSize);
  distance = std::clamp(distance * std::pow(0.9f, clicks), std::min(0.3f * size, distance),
                        std::max(20.0f * size, distance));
}

void OrbitCamera::lookAtBox(const Vec3& lo, const Vec3& hi) {
  *this = OrbitCamera{};
  target = 0.5 * (lo + hi);
  distance = static_cast<float>(1.05 * (hi - lo).norm());
}

float OrbitCamera::fittingDistance(const std::vector<Vec3>& points, float width, float height) const {
  const glm::vec3 toEye = towardsEye();
  const glm::vec3 right = glm::normalize(glm::cross(glm::vec3(0, 0, 1), toEye));
  const glm::vec3 up = glm::cross(toEye, right);
  const float margin = 0.9f;
  const float tanV = margin * std::tan(glm::radians(0.5f * kFieldOfViewDeg)), tanH = tanV * width / height;
  float fitting = 0;
  for (const Vec3& p : points) {
    const glm::vec3 q(p.x() - target.x(), p.y() - target.y(), p.z() - target.z());
    const float depth = glm::dot(q, toEye);  // towards the eye
    fitting = std::max({fitting, depth + std::abs(glm::dot(q, right)) / tanH, depth + std::abs(glm::dot(q, up)) / tanV});
  }
  return fitting > 0 ? fitting : distance;
}

std::pair<glm::mat4, glm::vec3> OrbitCamera::matrices(const GpuFrame& gpu, float width, float height, float top) const {
  const glm::vec3 at = glmOf(gpu.to(target));
  const float away = static_cast<float>(distance / gpu.scale);
  const glm::vec3 eye = at + away * towardsEye();
  const float below = height - top;  // the pane under the band at its top
  glm::mat4 proj = glm::perspective(glm::radians(kFieldOfViewDeg), width / below, away * 0.01f, away * 10.0f);
  proj[1][1] *= -1.0f;  // Vulkan's y points down
  const glm::mat4 underTheBand =
      glm::scale(glm::translate(glm::mat4(1.0f), glm::vec3(0, top / height, 0)), glm::vec3(1, below / height, 1));
  return {underTheBand * proj * glm::lookAt(eye, at, glm::vec3(0, 0, 1)), eye};
}

}  // namespace lloydscope
