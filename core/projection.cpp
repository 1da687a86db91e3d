#include "projection.h"

#include "cgal_types.h"
#include "parallel.h"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <tbb/parallel_sort.h>

#include <algorithm>
#include <cstdint>
#include <thread>
#include <vector>

namespace lloydscope {

namespace {

using Triangle3 = Kernel::Triangle_3;
using Primitive = CGAL::AABB_triangle_primitive<Kernel, std::vector<Triangle3>::const_iterator>;
using AabbTree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;

Point3 point(const Vec3& p) { return Point3(p.x(), p.y(), p.z()); }

// The 10 bits of x spread to every third bit.
uint64_t spreadBits(uint64_t x) {
  x = (x | (x << 16)) & 0x030000FF;
  x = (x | (x << 8)) & 0x0300F00F;
  x = (x | (x << 4)) & 0x030C30C3;
  return (x | (x << 2)) & 0x09249249;
}

// The points' indices in Morton (Z) order on a 1024^3 grid over their bounding box: near in
// the order, near in space, for a few sorts of 64-bit keys (CGAL's Hilbert sort took as long as
// the queries it ordered).
std::vector<size_t> mortonOrder(const std::vector<Vec3>& points) {
  const auto [lo, hi] = boundingBox(points);
  const double scale = 1023.0 / std::max((hi - lo).maxCoeff(), 1e-300);
  std::vector<uint64_t> keys(points.size());
  for (size_t i = 0; i < points.size(); ++i) {
    const Vec3 g = (points[i] - lo) * scale;
    const uint64_t cell = spreadBits(static_cast<uint64_t>(g.x())) | spreadBits(static_cast<uint64_t>(g.y())) << 1 |
                          spreadBits(static_cast<uint64_t>(g.z())) << 2;
    keys[i] = cell << 32 | i;  // ties in index order
  }
  tbb::parallel_sort(keys.begin(), keys.end());  // the keys differ: one order, whatever the threads
  std::vector<size_t> order(points.size());
  for (size_t i = 0; i < keys.size(); ++i) order[i] = keys[i] & 0xFFFFFFFFu;
  return order;
}

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

bool SurfaceProjection::hides(const Vec3& eye, const Vec3& p) const {
  return tree_->tree.do_intersect(Kernel::Segment_3(point(eye), point(eye + (1 - 1e-6) * (p - eye))));
}

Vec3 SurfaceProjection::closestPoint(const Vec3& p) const {
  const Point3 c = tree_->tree.closest_point(point(p));
  return Vec3(c.x(), c.y(), c.z());
}

int SurfaceProjection::closestTriangle(const Vec3& p, double* squaredDistance) const {
  const auto closest = tree_->tree.closest_point_and_primitive(point(p));
  if (squaredDistance) *squaredDistance = CGAL::squared_distance(closest.first, point(p));
  return static_cast<int>(closest.second - tree_->triangles.cbegin());
}

double SurfaceProjection::squaredDistance(const Vec3& p) const {
  return tree_->tree.squared_distance(point(p));
}

double SurfaceProjection::squaredDistance(const Vec3& p, Vec3& onSurface) const {
  onSurface = closestPoint(p, onSurface);
  return CGAL::squared_distance(point(p), point(onSurface));
}

Vec3 SurfaceProjection::closestPoint(const Vec3& p, const Vec3& onSurface) const {
  const Point3 c = tree_->tree.closest_point(point(p), point(onSurface));
  return Vec3(c.x(), c.y(), c.z());
}

std::vector<Vec3> SurfaceProjection::closestPoints(const std::vector<Vec3>& points, int threads) const {
  std::vector<Vec3> closest(points.size());
  inSpatialOrder(points, threads, [&](size_t i, const Point3& c, int) { closest[i] = Vec3(c.x(), c.y(), c.z()); });
  return closest;
}

std::vector<double> SurfaceProjection::squaredDistances(const std::vector<Vec3>& points) const {
  std::vector<double> squared(points.size());
  inSpatialOrder(points, 0, [&](size_t i, const Point3& c, int) { squared[i] = CGAL::squared_distance(point(points[i]), c); });
  return squared;
}

std::vector<int> SurfaceProjection::closestTriangles(const std::vector<Vec3>& points, std::vector<double>& squared) const {
  std::vector<int> closest(points.size());
  squared.resize(points.size());
  inSpatialOrder(points, 0, [&](size_t i, const Point3& c, int triangle) {
    closest[i] = triangle;
    squared[i] = CGAL::squared_distance(point(points[i]), c);
  });
  return closest;
}

SurfaceProjection::Nearby SurfaceProjection::nearby(const Vec3& centre, double reach) const {
  Nearby n;
  n.tree_ = tree_.get();
  n.low_ = centre - Vec3::Constant(reach);
  n.high_ = centre + Vec3::Constant(reach);
  std::vector<AabbTree::Primitive_id> found;
  const CGAL::Bbox_3 cube(n.low_.x(), n.low_.y(), n.low_.z(), n.high_.x(), n.high_.y(), n.high_.z());
  tree_->tree.all_intersected_primitives(cube, std::back_inserter(found));
  for (const auto& id : found) {
    const CGAL::Bbox_3 b = id->bbox();
    n.triangles_.push_back(static_cast<int>(id - tree_->triangles.cbegin()));
    n.triangleLow_.emplace_back(b.xmin(), b.ymin(), b.zmin());
    n.triangleHigh_.emplace_back(b.xmax(), b.ymax(), b.zmax());
  }
  return n;
}

Vec3 SurfaceProjection::Nearby::closestPoint(const Vec3& p, const Vec3& onSurface, bool* searchedTree) const {
  const Kernel kernel;
  const Point3 q = point(p);
  // As the tree's search: from the hint, each triangle's point taken unless farther (ties go to
  // the later one, in the tree's order, which all_intersected_primitives keeps).
  Point3 best = point(onSurface);
  double bestSquared = CGAL::squared_distance(q, best);
  for (size_t i = 0; i < triangles_.size(); ++i) {
    const Vec3 outsideBox = (triangleLow_[i] - p).cwiseMax(p - triangleHigh_[i]).cwiseMax(0.0);
    if (outsideBox.squaredNorm() > bestSquared * (1 + 1e-9)) continue;  // a tie kept, rounding and all
    const Point3 c = kernel.construct_projected_point_3_object()(tree_->triangles[triangles_[i]], q);
    if (kernel.compare_distance_3_object()(q, c, best) != CGAL::LARGER) {
      best = c;
      bestSquared = CGAL::squared_distance(q, c);
    }
  }
  const Vec3 radius = Vec3::Constant(std::sqrt(bestSquared) * (1 + 1e-9));
  const bool inside = ((p - radius).array() >= low_.array()).all() && ((p + radius).array() <= high_.array()).all();
  if (searchedTree) *searchedTree = !inside;
  if (!inside) best = tree_->tree.closest_point(q, point(onSurface));
  return Vec3(best.x(), best.y(), best.z());
}

template <class Fn>
void SurfaceProjection::inSpatialOrder(const std::vector<Vec3>& points, int threadCount, const Fn& fn) const {
  const auto found = [&](size_t i, const AabbTree::Point_and_primitive_id& c) {
    fn(i, c.first, static_cast<int>(c.second - tree_->triangles.cbegin()));
  };
  if (points.size() < 16) {  // a handful (a local check in the polish): ordering them costs more than it saves
    for (size_t i = 0; i < points.size(); ++i) found(i, tree_->tree.closest_point_and_primitive(point(points[i])));
    return;
  }
  const std::vector<size_t> order = mortonOrder(points);
  const size_t threads = points.size() < 1000 ? 1
                         : threadCount > 0    ? static_cast<size_t>(threadCount)
                                              : std::max(1u, std::thread::hardware_concurrency());
  parallelFor(order.size(), threads, [&](size_t begin, size_t end) {
    // The search is exact whatever the hint: only its speed depends on it.
    auto hint = tree_->tree.closest_point_and_primitive(point(points[order[begin]]));
    for (size_t i = begin; i < end; ++i) {
      hint = tree_->tree.closest_point_and_primitive(point(points[order[i]]), hint);
      found(order[i], hint);
    }
  });
}

}  // namespace lloydscope
