#include "flips.h"
#include "last_steps.h"
#include "lloyd.h"
#include "metrics.h"
#include "pipeline.h"
#include "parameterization.h"
#include "sites.h"
#include "mesh_io.h"
#include "polish.h"
#include "projection.h"
#include "test_support.h"
#include "topology.h"

#include <cmath>
#include <functional>
#include <map>
#include <numeric>
#include <random>

using namespace lloydscope;

namespace {

double angleAt(const Vec3& apex, const Vec3& p, const Vec3& q) {
  const Vec3 u = p - apex, v = q - apex;
  return std::atan2(u.cross(v).norm(), u.dot(v));
}

// The largest sum of the two angles facing an interior edge.
double worstOppositeAngles(const Mesh& m) {
  std::map<std::pair<int, int>, int> opposite;  // directed edge -> the vertex facing it
  for (const Triangle& t : m.triangles)
    for (int k = 0; k < 3; ++k) opposite[{t[k], t[(k + 1) % 3]}] = t[(k + 2) % 3];
  double worst = 0;
  for (const auto& [edge, c] : opposite) {
    const auto other = opposite.find({edge.second, edge.first});
    if (other == opposite.end()) continue;
    const Vec3 &a = m.points[edge.first], &b = m.points[edge.second];
    worst = std::max(worst, angleAt(m.points[c], a, b) + angleAt(m.points[other->second], a, b));
  }
  return worst;
}

}  // namespace

TEST(Polish, FlipsTheBadDiagonalOfAThinQuad) {
  Mesh m;
  m.points = {{0, 0, 0}, {2, 0, 0}, {1, 0.2, 0}, {1, -0.2, 0}};
  m.triangles = {{0, 1, 2}, {1, 0, 3}};
  EXPECT_EQ(flipToDelaunay(m), 1);
  EXPECT_NO_THROW(validateMesh(m, "quad"));
  for (const Triangle& t : m.triangles) {
    const Vec3 n = (m.points[t[1]] - m.points[t[0]]).cross(m.points[t[2]] - m.points[t[0]]);
    EXPECT_GT(n.z(), 0);  // still facing up
  }
  EXPECT_EQ(flipToDelaunay(m), 0);  // and then it is Delaunay
}

TEST(Polish, AfterFlipsEveryInteriorEdgeIsDelaunay) {
  Mesh m = test::grid(12);
  std::mt19937 random(3);
  std::uniform_real_distribution<double> jitter(-0.03, 0.03);
  for (Vec3& p : m.points)
    if (p.x() > 0 && p.x() < 1 && p.y() > 0 && p.y() < 1) p += Vec3(jitter(random), jitter(random), 0);
  for (size_t f = 0; f + 1 < m.triangles.size(); f += 4) {  // some diagonals the other way
    const Triangle a = m.triangles[f], b = m.triangles[f + 1];  // (i,j),(i+1,j),(i+1,j+1) / (i,j),(i+1,j+1),(i,j+1)
    m.triangles[f] = {a[0], a[1], b[2]};
    m.triangles[f + 1] = {a[1], a[2], b[2]};
  }
  ASSERT_NO_THROW(validateMesh(m, "grid"));
  ASSERT_GT(worstOppositeAngles(m), M_PI + 1e-6);
  EXPECT_GT(flipToDelaunay(m), 0);
  EXPECT_NO_THROW(validateMesh(m, "flipped"));
  EXPECT_TRUE(analyzeTopology(m).isDisk());
  EXPECT_LE(worstOppositeAngles(m), M_PI + 1e-6);
}

// Sites drawn at random from the density (no Lloyd at all), retriangulated: a rough mesh on
// the bumpy disk for the polish to work on.
struct RoughMesh {
  Mesh input;
  Parameterization param;
  Domain domain;
  LiftedMesh lifted;
};

RoughMesh roughMesh() {
  Mesh input = readMesh(test::assetPath("bumpy_disk.off")).mesh;
  Parameterization param = parameterize(input, {}, "bumpy");
  Domain domain(param.uv, input.triangles, areaDensity(input, param.uv));
  const InitialSites sites = initialSites(input, param, domain, {});
  LiftedMesh lifted = retriangulate(input, domain, sites.fixed, sites.movable, "test");
  return {std::move(input), std::move(param), std::move(domain), std::move(lifted)};
}

