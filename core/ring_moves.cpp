#include "ring_moves.h"

#include "flips.h"
#include "metrics.h"
#include "names.h"

#include <algorithm>
#include <iterator>
#include <numeric>

namespace lloydscope {

namespace {

Vec3 circumcenter(const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, n = ab.cross(ac);
  const double n2 = n.squaredNorm();
  if (!(n2 > 0)) return (a + b + c) / 3.0;
  return a + (ac.squaredNorm() * n.cross(ab) + ab.squaredNorm() * ac.cross(n)) / (2.0 * n2);
}

// The part of triangle (a, b, c) closer to a than to b and to c (a's Voronoi cell inside the
// triangle): its area and centroid. The triangle clipped by the two bisector planes.
std::pair<double, Vec3> voronoiPart(const Vec3& a, const Vec3& b, const Vec3& c) {
  Vec3 polygon[8] = {a, b, c}, clipped[8];
  int n = 3;
  for (const Vec3* other : {&b, &c}) {
    const Vec3 normal = *other - a, middle = 0.5 * (*other + a);
    int m = 0;
    for (int i = 0, j = n - 1; i < n; j = i++) {
      const double si = (polygon[i] - middle).dot(normal), sj = (polygon[j] - middle).dot(normal);
      if ((sj <= 0) != (si <= 0)) clipped[m++] = polygon[j] + (sj / (sj - si)) * (polygon[i] - polygon[j]);
      if (si <= 0) clipped[m++] = polygon[i];
    }
    n = m;
    std::copy(clipped, clipped + n, polygon);
  }
  double area = 0;
  Vec3 moment = Vec3::Zero();
  for (int i = 1; i + 1 < n; ++i) {
    const double part = 0.5 * (polygon[i] - polygon[0]).cross(polygon[i + 1] - polygon[0]).norm();
    area += part;
    moment += part * (polygon[0] + polygon[i] + polygon[i + 1]) / 3.0;
  }
  return {area, area > 0 ? Vec3(moment / area) : a};
}

}  // namespace

Vec3 relaxationMove(const Mesh& m, const Rings& rings, const std::vector<double>& weight, int v,
                    PolishTarget target, Vec3& normal) {
  Vec3 centre = Vec3::Zero();
  normal = Vec3::Zero();
  double total = 0;
  for (int k = rings.offset[v]; k < rings.offset[v + 1]; ++k) {
    const Triangle& t = m.triangles[rings.faces[k]];
    const Vec3 &a = m.points[t[0]], &b = m.points[t[1]], &c = m.points[t[2]];
    const Vec3 n = (b - a).cross(c - a);
    const double rho = (weight[t[0]] + weight[t[1]] + weight[t[2]]) / 3.0;
    normal += n;
    if (target == PolishTarget::Voronoi) {
      const int i = t[0] == v ? 0 : t[1] == v ? 1 : 2;
      const auto [area, centroid] =
          voronoiPart(m.points[v], m.points[t[(i + 1) % 3]], m.points[t[(i + 2) % 3]]);
      centre += rho * area * centroid;
      total += rho * area;
      continue;
    }
    const double w = 0.5 * n.norm() * rho;
    centre += w * (target == PolishTarget::Centroid ? Vec3((a + b + c) / 3.0) : circumcenter(a, b, c));
    total += w;
  }
  if (!(total > 0) || !(normal.squaredNorm() > 0)) return Vec3::Zero();
  normal.normalize();
  const Vec3 d = centre / total - m.points[v];
  return d - normal * normal.dot(d);
}

Vec3 ringNormal(const Mesh& m, const Rings& rings, int v) {
  Vec3 sum = Vec3::Zero();
  for (int k = rings.offset[v]; k < rings.offset[v + 1]; ++k) sum += faceNormal(m, m.triangles[rings.faces[k]]);
  return sum.squaredNorm() > 0 ? Vec3(sum.normalized()) : Vec3::Zero();
}

bool keepsRingUnfolded(const Mesh& m, const Rings& rings, int v, const Vec3& to, const Vec3& up) {
  for (int k = rings.offset[v]; k < rings.offset[v + 1]; ++k) {
    const Triangle& t = m.triangles[rings.faces[k]];
    auto at = [&](int i) -> const Vec3& { return t[i] == v ? to : m.points[t[i]]; };
    const Vec3 n = (at(1) - at(0)).cross(at(2) - at(0));
    if (!(n.dot(up) > 0.1 * n.norm())) return false;  // within ~84 degrees of the ring's normal
  }
  return true;
}

double ringSmallestAngle(const Mesh& m, const Rings& rings, int v, const Vec3& to,
                         const Vec3& up) {
  if (!keepsRingUnfolded(m, rings, v, to, up)) return -1;
  return smallestAngleOfRing(m, rings, v, to);
}

std::pair<std::vector<int>, std::vector<int>> borderNeighbours(const Mesh& m) {
  // Each vertex's sides a -> b, sorted by b (per-vertex sorts: the last steps ask after every
  // collapse of a border edge); a side is on the border where no triangle runs it back b -> a.
  const size_t n = m.points.size();
  std::vector<int> offset(n + 1, 0);
  for (const Triangle& t : m.triangles)
    for (int v : t) ++offset[v + 1];
  std::partial_sum(offset.begin(), offset.end(), offset.begin());
  std::vector<int> to(offset.back()), fill(offset.begin(), offset.end() - 1);
  for (const Triangle& t : m.triangles)
    for (int k = 0; k < 3; ++k) to[fill[t[k]]++] = t[(k + 1) % 3];
  for (size_t a = 0; a < n; ++a) std::sort(to.begin() + offset[a], to.begin() + offset[a + 1]);
  const auto runs = [&](int a, int b) {
    return std::binary_search(to.begin() + offset[a], to.begin() + offset[a + 1], b);
  };
  std::vector<int> before(n, -1), after(n, -1);
  for (size_t a = 0; a < n; ++a)  // in order of (a, b), as the last of two sides wins
    for (int i = offset[a]; i < offset[a + 1]; ++i) {
      const int b = to[i];
      if (runs(b, static_cast<int>(a))) continue;
      after[a] = b;
      before[b] = static_cast<int>(a);
    }
  return {before, after};
}

bool mergeVertex(Mesh& m, int from, int to) {
  std::vector<int> fromRing, toRing;
  std::vector<size_t> changed, removed;
  for (size_t g = 0; g < m.triangles.size(); ++g) {
    const Triangle& tri = m.triangles[g];
    for (int a = 0; a < 3; ++a) {
      if (tri[a] == from) fromRing.insert(fromRing.end(), {tri[(a + 1) % 3], tri[(a + 2) % 3]});
      if (tri[a] == to) toRing.insert(toRing.end(), {tri[(a + 1) % 3], tri[(a + 2) % 3]});
    }
  }
  for (auto* ring : {&fromRing, &toRing}) {
    std::sort(ring->begin(), ring->end());
    ring->erase(std::unique(ring->begin(), ring->end()), ring->end());
  }
  std::vector<int> shared;
  std::set_intersection(fromRing.begin(), fromRing.end(), toRing.begin(), toRing.end(),
                        std::back_inserter(shared));
  for (size_t g = 0; g < m.triangles.size(); ++g) {
    const Triangle& tri = m.triangles[g];
    if (std::find(tri.begin(), tri.end(), from) == tri.end()) continue;
    if (std::find(tri.begin(), tri.end(), to) != tri.end()) {
      removed.push_back(g);
      continue;
    }
    Triangle after = tri;
    std::replace(after.begin(), after.end(), from, to);
    const Vec3 n0 = faceNormal(m, tri), n1 = faceNormal(m, after);
    if (!(n1.dot(n0) > 0.1 * n0.norm() * n1.norm())) return false;
    changed.push_back(g);
  }
  if (removed.empty() || shared.size() != removed.size()) return false;
  for (size_t g : changed) std::replace(m.triangles[g].begin(), m.triangles[g].end(), from, to);
  // Removed triangles become markers, erased by the caller (indices stay valid meanwhile).
  for (size_t g : removed) m.triangles[g] = {to, to, to};
  return true;
}

void eraseMergedTriangles(Mesh& m) {
  m.triangles.erase(std::remove_if(m.triangles.begin(), m.triangles.end(), isMergeMarker), m.triangles.end());
}

// A flat triangle that neither moves nor flips can fix (a vertex on the segment between two
// others, on a sharp ridge where every flip would fold the surface) loses its shortest edge:
// its inside end is merged into the other end. The merged vertex is left unused; polish()
// drops such vertices at the end. Returns how many were merged.
constexpr double kCollapseBelow = 10.0;

int collapseFlatTriangles(Mesh& m) {
  const std::vector<bool> border = vertexEdges(m).onBoundary;
  int merged = 0;
  for (size_t f = 0; f < m.triangles.size(); ++f) {
    const Triangle t = m.triangles[f];
    if (isMergeMarker(t) || smallestAngleDeg(m.points[t[0]], m.points[t[1]], m.points[t[2]]) >= kCollapseBelow)
      continue;
    // Its edges, shortest first; each end that is not on the border may go.
    std::array<int, 3> edges = {0, 1, 2};
    auto length = [&](int k) { return (m.points[t[(k + 1) % 3]] - m.points[t[k]]).squaredNorm(); };
    std::sort(edges.begin(), edges.end(), [&](int a, int b) { return length(a) < length(b); });
    bool done = false;
    for (int k : edges)
      for (auto [from, to] : {std::pair{t[k], t[(k + 1) % 3]}, std::pair{t[(k + 1) % 3], t[k]}})
        if (!done && !border[from]) done = mergeVertex(m, from, to);
    merged += done;
  }
  eraseMergedTriangles(m);
  return merged;
}

void relaxOnce(Mesh& m, const std::vector<bool>& movable, const std::vector<bool>& fixed,
               const SurfaceProjection& surface) {
  const std::vector<double> unit(m.vertexCount(), 1.0);
  const Rings rings(m);
  for (int v = 0; v < m.vertexCount(); ++v) {
    if (!movable[v] || fixed[v]) continue;
    Vec3 up;
    const Vec3 move = relaxationMove(m, rings, unit, v, PolishTarget::Centroid, up);
    const double floor = std::min(30.0, ringSmallestAngle(m, rings, v, m.points[v], up));
    for (double step = 1.0; step >= 0.25; step *= 0.5) {
      const Vec3 to = surface.closestPoint(m.points[v] + step * move);
      if (ringSmallestAngle(m, rings, v, to, up) >= floor) {
        m.points[v] = to;
        break;
      }
    }
  }
}

namespace {

// relaxOnSurface's local passes, made on the triangles at the movable vertices and their
// neighbours alone, then written back in place. A flip of an edge at a movable vertex makes an
// edge between two of that vertex's neighbours, so the passes neither read nor change anything
// further out (the edges a flip checks for, the valences and the border included): the same
// result, where the whole mesh's edges, rings and valences at every pass cost most of a try in
// the last steps (the collapses of short border edges on a jagged border).
void relaxLocally(Mesh& m, const std::vector<bool>& movable, const SurfaceProjection& surface, int passes) {
  const std::vector<bool> near = withNeighbours(m, movable);
  Mesh part;
  part.points = m.points;
  std::vector<int> faces;
  for (int f = 0; f < m.faceCount(); ++f) {
    const Triangle& t = m.triangles[f];
    if (!near[t[0]] && !near[t[1]] && !near[t[2]]) continue;
    faces.push_back(f);
    part.triangles.push_back(t);
  }
  const std::vector<bool> border = vertexEdges(part).onBoundary;  // as the whole's, at a movable vertex
  for (int pass = 0; pass < passes; ++pass) {
    relaxOnce(part, movable, border, surface);
    flipEdges(part, notDelaunay, nullptr, &movable);
  }
  m.points = std::move(part.points);
  for (size_t i = 0; i < faces.size(); ++i) m.triangles[faces[i]] = part.triangles[i];
}

}  // namespace

void relaxOnSurface(Mesh& m, const std::vector<bool>& movable, const SurfaceProjection& surface,
                    int passes, bool local) {
  if (local) return relaxLocally(m, movable, surface, passes);
  const std::vector<bool> border = vertexEdges(m).onBoundary;
  for (int pass = 0; pass < passes; ++pass) {
    relaxOnce(m, movable, border, surface);
    flipEdges(m, notDelaunay);
  }
  if (passes > 0) {
    flipEdges(m, raisesRegularity);
    relaxOnce(m, movable, border, surface);
  }
}

std::vector<bool> withNeighbours(const Mesh& m, const std::vector<bool>& marked) {
  std::vector<bool> grown = marked;
  for (const Triangle& t : m.triangles)
    if (marked[t[0]] || marked[t[1]] || marked[t[2]])
      for (int v : t) grown[v] = true;
  return grown;
}

double smallestAngleAround(const Mesh& m, const std::vector<bool>& marked) {
  double smallest = 180;
  for (const Triangle& t : m.triangles)
    if (marked[t[0]] || marked[t[1]] || marked[t[2]])
      smallest = std::min(smallest, smallestAngleDeg(m.points[t[0]], m.points[t[1]], m.points[t[2]]));
  return smallest;
}

double meanEdgeLength(const Mesh& m) {
  double sum = 0;
  for (const Triangle& t : m.triangles)
    for (int k = 0; k < 3; ++k) sum += (m.points[t[k]] - m.points[t[(k + 1) % 3]]).norm();
  return sum / (3.0 * m.faceCount());
}

constexpr NamedValue<PolishTarget> kPolishTargetNames[] = {{PolishTarget::Voronoi, "voronoi"},
                                                            {PolishTarget::Centroid, "centroid"},
                                                            {PolishTarget::Circumcenter, "circumcenter"}};

const char* toString(PolishTarget target) { return nameOf(kPolishTargetNames, target); }

PolishTarget parsePolishTarget(const std::string& text) {
  return parseName(kPolishTargetNames, text, "polish target");
}

bool turnsOver(const Mesh& m, const Rings& rings, int v, const Vec3& to) {
  for (int k = rings.offset[v]; k < rings.offset[v + 1]; ++k) {
    const Triangle& t = m.triangles[rings.faces[k]];
    auto at = [&](int c) -> const Vec3& { return t[c] == v ? to : m.points[t[c]]; };
    if (!((at(1) - at(0)).cross(at(2) - at(0)).dot(faceNormal(m, t)) > 0)) return true;
  }
  return false;
}

double smallestAngleOfRing(const Mesh& m, const Rings& rings, int v, const Vec3& to) {
  double smallest = 180;
  for (int k = rings.offset[v]; k < rings.offset[v + 1]; ++k) {
    const Triangle& t = m.triangles[rings.faces[k]];
    auto at = [&](int i) -> const Vec3& { return t[i] == v ? to : m.points[t[i]]; };
    smallest = std::min(smallest, smallestAngleDeg(at(0), at(1), at(2)));
  }
  return smallest;
}

}  // namespace lloydscope
