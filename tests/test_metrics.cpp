#include "metrics.h"
#include "projection.h"
#include "test_support.h"

#include <algorithm>
#include <map>
#include <random>

using namespace lloydscope;

namespace {
// A patch of the regular triangular lattice: hexagonal rings around a centre.
Mesh hexPatch(int rings) {
  Mesh m;
  std::map<std::pair<int, int>, int> index;
  const Vec2 a(1, 0), b(0.5, std::sqrt(3.0) / 2);
  auto inside = [&](int i, int j) { return std::abs(i) <= rings && std::abs(j) <= rings && std::abs(i + j) <= rings; };
  for (int i = -rings; i <= rings; ++i)
    for (int j = -rings; j <= rings; ++j)
      if (inside(i, j)) {
        const Vec2 p = i * a + j * b;
        index[{i, j}] = m.vertexCount();
        m.points.emplace_back(p.x(), p.y(), 0);
      }
  for (const auto& [ij, v] : index) {
    const auto [i, j] = ij;
    if (inside(i + 1, j) && inside(i, j + 1)) m.triangles.push_back({v, index[{i + 1, j}], index[{i, j + 1}]});
    if (inside(i + 1, j) && inside(i + 1, j - 1)) m.triangles.push_back({v, index[{i + 1, j - 1}], index[{i + 1, j}]});
  }
  return m;
}
}  // namespace

// A spike: three triangles around an apex whose angles sum to 59 degrees (20 each): no
// triangles around a vertex there can all reach 30, and the metrics say where and how much; a
// flat fan's centre is no tip, even where its own angles are small.
TEST(Quality, ASmallestAngleAtATipGivesItsAngleSum) {
  const Mesh spike = test::polarDisk(3, 1, 0, [](double r, double) { return 5 * (1 - r); });
  const QualityMetrics m = measureQuality(spike);
  EXPECT_LT(m.minAngle, 30);
  EXPECT_NEAR(m.minAngleTipSum, 3 * 2 * std::asin(std::sqrt(3.0) / 2 / std::sqrt(26.0)) * 180 / M_PI, 1e-9);
  EXPECT_EQ(m.minAngleAt, Vec3(0, 0, 5));
  const Mesh needles = test::polarDisk(24, 1);  // 15-degree wedges, at a centre whose angles sum to 360
  EXPECT_LT(measureQuality(needles).minAngle, 30);
  EXPECT_EQ(measureQuality(needles).minAngleTipSum, 0);
}

TEST(Quality, EquilateralLatticeIsPerfectInside) {
  const Mesh m = hexPatch(3);  // 37 vertices, 54 triangles
  const QualityMetrics q = measureQuality(m);
  EXPECT_EQ(q.vertices, 37);
  EXPECT_EQ(q.faces, 54);
  EXPECT_NEAR(q.minAngle, 60.0, 1e-9);
  EXPECT_NEAR(q.avgMinAngle, 60.0, 1e-9);
  EXPECT_NEAR(q.maxAngle, 60.0, 1e-9);
  EXPECT_EQ(q.percentUnder30, 0.0);
  // 19 interior vertices have valence 6; of the 18 border ones, the 6 corners have valence 3
  // and the 12 others valence 4.
  EXPECT_EQ(q.boundaryVertices, 18);
  EXPECT_NEAR(q.irregularPercent, 100.0 * 18 / 37, 1e-9);
  EXPECT_NEAR(q.irregularBoundaryAware, 100.0 * 6 / 37, 1e-9);
  EXPECT_EQ(q.angleHistogram[5] + q.angleHistogram[6], 3 * 54);  // 60 degrees, give or take
}

// With every angle 60 degrees, a vertex's defect is its valence's distance from 6 (4 on the
// border) in units of 60 degrees: the curvature is the irregularity where each irregular vertex
// is one off. The lattice's six border corners are 3s (two triangles, 120 degrees: one unit each).
TEST(Quality, OnEquilateralTrianglesTheCurvatureIsTheIrregularity) {
  const QualityMetrics lattice = measureQuality(hexPatch(3));
  EXPECT_NEAR(lattice.curvatureDefects, 100.0 * 6 / 37, 1e-9);
  EXPECT_NEAR(lattice.curvatureDefects, lattice.irregularBoundaryAware, 1e-9);
}

// Gauss-Bonnet: a closed convex surface curves by 720 degrees in all, 12 units, however it is
// meshed and wherever its curvature is: at the cube's 8 corners (90 degrees each), or spread
// over a sphere's vertices.
TEST(Quality, AClosedConvexSurfaceCurvesByTwelveDefects) {
  for (const auto& [n, onSphere] : {std::pair{3, false}, {3, true}, {6, true}}) {
    const QualityMetrics q = measureQuality(test::cube(n, onSphere));
    EXPECT_NEAR(q.curvatureDefects * q.vertices / 100.0, 12.0, 1e-9) << n << " " << onSphere;
  }
}

