#include "polish.h"

#include "cgal_types.h"

#include <CGAL/Polygon_mesh_processing/angle_and_area_smoothing.h>
#include <CGAL/Polygon_mesh_processing/border.h>

#include <cmath>
#include <unordered_map>
#include <unordered_set>

namespace lloydscope {

namespace {

double angleAt(const Vec3& apex, const Vec3& p, const Vec3& q) {
  const Vec3 u = p - apex, v = q - apex;
  return std::atan2(u.cross(v).norm(), u.dot(v));
}

Vec3 normal(const Mesh& m, const Triangle& t) {
  return (m.points[t[1]] - m.points[t[0]]).cross(m.points[t[2]] - m.points[t[0]]);
}

using EdgeKey = long long;
EdgeKey key(int a, int b, int n) { return static_cast<EdgeKey>(std::min(a, b)) * n + std::max(a, b); }

}  // namespace

int flipToDelaunay(Mesh& mesh) {
  const int n = mesh.vertexCount();
  int flips = 0;
  for (int pass = 0; pass < 50; ++pass) {
    // Each directed edge a -> b to its face; an edge is interior when both directions exist.
    std::unordered_map<EdgeKey, int> faceOf;  // key (a, b) directed as a * n + b
    std::unordered_set<EdgeKey> edges;
    for (int f = 0; f < mesh.faceCount(); ++f)
      for (int k = 0; k < 3; ++k) {
        const int a = mesh.triangles[f][k], b = mesh.triangles[f][(k + 1) % 3];
        faceOf[static_cast<EdgeKey>(a) * n + b] = f;
        edges.insert(key(a, b, n));
      }
    std::vector<bool> touched(mesh.faceCount(), false);
    int passFlips = 0;
    for (int f1 = 0; f1 < mesh.faceCount(); ++f1)
      for (int k = 0; k < 3 && !touched[f1]; ++k) {
        const Triangle t1 = mesh.triangles[f1];
        const int a = t1[k], b = t1[(k + 1) % 3], c = t1[(k + 2) % 3];
        const auto other = faceOf.find(static_cast<EdgeKey>(b) * n + a);
        if (other == faceOf.end() || touched[other->second] || a > b) continue;
        const int f2 = other->second;
        const Triangle& t2 = mesh.triangles[f2];
        int d = -1;
        for (int v : t2)
          if (v != a && v != b) d = v;
        if (d < 0 || d == c || edges.count(key(c, d, n))) continue;
        const Vec3 &pa = mesh.points[a], &pb = mesh.points[b], &pc = mesh.points[c],
                   &pd = mesh.points[d];
        if (angleAt(pc, pa, pb) + angleAt(pd, pb, pa) <= M_PI + 1e-9) continue;
        // (a, b, c) and (b, a, d) become (c, a, d) and (d, b, c): keep both facing the same way.
        const Triangle n1{c, a, d}, n2{d, b, c};
        const Vec3 before = normal(mesh, t1).normalized() + normal(mesh, t2).normalized();
        const Vec3 m1 = normal(mesh, n1), m2 = normal(mesh, n2);
        if (m1.dot(before) <= 0 || m2.dot(before) <= 0 || m1.norm() < 1e-14 || m2.norm() < 1e-14)
          continue;
        mesh.triangles[f1] = n1;
        mesh.triangles[f2] = n2;
        touched[f1] = touched[f2] = true;
        edges.insert(key(c, d, n));
        ++passFlips;
      }
    flips += passFlips;
    if (passFlips == 0) break;
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
