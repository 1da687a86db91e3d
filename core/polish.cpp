#include "polish.h"

#include "cut.h"
#include "flips.h"
#include "metrics.h"
#include "ring_moves.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <unordered_map>

namespace lloydscope {

namespace {

// The parameter displacement whose image on input triangle `t` best matches the 3D `d`:
// with E = [P1 - P0, P2 - P0] and U = [p1 - p0, p2 - p0], the map is E U^-1, and its
// pseudo-inverse is U (E^T E)^-1 E^T.
Vec2 toParameter(const Mesh& input, const Domain& domain, int t, const Vec3& d) {
  const Triangle& tri = input.triangles[t];
  Eigen::Matrix<double, 3, 2> e;
  e << input.points[tri[1]] - input.points[tri[0]], input.points[tri[2]] - input.points[tri[0]];
  Eigen::Matrix2d u;
  u << domain.uv()[tri[1]] - domain.uv()[tri[0]], domain.uv()[tri[2]] - domain.uv()[tri[0]];
  const Eigen::Matrix2d ete = e.transpose() * e;
  if (!(std::abs(ete.determinant()) > 0)) return Vec2::Zero();
  return u * ete.inverse() * (e.transpose() * d);
}

// Moves `v` to location `l` of the domain: its point, its parameter point, its triangle and,
// if given, its density weight.
void moveTo(LiftedMesh& lm, const SurfaceMap& surface, const Density& surfaceDensity, int v,
            const Location& l, std::vector<int>& triangleOf, std::vector<double>* weight) {
  lm.mesh.points[v] = surface.at(l);
  lm.uv[v] = surface.domain.pointAt(l);
  triangleOf[v] = l.triangle;
  if (weight && !surfaceDensity.empty())
    (*weight)[v] = densityAt(surfaceDensity, l.triangle, l.weights);
}

// One Gauss-Seidel pass: each inside vertex, in order, takes its relaxation move (halved until
// its ring stays valid), through its parameter point.
void relaxPass(LiftedMesh& lm, const SurfaceMap& surface,
               const Density& surfaceDensity, PolishTarget target,
               std::vector<int>& triangleOf, std::vector<double>& weight) {
  Mesh& m = lm.mesh;
  const Rings rings(m);
  const std::vector<bool> border = vertexEdges(m).onBoundary;
  for (int v = 0; v < m.vertexCount(); ++v) {
    if (border[v]) continue;
    Vec3 up;
    const Vec3 move = relaxationMove(m, rings, weight, v, target, up);
    const Vec2 duv = toParameter(surface.mesh, surface.domain, triangleOf[v], move);
    for (double step = 1.0; step >= 0.25; step *= 0.5) {
      const Location l = surface.domain.locate(lm.uv[v] + step * duv, triangleOf[v]);
      if (!keepsRingUnfolded(m, rings, v, surface.at(l), up)) continue;
      moveTo(lm, surface, surfaceDensity, v, l, triangleOf, &weight);
      break;
    }
  }
}

// The domain's border, along which the repair slides border vertices of the result: each loop's
// domain vertices in order, their parameter points, their arc length along the loop (in the
// plane) and their points on the surface.
class DomainBorder {
 public:
  struct Place {  // a point of the border: its loop, and its arc length from the loop's start
    int loop = -1;
    double arc = 0;
  };