// The curvature is the surface's at the vertices, not the triangulation's: a flat square curves
// only at its 4 corners (90 degrees from straight: 1.5 units each), whichever diagonals split
// its cells, while the valences, hence the irregularity, follow the diagonals.
TEST(Quality, TheCurvatureDependsOnWhereTheVerticesAreNotOnHowTheyAreJoined) {
  const Mesh alike = test::grid(4);
  Mesh alternating = alike;
  for (size_t f = 0; f < alternating.triangles.size(); f += 2) {
    const int cell = static_cast<int>(f / 2), i = cell % 4, j = cell / 4;
    if ((i + j) % 2 == 0) continue;
    auto at = [](int x, int y) { return y * 5 + x; };  // the other diagonal
    alternating.triangles[f] = {at(i, j), at(i + 1, j), at(i, j + 1)};
    alternating.triangles[f + 1] = {at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)};
  }
  const QualityMetrics a = measureQuality(alike), b = measureQuality(alternating);
  EXPECT_NEAR(a.curvatureDefects, 100.0 * 6 / 25, 1e-9);
  EXPECT_NEAR(a.curvatureDefectsOnBorder, a.curvatureDefects, 1e-9);  // flat: all of it the border's corners
  EXPECT_NEAR(b.curvatureDefects, a.curvatureDefects, 1e-9);
  EXPECT_EQ(measureQuality(test::cube(3, true)).curvatureDefectsOnBorder, 0.0);  // no border
  EXPECT_NE(b.irregularBoundaryAware, a.irregularBoundaryAware);
}

TEST(Quality, RightIsoscelesGrid) {
  const QualityMetrics q = measureQuality(test::grid(3));
  EXPECT_NEAR(q.minAngle, 45.0, 1e-9);
  EXPECT_NEAR(q.maxAngle, 90.0, 1e-9);
  EXPECT_NEAR(q.avgMinAngle, 45.0, 1e-9);
  EXPECT_EQ(q.percentUnder30, 0.0);
}

// The smallest corner angle, measured only where it is (opposite the shortest edge), is the
// smallest of the three: on random triangles, slivers, caps, isosceles ones and a degenerate one.
TEST(Quality, TheSmallestAngleIsOppositeTheShortestEdge) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<std::array<Vec3, 3>> triangles = {
      {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.5, 1e-7, 0)},   // a cap
      {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1e-6, 1e-7, 0)},  // a needle
      {Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(1, 3, 0)},        // isosceles
      {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.5, std::sqrt(0.75), 0)},
      {Vec3(0, 0, 0), Vec3(0, 0, 0), Vec3(1, 0, 0)}};       // two corners at one point
  for (int i = 0; i < 1000; ++i)
    triangles.push_back({Vec3(u(rng), u(rng), u(rng)), Vec3(u(rng), u(rng), u(rng)), Vec3(u(rng), u(rng), u(rng))});
  for (const auto& [a, b, c] : triangles) {
    const auto angles = cornerAnglesDeg(a, b, c);
    const double smallest = std::min({angles[0], angles[1], angles[2]});
    for (const auto& [p, q, r] : {std::array<Vec3, 3>{a, b, c}, {b, c, a}, {c, a, b}, {b, a, c}})
      EXPECT_NEAR(smallestAngleDeg(p, q, r), smallest, 1e-12) << a.transpose() << " / " << b.transpose() << " / " << c.transpose();
  }
}

// The triangle to look at first: the one with the smallest angle, wherever it is.
TEST(Quality, TheWorstTriangleIsTheOneWithTheSmallestAngle) {
  Mesh m = test::grid(6);
  EXPECT_EQ(worstTriangle(Mesh{}), -1);
  const int sliver = 17;
  m.points[m.triangles[sliver][0]] += 0.9 * (m.points[m.triangles[sliver][1]] - m.points[m.triangles[sliver][0]]);
  const int worst = worstTriangle(m);
  ASSERT_GE(worst, 0);
  const auto smallest = [&](int t) {
    const Triangle& f = m.triangles[t];
    return smallestAngleDeg(m.points[f[0]], m.points[f[1]], m.points[f[2]]);
  };
  for (int t = 0; t < m.faceCount(); ++t) EXPECT_LE(smallest(worst), smallest(t)) << t;
  EXPECT_NEAR(smallest(worst), measureQuality(m).minAngle, 1e-9);
}

TEST(Fidelity, IdenticalSurfacesAreAtDistanceZero) {
  const Fidelity f = measureFidelity(test::grid(4), test::grid(4));
  EXPECT_NEAR(f.hausdorffPercent, 0.0, 1e-12);
  EXPECT_GT(f.samples, 20000);
}

