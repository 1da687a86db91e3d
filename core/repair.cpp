#include "repair.h"

#include "cgal_types.h"

#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_degeneracies.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>

#include <algorithm>
#include <array>
#include <cmath>
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

// The faces of zero area as readMesh() tells them (hasZeroArea: up to rounding).
std::vector<SurfaceMesh::Face_index> flatFaces(const SurfaceMesh& sm) {
  std::vector<SurfaceMesh::Face_index> flat;
  for (SurfaceMesh::Face_index f : sm.faces()) {
    std::array<Vec3, 3> corner;
    int k = 0;
    for (SurfaceMesh::Vertex_index v : CGAL::vertices_around_face(sm.halfedge(f), sm)) {
      const Point3& p = sm.point(v);
      corner[k++] = Vec3(p.x(), p.y(), p.z());
    }
    if (hasZeroArea(corner[0], corner[1], corner[2])) flat.push_back(f);
  }
  return flat;
}

// Removes the faces of zero area: those exactly flat by collapsing or flipping an edge (CGAL's
// remove_degenerate_faces), then those flat only up to rounding (a corner a hair off the line of
// the other two, which the exact test calls a triangle) as CGAL's almost-degenerate removal
// does: a cap's longest edge flipped, a needle's shortest collapsed. Returns how many there were.
int removeFlatFaces(SurfaceMesh& sm) {
  const int count = static_cast<int>(flatFaces(sm).size());
  if (count == 0) return 0;
  PMP::remove_degenerate_faces(sm);
  const std::vector<SurfaceMesh::Face_index> nearlyFlat = flatFaces(sm);
  if (!nearlyFlat.empty()) {
    // An angle within 1e-12 of 180 degrees is a cap, edges 10^6 times as long as another a
    // needle: a flat face is one or the other (the sine of one of its angles is under 1e-12).
    const double capCosine = std::cos(179.0 * M_PI / 180.0), needleRatio = 1e6;
    PMP::experimental::remove_almost_degenerate_faces(nearlyFlat, sm, capCosine, needleRatio, 0.0);
  }
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
  result.degenerateFaces = removeFlatFaces(sm);
  result.mesh = result.changed() ? fromSurfaceMesh(sm) : mesh;
  return result;
}

}  // namespace lloydscope
