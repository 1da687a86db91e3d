#include "remesh.h"

#include "cgal_types.h"
#include "lloyd.h"
#include "metrics.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <algorithm>
#include <cmath>
#include <deque>

namespace lloydscope {

namespace {

struct FaceInfo {
  int nesting = -1;  // how many constraint edges separate the face from the outside
  bool inDomain() const { return nesting % 2 == 1; }
};
using VertexBase = CGAL::Triangulation_vertex_base_with_info_2<int, Kernel>;
using FaceBase = CGAL::Triangulation_face_base_with_info_2<
    FaceInfo, Kernel, CGAL::Constrained_triangulation_face_base_2<Kernel>>;
using Tds = CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<Kernel, Tds, CGAL::Exact_predicates_tag>;

// Flood from the infinite face; crossing a constraint edge raises the nesting level
// (CGAL's polygon-triangulation example).
void markDomain(Cdt& cdt) {
  std::deque<std::pair<Cdt::Face_handle, int>> queue = {{cdt.infinite_face(), 0}};
  std::deque<std::pair<Cdt::Face_handle, int>> nextLevel;
  while (!queue.empty()) {
    while (!queue.empty()) {
      auto [face, level] = queue.front();
      queue.pop_front();
      if (face->info().nesting != -1) continue;
      face->info().nesting = level;
      for (int i = 0; i < 3; ++i) {
        Cdt::Face_handle n = face->neighbor(i);
        if (n->info().nesting != -1) continue;
        if (cdt.is_constrained({face, i}))
          nextLevel.push_back({n, level + 1});
        else
          queue.push_back({n, level});
      }
    }
    queue.swap(nextLevel);
  }
}

}  // namespace

Vec3 lift(const Mesh& input, const Domain& domain, const Vec2& p, int hint) {
  const Location l = hint >= 0 ? domain.locate(p, hint) : domain.locate(p);
  const Triangle& t = input.triangles[l.triangle];
  return l.weights[0] * input.points[t[0]] + l.weights[1] * input.points[t[1]] +
         l.weights[2] * input.points[t[2]];
}

Relocation relocate(const Mesh& input, const Domain& domain, const std::vector<int>& movableVertex,
                    const std::vector<Vec2>& sites) {
  Relocation r{input, domain.uv(), 0};
  std::vector<std::vector<int>> ring(input.vertexCount());  // each vertex's triangles
  std::vector<double> area(input.faceCount());               // each one's in the map, signed
  for (int f = 0; f < input.faceCount(); ++f) {
    const Triangle& t = input.triangles[f];
    for (int v : t) ring[v].push_back(f);
    area[f] = triangleArea(r.uv[t[0]], r.uv[t[1]], r.uv[t[2]]);
  }
  const auto corner = [&](int v) { return Vec3(r.uv[v].x(), r.uv[v].y(), 0.0); };
  // The smallest angle of v's triangles in the domain, 0 where one faces the other way.
  const auto smallestAngle = [&](int v) {
    double smallest = 180;
    for (int f : ring[v]) {
      const Triangle& t = input.triangles[f];
      if (!(area[f] * triangleArea(r.uv[t[0]], r.uv[t[1]], r.uv[t[2]]) > 0)) return 0.0;
      smallest = std::min(smallest, smallestAngleDeg(corner(t[0]), corner(t[1]), corner(t[2])));
    }
    return smallest;
  };
  // Each vertex as far towards its site as its triangles stay unfolded, their smallest angle
  // in the domain not under the lesser of what it was and kSmallest (pushed to the edge of a
  // fold, a triangle is a sliver): the whole way, or half of what is left, a quarter, ... (six
  // halvings); again while a sweep moves any.
  constexpr double kSmallest = 5;
  constexpr int kSweeps = 20, kHalvings = 6;
  for (int sweep = 0; sweep < kSweeps; ++sweep) {
    bool moved = false;
    for (size_t i = 0; i < sites.size(); ++i) {
      const int v = movableVertex[i];
      if (v < 0 || r.uv[v] == sites[i]) continue;
      const Vec2 from = r.uv[v];
      const double floor = std::min(kSmallest, smallestAngle(v));
      for (int halving = 0; halving <= kHalvings; ++halving) {
        r.uv[v] = halving == 0 ? sites[i] : from + std::ldexp(1.0, -halving) * (sites[i] - from);
        const double now = smallestAngle(v);
        if (now > 0 && now >= floor) break;
        r.uv[v] = from;
      }
      moved = moved || r.uv[v] != from;
    }
    if (!moved) break;
  }
  for (size_t i = 0; i < sites.size(); ++i) {
    const int v = movableVertex[i];
    if (v < 0) continue;
    r.heldBack += r.uv[v] != sites[i];
    r.mesh.points[v] = lift(input, domain, r.uv[v]);
  }
  return r;
}

std::vector<Triangle> triangulateSites(const std::vector<Vec2>& border,
                                       const std::vector<Vec2>& movableSites) {
  // A constraint from a sample to itself crashes CGAL's triangulation (a border of one sample,
  // from a handful of sites asked for).
  if (border.size() < 3)
    throw Error("the border of the parameter domain has " + std::to_string(border.size()) +
                (border.size() == 1 ? " sample" : " samples") + " (3 at least)");
  Cdt cdt;
  std::vector<Cdt::Vertex_handle> borderVertex;
  for (size_t i = 0; i < border.size(); ++i) {
    borderVertex.push_back(cdt.insert(Point2(border[i].x(), border[i].y())));
    borderVertex.back()->info() = static_cast<int>(i);
  }
  // On one line or at one point, the border encloses nothing to triangulate (a damaged
  // recording's: marking the domain of a triangulation of dimension 1 crashed).
  if (cdt.dimension() < 2) throw Error("the border of the parameter domain encloses no area");
  // Samples at the same place (where a map squeezes part of the border to a point) are one
  // vertex of the triangulation, and a constraint from a vertex to itself crashes CGAL's: the
  // later sample stands for both, the earlier is left out of the triangles.
  for (size_t i = 0; i < border.size(); ++i)
    if (borderVertex[i] != borderVertex[(i + 1) % border.size()])
      cdt.insert_constraint(borderVertex[i], borderVertex[(i + 1) % border.size()]);
  // Where two border segments cross, CGAL adds a vertex of its own: mark those.
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) v->info() = -1;
  for (size_t i = 0; i < border.size(); ++i) borderVertex[i]->info() = static_cast<int>(i);
  std::vector<std::pair<Point2, int>> inside;
  for (size_t i = 0; i < movableSites.size(); ++i)
    inside.emplace_back(Point2(movableSites[i].x(), movableSites[i].y()),
                        static_cast<int>(border.size() + i));
  cdt.insert(inside.begin(), inside.end());
  markDomain(cdt);

  std::vector<Triangle> triangles;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
    if (!f->info().inDomain()) continue;
    const Triangle t = {f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()};
    if (*std::min_element(t.begin(), t.end()) < 0)
      throw Error("the border of the parameter domain crosses itself");
    triangles.push_back(t);
  }
  return triangles;
}

LiftedMesh retriangulate(const Mesh& input, const Domain& domain,
                         const std::vector<Vec2>& border, const std::vector<Vec2>& movableSites,
                         const std::string& name, const std::vector<Vec3>& borderPoints) {
  const std::vector<Vec2> sites = allSites(border, movableSites);
  std::vector<Vec3> points;
  for (size_t i = 0; i < sites.size(); ++i)
    points.push_back(i < borderPoints.size() ? borderPoints[i] : lift(input, domain, sites[i]));
  LiftedMesh result;
  std::vector<int> kept;
  std::vector<Triangle> triangles;
  try {
    triangles = triangulateSites(border, movableSites);
  } catch (const Error& e) {
    throw Error(name + ": " + e.what());
  }
  result.mesh = assemble(triangles, points, &kept);
  for (int i : kept) result.uv.push_back(sites[i]);
  return result;
}

}  // namespace lloydscope
