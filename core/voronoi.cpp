#include "voronoi.h"

#include "cgal_types.h"
#include "parallel.h"

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <CGAL/property_map.h>
#include <CGAL/spatial_sort.h>
#include <CGAL/Spatial_sort_traits_adapter_2.h>

#include <algorithm>
#include <numeric>
#include <cmath>
#include <thread>

namespace lloydscope {

namespace {

using VertexBase = CGAL::Triangulation_vertex_base_with_info_2<int, Kernel>;
// Each face keeps its circumcentre, computed once for the three cells that share it.
using FaceBase = CGAL::Triangulation_face_base_with_info_2<Vec2, Kernel>;
using Tds = CGAL::Triangulation_data_structure_2<VertexBase, FaceBase>;
using Delaunay = CGAL::Delaunay_triangulation_2<Kernel, Tds>;
constexpr int kDummy = -1;

// A point within this distance (in the unit parameter domain) of a triangle's side is on it.
constexpr double kOnSide = 1e-9;

// A convex polygon whose sides are labelled: edge[i] names the side from points[i] to
// points[i + 1]: the site across it for a Voronoi edge, kTriangleSide for a cut by clipping.
constexpr int kTriangleSide = -2;
struct LabelledPolygon {
  std::vector<Vec2> points;
  std::vector<int> edge;
  size_t size() const { return points.size(); }
  void clear() {
    points.clear();
    edge.clear();
  }
  template <bool labelled = true>
  void push(const Vec2& p, int label) {
    points.push_back(p);
    if constexpr (labelled) edge.push_back(label);
  }
};

// Sutherland-Hodgman: the part of a convex polygon left of each edge of a CCW triangle: the
// polygon itself where the triangle holds it whole, else in one of the buffers `one` and
// `other` (no copy). `reaches` receives which edges of the triangle the part reaches (bit k:
// the edge from corner k to corner k+1): only across those can the cell overlap a
// neighbouring triangle. `side` is reused between calls to keep allocation out of the inner
// loop. Without `labelled`, a clipped result has no labels (the solvers but Newton's need
// none, and keeping them costs a tenth of the cells' time).
template <bool labelled>
const LabelledPolygon& clipToTriangle(const LabelledPolygon& polygon, const Vec2 (&corner)[3],
                                      LabelledPolygon& one, LabelledPolygon& other,
                                      std::vector<double>& side, int& reaches) {
  reaches = 0;
  const LabelledPolygon* in = &polygon;
  for (int k = 0; k < 3; ++k) {
    const Vec2 &a = corner[k], edge = corner[(k + 1) % 3] - a;
    const double onEdge = kOnSide * edge.norm();  // cross() is |edge| times the distance
    const size_t n = in->size();
    if (side.size() < n) side.resize(n);
    bool anyIn = false, anyOut = false, anyOn = false;
    for (size_t i = 0; i < n; ++i) {
      side[i] = cross(edge, in->points[i] - a);
      (side[i] >= 0 ? anyIn : anyOut) = true;
      anyOn = anyOn || std::abs(side[i]) <= onEdge;
    }
    if (!anyIn) {
      reaches = 0;
      one.clear();
      return one;
    }
    if (anyOn || anyOut) reaches |= 1 << k;
    if (!anyOut) continue;  // nothing to cut on this side
    LabelledPolygon& out = (in == &one) ? other : one;
    out.clear();
    for (size_t i = 0, j = n - 1; i < n; j = i++) {  // side (p, q) = (in[j], in[i])
      const Vec2 &p = in->points[j], &q = in->points[i];
      const bool pIn = side[j] >= 0, qIn = side[i] >= 0;
      // Leaving, the polygon goes on along the triangle's side; entering, along (p, q).
      const auto label = [&](size_t at) { return labelled ? in->edge[at] : 0; };
      if (pIn != qIn)
        out.push<labelled>(p + (side[j] / (side[j] - side[i])) * (q - p),
                           pIn ? kTriangleSide : label(j));
      if (qIn) out.push<labelled>(q, label(i));
    }
    in = &out;
  }
  return *in;
}

void integrateTriangle(const Vec2 (&p)[3], const double (&rho)[3], const Vec2& site,
                       PolygonIntegrals& sum) {
  const double area = 0.5 * cross(p[1] - p[0], p[2] - p[0]);
  const double rhoSum = rho[0] + rho[1] + rho[2];
  sum.area += area;
  sum.mass += area * rhoSum / 3.0;
  // ∫ x rho = Σ_ij p_i rho_j ∫λiλj, with ∫λiλj = A (1 + δij) / 12.
  sum.moment += area / 12.0 *
                ((p[0] + p[1] + p[2]) * rhoSum + rho[0] * p[0] + rho[1] * p[1] + rho[2] * p[2]);
  // ∫ rho |x - site|^2 = Σ_ijk rho_k (q_i·q_j) ∫λiλjλk with q_i = p_i - site, and
  // ∫λiλjλk = A (1 + δij + δjk + δik + 2 δijk) / 60, which sums to the closed form below.
  const Vec2 q[3] = {p[0] - site, p[1] - site, p[2] - site};
  const Vec2 qSum = q[0] + q[1] + q[2];
  double squares = 0, weightedDot = 0, weightedSquares = 0;
  for (int k = 0; k < 3; ++k) {
    squares += q[k].squaredNorm();
    weightedDot += rho[k] * q[k].dot(qSum);
    weightedSquares += rho[k] * q[k].squaredNorm();
  }
  const double energy =
      (rhoSum * (qSum.squaredNorm() + squares) + 2 * weightedDot + 2 * weightedSquares) / 60.0;
  sum.energy += area * energy;
}

// The box of the sites and the unit square: where the dummy sites go around.
std::pair<Vec2, Vec2> dummyBox(const std::vector<Vec2>& sites) {
  Vec2 lo(0, 0), hi(1, 1);
  for (const Vec2& s : sites) {
    lo = lo.cwiseMin(s);
    hi = hi.cwiseMax(s);
  }
  return {lo, hi};
}

// Four far dummy sites around `box` make every real cell bounded; their own cells are never
// used.
void insertDummies(Delaunay& dt, const std::pair<Vec2, Vec2>& box) {
  const auto& [lo, hi] = box;
  const Vec2 center = 0.5 * (lo + hi);
  const double far = 10.0 * std::max((hi - lo).maxCoeff(), 1.0);
  for (int dx : {-1, 1})
    for (int dy : {-1, 1})
      dt.insert(Point2(center.x() + dx * far, center.y() + dy * far))->info() = kDummy;
}

// Builds `dt`, empty, with its dummy sites around `box`, and `vertexOf`: each site's vertex (a
// site on top of an earlier one has none: null). `order`: the sites in a spatial order (from a
// previous call), or empty; receives the order used.
void triangulateSites(const std::vector<Vec2>& sites, const std::pair<Vec2, Vec2>& box,
                      std::vector<int>& order, Delaunay& dt,
                      std::vector<Delaunay::Vertex_handle>& vertexOf) {
  insertDummies(dt, box);
  // Inserting in a spatial order, each point from the last one, is what makes this fast. Sites
  // that moved a little keep a good order: the Hilbert sort is done once, not every iteration.
  std::vector<Point2> points;
  points.reserve(sites.size());
  for (const Vec2& s : sites) points.emplace_back(s.x(), s.y());
  if (order.size() != sites.size()) {
    std::vector<std::size_t> sorted(sites.size());
    std::iota(sorted.begin(), sorted.end(), 0);
    using Traits =
        CGAL::Spatial_sort_traits_adapter_2<Kernel, CGAL::Pointer_property_map<Point2>::type>;
    CGAL::spatial_sort(sorted.begin(), sorted.end(), Traits(CGAL::make_property_map(points)));
    order.assign(sorted.begin(), sorted.end());
  }
  Delaunay::Face_handle near;
  for (int i : order) {
    const size_t before = dt.number_of_vertices();
    const Delaunay::Vertex_handle v = dt.insert(points[i], near);
    // Sites on top of each other share one vertex: the smallest index keeps it, whatever the
    // order of insertion.
    v->info() = dt.number_of_vertices() > before ? i : std::min(v->info(), i);
    near = v->face();
  }
  vertexOf.assign(sites.size(), Delaunay::Vertex_handle());
  for (auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v)
    if (v->info() != kDummy) vertexOf[v->info()] = v;
}

// Moves each site's vertex of `dt` to its new place and flips edges until the triangulation
// is Delaunay again (Lawson), with the symbolic perturbation CGAL's insertion uses: the same
// triangulation a rebuild would make. False, with `dt` left to be rebuilt, where a site has no
// vertex of its own or a triangle turned over (its sites moved past each other).
bool moveSites(Delaunay& dt, const std::vector<Delaunay::Vertex_handle>& vertexOf,
               const std::vector<Vec2>& sites) {
  if (vertexOf.size() != sites.size()) return false;
  for (size_t i = 0; i < sites.size(); ++i) {
    if (vertexOf[i] == Delaunay::Vertex_handle()) return false;
    vertexOf[i]->set_point(Point2(sites[i].x(), sites[i].y()));
  }
  const auto orientation = dt.geom_traits().orientation_2_object();
  std::vector<Delaunay::Edge> check;
  check.reserve(3 * dt.number_of_faces());
  for (auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f) {
    if (orientation(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point()) !=
        CGAL::LEFT_TURN)
      return false;
    for (int i = 0; i < 3; ++i) check.emplace_back(f, i);
  }
  while (!check.empty()) {
    const auto [f, i] = check.back();
    check.pop_back();
    const Delaunay::Face_handle n = f->neighbor(i);
    if (dt.is_infinite(f) || dt.is_infinite(n)) continue;
    if (dt.side_of_oriented_circle(n, f->vertex(i)->point(), true) != CGAL::ON_POSITIVE_SIDE)
      continue;
    dt.flip(f, i);
    // The quadrilateral's four sides may have become non-Delaunay; its new diagonal is.
    for (const Delaunay::Face_handle& g : {f, n})
      for (int k = 0; k < 3; ++k)
        if (g->neighbor(k) != (g == f ? n : f)) check.emplace_back(g, k);
  }
  return true;
}

}  // namespace

struct SiteTriangulation::State {
  Delaunay dt;
  std::vector<Delaunay::Vertex_handle> vertexOf;  // per site
  std::pair<Vec2, Vec2> box;  // dummyBox() of the sites it was built for
};
SiteTriangulation::SiteTriangulation() = default;
SiteTriangulation::~SiteTriangulation() = default;
SiteTriangulation::SiteTriangulation(SiteTriangulation&&) noexcept = default;
SiteTriangulation& SiteTriangulation::operator=(SiteTriangulation&&) noexcept = default;
SiteTriangulation::SiteTriangulation(const SiteTriangulation&) {}
SiteTriangulation& SiteTriangulation::operator=(const SiteTriangulation&) {
  state.reset();
  builds = 0;
  return *this;
}

namespace {

// The Delaunay triangulation of `sites`: the last call's moved and mended, or built anew. Only
// where the dummy sites would go to the same places (sites in the unit square, as Lloyd's
// always are): the cells next to them are then bit for bit those of a new triangulation.
Delaunay& triangulate(const std::vector<Vec2>& sites, CellHints& hints) {
  auto& state = hints.triangulation.state;
  const std::pair<Vec2, Vec2> box = dummyBox(sites);
  if (state && state->box == box && moveSites(state->dt, state->vertexOf, sites)) return state->dt;
  state = std::make_unique<SiteTriangulation::State>();
  state->box = box;
  triangulateSites(sites, box, hints.order, state->dt, state->vertexOf);
  ++hints.triangulation.builds;
  return state->dt;
}

void storeCircumcenters(size_t begin, size_t end,
                        const std::vector<Delaunay::Face_handle>& faces) {
  auto before = [](const Point2& a, const Point2& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  };
  for (size_t f = begin; f < end; ++f) {
    // The same three points in the same order, however the triangulation stores the face
    // (insertion order changes that): the same rounding, bit for bit.
    std::array<Point2, 3> p = {faces[f]->vertex(0)->point(), faces[f]->vertex(1)->point(),
                               faces[f]->vertex(2)->point()};
    std::sort(p.begin(), p.end(), before);
    const Point2 c = CGAL::circumcenter(p[0], p[1], p[2]);
    faces[f]->info() = Vec2(c.x(), c.y());
  }
}

// The cell of v: the circumcentres of its faces, counter-clockwise, starting at the smallest
// (so that the cell's integrals do not depend on how the triangulation stores its faces); each
// side labelled with the site across it.
void voronoiPolygon(Delaunay::Vertex_handle v, LabelledPolygon& polygon) {
  polygon.clear();
  auto face = v->incident_faces(), end = face;
  do {
    const Vec2& p = face->info();
    // The side from this circumcentre to the next is dual to the Delaunay edge (v, w) that
    // this face shares with the next one counter-clockwise around v.
    const int across = face->vertex(Delaunay::cw(face->index(v)))->info();
    if (!polygon.points.empty() && p == polygon.points.back())
      polygon.edge.back() = across;  // the side before had no length
    else
      polygon.push(p, across);
  } while (++face != end);
  while (polygon.size() > 1 && polygon.points.front() == polygon.points.back()) {
    polygon.points.pop_back();
    polygon.edge.pop_back();
  }
  const auto first = std::min_element(
      polygon.points.begin(), polygon.points.end(),
      [](const Vec2& a, const Vec2& b) { return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y()); });
  const auto shift = first - polygon.points.begin();
  std::rotate(polygon.points.begin(), first, polygon.points.end());
  std::rotate(polygon.edge.begin(), polygon.edge.begin() + shift, polygon.edge.end());
}

// Buffers reused from cell to cell.
struct Workspace {
  std::vector<int> visitedBy, queue;
  LabelledPolygon polygon, piece, scratch;
  std::vector<double> rho, side;
  std::vector<std::pair<int, PolygonIntegrals>> parts;  // (triangle, integrals of the piece)
  std::vector<std::pair<std::pair<int, int>, int>> edgeOrder;  // ((neighbour, triangle), part)
  std::vector<EdgeMoments> edgeParts;
};

// Adds, for each Voronoi side of `piece` (inside one parameter triangle, where the density
// `rho` at its points is linear), the side's EdgeMoments about `site` to w.edgeParts. Simpson's
// rule is exact: the integrands are cubic along a side.
void addEdgeMoments(const LabelledPolygon& piece, const std::vector<double>& rho, const Vec2& site,
                    int triangle, Workspace& w) {
  for (size_t i = 0; i < piece.size(); ++i) {
    if (piece.edge[i] < 0) continue;  // a cut by the clipping, or a far dummy site's edge
    const size_t j = (i + 1) % piece.size();
    const double length = (piece.points[j] - piece.points[i]).norm();
    if (length == 0) continue;
    const Vec2 q[3] = {piece.points[i] - site, 0.5 * (piece.points[i] + piece.points[j]) - site,
                       piece.points[j] - site};
    const double weight[3] = {length / 6 * rho[i], length / 6 * 2 * (rho[i] + rho[j]),
                              length / 6 * rho[j]};  // Simpson's, times rho
    EdgeMoments m;
    m.neighbour = piece.edge[i];
    for (int k = 0; k < 3; ++k) {
      m.mass += weight[k];
      m.first += weight[k] * q[k];
      m.second += weight[k] * q[k] * q[k].transpose();
    }
    w.edgeOrder.push_back({{m.neighbour, triangle}, static_cast<int>(w.edgeParts.size())});
    w.edgeParts.push_back(m);
  }
}

// One EdgeMoments per neighbour from w.edgeParts, by neighbour, each one's parts summed in
// triangle order (as the cell's own integrals are: bit-identical wherever the walk started).
void sumEdgeParts(Workspace& w, std::vector<EdgeMoments>& edges) {
  std::sort(w.edgeOrder.begin(), w.edgeOrder.end());
  for (const auto& [key, index] : w.edgeOrder) {
    const EdgeMoments& part = w.edgeParts[index];
    if (edges.empty() || edges.back().neighbour != part.neighbour) {
      edges.push_back(part);
      continue;
    }
    EdgeMoments& sum = edges.back();
    sum.mass += part.mass;
    sum.first += part.first;
    sum.second += part.second;
  }
}

// Visits, breadth first through shared edges, the parameter triangles that the cell overlaps,
// starting from `start`, the one that holds the site, and integrates cell ∩ triangle for each.
// The parts are summed in triangle order, so the result does not depend on where the walk
// started: a cell recomputed later is bit-identical.
void clipAndIntegrate(const Domain& domain, const LabelledPolygon& voronoi, const Vec2& site,
                      int start, int cellId, CellDetail detail, Workspace& w,
                      BoundedCell& cell) {
  w.queue.assign(1, start);
  w.visitedBy[start] = cellId;
  w.parts.clear();
  w.edgeParts.clear();
  w.edgeOrder.clear();
  for (size_t head = 0; head < w.queue.size(); ++head) {
    const int t = w.queue[head];
    const Triangle& tri = domain.triangles()[t];
    const Vec2 corner[3] = {domain.uv()[tri[0]], domain.uv()[tri[1]], domain.uv()[tri[2]]};
    int reaches;
    const LabelledPolygon& piece =
        detail != CellDetail::EdgeMoments
            ? clipToTriangle<false>(voronoi, corner, w.piece, w.scratch, w.side, reaches)
            : clipToTriangle<true>(voronoi, corner, w.piece, w.scratch, w.side, reaches);
    if (piece.size() < 3) continue;
    if (w.rho.size() < piece.size()) w.rho.resize(piece.size());
    for (size_t i = 0; i < piece.size(); ++i) w.rho[i] = domain.densityAt(t, piece.points[i]);
    const PolygonIntegrals part = integratePolygon(piece.points, w.rho, site);
    if (part.area <= 0) continue;
    w.parts.emplace_back(t, part);
    if (detail == CellDetail::EdgeMoments) addEdgeMoments(piece, w.rho, site, t, w);
    if (detail == CellDetail::Geometry) cell.pieces.push_back({t, piece.points});
    for (int k = 0; k < 3; ++k) {
      const int n = domain.neighbours()[t][(k + 2) % 3];  // across edge (corner k, corner k+1)
      if ((reaches & (1 << k)) && n >= 0 && w.visitedBy[n] != cellId) {
        w.visitedBy[n] = cellId;
        w.queue.push_back(n);
      }
    }
  }
  std::sort(w.parts.begin(), w.parts.end(),
            [](const auto& a, const auto& b) { return a.first < b.first; });
  PolygonIntegrals sum;
  for (const auto& [triangle, part] : w.parts) {
    sum.area += part.area;
    sum.mass += part.mass;
    sum.moment += part.moment;
    sum.energy += part.energy;
  }
  sumEdgeParts(w, cell.edges);
  if (detail == CellDetail::Geometry)
    std::sort(cell.pieces.begin(), cell.pieces.end(),
              [](const CellPiece& a, const CellPiece& b) { return a.triangle < b.triangle; });
  cell.area = sum.area;
  cell.mass = sum.mass;
  cell.energy = sum.energy;
  cell.centroid = sum.mass > 0 ? Vec2(sum.moment / sum.mass) : site;
}

}  // namespace

