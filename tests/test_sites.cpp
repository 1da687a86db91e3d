#include "density.h"
#include "mesh_io.h"
#include "pipeline.h"
#include "sites.h"
#include "test_support.h"
#include "topology.h"

#include <algorithm>
#include <cmath>

using namespace lloydscope;

// A converged tessellation of density rho has about sqrt(rho) sites per unit area in 2D
// (Gersho): the first sites are drawn that way. Drawn by rho itself, the half with 4 times the
// density got 4 times the sites instead of 2 (on a cut knot: every site at one end).
TEST(Sites, InsideSitesAreDrawnBySqrtOfTheDensity) {
  const Mesh grid = test::grid(20);
  const Parameterization param = parameterize(grid, {ParamMethod::Tutte, Border::Square, {}}, "grid");
  std::vector<double> rho(grid.vertexCount());
  for (int v = 0; v < grid.vertexCount(); ++v) rho[v] = param.uv[v].x() < 0.5 ? 4.0 : 1.0;
  const Domain domain(param.uv, grid.triangles, vertexDensity(grid.triangles, rho));
  SiteOptions o;
  o.count = 4000;
  const InitialSites sites = initialSites(grid, param, domain, o, "m.off");
  int left = 0, right = 0;
  for (const Vec2& p : sites.movable) {
    if (p.x() < 0.45) ++left;
    if (p.x() > 0.55) ++right;
  }
  ASSERT_GT(right, 0);
  EXPECT_NEAR(double(left) / right, 2.0, 0.25);
}

// The border sampled at the spacing of the vertices asked: fewer than three samples (a spike
// far taller than its border is wide) or over ten times the vertices asked (a strip far longer
// than wide) is an error naming the mesh. For the first it says how many would take three, and
// that many do.
TEST(Sites, ABorderFarTooShortOrTooLongForTheVerticesAskedIsAnError) {
  const auto sitesOn = [](const Mesh& m, int count) {
    const Parameterization param = parameterize(m, {ParamMethod::Tutte, Border::Square, {}}, "m.off");
    const Domain domain(param.uv, m.triangles, vertexDensity(m.triangles, std::vector<double>(m.vertexCount(), 1.0)));
    SiteOptions o;
    o.count = count;
    return initialSites(m, param, domain, o, "m.off");
  };
  Mesh spike = test::grid(2);
  spike.points[4].z() = 1000;
  std::string problem;
  try {
    sitesOn(spike, 20);
  } catch (const Error& e) {
    problem = e.what();
  }
  ASSERT_EQ(problem.rfind("m.off: at the spacing of 20 vertices its border takes 1 sample (3 at least)", 0), 0u) << problem;
  const size_t about = problem.find("about ");
  ASSERT_NE(about, std::string::npos) << problem;
  const int enough = std::stoi(problem.substr(about + 6));
  EXPECT_GT(enough, 1000);
  EXPECT_GE(sitesOn(spike, enough).fixed.size(), 3u);
  spike.points[4].z() = 1e7;  // past the million vertices a run takes, it says so
  try {
    sitesOn(spike, 20);
  } catch (const Error& e) {
    problem = e.what();
  }
  EXPECT_NE(problem.find("; it would take more than the 1000000 vertices a run may be asked for"), std::string::npos) << problem;
  Mesh strip = test::grid(8);
  for (Vec3& p : strip.points) p.x() *= 1000;  // border 2002, area 1000
  EXPECT_THROW(sitesOn(strip, 20), Error);     // its border takes 263 at their spacing
  EXPECT_GT(sitesOn(strip, 100).fixed.size(), 200u);  // 587, under 1000
}

