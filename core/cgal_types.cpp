#include "cgal_types.h"

#include <vector>

namespace lloydscope {

SurfaceMesh toSurfaceMesh(const Mesh& mesh) {
  SurfaceMesh sm;
  sm.reserve(mesh.points.size(), 3 * mesh.triangles.size() / 2, mesh.triangles.size());
  for (const Vec3& p : mesh.points) sm.add_vertex(Point3(p.x(), p.y(), p.z()));
  for (const Triangle& t : mesh.triangles)
    sm.add_face(SurfaceMesh::Vertex_index(t[0]), SurfaceMesh::Vertex_index(t[1]),
                SurfaceMesh::Vertex_index(t[2]));
  return sm;
}

Mesh fromSurfaceMesh(const SurfaceMesh& sm) {
  Mesh mesh;
  std::vector<int> index(sm.num_vertices(), -1);  // num_vertices counts removed ones too
  for (SurfaceMesh::Vertex_index v : sm.vertices()) {
    index[v] = mesh.vertexCount();
    const Point3& p = sm.point(v);
    mesh.points.emplace_back(p.x(), p.y(), p.z());
  }
  for (SurfaceMesh::Face_index f : sm.faces()) {
    Triangle t{};
    int k = 0;
    for (SurfaceMesh::Vertex_index v : sm.vertices_around_face(sm.halfedge(f)))
      if (k < 3) t[k++] = index[v];
    mesh.triangles.push_back(t);
  }
  return mesh;
}

}  // namespace lloydscope
