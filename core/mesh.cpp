#include "mesh.h"

#include <algorithm>

namespace lloydscope {

VertexEdges vertexEdges(const Mesh& mesh) {
  // Sorted edge list: each undirected edge appears once per face that uses it.
  std::vector<std::pair<int, int>> edges;
  edges.reserve(3 * mesh.triangles.size());
  for (const Triangle& t : mesh.triangles)
    for (int k = 0; k < 3; ++k)
      edges.emplace_back(std::min(t[k], t[(k + 1) % 3]), std::max(t[k], t[(k + 1) % 3]));
  std::sort(edges.begin(), edges.end());
  VertexEdges v{std::vector<int>(mesh.points.size(), 0),
                std::vector<bool>(mesh.points.size(), false)};
  for (size_t i = 0; i < edges.size();) {
    size_t j = i;
    while (j < edges.size() && edges[j] == edges[i]) ++j;
    const auto [a, b] = edges[i];
    ++v.valence[a];
    ++v.valence[b];
    if (j - i == 1) v.onBoundary[a] = v.onBoundary[b] = true;
    i = j;
  }
  return v;
}

std::pair<Vec3, Vec3> boundingBox(const Mesh& mesh) {
  if (mesh.points.empty()) return {Vec3::Zero(), Vec3::Zero()};
  Vec3 lo = mesh.points.front(), hi = lo;
  for (const Vec3& p : mesh.points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  return {lo, hi};
}

double boundingBoxDiagonal(const Mesh& mesh) {
  const auto [lo, hi] = boundingBox(mesh);
  return (hi - lo).norm();
}

double surfaceArea(const Mesh& mesh) {
  double area = 0;
  for (const Triangle& t : mesh.triangles)
    area += triangleArea(mesh.points[t[0]], mesh.points[t[1]], mesh.points[t[2]]);
  return area;
}

double triangleArea(const Vec3& a, const Vec3& b, const Vec3& c) {
  return 0.5 * (b - a).cross(c - a).norm();
}

double triangleArea(const Vec2& a, const Vec2& b, const Vec2& c) {
  const Vec2 u = b - a, v = c - a;
  return 0.5 * (u.x() * v.y() - u.y() * v.x());
}

}  // namespace lloydscope