TEST(Fidelity, ShiftedPlaneIsAtTheShift) {
  Mesh shifted = test::grid(4);
  for (Vec3& p : shifted.points) p.z() += 0.01;
  const Fidelity f = measureFidelity(shifted, test::grid(4));
  const double expected = 100.0 * 0.01 / std::sqrt(2.0);
  EXPECT_NEAR(f.hausdorffPercent, expected, 1e-9);
  EXPECT_NEAR(f.rmsPercent, expected, 1e-9);
}

TEST(Fidelity, IsTwoSided) {
  // Half a square against the whole one: nothing of the half is far from the whole, but the
  // whole's far corner is 0.5 from the half.
  Mesh half;
  half.points = {{0, 0, 0}, {0.5, 0, 0}, {0.5, 1, 0}, {0, 1, 0}};
  half.triangles = {{0, 1, 2}, {0, 2, 3}};
  const Fidelity f = measureFidelity(half, test::grid(2));
  EXPECT_NEAR(f.hausdorffPercent, 100.0 * 0.5 / std::sqrt(2.0), 1e-9);
  // Reached on the whole square's side x = 1 (its vertices are samples), not on the half.
  EXPECT_TRUE(f.farthestOnReference);
  EXPECT_NEAR(f.farthestPoint.x(), 1.0, 1e-12);
}

TEST(Fidelity, SaysWhereTheResultStraysFarthest) {
  // One inside vertex of the result raised by 0.2: the result is farthest from the reference
  // there, and the reference is nowhere that far from the result.
  Mesh raised = test::grid(4);
  int middle = 0;
  for (int v = 0; v < raised.vertexCount(); ++v)
    if ((raised.points[v] - Vec3(0.5, 0.5, 0)).norm() < 1e-9) middle = v;
  raised.points[middle].z() = 0.2;
  const Fidelity f = measureFidelity(raised, test::grid(4));
  EXPECT_FALSE(f.farthestOnReference);
  EXPECT_NEAR((f.farthestPoint - Vec3(0.5, 0.5, 0.2)).norm(), 0.0, 1e-12);
  EXPECT_NEAR(f.hausdorffPercent, 100.0 * 0.2 / std::sqrt(2.0), 1e-9);
}

// The farthest point lies between samples: a square against the same square with a small
// square hole of half-width r, off every vertex and edge of the square's two triangles. The
// square's farthest point from the holed one is the hole's centre, r from its sides; the
// farthest of 10,000 random samples was about half as far.
TEST(Fidelity, FindsTheFarthestPointBetweenItsSamples) {
  const double r = 0.01;
  const Vec3 c(0.37, 0.61, 0);
  Mesh holed;
  holed.points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                  c + Vec3(-r, -r, 0), c + Vec3(r, -r, 0), c + Vec3(r, r, 0), c + Vec3(-r, r, 0)};
  for (int k = 0; k < 4; ++k) {  // the band between side k of the square and side k of the hole
    const int o = k, o1 = (k + 1) % 4, i = 4 + k, i1 = 4 + (k + 1) % 4;
    holed.triangles.push_back({o, o1, i1});
    holed.triangles.push_back({o, i1, i});
  }
  Mesh square;
  square.points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  square.triangles = {{0, 1, 2}, {0, 2, 3}};
  const Fidelity f = measureFidelity(square, holed);
  EXPECT_NEAR(f.hausdorffPercent, 100.0 * r / std::sqrt(2.0), 1e-3 * 100.0 * r / std::sqrt(2.0));
  EXPECT_FALSE(f.farthestOnReference);
  EXPECT_NEAR((f.farthestPoint - c).norm(), 0.0, 1e-4);
}

// Each edge is sampled once at its midpoint, the border's too (half of the border's edges were
// left out): a triangle has 3 vertices, 3 edges and 10,000 + 10 random points.
TEST(Fidelity, SamplesEveryVertexAndEdgeOnce) {
  Mesh triangle;
  triangle.points = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  triangle.triangles = {{0, 1, 2}};
  EXPECT_EQ(measureFidelity(triangle, triangle).samples, 2 * (3 + 3 + 10010));
}

// A fine surface is sampled at the coarser one's scale (its vertices and edges all the same): a
// 20,000-triangle grid against a 32-triangle one took 200,000 random samples (ten per triangle),
// now 640 (twenty per triangle of the coarse one) and 10,000. The farthest point is still found:
// the fine grid's middle vertex raised by 0.2 off the coarse grid's plane.
TEST(Fidelity, AFineSurfaceIsSampledAtTheCoarserOnesScale) {
  Mesh fine = test::grid(100);
  const int middle = 50 * 101 + 50;
  ASSERT_NEAR((fine.points[middle] - Vec3(0.5, 0.5, 0)).norm(), 0.0, 1e-12);
  fine.points[middle].z() = 0.2;
  const Mesh coarse = test::grid(4);
  const int fineSamples = fine.vertexCount() + (3 * 100 * 100 + 2 * 100) + 10000 + 20 * coarse.faceCount();
  const int coarseSamples = coarse.vertexCount() + (3 * 4 * 4 + 2 * 4) + 10000 + 10 * coarse.faceCount();
  const Fidelity f = measureFidelity(coarse, fine);
  EXPECT_EQ(f.samples, fineSamples + coarseSamples);
  EXPECT_TRUE(f.farthestOnReference);
  EXPECT_NEAR(f.hausdorffPercent, 100.0 * 0.2 / std::sqrt(2.04), 1e-9);  // the raised grid's diagonal
  EXPECT_NEAR((f.farthestPoint - Vec3(0.5, 0.5, 0.2)).norm(), 0.0, 1e-12);
}

