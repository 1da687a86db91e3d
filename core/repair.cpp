#include "repair.h"

#include "cgal_types.h"

#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_degeneracies.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>

#include <vector>

namespace lloydscope {

namespace PMP = CGAL::Polygon_mesh_processing;

namespace {

using Soup = std::vector<std::vector<std::size_t>>;

// orient_polygon_soup reverses faces in place (and may give a corner a new copy of its point):
// a face is turned if its corners' positions now run the other way round.
int turnedFaces(const std::vector<Point3>& points, const Soup& before, const Soup& after) {
  int turned = 0;
  for (std::size_t i = 0; i < before.size(); ++i) {
    const auto &a = before[i], &b = after[i];
    const std::size_t n = a.size();
    for (std::size_t k = 0; k < n; ++k) {
      if (points[a[k]] != points[b[0]]) continue;
      if (points[a[(k + 1) % n]] != points[b[1]]) ++turned;
      break;
    }
  }
  return turned;
}

int degenerateFaceCount(const SurfaceMesh& sm) {
  int count = 0;
  for (SurfaceMesh::Face_index f : sm.faces())
    if (PMP::is_degenerate_triangle_face(f, sm)) ++count;
  return count;
}

}  // namespace

RepairResult repairMesh(const Mesh& mesh) {
  std::vector<Point3> points;
  points.reserve(mesh.points.size());
  for (const Vec3& p : mesh.points) points.emplace_back(p.x(), p.y(), p.z());
  Soup faces;
  faces.reserve(mesh.triangles.size());
  std::vector<bool> used(mesh.points.size(), false);
  for (const Triangle& t : mesh.triangles) {
    faces.push_back({std::size_t(t[0]), std::size_t(t[1]), std::size_t(t[2])});
    for (int v : t) used[v] = true;
  }
  const int usedCount = static_cast<int>(std::count(used.begin(), used.end(), true));

  RepairResult result;
  PMP::repair_polygon_soup(points, faces);  // also drops unused points
  result.droppedFaces = mesh.faceCount() - static_cast<int>(faces.size());
  const Soup welded = faces;
  PMP::orient_polygon_soup(points, faces);
  result.turnedFaces = turnedFaces(points, welded, faces);
  result.weldedVertices = usedCount - static_cast<int>(points.size());

  SurfaceMesh sm;
  PMP::polygon_soup_to_polygon_mesh(points, faces, sm);
  result.degenerateFaces = degenerateFaceCount(sm);
  if (result.degenerateFaces > 0) PMP::remove_degenerate_faces(sm);
  result.mesh = result.changed() ? fromSurfaceMesh(sm) : mesh;
  return result;
}

}  // namespace lloydscope
