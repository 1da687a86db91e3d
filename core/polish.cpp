#include "polish.h"

#include "cgal_types.h"
#include "metrics.h"

#include <CGAL/Polygon_mesh_processing/angle_and_area_smoothing.h>
#include <CGAL/Polygon_mesh_processing/border.h>

#include <cmath>
#include <unordered_map>

namespace lloydscope {

namespace {

Vec3 normal(const Mesh& m, const Triangle& t) {
  return (m.points[t[1]] - m.points[t[0]]).cross(m.points[t[2]] - m.points[t[0]]);
}

using EdgeKey = long long;

}  // namespace

int flipToDelaunay(Mesh& mesh) {
  const long long n = mesh.vertexCount();
  auto directed = [n](int a, int b) { return a * n + b; };
  std::unordered_map<EdgeKey, int> faceOf;  // each directed edge a -> b to the face that has it
  faceOf.reserve(3 * mesh.triangles.size());
  std::vector<std::pair<int, int>> work;  // edges to check, each direction once
  for (int f = 0; f < mesh.faceCount(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = mesh.triangles[f][k], b = mesh.triangles[f][(k + 1) % 3];
      faceOf[directed(a, b)] = f;
      if (a < b) work.emplace_back(a, b);
    }
  auto third = [&](int f, int a, int b) {
    for (int v : mesh.triangles[f])
      if (v != a && v != b) return v;
    return -1;
  };
  int flips = 0;
  // Flipping on a surface need not terminate as in the plane: bound the work.
  for (size_t budget = 20 * mesh.triangles.size() + 100; !work.empty() && budget > 0; --budget) {
    const auto [a, b] = work.back();
    work.pop_back();
    const auto e1 = faceOf.find(directed(a, b)), e2 = faceOf.find(directed(b, a));
    if (e1 == faceOf.end() || e2 == faceOf.end()) continue;  // a border edge, or gone
    const int f1 = e1->second, f2 = e2->second;  // (a, b, c) and (b, a, d)
    const int c = third(f1, a, b), d = third(f2, a, b);
    if (c < 0 || d < 0 || c == d || faceOf.count(directed(c, d)) || faceOf.count(directed(d, c)))
      continue;
    const Vec3 &pa = mesh.points[a], &pb = mesh.points[b], &pc = mesh.points[c],
               &pd = mesh.points[d];
    const double opposite = cornerAnglesDeg(pc, pa, pb)[0] + cornerAnglesDeg(pd, pb, pa)[0];
    if (opposite <= 180.0 + 1e-9 * 180.0 / M_PI) continue;
    const Triangle n1{c, a, d}, n2{d, b, c};  // keep both facing the same way
    const Vec3 before = normal(mesh, mesh.triangles[f1]).normalized() +
                        normal(mesh, mesh.triangles[f2]).normalized();
    const Vec3 m1 = normal(mesh, n1), m2 = normal(mesh, n2);
    if (m1.dot(before) <= 0 || m2.dot(before) <= 0 || m1.norm() < 1e-14 || m2.norm() < 1e-14)
      continue;
    for (int f : {f1, f2})
      for (int k = 0; k < 3; ++k)
        faceOf.erase(directed(mesh.triangles[f][k], mesh.triangles[f][(k + 1) % 3]));
    mesh.triangles[f1] = n1;
    mesh.triangles[f2] = n2;
    for (int f : {f1, f2})
      for (int k = 0; k < 3; ++k)
        faceOf[directed(mesh.triangles[f][k], mesh.triangles[f][(k + 1) % 3])] = f;
    for (auto [u, v] : {std::pair{a, c}, std::pair{a, d}, std::pair{b, c}, std::pair{b, d}})
      work.emplace_back(std::min(u, v), std::max(u, v));
    ++flips;
  }
  return flips;
}

Mesh polish(const Mesh& mesh, const PolishOptions& options) {
  Mesh result = mesh;
  flipToDelaunay(result);
  if (options.smoothingIterations <= 0) return result;
  SurfaceMesh sm = toSurfaceMesh(result);
  auto fixed = sm.add_property_map<SurfaceMesh::Vertex_index, bool>("v:fixed", false).first;
  for (SurfaceMesh::Vertex_index v : sm.vertices())
    if (CGAL::is_border(v, sm)) fixed[v] = true;
  CGAL::Polygon_mesh_processing::angle_and_area_smoothing(
      faces(sm), sm,
      CGAL::parameters::number_of_iterations(options.smoothingIterations)
          .use_area_smoothing(false)
          .use_safety_constraints(true)
          .vertex_is_constrained_map(fixed));
  result = fromSurfaceMesh(sm);
  flipToDelaunay(result);
  return result;
}

}  // namespace lloydscope
