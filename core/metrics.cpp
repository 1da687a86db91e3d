#include "metrics.h"

#include "parallel.h"
#include "projection.h"
#include "ring_moves.h"
#include "topology.h"

#include <Eigen/Cholesky>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <random>
#include <set>
#include <thread>

namespace lloydscope {

namespace {
double angleDeg(const Vec3& at, const Vec3& p, const Vec3& q) { return cornerAngle(at, p, q) * 180.0 / M_PI; }
}  // namespace

std::array<double, 3> cornerAnglesDeg(const Vec3& a, const Vec3& b, const Vec3& c) {
  return {angleDeg(a, b, c), angleDeg(b, c, a), angleDeg(c, a, b)};
}

double smallestAngleDeg(const Vec3& a, const Vec3& b, const Vec3& c) {
  // Opposite the shortest edge.
  const double ab = (b - a).squaredNorm(), bc = (c - b).squaredNorm(), ca = (a - c).squaredNorm();
  if (bc <= ab && bc <= ca) return angleDeg(a, b, c);
  if (ca <= ab) return angleDeg(b, c, a);
  return angleDeg(c, a, b);
}

int worstTriangle(const Mesh& mesh) {
  int worst = -1;
  double smallest = std::numeric_limits<double>::infinity();
  for (int t = 0; t < mesh.faceCount(); ++t) {
    const Triangle& f = mesh.triangles[t];
    const double angle = smallestAngleDeg(mesh.points[f[0]], mesh.points[f[1]], mesh.points[f[2]]);
    if (angle < smallest) smallest = angle, worst = t;
  }
  return worst;
}

const BorderCorner* inputCornerKept(const QualityMetrics& input, const BorderCorner& corner) {
  for (const BorderCorner& c : input.sharpCorners)
    if ((c.at - corner.at).norm() <= 1e-6 * std::min(c.shorterEdge, corner.shorterEdge))
      return corner.degrees >= c.degrees - kCornerSlackDegrees ? &c : nullptr;
  return nullptr;
}

bool meetsMinAngleBar(const QualityMetrics& result, const QualityMetrics& input) {
  if (result.minAngle >= kLeastMinAngle) return true;
  if (result.minAngleOffSharpCorners < kLeastMinAngle) return false;
  bool any = false;  // the smallest angle is at one of them
  for (const BorderCorner& corner : result.sharpCorners) {
    if (!filledByOneTriangle(corner)) continue;
    if (!inputCornerKept(input, corner)) return false;
    any = true;
  }
  return any;
}

int foldsAnew(const QualityMetrics& result, const QualityMetrics& input) {
  const auto inputsOwn = [&](const QualityMetrics::Fold& fold) {
    return std::any_of(input.folds.begin(), input.folds.end(), [&](const QualityMetrics::Fold& other) {
      return distanceToSegment(fold.middle(), other.from, other.to) <= 2 * fold.length();
    });
  };
  return static_cast<int>(std::count_if(result.folds.begin(), result.folds.end(),
                                        [&](const QualityMetrics::Fold& fold) { return !inputsOwn(fold); }));
}

int barsMet(const QualityMetrics& result, const QualityMetrics& input) {
  return (result.irregularBoundaryAware <= kMostIrregularPercent) + meetsMinAngleBar(result, input) +
         (result.avgMinAngle >= kLeastAvgMinAngle);
}

namespace {

// Each inside edge once, from the triangle where it runs from its smaller end to its larger
// (the other runs it back), its other triangle found among its smaller end's: no sort of all
// the edges, as measureQuality runs for every iteration the inspector shows.
std::vector<QualityMetrics::Fold> foldsOf(const Mesh& mesh, const Rings& rings) {
  std::vector<Vec3> normal(mesh.triangles.size(), Vec3::Zero());
  for (int f = 0; f < mesh.faceCount(); ++f) {
    const Vec3 n = faceNormal(mesh, mesh.triangles[f]);
    if (n.norm() > 0) normal[f] = n.normalized();
  }
  const double cosFold = std::cos(kFoldDegrees * M_PI / 180.0);
  std::vector<QualityMetrics::Fold> folded;
  for (int f = 0; f < mesh.faceCount(); ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = mesh.triangles[f][k], b = mesh.triangles[f][(k + 1) % 3];
      if (a > b) continue;
      for (int i = rings.offset[a]; i < rings.offset[a + 1]; ++i) {
        const Triangle& g = mesh.triangles[rings.faces[i]];
        if (rings.faces[i] != f && std::find(g.begin(), g.end(), b) != g.end()) {
          if (normal[f].dot(normal[rings.faces[i]]) < cosFold)
            folded.push_back({mesh.points[a], mesh.points[b]});
          break;
        }
      }
    }
  return folded;
}

// The shorter of the border edges at `v` (edges of one triangle), from its own triangles.
double shorterBorderEdge(const Mesh& mesh, const Rings& rings, int v) {
  std::map<int, int> uses;  // the other end of each edge at v: its triangles
  for (int i = rings.offset[v]; i < rings.offset[v + 1]; ++i)
    for (int w : mesh.triangles[rings.faces[i]])
      if (w != v) ++uses[w];
  double shorter = std::numeric_limits<double>::infinity();
  for (const auto& [w, count] : uses)
    if (count == 1) shorter = std::min(shorter, (mesh.points[w] - mesh.points[v]).norm());
  return shorter;
}

}  // namespace

std::vector<VertexValence> vertexValences(const Mesh& mesh) {
  const VertexEdges edges = vertexEdges(mesh);
  std::vector<VertexValence> valences(mesh.points.size());
  for (size_t v = 0; v < valences.size(); ++v) valences[v] = {edges.valence[v], edges.onBoundary[v]};
  return valences;
}

namespace {

// The next vertex along the border from `v`, in the faces' orientation: the end of the edge
// leaving v that no triangle runs back; -1 where none does.
int nextOnBorder(const Mesh& mesh, const Rings& rings, int v) {
  const auto after = [&](const Triangle& t, int shift) {
    const int k = static_cast<int>(std::find(t.begin(), t.end(), v) - t.begin());
    return t[(k + shift) % 3];
  };
  for (int i = rings.offset[v]; i < rings.offset[v + 1]; ++i) {
    const int to = after(mesh.triangles[rings.faces[i]], 1);
    bool back = false;  // a triangle running to -> v
    for (int j = rings.offset[v]; j < rings.offset[v + 1] && !back; ++j)
      back = after(mesh.triangles[rings.faces[j]], 2) == to;
    if (!back) return to;
  }
  return -1;
}

// Sets m's minAngleHole... where `worst` touches a border loop shorter than kPinholeOfMeanEdge of
// the mean edge. Each loop is followed only as far as that: the inspector measures every
// iteration it shows, and a sort of all the edges there slowed its scrubbing.
void findPinholeAt(const Mesh& mesh, const Rings& rings, const Triangle& worst, const std::vector<bool>& boundary,
                   QualityMetrics& m) {
  if (std::none_of(worst.begin(), worst.end(), [&](int v) { return boundary[v]; })) return;
  m.meanEdge = meanEdgeLength(mesh);
  for (int start : worst) {
    if (!boundary[start]) continue;
    double length = 0;
    int edges = 0, v = start;
    do {
      const int next = nextOnBorder(mesh, rings, v);
      if (next < 0) break;
      length += (mesh.points[next] - mesh.points[v]).norm();
      ++edges;
      v = next;
    } while (v != start && length < kPinholeOfMeanEdge * m.meanEdge && edges < mesh.vertexCount());
    if (v == start && edges > 0 && length < kPinholeOfMeanEdge * m.meanEdge) {
      m.minAngleHoleEdges = edges;
      m.minAngleHoleLength = length;
      return;
    }
  }
}

}  // namespace

QualityMetrics measureQuality(const Mesh& mesh) {
  QualityMetrics m;
  m.vertices = mesh.vertexCount();
  m.faces = mesh.faceCount();
  if (mesh.triangles.empty()) return m;

  const VertexEdges edges = vertexEdges(mesh);
  const std::vector<int>& valence = edges.valence;
  const std::vector<bool>& boundary = edges.onBoundary;
  int irregular = 0, irregularAware = 0, used = 0;
  for (size_t v = 0; v < valence.size(); ++v) {
    if (valence[v] == 0) continue;
    ++used;
    if (boundary[v]) ++m.boundaryVertices;
    if (valence[v] != 6) ++irregular;
    if (VertexValence{valence[v], boundary[v]}.irregular()) ++irregularAware;
  }
  m.irregularPercent = 100.0 * irregular / used;
  m.irregularBoundaryAware = 100.0 * irregularAware / used;

  m.minAngle = 180;
  double sumMin = 0;
  int under30 = 0;
  std::vector<double> angleSum(mesh.points.size(), 0.0);
  std::vector<std::array<double, 3>> cornerAngles;
  cornerAngles.reserve(mesh.triangles.size());
  for (const Triangle& t : mesh.triangles) {
    const auto angles = cornerAnglesDeg(mesh.points[t[0]], mesh.points[t[1]], mesh.points[t[2]]);
    cornerAngles.push_back(angles);
    for (int k = 0; k < 3; ++k) angleSum[t[k]] += angles[k];
    const double lo = *std::min_element(angles.begin(), angles.end());
    m.minAngle = std::min(m.minAngle, lo);
    m.maxAngle = std::max(m.maxAngle, *std::max_element(angles.begin(), angles.end()));
    sumMin += lo;
    if (lo < 30.0) ++under30;
    for (double a : angles) ++m.angleHistogram[std::clamp(static_cast<int>(a / 10.0), 0, 17)];
  }
  m.avgMinAngle = sumMin / mesh.faceCount();
  m.percentUnder30 = 100.0 * under30 / mesh.faceCount();
  double defects = 0, onBorder = 0;  // in units of 60 degrees
  for (size_t v = 0; v < angleSum.size(); ++v)
    if (valence[v] > 0) {
      const double defect = std::abs((boundary[v] ? 180.0 : 360.0) - angleSum[v]) / 60.0;
      defects += defect;
      if (boundary[v]) onBorder += defect;
    }
  m.curvatureDefects = 100.0 * defects / used;
  m.curvatureDefectsOnBorder = 100.0 * onBorder / used;
  const Rings rings(mesh);
  std::vector<bool> filledCorner(mesh.points.size(), false);  // filledByOneTriangle
  for (size_t v = 0; v < angleSum.size(); ++v) {
    if (!boundary[v]) continue;
    m.sharpestBorderCorner = std::min(m.sharpestBorderCorner, angleSum[v]);
    if (angleSum[v] >= kSharpCornerDegrees) continue;
    const BorderCorner corner{mesh.points[v], angleSum[v], rings.offset[v + 1] - rings.offset[v],
                              shorterBorderEdge(mesh, rings, static_cast<int>(v))};
    filledCorner[v] = filledByOneTriangle(corner);
    m.sharpCorners.push_back(corner);
  }
  std::sort(m.sharpCorners.begin(), m.sharpCorners.end(),
            [](const BorderCorner& a, const BorderCorner& b) { return a.degrees < b.degrees; });
  m.minAngleOffSharpCorners = 180;
  for (int f = 0; f < m.faces; ++f)
    for (int k = 0; k < 3; ++k)
      if (!filledCorner[mesh.triangles[f][k]])
        m.minAngleOffSharpCorners = std::min(m.minAngleOffSharpCorners, cornerAngles[f][k]);
  m.folds = foldsOf(mesh, rings);
  if (m.minAngle < kLeastMinAngle) {  // the one "Pin the worst triangle" pins
    const int worst = worstTriangle(mesh);
    const auto& angles = cornerAngles[worst];
    const int corner = mesh.triangles[worst][std::min_element(angles.begin(), angles.end()) - angles.begin()];
    m.minAngleAt = mesh.points[corner];
    if (!boundary[corner] && angleSum[corner] < 3 * kLeastMinAngle) m.minAngleTipSum = angleSum[corner];
    findPinholeAt(mesh, rings, mesh.triangles[worst], boundary, m);
  }
  return m;
}

namespace {

// Metro's sampling: every vertex, every edge's midpoint, and area-weighted random points, each
// with a triangle it lies on (a vertex's or an edge's: one of them). The random numbers are
// drawn in order, and the triangle each point falls in is found in parallel (a binary search
// per point: most of the sampling's time on a large input).
struct Samples {
  std::vector<Vec3> points;
  std::vector<int> triangle;
  size_t firstRandom = 0;  // the area-weighted ones are the last
};

Samples samplePoints(const Mesh& mesh, int randomCount) {
  Samples samples;
  samples.points = mesh.points;
  samples.triangle.assign(mesh.points.size(), 0);
  std::vector<double> cumulative;
  cumulative.reserve(mesh.triangles.size());
  double total = 0;
  for (size_t f = 0; f < mesh.triangles.size(); ++f) {
    const Triangle& t = mesh.triangles[f];
    for (int v : t) samples.triangle[v] = static_cast<int>(f);
    total += triangleArea(mesh.points[t[0]], mesh.points[t[1]], mesh.points[t[2]]);
    cumulative.push_back(total);
  }
  // Each edge once, the border's too (taken where a triangle ran it from its smaller end, half
  // of the border's edges were never sampled).
  for (const MeshEdge& e : uniqueEdges(mesh)) {
    samples.points.push_back(0.5 * (mesh.points[e.from] + mesh.points[e.to]));
    samples.triangle.push_back(e.triangle);
  }
  std::mt19937_64 rng(12345);
  auto uniform01 = [&] { return (rng() >> 11) * 0x1.0p-53; };
  std::vector<std::array<double, 3>> draws(randomCount);  // where in the area, then where in the triangle
  for (auto& draw : draws) draw = {uniform01() * total, uniform01(), uniform01()};
  samples.firstRandom = samples.points.size();
  samples.points.resize(samples.firstRandom + draws.size());
  samples.triangle.resize(samples.points.size());
  parallelFor(draws.size(), std::max(1u, std::thread::hardware_concurrency()), [&](size_t begin, size_t end) {
    for (size_t i = begin; i < end; ++i) {
      const auto [at, s, t] = draws[i];
      const size_t f = pickByShare(cumulative, at);
      const Triangle& corners = mesh.triangles[f];
      samples.points[samples.firstRandom + i] =
          pointInTriangle(mesh.points[corners[0]], mesh.points[corners[1]], mesh.points[corners[2]], s, t);
      samples.triangle[samples.firstRandom + i] = static_cast<int>(f);
    }
  });
  return samples;
}

// The farthest sample of `from` from the surface `to`, and the summed squared distances of the
// area-weighted samples (those alone: the vertices and edges would weigh a finer part more).
struct OneSided {
  double maxSquared = 0, sumSquared = 0;
  Vec3 farthest = Vec3::Zero();
  int count = 0, areaCount = 0;
};

// The triangles to search for the farthest point: those holding the farthest samples.
constexpr int kTrianglesSearched = 64;

// The point of triangle t farthest from `to`, as far as a grid and a climb from its best point
// find it: the distance peaks between samples (on the mushroom at 1000 vertices, 1.055% of the
// diagonal at the farthest of 30,000 samples, 1.163% at the point between them).
OneSided climbToFarthest(const Mesh& from, const Triangle& t, const Vec3& farthestSample, const SurfaceProjection& to) {
  const Vec3 &p0 = from.points[t[0]], e1 = from.points[t[1]] - p0, e2 = from.points[t[2]] - p0;
  Vec3 near = to.closestPoint(farthestSample);  // each search starts from the point found before
  const auto squaredAt = [&](double a, double b) { return to.squaredDistance(p0 + a * e1 + b * e2, near); };
  // From the triangle's farthest sample, or a grid point farther still.
  Eigen::Matrix2d gram;
  gram << e1.dot(e1), e1.dot(e2), e1.dot(e2), e2.dot(e2);
  const Eigen::Vector2d ab = gram.ldlt().solve(Eigen::Vector2d(e1.dot(farthestSample - p0), e2.dot(farthestSample - p0)));
  double bestA = std::clamp(ab.x(), 0.0, 1.0), bestB = std::clamp(ab.y(), 0.0, 1.0 - bestA);
  double best = squaredAt(bestA, bestB);
  constexpr int kGrid = 8;
  for (int i = 0; i <= kGrid; ++i)
    for (int j = 0; i + j <= kGrid; ++j)
      if (const double d = squaredAt(double(i) / kGrid, double(j) / kGrid); d > best) {
        best = d;
        bestA = double(i) / kGrid;
        bestB = double(j) / kGrid;
      }
  // Pattern search in the triangle's barycentric plane, the step halved where no move gains;
  // twelve directions, so that a ridge of the distance (equidistant from two parts of the
  // other surface) leaves one of them uphill.
  constexpr double kSteps[12][2] = {{1, 0}, {-1, 0}, {0, 1},  {0, -1}, {1, -1}, {-1, 1},
                                    {2, -1}, {-2, 1}, {1, 1}, {-1, -1}, {1, -2}, {-1, 2}};
  for (double step = 0.5 / kGrid, rounds = 0; step > 1e-4 / kGrid && rounds < 200; ++rounds) {
    bool moved = false;
    for (const auto& s : kSteps) {
      const double a = bestA + step * s[0], b = bestB + step * s[1];
      if (a < 0 || b < 0 || a + b > 1) continue;
      if (const double d = squaredAt(a, b); d > best) {
        best = d;
        bestA = a;
        bestB = b;
        moved = true;
      }
    }
    if (!moved) step /= 2;
  }
  OneSided farthest;
  farthest.maxSquared = best;
  farthest.farthest = p0 + bestA * e1 + bestB * e2;
  return farthest;
}

// Area-weighted samples of `from`: 10,000 and ten per triangle, but twenty per triangle of `to`
// at most (twice ten: two surfaces of about one size keep all of theirs). Against `to` the
// distance varies at the scale of `to`'s triangles; `from`'s own vertices and edges are sampled
// however fine it is, and the climb finds the peak between samples. (The edges stay: a thin
// triangle across a hole of `to`, its corners on `to`, has no area for random points, and is
// farthest at its long edge's midpoint.) A 500-vertex result against a 25,905-vertex face scan:
// 652,000 samples -> 154,000, the Hausdorff distance the same, RMS 1.7% lower (0.1566 -> 0.1539%).
int randomSampleCount(int fromFaces, int toFaces) {
  return 10000 + 10 * std::min(fromFaces, 2 * toFaces);
}

OneSided oneSided(const Mesh& from, const SurfaceProjection& to, int toFaces) {
  const Samples samples = samplePoints(from, randomSampleCount(from.faceCount(), toFaces));
  const std::vector<double> squared = to.squaredDistances(samples.points);
  OneSided all;
  all.count = static_cast<int>(samples.points.size());
  all.areaCount = static_cast<int>(samples.points.size() - samples.firstRandom);
  // Each triangle's farthest sample (a vertex counts for all of its triangles).
  std::vector<double> triangleMax(from.triangles.size(), -1.0);
  std::vector<Vec3> farthestSample(from.triangles.size());
  const auto offer = [&](int f, const Vec3& p, double d) {
    if (d > triangleMax[f]) {
      triangleMax[f] = d;
      farthestSample[f] = p;
    }
  };
  for (size_t i = 0; i < samples.points.size(); ++i) {
    if (squared[i] > all.maxSquared) {
      all.maxSquared = squared[i];
      all.farthest = samples.points[i];
    }
    if (i >= samples.firstRandom) all.sumSquared += squared[i];
    offer(samples.triangle[i], samples.points[i], squared[i]);
  }
  for (size_t f = 0; f < from.triangles.size(); ++f)
    for (int v : from.triangles[f]) offer(static_cast<int>(f), from.points[v], squared[v]);
  std::vector<int> order(from.triangles.size());
  std::iota(order.begin(), order.end(), 0);
  const size_t searched = std::min<size_t>(kTrianglesSearched, order.size());
  std::partial_sort(order.begin(), order.begin() + searched, order.end(),
                    [&](int a, int b) { return triangleMax[a] > triangleMax[b] || (triangleMax[a] == triangleMax[b] && a < b); });
  std::vector<OneSided> climbed(searched);
  parallelFor(searched, std::max(1u, std::thread::hardware_concurrency()), [&](size_t begin, size_t end) {
    for (size_t k = begin; k < end; ++k) climbed[k] = climbToFarthest(from, from.triangles[order[k]], farthestSample[order[k]], to);
  });
  for (const OneSided& c : climbed)  // in a fixed order: the point found does not depend on timing
    if (c.maxSquared > all.maxSquared) {
      all.maxSquared = c.maxSquared;
      all.farthest = c.farthest;
    }
  return all;
}

double meanBorderEdge(const Mesh& m) {
  double length = 0;
  size_t edges = 0;
  for (const std::vector<int>& loop : analyzeTopology(m).boundaryLoops) {
    length += loopLength(m, loop);
    edges += loop.size();
  }
  return edges > 0 ? length / edges : 0.0;
}

// A corner is cut where it is also farther than this many of the result's border edges
// (on a flat surface nothing else strays at all: the chords of a lens's curved sides cut its
// arcs by 0.001 of an edge).
constexpr double kCutOffStray = 0.03;
// Where the input's border is coarse, all its vertices are kept: corners kept only where the
// result cut them move the samples between, and those cut the next ones (the saddle at 1000
// vertices: 0.134 -> 0.068%, all of its rim's vertices: 0.043%). Coarse: both border edges at
// least this many of the result's mean border edge, as far apart as core/sites keeps corners.
constexpr double kCoarseBorder = 0.7;

double largest(const std::vector<double>& values) {
  return values.empty() ? 0.0 : *std::max_element(values.begin(), values.end());
}
}  // namespace

std::vector<Vec3> borderCornersCut(const Mesh& result, const SearchableSurface& input) {
  if (result.triangles.empty() || input.mesh.triangles.empty()) return {};
  // The border first: on most inputs nothing there strays, and nothing else is measured. A
  // convex corner cut off is an input border vertex far from the result; a reflex one, the
  // result's border chord across it, far from the input.
  const std::vector<bool> onBorder = vertexEdges(input.mesh).onBoundary;
  std::vector<Vec3> borderPoints, insidePoints;
  for (int v = 0; v < input.mesh.vertexCount(); ++v)
    (onBorder[v] ? borderPoints : insidePoints).push_back(input.mesh.points[v]);
  std::set<std::pair<int, int>> resultBorder;
  std::vector<Vec3> borderChords;
  for (const std::vector<int>& loop : analyzeTopology(result).boundaryLoops)
    for (size_t i = 0; i < loop.size(); ++i) {
      const int a = loop[i], b = loop[(i + 1) % loop.size()];
      resultBorder.insert(std::minmax(a, b));
      borderChords.push_back((result.points[a] + result.points[b]) / 2);
    }
  const SurfaceProjection toResult(result);
  const double border = std::max(largest(toResult.squaredDistances(borderPoints)),
                                 largest(input.projection.squaredDistances(borderChords)));
  const double spacing = meanBorderEdge(result);
  if (!(border > kCutOffStray * kCutOffStray * spacing * spacing)) return {};
  // Then the input's other vertices, and last the result's other chords, each only where the
  // border still strays farther than kCutOffBy times what was found.
  double elsewhere = largest(toResult.squaredDistances(insidePoints));
  if (!(border > kCutOffBy * kCutOffBy * elsewhere)) return {};
  std::vector<Vec3> chordPoints;
  for (const Triangle& t : result.triangles)
    chordPoints.push_back((result.points[t[0]] + result.points[t[1]] + result.points[t[2]]) / 3);
  for (const MeshEdge& e : uniqueEdges(result))
    if (!resultBorder.count({e.from, e.to})) chordPoints.push_back((result.points[e.from] + result.points[e.to]) / 2);
  elsewhere = std::max(elsewhere, largest(input.projection.squaredDistances(chordPoints)));
  if (!(border > kCutOffBy * kCutOffBy * elsewhere)) return {};
  const Rings rings(input.mesh);
  std::vector<Vec3> cutOff;
  for (int v = 0; v < input.mesh.vertexCount(); ++v)
    if (onBorder[v] && shorterBorderEdge(input.mesh, rings, v) >= kCoarseBorder * spacing)
      cutOff.push_back(input.mesh.points[v]);
  return cutOff;
}

Fidelity measureFidelity(const Mesh& mesh, const Mesh& reference) {
  if (mesh.triangles.empty() || reference.triangles.empty()) return Fidelity{};
  return measureFidelity(mesh, SearchableSurface(reference));
}

Fidelity measureFidelity(const Mesh& mesh, const SearchableSurface& reference) {
  Fidelity f;
  if (mesh.triangles.empty() || reference.mesh.triangles.empty()) return f;
  const OneSided fromMesh = oneSided(mesh, reference.projection, reference.mesh.faceCount()),
                 fromReference = oneSided(reference.mesh, SurfaceProjection(mesh), mesh.faceCount());
  const double diagonal = boundingBoxDiagonal(reference.mesh);
  f.samples = fromMesh.count + fromReference.count;
  f.farthestOnReference = fromReference.maxSquared > fromMesh.maxSquared;
  const OneSided& worst = f.farthestOnReference ? fromReference : fromMesh;
  f.farthestPoint = worst.farthest;
  f.hausdorffPercent = 100.0 * std::sqrt(worst.maxSquared) / diagonal;
  // Metro's RMS distance is one-sided, over the area: the larger of the two, as the Hausdorff
  // distance is the larger of its two.
  f.rmsPercent = 100.0 * std::sqrt(std::max(fromMesh.sumSquared / fromMesh.areaCount,
                                            fromReference.sumSquared / fromReference.areaCount)) / diagonal;
  return f;
}

}  // namespace lloydscope
