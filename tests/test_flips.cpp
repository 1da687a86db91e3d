#include "flips.h"
#include "metrics.h"
#include "test_support.h"
#include "topology.h"

#include <cmath>
#include <limits>
#include <map>
#include <random>
#include <set>

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

TEST(Flips, FlipsTheBadDiagonalOfAThinQuad) {
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

TEST(Flips, AfterFlipsEveryInteriorEdgeIsDelaunay) {
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

// test::grid(n) with the diagonal of square (i, j) turned the other way: two of its corners
// lose a neighbour, two gain one.
Mesh gridWithOneDiagonalTurned(int n, int i, int j) {
  Mesh m = test::grid(n);
  auto at = [n](int x, int y) { return y * (n + 1) + x; };
  test::flip(m, at(i, j), at(i + 1, j + 1));
  return m;
}

TEST(Flips, LastValenceFlipsMakeVerticesRegularWhereNoAngleFallsUnder35) {
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

TEST(Flips, LastValenceFlipsLeaveNoMoreIrregularVertices) {
  Mesh m = test::patchWithTwoFlips();
  ASSERT_NO_THROW(validateMesh(m, "patch"));
  const double before = measureQuality(m).irregularBoundaryAware;
  EXPECT_EQ(flipToRegularity(m, /*smallestAngle=*/0.0), 0);  // (its flips make 30 degrees)
  EXPECT_EQ(measureQuality(m).irregularBoundaryAware, before);
}

// Whatever the mesh's scale: at a millionth, its new triangles' areas (2e-14) were under the
// flat test's absolute 1e-14, no flip was made, and the bumpy disk at 500 vertices came out
// 17.6% irregular instead of 9.6%.
TEST(Flips, TheSameFlipsAtAnyScale) {
  for (double scale : {1e-6, 1.0, 1e6}) {
    Mesh m;
    m.points = {{0, 0, 0}, {2e-1, 0, 0}, {1e-1, 2e-2, 0}, {1e-1, -2e-2, 0}};
    for (Vec3& p : m.points) p *= scale;
    m.triangles = {{0, 1, 2}, {1, 0, 3}};
    EXPECT_EQ(flipToDelaunay(m), 1) << scale;
    Mesh turned = gridWithOneDiagonalTurned(6, 2, 3);
    for (Vec3& p : turned.points) p *= 1e-1 * scale;
    EXPECT_GE(flipToRegularity(turned), 1) << scale;
  }
}

namespace {

std::set<std::vector<std::pair<int, int>>> edgesOf(const std::vector<ValenceMove>& moves, bool singleFlipsOnly) {
  std::set<std::vector<std::pair<int, int>>> edges;
  for (const ValenceMove& move : moves)
    if (!singleFlipsOnly || move.edges.size() == 1) edges.insert(move.edges);
  return edges;
}

}  // namespace

// The search for sequences stops where it has looked at its budget of flips; the single flips
// are all still there.
TEST(Flips, ValenceMovesSearchSequencesWithinABudget) {
  // Four edges of a row flipped: two 5-7 pairs of valences inside, which only a sequence of
  // four flips makes regular again.
  Mesh m = test::patchWithFlips({{9, 15}, {10, 16}, {11, 17}, {12, 18}});
  EdgeFlips flips(m, nullptr);
  const auto unbounded = valenceMoves(flips, m, 0.0, nullptr, std::numeric_limits<size_t>::max());
  EXPECT_GT(edgesOf(unbounded, false).size(), edgesOf(unbounded, true).size());  // sequences found
  EXPECT_EQ(edgesOf(valenceMoves(flips, m, 0.0, nullptr, 0), false), edgesOf(unbounded, true));
  // On a disk as Lloyd leaves it, the default budget is far from reached.
  EXPECT_EQ(edgesOf(valenceMoves(flips, m, 0.0), false), edgesOf(unbounded, false));
}
