#include "mesh.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <tuple>

namespace lloydscope {

Mesh assemble(const std::vector<Triangle>& triangles, const std::vector<Vec3>& points,
              std::vector<int>* kept) {
  std::vector<int> newIndex(points.size(), -1);
  for (const Triangle& t : triangles)
    for (int v : t) newIndex[v] = 0;
  Mesh output;
  for (size_t v = 0; v < points.size(); ++v) {
    if (newIndex[v] < 0) continue;
    newIndex[v] = output.vertexCount();
    output.points.push_back(points[v]);
    if (kept) kept->push_back(static_cast<int>(v));
  }
  for (const Triangle& t : triangles)
    output.triangles.push_back({newIndex[t[0]], newIndex[t[1]], newIndex[t[2]]});
  return output;
}

std::vector<MeshEdge> uniqueEdges(const Mesh& mesh) {
  std::vector<MeshEdge> edges;
  edges.reserve(3 * mesh.triangles.size());
  for (size_t f = 0; f < mesh.triangles.size(); ++f)
    for (int k = 0; k < 3; ++k) {
      const auto [from, to] = std::minmax(mesh.triangles[f][k], mesh.triangles[f][(k + 1) % 3]);
      edges.push_back({from, to, static_cast<int>(f)});
    }
  const auto key = [](const MeshEdge& e) { return std::make_tuple(e.from, e.to, e.triangle); };
  std::sort(edges.begin(), edges.end(), [&](const MeshEdge& a, const MeshEdge& b) { return key(a) < key(b); });
  edges.erase(std::unique(edges.begin(), edges.end(),
                          [](const MeshEdge& a, const MeshEdge& b) { return a.from == b.from && a.to == b.to; }),
              edges.end());
  return edges;
}

VertexEdges vertexEdges(const Mesh& mesh) {
  // Each vertex's neighbours, once per face they share: across an inside edge twice, across a
  // border edge once. Small per-vertex sorts instead of one sort of every edge: the polish
  // asks for this after every pass.
  const size_t n = mesh.points.size();
  std::vector<int> offset(n + 1, 0);
  for (const Triangle& t : mesh.triangles)
    for (int v : t) offset[v + 1] += 2;
  std::partial_sum(offset.begin(), offset.end(), offset.begin());
  std::vector<int> neighbour(offset.back()), fill(offset.begin(), offset.end() - 1);
  for (const Triangle& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      neighbour[fill[t[k]]++] = t[(k + 1) % 3];
      neighbour[fill[t[k]]++] = t[(k + 2) % 3];
    }
  VertexEdges v{std::vector<int>(n, 0), std::vector<bool>(n, false)};
  for (size_t u = 0; u < n; ++u) {
    const auto begin = neighbour.begin() + offset[u], end = neighbour.begin() + offset[u + 1];
    std::sort(begin, end);
    for (auto i = begin; i != end;) {
      const auto j = std::find_if(i, end, [&](int w) { return w != *i; });
      ++v.valence[u];
      if (j - i == 1) v.onBoundary[u] = true;  // an edge of one face
      i = j;
    }
  }
  return v;
}

void append(Mesh& to, const Mesh& part) {
  const int offset = to.vertexCount();
  to.points.insert(to.points.end(), part.points.begin(), part.points.end());
  for (Triangle t : part.triangles) to.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
}

namespace {
template <class Point>
std::pair<Point, Point> boxOf(const std::vector<Point>& points) {
  if (points.empty()) return {Point::Zero(), Point::Zero()};
  Point lo = points.front(), hi = lo;
  for (const Point& p : points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  return {lo, hi};
}
}  // namespace

std::pair<Vec3, Vec3> boundingBox(const std::vector<Vec3>& points) { return boxOf(points); }
std::pair<Vec2, Vec2> boundingBox(const std::vector<Vec2>& points) { return boxOf(points); }

std::pair<Vec3, Vec3> boundingBox(const Mesh& mesh) { return boundingBox(mesh.points); }

double boundingBoxDiagonal(const Mesh& mesh) {
  const auto [lo, hi] = boundingBox(mesh);
  return (hi - lo).norm();
}

double cornerAngle(const Vec3& a, const Vec3& b, const Vec3& c) {
  return std::atan2((b - a).cross(c - a).norm(), (b - a).dot(c - a));
}

double cornerAngle(const Vec2& a, const Vec2& b, const Vec2& c) {
  const Vec2 u = b - a, v = c - a;
  return std::atan2(std::abs(u.x() * v.y() - u.y() * v.x()), u.dot(v));
}

double surfaceArea(const Mesh& mesh) {
  double area = 0;
  for (const Triangle& t : mesh.triangles)
    area += triangleArea(mesh.points[t[0]], mesh.points[t[1]], mesh.points[t[2]]);
  return area;
}

double mapArea(const Mesh& mesh, const std::vector<Vec2>& uv) {
  double area = 0;
  for (const Triangle& t : mesh.triangles) area += std::abs(triangleArea(uv[t[0]], uv[t[1]], uv[t[2]]));
  return area;
}

double equilateralEdgeLength(double area, int vertices) { return std::sqrt(2.0 * area / (std::sqrt(3.0) * vertices)); }

double loopLength(const Mesh& mesh, const std::vector<int>& loop) {
  double length = 0;
  for (size_t i = 0; i < loop.size(); ++i) length += (mesh.points[loop[i]] - mesh.points[loop[(i + 1) % loop.size()]]).norm();
  return length;
}

double triangleArea(const Vec3& a, const Vec3& b, const Vec3& c) {
  return 0.5 * (b - a).cross(c - a).norm();
}

bool hasZeroArea(const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 u = b - a, v = c - a;
  return u.cross(v).norm() <= 1e-12 * u.norm() * v.norm();
}

namespace {
template <class Point>
double distanceToSegmentOf(const Point& p, const Point& a, const Point& b) {
  const Point ab = b - a;
  const double t = ab.squaredNorm() > 0 ? std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0) : 0.0;
  return (p - (a + t * ab)).norm();
}
}  // namespace

double distanceToSegment(const Vec3& p, const Vec3& a, const Vec3& b) { return distanceToSegmentOf(p, a, b); }
double distanceToSegment(const Vec2& p, const Vec2& a, const Vec2& b) { return distanceToSegmentOf(p, a, b); }

double triangleArea(const Vec2& a, const Vec2& b, const Vec2& c) { return 0.5 * cross(b - a, c - a); }

size_t pickByShare(const std::vector<double>& cumulative, double at) {
  const size_t index = std::upper_bound(cumulative.begin(), cumulative.end(), at) - cumulative.begin();
  return std::min(index, cumulative.size() - 1);
}

Rings::Rings(const Mesh& m) : offset(m.vertexCount() + 1, 0) {
  for (const Triangle& t : m.triangles)
    for (int v : t) ++offset[v + 1];
  for (size_t v = 1; v < offset.size(); ++v) offset[v] += offset[v - 1];
  faces.resize(offset.back());
  std::vector<int> fill(offset.begin(), offset.end() - 1);
  for (int f = 0; f < m.faceCount(); ++f)
    for (int v : m.triangles[f]) faces[fill[v]++] = f;
}

Vec3 faceNormal(const Mesh& m, const Triangle& t) {
  return (m.points[t[1]] - m.points[t[0]]).cross(m.points[t[2]] - m.points[t[0]]);
}

}  // namespace lloydscope
