#include "mesh.h"

namespace lloydscope {

double boundingBoxDiagonal(const Mesh& mesh) {
  if (mesh.points.empty()) return 0.0;
  Vec3 lo = mesh.points.front(), hi = lo;
  for (const Vec3& p : mesh.points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  return (hi - lo).norm();
}

double triangleArea(const Vec3& a, const Vec3& b, const Vec3& c) {
  return 0.5 * (b - a).cross(c - a).norm();
}

double triangleArea(const Vec2& a, const Vec2& b, const Vec2& c) {
  const Vec2 u = b - a, v = c - a;
  return 0.5 * (u.x() * v.y() - u.y() * v.x());
}

}  // namespace lloydscope
