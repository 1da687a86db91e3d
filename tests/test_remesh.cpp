#include "mesh_io.h"
#include "parameterization.h"
#include "remesh.h"
#include "test_support.h"
#include "topology.h"

#include <set>

using namespace lloydscope;

namespace {
Mesh wavyGrid(int n) {
  Mesh mesh = test::grid(n);
  for (Vec3& p : mesh.points) p.z() = 0.2 * std::sin(4 * p.x()) * std::cos(3 * p.y());
  return mesh;
}

// wavyGrid(n), its LSCM map and the map's domain.
struct WavyMap {
  explicit WavyMap(int n) : mesh(wavyGrid(n)), p(parameterize(mesh, {}, "wavy")), domain(p.uv, mesh.triangles, {}) {}
  const Mesh mesh;
  const Parameterization p;
  const Domain domain;
};
}  // namespace

TEST(Lift, AVertexOwnUVReturnsThatVertex) {
  const WavyMap w(10);
  for (int v = 0; v < w.mesh.vertexCount(); ++v)
    EXPECT_NEAR((lift(w.mesh, w.domain, w.p.uv[v]) - w.mesh.points[v]).norm(), 0.0, 1e-12) << v;
}

TEST(Lift, BarycentricInsideATriangle) {
  const WavyMap w(4);
  const Triangle& t = w.mesh.triangles[7];
  const Vec2 uv = 0.2 * w.p.uv[t[0]] + 0.3 * w.p.uv[t[1]] + 0.5 * w.p.uv[t[2]];
  const Vec3 expected = 0.2 * w.mesh.points[t[0]] + 0.3 * w.mesh.points[t[1]] + 0.5 * w.mesh.points[t[2]];
  EXPECT_NEAR((lift(w.mesh, w.domain, uv) - expected).norm(), 0.0, 1e-12);
  const Location l = w.domain.locate(uv, 0);  // by walking from triangle 0
  EXPECT_EQ(l.triangle, 7);
  EXPECT_TRUE(l.inside);
}

TEST(Lift, PointsOutsideGoToTheClosestPointOfTheDomain) {
  const Mesh mesh = test::grid(2);
  const Domain domain(std::vector<Vec2>{{0, 0}, {0.5, 0}, {1, 0}, {0, 0.5}, {0.5, 0.5}, {1, 0.5},
                                        {0, 1}, {0.5, 1}, {1, 1}},
                      mesh.triangles, {});
  const Location l = domain.locate(Vec2(1.5, 0.25));
  EXPECT_FALSE(l.inside);
  EXPECT_NEAR((domain.pointAt(l) - Vec2(1.0, 0.25)).norm(), 0.0, 1e-12);
}

TEST(Lift, LocateFindsTheTriangleOfEveryPointOfANonConvexDomain) {
  // An L of 3 x 3 squares' triangles: its bounding box's buckets straddle the notch, where the
  // answer must come from the closest point, and inside the L from the triangle holding it.
  const Mesh grid = test::grid(3);
  std::vector<Triangle> l;
  for (const Triangle& t : grid.triangles) {
    const Vec3 c = (grid.points[t[0]] + grid.points[t[1]] + grid.points[t[2]]) / 3;
    if (c.x() < 2.0 / 3 || c.y() < 1.0 / 3) l.push_back(t);
  }
  std::vector<Vec2> uv;
  for (const Vec3& p : grid.points) uv.emplace_back(p.x(), p.y());
  const Domain domain(uv, l, {});
  for (int i = 0; i <= 40; ++i)
    for (int j = 0; j <= 40; ++j) {
      const Vec2 p(0.013 + i / 41.0, 0.007 + j / 41.0);
      const Location at = domain.locate(p);
      ASSERT_GE(at.triangle, 0);
      const bool inNotch = p.x() > 2.0 / 3 && p.y() > 1.0 / 3;
      EXPECT_EQ(at.inside, !inNotch) << p.transpose();
      EXPECT_NEAR(at.weights.sum(), 1.0, 1e-12);
      EXPECT_GE(at.weights.minCoeff(), 0.0);
      const Vec2 found = domain.pointAt(at);
      // In the notch: the closest point of the L, on its side x = 2/3 or y = 1/3.
      const double distance = inNotch ? std::min(p.x() - 2.0 / 3, p.y() - 1.0 / 3) : 0.0;
      EXPECT_NEAR((found - p).norm(), distance, 1e-9) << p.transpose();
    }
  // Far off: the closest point, never a bucket out of range.
  for (const Vec2& far : {Vec2(1e300, 0.5), Vec2(-1e300, 1e300), Vec2(0.5, 1e30)}) {
    const Location at = domain.locate(far);
    ASSERT_GE(at.triangle, 0);
    EXPECT_FALSE(at.inside);
  }
}

