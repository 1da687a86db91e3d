#include "projection.h"

#include "cgal_types.h"
#include "parallel.h"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>

#include <algorithm>
#include <thread>
#include <vector>

namespace lloydscope {

namespace {

using Triangle3 = Kernel::Triangle_3;
using Primitive = CGAL::AABB_triangle_primitive<Kernel, std::vector<Triangle3>::const_iterator>;
using AabbTree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

Point3 point(const Vec3& p) { return Point3(p.x(), p.y(), p.z()); }

}  // namespace

struct SurfaceProjection::Tree {
  std::vector<Triangle3> triangles;  // the tree points into them
  AabbTree tree;
};

SurfaceProjection::SurfaceProjection(const Mesh& surface) : tree_(std::make_unique<Tree>()) {
  for (const Triangle& t : surface.triangles)
    tree_->triangles.emplace_back(point(surface.points[t[0]]), point(surface.points[t[1]]),
                                  point(surface.points[t[2]]));
  tree_->tree.insert(tree_->triangles.cbegin(), tree_->triangles.cend());
  tree_->tree.build();
  tree_->tree.accelerate_distance_queries();
}

SurfaceProjection::~SurfaceProjection() = default;
SurfaceProjection::SurfaceProjection(SurfaceProjection&&) noexcept = default;

Vec3 SurfaceProjection::closestPoint(const Vec3& p) const {
  const Point3 c = tree_->tree.closest_point(point(p));
  return Vec3(c.x(), c.y(), c.z());
}

std::vector<Vec3> SurfaceProjection::closestPoints(const std::vector<Vec3>& points, int threadCount) const {
  std::vector<Vec3> closest(points.size());
  const size_t threads = points.size() < 1000 ? 1
                         : threadCount > 0    ? static_cast<size_t>(threadCount)
                                              : std::max(1u, std::thread::hardware_concurrency());
  parallelFor(points.size(), threads, [&](size_t begin, size_t end) {
    for (size_t i = begin; i < end; ++i) closest[i] = closestPoint(points[i]);
  });
  return closest;
}

int SurfaceProjection::closestTriangle(const Vec3& p, double* squaredDistance) const {
  const auto closest = tree_->tree.closest_point_and_primitive(point(p));
  if (squaredDistance) *squaredDistance = CGAL::squared_distance(closest.first, point(p));
  return static_cast<int>(closest.second - tree_->triangles.cbegin());
}

double SurfaceProjection::squaredDistance(const Vec3& p) const {
  return tree_->tree.squared_distance(point(p));
}

}  // namespace lloydscope
