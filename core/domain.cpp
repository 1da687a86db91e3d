#include "domain.h"

#include "cgal_types.h"

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>

#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <map>

namespace lloydscope {

namespace {
using Triangle3 = Kernel::Triangle_3;
using Primitive = CGAL::AABB_triangle_primitive<Kernel, std::vector<Triangle3>::const_iterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<Kernel, Primitive>>;
}  // namespace

// A uniform grid of buckets over the UV bounding box, each listing the triangles whose bounding
// box meets it, answers "which triangle contains p" with a few barycentric tests; CGAL's AABB
// tree over the UV triangles lifted to the plane z = 0 answers "where is the domain closest
// to p" for the points that no triangle contains (a closest-point query, 5-10 times dearer).
struct Domain::Index {
  std::vector<Triangle3> triangles;
  std::vector<int> triangleId;  // of each indexed triangle in Domain::triangles()
  Tree tree;
  Vec2 lo = Vec2::Zero(), hi = Vec2::Zero();  // the buckets' box: the triangles' bounding box
  Vec2 perUnit = Vec2::Zero();                 // buckets per unit of u and of v
  int columns = 0, rows = 0;
  std::vector<int> start, bucket;  // bucket[start[c] .. start[c + 1]): the triangles of cell c
  // The vertices whose every triangle is flat (left out above), by their point: each at its
  // own corner of one of them. The triangle beside such a vertex holds its point on an edge,
  // and lifting it there would put it between that edge's ends (the tip of a slit whose one
  // triangle, an ear, was flat in the map lifted off its seam, which then did not stitch).
  std::map<std::pair<double, double>, Location> stranded;