namespace {
// The map's inside vertices, and a site for each at its own parameter point.
void insideVerticesAsSites(const WavyMap& w, std::vector<int>& inside, std::vector<Vec2>& sites) {
  for (int v = 0; v < w.mesh.vertexCount(); ++v)
    if (!w.p.onBoundary[v]) {
      inside.push_back(v);
      sites.push_back(w.p.uv[v]);
    }
}
}  // namespace

TEST(Relocate, KeepsConnectivityAndMovesOnlyInsideVertices) {
  const WavyMap w(6);
  std::vector<int> inside;
  std::vector<Vec2> sites;
  insideVerticesAsSites(w, inside, sites);
  for (Vec2& s : sites) s = 0.5 * s + Vec2(0.25, 0.25);  // pulled towards the centre
  const Relocation r = relocate(w.mesh, w.domain, inside, sites);
  const Mesh& out = r.mesh;
  EXPECT_EQ(out.triangles, w.mesh.triangles);
  for (int v = 0; v < w.mesh.vertexCount(); ++v)
    if (w.p.onBoundary[v]) EXPECT_EQ(out.points[v], w.mesh.points[v]);
  EXPECT_EQ(r.heldBack, 0);  // pulled towards the centre, nothing folds: every vertex at its site
  for (size_t i = 0; i < inside.size(); ++i) {
    EXPECT_EQ(r.uv[inside[i]], sites[i]);
    EXPECT_EQ(out.points[inside[i]], lift(w.mesh, w.domain, sites[i]));
  }
}

// Sites that moved past one another: moved all the way, the input's triangles would turn over
// (relocate wrote 146 such on the bumpy disk). The vertices go only as far as none folds.
TEST(Relocate, HoldsVerticesBackWhereTheirTrianglesWouldFold) {
  const WavyMap w(6);
  std::vector<int> inside;
  std::vector<Vec2> sites;
  insideVerticesAsSites(w, inside, sites);
  std::swap(sites[3], sites[10]);  // two sites that passed each other, far apart
  sites[5] = Vec2(0.5, 0.5) + 0.2 * (sites[5] - Vec2(0.5, 0.5));
  const Relocation r = relocate(w.mesh, w.domain, inside, sites);
  EXPECT_GT(r.heldBack, 0);
  const auto area = [](const Triangle& t, const std::vector<Vec2>& uv) {
    return triangleArea(uv[t[0]], uv[t[1]], uv[t[2]]);
  };
  for (const Triangle& t : w.mesh.triangles) EXPECT_GT(area(t, w.p.uv) * area(t, r.uv), 0);
  for (size_t i = 0; i < inside.size(); ++i)
    if (r.uv[inside[i]] == sites[i]) EXPECT_EQ(r.mesh.points[inside[i]], lift(w.mesh, w.domain, sites[i]));
}

TEST(Retriangulate, GivesAValidDiskWithAllSitesUsed) {
  const WavyMap w(8);
  std::vector<Vec2> border, sites;
  for (int v : w.p.boundaryLoop) border.push_back(w.p.uv[v]);
  for (int i = 0; i < 40; ++i)
    sites.push_back(Vec2(0.5, 0.5) + 0.3 * (i / 40.0) * Vec2(std::cos(i * 2.4), std::sin(i * 2.4)));
  const Mesh out = retriangulate(w.mesh, w.domain, border, sites, "test").mesh;
  EXPECT_EQ(out.vertexCount(), static_cast<int>(border.size() + sites.size()));
  EXPECT_NO_THROW(validateMesh(out, "out"));
  EXPECT_TRUE(analyzeTopology(out).isDisk());
  // Euler: a disk with V vertices, B on the border, has 2V - B - 2 triangles.
  EXPECT_EQ(out.faceCount(), 2 * out.vertexCount() - static_cast<int>(border.size()) - 2);
}