// A thin triangle of the input across a hole of the result, its corners on the result's border:
// it has next to no area for the random samples, and its long edge's midpoint, a quarter from the
// result, is where the input is farthest from it. Without the edges' midpoints (sampling a much
// finer surface by its vertices and random points alone) it measured 0.
TEST(Fidelity, AThinTriangleAcrossAHoleIsMeasured) {
  const auto holed = [](int n) {
    Mesh m = test::grid(n);
    std::vector<Triangle> kept;
    for (const Triangle& t : m.triangles) {
      const Vec3 c = (m.points[t[0]] + m.points[t[1]] + m.points[t[2]]) / 3;
      if (std::abs(c.x() - 0.5) > 0.25 || std::abs(c.y() - 0.5) > 0.25) kept.push_back(t);
    }
    return assemble(kept, m.points);  // no vertex left in the hole
  };
  const Mesh result = holed(4);
  Mesh input = holed(100);
  const auto vertexAt = [&](const Vec3& p) {
    for (int v = 0; v < input.vertexCount(); ++v)
      if ((input.points[v] - p).norm() < 1e-12) return v;
    return -1;
  };
  const int left = vertexAt({0.25, 0.5, 0}), right = vertexAt({0.75, 0.5, 0});
  ASSERT_GE(left, 0);
  ASSERT_GE(right, 0);
  input.points.emplace_back(0.75, 0.500001, 0);
  input.triangles.push_back({left, right, input.vertexCount() - 1});
  const Fidelity f = measureFidelity(result, input);
  EXPECT_TRUE(f.farthestOnReference);
  EXPECT_NEAR(f.hausdorffPercent, 100.0 * 0.25 / std::sqrt(2.0), 1e-3);
}

// The RMS distance is Metro's, one-sided over the area, the larger of the two sides: the whole
// unit square against its half x <= 0.5 is sqrt(integral of (x - 0.5)^2 for x in 0.5..1) =
// sqrt(1/24) from it, and the half 0 from the whole. Both sides pooled said about 0.7 of that.
TEST(Fidelity, TheRmsDistanceIsTheLargerOneSidedRmsOverTheArea) {
  Mesh half;
  half.points = {{0, 0, 0}, {0.5, 0, 0}, {0.5, 1, 0}, {0, 1, 0}};
  half.triangles = {{0, 1, 2}, {0, 2, 3}};
  const Fidelity f = measureFidelity(test::grid(8), half);
  const double expected = 100.0 * std::sqrt(1.0 / 24) / std::sqrt(1.25);  // the half's diagonal
  EXPECT_NEAR(f.rmsPercent, expected, 0.02 * expected);
}

// The batch queries take the points in a spatial order, each search started from the one
// before, as a single query may start from a point found before: each answer must still be the
// one asked for, at the same index, exactly.
TEST(Projection, BatchAndStartedQueriesAnswerEachPointAsASingleQueryDoes) {
  const Mesh surface = test::torus();
  const SurfaceProjection projection(surface);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> coordinate(-3.0, 3.0);
  std::vector<Vec3> points(5000);  // over a thousand: split over the threads
  for (Vec3& p : points) p = Vec3(coordinate(rng), coordinate(rng), coordinate(rng));
  const std::vector<double> squared = projection.squaredDistances(points);
  const std::vector<Vec3> closest = projection.closestPoints(points);
  std::vector<double> triangleSquared;
  const std::vector<int> triangle = projection.closestTriangles(points, triangleSquared);
  ASSERT_EQ(squared.size(), points.size());
  ASSERT_EQ(closest.size(), points.size());
  ASSERT_EQ(triangle.size(), points.size());
  for (size_t i = 0; i < points.size(); ++i) {
    ASSERT_EQ(squared[i], projection.squaredDistance(points[i])) << i;
    ASSERT_EQ(closest[i], projection.closestPoint(points[i])) << i;
    // The triangle that holds the closest point: where that is on an edge or a corner, the
    // search may name any triangle there (the one started from another point's may differ).
    Mesh held;
    held.points = surface.points;
    held.triangles = {surface.triangles.at(triangle[i])};
    ASSERT_EQ(SurfaceProjection(held).squaredDistance(points[i]), squared[i]) << i;
    ASSERT_EQ(triangleSquared[i], squared[i]) << i;
    if (i > 0) ASSERT_EQ(projection.closestPoint(points[i], closest[i - 1]), closest[i]) << i;  // from another's
    Vec3 onSurface = closest[i > 0 ? i - 1 : 0];  // the same, and the point found given back
    ASSERT_EQ(projection.squaredDistance(points[i], onSurface), squared[i]) << i;
    ASSERT_EQ(onSurface, closest[i]) << i;
  }
  EXPECT_TRUE(projection.squaredDistances({}).empty());
  const std::vector<Vec3> few(points.begin(), points.begin() + 10);  // taken one by one
  const std::vector<double> fewSquared = projection.squaredDistances(few);
  std::vector<double> fewTriangleSquared;
  const std::vector<int> fewTriangles = projection.closestTriangles(few, fewTriangleSquared);
  for (size_t i = 0; i < few.size(); ++i) {
    ASSERT_EQ(fewSquared[i], squared[i]) << i;
    ASSERT_EQ(fewTriangles[i], projection.closestTriangle(few[i])) << i;
    ASSERT_EQ(fewTriangleSquared[i], squared[i]) << i;
  }
}

