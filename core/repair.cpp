#include "repair.h"

#include "cgal_types.h"

#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_degeneracies.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>

#include <algorithm>
#include <vector>

namespace lloydscope {

namespace PMP = CGAL::Polygon_mesh_processing;

namespace {

using Soup = std::vector<std::vector<std::size_t>>;

// orient_polygon_soup reverses faces in place (and may give a corner a new copy of its point):
// a face is turned if its corners' positions now run the other way round.
std::vector<bool> turnedFaces(const std::vector<Point3>& points, const Soup& before, const Soup& after) {
  std::vector<bool> turned(before.size(), false);
  for (std::size_t i = 0; i < before.size(); ++i) {
    const auto &a = before[i], &b = after[i];
    const std::size_t n = a.size();
    for (std::size_t k = 0; k < n; ++k) {
      if (points[a[k]] != points[b[0]]) continue;
      turned[i] = points[a[(k + 1) % n]] != points[b[1]];
      break;
    }
  }
  return turned;
}

// orient_polygon_soup keeps the first face of each piece as it was and turns its neighbours to
// match: where that face was the odd one out, the whole piece is turned back, so that most faces
// keep the side the file gave them. `sm` is the soup as a mesh, face i its face i (all added).
// Returns whether it turned any piece back (`faces` and `turned` follow; `sm` does not).
bool turnMostBack(SurfaceMesh& sm, Soup& faces, std::vector<bool>& turned) {
  auto piece = sm.add_property_map<SurfaceMesh::Face_index, std::size_t>("f:piece", 0).first;
  std::vector<long> balance(PMP::connected_components(sm, piece), 0);  // turned less the others
  for (SurfaceMesh::Face_index f : sm.faces()) balance[piece[f]] += turned[f] ? 1 : -1;
  bool any = false;
  for (SurfaceMesh::Face_index f : sm.faces()) {
    if (balance[piece[f]] <= 0) continue;
    std::reverse(faces[f].begin(), faces[f].end());
    turned[f] = !turned[f];
    any = true;
  }
  sm.remove_property_map(piece);
  return any;
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
  result.weldedVertices = usedCount - static_cast<int>(points.size());

  std::vector<bool> turned = turnedFaces(points, welded, faces);
  SurfaceMesh sm;
  PMP::polygon_soup_to_polygon_mesh(points, faces, sm);
  if (sm.number_of_faces() == faces.size() && turnMostBack(sm, faces, turned)) {
    sm.clear();
    PMP::polygon_soup_to_polygon_mesh(points, faces, sm);
  }
  result.turnedFaces = static_cast<int>(std::count(turned.begin(), turned.end(), true));
  result.degenerateFaces = degenerateFaceCount(sm);
  if (result.degenerateFaces > 0) PMP::remove_degenerate_faces(sm);
  result.mesh = result.changed() ? fromSurfaceMesh(sm) : mesh;
  return result;
}

}  // namespace lloydscope
