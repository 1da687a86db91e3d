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
  const InitialSites sites = initialSites(input, param, domain, {}, "m.off");
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

TEST(Polish, BorderVerticesSlideAlongTheBorderOutOfASharpCornersStrip) {
  // Sampled evenly into a 34-degree corner, the border makes a strip of triangles across the
  // wedge with a 25-degree angle next to the corner's ear: a border vertex slid towards the
  // corner makes it 34.
  const Mesh input = test::sector(34);
  const Parameterization param = parameterize(input, {}, "sector");
  const Domain domain(param.uv, input.triangles, {});
  SiteOptions sites;
  sites.count = 100;
  const InitialSites start = initialSites(input, param, domain, sites, "m.off");
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