// A search over the triangles near a point answers as the whole tree does: near it, from its own
// few triangles (every point within 0.1 of the centre of a cube of half-side 0.4 is closer
// than 0.3 to the torus); farther (the sphere through the point found leaves the cube), from
// the tree. Without that fallback, points far from the cube got the closest point within it
// (0.69 off).
TEST(Projection, ANearbySearchAnswersAsTheWholeTreeNearAndFar) {
  const Mesh surface = test::torus();
  const SurfaceProjection projection(surface);
  const Vec3 centre = surface.points[40];
  const SurfaceProjection::Nearby nearby = projection.nearby(centre, 0.4);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
  int searchedTree = 0;
  for (int i = 0; i < 2000; ++i) {
    const bool near = i < 1000;
    const Vec3 p = centre + (near ? 0.1 : 5.0) * Vec3(coordinate(rng), coordinate(rng), coordinate(rng));
    const Vec3 hint = projection.closestPoint(centre + 0.1 * Vec3(coordinate(rng), coordinate(rng), 0.0));
    bool fromTree = true;
    ASSERT_EQ(nearby.closestPoint(p, hint, &fromTree), projection.closestPoint(p, hint)) << i;
    if (near) ASSERT_FALSE(fromTree) << i;
    searchedTree += fromTree;
  }
  EXPECT_GT(searchedTree, 500);  // of the 1000 far ones
}

// The three bars that need no reference, at their edges: 15% irregular is met, 30 and 53
// degrees are met; a hair beyond each is not. Every trial's choice (slit or whole, with or
// without the first pass, one disk or charts) counts them.
// Two triangles on one edge, the second turned about it: folded when their normals turn more
// than 150 degrees (a flap bent back on itself), not at 120.
TEST(Quality, CountsTheEdgesWhereTheSurfaceFoldsBackOnItself) {
  const auto hinge = [](double degrees) {
    Mesh m;
    const double a = degrees * M_PI / 180;
    m.points = {{0, 0, 0}, {1, 0, 0}, {0.5, 1, 0}, {0.5, -std::cos(a), std::sin(a)}};
    m.triangles = {{0, 1, 2}, {1, 0, 3}};
    return m;
  };
  EXPECT_EQ(measureQuality(hinge(0)).foldedEdges(), 0);
  EXPECT_EQ(measureQuality(hinge(120)).foldedEdges(), 0);
  EXPECT_EQ(measureQuality(hinge(170)).foldedEdges(), 1);
  EXPECT_EQ(measureQuality(test::grid(4)).foldedEdges(), 0);
  const QualityMetrics folded = measureQuality(hinge(170));
  ASSERT_EQ(folded.folds.size(), 1u);
  EXPECT_TRUE(folded.folds[0].middle().isApprox(Vec3(0.5, 0, 0)));  // the hinge
  EXPECT_DOUBLE_EQ(folded.folds[0].length(), 1.0);
}

// A result's folds are the remeshing's where the input folds nowhere near them: CGAL's dino at
// 500 folded at 30 edges of its legs and neck, with no warning, because the input folds once,
// elsewhere.
TEST(Quality, FoldsAnewAreThoseAwayFromTheInputsOwn) {
  QualityMetrics input, result;
  const auto edge = [](double x) { return QualityMetrics::Fold{Vec3(x - 0.05, 0, 0), Vec3(x + 0.05, 0, 0)}; };
  result.folds = {edge(0), edge(5), edge(5.1)};  // 0.1 long
  EXPECT_EQ(foldsAnew(result, input), 3);
  input.folds = {{Vec3(0.15, 0, 0), Vec3(0.16, 0, 0)}};  // within twice the result's edge of the first
  EXPECT_EQ(foldsAnew(result, input), 2);
  input.folds.push_back({Vec3(5, 1, 0), Vec3(5.01, 1, 0)});  // farther from the others than that
  EXPECT_EQ(foldsAnew(result, input), 2);
  input.folds.push_back({Vec3(5.05, 0.19, 0), Vec3(5.06, 0.19, 0)});
  EXPECT_EQ(foldsAnew(result, input), 0);
  EXPECT_EQ(foldsAnew(QualityMetrics(), input), 0);
  // A long folded sliver of the input is its own fold only near itself, not all around it (by
  // its midpoint and length, one sliver 10 long hid every fold of the result within 20).
  input.folds = {{Vec3(-10, 3, 0), Vec3(0, 3, 0)}};
  EXPECT_EQ(foldsAnew(result, input), 3);
  input.folds = {{Vec3(-10, 0.15, 0), Vec3(0, 0.15, 0)}};  // along the first
  EXPECT_EQ(foldsAnew(result, input), 2);
}