TEST(Polish, KeepsTheBorderAndTheSurfaceAndRaisesTheAngles) {
  RoughMesh r = roughMesh();
  LiftedMesh polished = r.lifted;
  polish(polished, {r.input, r.domain}, {}, {});
  const Mesh& before = r.lifted.mesh;
  const Mesh& after = polished.mesh;
  ASSERT_EQ(after.vertexCount(), before.vertexCount());
  EXPECT_NO_THROW(validateMesh(after, "polished"));
  const Topology topology = analyzeTopology(after);
  ASSERT_TRUE(topology.isDisk());
  // The border's vertices stay on the domain's border: where they were, or slid along it.
  std::vector<std::pair<Vec2, Vec2>> domainBorder;
  for (size_t t = 0; t < r.domain.triangles().size(); ++t)
    for (int k = 0; k < 3; ++k)
      if (r.domain.neighbours()[t][k] < 0)
        domainBorder.emplace_back(r.domain.uv()[r.domain.triangles()[t][(k + 1) % 3]],
                                  r.domain.uv()[r.domain.triangles()[t][(k + 2) % 3]]);
  for (int v : topology.boundaryLoops[0]) {
    double nearest = 1;
    for (const auto& [a, b] : domainBorder) {
      const Vec2 ab = b - a;
      const double t = std::clamp((polished.uv[v] - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
      nearest = std::min(nearest, (a + t * ab - polished.uv[v]).norm());
    }
    EXPECT_LT(nearest, 1e-9) << v;
  }
  // Every vertex is still the lift of its parameter point: on the input surface.
  for (int v = 0; v < after.vertexCount(); ++v)
    EXPECT_LT((after.points[v] - lift(r.input, r.domain, polished.uv[v])).norm(), 1e-9);
  const QualityMetrics q0 = measureQuality(before), q1 = measureQuality(after);
  EXPECT_GT(q1.minAngle, q0.minAngle + 10);
  EXPECT_GT(q1.avgMinAngle, q0.avgMinAngle + 5);
  EXPECT_LT(q1.irregularBoundaryAware, q0.irregularBoundaryAware);
}

TEST(Polish, EveryTargetRelaxes) {
  RoughMesh r = roughMesh();
  const double rough = measureQuality(r.lifted.mesh).avgMinAngle;
  for (PolishTarget target : {PolishTarget::Voronoi, PolishTarget::Centroid, PolishTarget::Circumcenter}) {
    LiftedMesh m = r.lifted;
    polish(m, {r.input, r.domain}, {}, {5, target});
    EXPECT_GT(measureQuality(m.mesh).avgMinAngle, rough + 5) << toString(target);
  }
  EXPECT_EQ(parsePolishTarget("circumcenter"), PolishTarget::Circumcenter);
  EXPECT_THROW(parsePolishTarget("middle"), Error);
}
TEST(Polish, KeepsVerticesOnTheSurfaceItIsGiven) {
  // A map that lifts every point 1 above the input: the polish must place vertices there.
  RoughMesh r = roughMesh();
  SurfaceMap raised{r.input, r.domain, [&](const Location& l) {
    const Triangle& t = r.input.triangles[l.triangle];
    return Vec3(l.weights[0] * r.input.points[t[0]] + l.weights[1] * r.input.points[t[1]] +
                l.weights[2] * r.input.points[t[2]] + Vec3(0, 0, 1));
  }};
  LiftedMesh m = r.lifted;
  for (int v = 0; v < m.mesh.vertexCount(); ++v) m.mesh.points[v] = raised.at(r.domain.locate(m.uv[v]));
  polish(m, raised, {}, {});
  for (int v = 0; v < m.mesh.vertexCount(); ++v)
    EXPECT_LT((m.mesh.points[v] - raised.at(r.domain.locate(m.uv[v]))).norm(), 1e-9);
}

// The quality of the rough mesh polished with `options`.
QualityMetrics polished(const RoughMesh& r, const PolishOptions& options) {
  LiftedMesh m = r.lifted;
  polish(m, {r.input, r.domain}, {}, options);
  return measureQuality(m.mesh);
}

TEST(Polish, AngleRepairLiftsTheSmallestAngle) {
  const RoughMesh r = roughMesh();
  PolishOptions without;  // one relaxation pass, nothing else: small angles are left
  without.iterations = 1;
  without.valencePasses = 0;
  without.repairPasses = 0;
  PolishOptions with = without;
  with.repairPasses = 3;
  const QualityMetrics a = polished(r, without), b = polished(r, with);
  EXPECT_GT(b.minAngle, a.minAngle + 3);
  EXPECT_LT(b.percentUnder30, a.percentUnder30);
}

TEST(Polish, ValenceFlipsMakeMoreVerticesRegular) {
  const RoughMesh r = roughMesh();
  PolishOptions without;
  without.valencePasses = 0;
  without.repairPasses = 0;
  PolishOptions with = without;
  with.valencePasses = 2;
  const QualityMetrics a = polished(r, without), b = polished(r, with);
  EXPECT_LT(b.irregularBoundaryAware, a.irregularBoundaryAware - 3);
  EXPECT_GE(b.minAngle, std::min(30.0, a.minAngle) - 1e-9);
}

// Flips edge (a, b) of m: its two triangles (a, b, c) and (b, a, d) become (c, a, d), (d, b, c).
void flip(Mesh& m, int a, int b) {
  std::vector<size_t> faces;
  for (size_t f = 0; f < m.triangles.size(); ++f)
    if (std::count(m.triangles[f].begin(), m.triangles[f].end(), a) && std::count(m.triangles[f].begin(), m.triangles[f].end(), b))
      faces.push_back(f);
  ASSERT_EQ(faces.size(), 2u);
  auto third = [&](size_t f) {
    for (int v : m.triangles[f])
      if (v != a && v != b) return v;
    return -1;
  };
  // Which of the two has the edge as a -> b decides the orientation.
  const Triangle& t = m.triangles[faces[0]];
  const bool forward = (t[0] == a && t[1] == b) || (t[1] == a && t[2] == b) || (t[2] == a && t[0] == b);
  const int c = third(forward ? faces[0] : faces[1]), d = third(forward ? faces[1] : faces[0]);
  m.triangles[faces[0]] = {c, a, d};
  m.triangles[faces[1]] = {d, b, c};
}

// test::grid(n) with the diagonal of square (i, j) turned the other way: two of its corners
// lose a neighbour, two gain one.
Mesh gridWithOneDiagonalTurned(int n, int i, int j) {
  Mesh m = test::grid(n);
  auto at = [n](int x, int y) { return y * (n + 1) + x; };
  flip(m, at(i, j), at(i + 1, j + 1));
  return m;
}

TEST(Polish, LastValenceFlipsMakeVerticesRegularWhereNoAngleFallsUnder35) {
  const double regular = measureQuality(test::grid(6)).irregularBoundaryAware;
  Mesh m = gridWithOneDiagonalTurned(6, 2, 3);
  ASSERT_NO_THROW(validateMesh(m, "grid"));
  ASSERT_GT(measureQuality(m).irregularBoundaryAware, regular);
  EXPECT_GE(flipToRegularity(m), 1);
  EXPECT_NO_THROW(validateMesh(m, "flipped"));
  EXPECT_EQ(measureQuality(m).irregularBoundaryAware, regular);
  EXPECT_GE(measureQuality(m).minAngle, 45.0 - 1e-9);
  // Squares stretched 3:2: turning the diagonal back would leave angles of 33.7 degrees.
  Mesh stretched = gridWithOneDiagonalTurned(6, 2, 3);
  for (Vec3& p : stretched.points) p.x() *= 1.5;
  EXPECT_EQ(flipToRegularity(stretched), 0);
  EXPECT_GE(flipToRegularity(stretched, 30.0), 1);
}

// A 7 x 7 patch of equilateral triangles: vertex 7 i + j at (i + j / 2, j sqrt(3) / 2).
Mesh equilateralPatch() {
  Mesh m;
  auto at = [](int i, int j) { return 7 * i + j; };
  for (int i = 0; i < 7; ++i)
    for (int j = 0; j < 7; ++j) m.points.emplace_back(i + 0.5 * j, j * std::sqrt(3.0) / 2, 0.0);
  for (int j = 0; j < 6; ++j)
    for (int i = 0; i < 6; ++i) {
      m.triangles.push_back({at(i, j), at(i + 1, j), at(i, j + 1)});
      m.triangles.push_back({at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  return m;
}

// `m` with its inside vertices moved in x and y by up to `amount` each, at random.
Mesh jitteredInside(Mesh m, unsigned seed, double amount) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> jitter(-amount, amount);
  const std::vector<bool> border = vertexEdges(m).onBoundary;
  for (int v = 0; v < m.vertexCount(); ++v)
    if (!border[v]) m.points[v] += Vec3(jitter(rng), jitter(rng), 0.0);
  return m;
}

// The smallest angle of v's triangles (`rings` of m's triangles), and the mean of their
// smallest angles.
using Angles = std::pair<double, double>;
Angles smallestAnglesAround(const Mesh& m, const Rings& rings, int v) {
  double smallest = 180, mean = 0;
  for (int k = rings.offset[v]; k < rings.offset[v + 1]; ++k) {
    const Triangle& t = m.triangles[rings.faces[k]];
    const auto a = cornerAnglesDeg(m.points[t[0]], m.points[t[1]], m.points[t[2]]);
    smallest = std::min(smallest, std::min({a[0], a[1], a[2]}));
    mean += std::min({a[0], a[1], a[2]}) / (rings.offset[v + 1] - rings.offset[v]);
  }
  return {smallest, mean};
}

// Each inside vertex of `start` moved alone by `step` (given every other vertex to pin), on
// its own copy: `check` gets, for each vertex that moved, the smallestAnglesAround() it before
// and after. Returns how many moved.
int movedOneByOne(const Mesh& start, const Mesh& surface,
                  const std::function<int(Mesh&, const std::vector<int>&)>& step,
                  const std::function<void(int, Angles, Angles)>& check) {
  const std::vector<bool> border = vertexEdges(surface).onBoundary;
  const Rings rings(start);
  int moved = 0;
  for (int v = 0; v < start.vertexCount(); ++v) {
    if (border[v]) continue;
    std::vector<int> others;
    for (int w = 0; w < start.vertexCount(); ++w)
      if (w != v) others.push_back(w);
    Mesh m = start;
    if (step(m, others) == 0) continue;
    ++moved;
    check(v, smallestAnglesAround(start, rings, v), smallestAnglesAround(m, rings, v));
  }
  return moved;
}

// The patch with edges (8, 14) and (9, 15) flipped: inside, vertex 9 is left with valence 5
// and 16 with 7; on the border 7 with 5 and 14 with 3. The one flip left that lowers the
// valences' squared deviation from regular (by 2) makes one more vertex irregular; flipping
// both back makes the patch regular again.
Mesh patchWithTwoFlips() {
  Mesh m = equilateralPatch();
  flip(m, 8, 14);
  flip(m, 9, 15);
  return m;
}

TEST(Polish, LastValenceFlipsLeaveNoMoreIrregularVertices) {
  Mesh m = patchWithTwoFlips();
  ASSERT_NO_THROW(validateMesh(m, "patch"));
  const double before = measureQuality(m).irregularBoundaryAware;
  EXPECT_EQ(flipToRegularity(m, /*smallestAngle=*/0.0), 0);  // (its flips make 30 degrees)
  EXPECT_EQ(measureQuality(m).irregularBoundaryAware, before);
}

// What no single flip can do, two together do: the patch is regular again, and its vertices,
// jittered, relax on the surface where the flips were, but for the pinned one and the border.
TEST(Polish, RelaxedValenceMovesFlipTwoEdgesWhereOneWouldNotDo) {
  const Mesh surface = patchWithTwoFlips();
  Mesh m = jitteredInside(surface, 5, 0.05);
  const std::vector<bool> border = vertexEdges(m).onBoundary;
  const Mesh jittered = m;
  const QualityMetrics before = measureQuality(m);
  const int pinned = 15;
  EXPECT_EQ(relaxedValenceMoves(m, surface, {pinned}), 1);
  EXPECT_NO_THROW(validateMesh(m, "moved"));
  const QualityMetrics after = measureQuality(m);
  EXPECT_LT(after.irregularBoundaryAware, before.irregularBoundaryAware);
  for (int v = 0; v < m.vertexCount(); ++v)
    if (!border[v]) EXPECT_EQ(vertexEdges(m).valence[v], 6) << "vertex " << v;
  EXPECT_GE(after.minAngle, std::min(30.0, before.minAngle));
  EXPECT_GE(after.avgMinAngle, before.avgMinAngle);
  EXPECT_EQ(m.points[pinned], jittered.points[pinned]);
  int moved = 0;
  for (int v = 0; v < m.vertexCount(); ++v) {
    if (border[v]) EXPECT_EQ(m.points[v], jittered.points[v]);
    moved += m.points[v] != jittered.points[v];
    EXPECT_NEAR(m.points[v].z(), 0.0, 1e-12);
  }
  EXPECT_GT(moved, 4);
}

// The patch with `edges` flipped, one after the other.
Mesh patchWithFlips(std::initializer_list<std::pair<int, int>> edges) {
  Mesh m = equilateralPatch();
  for (auto [a, b] : edges) flip(m, a, b);
  EXPECT_NO_THROW(validateMesh(m, "patch"));
  return m;
}

// relaxedValenceMoves() on `m`, its own surface, makes every inside vertex regular, with no
// angle under 30 degrees.
void expectMovesMakeItRegular(Mesh m) {
  const Mesh surface = m;
  const std::vector<bool> border = vertexEdges(m).onBoundary;
  EXPECT_GE(relaxedValenceMoves(m, surface), 1);
  EXPECT_NO_THROW(validateMesh(m, "moved"));
  for (int v = 0; v < m.vertexCount(); ++v)
    if (!border[v]) EXPECT_EQ(vertexEdges(m).valence[v], 6) << "vertex " << v;
  EXPECT_GE(measureQuality(m).minAngle, 30.0);
}

// The patch with four edges of a row flipped, (9, 15), (10, 16), (11, 17) and (12, 18): two
// 5-7 pairs of valences inside, which no flip, nor any two or three together, makes more
// regular. The four flipped back, one after the other, make the patch regular again: the
// first three move a 5-7 pair along, the last cancels it.
TEST(Polish, RelaxedValenceMovesFlipFourEdgesWhereFewerWouldNotDo) {
  const Mesh surface = patchWithFlips({{9, 15}, {10, 16}, {11, 17}, {12, 18}});
  Mesh m = jitteredInside(surface, 5, 0.05);
  const std::vector<bool> border = vertexEdges(m).onBoundary;
  const QualityMetrics before = measureQuality(m);
  EXPECT_GE(relaxedValenceMoves(m, surface), 1);
  EXPECT_NO_THROW(validateMesh(m, "moved"));
  for (int v = 0; v < m.vertexCount(); ++v)
    if (!border[v]) EXPECT_EQ(vertexEdges(m).valence[v], 6) << "vertex " << v;
  const QualityMetrics after = measureQuality(m);
  EXPECT_LT(after.irregularBoundaryAware, before.irregularBoundaryAware);
  EXPECT_GE(after.minAngle, std::min(30.0, before.minAngle));
}

// The patch with four edges flipped, (38, 37), (32, 38), (33, 40) and (24, 31). The move that
// makes it regular again flips (38, 45), (31, 44), (25, 30) and (31, 39): after its second flip
// it leaves fewer vertices irregular already, but vertex 39 with valence 9, which no move may
// leave; the search has to go on past such a sequence to the fourth flip, which takes 39 back
// to 8, not end it there (and have it refused).
TEST(Polish, RelaxedValenceMovesSearchPastSequencesThatPushAVertexTooFar) {
  expectMovesMakeItRegular(patchWithFlips({{38, 37}, {32, 38}, {33, 40}, {24, 31}}));
}

// The patch with three edges flipped, (35, 36), (37, 31) and (28, 29). The sequence that
// starts by flipping (21, 22) and gains most ends by flipping (29, 30), which lowers the mean
// of the smallest angles around by 1.8 degrees and is refused; the next best from the same
// first flip ends by flipping (29, 42) instead, and is kept: with it the patch is regular again.
TEST(Polish, RelaxedValenceMovesTryTheNextSequenceWhereTheBestIsRefused) {
  expectMovesMakeItRegular(patchWithFlips({{35, 36}, {37, 31}, {28, 29}}));
}

// The same patch folded along its two flipped edges (their ends raised): flipping them back
// would cut the two ridges off, so nothing is moved, whether the vertices around may relax
// (then they are put back) or are all pinned (then only the distance check refuses). Flat,
// the same flips are made.
TEST(Polish, RelaxedValenceMovesCutNoRidgeOff) {
  Mesh surface = patchWithTwoFlips();
  for (int v : {8, 9, 14, 15}) surface.points[v].z() = 0.3;
  Mesh m = surface;
  EXPECT_EQ(relaxedValenceMoves(m, surface), 0);
  EXPECT_EQ(m.triangles, surface.triangles);
  for (int v = 0; v < m.vertexCount(); ++v) EXPECT_EQ(m.points[v], surface.points[v]) << "vertex " << v;
  std::vector<int> all(surface.vertexCount());
  std::iota(all.begin(), all.end(), 0);
  EXPECT_EQ(relaxedValenceMoves(m, surface, all), 0);
  EXPECT_EQ(m.triangles, surface.triangles);
  for (Vec3& p : surface.points) p.z() = 0;
  m = surface;
  EXPECT_EQ(relaxedValenceMoves(m, surface, all), 1);
}

// The patch's middle vertex, 24, pushed 0.6 of an edge towards vertex 31 (the input keeps it
// there too): its triangles' smallest angle is 23 degrees.
Mesh patchWithOneVertexPushed(double height) {
  Mesh m = equilateralPatch();
  m.points[24] += 0.6 * (m.points[31] - m.points[24]);
  m.points[24].z() = height;
  return m;
}

// On a flat surface the pushed vertex goes back to where every angle is about 60 degrees when
// it alone may move; its neighbours move too when they may; pinned vertices and the border stay.
TEST(Polish, RaiseSmallAnglesMovesAVertexWhereItsAnglesAreLargest) {
  const Mesh surface = patchWithOneVertexPushed(0.0);
  ASSERT_LT(measureQuality(surface).minAngle, 25.0);
  std::vector<int> all(surface.vertexCount());
  std::iota(all.begin(), all.end(), 0);
  Mesh m = surface;
  EXPECT_EQ(raiseSmallAngles(m, surface, all), 0);
  EXPECT_EQ(m.points, surface.points);
  EXPECT_GE(raiseSmallAngles(m, surface, {24}), 1);
  EXPECT_EQ(m.points[24], surface.points[24]);
  m = surface;
  std::vector<int> allBut24 = all;
  allBut24.erase(allBut24.begin() + 24);
  EXPECT_EQ(raiseSmallAngles(m, surface, allBut24), 1);
  EXPECT_GT(measureQuality(m).minAngle, 58.0);
  EXPECT_LT((m.points[24] - equilateralPatch().points[24]).norm(), 0.03);
  m = surface;
  EXPECT_GE(raiseSmallAngles(m, surface), 1);
  EXPECT_NO_THROW(validateMesh(m, "raised"));
  EXPECT_GT(measureQuality(m).minAngle, 50.0);
  const std::vector<bool> border = vertexEdges(m).onBoundary;
  for (int v = 0; v < m.vertexCount(); ++v) {
    if (border[v]) EXPECT_EQ(m.points[v], surface.points[v]);
    EXPECT_NEAR(m.points[v].z(), 0.0, 1e-12);
  }
}

// A vertex moved alone (the others pinned) on a jittered patch: its triangles' smallest angle
// rises, and their mean smallest angle falls by a quarter of a degree at most, though a
// larger smallest angle is often where the mean is lower.
TEST(Polish, RaiseSmallAnglesKeepsTheMeanSmallestAngle) {
  const Mesh flat = equilateralPatch();
  const int moved = movedOneByOne(
      jitteredInside(flat, 3, 0.3), flat,
      [&](Mesh& m, const std::vector<int>& others) { return raiseSmallAngles(m, flat, others, 180.0); },
      [](int v, Angles before, Angles after) {
        EXPECT_GT(after.first, before.first) << "vertex " << v;
        EXPECT_GE(after.second, before.second - 0.25 - 1e-9) << "vertex " << v;
      });
  EXPECT_GT(moved, 10);
}

// On a jittered flat patch: each vertex moved alone (the others pinned) raises its triangles'
// mean smallest angle and keeps their smallest; all together, the mesh's average smallest angle
// rises and its smallest does not fall; the border stays, and nothing moves where all is pinned.
TEST(Polish, RaiseMeanAnglesKeepsTheSmallestAngle) {
  const Mesh flat = equilateralPatch();
  const Mesh jittered = jitteredInside(flat, 7, 0.25);
  const std::vector<bool> border = vertexEdges(flat).onBoundary;
  const int moved = movedOneByOne(
      jittered, flat, [&](Mesh& m, const std::vector<int>& others) { return raiseMeanAngles(m, flat, others); },
      [](int v, Angles before, Angles after) {
        EXPECT_GT(after.second, before.second) << "vertex " << v;
        EXPECT_GE(after.first, before.first) << "vertex " << v;
      });
  EXPECT_GT(moved, 15);
  std::vector<int> all(flat.vertexCount());
  std::iota(all.begin(), all.end(), 0);
  Mesh m = jittered;
  EXPECT_EQ(raiseMeanAngles(m, flat, all), 0);
  EXPECT_EQ(m.points, jittered.points);
  EXPECT_GT(raiseMeanAngles(m, flat), 15);
  const QualityMetrics before = measureQuality(jittered), after = measureQuality(m);
  EXPECT_GT(after.avgMinAngle, before.avgMinAngle + 2);
  EXPECT_GE(after.minAngle, before.minAngle);
  for (int v = 0; v < m.vertexCount(); ++v) {
    if (border[v]) EXPECT_EQ(m.points[v], jittered.points[v]);
    EXPECT_NEAR(m.points[v].z(), 0.0, 1e-12);
  }
}

// The pushed vertex raised into a peak of the input: moving it down the slope, where its angles
// are larger, would cut the peak off, so it stays.
TEST(Polish, RaiseSmallAnglesCutsNoPeakOff) {
  const Mesh surface = patchWithOneVertexPushed(0.2);
  Mesh m = surface;
  EXPECT_EQ(raiseSmallAngles(m, surface), 0);
  EXPECT_EQ(m.points, surface.points);
}

// The patch folded along its middle row (vertices 3, 10, ... 45) into a fin 8 degrees thin:
// the faces around a vertex of the fold's edge face more than 84 degrees away from their mean
// normal, as around a vertex snapped onto a horn. Vertex 24, on the edge, slid 0.7 along it.
Mesh finWithAVertexSlid() {
  Mesh m = equilateralPatch();
  const double edgeY = m.points[24].y(), opening = 8.0 * M_PI / 180;
  for (Vec3& p : m.points) {
    const double t = p.y() - edgeY;  // across the fold, in the flat patch
    if (t > 0) p = Vec3(p.x(), edgeY - t * std::cos(opening), t * std::sin(opening));
  }
  m.points[24].x() += 0.7;
  return m;
}

// The vertex slid along the fin's edge goes back, close to the edge, though its ring is wider
// than a fold test against its mean normal lets any point pass (none would move it, before).
// The result is a little off the fin elsewhere (its corner 0 raised 0.05), as a remeshed surface
// is off its input: a move may take the chords that far from it.
TEST(Polish, RaiseSmallAnglesMovesAVertexOnTheEdgeOfAThinFin) {
  const Mesh fin = finWithAVertexSlid();
  const double before = measureQuality(fin).minAngle;
  ASSERT_LT(before, 25.0);
  std::vector<int> allBut24(fin.vertexCount());
  std::iota(allBut24.begin(), allBut24.end(), 0);
  allBut24.erase(allBut24.begin() + 24);
  Mesh m = fin;
  m.points[0].z() += 0.05;
  EXPECT_EQ(raiseSmallAngles(m, fin, allBut24), 1);
  EXPECT_GT(measureQuality(m).minAngle, before + 15);
  EXPECT_LT((m.points[24] - fin.points[24]).norm(), 0.7);
  EXPECT_LT(std::abs(m.points[24].y() - fin.points[24].y()) + std::abs(m.points[24].z()), 0.05);  // by the edge
}

// The patch with border vertex 1 (on its straight side from corner 0 through 1, 2, ... 6)
// moved to `length` of an edge from vertex 2: the border edge (1, 2) that short, and the
// triangle on it, (1, 8, 2), thin.
Mesh patchWithAShortBorderEdge(double length) {
  Mesh m = equilateralPatch();
  m.points[1] = m.points[2] + length * (m.points[1] - m.points[2]);
  return m;
}

// One end goes (merged into the other): a vertex fewer, the border's course and its other vertices
// kept, the smallest angle up; a pinned vertex keeps its place under its new number. With both
// ends pinned, nothing changes.
TEST(Polish, AShortBorderEdgeLosesAnEnd) {
  const Mesh surface = patchWithAShortBorderEdge(0.25);
  Mesh m = surface;
  const double before = measureQuality(m).minAngle;
  ASSERT_LT(before, 20.0);
  std::vector<int> pinned = {9, 24};  // 9: next to both ends, in the rings that relax
  EXPECT_EQ(collapseShortBorderEdges(m, surface, pinned), 1);
  EXPECT_NO_THROW(validateMesh(m, "collapsed"));
  EXPECT_TRUE(analyzeTopology(m).isDisk());
  EXPECT_EQ(m.vertexCount(), surface.vertexCount() - 1);
  EXPECT_GT(measureQuality(m).minAngle, before + 10);
  ASSERT_EQ(pinned, (std::vector<int>{8, 23}));
  EXPECT_EQ(m.points[8], surface.points[9]);
  EXPECT_EQ(m.points[23], surface.points[24]);
  const std::vector<bool> border = vertexEdges(m).onBoundary;
  for (int v = 0; v < m.vertexCount(); ++v) {
    const bool wasThere = std::count(surface.points.begin(), surface.points.end(), m.points[v]) == 1;
    if (border[v]) EXPECT_TRUE(wasThere) << "vertex " << v;
    EXPECT_NEAR(m.points[v].z(), 0.0, 1e-12);
  }
  Mesh kept = surface;
  std::vector<int> both = {1, 2};
  EXPECT_EQ(collapseShortBorderEdges(kept, surface, both), 0);
  EXPECT_EQ(kept.points, surface.points);
  EXPECT_EQ(kept.triangles, surface.triangles);
}

// The border bent at vertex 1 (pushed 0.6 of an edge outwards, across the border): merging
// either end of the short edge into the other would cut the bend off (0.6 and 0.5 edge lengths
// from the chord), so nothing is collapsed.
TEST(Polish, AShortBorderEdgeAtABendStays) {
  Mesh surface = patchWithAShortBorderEdge(0.25);
  surface.points[1] += 0.6 * Vec3(-std::sqrt(3.0) / 2, 0.5, 0.0);
  Mesh m = surface;
  std::vector<int> none;
  EXPECT_EQ(collapseShortBorderEdges(m, surface, none), 0);
  EXPECT_EQ(m.triangles, surface.triangles);
}

// A short border edge whose triangle is nearly as round as the others (vertex 8 moved half way
// to where (1, 8, 2) would be equilateral): with the inside pinned, either collapse lowers the
// smallest angle there (27.7 to 18.2 or 26.9 degrees), so neither is made.
TEST(Polish, AShortBorderEdgeStaysWhereItsCollapseLowersTheAngles) {
  Mesh surface = patchWithAShortBorderEdge(0.45);
  const Vec3 middle = 0.5 * (surface.points[1] + surface.points[2]);
  const Vec3 along = surface.points[2] - surface.points[1];
  const Vec3 apex = middle + std::sqrt(3.0) / 2 * Vec3(along.y(), -along.x(), 0.0);
  surface.points[8] = 0.5 * (surface.points[8] + apex);
  const std::vector<bool> border = vertexEdges(surface).onBoundary;
  std::vector<int> inside;
  for (int v = 0; v < surface.vertexCount(); ++v)
    if (!border[v]) inside.push_back(v);
  Mesh m = surface;
  EXPECT_EQ(collapseShortBorderEdges(m, surface, inside), 0);
  EXPECT_EQ(m.triangles, surface.triangles);
}

TEST(Polish, AFlatTriangleLosesAVertex) {
  // A square whose inside vertex X lies almost on the segment A C: triangle (A, C, X) is flat.
  Mesh m;
  m.points = {{0, 0, 0}, {0.5, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0.5, 1, 0}, {0, 1, 0},
              {0.3, 0.5, 0}, {0.7, 0.5, 0}, {0.5, 0.5005, 0}};
  enum { B0, M0, B1, B2, M2, B3, A, C, X };
  m.triangles = {{B0, M0, A}, {M0, C, A}, {M0, B1, C}, {C, B1, B2}, {M2, C, B2},
                 {X, C, M2},  {A, X, M2}, {A, C, X},  {B3, A, M2}, {B0, A, B3}};
  ASSERT_NO_THROW(validateMesh(m, "square"));
  ASSERT_LT(measureQuality(m).minAngle, 1.0);
  EXPECT_EQ(collapseFlatTriangles(m), 1);
  const Mesh merged = assemble(m.triangles, m.points);
  EXPECT_EQ(merged.vertexCount(), 8);
  EXPECT_NO_THROW(validateMesh(merged, "merged"));
  EXPECT_TRUE(analyzeTopology(merged).isDisk());
  EXPECT_GT(measureQuality(merged).minAngle, 10.0);
  EXPECT_EQ(collapseFlatTriangles(m), 0);  // nothing flat left
}

// Issue 6: the vertices of a stitched seam (here a jittered column of a flat grid) move on the
// surface and their triangles get rounder; the rest of the mesh stays where it was but for the
// seam's neighbours.
TEST(Polish, SeamVerticesRelaxOnTheSurfaceOnceStitched) {
  const Mesh surface = test::grid(8);
  Mesh m = surface;
  std::vector<bool> seam(m.vertexCount(), false);
  for (int j = 1; j < 8; ++j) {
    const int v = j * 9 + 4;
    seam[v] = true;
    m.points[v].x() += (j % 2 ? 0.3 : -0.3) / 8;
  }
  const double before = measureQuality(m).minAngle;
  polishSeams(m, seam, surface, 3);
  EXPECT_NO_THROW(validateMesh(m, "polished"));
  EXPECT_GT(measureQuality(m).minAngle, before + 5.0);
  for (const Vec3& p : m.points) EXPECT_NEAR(p.z(), 0.0, 1e-12);
  for (int v = 0; v < m.vertexCount(); ++v)
    if (std::abs(surface.points[v].x() - 0.5) > 0.3) EXPECT_EQ(m.points[v], surface.points[v]);
}

// A thin spike of the input (a horn's tip) between the result's vertices: the result cuts it
// off, and the Hausdorff distance is the spike's height. snapToTips() puts the nearest vertex on
// its tip; the result stays a valid mesh with the same vertices.
TEST(Polish, AVertexIsSnappedOntoATipTheResultCutOff) {
  Mesh input = test::grid(40);
  const int top = 20 * 41 + 20;  // (0.5, 0.5)
  input.points[top].z() = 0.3;
  Mesh result = test::grid(8);
  const double before = measureFidelity(result, input).hausdorffPercent;
  EXPECT_GE(snapToTips(result, input).size(), 1u);
  EXPECT_NO_THROW(validateMesh(result, "snapped"));
  EXPECT_EQ(result.vertexCount(), 81);
  const Vec3 tip = input.points[top];
  EXPECT_TRUE(std::any_of(result.points.begin(), result.points.end(),
                          [&](const Vec3& p) { return (p - tip).norm() < 1e-12; }));
  EXPECT_LT(measureFidelity(result, input).hausdorffPercent, 0.3 * before);
  // Every vertex is still on the input surface (the snapped one at its tip, the relaxed ones
  // around it by closest point).
  const SurfaceProjection surface(input);
  for (const Vec3& p : result.points) EXPECT_LT(surface.squaredDistance(p), 1e-20);
}

// A low bump (under an edge length from the result) is snapped to only where the triangles
// around keep their smallest angle at 30 degrees or more (the grid's is 45).
TEST(Polish, ASnapCloserThanAnEdgeLengthKeepsTheAngles) {
  Mesh input = test::grid(40);
  const int top = 20 * 41 + 20;  // (0.5, 0.5)
  input.points[top].z() = 0.1;   // the grid's edges are 0.125 and 0.177 long
  Mesh result = test::grid(8);
  const double before = measureFidelity(result, input).hausdorffPercent;
  EXPECT_EQ(snapToTips(result, input).size(), 1u);
  EXPECT_GE(measureQuality(result).minAngle, 30.0);
  EXPECT_LT(measureFidelity(result, input).hausdorffPercent, 0.5 * before);
}

// A result that already follows its input has no tip to snap to: it is left as it is.
TEST(Polish, NothingIsSnappedWhereTheResultFollowsTheInput) {
  const Mesh input = test::grid(8);
  Mesh result = input;
  EXPECT_TRUE(snapToTips(result, input).empty());
  EXPECT_EQ(result.points, input.points);
  EXPECT_EQ(result.triangles, input.triangles);
}

TEST(Polish, BorderVerticesSlideAlongTheBorderOutOfASharpCornersStrip) {
  // Sampled evenly into a 34-degree corner, the border makes a strip of triangles across the
  // wedge with a 25-degree angle next to the corner's ear: a border vertex slid towards the
  // corner makes it 34.
  const Mesh input = test::sector(34);
  const Parameterization param = parameterize(input, {}, "sector");
  const Domain domain(param.uv, input.triangles, {});
  SiteOptions sites;
  sites.count = 100;
  const InitialSites start = initialSites(input, param, domain, sites);
  LloydSolver solver(domain, start.fixed, start.movable, {});
  solver.run();
  const LiftedMesh relaxed = retriangulate(input, domain, start.fixed, solver.movableSites(), "sector");
  PolishOptions fixedBorder;
  fixedBorder.slideBorder = false;
  LiftedMesh slid = relaxed, kept = relaxed;
  polish(slid, {input, domain}, {}, {});
  polish(kept, {input, domain}, {}, fixedBorder);
  EXPECT_LT(measureQuality(kept.mesh).minAngle, 27);
  EXPECT_GT(measureQuality(slid.mesh).minAngle, 33.9);
  // The border's vertices are still on the sector's border, its corners where they were.
  const Topology topology = analyzeTopology(slid.mesh);
  ASSERT_TRUE(topology.isDisk());
  int moved = 0;
  for (int v : topology.boundaryLoops[0]) {
    const Vec3& p = slid.mesh.points[v];
    const double angle = std::atan2(p.y(), p.x()) * 180 / M_PI;
    const bool onSide = std::abs(angle) < 1e-6 || std::abs(angle - 34) < 1e-6 || p.norm() < 1e-12;
    const bool onArc = std::abs(p.norm() - 1) < 1e-3;  // the arc is a polygon of 12 sides
    EXPECT_TRUE(onSide || onArc) << v;
    moved += p != relaxed.mesh.points[v];
  }
  EXPECT_GT(moved, 0);
  for (const Vec3& corner : {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(std::cos(34 * M_PI / 180), std::sin(34 * M_PI / 180), 0)})
    EXPECT_TRUE(std::any_of(slid.mesh.points.begin(), slid.mesh.points.end(),
                            [&](const Vec3& p) { return (p - corner).norm() < 1e-12; }));
}
