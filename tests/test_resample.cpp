#include "mesh_io.h"
#include "metrics.h"
#include "pipeline.h"
#include "resample.h"
#include "sites.h"
#include "test_support.h"
#include "topology.h"

#include <algorithm>

using namespace lloydscope;

TEST(Resample, GivesAWellShapedDiskWhoseVerticesLieOnTheInput) {
  const Mesh input = readMesh(test::assetPath("bumpy_disk.off")).mesh;
  SiteOptions sites;
  sites.count = 400;
  const Resampling r = resample(input, sites, {}, {}, "bumpy");
  const Mesh& m = r.mesh.mesh;
  EXPECT_NO_THROW(validateMesh(m, "resampled"));
  EXPECT_TRUE(analyzeTopology(m).isDisk());
  EXPECT_NEAR(m.vertexCount(), 400, 4);
  EXPECT_GT(measureQuality(m).minAngle, measureQuality(input).minAngle + 10);
  for (int v = 0; v < m.vertexCount(); ++v)
    EXPECT_LT((m.points[v] - lift(input, r.domain, r.mesh.uv[v])).norm(), 1e-12);
  // A point inside a resampled triangle maps onto the input surface, not onto the chord.
  const Eigen::Vector3d middle(1.0 / 3, 1.0 / 3, 1.0 / 3);
  const Triangle& t = m.triangles[0];
  const Vec2 uv = (r.mesh.uv[t[0]] + r.mesh.uv[t[1]] + r.mesh.uv[t[2]]) / 3.0;
  EXPECT_LT((r.toInput(input, 0, middle) - lift(input, r.domain, uv)).norm(), 1e-12);
}

TEST(Resample, TheRemeshedOutputLiesOnTheInputSurface) {
  // The sphere cap's vertices lie on the unit sphere; points of its triangles are within the
  // sagitta of its (finer) triangles, a chord of the resampled surface would be much deeper.
  const Mesh input = readMesh(test::assetPath("sphere_cap.off")).mesh;
  RemeshOptions o;
  o.sites.count = 150;
  o.measureFidelity = false;
  o.fit = false;  // the fit moves vertices off the input, on purpose
  const RemeshResult r = remesh(input, o, "cap");
  double deepest = 0, highest = 0, inputSagitta = 0;
  for (const Vec3& p : r.output.points) {
    deepest = std::max(deepest, 1.0 - p.norm());
    highest = std::max(highest, p.norm() - 1.0);  // the input's triangles are chords: inside
  }
  double inputHighest = 0;  // the file's vertices are on the sphere to its 7 digits
  for (const Vec3& p : input.points) inputHighest = std::max(inputHighest, p.norm() - 1.0);
  EXPECT_LE(highest, inputHighest + 1e-12);
  for (const Triangle& t : input.triangles)
    inputSagitta = std::max(
        inputSagitta, 1.0 - ((input.points[t[0]] + input.points[t[1]] + input.points[t[2]]) / 3).norm());
  EXPECT_LE(deepest, inputSagitta);
}

TEST(Sites, AChamferedCornerGivesOneBorderSampleNotTwo) {
  // A square with its top-right corner cut off: two border corners of 135 degrees, 0.07
  // apart, closer than half the spacing of 50 sites (0.15): only one of them is a sample.
  Mesh m = test::grid(20);
  auto at = [](int i, int j) { return j * 21 + i; };
  m.triangles.resize(m.triangles.size() - 2);  // the top-right cell's two triangles
  m.triangles.push_back({at(19, 19), at(20, 19), at(19, 20)});
  const Mesh cleaned = assemble(m.triangles, m.points);
  const Parameterization p = parameterize(cleaned, {ParamMethod::Lscm, Border::Circle}, "chamfered");
  const Domain domain(p.uv, cleaned.triangles, {});
  SiteOptions o;
  o.count = 50;
  const InitialSites sites = initialSites(cleaned, p, domain, o, "m.off");
  const double spacing = std::sqrt(2.0 * surfaceArea(cleaned) / (std::sqrt(3.0) * 50));
  const size_t n = sites.fixed.size();
  ASSERT_GT(n, 2u);
  for (size_t i = 0; i < n; ++i) {
    const Vec3 a = lift(cleaned, domain, sites.fixed[i]);
    const Vec3 b = lift(cleaned, domain, sites.fixed[(i + 1) % n]);
    EXPECT_GT((b - a).norm(), 0.5 * spacing) << "samples " << i << " and " << i + 1 << " at "
                                             << a.transpose() << " / " << b.transpose();
  }
}