TEST(Quality, TheBarsAreMetAtTheirEdges) {
  const QualityMetrics input;  // no border: nothing of it in the way
  QualityMetrics q;
  q.irregularBoundaryAware = kMostIrregularPercent;
  q.minAngle = kLeastMinAngle;
  q.avgMinAngle = kLeastAvgMinAngle;
  EXPECT_EQ(barsMet(q, input), 3);
  q.irregularBoundaryAware = 15.0001;
  EXPECT_EQ(barsMet(q, input), 2);
  q.minAngle = 29.9999;
  EXPECT_EQ(barsMet(q, input), 1);
  q.avgMinAngle = 52.9999;
  EXPECT_EQ(barsMet(q, input), 0);
  EXPECT_EQ(kMostIrregularPercent, 15.0);  // issue 5's numbers
  EXPECT_EQ(kLeastMinAngle, 30.0);
  EXPECT_EQ(kLeastAvgMinAngle, 53.0);
}

TEST(Quality, MeasuresTheSharpCornersOfTheBorder) {
  // A sector's apex: the sum of its 12 triangles' angles there; the far corners are 90 degrees.
  const QualityMetrics sector = measureQuality(test::sector(20));
  EXPECT_NEAR(sector.sharpestBorderCorner, 20.0, 1e-9);
  ASSERT_EQ(sector.sharpCorners.size(), 1u);
  EXPECT_NEAR(sector.sharpCorners[0].at.norm(), 0.0, 1e-12);
  EXPECT_NEAR(sector.sharpCorners[0].degrees, 20.0, 1e-9);
  EXPECT_EQ(sector.sharpCorners[0].triangles, 12);
  EXPECT_NEAR(sector.sharpCorners[0].shorterEdge, 1.0 / 30, 1e-12);  // to the first ring
  EXPECT_EQ(sector.minAngleOffSharpCorners, sector.minAngle);  // more than one triangle there
  const QualityMetrics grid = measureQuality(test::grid(4));
  EXPECT_NEAR(grid.sharpestBorderCorner, 90.0, 1e-9);
  EXPECT_TRUE(grid.sharpCorners.empty());
  EXPECT_EQ(measureQuality(test::cube(3, false)).sharpestBorderCorner, 360.0);  // no border
  // One triangle of 20, 70 and 90 degrees: its 20-degree corner is all the border has there.
  Mesh one;
  one.points = {{0, 0, 0}, {1, 0, 0}, {1, std::tan(20 * M_PI / 180), 0}};
  one.triangles = {{0, 1, 2}};
  const QualityMetrics q = measureQuality(one);
  EXPECT_NEAR(q.minAngle, 20.0, 1e-9);
  EXPECT_NEAR(q.minAngleOffSharpCorners, 70.0, 1e-9);
  ASSERT_EQ(q.sharpCorners.size(), 1u);
  EXPECT_EQ(q.sharpCorners[0].triangles, 1);
  EXPECT_NEAR(q.sharpCorners[0].shorterEdge, 1.0, 1e-12);
}

// A flat ring of 12 outer points around a hole of 3, of radius `hole`: each inner point fans to
// four outer ones, and three triangles join the inner points across the hole's sides.
Mesh ringAroundAHole(double hole) {
  Mesh ring;
  for (int k = 0; k < 3; ++k) {
    const double a = (45 + 120 * k) * M_PI / 180;
    ring.points.emplace_back(hole * std::cos(a), hole * std::sin(a), 0);
  }
  for (int i = 0; i < 12; ++i) ring.points.emplace_back(std::cos(i * M_PI / 6), std::sin(i * M_PI / 6), 0);
  for (int i = 0; i < 12; ++i) {
    const int k = i / 4, next = (i + 1) % 12;
    ring.triangles.push_back({k, 3 + i, 3 + next});
    if (next / 4 != k) ring.triangles.push_back({k, 3 + next, next / 4});
  }
  return ring;
}

