#include "flips.h"
#include "last_steps.h"
#include "metrics.h"
#include "projection.h"
#include "ring_moves.h"
#include "test_support.h"
#include "topology.h"

#include <cmath>
#include <functional>
#include <numeric>
#include <random>

using namespace lloydscope;

// Every vertex of `m`, to pin them all.
std::vector<int> everyVertex(const Mesh& m) {
  std::vector<int> all(m.vertexCount());
  std::iota(all.begin(), all.end(), 0);
  return all;
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

// What no single flip can do, two together do: the patch is regular again, and its vertices,
// jittered, relax on the surface where the flips were, but for the pinned one and the border.
TEST(LastSteps, RelaxedValenceMovesFlipTwoEdgesWhereOneWouldNotDo) {
  const Mesh surface = test::patchWithTwoFlips();
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
TEST(LastSteps, RelaxedValenceMovesFlipFourEdgesWhereFewerWouldNotDo) {
  const Mesh surface = test::patchWithFlips({{9, 15}, {10, 16}, {11, 17}, {12, 18}});
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
TEST(LastSteps, RelaxedValenceMovesSearchPastSequencesThatPushAVertexTooFar) {
  expectMovesMakeItRegular(test::patchWithFlips({{38, 37}, {32, 38}, {33, 40}, {24, 31}}));
}

// The patch with three edges flipped, (35, 36), (37, 31) and (28, 29). The sequence that
// starts by flipping (21, 22) and gains most ends by flipping (29, 30), which lowers the mean
// of the smallest angles around by 1.8 degrees and is refused; the next best from the same
// first flip ends by flipping (29, 42) instead, and is kept: with it the patch is regular again.
TEST(LastSteps, RelaxedValenceMovesTryTheNextSequenceWhereTheBestIsRefused) {
  expectMovesMakeItRegular(test::patchWithFlips({{35, 36}, {37, 31}, {28, 29}}));
}

// The same patch folded along its two flipped edges (their ends raised): flipping them back
// would cut the two ridges off, so nothing is moved, whether the vertices around may relax
// (then they are put back) or are all pinned (then only the distance check refuses). Flat,
// the same flips are made.
TEST(LastSteps, RelaxedValenceMovesCutNoRidgeOff) {
  Mesh surface = test::patchWithTwoFlips();
  for (int v : {8, 9, 14, 15}) surface.points[v].z() = 0.3;
  Mesh m = surface;
  EXPECT_EQ(relaxedValenceMoves(m, surface), 0);
  EXPECT_EQ(m.triangles, surface.triangles);
  for (int v = 0; v < m.vertexCount(); ++v) EXPECT_EQ(m.points[v], surface.points[v]) << "vertex " << v;
  const std::vector<int> all = everyVertex(surface);
  EXPECT_EQ(relaxedValenceMoves(m, surface, all), 0);
  EXPECT_EQ(m.triangles, surface.triangles);
  for (Vec3& p : surface.points) p.z() = 0;
  m = surface;
  EXPECT_EQ(relaxedValenceMoves(m, surface, all), 1);
}

// The patch's middle vertex, 24, pushed 0.6 of an edge towards vertex 31 (the input keeps it
// there too): its triangles' smallest angle is 23 degrees.
Mesh patchWithOneVertexPushed(double height) {
  Mesh m = test::equilateralPatch();
  m.points[24] += 0.6 * (m.points[31] - m.points[24]);
  m.points[24].z() = height;
  return m;
}

// On a flat surface the pushed vertex goes back to where every angle is about 60 degrees when
// it alone may move; its neighbours move too when they may; pinned vertices and the border stay.
TEST(LastSteps, RaiseSmallAnglesMovesAVertexWhereItsAnglesAreLargest) {
  const Mesh surface = patchWithOneVertexPushed(0.0);
  ASSERT_LT(measureQuality(surface).minAngle, 25.0);
  const std::vector<int> all = everyVertex(surface);
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
  EXPECT_LT((m.points[24] - test::equilateralPatch().points[24]).norm(), 0.03);
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
TEST(LastSteps, RaiseSmallAnglesKeepsTheMeanSmallestAngle) {
  const Mesh flat = test::equilateralPatch();
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
TEST(LastSteps, RaiseMeanAnglesKeepsTheSmallestAngle) {
  const Mesh flat = test::equilateralPatch();
  const Mesh jittered = jitteredInside(flat, 7, 0.25);
  const std::vector<bool> border = vertexEdges(flat).onBoundary;
  const int moved = movedOneByOne(
      jittered, flat, [&](Mesh& m, const std::vector<int>& others) { return raiseMeanAngles(m, flat, others); },
      [](int v, Angles before, Angles after) {
        EXPECT_GT(after.second, before.second) << "vertex " << v;
        EXPECT_GE(after.first, before.first) << "vertex " << v;
      });
  EXPECT_GT(moved, 15);
  const std::vector<int> all = everyVertex(flat);
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
TEST(LastSteps, RaiseSmallAnglesCutsNoPeakOff) {
  const Mesh surface = patchWithOneVertexPushed(0.2);
  Mesh m = surface;
  EXPECT_EQ(raiseSmallAngles(m, surface), 0);
  EXPECT_EQ(m.points, surface.points);
}

// The patch folded along its middle row (vertices 3, 10, ... 45) into a fin 8 degrees thin:
// the faces around a vertex of the fold's edge face more than 84 degrees away from their mean
// normal, as around a vertex snapped onto a horn. Vertex 24, on the edge, slid 0.7 along it.
Mesh finWithAVertexSlid() {
  Mesh m = test::equilateralPatch();
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
TEST(LastSteps, RaiseSmallAnglesMovesAVertexOnTheEdgeOfAThinFin) {
  const Mesh fin = finWithAVertexSlid();
  const double before = measureQuality(fin).minAngle;
  ASSERT_LT(before, 25.0);
  std::vector<int> allBut24 = everyVertex(fin);
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
  Mesh m = test::equilateralPatch();
  m.points[1] = m.points[2] + length * (m.points[1] - m.points[2]);
  return m;
}

// One end goes (merged into the other): a vertex fewer, the border's course and its other vertices
// kept, the smallest angle up; a pinned vertex keeps its place under its new number. With both
// ends pinned, nothing changes.
TEST(LastSteps, AShortBorderEdgeLosesAnEnd) {
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
TEST(LastSteps, AShortBorderEdgeAtABendStays) {
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
TEST(LastSteps, AShortBorderEdgeStaysWhereItsCollapseLowersTheAngles) {
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

// A point `length` from the origin at `degrees` from the x axis, in the plane z = 0.
Vec3 polar(double length, double degrees) {
  const double a = degrees * M_PI / 180;
  return Vec3(length * std::cos(a), length * std::sin(a), 0.0);
}

// A border corner of 40 degrees at vertex 0 whose two triangles share inside vertex 3 (a site
// in the wedge, 0.6 out along its bisector): 20 degrees at the corner, which no move of vertex 3
// raises. Vertex 3 goes, and the corner is one triangle of 40, 70 and 70 degrees; a pinned
// vertex keeps its place under its new number. Pinned itself, vertex 3 stays.
TEST(LastSteps, ASharpCornerWithASiteInItsWedgeBecomesAnEar) {
  Mesh surface;
  surface.points = {Vec3::Zero(), polar(1, 0), polar(1, 40), polar(0.6, 20), polar(1.6, 20)};
  surface.triangles = {{0, 1, 3}, {0, 3, 2}, {3, 1, 2}, {1, 4, 2}};
  ASSERT_NEAR(measureQuality(surface).minAngle, 20.0, 1e-9);
  Mesh m = surface;
  std::vector<int> pinned = {4};
  EXPECT_EQ(earsAtSharpCorners(m, surface, pinned), 1);
  EXPECT_NO_THROW(validateMesh(m, "ear"));
  EXPECT_TRUE(analyzeTopology(m).isDisk());
  EXPECT_EQ(m.vertexCount(), 4);
  EXPECT_EQ(m.faceCount(), 2);
  EXPECT_NEAR(measureQuality(m).minAngle, 40.0, 1e-9);
  ASSERT_EQ(pinned, std::vector<int>{3});
  EXPECT_EQ(m.points[3], surface.points[4]);

  Mesh kept = surface;
  std::vector<int> site = {3};
  EXPECT_EQ(earsAtSharpCorners(kept, surface, site), 0);
  EXPECT_EQ(kept.triangles, surface.triangles);
}

// A border corner of 50 degrees at vertex 0 whose two triangles share inside vertex 3 of five
// triangles, beyond the chord between the corner's neighbours: 25 degrees at the corner. The
// edge from the corner to vertex 3 is flipped: the corner is one triangle, the one across the
// new edge has 35.2 degrees at least, and the mesh's smallest angle is now that of the triangles
// beside them (30.2). A corner of 70 degrees (35 on either side) is left as it is.
TEST(LastSteps, ASharpCornersEdgeToAnInsideVertexIsFlippedAway) {
  const auto fan = [](double corner) {
    Mesh m;
    m.points = {Vec3::Zero(), polar(1, 0), polar(1, corner), polar(1.2, corner / 2), polar(2, 5),
                polar(2, corner - 5)};
    m.triangles = {{0, 1, 3}, {0, 3, 2}, {1, 4, 3}, {3, 4, 5}, {3, 5, 2}};
    return m;
  };
  const Mesh surface = fan(50);
  ASSERT_NEAR(measureQuality(surface).minAngle, 25.0, 1e-9);
  Mesh m = surface;
  std::vector<int> none;
  EXPECT_EQ(earsAtSharpCorners(m, surface, none), 1);
  EXPECT_EQ(m.vertexCount(), surface.vertexCount());
  EXPECT_EQ(Rings(m).offset[1] - Rings(m).offset[0], 1);  // the corner's one triangle
  EXPECT_NEAR(measureQuality(m).minAngle, 30.16, 0.01);

  const Mesh wide = fan(70);
  Mesh same = wide;
  EXPECT_EQ(earsAtSharpCorners(same, wide, none), 0);
  EXPECT_EQ(same.triangles, wide.triangles);
}

// borderNeighbours() walks the border the way the triangles run along it, once round, and
// gives the inside vertices none.
TEST(LastSteps, BorderNeighboursWalkTheBorderOnceRound) {
  const Mesh m = test::grid(6);
  const auto [before, after] = borderNeighbours(m);
  const std::vector<bool> border = vertexEdges(m).onBoundary;
  EXPECT_EQ(after[0], 1);
  EXPECT_EQ(before[1], 0);
  int steps = 0;
  for (int v = 0; steps == 0 || v != 0; v = after[v], ++steps) {
    ASSERT_GE(after[v], 0);
    EXPECT_EQ(before[after[v]], v);
    ASSERT_LE(steps, m.vertexCount());
  }
  EXPECT_EQ(steps, 24);
  for (int v = 0; v < m.vertexCount(); ++v)
    if (!border[v]) EXPECT_EQ(std::make_pair(before[v], after[v]), std::make_pair(-1, -1));
}

// relaxOnSurface(local) works on the triangles near the movable vertices alone: the result is
// that of its passes on the whole mesh, bit for bit, here where a flip at the rim of two rings
// around a vertex of a jittered bumpy grid makes a triangle with no movable corner.
TEST(LastSteps, ALocalRelaxationIsThePassesOnTheWholeMesh) {
  Mesh surface = test::grid(16);
  for (Vec3& p : surface.points) p.z() = 0.1 * std::sin(6 * p.x()) * std::cos(5 * p.y());
  const Mesh start = jitteredInside(surface, 1, 0.4 / 16);
  std::vector<bool> movable(start.vertexCount(), false);
  movable[8 * 17 + 8] = true;
  movable = withNeighbours(start, withNeighbours(start, movable));
  const SurfaceProjection projection(surface);

  Mesh local = start;
  relaxOnSurface(local, movable, projection, 3, /*local=*/true);
  Mesh whole = start;
  const std::vector<bool> border = vertexEdges(whole).onBoundary;
  for (int pass = 0; pass < 3; ++pass) {
    relaxOnce(whole, movable, border, projection);
    flipEdges(whole, notDelaunay, nullptr, &movable);
  }
  EXPECT_EQ(local.points, whole.points);
  EXPECT_EQ(local.triangles, whole.triangles);
  int outside = 0;  // changed triangles with no movable corner
  for (int f = 0; f < start.faceCount(); ++f) {
    const Triangle& t = whole.triangles[f];
    outside += t != start.triangles[f] && !movable[t[0]] && !movable[t[1]] && !movable[t[2]];
  }
  EXPECT_GT(outside, 0);
}

// Issue 6: the vertices of a stitched seam (here a jittered column of a flat grid) move on the
// surface and their triangles get rounder; the rest of the mesh stays where it was but for the
// seam's neighbours.
TEST(LastSteps, SeamVerticesRelaxOnTheSurfaceOnceStitched) {
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
TEST(LastSteps, AVertexIsSnappedOntoATipTheResultCutOff) {
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
TEST(LastSteps, ASnapCloserThanAnEdgeLengthKeepsTheAngles) {
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
TEST(LastSteps, NothingIsSnappedWhereTheResultFollowsTheInput) {
  const Mesh input = test::grid(8);
  Mesh result = input;
  EXPECT_TRUE(snapToTips(result, input).empty());
  EXPECT_EQ(result.points, input.points);
  EXPECT_EQ(result.triangles, input.triangles);
}

// A coarse input: a roof of six triangles whose crest runs between two tips 0.8 apart, and a
// finer result (a 7 x 7 grid put onto it) that cuts the crest between its vertices. The tips
// are snapped to as input vertices; the crest's midpoint, on no input vertex, is a candidate
// as the midpoint of an edge longer than the result's, and a vertex is snapped there too.
TEST(LastSteps, AVertexIsSnappedOntoTheCrestOfACoarseInput) {
  Mesh input;
  input.points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.1, 0.5, 0.3}, {0.9, 0.5, 0.3}};
  input.triangles = {{0, 1, 5}, {0, 5, 4}, {1, 2, 5}, {2, 3, 4}, {2, 4, 5}, {3, 0, 4}};
  Mesh result = test::grid(7);
  const SurfaceProjection onInput(input);
  for (Vec3& p : result.points) p = onInput.closestPoint(p);
  const double before = measureFidelity(result, input).hausdorffPercent;
  EXPECT_EQ(snapToTips(result, input).size(), 3u);
  EXPECT_NO_THROW(validateMesh(result, "snapped"));
  for (const Vec3& snappedTo : {input.points[4], input.points[5], Vec3(0.5, 0.5, 0.3)})
    EXPECT_TRUE(std::any_of(result.points.begin(), result.points.end(),
                            [&](const Vec3& p) { return (p - snappedTo).norm() < 1e-12; }))
        << snappedTo.transpose();
  EXPECT_LT(measureFidelity(result, input).hausdorffPercent, 0.5 * before);
  EXPECT_GE(measureQuality(result).minAngle, 30.0);
}

// A ridge of the input across the equilateral patch, oblique to its edges: the patch's vertices
// on the input, its triangles' chords cut under the ridge. A fine grid over the patch's
// parallelogram, raised 0.3 along the line x - 0.4 y = 4, falling to nothing 0.8 away.
Mesh ridgeUnderThePatch() {
  Mesh input = test::grid(90);
  for (Vec3& p : input.points) {
    const double x = 6 * p.x() + 3 * p.y(), y = 3 * std::sqrt(3.0) * p.y();
    const double across = std::abs(x - 0.4 * y - 4) / std::hypot(1.0, 0.4);
    p = Vec3(x, y, 0.3 * std::max(0.0, 1 - across / 0.8));
  }
  return input;
}

// The farthest of points on a fine grid over each triangle of `m` from `surface`.
double farthestFrom(const Mesh& m, const SurfaceProjection& surface) {
  double farthest = 0;
  constexpr int n = 20;
  for (const Triangle& t : m.triangles)
    for (int i = 0; i <= n; ++i)
      for (int j = 0; i + j <= n; ++j) {
        const Vec3 p = (i * m.points[t[0]] + j * m.points[t[1]] + (n - i - j) * m.points[t[2]]) / n;
        farthest = std::max(farthest, std::sqrt(surface.squaredDistance(p)));
      }
  return farthest;
}

// The vertices of the triangles that cut farthest under the ridge move along the input, their
// chords nearer it: the farthest any point of the patch is from the input falls (by 6%: a move
// that brings one triangle nearer takes the one beyond the ridge farther, and a ridge this
// sharp would need a row of vertices along it), the smallest angle stays over 35 degrees, and
// the border and pinned vertices stay. The same at a ten-thousandth of the size and at ten
// times it: what a move must gain is a part of an edge, and a refused place scores below any
// distance (a score of -1 had beaten a distance over 1).
TEST(LastSteps, TheChordsFarthestFromTheInputAreBroughtNearer) {
  for (double scale : {1.0, 1e-4, 10.0}) {
    SCOPED_TRACE(scale);
    const Mesh input = test::moved(ridgeUnderThePatch(), scale, Vec3::Zero());
    const SurfaceProjection projection(input);
    Mesh patch = test::moved(test::equilateralPatch(), scale, Vec3::Zero());
    for (Vec3& p : patch.points) p = projection.closestPoint(p);
    const double before = farthestFrom(patch, projection);
    ASSERT_GT(before, 0.05 * scale);
    ASSERT_GT(measureQuality(patch).minAngle, 50.0);

    const std::vector<int> all = everyVertex(patch);
    Mesh m = patch;
    EXPECT_EQ(bringNearer(m, input, all), 0);
    EXPECT_EQ(m.points, patch.points);

    EXPECT_GT(bringNearer(m, input), 0);
    EXPECT_LT(farthestFrom(m, projection), 0.97 * before);  // 0.170 -> 0.159 at scale 1
    EXPECT_GE(measureQuality(m).minAngle, 35.0);
    const std::vector<bool> border = vertexEdges(patch).onBoundary;
    for (int v = 0; v < m.vertexCount(); ++v) {
      if (border[v]) EXPECT_EQ(m.points[v], patch.points[v]) << "vertex " << v;
      EXPECT_LT(std::sqrt(projection.squaredDistance(m.points[v])), 1e-9 * scale) << "vertex " << v;
    }
  }

  // Where the input is the patch itself, nothing strays and nothing moves.
  Mesh flat = test::equilateralPatch();
  EXPECT_EQ(bringNearer(flat, test::equilateralPatch()), 0);
}