  explicit DomainBorder(const SurfaceMap& surface) {
    const std::vector<Triangle>& triangles = surface.domain.triangles();
    std::unordered_map<int, int> next;
    std::unordered_map<int, Location> at;
    for (size_t t = 0; t < triangles.size(); ++t)
      for (int k = 0; k < 3; ++k) {
        if (surface.domain.neighbours()[t][k] >= 0) continue;
        const int a = triangles[t][(k + 1) % 3], b = triangles[t][(k + 2) % 3];
        if (!next.emplace(a, b).second) return;  // a border that touches itself: no slides
        Location l;
        l.triangle = static_cast<int>(t);
        l.weights = Eigen::Vector3d::Unit((k + 1) % 3);
        l.inside = true;
        at.emplace(a, l);
      }
    while (!next.empty()) {
      Loop loop;
      for (int v = next.begin()->first; next.count(v);) {
        loop.uv.push_back(surface.domain.uv()[v]);
        loop.point.push_back(surface.at(at.at(v)));
        const int following = next.at(v);
        next.erase(v);
        v = following;
      }
      loop.arc.assign(1, 0.0);
      for (size_t i = 0; i < loop.uv.size(); ++i)
        loop.arc.push_back(loop.arc.back() + (loop.uv[(i + 1) % loop.uv.size()] - loop.uv[i]).norm());
      loops_.push_back(std::move(loop));
    }
  }

  // The place of the border nearest to a parameter point (one on the border, in use).
  Place placeOf(const Vec2& p) const {
    Place best;
    double nearest = std::numeric_limits<double>::infinity();
    for (size_t l = 0; l < loops_.size(); ++l) {
      const Loop& loop = loops_[l];
      for (size_t i = 0; i < loop.uv.size(); ++i) {
        const Vec2 a = loop.uv[i], ab = loop.uv[(i + 1) % loop.uv.size()] - a;
        const double t = ab.squaredNorm() > 0 ? std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0) : 0.0;
        const double d = (a + t * ab - p).norm();
        if (d < nearest) {
          nearest = d;
          best = {static_cast<int>(l), loop.arc[i] + t * (loop.arc[i + 1] - loop.arc[i])};
        }
      }
    }
    return best;
  }

  Vec2 uvAt(const Place& place) const {
    const Loop& loop = loops_[place.loop];
    const double length = loop.arc.back(), arc = place.arc - length * std::floor(place.arc / length);
    const size_t i = std::min<size_t>(std::upper_bound(loop.arc.begin(), loop.arc.end(), arc) - loop.arc.begin(),
                                      loop.uv.size()) - 1;
    const double span = loop.arc[i + 1] - loop.arc[i];
    const double t = span > 0 ? (arc - loop.arc[i]) / span : 0.0;
    return (1 - t) * loop.uv[i] + t * loop.uv[(i + 1) % loop.uv.size()];
  }

  // The arc length from a to b the shorter way round the loop (negative: backwards).
  double arcBetween(const Place& a, const Place& b) const {
    const double length = loops_[a.loop].arc.back();
    double d = std::fmod(b.arc - a.arc, length);
    if (d > 0.5 * length) d -= length;
    if (d < -0.5 * length) d += length;
    return d;
  }

  // How far the border between a and b (its domain vertices) strays from the segment from A to
  // B, the result's edge between them.
  double strayFrom(const Place& a, const Place& b, const Vec3& A, const Vec3& B) const {
    const Loop& loop = loops_[a.loop];
    const double length = loop.arc.back(), d = arcBetween(a, b);
    double farthest = 0;
    for (size_t i = 0; i < loop.uv.size(); ++i) {
      double along = (d > 0 ? 1 : -1) * (loop.arc[i] - a.arc);
      along -= length * std::floor(along / length);
      if (along > 0 && along < std::abs(d)) farthest = std::max(farthest, distanceToSegment(loop.point[i], A, B));
    }
    return farthest;
  }

  bool empty() const { return loops_.empty(); }