namespace {

// Whether the segment p q lies along a side of the parameter triangle (it is then a cut made
// by the clipping, not an edge of the diagram).
bool onTriangleSide(const Domain& domain, int triangle, const Vec2& p, const Vec2& q) {
  const Triangle& tri = domain.triangles()[triangle];
  const Vec2 corner[3] = {domain.uv()[tri[0]], domain.uv()[tri[1]], domain.uv()[tri[2]]};
  for (int k = 0; k < 3; ++k) {
    const Vec2 side = corner[(k + 1) % 3] - corner[k];
    const double tolerance = kOnSide * side.norm();
    if (std::abs(cross(side, p - corner[k])) <= tolerance &&
        std::abs(cross(side, q - corner[k])) <= tolerance)
      return true;
  }
  return false;
}

// Which side of the (unclipped) Voronoi polygon the piece edge p -> q lies on: the nearest.
size_t voronoiSideOf(const std::vector<Vec2>& voronoi, const Vec2& p, const Vec2& q) {
  size_t best = 0;
  double bestDistance = INFINITY;
  for (size_t k = 0; k < voronoi.size(); ++k) {
    const Vec2 &a = voronoi[k], side = voronoi[(k + 1) % voronoi.size()] - a;
    const double distance =
        (std::abs(cross(side, p - a)) + std::abs(cross(side, q - a))) / side.norm();
    if (distance < bestDistance) {
      bestDistance = distance;
      best = k;
    }
  }
  return best;
}

}  // namespace