// A flat 24-gon of 49 vertices remeshed to 400: the first pass has 49 sites (no more than the
// input's vertices), so its border is as coarse as the input's and, where the input's turns by
// less than a corner (15 degrees against 20: sites.cpp), cuts inside; the result's 50 or so
// border vertices were lifted onto those chords (Hausdorff distance 0.63% of the diagonal, at
// the input's border). They go onto the input's own border now (Resampling::borderToInput;
// 0.22%, where the result's border edges cut the input's corners).
TEST(Resample, TheBorderOfACoarseInputRefinedStaysOnItsBorder) {
  Mesh polygon;
  polygon.points.push_back(Vec3::Zero());
  constexpr int kSides = 24;
  for (double radius : {0.5, 1.0})
    for (int i = 0; i < kSides; ++i)
      polygon.points.push_back(radius * Vec3(std::cos(2 * M_PI * i / kSides), std::sin(2 * M_PI * i / kSides), 0));
  for (int i = 0; i < kSides; ++i) {
    const int inner = 1 + i, next = 1 + (i + 1) % kSides;  // outer ones: kSides more
    polygon.triangles.push_back({0, inner, next});
    polygon.triangles.push_back({inner, inner + kSides, next + kSides});
    polygon.triangles.push_back({inner, next + kSides, next});
  }
  ASSERT_TRUE(analyzeTopology(polygon).isDisk());
  RemeshOptions o;
  o.sites.count = 400;
  o.measureFidelity = false;
  o.fit = false;  // which then moves the border across itself (core/fit): this is about the lift
  const RemeshResult r = remesh(polygon, o, "24-gon");
  const VertexEdges edges = vertexEdges(r.output);
  int onBorder = 0;
  for (int v = 0; v < r.output.vertexCount(); ++v) {
    if (!edges.onBoundary[v]) continue;
    ++onBorder;
    double nearest = INFINITY;  // to the polygon's sides
    for (int i = 0; i < kSides; ++i) {
      const Vec3 &a = polygon.points[1 + kSides + i], &b = polygon.points[1 + kSides + (i + 1) % kSides];
      const double t = std::clamp((r.output.points[v] - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
      nearest = std::min(nearest, (r.output.points[v] - (a + t * (b - a))).norm());
    }
    EXPECT_LT(nearest, 1e-9) << "border vertex " << v << " at " << r.output.points[v].transpose();
  }
  EXPECT_GT(onBorder, 30);
}

// A rectangle whose bottom border has a narrow bump (0.006 deep, a Gaussian 0.015 wide; no
// vertex of it turns by more than 16 degrees, so none is a corner), remeshed to 300 vertices
// (0.04 apart): the border edge between the samples around the bump cut it off (Hausdorff
// distance 0.46% of the diagonal, there). Its tip is a sample now (keepBumps in sites.cpp;
// 0.20%).
TEST(Sites, ANarrowBumpOfTheBorderIsKept) {
  constexpr int kColumns = 200, kRows = 20;
  Mesh m = test::grid(kColumns);  // (kColumns + 1)^2 points; the first kRows + 1 rows used
  m.points.resize((kColumns + 1) * (kRows + 1));
  m.triangles.resize(2 * kColumns * kRows);
  const auto bump = [](double x) { return -0.006 * std::exp(-std::pow((x - 0.5) / 0.015, 2)); };
  for (Vec3& p : m.points) {
    const double row = p.y() * kColumns / kRows;  // 0 at the bottom, 1 at the top
    p.y() = 0.5 * row + (1 - row) * bump(p.x());
  }
  RemeshOptions o;
  o.sites.count = 300;
  o.measureFidelity = false;
  const RemeshResult r = remesh(m, o, "bump");
  EXPECT_LT(test::nearestDistance(r.output.points, Vec3(0.5, bump(0.5), 0)), 1e-9);
}

// As above, but the map turns by 30 degrees at a border vertex 0.02 from the bump's tip (the
// surface does not): a corner of the map alone, kept as a sample, was closer than 0.7 spacings
// to the tip and kept it out (CGAL's blobby clipped in half: Hausdorff 0.309 against CGAL's
// 0.251% at 2000). It gives way to the tip now.
TEST(Sites, ACornerOfTheMapAloneGivesWayToABumpOfTheBorder) {
  constexpr int kColumns = 200, kRows = 20;
  Mesh m = test::grid(kColumns);
  m.points.resize((kColumns + 1) * (kRows + 1));
  m.triangles.resize(2 * kColumns * kRows);
  const auto bump = [](double x) { return -0.006 * std::exp(-std::pow((x - 0.5) / 0.015, 2)); };
  for (Vec3& p : m.points) {
    const double row = p.y() * kColumns / kRows;
    p.y() = 0.5 * row + (1 - row) * bump(p.x());
  }
  Parameterization p = parameterize(m, {ParamMethod::Lscm, Border::Circle}, "bump");
  const int kink = 104;  // the border vertex at x = 0.52, on the bottom row
  ASSERT_TRUE(p.onBoundary[kink]);
  const Vec2 along = (p.uv[kink + 1] - p.uv[kink - 1]).normalized();
  p.uv[kink] += 0.6 * (p.uv[kink + 1] - p.uv[kink]).norm() * Vec2(along.y(), -along.x());  // outwards
  const Domain domain(p.uv, m.triangles, {});
  SiteOptions o;
  o.count = 300;
  const InitialSites sites = initialSites(m, p, domain, o, "m.off");
  EXPECT_LT(test::nearestDistance(sites.fixedPoints, Vec3(0.5, bump(0.5), 0)), 1e-9);
}