 private:
  struct Loop {
    std::vector<Vec2> uv;
    std::vector<Vec3> point;
    std::vector<double> arc;  // one more than the vertices: the last is the loop's length
  };
  std::vector<Loop> loops_;
};

// A border vertex in a triangle with a small angle, where the border was sampled evenly into a
// sharp corner (the strip of triangles across a 30-degree wedge has a 24-degree angle next to
// its tip), slides along the domain's border towards either border neighbour, up to 0.4 of the
// way, where that raises the smallest angle of its ring, unless the result's border would
// stray farther from the domain's than it does, or than kSlideStray of its edges' length where
// it strays less: moving off a corner, or the tip of a bump, would cut it; along a bent border
// any move strays a little farther (with no allowance, a bent sector's border never slid).
constexpr double kSlideStray = 0.02;

void slideAlongBorder(LiftedMesh& lm, const SurfaceMap& surface, const DomainBorder& domainBorder,
                      const Density& surfaceDensity, const std::vector<bool>& slides,
                      std::vector<int>& triangleOf) {
  Mesh& m = lm.mesh;
  const Rings rings(m);
  const auto [before, after] = borderNeighbours(m);
  for (int v = 0; v < m.vertexCount(); ++v) {
    if (!slides[v] || before[v] < 0 || after[v] < 0) continue;
    const int p = before[v], n = after[v];
    const DomainBorder::Place at = domainBorder.placeOf(lm.uv[v]);
    const DomainBorder::Place atP = domainBorder.placeOf(lm.uv[p]), atN = domainBorder.placeOf(lm.uv[n]);
    if (at.loop < 0 || atP.loop != at.loop || atN.loop != at.loop) continue;
    auto stray = [&](const DomainBorder::Place& place, const Vec3& x) {
      return std::max(domainBorder.strayFrom(atP, place, m.points[p], x),
                      domainBorder.strayFrom(place, atN, x, m.points[n]));
    };
    const double edge = 0.5 * ((m.points[v] - m.points[p]).norm() + (m.points[n] - m.points[v]).norm());
    const double strayNow = std::max(stray(at, m.points[v]), kSlideStray * edge);
    const Vec3 up = ringNormal(m, rings, v);
    double best = ringSmallestAngle(m, rings, v, m.points[v], up);
    Location bestLocation;
    for (const DomainBorder::Place& toward : {atP, atN}) {
      const double arc = domainBorder.arcBetween(at, toward);
      for (double fraction : {0.1, 0.2, 0.3, 0.4}) {
        const DomainBorder::Place place{at.loop, at.arc + fraction * arc};
        const Location l = surface.domain.locate(domainBorder.uvAt(place), triangleOf[v]);
        const Vec3 to = surface.at(l);
        const double score = ringSmallestAngle(m, rings, v, to, up);
        if (score > best + 1e-9 && stray(place, to) <= strayNow) {
          best = score;
          bestLocation = l;
        }
      }
    }
    if (bestLocation.triangle >= 0) moveTo(lm, surface, surfaceDensity, v, bestLocation, triangleOf, nullptr);
  }
}

// The vertices of triangles with an angle under `degrees`.
std::vector<bool> inTrianglesUnder(const Mesh& m, double degrees) {
  std::vector<bool> in(m.vertexCount(), false);
  for (const Triangle& t : m.triangles)
    if (smallestAngleDeg(m.points[t[0]], m.points[t[1]], m.points[t[2]]) < degrees)
      for (int v : t) in[v] = true;
  return in;
}

// Where relaxation left small angles: each inside vertex of a triangle under kRepairBelow
// degrees moves to whichever candidate (its Voronoi centroid, its ring's centroid, its
// circumcentre target, or halfway to one) gives its ring the largest smallest angle; the border
// vertices of a triangle still under kSlideBelow (issue 5's bar) slide along the border
// (slideAlongBorder, given `domainBorder`); then edges flip wherever that raises the smallest
// angle of the two triangles. Sliding for the angles the inside's moves fix anyway, or first,
// changed results at random (CGAL's three peaks at 1000 vertices lost a bar).
constexpr double kRepairBelow = 35.0;
constexpr double kSlideBelow = 30.0;

void repairAngles(LiftedMesh& lm, const SurfaceMap& surface, const Density& surfaceDensity,
                  const std::vector<int>* stitched, const DomainBorder* domainBorder,
                  std::vector<int>& triangleOf, std::vector<double>& weight) {
  Mesh& m = lm.mesh;
  const std::vector<bool> border = vertexEdges(m).onBoundary;
  const std::vector<bool> bad = inTrianglesUnder(m, kRepairBelow);
  const Rings rings(m);
  for (int v = 0; v < m.vertexCount(); ++v) {
    if (!bad[v] || border[v]) continue;
    Vec3 up = ringNormal(m, rings, v);
    double best = ringSmallestAngle(m, rings, v, m.points[v], up);
    Location bestLocation;
    for (PolishTarget target : {PolishTarget::Voronoi, PolishTarget::Centroid, PolishTarget::Circumcenter}) {
      const Vec3 move = relaxationMove(m, rings, weight, v, target, up);
      const Vec2 duv = toParameter(surface.mesh, surface.domain, triangleOf[v], move);
      for (double step : {1.0, 0.5}) {
        const Location l = surface.domain.locate(lm.uv[v] + step * duv, triangleOf[v]);
        const double score = ringSmallestAngle(m, rings, v, surface.at(l), up);
        if (score > best + 1e-9) {
          best = score;
          bestLocation = l;
        }
      }
    }
    if (bestLocation.triangle >= 0)
      moveTo(lm, surface, surfaceDensity, v, bestLocation, triangleOf, nullptr);
  }
  if (domainBorder)
    slideAlongBorder(lm, surface, *domainBorder, surfaceDensity, inTrianglesUnder(m, kSlideBelow), triangleOf);
  flipEdges(m, raisesSmallestAngle, stitched);
}

// Drops the vertices no triangle uses (merged ones), keeping the order of the rest.
void dropUnusedVertices(LiftedMesh& lm) {
  std::vector<int> kept;
  lm.mesh = assemble(lm.mesh.triangles, lm.mesh.points, &kept);
  std::vector<Vec2> uv;
  for (int v : kept) uv.push_back(lm.uv[v]);
  lm.uv = std::move(uv);
}

}  // namespace