// A sphere with a pinhole 10^-6 across was remeshed with needles of 0.0001 degrees around the
// hole, which the border keeps, and nothing said why: the metrics find the hole beside the
// smallest angle.
TEST(Quality, FindsAPinholeBesideTheSmallestAngle) {
  const QualityMetrics pinhole = measureQuality(ringAroundAHole(1e-6));
  EXPECT_LT(pinhole.minAngle, 1e-3);
  EXPECT_EQ(pinhole.minAngleHoleEdges, 3);
  EXPECT_NEAR(pinhole.minAngleHoleLength, 3 * std::sqrt(3.0) * 1e-6, 1e-12);
  EXPECT_GT(pinhole.meanEdge, 0.5);
  EXPECT_LT(pinhole.minAngleAt.norm(), 1.0 + 1e-12);
  EXPECT_GT(pinhole.minAngleAt.norm(), 1.0 - 1e-12);  // the needles' tips are on the outer ring
  const QualityMetrics wide = measureQuality(ringAroundAHole(0.2));  // a hole longer than half the mean edge
  ASSERT_LT(wide.minAngle, 30.0);  // so the hole is looked for
  EXPECT_EQ(wide.minAngleHoleEdges, 0) << wide.minAngleHoleLength << " " << wide.meanEdge;
  EXPECT_EQ(measureQuality(test::sector(20)).minAngleHoleEdges, 0);  // a sharp corner, no hole
}

// Each corner's own shorter border edge, read from its own triangles: a strip
// with three teeth on top, of widths 1, 2 and 0.5 and height 4 (tips of 14.3, 28.1 and 7.2
// degrees); each tooth's shorter border edge is its side, sqrt(4^2 + (w/2)^2).
TEST(Quality, EachSharpCornerHasItsOwnShorterBorderEdge) {
  const double widths[3] = {1, 2, 0.5};
  // Points 0-3 along y = 0, 4-7 along y = 1 (the teeth's bases), 8-10 the tips.
  Mesh comb;
  double x[4] = {0, 0, 0, 0};
  for (int i = 0; i < 3; ++i) x[i + 1] = x[i] + widths[i];
  for (double y : {0.0, 1.0})
    for (double xi : x) comb.points.emplace_back(xi, y, 0);
  for (int i = 0; i < 3; ++i) {
    comb.points.emplace_back(x[i] + widths[i] / 2, 5, 0);
    comb.triangles.insert(comb.triangles.end(), {{i, i + 1, i + 5}, {i, i + 5, i + 4}, {i + 4, i + 5, 8 + i}});
  }
  const QualityMetrics q = measureQuality(comb);
  ASSERT_EQ(q.sharpCorners.size(), 3u);  // sharpest first: the widths 0.5, 1, 2
  const double sorted[3] = {0.5, 1, 2};
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(q.sharpCorners[k].degrees, 2 * std::atan(sorted[k] / 8) * 180 / M_PI, 1e-9);
    EXPECT_NEAR(q.sharpCorners[k].shorterEdge, std::hypot(4.0, sorted[k] / 2), 1e-12) << k;
    EXPECT_EQ(q.sharpCorners[k].triangles, 1);
  }
}

TEST(Quality, TheSmallestAngleBarIsWithinTheInputsReach) {
  // A result keeps its input's border corners: where one of 20 degrees is one triangle's, that
  // triangle's angle there is the corner's.
  const Vec3 tip(1, 2, 3);
  QualityMetrics input, result;
  input.sharpCorners = {{tip, 20.0, 3, 0.1}};
  result.minAngle = 20.0;
  result.minAngleOffSharpCorners = 35.0;
  result.sharpCorners = {{tip, 20.0, 1, 0.12}};
  EXPECT_TRUE(meetsMinAngleBar(result, input));
  result.sharpCorners[0].degrees = result.minAngle = 19.6;  // sides curving outward: a little sharper
  EXPECT_TRUE(meetsMinAngleBar(result, input));
  result.sharpCorners[0].degrees = result.minAngle = 19.4;  // sharper than that: the result's doing
  EXPECT_FALSE(meetsMinAngleBar(result, input));
  result.sharpCorners[0].degrees = result.minAngle = 20.0;
  result.sharpCorners[0].at = tip + Vec3(0.01, 0, 0);  // elsewhere than the input's corner
  EXPECT_FALSE(meetsMinAngleBar(result, input));
  result.sharpCorners[0].at = tip;
  result.sharpCorners[0].triangles = 2;  // two triangles in it: each sharper than it need be
  EXPECT_FALSE(meetsMinAngleBar(result, input));
  result.sharpCorners[0].triangles = 1;
  result.minAngleOffSharpCorners = 29.9;  // a small angle elsewhere too
  EXPECT_FALSE(meetsMinAngleBar(result, input));
  const QualityMetrics square;  // no sharp corner: no less than 30
  result.minAngleOffSharpCorners = 35.0;
  EXPECT_FALSE(meetsMinAngleBar(result, square));
  result = QualityMetrics{};
  result.minAngle = 29.99;
  EXPECT_FALSE(meetsMinAngleBar(result, square));
  result.minAngle = 30.0;
  EXPECT_TRUE(meetsMinAngleBar(result, square));
  result.irregularBoundaryAware = 100;  // and barsMet counts it
  EXPECT_EQ(barsMet(result, square), 1);
}