// A sphere with a small hole (a quad) mapped to a square, at 200 sites: its border takes 3 samples
// by their spacing, and their triangle was half the square; the sites in the other half were in
// no triangle of the result (2000 asked of such a sphere gave 875 vertices). The border is now
// sampled until it follows the map's border within half a spacing: the samples' polygon covers
// the square.
TEST(Sites, TheBorderSamplesCoverTheMap) {
  Mesh sphere = test::cube(8, true);
  sphere.triangles.erase(sphere.triangles.begin(), sphere.triangles.begin() + 2);  // a quad: 4 border vertices
  const Parameterization param = parameterize(sphere, {ParamMethod::Tutte, Border::Square, {}}, "m.off");
  const Domain domain(param.uv, sphere.triangles, vertexDensity(sphere.triangles, std::vector<double>(sphere.vertexCount(), 1.0)));
  double mapArea = 0;
  for (const Triangle& t : sphere.triangles) mapArea += std::abs(triangleArea(param.uv[t[0]], param.uv[t[1]], param.uv[t[2]]));
  SiteOptions o;
  o.count = 200;
  const std::vector<Vec2> border = initialSites(sphere, param, domain, o, "m.off").fixed;
  double polygonArea = 0;
  for (size_t i = 0; i < border.size(); ++i) {
    const Vec2 &a = border[i], &b = border[(i + 1) % border.size()];
    polygonArea += 0.5 * (a.x() * b.y() - a.y() * b.x());
  }
  EXPECT_GT(std::abs(polygonArea), 0.95 * mapArea) << border.size() << " samples";
}

// A border vertex asked to be kept (SiteOptions::keptBorderPoints: a corner a result cut off)
// is a sample, where the even spacing puts none: the grid's side is sampled about every 0.07,
// and (0.35, 0) is on no sample until asked.
TEST(Sites, BorderPointsAskedForAreSamples) {
  const Mesh grid = test::grid(20);
  const Parameterization param = parameterize(grid, {ParamMethod::Tutte, Border::Square, {}}, "grid");
  const Domain domain(param.uv, grid.triangles, vertexDensity(grid.triangles, std::vector<double>(grid.vertexCount(), 1.0)));
  SiteOptions o;
  o.count = 500;
  const Vec3 corner(0.35, 0, 0);
  const auto sampled = [&] {
    const std::vector<Vec3> points = initialSites(grid, param, domain, o, "grid").fixedPoints;
    return std::any_of(points.begin(), points.end(), [&](const Vec3& p) { return (p - corner).norm() < 1e-9; });
  };
  EXPECT_FALSE(sampled());
  o.keptBorderPoints = {corner + Vec3(1e-8, 0, 0)};  // within a millionth of the diagonal
  EXPECT_TRUE(sampled());
}

// Charts of one surface (core/charts) sample their shared borders at one spacing, whatever
// their own number of sites: the unit square's border (length 4) at 0.1 is 40 samples.
TEST(Sites, TheBorderSpacingCanBeGiven) {
  const Mesh grid = test::grid(20);
  const Parameterization param = parameterize(grid, {ParamMethod::Tutte, Border::Square, {}}, "grid");
  const Domain domain(param.uv, grid.triangles, vertexDensity(grid.triangles, std::vector<double>(grid.vertexCount(), 1.0)));
  SiteOptions o;
  o.count = 500;  // its own spacing would be about 0.068: 59 samples
  EXPECT_GT(initialSites(grid, param, domain, o, "m.off").fixed.size(), 50u);
  o.spacing = 0.1;
  const InitialSites sites = initialSites(grid, param, domain, o, "m.off");
  EXPECT_EQ(sites.fixed.size(), 40u);
  EXPECT_EQ(sites.fixed.size() + sites.movable.size(), 500u);
}