// Border points given (a chart's samples, InitialSites::fixedPoints) are taken as they are,
// not lifted through the map.
TEST(Retriangulate, TakesTheBorderPointsGiven) {
  const WavyMap w(8);
  std::vector<Vec2> border;
  std::vector<Vec3> points;
  for (int v : w.p.boundaryLoop) {
    border.push_back(w.p.uv[v]);
    points.push_back(w.mesh.points[v] + Vec3(0, 0, 1));  // not where the map lifts it
  }
  const Mesh out = retriangulate(w.mesh, w.domain, border, {Vec2(0.5, 0.5)}, "test", points).mesh;
  for (size_t i = 0; i < border.size(); ++i) EXPECT_EQ(out.points[i], points[i]);
  const Mesh lifted = retriangulate(w.mesh, w.domain, border, {Vec2(0.5, 0.5)}, "test").mesh;
  EXPECT_NEAR((lifted.points[0] - points[0]).norm(), 1.0, 1e-9);
}

TEST(Retriangulate, RespectsANonConvexBorder) {
  // L-shaped border: without constraints the Delaunay triangulation would fill the notch.
  const std::vector<Vec2> border = {{0, 0}, {1, 0}, {1, 0.5}, {0.5, 0.5}, {0.5, 1}, {0, 1}};
  const std::vector<Triangle> triangles = triangulateSites(border, {{0.25, 0.25}});
  double area = 0;
  auto point = [&](int i) { return i < 6 ? border[i] : Vec2(0.25, 0.25); };
  for (const Triangle& t : triangles) area += triangleArea(point(t[0]), point(t[1]), point(t[2]));
  EXPECT_NEAR(area, 0.75, 1e-12);
}

TEST(Retriangulate, ABorderThatCrossesItselfIsAnErrorNotACrash) {
  const std::vector<Vec2> bowtie = {{0, 0}, {1, 1}, {1, 0}, {0, 1}};
  EXPECT_THROW(triangulateSites(bowtie, {{0.5, 0.2}}), Error);
}

// Border samples at the same place (where a map squeezed part of the border to a point) made a
// constraint from a vertex to itself, which crashed CGAL's triangulation. The last stands for
// both.
TEST(Retriangulate, BorderSamplesAtTheSamePlaceAreOneVertex) {
  const std::vector<Vec2> border = {{0, 0}, {1, 0}, {1, 0}, {1, 0}, {1, 1}, {0, 1}};
  const std::vector<Triangle> triangles = triangulateSites(border, {{0.5, 0.5}});
  double area = 0;
  auto point = [&](int i) { return i < 6 ? border[i] : Vec2(0.5, 0.5); };
  std::set<int> used;
  for (const Triangle& t : triangles) {
    area += triangleArea(point(t[0]), point(t[1]), point(t[2]));
    used.insert(t.begin(), t.end());
  }
  EXPECT_NEAR(area, 1.0, 1e-12);
  EXPECT_EQ(used, (std::set<int>{0, 3, 4, 5, 6}));
}

// A border of fewer than 3 samples (a handful of sites asked for) crashed CGAL's triangulation;
// retriangulate()'s errors name the input.
TEST(Retriangulate, ABorderOfFewerThanThreeSamplesIsAnError) {
  const WavyMap w(8);
  const auto problem = [&](const std::vector<Vec2>& border) -> std::string {
    try {
      retriangulate(w.mesh, w.domain, border, {Vec2(0.5, 0.3)}, "m.off");
    } catch (const Error& e) {
      return e.what();
    }
    return "no error";
  };
  EXPECT_EQ(problem({Vec2(0.7, 0.05)}), "m.off: the border of the parameter domain has 1 sample (3 at least)");
  EXPECT_EQ(problem({Vec2(0.7, 0.05), Vec2(0.2, 0.9)}),
            "m.off: the border of the parameter domain has 2 samples (3 at least)");
  EXPECT_EQ(problem({Vec2(0.1, 0.1), Vec2(0.9, 0.9), Vec2(0.9, 0.1), Vec2(0.1, 0.9)}),
            "m.off: the border of the parameter domain crosses itself");
}
