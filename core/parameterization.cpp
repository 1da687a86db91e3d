#include "parameterization.h"

#include "cgal_types.h"
#include "names.h"
#include "topology.h"

#include <CGAL/Eigen_solver_traits.h>
#include <CGAL/Surface_mesh_parameterization/Barycentric_mapping_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Circular_border_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_authalic_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Discrete_conformal_map_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/LSCM_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Mean_value_coordinates_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/Square_border_parameterizer_3.h>
#include <CGAL/Surface_mesh_parameterization/parameterize.h>
#include <CGAL/Polygon_2.h>
#include <CGAL/Polygon_mesh_processing/measure.h>

#include <Eigen/SparseCholesky>
#include <Eigen/SparseLU>

#include <algorithm>
#include <optional>
#include <cmath>

namespace lloydscope {

namespace SMP = CGAL::Surface_mesh_parameterization;

namespace {

using Halfedge = boost::graph_traits<SurfaceMesh>::halfedge_descriptor;
using UVMap = SurfaceMesh::Property_map<SurfaceMesh::Vertex_index, Point2>;
// SparseLU was 1.2-1.6x faster than CGAL's default BiCGSTAB here (shared/notes/cgal.md);
// the matrices of the fixed-border methods are not symmetric, so LU it is.
using Solver = CGAL::Eigen_solver_traits<
    Eigen::SparseLU<CGAL::Eigen_sparse_matrix<double>::EigenType, Eigen::COLAMDOrdering<int>>>;

using Vertex = SurfaceMesh::Vertex_index;

double angleAt(const Point3& at, const Point3& p, const Point3& q) {
  const auto u = p - at, v = q - at;
  return std::atan2(std::sqrt(CGAL::cross_product(u, v).squared_length()), u * v);
}

// The border walked once: its vertices in order, how sharply it turns at each (pi less the sum
// of the corner angles there: pi/2 at a square's corner) and how far along it each is.
struct BorderWalk {
  std::vector<Vertex> loop;
  std::vector<double> turn, position;
  double length = 0;
};

BorderWalk walkBorder(const SurfaceMesh& sm, Halfedge border) {
  BorderWalk w;
  for (Halfedge h : CGAL::halfedges_around_face(border, sm)) {
    const Vertex v = sm.source(h);
    double angles = 0;
    for (auto f : CGAL::faces_around_target(sm.halfedge(v), sm)) {
      if (f == SurfaceMesh::null_face()) continue;
      const Halfedge at = [&] {
        for (Halfedge g : CGAL::halfedges_around_face(sm.halfedge(f), sm))
          if (sm.target(g) == v) return g;
        return sm.halfedge(f);
      }();
      angles += angleAt(sm.point(v), sm.point(sm.source(at)), sm.point(sm.target(sm.next(at))));
    }
    w.loop.push_back(v);
    w.turn.push_back(M_PI - angles);
    w.position.push_back(w.length);
    w.length += std::sqrt(CGAL::squared_distance(sm.point(sm.source(h)), sm.point(sm.target(h))));
  }
  return w;
}

// The four border vertices that become the square's corners: the sharpest turn of the border,
// then the sharpest turn near each quarter of the border's length from it. CGAL's own choice
// (quarters of the length from an arbitrary vertex) can put a corner mid-side and leave the
// triangles at the shape's real corners with three vertices on one side of the square: flat.
std::array<Vertex, 4> squareCorners(const SurfaceMesh& sm, Halfedge border) {
  const auto& [loop, turn, position, length] = walkBorder(sm, border);
  const size_t first = std::max_element(turn.begin(), turn.end()) - turn.begin();
  std::array<Vertex, 4> corners = {loop[first], loop[first], loop[first], loop[first]};
  for (int k = 1; k < 4; ++k) {
    double best = -INFINITY, nearest = INFINITY;
    Vertex nearestFree = loop[first];
    for (size_t i = 0; i < loop.size(); ++i) {
      // Four corners, each once: CGAL refuses a corner given twice (and says so on the standard
      // error, before our own error: a border of four vertices, one raised).
      if (std::find(corners.begin(), corners.begin() + k, loop[i]) != corners.begin() + k) continue;
      // Offset along the border from the first corner, compared with k quarters.
      const double offset = std::fmod(position[i] - position[first] + length, length);
      const double miss = std::abs(offset - k * length / 4);
      if (miss < nearest) {
        nearest = miss;
        nearestFree = loop[i];
      }
      if (miss > length / 8) continue;
      const double score = turn[i] - 1e-9 * miss;  // sharpest; the nearer on ties
      if (score > best) {
        best = score;
        corners[k] = loop[i];
      }
    }
    if (best == -INFINITY) corners[k] = nearestFree;  // no vertex near this quarter: the nearest
  }
  return corners;
}

// The corners of a border that is a quadrilateral: exactly four vertices where it turns by 60
// to 135 degrees, and nowhere else by more than 30 either way (a slit's end turns back by 180,
// and a cut surface's border has many; a regular octagon's 45 is neither), in the border's
// order. A strip's or a plate's, which a rectangle keeps.
std::optional<std::array<Vertex, 4>> rectangleCorners(const SurfaceMesh& sm, Halfedge border) {
  const BorderWalk w = walkBorder(sm, border);
  std::vector<Vertex> corners;
  for (size_t i = 0; i < w.loop.size(); ++i) {
    const double turn = w.turn[i];
    if (turn >= M_PI / 3 && turn <= 3 * M_PI / 4) corners.push_back(w.loop[i]);
    else if (std::abs(turn) > M_PI / 6) return std::nullopt;
  }
  if (corners.size() != 4) return std::nullopt;
  return std::array<Vertex, 4>{corners[0], corners[1], corners[2], corners[3]};
}

// A map onto the unit square stretched to the rectangle whose sides are as long as the border
// between its corners (the mean of opposite sides). The fixed-border maps are affine in their
// border (each inside point is a weighted mean of its neighbours), so this is the map onto that
// rectangle.
void stretchToSides(const SurfaceMesh& sm, Halfedge border, UVMap uv) {
  double across = 0, along = 0;  // the sides on y = 0 and 1, and on x = 0 and 1
  for (Halfedge h : CGAL::halfedges_around_face(border, sm)) {
    const Point2 a = get(uv, sm.source(h)), b = get(uv, sm.target(h));
    const double length = std::sqrt(CGAL::squared_distance(sm.point(sm.source(h)), sm.point(sm.target(h))));
    const auto on = [](double x, double y, double at) { return std::abs(x - at) < 1e-9 && std::abs(y - at) < 1e-9; };
    if (on(a.y(), b.y(), 0) || on(a.y(), b.y(), 1)) across += length;
    else if (on(a.x(), b.x(), 0) || on(a.x(), b.x(), 1)) along += length;
  }
  if (!(across > 0 && along > 0)) return;
  for (Vertex v : sm.vertices()) put(uv, v, Point2(get(uv, v).x() * across / along, get(uv, v).y()));
}

template <template <class, class, class> class Method>
SMP::Error_code solveFixedBorder(SurfaceMesh& sm, Halfedge border, UVMap uv, Border shape) {
  if (shape == Border::Rectangle) {
    using B = SMP::Square_border_arc_length_parameterizer_3<SurfaceMesh>;
    const auto c = rectangleCorners(sm, border).value();  // solveMap asked
    const SMP::Error_code status =
        SMP::parameterize(sm, Method<SurfaceMesh, B, Solver>(B(c[0], c[1], c[2], c[3])), border, uv);
    if (status == SMP::OK) stretchToSides(sm, border, uv);
    return status;
  }
  if (shape == Border::Square) {
    using B = SMP::Square_border_arc_length_parameterizer_3<SurfaceMesh>;
    const auto c = squareCorners(sm, border);
    return SMP::parameterize(sm, Method<SurfaceMesh, B, Solver>(B(c[0], c[1], c[2], c[3])),
                             border, uv);
  }
  using B = SMP::Circular_border_arc_length_parameterizer_3<SurfaceMesh>;
  return SMP::parameterize(sm, Method<SurfaceMesh, B, Solver>(), border, uv);
}

SMP::Error_code solve(SurfaceMesh& sm, Halfedge border, UVMap uv, const ParamOptions& o) {
  switch (o.method) {
    case ParamMethod::Authalic:
      return solveFixedBorder<SMP::Discrete_authalic_parameterizer_3>(sm, border, uv, o.border);
    case ParamMethod::Conformal:
      return solveFixedBorder<SMP::Discrete_conformal_map_parameterizer_3>(sm, border, uv,
                                                                          o.border);
    case ParamMethod::MeanValue:
      return solveFixedBorder<SMP::Mean_value_coordinates_parameterizer_3>(sm, border, uv,
                                                                          o.border);
    case ParamMethod::Tutte:
      return solveFixedBorder<SMP::Barycentric_mapping_parameterizer_3>(sm, border, uv, o.border);
    case ParamMethod::Lscm:
      return SMP::parameterize(sm, SMP::LSCM_parameterizer_3<SurfaceMesh>(), border, uv);
    case ParamMethod::Auto:
    case ParamMethod::Given:
      break;  // resolved by parameterize()
  }
  return SMP::ERROR_EMPTY_MESH;
}

// CGAL 5.5's get_error_message() is off by one from ERROR_NO_TOPOLOGICAL_BALL on (its table
// lacks that entry): a singular linear system read "no one-to-one mapping".
const char* errorMessage(SMP::Error_code code) {
  switch (code) {
    case SMP::OK: return "success";
    case SMP::ERROR_EMPTY_MESH: return "the mesh is empty";
    case SMP::ERROR_NON_TRIANGULAR_MESH: return "the mesh is not triangular";
    case SMP::ERROR_NO_TOPOLOGICAL_DISC: return "the mesh is not a topological disk";
    case SMP::ERROR_NO_TOPOLOGICAL_BALL: return "the mesh is not a topological ball";
    case SMP::ERROR_BORDER_TOO_SHORT: return "the border has too few vertices (a square border needs 4 at least: try --border circle)";
    case SMP::ERROR_NON_CONVEX_BORDER: return "the method needs a convex border";
    case SMP::ERROR_CANNOT_SOLVE_LINEAR_SYSTEM: return "its linear system could not be solved";
    case SMP::ERROR_NO_1_TO_1_MAPPING: return "the map is not one-to-one";
    case SMP::ERROR_WRONG_PARAMETER: return "a wrong parameter";
  }
  return "unknown error";
}

// The two vertices CGAL's LSCM pins (Two_vertices_parameterizer_3) and where: the extremes along
// the bounding box's longest axis, ties broken along the second longest, at their coordinates
// along those two axes. Which two are pinned changes the map, not only by a similarity. (Where
// two vertices tie on both axes, CGAL's pick depends on its hash set's order.)
struct Pin {
  int vertex = 0;
  Vec2 at = Vec2::Zero();
};

std::array<Pin, 2> lscmPins(const Mesh& mesh) {
  const auto [lo, hi] = boundingBox(mesh);
  const Vec3 size = hi - lo;
  int longest = 0, second = 1;  // CGAL's order of cases, ties and all
  if (size.x() < size.y() && size.x() < size.z()) longest = size.y() > size.z() ? 1 : 2, second = 3 - longest;
  else if (size.y() < size.x() && size.y() < size.z()) longest = size.x() > size.z() ? 0 : 2, second = 2 - longest;
  else longest = size.x() > size.y() ? 0 : 1, second = 1 - longest;
  std::array<Pin, 2> pins;
  pins[0].at = Vec2(INFINITY, INFINITY);
  pins[1].at = -pins[0].at;
  for (int i = 0; i < mesh.vertexCount(); ++i) {
    const Vec2 at((mesh.points[i][longest] - lo[longest]) / size[longest],
                  (mesh.points[i][second] - lo[second]) / size[second]);
    if (at.x() < pins[0].at.x() || (at.x() == pins[0].at.x() && at.y() < pins[0].at.y())) pins[0] = {i, at};
    if (at.x() > pins[1].at.x() || (at.x() == pins[1].at.x() && at.y() > pins[1].at.y())) pins[1] = {i, at};
  }
  return pins;
}

// CGAL's LSCM (LSCM_parameterizer_3): per triangle, in its own plane (z0, z1, z2), the two real
// rows of (z1 - z0)(U2 - U0) = (z2 - z0)(U1 - U0), CGAL's coefficients, CGAL's two vertices
// pinned, solved in the least squares sense. CGAL assembles the normal equations row by row
// through OpenNL and ignores the solver it is given; built here as one sparse product, the same
// map (to 1e-12 of its size) comes 2.5-3 times as fast: the cut measures several maps of the
// whole input. (The other maps stay CGAL's: a map different in its last bits sends Lloyd's
// iterations elsewhere, and every result would move.)
std::vector<Vec2> leastSquaresConformalMap(const Mesh& mesh, const std::string& name) {
  const int n = mesh.vertexCount();
  const std::array<Pin, 2> pins = lscmPins(mesh);
  if (pins[0].vertex == pins[1].vertex)
    throw Error(name + ": lscm parameterization failed: " + errorMessage(SMP::ERROR_CANNOT_SOLVE_LINEAR_SYSTEM));
  // Variables u, v of vertex i are 2i, 2i + 1: the pins' values, the others' unknown's index.
  std::vector<double> pinned(2 * n, 0.0);
  std::vector<int> unknown(2 * n, 0);
  for (const Pin& pin : pins) {
    pinned[2 * pin.vertex] = pin.at.x(), pinned[2 * pin.vertex + 1] = pin.at.y();
    unknown[2 * pin.vertex] = unknown[2 * pin.vertex + 1] = -1;
  }
  int unknowns = 0;
  for (int& u : unknown)
    if (u >= 0) u = unknowns++;
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(10 * mesh.faceCount());
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(2 * mesh.faceCount());
  auto add = [&](int row, int variable, double coefficient) {
    if (unknown[variable] >= 0) entries.emplace_back(row, unknown[variable], coefficient);
    else rhs[row] -= coefficient * pinned[variable];
  };
  for (int f = 0; f < mesh.faceCount(); ++f) {
    const Triangle& t = mesh.triangles[f];
    const Vec3 &p0 = mesh.points[t[0]], &p1 = mesh.points[t[1]], &p2 = mesh.points[t[2]];
    Vec3 x = p1 - p0;  // the triangle's own frame, as CGAL's project_triangle makes it
    if (x.norm() != 0) x /= x.norm();
    Vec3 z = x.cross(p2 - p0);
    if (z.norm() != 0) z /= z.norm();
    const Vec3 y = z.cross(x);
    const double a = (p1 - p0).norm(), c = (p2 - p0).dot(x), d = (p2 - p0).dot(y);
    const int u0 = 2 * t[0], v0 = u0 + 1, u1 = 2 * t[1], v1 = u1 + 1, u2 = 2 * t[2], v2 = u2 + 1;
    add(2 * f, u0, c - a), add(2 * f, v0, -d), add(2 * f, u1, -c), add(2 * f, v1, d), add(2 * f, u2, a);
    add(2 * f + 1, u0, d), add(2 * f + 1, v0, c - a), add(2 * f + 1, u1, -d), add(2 * f + 1, v1, -c),
        add(2 * f + 1, v2, a);
  }
  Eigen::SparseMatrix<double> rows(2 * mesh.faceCount(), unknowns);
  rows.setFromTriplets(entries.begin(), entries.end());
  const Eigen::SparseMatrix<double> transposed = rows.transpose();
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(transposed * rows);
  const Eigen::VectorXd x = solver.solve(transposed * rhs);
  if (solver.info() != Eigen::Success || !x.allFinite())
    throw Error(name + ": lscm parameterization failed: " + errorMessage(SMP::ERROR_CANNOT_SOLVE_LINEAR_SYSTEM));
  std::vector<Vec2> uv(n);
  for (int v = 0; v < n; ++v) {
    auto value = [&](int i) { return unknown[i] >= 0 ? x[unknown[i]] : pinned[i]; };
    uv[v] = Vec2(value(2 * v), value(2 * v + 1));
  }
  return uv;
}

// CGAL's map of the disk `mesh`, as the solver leaves it, and the vertices of its longest border.
struct SolvedMap {
  std::vector<Vec2> uv;
  std::vector<int> boundaryLoop;
};

SolvedMap solveMap(const Mesh& mesh, const ParamOptions& options, const std::string& name) {
  SurfaceMesh sm = toSurfaceMesh(mesh);
  const Halfedge border = CGAL::Polygon_mesh_processing::longest_border(sm).first;
  UVMap uvMap = sm.add_property_map<SurfaceMesh::Vertex_index, Point2>("v:uv").first;
  if (options.border == Border::Rectangle && !isFreeBorder(options.method) && !rectangleCorners(sm, border))
    throw Error(name + ": a rectangle border needs a border with four corners, where it turns by 60 to 135 "
                       "degrees, and nowhere else by more than 30 (--border circle or square fits any border)");
  const SMP::Error_code err = solve(sm, border, uvMap, options);
  // CGAL's own one-to-one check only reports: the map is there, for repairFolds and
  // requireOneToOne to judge.
  if (err != SMP::OK && err != SMP::ERROR_NO_1_TO_1_MAPPING)
    throw Error(name + ": " + toString(options.method) + " parameterization failed: " +
                errorMessage(err));
  SolvedMap solved;
  solved.uv.resize(mesh.points.size());
  for (auto v : sm.vertices()) solved.uv[v.idx()] = Vec2(uvMap[v].x(), uvMap[v].y());
  for (Halfedge h : CGAL::halfedges_around_face(border, sm))
    solved.boundaryLoop.push_back(static_cast<int>(sm.source(h).idx()));
  return solved;
}

SolvedMap givenMap(const Mesh& mesh, const std::vector<Vec2>& uv, const std::string& name) {
  if (uv.size() != mesh.points.size())
    throw Error(name + ": the given map has " + std::to_string(uv.size()) + " points for " +
                std::to_string(mesh.vertexCount()) + " vertices");
  return {uv, analyzeTopology(mesh).boundaryLoops.at(0)};
}

// Uniform scale and translation so that the UV bounding box fits [0,1]^2 with its lower-left
// corner at the origin: thresholds can then be given as fractions of the domain size.
void normalize(std::vector<Vec2>& uv) {
  const auto [lo, hi] = boundingBox(uv);
  const double scale = 1.0 / std::max((hi - lo).maxCoeff(), 1e-300);
  for (Vec2& p : uv) p = (p - lo) * scale;
}

// Triangles that face against the map's orientation, and triangles of (nearly) zero area but
// for ears of the border (three border vertices on one straight side of the square: flat, but
// harmless, as they cover no part of the domain). An ear with a side squeezed to a point is
// collapsed all the same: the border's samples along that side would pile up on one point.
struct Folds {
  std::vector<int> flipped, collapsed;
  bool empty() const { return flipped.empty() && collapsed.empty(); }
};

// A side this short (the map is scaled to a unit square) is a point: LSCM squeezed an ear of an
// 11-vertex surface's border to 3e-16.
constexpr double kSqueezedSide = 1e-12;

double shortestSide(const Vec2& a, const Vec2& b, const Vec2& c) {
  return std::min({(b - a).norm(), (c - b).norm(), (a - c).norm()});
}

Folds findFolds(const Mesh& mesh, const std::vector<Vec2>& uv, const std::vector<bool>& onBoundary) {
  double total = 0;
  for (const Triangle& t : mesh.triangles) total += triangleArea(uv[t[0]], uv[t[1]], uv[t[2]]);
  const double minArea = kFlatAreaShare * std::abs(total), sign = total < 0 ? -1.0 : 1.0;
  Folds folds;
  for (int f = 0; f < mesh.faceCount(); ++f) {
    const Triangle& t = mesh.triangles[f];
    const double a = sign * triangleArea(uv[t[0]], uv[t[1]], uv[t[2]]);
    const bool ear = onBoundary[t[0]] && onBoundary[t[1]] && onBoundary[t[2]] &&
                     shortestSide(uv[t[0]], uv[t[1]], uv[t[2]]) > kSqueezedSide;
    if (a < -minArea) folds.flipped.push_back(f);
    else if (a <= minArea && !ear) folds.collapsed.push_back(f);
  }
  return folds;
}

// A free border (LSCM) can overlap itself far from any folded triangle: every triangle faces
// up, yet two parts of the surface land on the same place.
bool borderIsSimple(const std::vector<Vec2>& uv, const std::vector<int>& boundaryLoop) {
  CGAL::Polygon_2<Kernel> polygon;
  for (int v : boundaryLoop) polygon.push_back(Point2(uv[v].x(), uv[v].y()));
  return polygon.is_simple();
}

// What to try where `method`'s map is not one-to-one. A map with a fixed convex border (Tutte,
// mean value) is one-to-one in exact arithmetic: where it is not, rounding squeezed thin parts
// of the surface to nothing (CGAL's dino: its tail and legs), and a coarser input has fewer
// triangles there; Tutte's positive weights hold on longest. Any other map may fold: those two
// are one-to-one.
std::string adviceAfterFolds(ParamMethod method) {
  const std::string coarser = "--simplify to fewer vertices (rounding squeezed thin parts of the surface to nothing)";
  if (method == ParamMethod::Tutte) return "try " + coarser;
  if (method == ParamMethod::MeanValue) return "try --param tutte or " + coarser;
  return "try --param tutte or mean-value, whose maps are always one-to-one";
}

// Mirrors the map if it came out clockwise, then refuses any folds (findFolds) and a border
// that crosses itself, saying what to try instead (adviceAfterFolds).
void requireOneToOne(const Mesh& mesh, std::vector<Vec2>& uv, const std::vector<bool>& onBoundary,
                     const std::vector<int>& boundaryLoop, ParamMethod method, const std::string& name) {
  double total = 0;
  for (const Triangle& t : mesh.triangles) total += triangleArea(uv[t[0]], uv[t[1]], uv[t[2]]);
  if (total < 0)
    for (Vec2& p : uv) p.x() = 1.0 - p.x();
  const Folds folds = findFolds(mesh, uv, onBoundary);
  const size_t flipped = folds.flipped.size(), collapsed = folds.collapsed.size();
  if (folds.empty() && !borderIsSimple(uv, boundaryLoop))
    throw Error(name + ": the parameterization is not one-to-one (its border crosses itself); " +
                adviceAfterFolds(method));
  if (!folds.empty())
    throw Error(name + ": the parameterization is not one-to-one (" + std::to_string(flipped) +
                " flipped and " + std::to_string(collapsed) + " collapsed of " +
                std::to_string(mesh.faceCount()) + " triangles); " + adviceAfterFolds(method));
}

// LSCM folds where the input has slivers, which cost it almost nothing to flip. Unfolds them
// locally: the vertices of folded triangles and a few rings around them are placed again by
// Floater's mean-value coordinates (positive weights: a convex combination of their
// neighbours), the rest of the map held fixed. Rings grow until nothing is folded or the
// attempts run out; what stays folded is for requireOneToOne to report.
void repairFolds(const Mesh& mesh, std::vector<Vec2>& uv, const std::vector<bool>& onBoundary,
                 const std::vector<int>& boundaryLoop) {
  const int n = mesh.vertexCount();
  std::vector<std::vector<int>> neighbours(n);
  for (const Triangle& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) neighbours[t[k]].push_back(t[(k + 1) % 3]);
  // Each border vertex's two neighbours along the border.
  std::vector<std::vector<int>> alongBorder(n);
  for (size_t i = 0, m = boundaryLoop.size(); i < m; ++i)
    alongBorder[boundaryLoop[i]] = {boundaryLoop[(i + m - 1) % m], boundaryLoop[(i + 1) % m]};
  for (int rings = 2; rings <= 8; rings *= 2) {
    const Folds folds = findFolds(mesh, uv, onBoundary);
    if (folds.empty()) return;
    std::vector<int> folded = folds.flipped;
    folded.insert(folded.end(), folds.collapsed.begin(), folds.collapsed.end());
    std::vector<int> freeIndex(n, -1), freeVertices;
    auto makeFree = [&](int v) {
      if (freeIndex[v] >= 0) return;
      freeIndex[v] = static_cast<int>(freeVertices.size());
      freeVertices.push_back(v);
    };
    for (int f : folded)
      for (int v : mesh.triangles[f]) makeFree(v);
    for (int r = 0; r < rings; ++r)
      for (size_t i = 0, end = freeVertices.size(); i < end; ++i)
        for (int w : neighbours[freeVertices[i]])
          if (!onBoundary[w]) makeFree(w);
    // Mean-value weights w_ij = (tan(a/2) + tan(b/2)) / |x_i - x_j|, summed corner by corner.
    std::vector<Eigen::Triplet<double>> entries;
    Eigen::VectorXd bu = Eigen::VectorXd::Zero(freeVertices.size()), bv = bu;
    // A border vertex of a folded triangle goes between its two border neighbours, at its 3D
    // arc length: the border straightened there (mean-value weights, all on one side of it,
    // would pull it inside and fold its other triangles).
    auto addWeight = [&](int i, int j, double w) {
      entries.emplace_back(freeIndex[i], freeIndex[i], w);
      if (freeIndex[j] >= 0) entries.emplace_back(freeIndex[i], freeIndex[j], -w);
      else {
        bu[freeIndex[i]] += w * uv[j].x();
        bv[freeIndex[i]] += w * uv[j].y();
      }
    };
    for (int i : freeVertices)
      if (onBoundary[i] && alongBorder[i].size() == 2)
        for (int k = 0; k < 2; ++k)  // the nearer neighbour weighs more
          addWeight(i, alongBorder[i][k],
                    1.0 / std::max((mesh.points[alongBorder[i][k]] - mesh.points[i]).norm(), 1e-300));
    for (const Triangle& t : mesh.triangles)
      for (int k = 0; k < 3; ++k) {
        const int i = t[k];
        if (freeIndex[i] < 0 || (onBoundary[i] && alongBorder[i].size() == 2)) continue;
        const Vec3 &pi = mesh.points[i];
        const double half = std::tan(0.5 * cornerAngle(pi, mesh.points[t[(k + 1) % 3]],
                                                       mesh.points[t[(k + 2) % 3]]));
        for (int j : {t[(k + 1) % 3], t[(k + 2) % 3]})
          addWeight(i, j, half / std::max((mesh.points[j] - pi).norm(), 1e-300));
      }
    Eigen::SparseMatrix<double> a(freeVertices.size(), freeVertices.size());
    a.setFromTriplets(entries.begin(), entries.end());
    Eigen::SparseLU<Eigen::SparseMatrix<double>> lu(a);
    if (lu.info() != Eigen::Success) return;
    const Eigen::VectorXd u = lu.solve(bu), v = lu.solve(bv);
    for (size_t i = 0; i < freeVertices.size(); ++i) uv[freeVertices[i]] = Vec2(u[i], v[i]);
  }
}

}  // namespace

Distortion measureDistortion(const Mesh& mesh, const std::vector<Vec2>& uv) {
  const double area3 = surfaceArea(mesh), area2 = mapArea(mesh, uv);
  Distortion d;
  d.minAreaRatio = INFINITY;
  d.maxAreaRatio = 0;
  double angleError = 0;
  for (const Triangle& t : mesh.triangles) {
    const double a3 = triangleArea(mesh.points[t[0]], mesh.points[t[1]], mesh.points[t[2]]);
    const double a2 = std::abs(triangleArea(uv[t[0]], uv[t[1]], uv[t[2]]));
    if (a2 > kFlatAreaShare * area2) {  // a flat ear covers none of the domain: no ratio
      const double r = (a3 / area3) / (a2 / area2);
      d.minAreaRatio = std::min(d.minAreaRatio, r);
      d.maxAreaRatio = std::max(d.maxAreaRatio, r);
      d.meanLogAreaRatio += a3 / area3 * std::abs(std::log(std::max(r, 1e-300)));
    }
    for (int k = 0; k < 3; ++k) {
      const int i = t[k], j = t[(k + 1) % 3], l = t[(k + 2) % 3];
      angleError += std::abs(cornerAngle(mesh.points[i], mesh.points[j], mesh.points[l]) -
                             cornerAngle(uv[i], uv[j], uv[l]));
    }
  }
  d.meanAngleErrorDeg = angleError / (3.0 * mesh.faceCount()) * 180.0 / M_PI;
  return d;
}

Parameterization parameterize(const Mesh& mesh, const ParamOptions& options,
                              const std::string& name) {
  if (options.method == ParamMethod::Auto) {
    // LSCM distorts least but may fold; mean value and then Tutte, on the border asked (it was
    // a circle whatever --border said), are one-to-one in exact arithmetic, and Tutte's positive
    // weights hold on where rounding folds the other. A border with four corners (a strip's)
    // is tried on a rectangle first: a helicoid of two turns, whose LSCM map winds round twice
    // and overlaps itself, kept its angles to 4 degrees there (mean error), 46 on a circle.
    // (A rectangle asked has a circle after it, for a border that is no quadrilateral.)
    const Border after = options.border == Border::Rectangle ? Border::Circle : options.border;
    std::vector<ParamOptions> tries = {{ParamMethod::Lscm, options.border, {}},
                                       {ParamMethod::MeanValue, Border::Rectangle, {}},
                                       {ParamMethod::MeanValue, after, {}},
                                       {ParamMethod::Tutte, after, {}}};
    if (!options.fallback.empty())
      tries.insert(tries.begin() + 1, {ParamMethod::Given, Border::Circle, options.fallback});
    for (size_t i = 0;; ++i) {
      try {
        return parameterize(mesh, tries[i], name);
      } catch (const Error&) {  // folded, or its solver failed: the next one
        if (i + 1 == tries.size()) throw;
      }
    }
  }
  // CGAL does not check the topology itself (shared/notes/cgal.md): a non-disk "succeeds".
  requireDisk(mesh, name);
  Parameterization result;
  result.method = options.method;
  result.border = options.border;
  SolvedMap solved = options.method == ParamMethod::Given ? givenMap(mesh, options.fallback, name)
                                                         : solveMap(mesh, options, name);
  result.uv = std::move(solved.uv);
  result.boundaryLoop = std::move(solved.boundaryLoop);
  for (const Vec2& p : result.uv)
    if (!p.allFinite()) throw Error(name + ": the parameterization produced non-finite UVs");
  normalize(result.uv);
  result.onBoundary.assign(mesh.points.size(), false);
  for (int v : result.boundaryLoop) result.onBoundary[v] = true;
  if (isFreeBorder(options.method)) {
    repairFolds(mesh, result.uv, result.onBoundary, result.boundaryLoop);
    normalize(result.uv);  // the repair may have moved the border in from the square's sides
  }
  requireOneToOne(mesh, result.uv, result.onBoundary, result.boundaryLoop, options.method, name);
  // The border cycle runs around the hole; make it counter-clockwise around the domain.
  double signedArea = 0;
  const auto& loop = result.boundaryLoop;
  for (size_t i = 0; i < loop.size(); ++i) {
    const Vec2& a = result.uv[loop[i]];
    const Vec2& b = result.uv[loop[(i + 1) % loop.size()]];
    signedArea += a.x() * b.y() - b.x() * a.y();
  }
  if (signedArea < 0) std::reverse(result.boundaryLoop.begin(), result.boundaryLoop.end());
  result.distortion = measureDistortion(mesh, result.uv);
  return result;
}

std::vector<Vec2> conformalMap(const Mesh& disk, const std::string& name) {
  return leastSquaresConformalMap(disk, name);
}

// The methods one can ask for; the input's own map ("input-map") is not one of them.
constexpr NamedValue<ParamMethod> kParamMethodNames[] = {
    {ParamMethod::Auto, "auto"},   {ParamMethod::Authalic, "authalic"}, {ParamMethod::Conformal, "conformal"},
    {ParamMethod::MeanValue, "mean-value"}, {ParamMethod::Tutte, "tutte"}, {ParamMethod::Lscm, "lscm"}};
constexpr NamedValue<Border> kBorderNames[] = {
    {Border::Square, "square"}, {Border::Circle, "circle"}, {Border::Rectangle, "rectangle"}};

const char* toString(ParamMethod method) {
  return method == ParamMethod::Given ? "input-map" : nameOf(kParamMethodNames, method);
}

const char* toString(Border border) { return nameOf(kBorderNames, border); }

std::string borderPhrase(ParamMethod used, Border border) {
  if (used == ParamMethod::Lscm) return "free border";
  if (used == ParamMethod::Given) return "border of the input's map";
  return std::string(toString(border)) + " border";
}

ParamMethod parseParamMethod(const std::string& text) {
  return parseName(kParamMethodNames, text, "parameterization");
}

Border parseBorder(const std::string& text) { return parseName(kBorderNames, text, "border"); }

}  // namespace lloydscope