std::vector<std::pair<Vec2, Vec2>> voronoiEdges(const Domain& domain,
                                                const std::vector<BoundedCell>& cells) {
  std::vector<std::pair<Vec2, Vec2>> edges;
  struct Part {
    size_t side;
    double start;  // along the side
    Vec2 p, q;
  };
  std::vector<Part> parts;
  for (const BoundedCell& cell : cells) {
    parts.clear();
    for (const CellPiece& piece : cell.pieces) {
      const size_t n = piece.polygon.size();
      for (size_t i = 0; i < n; ++i) {
        const Vec2 &p = piece.polygon[i], &q = piece.polygon[(i + 1) % n];
        // The two cells an edge separates hold it in opposite directions: keep one.
        if (std::make_pair(p.x(), p.y()) >= std::make_pair(q.x(), q.y())) continue;
        if (onTriangleSide(domain, piece.triangle, p, q)) continue;
        const size_t side = voronoiSideOf(cell.voronoi, p, q);
        parts.push_back({side, (p - cell.voronoi[side]).norm(), p, q});
      }
    }
    // Along each side of the cell, pieces that meet (on a parameter triangle's side) are one
    // edge: half as many lines to draw.
    std::sort(parts.begin(), parts.end(), [](const Part& a, const Part& b) {
      return a.side != b.side ? a.side < b.side : a.start < b.start;
    });
    for (size_t i = 0; i < parts.size();) {
      const Vec2 p = parts[i].p;
      Vec2 q = parts[i].q;
      size_t j = i + 1;
      for (; j < parts.size() && parts[j].side == parts[i].side &&
             (parts[j].p - q).norm() <= kOnSide * (1.0 + (q - p).norm());
           ++j)
        q = parts[j].q;
      edges.emplace_back(p, q);
      i = j;
    }
  }
  return edges;
}