// A notch one grid cell wide in the square's top side: four corners 0.6 spacings apart. A corner
// closer than 0.7 spacings to a sharper one is no sample, so that no border edge is much
// shorter than the spacing (a triangle on a border edge half a spacing long has an angle under
// 30 degrees). The shortest left here is 0.72 spacings; at 0.5, 0.6.
TEST(Sites, CornersCloseTogetherMakeNoShortBorderEdge) {
  Mesh notched = test::grid(20);
  notched.triangles.erase(notched.triangles.begin() + 2 * (19 * 20 + 10), notched.triangles.begin() + 2 * (19 * 20 + 11));
  ASSERT_TRUE(analyzeTopology(notched).isDisk());
  const Parameterization param = parameterize(notched, {ParamMethod::Lscm, Border::Circle, {}}, "notched");
  const Domain domain(param.uv, notched.triangles, vertexDensity(notched.triangles, std::vector<double>(notched.vertexCount(), 1.0)));
  SiteOptions o;
  o.count = 150;
  o.spacing = 0.05 / 0.6;
  const InitialSites sites = initialSites(notched, param, domain, o, "m.off");
  ASSERT_GT(sites.fixedPoints.size(), 10u);
  for (size_t i = 0; i < sites.fixedPoints.size(); ++i) {
    const Vec3& next = sites.fixedPoints[(i + 1) % sites.fixedPoints.size()];
    EXPECT_GT((next - sites.fixedPoints[i]).norm(), 0.66 * o.spacing) << "sample " << i;
  }
}

