// GCC 12 warns that CGAL's Garland-Heckbert quadrics (Eigen 4x4 matrices) may be used
// uninitialized, inside Eigen's own headers, on every build: a false alarm. Off before the
// first include, which is where Eigen's headers come in for this file.
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"

#include "simplify.h"

#include "cgal_types.h"
#include "stopwatch.h"

#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Bounded_normal_change_filter.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/GarlandHeckbert_policies.h>
#include <CGAL/Surface_mesh_simplification/edge_collapse.h>
#include <CGAL/subdivision_method_3.h>

#include <algorithm>

namespace lloydscope {

namespace {

namespace SMS = CGAL::Surface_mesh_simplification;
using Profile = SMS::Edge_profile<SurfaceMesh>;

// Whether v, an end of the profile's edge, is on the border: one of the border edges the profile
// has gathered around both ends ends at it. CGAL::is_border(v) walks v's whole ring, and this is
// asked of every edge around a vertex again after each collapse there: around a hub of 1000
// triangles that was 41% of the time.
bool onBorder(const Profile& profile, SurfaceMesh::Vertex_index v) {
  const SurfaceMesh& sm = profile.surface_mesh();
  return std::any_of(profile.border_edges().begin(), profile.border_edges().end(),
                     [&](SurfaceMesh::Halfedge_index h) { return sm.source(h) == v || sm.target(h) == v; });
}

// Garland-Heckbert placement, except where the boundary would move (see simplify()).
template <typename Inner>
struct BoundaryKeepingPlacement {
  Inner inner;
  boost::optional<Point3> operator()(const Profile& profile) const {
    const bool border0 = onBorder(profile, profile.v0()), border1 = onBorder(profile, profile.v1());
    if (!border0 && !border1) return inner(profile);
    if (border0 && border1) {
      if (!profile.is_v0_v1_a_border() && !profile.is_v1_v0_a_border()) return boost::none;
      // On the border edge itself: the quadric's choice, moved onto the segment.
      const boost::optional<Point3> best = inner(profile);
      const Vec3 a(profile.p0().x(), profile.p0().y(), profile.p0().z());
      const Vec3 b(profile.p1().x(), profile.p1().y(), profile.p1().z());
      double t = 0.5;
      if (best) {
        const Vec3 p(best->x(), best->y(), best->z());
        t = std::clamp((p - a).dot(b - a) / std::max((b - a).squaredNorm(), 1e-300), 0.0, 1.0);
      }
      const Vec3 q = a + t * (b - a);
      return Point3(q.x(), q.y(), q.z());
    }
    return border0 ? profile.p0() : profile.p1();
  }
};

// Stops at the target number of vertices, or of faces.
struct SizeStop {
  std::size_t vertices, faces;
  bool operator()(double, const Profile& profile, std::size_t, std::size_t) const {
    const SurfaceMesh& sm = profile.surface_mesh();
    return sm.number_of_vertices() <= vertices || sm.number_of_faces() <= faces;
  }
};

// Garland and Heckbert's quadrics keep each plane as n.p + d with d = -n.q: far from the origin
// (a scan in world coordinates) d is large, and the costs and placements computed from them
// lose the digits the mesh's detail is in. The camel head of docs/bench_log.md (1.2 across),
// simplified to 5000 vertices: moved 10^2 away, as at the origin; 10^3, its smallest angle
// 0.9 -> 0.6 degrees; 10^5, 0.1 degrees, its average smallest angle 27.8 -> 24.3, 30 times as
// long, and every map of its cut open surface collapsed. So a mesh farther from the origin than
// ten times its size is simplified about the centre of its bounding box, then moved back
// (nearer, the move would only change the last bits of its points, and with them the order of
// equal collapses).
Mesh moved(Mesh mesh, const Vec3& offset) {
  for (Vec3& p : mesh.points) p += offset;
  return mesh;
}

Vec3 farOffset(const Mesh& mesh) {
  const auto [lo, hi] = boundingBox(mesh);
  const Vec3 centre = 0.5 * (lo + hi);
  return centre.norm() > 10 * (hi - lo).norm() ? centre : Vec3::Zero();
}

// Where the options stop the collapses on `input`. Throws Error naming `name` for no target or a
// ratio outside (0, 1].
SizeStop sizeStop(const Mesh& input, const SimplifyOptions& options, const std::string& name) {
  SizeStop stop{0, 0};
  if (options.vertices > 0) {
    stop.vertices = options.vertices;
  } else if (options.faces > 0) {
    stop.faces = options.faces;
  } else if (options.ratio > 0) {
    if (!(options.ratio <= 1.0)) throw Error(name + ": simplification ratio must be in (0, 1]");
    stop.vertices = std::max(3L, std::lround(options.ratio * input.vertexCount()));
  } else {
    throw Error(name + ": give a positive number of vertices or faces, or a ratio, to simplify to");
  }
  return stop;
}

bool reaches(const SizeStop& stop, const Mesh& mesh) {
  return stop.vertices >= size_t(mesh.vertexCount()) || stop.faces >= size_t(mesh.faceCount());
}

}  // namespace

bool simplifyCollapses(const Mesh& input, const SimplifyOptions& options, const std::string& name) {
  return !reaches(sizeStop(input, options, name), input);
}

SimplifyResult simplify(const Mesh& input, const SimplifyOptions& options, const std::string& name) {
  Stopwatch stopwatch;
  const SizeStop stop = sizeStop(input, options, name);
  SimplifyResult result;
  if (reaches(stop, input)) {
    result.mesh = input;  // nothing to take away
    return result;
  }
  const Vec3 offset = farOffset(input);
  SurfaceMesh sm = toSurfaceMesh(offset.isZero() ? input : moved(input, -offset));
  using Policies = SMS::GarlandHeckbert_plane_policies<SurfaceMesh, Kernel>;
  Policies policies(sm);
  BoundaryKeepingPlacement<Policies::Get_placement> placement{policies.get_placement()};
  // No collapse may turn a triangle around the edge by 90 degrees or more: quadrics choose the
  // placement without looking at the triangles around, and a border vertex slides along the
  // border. Without the filter the bench's inputs of nefertiti, the lion head and the mannequin
  // had 2-24 folded edges (metrics), with it 0-11 (the mannequin has 104 as it comes); a
  // wiggly-bordered dome at 300 and 500 vertices had 5 and 11 triangles upside down, with it
  // none (test_simplify). The filter refuses one collapse at a time: several may still turn a
  // triangle over between them, and an input's own folds stay.
  SMS::edge_collapse(sm, stop,
                     CGAL::parameters::get_cost(policies.get_cost())
                         .get_placement(placement)
                         .filter(SMS::Bounded_normal_change_filter<>()));
  sm.collect_garbage();
  result.mesh = fromSurfaceMesh(sm);
  // One vertex goes with each collapse (edge_collapse counts the edges removed: three inside).
  result.collapses = input.vertexCount() - result.mesh.vertexCount();
  if (!offset.isZero()) result.mesh = moved(std::move(result.mesh), offset);
  const bool byFaces = stop.faces > 0;
  const size_t reached = byFaces ? result.mesh.faceCount() : result.mesh.vertexCount(),
               asked = byFaces ? stop.faces : stop.vertices;
  if (reached > asked)
    result.stoppedShort = "stopped at " + std::to_string(reached) + (byFaces ? " faces" : " vertices") + ", not " +
                          std::to_string(asked) +
                          ": no edge is left whose collapse keeps the surface's topology (its components, border "
                          "loops and genus) and its border where it is, and turns no triangle by 90 degrees or more";
  result.milliseconds = stopwatch.lap();
  return result;
}

Mesh subdivideTo(const Mesh& input, int vertices) {
  if (input.vertexCount() >= vertices) return input;
  SurfaceMesh sm = toSurfaceMesh(input);
  while (static_cast<int>(sm.number_of_vertices()) < vertices)
    CGAL::Subdivision_method_3::Loop_subdivision(sm, CGAL::parameters::number_of_iterations(1));
  return fromSurfaceMesh(sm);
}

Mesh benchInput(const Mesh& model, int size, const std::string& name) {
  return simplify(subdivideTo(model, 2 * size), {size}, name).mesh;
}

int mostTrianglesAroundAVertex(const Mesh& mesh) {
  std::vector<int> around(mesh.points.size(), 0);
  for (const Triangle& t : mesh.triangles)
    for (int v : t) ++around[v];
  return around.empty() ? 0 : *std::max_element(around.begin(), around.end());
}

}  // namespace lloydscope