Vec3 SurfaceMap::at(const Location& l) const {
  if (lift) return lift(l);
  const Triangle& t = mesh.triangles[l.triangle];
  return l.weights[0] * mesh.points[t[0]] + l.weights[1] * mesh.points[t[1]] +
         l.weights[2] * mesh.points[t[2]];
}

namespace {

// Splits inside edge (a, b) at its parameter midpoint: its two triangles become four.
void splitEdge(LiftedMesh& lm, const SurfaceMap& surface, int a, int b) {
  Mesh& m = lm.mesh;
  auto find = [&](int from, int to) {  // the face with the directed edge from -> to, rotated to start there
    for (int f = 0; f < m.faceCount(); ++f)
      for (int k = 0; k < 3; ++k)
        if (m.triangles[f][k] == from && m.triangles[f][(k + 1) % 3] == to) return std::pair{f, m.triangles[f][(k + 2) % 3]};
    return std::pair{-1, -1};
  };
  const auto [f1, c] = find(a, b);
  const auto [f2, d] = find(b, a);
  if (f1 < 0 || f2 < 0) return;
  const Location l = surface.domain.locate(0.5 * (lm.uv[a] + lm.uv[b]));
  const int mid = m.vertexCount();
  m.points.push_back(surface.at(l));
  lm.uv.push_back(surface.domain.pointAt(l));
  m.triangles[f1] = {a, mid, c};
  m.triangles.push_back({mid, b, c});
  m.triangles[f2] = {b, mid, d};
  m.triangles.push_back({mid, a, d});
}

// Where stitching would make edges of the disk one edge of more than two triangles (an inside
// vertex joined to two copies of one seam sample, which no flip can undo at a node of the cut
// graph, where three copies or more meet and flips would join border vertices; or an inside
// edge between two seam samples that a seam joins too), inside edges are split until two
// triangles are left: the vertex is then joined to that sample once.
// `partners` (seamPartners() of the disk) grows with the new vertices.
void splitDoubledEdges(LiftedMesh& lm, const SurfaceMap& surface, std::vector<int>& partners) {
  std::set<std::pair<int, int>> directed;
  for (const Triangle& t : lm.mesh.triangles)
    for (int k = 0; k < 3; ++k) directed.emplace(t[k], t[(k + 1) % 3]);
  struct Group {
    std::vector<std::pair<int, int>> inside;  // each edge of two triangles, once
    int border = 0;                           // edges of one triangle
  };
  std::map<std::pair<int, int>, Group> byStitchedEdge;
  for (const auto& [a, b] : directed) {
    Group& group = byStitchedEdge[std::minmax(partners[a], partners[b])];
    if (!directed.count({b, a})) ++group.border;
    else if (a < b) group.inside.emplace_back(a, b);
  }
  for (const auto& [stitched, group] : byStitchedEdge) {
    const size_t keep = group.border > 0 ? 0 : 1;
    if (2 * group.inside.size() + group.border <= 2) continue;
    for (size_t i = keep; i < group.inside.size(); ++i)
      splitEdge(lm, surface, group.inside[i].first, group.inside[i].second);
  }
  while (partners.size() < lm.uv.size()) partners.push_back(static_cast<int>(partners.size()));
}

}  // namespace