std::vector<std::pair<Vec2, Vec2>> cellOutline(const Domain& domain, const BoundedCell& cell) {
  std::vector<std::pair<Vec2, Vec2>> edges;
  for (const CellPiece& piece : cell.pieces)
    for (size_t i = 0; i < piece.polygon.size(); ++i) {
      const Vec2 &p = piece.polygon[i], &q = piece.polygon[(i + 1) % piece.polygon.size()];
      if (!onTriangleSide(domain, piece.triangle, p, q)) edges.emplace_back(p, q);
    }
  return edges;
}

PolygonIntegrals integratePolygon(const std::vector<Vec2>& polygon,
                                  const std::vector<double>& density, const Vec2& site) {
  PolygonIntegrals sum;
  for (size_t i = 1; i + 1 < polygon.size(); ++i) {
    const Vec2 p[3] = {polygon[0], polygon[i], polygon[i + 1]};
    const double rho[3] = {density[0], density[i], density[i + 1]};
    integrateTriangle(p, rho, site, sum);
  }
  return sum;
}

std::vector<BoundedCell> computeCells(const Domain& domain, const std::vector<Vec2>& sites,
                                      CellDetail detail, CellHints* hints,
                                      int threadCount) {
  std::vector<BoundedCell> cells(sites.size());
  for (size_t i = 0; i < sites.size(); ++i) cells[i].centroid = sites[i];
  if (sites.empty() || domain.triangles().empty()) return cells;
  CellHints local;
  if (!hints) hints = &local;
  hints->triangle.resize(sites.size(), -1);
  Delaunay& dt = triangulate(sites, *hints);
  // A site that coincides with an earlier one has no vertex of its own: its cell stays empty.
  std::vector<Delaunay::Vertex_handle> vertices;
  for (auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v)
    if (v->info() != kDummy) vertices.push_back(v);

  // Cells are independent: split them over the cores. Each cell's numbers do not depend on
  // which thread computed it.
  auto work = [&](size_t begin, size_t end) {
    Workspace w;
    w.visitedBy.assign(domain.triangles().size(), -1);
    for (size_t k = begin; k < end; ++k) {
      const Delaunay::Vertex_handle v = vertices[k];
      const int id = v->info();
      // In a triangle with neighbours: a fixed site on an ear of a square border, located in
      // the ear's flat triangle, had an empty cell and left a hole in the domain.
      const int start = domain.locateInArea(sites[id], hints->triangle[id]).triangle;
      hints->triangle[id] = start;
      BoundedCell& cell = cells[id];
      voronoiPolygon(v, w.polygon);
      clipAndIntegrate(domain, w.polygon, sites[id], start, id, detail, w, cell);
      if (detail == CellDetail::Geometry) {
        cell.voronoi = w.polygon.points;
        auto n = dt.incident_vertices(v), end = n;
        do {
          if (!dt.is_infinite(n) && n->info() != kDummy) cell.neighbours.push_back(n->info());
        } while (++n != end);
        std::sort(cell.neighbours.begin(), cell.neighbours.end());  // wherever the walk began
      }
    }
  };
  const size_t threads =
      threadCount > 0         ? static_cast<size_t>(threadCount)
      : vertices.size() < 500 ? 1
                              : std::max(1u, std::thread::hardware_concurrency());
  std::vector<Delaunay::Face_handle> faces;
  faces.reserve(dt.number_of_faces());
  for (auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f) faces.push_back(f);
  parallelFor(faces.size(), threads,
              [&](size_t begin, size_t end) { storeCircumcenters(begin, end, faces); });
  parallelFor(vertices.size(), threads, work);
  return cells;
}

}  // namespace lloydscope