  bool inBox(const Vec2& p) const {  // (false for NaN)
    return p.x() >= lo.x() && p.y() >= lo.y() && p.x() <= hi.x() && p.y() <= hi.y();
  }
  int cellOf(const Vec2& p) const {  // p in the box
    const int x = std::min(static_cast<int>((p.x() - lo.x()) * perUnit.x()), columns - 1);
    const int y = std::min(static_cast<int>((p.y() - lo.y()) * perUnit.y()), rows - 1);
    return y * columns + x;
  }
  void buildGrid(const std::vector<Vec2>& uv, const std::vector<Triangle>& all);
};

void Domain::Index::buildGrid(const std::vector<Vec2>& uv, const std::vector<Triangle>& all) {
  if (triangleId.empty()) return;
  hi = lo = uv[all[triangleId[0]][0]];
  for (int t : triangleId)
    for (int v : all[t]) {
      lo = lo.cwiseMin(uv[v]);
      hi = hi.cwiseMax(uv[v]);
    }
  const Vec2 size = (hi - lo).cwiseMax(1e-300);
  // About one bucket per triangle, as square as the box allows.
  double perSide = std::sqrt(static_cast<double>(triangleId.size()) / (size.x() * size.y()));
  if (!std::isfinite(perSide)) perSide = 1.0 / std::max(size.x(), size.y());
  columns = std::clamp(static_cast<int>(std::ceil(size.x() * perSide)), 1, 4096);
  rows = std::clamp(static_cast<int>(std::ceil(size.y() * perSide)), 1, 4096);
  perUnit = Vec2(columns / size.x(), rows / size.y());
  auto forCells = [&](int t, const auto& fn) {
    Vec2 a = uv[all[t][0]], b = a;
    for (int v : all[t]) {
      a = a.cwiseMin(uv[v]);
      b = b.cwiseMax(uv[v]);
    }
    const int first = cellOf(a), last = cellOf(b);
    for (int y = first / columns; y <= last / columns; ++y)
      for (int x = first % columns; x <= last % columns; ++x) fn(y * columns + x);
  };
  start.assign(static_cast<size_t>(columns) * rows + 1, 0);
  for (int t : triangleId) forCells(t, [&](int c) { ++start[c + 1]; });
  for (size_t c = 1; c < start.size(); ++c) start[c] += start[c - 1];
  bucket.resize(start.back());
  std::vector<int> filled(start.begin(), start.end() - 1);
  for (int t : triangleId) forCells(t, [&](int c) { bucket[filled[c]++] = t; });
}

Domain::Domain(std::vector<Vec2> uv, std::vector<Triangle> triangles, Density density)
    : uv_(std::move(uv)), triangles_(std::move(triangles)), density_(std::move(density)),
      index_(std::make_unique<Index>()) {
  if (density_.empty()) density_.assign(triangles_.size(), {1.0, 1.0, 1.0});
  std::map<std::pair<int, int>, std::pair<int, int>> edgeOwner;  // (a,b) -> (triangle, corner)
  neighbours_.assign(triangles_.size(), {-1, -1, -1});
  // Flat triangles (ears of a square border) cover nothing: leave them out of the adjacency
  // and the spatial index, so no walk or search ever ends in one.
  std::vector<double> area(triangles_.size());
  double total = 0;
  for (size_t t = 0; t < triangles_.size(); ++t) {
    const Triangle& tri = triangles_[t];
    area[t] = triangleArea(uv_[tri[0]], uv_[tri[1]], uv_[tri[2]]);
    total += std::abs(area[t]);
  }
  std::vector<bool> flat(triangles_.size());
  for (size_t t = 0; t < triangles_.size(); ++t) flat[t] = !(area[t] > kFlatAreaShare * total);
  for (int t = 0; t < static_cast<int>(triangles_.size()); ++t) {
    if (flat[t]) continue;
    for (int k = 0; k < 3; ++k) {
      const int a = triangles_[t][(k + 1) % 3], b = triangles_[t][(k + 2) % 3];
      auto twin = edgeOwner.find({b, a});
      if (twin != edgeOwner.end()) {
        neighbours_[t][k] = twin->second.first;
        neighbours_[twin->second.first][twin->second.second] = t;
      } else {
        edgeOwner[{a, b}] = {t, k};
      }
    }
  }
  for (int t = 0; t < static_cast<int>(triangles_.size()); ++t) {
    // Solve a + b u + c v = rho at the three corners.
    Eigen::Matrix3d m;
    Eigen::Vector3d rho;
    for (int k = 0; k < 3; ++k) {
      const int v = triangles_[t][k];
      m.row(k) << 1.0, uv_[v].x(), uv_[v].y();
      rho[k] = density_[t][k];
    }
    densityPlanes_.push_back(flat[t] ? Eigen::Vector3d(rho.mean(), 0, 0)
                                     : Eigen::Vector3d(m.fullPivLu().solve(rho)));
  }
  index_->triangles.reserve(triangles_.size());
  for (size_t t = 0; t < triangles_.size(); ++t) {
    if (flat[t]) continue;
    auto p = [&](int i) { return Point3(uv_[i].x(), uv_[i].y(), 0.0); };
    index_->triangles.emplace_back(p(triangles_[t][0]), p(triangles_[t][1]), p(triangles_[t][2]));
    index_->triangleId.push_back(static_cast<int>(t));
  }
  std::vector<bool> inIndex(uv_.size(), false);
  for (int t : index_->triangleId)
    for (int v : triangles_[t]) inIndex[v] = true;
  for (int t = 0; t < static_cast<int>(triangles_.size()); ++t)
    for (int k = 0; k < 3; ++k)
      if (const int v = triangles_[t][k]; !inIndex[v])
        index_->stranded.emplace(std::pair(uv_[v].x(), uv_[v].y()), Location{t, Eigen::Vector3d::Unit(k), true});
  index_->tree.insert(index_->triangles.cbegin(), index_->triangles.cend());
  index_->tree.build();
  index_->tree.accelerate_distance_queries();
  index_->buildGrid(uv_, triangles_);
}

Domain::~Domain() = default;
Domain::Domain(Domain&&) noexcept = default;
Domain& Domain::operator=(Domain&&) noexcept = default;

const Location* Domain::stranded(const Vec2& p) const {
  if (index_->stranded.empty()) return nullptr;
  const auto it = index_->stranded.find({p.x(), p.y()});
  return it == index_->stranded.end() ? nullptr : &it->second;
}

Location Domain::locate(const Vec2& p) const {
  if (index_->triangles.empty()) return Location{};
  if (const Location* own = stranded(p)) return *own;
  return locateInArea(p);
}

Location Domain::locate(const Vec2& p, int hint) const {
  if (const Location* own = stranded(p)) return *own;
  return locateInArea(p, hint);
}

Location Domain::locateInArea(const Vec2& p, int hint) const {
  for (int t = hint, step = 0; t >= 0 && step < 64; ++step) {
    const Eigen::Vector3d w = barycentric(t, p);
    int k;
    if (w.minCoeff(&k) >= 0.0) return {t, w, true};
    t = neighbours_[t][k];  // across the edge opposite the most negative weight
  }
  // Left the domain, too far from the hint, or no hint.
  Location l;
  if (index_->triangles.empty()) return l;
  const Index& g = *index_;
  if (g.inBox(p)) {
    const int c = g.cellOf(p);
    for (int k = g.start[c]; k < g.start[c + 1]; ++k) {
      const Eigen::Vector3d w = barycentric(g.bucket[k], p);
      if (w.minCoeff() >= 0.0) return {g.bucket[k], w / w.sum(), true};
    }
  }
  const auto [closest, primitive] =
      index_->tree.closest_point_and_primitive(Point3(p.x(), p.y(), 0.0));
  l.triangle = index_->triangleId[primitive - index_->triangles.cbegin()];
  const Vec2 q(closest.x(), closest.y());
  l.weights = barycentric(l.triangle, q).cwiseMax(0.0);
  l.weights /= l.weights.sum();
  l.inside = (q - p).squaredNorm() == 0.0;
  return l;
}

Eigen::Vector3d Domain::barycentric(int triangle, const Vec2& p) const {
  const Triangle& t = triangles_[triangle];
  const Vec2 &a = uv_[t[0]], &b = uv_[t[1]], &c = uv_[t[2]];
  return Eigen::Vector3d(triangleArea(p, b, c), triangleArea(a, p, c), triangleArea(a, b, p)) /
         triangleArea(a, b, c);
}

Vec2 Domain::pointAt(const Location& l) const {
  const Triangle& t = triangles_[l.triangle];
  return l.weights[0] * uv_[t[0]] + l.weights[1] * uv_[t[1]] + l.weights[2] * uv_[t[2]];
}

int farthestCorner(const Eigen::Vector3d& weights) {
  int off = 0;
  for (int k = 1; k < 3; ++k)
    if (weights[k] < weights[off]) off = k;
  return off;
}

bool Domain::onBorder(const Location& l) const {
  const int off = farthestCorner(l.weights);
  return l.weights[off] <= kOnBorderEdge && neighbours_[l.triangle][off] < 0;
}

}  // namespace lloydscope