std::vector<int> prepareSeams(LiftedMesh& mesh, const SurfaceMap& surface) {
  // The border stays as it is, so its stitching partners do too.
  std::vector<int> partners = seamPartners(mesh.mesh, seamTolerance(mesh.mesh));
  flipEdges(mesh.mesh, doubledWhenStitched, &partners);  // what the CDT left
  splitDoubledEdges(mesh, surface, partners);            // what no flip could remove
  return partners;
}

void polish(LiftedMesh& mesh, const SurfaceMap& surface, const Density& surfaceDensity,
            const PolishOptions& options) {
  std::vector<int> partners = options.seams ? prepareSeams(mesh, surface) : std::vector<int>();
  const std::vector<int>* stitched = options.seams ? &partners : nullptr;
  flipEdges(mesh.mesh, notDelaunay, stitched);
  if (options.iterations <= 0) return;
  std::vector<int> triangleOf(mesh.uv.size());
  std::vector<double> weight(mesh.uv.size(), 1.0);
  for (size_t v = 0; v < mesh.uv.size(); ++v) {
    const Location l = surface.domain.locate(mesh.uv[v]);
    triangleOf[v] = l.triangle;
    if (!surfaceDensity.empty()) weight[v] = densityAt(surfaceDensity, l.triangle, l.weights);
  }
  for (int pass = 0; pass < options.iterations; ++pass) {
    relaxPass(mesh, surface, surfaceDensity, options.target, triangleOf, weight);
    flipEdges(mesh.mesh, notDelaunay, stitched);
  }
  for (int pass = 0; pass < options.valencePasses; ++pass) {
    flipEdges(mesh.mesh, raisesRegularity, stitched);
    relaxPass(mesh, surface, surfaceDensity, options.target, triangleOf, weight);
  }
  // A cut surface's border holds seams, whose two copies must stay together.
  const std::optional<DomainBorder> domainBorder =
      options.seams || !options.slideBorder ? std::nullopt : std::optional<DomainBorder>(std::in_place, surface);
  const DomainBorder* slides = domainBorder && !domainBorder->empty() ? &*domainBorder : nullptr;
  for (int pass = 0; pass < options.repairPasses; ++pass) {
    repairAngles(mesh, surface, surfaceDensity, stitched, slides, triangleOf, weight);
    // Merges next to seams could double a stitched edge: none on a cut surface.
    if (pass + 1 == options.repairPasses && !options.seams && collapseFlatTriangles(mesh.mesh) > 0) {
      repairAngles(mesh, surface, surfaceDensity, stitched, slides, triangleOf, weight);  // around them
      dropUnusedVertices(mesh);
    }
  }
}

}  // namespace lloydscope