// A flat disk whose rim is a 16-gon, and a "result" of it whose rim is the 16-gon turned by half
// a side: every corner of the input's rim is cut off (0.019 of the radius, 0.05 of a side),
// nothing else is off. All 16 rim vertices are returned, as the input's border is as coarse as
// the result's. An input rim of 64 sides is cut off the same way, but it is finer than the
// result's border (its vertices would crowd the samples): nothing. A result on the input: nothing.
TEST(Fidelity, TheCornersOfACoarseBorderThatAResultCutsOffAreFound) {
  const Mesh coarse = test::polarDisk(16, 6), fine = test::polarDisk(64, 6);
  const Mesh turned = test::polarDisk(16, 6, M_PI / 16);
  const std::vector<Vec3> corners = borderCornersCut(turned, SearchableSurface(coarse));
  ASSERT_EQ(corners.size(), 16u);
  for (const Vec3& p : corners) EXPECT_NEAR(p.head<2>().norm(), 1.0, 1e-12);
  EXPECT_TRUE(borderCornersCut(turned, SearchableSurface(fine)).empty());
  EXPECT_TRUE(borderCornersCut(coarse, SearchableSurface(coarse)).empty());
}

// The other way round: a flat star whose rim alternates between radius 1 and 0.9, 16 corners,
// the eight at 0.9 reflex; a "result" of it whose rim has the eight convex corners and the
// midpoints of the rim's edges, so that its border chord crosses each reflex corner outside the
// input (0.012 of the radius, 0.05 of the result's mean border edge). No input vertex is off
// the result; the chords are. All 16 rim vertices are returned.
TEST(Fidelity, TheReflexCornersOfACoarseBorderThatAResultCutsAcrossAreFound) {
  const auto rim = [](int i) { return test::starRim(8, 0.9, i); };
  const Mesh star = test::starDisk(8, 0.9, 6);
  std::vector<Vec3> cutAcross;  // a convex corner, the midpoints of the two edges of the reflex one after it
  for (int i = 0; i < 16; i += 2) {
    cutAcross.push_back(rim(i));
    cutAcross.push_back((rim(i) + rim(i + 1)) / 2);
    cutAcross.push_back((rim(i + 1) + rim(i + 2)) / 2);
  }
  const Mesh result = test::polarGrid(4, 24, true, Vec3::Zero(), [&](int k, int i) -> Vec3 { return cutAcross[i] * k / 4; });
  const std::vector<Vec3> corners = borderCornersCut(result, SearchableSurface(star));
  ASSERT_EQ(corners.size(), 16u);
  for (int i = 0; i < 16; ++i) EXPECT_NEAR((corners[i] - rim(i)).norm(), 0.0, 1e-12);
  EXPECT_TRUE(borderCornersCut(star, SearchableSurface(star)).empty());
  // The star's centre raised off the flat result: where it strays 1/1.4 as far as the chords
  // (0.0119), they are still found; 1/1.15 as far, and the border is no worse than the rest
  // (kCutOffBy).
  for (const auto& [ratio, found] : {std::pair{1.4, 16u}, std::pair{1.15, 0u}}) {
    const Mesh raised = test::starDisk(8, 0.9, 6, 0.0119 / ratio);
    EXPECT_EQ(borderCornersCut(result, SearchableSurface(raised)).size(), found) << ratio;
  }
}

// A point on a sheet is hidden from an eye behind another sheet, not by its own triangles, and
// seen from either side of its own sheet where nothing is between (the seams of a chart seen
// from behind).
TEST(Projection, APointIsHiddenOnlyBehindAnotherPartOfTheSurface) {
  Mesh sheets = test::grid(4);  // z = 0, and a copy at z = 1
  const int n = sheets.vertexCount();
  for (int v = 0; v < n; ++v) sheets.points.push_back(sheets.points[v] + Vec3(0, 0, 1));
  const size_t faces = sheets.triangles.size();
  for (size_t f = 0; f < faces; ++f) {
    const Triangle& t = sheets.triangles[f];
    sheets.triangles.push_back({t[0] + n, t[1] + n, t[2] + n});
  }
  const SurfaceProjection surface(sheets);
  const Vec3 onLower(0.5, 0.5, 0), onEdge(0.25, 0, 0);  // inside, and on the border
  EXPECT_TRUE(surface.hides(Vec3(0.5, 0.5, 5), onLower));
  EXPECT_FALSE(surface.hides(Vec3(0.5, 0.5, -5), onLower));  // from below: its back, in view
  EXPECT_FALSE(surface.hides(Vec3(0.25, -3, -1), onEdge));
  EXPECT_FALSE(surface.hides(Vec3(0.5, 0.5, 0.5), onLower));  // between the sheets
}