// Each border sample's point is on a border edge of the mesh itself, interpolated in 3D: where
// the sample of a neighbouring chart on the same edge is, whatever the map does there.
TEST(Sites, FixedPointsLieOnTheBorderEdges) {
  Mesh grid = test::grid(10);
  for (Vec3& p : grid.points) p.z() = std::sin(3 * p.x()) * std::cos(2 * p.y());
  const Parameterization param = parameterize(grid, {ParamMethod::Tutte, Border::Circle, {}}, "grid");
  const Domain domain(param.uv, grid.triangles, vertexDensity(grid.triangles, std::vector<double>(grid.vertexCount(), 1.0)));
  SiteOptions o;
  o.count = 300;
  const InitialSites sites = initialSites(grid, param, domain, o, "m.off");
  ASSERT_EQ(sites.fixedPoints.size(), sites.fixed.size());
  ASSERT_GT(sites.fixedPoints.size(), 2u);
  const std::vector<int>& loop = param.boundaryLoop;
  for (const Vec3& p : sites.fixedPoints) {
    double nearest = INFINITY;
    for (size_t i = 0; i < loop.size(); ++i) {
      const Vec3 &a = grid.points[loop[i]], &b = grid.points[loop[(i + 1) % loop.size()]];
      const double t = std::clamp((p - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
      nearest = std::min(nearest, (a + t * (b - a) - p).norm());
    }
    EXPECT_LT(nearest, 1e-12);
  }
}

// A grid with a hole of one missing triangle, far smaller than the spacing of 35 sites: the
// cut joins it to the border at one node, and it still comes back as a hole.
TEST(Sites, AHoleSmallerThanTheSpacingStaysAHole) {
  Mesh holed = test::grid(12);
  holed.triangles.erase(holed.triangles.begin() + 2 * (6 * 12 + 6));
  ASSERT_EQ(analyzeTopology(holed).boundaryLoops.size(), 2u);
  RemeshOptions o;
  o.sites.count = 35;
  o.measureFidelity = false;
  const RemeshResult r = remesh(holed, o, "holed");
  EXPECT_NO_THROW(validateMesh(r.output, "output"));
  const Topology t = analyzeTopology(r.output);
  EXPECT_EQ(t.genus, 0);
  EXPECT_EQ(t.boundaryLoops.size(), 2u);
}

// A star of 30 sharp spikes (12 degrees), at 400 vertices: its border sampled at the inside's
// spacing took 750 samples, and none was left inside (the result: fans of slivers around the
// centre). Sampled at the spacing at which border and inside together make the count, it takes
// 420 (its tips' samples graded), and the inside 205.
TEST(Sites, ABorderLongerThanTheInsideTakesNotEveryVertex) {
  const Mesh star = test::starDisk(30, 0.5, 10);
  const Parameterization param = parameterize(star, {ParamMethod::MeanValue, Border::Circle, {}}, "star");
  const Domain domain(param.uv, star.triangles, vertexDensity(star.triangles, std::vector<double>(star.vertexCount(), 1.0)));
  SiteOptions o;
  o.count = 400;
  const InitialSites sites = initialSites(star, param, domain, o, "star");
  EXPECT_LT(sites.fixed.size(), 500u);
  EXPECT_GT(sites.movable.size(), 150u);
}

// A tall cone of 32 border vertices and its apex: its LSCM map squashes it into a lens, and the
// border, sampled until it follows the lens, took every site asked (33 of 33), none was left
// inside, and the result was a flat disk 99.6% of the diagonal from the input. The inside keeps
// what a border sampled by its length would leave it, and the apex is there.
TEST(Sites, ASquashedBorderLeavesSitesInside) {
  Mesh cone;
  cone.points.push_back(Vec3(0, 0, 30));
  for (int i = 0; i < 32; ++i) cone.points.push_back(Vec3(std::cos(2 * M_PI * i / 32), std::sin(2 * M_PI * i / 32), 0));
  for (int i = 0; i < 32; ++i) cone.triangles.push_back({0, 1 + i, 1 + (i + 1) % 32});
  const RemeshResult r = remesh(cone, RemeshOptions{}, "cone.off");
  EXPECT_GT(r.recording.iterations.front().sites.size(), 10u);  // movable sites
  EXPECT_LT(r.fidelity.hausdorffPercent, 10);
  double top = 0;
  for (const Vec3& p : r.output.points) top = std::max(top, p.z());
  EXPECT_GT(top, 25);
}

// A stretch of the border is sampled evenly between corners, but graded towards a corner under
// 30 degrees: each gap about the wedge's width there, from half a spacing out.
TEST(Sites, TheBorderIsSampledCloserTowardsASharpCorner) {
  const std::vector<double> even = borderSamplePositions(10, 1, 10, 90, 180);
  ASSERT_EQ(even.size(), 10u);
  for (size_t i = 0; i < even.size(); ++i) EXPECT_DOUBLE_EQ(even[i], static_cast<double>(i));
  const std::vector<double> graded = borderSamplePositions(10, 1, 10, 20, 180);
  ASSERT_GT(graded.size(), 4u);
  EXPECT_EQ(graded[0], 0.0);  // the corner itself
  EXPECT_GE(graded[1], 0.5);
  EXPECT_LT(graded[1], 1.0);
  const double ratio = 1 + 2.5 * std::sin(10 * M_PI / 180);
  EXPECT_NEAR(graded[2] / graded[1], ratio, 1e-12);  // a geometric progression from the corner
  EXPECT_NEAR(graded[3] / graded[2], ratio, 1e-12);
  for (size_t i = 2; i < graded.size(); ++i) {  // the gaps the wedge's width, up to about a spacing
    EXPECT_GT(graded[i] - graded[i - 1], 0.2) << i;
    EXPECT_LT(graded[i] - graded[i - 1], 1.5) << i;
  }
  EXPECT_NEAR(graded.back() + (graded.back() - graded[graded.size() - 2]), 10.0, 1e-9);  // evenly to the end
  EXPECT_NEAR(graded[graded.size() - 1] - graded[graded.size() - 2], 1.0, 0.3);
}

// Two sharp corners of different angles at the two ends of a short stretch: their graded
// samples met mid-stretch 0.005 spacings apart, a sliver of a border edge (found by review).
TEST(Sites, GradedSamplesFromTwoSharpCornersKeepApart) {
  for (const auto& [length, begin, end] : {std::tuple{5.518, 13.0, 20.0}, std::tuple{4.608, 20.0, 25.0},
                                           std::tuple{3.0, 10.0, 29.0}, std::tuple{1.2, 20.0, 20.0}}) {
    const std::vector<double> at = borderSamplePositions(length, 1, std::max(1, static_cast<int>(std::lround(length))), begin, end);
    EXPECT_EQ(at[0], 0.0);
    // No gap under the smallest a progression makes (half a spacing times its least ratio 1.25,
    // less one).
    for (size_t i = 1; i < at.size(); ++i) EXPECT_GE(at[i] - at[i - 1], 0.12) << length << " " << i;
    EXPECT_GE(length - at.back(), 0.12) << length;
  }
}
