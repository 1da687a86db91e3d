#include "isotropic.h"
#include "mesh_io.h"
#include "pipeline.h"
#include "simplify.h"
#include "test_support.h"
#include "topology.h"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <sstream>

using namespace lloydscope;

TEST(Pipeline, DefaultRetriangulationImprovesTheBumpyDisk) {
  const Mesh input = readMesh(test::assetPath("bumpy_disk.off")).mesh;
  const RemeshResult r = remesh(input, RemeshOptions{}, "bumpy_disk.off");
  EXPECT_TRUE(r.converged);
  EXPECT_NO_THROW(validateMesh(r.output, "output"));
  EXPECT_TRUE(analyzeTopology(r.output).isDisk());
  EXPECT_NEAR(r.output.vertexCount(), input.vertexCount(), 0.02 * input.vertexCount());
  // The issue's bar for a 1000-vertex disk, well inside what this mesh reaches.
  EXPECT_GE(r.after.avgMinAngle, 50.0);
  EXPECT_GE(r.after.minAngle, 20.0);
  EXPECT_LE(r.after.irregularBoundaryAware, 30.0);
  EXPECT_LE(r.fidelity.hausdorffPercent, 1.5);
  EXPECT_GT(r.after.avgMinAngle, r.before.avgMinAngle + 15);
  EXPECT_EQ(r.recording.iterations.size(), static_cast<size_t>(r.iterations));
}

// Half of CGAL's corner_poly: 11 vertices, planes meeting at right angles. Its first pass has
// as many vertices as the input (no finer), and LSCM squeezed an ear of that mesh's border to
// a point; the border samples of the run piled up there and CGAL's triangulation of the sites
// crashed, at any size asked.
TEST(Pipeline, ATinyInputWithCreasesIsRemeshedFiner) {
  Mesh input;
  input.points = {{2, 0, 1},  {2, 0, -1}, {1, 1, 1}, {1, 1, -1}, {0, 1, 1}, {0, 1, -1},
                  {1, 0, 1},  {1, 0, -1}, {2, 1, 1}, {2, 1, -1}, {2, 1, 0}};
  input.triangles = {{4, 2, 6}, {4, 6, 0}, {4, 0, 8}, {5, 9, 1}, {5, 1, 7}, {5, 7, 3}, {1, 9, 10},
                     {1, 10, 8}, {1, 8, 0}, {7, 1, 0}, {7, 0, 6}, {7, 6, 2}, {7, 2, 3}};
  RemeshOptions o;
  o.sites.count = 200;
  const RemeshResult r = remesh(input, o, "corner_poly_1.off");
  EXPECT_TRUE(analyzeTopology(r.output).isDisk());
  EXPECT_NEAR(r.output.vertexCount(), 200, 10);
  EXPECT_GE(r.after.minAngle, 30.0);
}

TEST(Pipeline, RelocateKeepsTheInputConnectivity) {
  const Mesh input = readMesh(test::assetPath("sphere_cap.off")).mesh;
  RemeshOptions o = referencePreset(RemeshMethod::Relocate);
  o.lloyd.maxIterations = 20;
  const RemeshResult r = remesh(input, o, "sphere_cap.off");
  EXPECT_EQ(r.output.triangles, input.triangles);
  EXPECT_EQ(r.after.irregularPercent, r.before.irregularPercent);
  EXPECT_GT(r.after.avgMinAngle, r.before.avgMinAngle);
  // Vertices stay on the unit sphere (lifted onto the input's triangles, inside its hull).
  for (const Vec3& p : r.output.points) EXPECT_NEAR(p.norm(), 1.0, 0.01);
}

// Run to convergence, the sites move past one another; the input's triangles, kept, must not
// turn over (77 of the sphere cap's 938 faced inwards): vertices stop short where they would.
TEST(Pipeline, RelocateTurnsNoTriangleOver) {
  const Mesh input = readMesh(test::assetPath("sphere_cap.off")).mesh;
  RemeshOptions o;
  o.method = RemeshMethod::Relocate;
  o.measureFidelity = false;
  const RemeshResult r = remesh(input, o, "sphere_cap.off");
  ASSERT_EQ(r.output.triangles, input.triangles);
  EXPECT_GT(r.heldBack, 0);
  for (const Triangle& t : r.output.triangles) {
    const Vec3* p = r.output.points.data();
    const Vec3 normal = (p[t[1]] - p[t[0]]).cross(p[t[2]] - p[t[0]]);
    EXPECT_GT(normal.dot(p[t[0]] + p[t[1]] + p[t[2]]), 0);  // outwards, as the cap's faces are
  }
}

TEST(Pipeline, SiteCountIsHonoured) {
  const Mesh input = readMesh(test::assetPath("sphere_cap.off")).mesh;
  RemeshOptions o;
  o.sites.count = 300;
  o.lloyd.maxIterations = 30;
  const RemeshResult r = remesh(input, o, "sphere_cap.off");
  EXPECT_EQ(r.output.vertexCount(), 300);
}

// The last steps raise the small angles they can (raiseSmallAngles): on the sphere cap at 500
// vertices, without that step, a triangle of 33 degrees is left; and the mean smallest angles
// (raiseMeanAngles): 55.25 degrees on average without that step.
TEST(Pipeline, LastStepsRaiseSmallAngles) {
  const Mesh input = readMesh(test::assetPath("sphere_cap.off")).mesh;
  RemeshOptions o;
  o.sites.count = 500;
  o.fit = false;  // which moves the vertices off the input
  o.measureFidelity = false;
  const RemeshResult r = remesh(input, o, "sphere_cap.off");
  EXPECT_GE(r.after.minAngle, 35.0);
  EXPECT_GT(r.after.avgMinAngle, 55.4);
}

TEST(Pipeline, EveryParameterizationWorksOnTheSphereCap) {
  const Mesh input = readMesh(test::assetPath("sphere_cap.off")).mesh;
  for (ParamMethod m : {ParamMethod::Authalic, ParamMethod::Conformal, ParamMethod::MeanValue,
                        ParamMethod::Tutte, ParamMethod::Lscm})
    for (DensityKind d : {DensityKind::Uniform, DensityKind::Area, DensityKind::Curvature}) {
      RemeshOptions o;
      o.param.method = m;
      o.density.kind = d;
      o.lloyd.maxIterations = 15;
      o.measureFidelity = false;
      const RemeshResult r = remesh(input, o, "sphere_cap.off");
      EXPECT_NO_THROW(validateMesh(r.output, "output")) << toString(m) << " " << toString(d);
      EXPECT_GT(r.after.avgMinAngle, 35.0) << toString(m) << " " << toString(d);
    }
}

TEST(Pipeline, ReferencePresetIsTheReportsSettings) {
  const RemeshOptions o = referencePreset(RemeshMethod::Retriangulate);
  EXPECT_EQ(o.param.method, ParamMethod::Authalic);
  EXPECT_EQ(o.param.border, Border::Square);
  EXPECT_EQ(o.density.kind, DensityKind::Uniform);
  EXPECT_TRUE(o.sites.fromInputVertices);
  EXPECT_EQ(o.lloyd.distanceThreshold, 1e-6);
  EXPECT_EQ(o.lloyd.percentThreshold, 5.0);
  EXPECT_EQ(o.lloyd.solver, CvtSolver::Lloyd);
}

// CGAL's disk-topology sample meshes (test::cgalSample), remeshed to 1000 vertices with the
// default settings.
struct SampleBar {
  const char* file;
  bool meetsIssueBar;  // irregular <= 15%, smallest angle >= 30, average >= 53 (issue 5)
};

class CgalSamples : public ::testing::TestWithParam<SampleBar> {};

// 1000 sites on CGAL's disk samples. The face mask and the mushroom meet the issue's bar; the
// three peaks did too (13.6% irregular) until the first sites were drawn by sqrt(rho), the
// density a converged tessellation has, and it came out at 15.7% (its 1000-vertex
// simplification in the bench still meets every bar). The lion head and the mannequin are
// closed shapes with a small hole, whose conformal maps shrink the far side by 10^3-10^4 (the
// mannequin's so much that it is slit open and stitched back): valid and far better than the
// input, with irregularity and angles short of the bar.
TEST_P(CgalSamples, RemeshTo1000Vertices) {
  const std::string path = test::cgalSample(GetParam().file);
  SKIP_UNLESS_EXTRACTED(path);
  const Mesh input = readMesh(path).mesh;
  RemeshOptions o;
  o.sites.count = 1000;
  o.measureFidelity = GetParam().meetsIssueBar;
  const RemeshResult r = remesh(input, o, path);
  EXPECT_NO_THROW(validateMesh(r.output, "output"));
  EXPECT_TRUE(analyzeTopology(r.output).isDisk());
  EXPECT_TRUE(r.converged);
  // Within 1.5%: the mannequin is slit open (core/cut.h), its seams' copies estimated.
  EXPECT_NEAR(r.output.vertexCount(), 1000, 15);
  EXPECT_GE(r.after.avgMinAngle, 52.0);
  EXPECT_LE(r.after.irregularBoundaryAware, 22.0);
  if (GetParam().meetsIssueBar) {
    EXPECT_LE(r.after.irregularBoundaryAware, 15.0);
    EXPECT_GE(r.after.minAngle, 30.0);
    EXPECT_GE(r.after.avgMinAngle, 53.0);
    EXPECT_LE(r.fidelity.hausdorffPercent, 2.5);
    EXPECT_FALSE(r.firstPassTrial.has_value());  // nothing missed: no second run
  }
}

INSTANTIATE_TEST_SUITE_P(Meshes, CgalSamples,
                         ::testing::Values(SampleBar{"nefertiti.off", true},
                                           SampleBar{"mushroom.off", true},
                                           SampleBar{"three_peaks.off", false},
                                           SampleBar{"lion-head.off", false},
                                           SampleBar{"mannequin-devil.off", false}),
                         [](const auto& info) {
                           std::string name = info.param.file;
                           name = name.substr(0, name.find('.'));
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name;
                         });

// CGAL's triceratops clipped in half (its lower half), remeshed to 1000 with one polish pass:
// with the first pass its result misses a bar; without, it meets the three and is closer to
// the input (0.79% of the diagonal against 0.94%).
TEST(Pipeline, ADiskThatMissesABarIsRemeshedWithoutTheFirstPassToo) {
  const std::string path = test::cgalSample("triceratops.off");
  SKIP_UNLESS_EXTRACTED(path);
  const Mesh input = test::lowerHalf(readMesh(path).mesh);
  ASSERT_TRUE(analyzeTopology(input).isDisk());
  RemeshOptions o;
  o.sites.count = 1000;
  o.polish = 1;
  const RemeshResult r = remesh(input, o, path);
  ASSERT_TRUE(r.firstPassTrial.has_value());
  EXPECT_LT(r.firstPassTrial->withBars, 3);
  EXPECT_EQ(r.firstPassTrial->withoutBars, 3);
  EXPECT_TRUE(r.firstPassTrial->keptWithout);
  EXPECT_GE(r.after.minAngle, 30.0);
  EXPECT_LE(r.after.irregularBoundaryAware, 15.0);
  EXPECT_GE(r.after.avgMinAngle, 53.0);
  EXPECT_EQ(r.fidelity.hausdorffPercent, r.firstPassTrial->withoutHausdorff);
  EXPECT_LT(r.firstPassTrial->withoutHausdorff, r.firstPassTrial->withHausdorff);
  EXPECT_GT(r.ms.compared, 0.0);  // the other run's time counts
}

// CGAL's dino (3916 vertices, closed) at 500: every map of it as it is collapses triangles at
// its tail's tip (rounding), and chart by chart its seams do not stitch; the run is made again
// on it simplified to 500 vertices, as --simplify 500 (which the error advised) does. It
// failed with that error. With --full-input it still fails, as it did.
TEST(Pipeline, AnInputThatFailsAsItIsIsRemeshedSimplified) {
  const std::string path = test::cgalSample("dino.off");
  SKIP_UNLESS_EXTRACTED(path);
  const Mesh input = readMesh(path).mesh;
  RemeshOptions o;
  o.sites.count = 500;
  o.polish = 1;
  const auto started = std::chrono::steady_clock::now();
  const RemeshResult r = remesh(input, o, path);
  const double wall = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - started).count();
  EXPECT_NE(r.fullInputFailed.find("the parameterization is not one-to-one"), std::string::npos) << r.fullInputFailed;
  EXPECT_EQ(r.fullInputFailed.find(path), std::string::npos);  // the problem, not the file's name again
  EXPECT_NEAR(r.output.vertexCount(), 500, 10);
  EXPECT_EQ(analyzeTopology(r.output).genus, 0);
  EXPECT_GT(r.fidelity.samples, 0);
  // The failed run's time counts: without it the total was the second run's, half the wall
  // clock's. (Not a speed test: both clocks time the same work.)
  EXPECT_GT(r.ms.total, 0.8 * wall);
  o.coarsenInput = false;  // --full-input: the input as it is, or nothing
  const std::string asItIs = test::errorOf([&] { remesh(input, o, path); }, "--full-input remeshed it");
  EXPECT_NE(asItIs.find("not one-to-one"), std::string::npos) << asItIs;
  EXPECT_EQ(asItIs.find("simplified to"), std::string::npos) << asItIs;
}

// The inspector's sessions start as remesh() makes its run: the dino at 500 as it is fails with
// and without the first pass, and its session is of it simplified to 500, saying why (Open mesh
// failed on it, while inspect remeshed it); a mesh that needs neither starts as asked.
TEST(Pipeline, ASessionStartsAsRemeshMakesItsRun) {
  const std::string path = test::cgalSample("dino.off");
  SKIP_UNLESS_EXTRACTED(path);
  RemeshOptions o;
  o.sites.count = 500;
  const StartedSession dino = startSession(readMesh(path).mesh, o, path);
  ASSERT_TRUE(dino.session);
  EXPECT_EQ(dino.used.simplifyTo, 500);
  EXPECT_TRUE(dino.used.resample);  // simplified, the first pass holds
  EXPECT_EQ(dino.resampleDropped, "");
  EXPECT_NE(dino.fullInputFailed.find("not one-to-one"), std::string::npos) << dino.fullInputFailed;
  const StartedSession cap = startSession(readMesh(test::assetPath("sphere_cap.off")).mesh, o, "cap");
  EXPECT_EQ(cap.used.simplifyTo, 0);
  EXPECT_TRUE(cap.used.resample);
  EXPECT_EQ(cap.resampleDropped + cap.fullInputFailed, "");
  // CGAL's triceratops at 2000: every map of its first resampling collapses a horn; its session
  // is made without that pass (as the inspector's own code did before).
  const std::string triceratops = test::cgalSample("triceratops.off");
  SKIP_UNLESS_EXTRACTED(triceratops);
  RemeshOptions simplified;
  simplified.simplifyTo = 2000;
  const StartedSession t = startSession(readMesh(triceratops).mesh, simplified, triceratops);
  EXPECT_FALSE(t.used.resample);
  EXPECT_NE(t.resampleDropped.find("not one-to-one"), std::string::npos) << t.resampleDropped;
  EXPECT_EQ(t.fullInputFailed, "");
  // LSCM alone folds the dino as it is and simplified: both problems, and the last one's advice.
  RemeshOptions lscm = o;
  lscm.param.method = ParamMethod::Lscm;
  const std::string both = test::errorOf([&] { startSession(readMesh(path).mesh, lscm, path); }, "LSCM's map of the dino held");
  EXPECT_NE(both.find("; simplified to 500 vertices first, it failed too: the parameterization is not one-to-one"),
            std::string::npos) << both;
  EXPECT_EQ(both.find("; try"), both.rfind("; try")) << both;  // once, last
  // Two components: tried once, its own refusal (it was tried four times, and both failures said).
  Mesh two = readMesh(test::assetPath("sphere_cap.off")).mesh;
  append(two, test::grid(6));
  const std::string twoRefused = test::errorOf([&] { startSession(two, o, "two"); }, "a session of two components");
  EXPECT_NE(twoRefused.find("a session steps one surface"), std::string::npos) << twoRefused;
  EXPECT_EQ(twoRefused.find("simplified to"), std::string::npos) << twoRefused;
  o.coarsenInput = false;  // --full-input: the first try's error, the simplified one not tried
  const std::string asItIs = test::errorOf([&] { startSession(readMesh(path).mesh, o, path); }, "--full-input started a session");
  EXPECT_NE(asItIs.find("not one-to-one"), std::string::npos) << asItIs;
  EXPECT_EQ(asItIs.find("simplified to"), std::string::npos) << asItIs;
}

// CGAL's lion head as it comes (8356 vertices, simplified to 3500 first) at 350 vertices: a
// nearly closed disk, remeshed slit open and whole, the slit kept; it misses a bar, and is
// remeshed without the first pass both ways again, and missing it still, chart by chart (not
// kept): five runs, which the result counts.
TEST(Pipeline, ANearlyClosedDiskThatMissesABarCountsFiveRuns) {
  const std::string path = test::cgalSample("lion-head.off");
  SKIP_UNLESS_EXTRACTED(path);
  RemeshOptions o;
  o.sites.count = 350;
  const RemeshResult r = remesh(readMesh(path).mesh, o, path);
  ASSERT_TRUE(r.slitTrial.has_value());
  ASSERT_TRUE(r.firstPassTrial.has_value());
  EXPECT_TRUE(r.firstPassTrial->failed.empty()) << r.firstPassTrial->failed;
  EXPECT_GT(r.cut.seamEdges, 0);  // slit open, whichever pass was kept
  ASSERT_TRUE(r.chartTrial.has_value());
  EXPECT_TRUE(r.chartTrial->forBars);
  EXPECT_EQ(r.charts, 0);
  EXPECT_EQ(r.runs, 5);
  // Neither trial's other run met more bars: the distances, which would not have decided, were
  // not measured (a run's last measure is a tenth of it on a large input).
  EXPECT_LE(r.firstPassTrial->withoutBars, r.firstPassTrial->withBars);
  EXPECT_EQ(r.firstPassTrial->withoutHausdorff, 0.0);
  EXPECT_LE(r.chartTrial->chartsBars, r.chartTrial->oneCutBars);
  EXPECT_EQ(r.chartTrial->chartsHausdorff, 0.0);
  EXPECT_GT(r.fidelity.hausdorffPercent, 0.0);  // the result's own, as asked
}

// Where the run without the first pass fails, the first stands: CGAL's armadillo clipped in half
// across x, remeshed to 500 with LSCM asked for and one polish pass, misses a bar, and LSCM of
// the input itself folds (6 triangles flipped).
TEST(Pipeline, TheFirstPassStandsWhereTheRunWithoutFails) {
  const std::string path = test::cgalSample("armadillo.off");
  SKIP_UNLESS_EXTRACTED(path);
  const Mesh input = test::lowerHalf(readMesh(path).mesh, 0);
  ASSERT_TRUE(analyzeTopology(input).isDisk());
  RemeshOptions o;
  o.sites.count = 500;
  o.param.method = ParamMethod::Lscm;
  o.polish = 1;
  o.measureFidelity = false;
  RemeshResult r;
  ASSERT_NO_THROW(r = remesh(input, o, path));
  ASSERT_TRUE(r.firstPassTrial.has_value());
  EXPECT_NE(r.firstPassTrial->failed.find("not one-to-one"), std::string::npos) << r.firstPassTrial->failed;
  EXPECT_FALSE(r.firstPassTrial->keptWithout);
  EXPECT_LT(r.firstPassTrial->withBars, 3);
  EXPECT_NEAR(r.output.vertexCount(), 500, 25);
}

// Without the polish (--polish -1, the bench's row that shows what it buys) a run that misses
// the bars is left as it is.
TEST(Pipeline, OnlyAPolishedRunIsTriedWithoutTheFirstPass) {
  RemeshOptions o;
  o.sites.count = 60;
  o.measureFidelity = false;
  const Mesh grid = test::grid(8);
  EXPECT_TRUE(remesh(grid, o, "grid").firstPassTrial.has_value());  // a bar missed
  o.polish = -1;
  const RemeshResult raw = remesh(grid, o, "grid");
  EXPECT_TRUE(raw.after.irregularBoundaryAware > 15.0 || raw.after.minAngle < 30.0 || raw.after.avgMinAngle < 53.0);
  EXPECT_FALSE(raw.firstPassTrial.has_value());
}

// An input far finer than the result asked for is simplified first: its cut, maps and Lloyd's
// domain are then that size, while the result is measured against the input itself.
TEST(Pipeline, ALargeInputIsSimplifiedToTenVerticesPerVertexAskedFirst) {
  EXPECT_EQ(coarseInputSize(500), 5000);
  EXPECT_EQ(coarseInputSize(1000), 10000);
  EXPECT_EQ(coarseInputSize(2000), 10000);  // five per vertex over 10,000
  EXPECT_EQ(coarseInputSize(4000), 20000);
  const Mesh grid = test::grid(24);  // 625 vertices
  RemeshOptions o;
  o.sites.count = 40;
  o.resample = false;  // Lloyd's domain is then the (simplified) input's map itself
  o.measureFidelity = false;
  const RemeshResult coarse = remesh(grid, o, "grid");
  EXPECT_EQ(coarse.coarseInput, 400);
  EXPECT_EQ(coarse.recording.input.vertexCount(), 400);
  EXPECT_EQ(coarse.before.vertices, 625);  // measured against the input itself
  o.coarsenInput = false;
  const RemeshResult full = remesh(grid, o, "grid");
  EXPECT_EQ(full.coarseInput, 0);
  EXPECT_EQ(full.recording.input.vertexCount(), 625);
  o.coarsenInput = true;
  o.sites.count = 70;  // 700 > 625: as it is
  EXPECT_EQ(remesh(grid, o, "grid").coarseInput, 0);
  o.sites.count = 40;
  o.simplifyTo = 500;  // the caller's simplification stands
  EXPECT_EQ(remesh(grid, o, "grid").recording.input.vertexCount(), 500);
}

// A disk offered slits says its conformal map's area spread, slit or kept whole (the sphere cap,
// kept whole, said 1: the spread measured was dropped); where none are offered, none is measured.
TEST(Pipeline, ADiskKeptWholeSaysItsAreaSpread) {
  const Mesh cap = readMesh(test::assetPath("sphere_cap.off")).mesh;
  RemeshOptions o = test::shortRun(0, 2);
  const RemeshResult offered = remesh(cap, o, "cap");
  EXPECT_EQ(offered.cut.seamEdges, 0);
  EXPECT_GT(offered.cut.areaSpread, 1.0);
  o.slitDisks = false;
  EXPECT_EQ(remesh(cap, o, "cap").cut.areaSpread, 0.0);
}

// Two sphere caps relocated each on its own: the vertices held back are both's (the second's
// were not counted).
TEST(Pipeline, RelocatedComponentsCountTheVerticesEachHeldBack) {
  const Mesh cap = readMesh(test::assetPath("sphere_cap.off")).mesh;
  Mesh two = cap;
  append(two, test::moved(cap, 1.0, Vec3(5, 0, 0)));
  RemeshOptions o;
  o.method = RemeshMethod::Relocate;
  o.measureFidelity = false;
  const int one = remesh(cap, o, "sphere_cap.off").heldBack;
  ASSERT_GT(one, 0);
  EXPECT_GT(remesh(two, o, "two caps").heldBack, one);
}

// Each component is simplified on its own rule, and the result says so: two 625-vertex grids
// at 40 vertices each are relaxed on 400 each.
TEST(Pipeline, ComponentsSaySimplifiedTooWhenTheyAre) {
  Mesh two = test::grid(24);
  const Mesh other = test::moved(test::grid(24), 1.0, Vec3(3, 0, 0));
  const int offset = two.vertexCount();
  two.points.insert(two.points.end(), other.points.begin(), other.points.end());
  for (Triangle t : other.triangles) two.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  RemeshOptions o;
  o.sites.count = 80;
  o.resample = false;
  o.measureFidelity = false;
  const RemeshResult coarse = remesh(two, o, "grids");
  EXPECT_EQ(coarse.components, 2);
  EXPECT_EQ(coarse.coarseInput, 800);
  o.coarsenInput = false;
  EXPECT_EQ(remesh(two, o, "grids").coarseInput, 0);
}

// remesh() simplifies a large input once for all its runs and hands the result to each session,
// which takes it rather than simplifying again.
TEST(Pipeline, ASessionTakesTheSimplifiedInputItIsGiven) {
  const Mesh grid = test::grid(24);  // 625 vertices: simplified to 400 for 40 sites
  RemeshOptions o;
  o.sites.count = 40;
  o.resample = false;  // the session then relaxes on the (simplified) input's own map
  const PreparedInput given(grid, test::grid(12));  // 169 vertices: not what simplify() would give
  RemeshSession session(grid, o, "grid", &given);
  EXPECT_EQ(session.header().input.vertexCount(), 169);
  const RemeshSession own(grid, o, "grid");
  EXPECT_EQ(own.header().input.vertexCount(), 400);
  EXPECT_EQ(own.coarseInput(), 400);  // what the inspector says after a Restart
  o.coarsenInput = false;
  EXPECT_EQ(RemeshSession(grid, o, "grid").coarseInput(), 0);
}

// remesh() also builds the input's search once for all its runs; a session given it measures
// (and takes its last steps) against it, and builds none of its own. Here it is given another
// surface's, half a unit above the grid, to tell which one it measured against.
TEST(Pipeline, ASessionMeasuresAgainstTheSearchItIsGiven) {
  const Mesh grid = test::grid(12);
  Mesh above = grid;
  for (Vec3& p : above.points) p.z() += 0.5;
  RemeshOptions o;
  o.sites.count = 60;
  o.polish = 0;  // no last steps: they would move the result towards the surface given
  o.fit = false;
  const auto measured = [&](const PreparedInput* prepared) {
    RemeshSession session(grid, o, "grid", prepared);
    while (!session.finished()) session.step();
    return session.finish().fidelity.hausdorffPercent;
  };
  const PreparedInput elsewhere(above, std::nullopt);
  EXPECT_LT(measured(nullptr), 0.01);
  EXPECT_GT(measured(&elsewhere), 10.0);
}

TEST(Pipeline, TheRunWithoutTheFirstPassIsKeptWhereItMeetsMoreBarsAndIsNotMuchFarther) {
  auto keptWithout = [](int withBars, int withoutBars, double withDistance, double withoutDistance) {
    FirstPassTrial t;
    t.withBars = withBars;
    t.withoutBars = withoutBars;
    t.withHausdorff = withDistance;
    t.withoutHausdorff = withoutDistance;
    return t.withoutBetter();
  };
  EXPECT_TRUE(keptWithout(2, 3, 2.34, 1.27));   // the camel head at 1000: closer too
  EXPECT_TRUE(keptWithout(2, 3, 1.00, 1.25));   // at most 1.25 times as far
  EXPECT_FALSE(keptWithout(2, 3, 0.80, 1.47));  // CGAL's man clipped in half at 2000: 1.84x as far
  EXPECT_FALSE(keptWithout(0, 1, 6.05, 8.26));  // a spike no longer reached
  EXPECT_FALSE(keptWithout(2, 2, 2.34, 1.27));  // as many bars: the first pass stands
  EXPECT_FALSE(keptWithout(2, 1, 2.34, 1.27));
}

// A nearly closed disk's two runs: more bars win; where both meet the three, the closer to the
// input (CGAL's lion head at 500, whose whole run is rounder by a tenth of a degree but 1.23
// times as far, over CGAL's own distance); else the rounder.
TEST(Pipeline, TheSlitTrialKeepsMoreBarsThenTheCloserThenTheRounder) {
  auto wholeKept = [](int slitBars, int wholeBars, double slitAngle, double wholeAngle, double slitDistance,
                      double wholeDistance) {
    SlitTrial t{slitAngle, wholeAngle, slitBars, wholeBars};
    if (t.bothMeetTheBars()) {
      t.slitHausdorff = slitDistance;
      t.wholeHausdorff = wholeDistance;
    }
    return t.wholeBetter();
  };
  EXPECT_FALSE(wholeKept(3, 3, 53.87, 53.99, 2.99, 3.68));  // the lion head at 500
  EXPECT_TRUE(wholeKept(3, 3, 54.5, 53.2, 1.50, 1.40));
  EXPECT_TRUE(wholeKept(2, 3, 55.0, 53.5, 1.0, 2.0));   // more bars, however far
  EXPECT_FALSE(wholeKept(3, 2, 53.5, 55.0, 2.0, 1.0));
  EXPECT_TRUE(wholeKept(2, 2, 52.0, 52.5, 0, 0));      // as many, not all: the rounder
  EXPECT_FALSE(wholeKept(1, 1, 52.5, 52.0, 0, 0));
}

// A local change of the last steps (a valence move, a vertex moved for its angles) may take a
// chord up to three quarters of the farthest anywhere from the input (half before): CGAL's
// nefertiti as the bench prepares it at 500 vertices went 9.8 -> 8.0% irregular.
TEST(Pipeline, LastStepsMayStrayThreeQuartersOfTheFarthestAnywhere) {
  const std::string path = test::cgalSample("nefertiti.off");
  SKIP_UNLESS_EXTRACTED(path);
  const Mesh input = benchInput(readMesh(path).mesh, 500, path);
  RemeshOptions o;
  o.sites.count = 500;
  o.measureFidelity = false;
  const RemeshResult r = remesh(input, o, path);
  EXPECT_LE(r.after.irregularBoundaryAware, 9.0);
  EXPECT_GE(r.after.minAngle, 30.0);
  EXPECT_GE(r.after.avgMinAngle, 53.0);
}

TEST(Session, SteppingByHandGivesTheSameRunAsRemesh) {
  const Mesh input = readMesh(test::assetPath("sphere_cap.off")).mesh;
  RemeshOptions o;
  o.measureFidelity = false;
  const RemeshResult whole = remesh(input, o, "cap");
  RemeshSession session(input, o, "cap");
  EXPECT_EQ(session.header().iterations.size(), 0u);
  int steps = 0;
  while (!session.finished()) {
    const IterationRecord& r = session.step();
    EXPECT_EQ(r.sites, whole.recording.iterations[steps].sites);
    ++steps;
  }
  EXPECT_EQ(steps, whole.iterations);
  const RemeshResult stepped = session.finish();
  EXPECT_EQ(stepped.output.points, whole.output.points);
  EXPECT_EQ(stepped.output.triangles, whole.output.triangles);
  EXPECT_EQ(stepped.after.avgMinAngle, whole.after.avgMinAngle);
  EXPECT_TRUE(stepped.converged);
}

TEST(Pipeline, SimplifiesFirstWhenAsked) {
  const Mesh input = readMesh(test::assetPath("bumpy_disk.off")).mesh;  // 1000 vertices
  RemeshOptions o;
  o.simplifyTo = 400;
  o.sites.count = 400;
  o.lloyd.maxIterations = 20;
  const RemeshResult r = remesh(input, o, "bumpy");
  EXPECT_EQ(r.recording.input.vertexCount(), 400);  // the disk that was parameterized
  EXPECT_EQ(r.before.vertices, input.vertexCount());  // Table II's "before": the user's mesh
  EXPECT_GT(r.ms.simplify, 0.0);
  // Measured against the user's mesh, not the simplified one (> 0 held for either).
  EXPECT_NEAR(r.fidelity.hausdorffPercent, measureFidelity(r.output, input).hausdorffPercent, 1e-12);
  EXPECT_NE(r.fidelity.hausdorffPercent, measureFidelity(r.output, r.recording.input).hausdorffPercent);
  EXPECT_NE(describe(o).find("simplify=400"), std::string::npos);
}

// The settings line says what runs: relocate moves the input's own vertices, with no first
// pass (it said "resample=yes sites=as-many-as-input" of a relocate run).
TEST(Pipeline, TheSettingsLineDescribesWhatRuns) {
  RemeshOptions o;
  o.method = RemeshMethod::Relocate;
  const std::string line = describe(o);
  EXPECT_NE(line.find("resample=no"), std::string::npos) << line;
  EXPECT_NE(line.find("sites=input-vertices"), std::string::npos) << line;
  EXPECT_NE(describe(RemeshOptions()).find("resample=yes"), std::string::npos);
}

// A recording's settings line gives back the options it was made with (the inspector showed a
// recording with the command line's defaults), and names the map "auto" chose.
TEST(Pipeline, TheSettingsLineGivesBackItsOptions) {
  std::vector<RemeshOptions> cases(5);
  cases[1].method = RemeshMethod::Relocate;
  cases[2].lloyd.solver = CvtSolver::Newton;
  cases[2].density.kind = DensityKind::Curvature;
  cases[2].density.alpha = 0.5;
  cases[2].lloyd.distanceThreshold = 1e-5;
  cases[2].lloyd.percentThreshold = 2.5;
  cases[2].sites.count = 321;
  cases[3] = referencePreset(RemeshMethod::Retriangulate);
  cases[4].polish = 0;
  cases[4].param.method = ParamMethod::Tutte;
  cases[4].param.border = Border::Square;
  cases[4].simplifyTo = 700;
  cases[4].slitDisks = false;
  cases[4].fit = false;
  for (const RemeshOptions& o : cases) {
    const std::string line = describe(o);
    EXPECT_EQ(describe(optionsFromSettings(line)), line);
  }
  const RemeshOptions newton = optionsFromSettings(describe(cases[2]));
  EXPECT_EQ(newton.lloyd.solver, CvtSolver::Newton);
  EXPECT_EQ(newton.lloyd.distanceThreshold, 1e-5);
  EXPECT_EQ(newton.sites.count, 321);
  EXPECT_EQ(settingValue("polish=3 polish-target=voronoi", "polish"), "3");
  EXPECT_EQ(settingValue("polish=3 polish-target=voronoi", "polish-target"), "voronoi");
  EXPECT_EQ(settingValue("polish=3", "param-used"), "");
  EXPECT_THROW(optionsFromSettings("solver=quick"), Error);
  EXPECT_THROW(optionsFromSettings("max-iterations=many"), Error);
  // The whole value, and a finite one (std::stoi read "12abc" as 12).
  EXPECT_THROW(optionsFromSettings("max-iterations=12abc"), Error);
  EXPECT_THROW(optionsFromSettings("distance-threshold=1e-6x"), Error);
  EXPECT_THROW(optionsFromSettings("alpha=nan"), Error);
  // Every digit of a double comes back (six of them did: 1.234567e-06 came back 1.23457e-06),
  // and a round one stays short.
  RemeshOptions fine;
  fine.lloyd.distanceThreshold = 1.234567e-6;
  fine.density.kind = DensityKind::Curvature;
  fine.density.floor = 0.1 + 0.2;  // 0.30000000000000004
  const RemeshOptions back = optionsFromSettings(describe(fine));
  EXPECT_EQ(back.lloyd.distanceThreshold, fine.lloyd.distanceThreshold);
  EXPECT_EQ(back.density.floor, fine.density.floor);
  EXPECT_NE(describe(RemeshOptions()).find(" distance-threshold=1e-06 "), std::string::npos) << describe(RemeshOptions());

  RemeshOptions quick;
  quick.lloyd.maxIterations = 2;
  quick.measureFidelity = false;
  const RemeshResult r = remesh(readMesh(test::assetPath("sphere_cap.off")).mesh, quick, "cap");
  EXPECT_EQ(settingValue(r.recording.settings, "param-used"), toString(r.paramUsed));
  // Opened again (inspect, and the window's Open recording): the run's options, map and
  // iterations, and the quality of the mesh that was mapped.
  const RecordedRun opened = recordedRun(r.recording);
  EXPECT_EQ(describe(opened.options), describe(quick));
  EXPECT_EQ(opened.result.paramUsed, r.paramUsed);
  EXPECT_EQ(opened.result.iterations, 2);
  EXPECT_EQ(opened.result.before.vertices, r.recording.input.vertexCount());
  EXPECT_EQ(opened.result.recording.iterations.size(), r.recording.iterations.size());
  // The map's distortion, which the Parameterize stage quotes (it read 1.00 to 1.00, none).
  EXPECT_GT(r.distortion.maxAreaRatio, 1.1);
  EXPECT_DOUBLE_EQ(opened.result.distortion.minAreaRatio, r.distortion.minAreaRatio);
  EXPECT_DOUBLE_EQ(opened.result.distortion.maxAreaRatio, r.distortion.maxAreaRatio);
  EXPECT_DOUBLE_EQ(opened.result.distortion.meanLogAreaRatio, r.distortion.meanLogAreaRatio);
}

// Sizes double precision cannot remesh are refused in one line saying which and why: they crashed
// (coordinates of 1e80: GMP's abort on an overflowed NaN in CGAL's exact predicates), looped
// (a strip 10^9 times as long as wide; a vertex 10^10 away from a unit grid) or came out with
// 0-degree angles (a unit grid 10^15 from the origin); and too few vertices for a surface's
// border. Just inside the limits, a run works.
TEST(Pipeline, SizesDoublePrecisionCannotRemeshAreRefused) {
  const Mesh grid = test::grid(8);
  auto transformed = [&](const std::function<Vec3(const Vec3&)>& f) {
    Mesh m = grid;
    for (Vec3& p : m.points) p = f(p);
    return m;
  };
  auto why = [](const Mesh& m) {
    RemeshOptions quick;
    quick.lloyd.maxIterations = 3;
    quick.measureFidelity = false;
    try {
      remesh(m, quick, "m.off");
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(why(transformed([](const Vec3& p) -> Vec3 { return 1e80 * p; })).rfind("m.off: coordinates as large as 1e+80", 0), 0u);
  EXPECT_EQ(why(transformed([](const Vec3& p) -> Vec3 { return 1e-40 * p; })).rfind("m.off: too small to be remeshed", 0), 0u);
  const std::string far = why(transformed([](const Vec3& p) -> Vec3 { return p + Vec3(1e15, 0, 0); }));
  EXPECT_EQ(far.rfind("m.off: too far from the origin", 0), 0u) << far;
  EXPECT_EQ(why(transformed([](const Vec3& p) -> Vec3 { return Vec3(p.x(), 1e-9 * p.y(), p.z()); })).rfind("m.off: too thin to remesh", 0), 0u);
  EXPECT_EQ(why(transformed([](const Vec3& p) -> Vec3 { return Vec3(p.x(), 1e-7 * p.y(), p.z()); })).rfind("m.off: too thin to remesh", 0), 0u);
  // Just past the limit, in as many digits as tell it from the limit (it read "1e-06 ... (the least is 1e-06)").
  const std::string thin = why(transformed([](const Vec3& p) -> Vec3 { return Vec3(p.x(), 0.999e-6 * p.y(), p.z()); }));
  EXPECT_NE(thin.find("its area is 9.99e-07 times its bounding box's diagonal squared (the least is 1e-06)"), std::string::npos) << thin;
  // A strip 10^4 to 1 at its 81 vertices: sampled at their spacing, its border alone takes 1676
  // (the result had 1676 vertices; at 10^6 to 1, 16,751 in 31 s).
  const std::string few = why(transformed([](const Vec3& p) -> Vec3 { return Vec3(p.x(), 1e-4 * p.y(), p.z()); }));
  EXPECT_EQ(few.rfind("m.off: 81 vertices are too few for it: at their spacing its border alone takes 1676 (over 10", 0), 0u) << few;
  Mesh farVertex = grid;
  farVertex.points[0] = Vec3(-1e10, -1e10, 0);
  EXPECT_EQ(why(farVertex).rfind("m.off: too thin to remesh", 0), 0u);
  for (const Mesh& fine : {transformed([](const Vec3& p) -> Vec3 { return 1e29 * p; }), transformed([](const Vec3& p) -> Vec3 { return 1e-29 * p; }),
                           transformed([](const Vec3& p) -> Vec3 { return p + Vec3(1e11, 0, 0); }),
                           transformed([](const Vec3& p) -> Vec3 { return Vec3(p.x(), 0.01 * p.y(), p.z()); })})
    EXPECT_EQ(why(fine), "");
}

// A stray vertex (the bumpy disk's vertex 340 moved 1000 times as far, through the disk) is
// refused in one line naming it: the run took over 200 s (ears made at the sharp corners of a
// result that was mostly needle). 30 times as far is a spike the run follows, in about a second.
TEST(Pipeline, AStrayVertexIsRefused) {
  const Mesh disk = readMesh(test::assetPath("bumpy_disk.off")).mesh;
  const auto movedAway = [&](double times) {
    Mesh m = disk;
    m.points[340] *= -times;
    return m;
  };
  const Mesh stray = movedAway(1000);
  const Topology topology = analyzeTopology(stray);
  try {
    requireRemeshableSize(stray, topology, 600, "m.off");
    ADD_FAILURE() << "not refused";
  } catch (const Error& e) {
    // Named by where it is, as the file has it: by its number it was the reader's, from 0 once
    // unused vertices were dropped (an OBJ's vertex 53 was "vertex 50").
    std::ostringstream at;
    at << '(' << stray.points[340].x() << ", " << stray.points[340].y() << ", " << stray.points[340].z() << ')';
    EXPECT_EQ(std::string(e.what()),
              "m.off: the vertex at " + at.str() + " is 696 times as far from the middle of the surface as 99% of its "
              "vertices (at most 100): a stray vertex, whose triangles make a needle; remove it or move it back");
  }
  RemeshOptions quick;
  quick.lloyd.maxIterations = 3;
  EXPECT_THROW(remesh(stray, quick, "m.off"), Error);  // remesh() checks it
  EXPECT_NO_THROW(requireRemeshableSize(movedAway(30), topology, 600, "m.off"));
}

// A 2 x 2 grid whose middle vertex is `height` up: a spike, and in the plane (height 0) with
// its middle vertex moved `over` along x: a fold, whose triangles overlap.
Mesh spikeOrFold(double height, double over = 0) {
  Mesh m = test::grid(2);
  m.points[4] += Vec3(over, 0, height);
  return m;
}

// Surfaces far larger than their border (a spike 10^5 or 10^6 times as tall as wide; a fold
// 66,666 long inside a unit square) are refused in one line, the border's samples counted: they
// ran for 2, 4 and over 5 minutes (raising the small angles of a result of slivers; Lloyd's
// cells in a domain of overlapping triangles; the charts, whose seams up the spike took
// thousands of samples for 200 vertices asked), the first one making a result of 0-degree angles.
TEST(Pipeline, ASurfaceFarLargerThanItsBorderIsRefused) {
  auto why = [](const Mesh& m, int sites) {
    RemeshOptions o;
    o.sites.count = sites;
    try {
      remesh(m, o, "m.off");
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  const std::string spike = why(spikeOrFold(1e5), 0);
  EXPECT_EQ(spike.rfind("m.off: at the spacing of 9 vertices its border takes 1 sample (3 at least), far too short", 0), 0u)
      << spike;
  // The charts, tried where the one disk failed, say why they failed too.
  EXPECT_NE(spike.find("; chart by chart it failed too: one chart covers it"), std::string::npos) << spike;
  const std::string fold = why(spikeOrFold(0, 66666), 0);
  EXPECT_EQ(fold.rfind("m.off: at the spacing of 9 vertices its border takes 1 sample (3 at least)", 0), 0u) << fold;
  const std::string charts = why(spikeOrFold(1e6), 200);
  EXPECT_EQ(charts.rfind("m.off: at the spacing of 200 vertices its border takes 1 sample", 0), 0u) << charts;
  EXPECT_EQ(why(spikeOrFold(10), 100), "");  // a spike 10 times as tall as wide is remeshed
}

// --simplify N asks for N vertices: a coarser input is not simplified but remeshed finer, to N
// (the result of `remesh pig.off --simplify 2000` had the pig's 468 vertices).
TEST(Pipeline, ACoarserInputIsRemeshedToTheSimplifySize) {
  const Mesh input = readMesh(test::assetPath("bumpy_disk.off")).mesh;  // 1000 vertices
  RemeshOptions o;
  o.simplifyTo = 1500;
  o.lloyd.maxIterations = 20;
  o.measureFidelity = false;
  const RemeshResult r = remesh(input, o, "bumpy");
  EXPECT_EQ(r.recording.input.vertexCount(), 1000);  // not simplified: the resampled surface
  EXPECT_NEAR(r.output.vertexCount(), 1500, 15);
}

TEST(Cli, SimplifyWritesTheTargetSize) {
  const std::string out = test::tempPath("simplified.off");
  EXPECT_EQ(std::system((std::string(LLOYDSCOPE_CLI) + " simplify " + test::assetPath("bumpy_disk.off") +
                         " -o " + out + " --vertices 300 > /dev/null").c_str()),
            0);
  EXPECT_EQ(readMesh(out).mesh.vertexCount(), 300);
  // Any ratio in (0, 1], a subnormal one too (1e-310 was "not in (0, 1]"): as few as it goes.
  EXPECT_EQ(std::system((std::string(LLOYDSCOPE_CLI) + " simplify " + test::assetPath("bumpy_disk.off") + " -o " + out +
                         " --ratio 1e-310 > /dev/null").c_str()),
            0);
  EXPECT_EQ(readMesh(out).mesh.vertexCount(), 3);
}

// A 34-degree sector, bent, remeshed to 100 vertices: the border, sampled evenly into its
// sharp corner, leaves a strip of triangles with a small angle, until the polish slides a border
// vertex along the border. The slid vertex lands on the input's own border, not on a chord of
// the resampled surface's (its sides are bent).
TEST(Pipeline, TheBorderSlidOutOfASharpCornerStaysOnTheInputsBorder) {
  const Mesh input = test::sector(34, [](double x, double) { return 0.5 * x * x; });
  RemeshOptions o;
  o.sites.count = 100;
  o.fit = false;  // (the fit would move the border across it)
  const RemeshResult r = remesh(input, o, "sector");
  EXPECT_GE(r.after.minAngle, 30.0);
  const Topology topology = analyzeTopology(r.output);
  ASSERT_TRUE(topology.isDisk());
  const std::vector<int> border = analyzeTopology(input).boundaryLoops[0];
  for (int v : topology.boundaryLoops[0]) {
    double nearest = 1;
    for (size_t i = 0; i < border.size(); ++i)
      nearest = std::min(nearest, distanceToSegment(r.output.points[v], input.points[border[i]],
                                                    input.points[border[(i + 1) % border.size()]]));
    EXPECT_LT(nearest, 1e-9) << v;
  }
}

// A 20-degree sector, bent: the result keeps its apex, one triangle's corner, which can have no
// more than 20 degrees. The trials count that as the bar met, and make no other run to reach 30
// (before, the run without the first pass was made too, in vain). The border samples beside
// the apex are graded, so that the triangles across the wedge are round (evenly spaced, they
// were squeezed to 22.9 degrees at 300 vertices, 21.0 at 200).
TEST(Pipeline, ASharpCornerOfTheInputsBorderIsNoBarToMiss) {
  const Mesh input = test::sector(20, [](double x, double) { return 0.5 * x * x; });
  RemeshOptions o;
  o.sites.count = 300;
  const RemeshResult r = remesh(input, o, "sector");
  EXPECT_NEAR(r.before.sharpestBorderCorner, 20.0, 0.01);  // bent a little
  EXPECT_LT(r.after.minAngle, 30.0);
  EXPECT_GE(r.after.minAngleOffSharpCorners, 30.0);
  EXPECT_TRUE(meetsMinAngleBar(r.after, r.before));
  EXPECT_EQ(barsMet(r.after, r.before), 3);
  EXPECT_EQ(r.runs, 1);
  EXPECT_FALSE(r.firstPassTrial.has_value());
}

// A lens between two circular arcs, its tips 24.8 degrees. Its sides curve outward, so the
// chords to the first border samples cut the tips a little: evenly sampled, they came out
// 24.778 degrees at 1200 vertices, which the first rule (the input's sharpest corner anywhere,
// to 1e-6 degrees) counted as a bar missed, and the run was remade in vain (found by review).
// Graded samples now cut them about half as much, and at 1200 vertices they come out no
// sharper than the input's (24.789); a corner up to 0.5 degrees sharper would count as the
// input's (Quality.TheSmallestAngleBarIsWithinTheInputsReach).
TEST(Pipeline, ALensKeepsItsTipsAndMeetsTheBarInOneRun) {
  const double half = 12.5 * M_PI / 180, tipX = std::tan(half), radius = std::hypot(tipX, 1.0);
  const int columns = 120, rows = 6;
  Mesh lens;
  lens.points = {{-tipX, 0, 0}, {tipX, 0, 0}};
  const auto at = [&](int i, int j) { return 2 + (i - 1) * (rows + 1) + j; };
  for (int i = 1; i < columns; ++i) {
    const double x = -tipX + 2 * tipX * i / columns, y = std::sqrt(radius * radius - x * x) - 1;
    for (int j = 0; j <= rows; ++j) lens.points.emplace_back(x, (-1 + 2.0 * j / rows) * y, 0);
  }
  for (int j = 0; j < rows; ++j) {
    lens.triangles.push_back({0, at(1, j), at(1, j + 1)});
    lens.triangles.push_back({1, at(columns - 1, j + 1), at(columns - 1, j)});
  }
  for (int i = 1; i < columns - 1; ++i)
    for (int j = 0; j < rows; ++j) {
      lens.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      lens.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  RemeshOptions o;
  o.sites.count = 1200;
  o.measureFidelity = false;
  const RemeshResult r = remesh(lens, o, "lens");
  EXPECT_NEAR(r.before.sharpestBorderCorner, 24.788, 0.001);
  EXPECT_LT(r.after.minAngle, 30.0);
  EXPECT_TRUE(meetsMinAngleBar(r.after, r.before));
  EXPECT_EQ(r.runs, 1);
}

// A surface cut open needs its seams made ready for stitching (edges that stitching would
// share among three triangles flipped, or split) with or without the polish: without it
// (--polish -1) CGAL's femur at 500 was refused, "the remeshed seams did not stitch back".
TEST(Pipeline, ACutSurfaceIsStitchedWithoutThePolishToo) {
  const std::string path = test::cgalSample("femur.off");
  SKIP_UNLESS_EXTRACTED(path);
  const Mesh femur = readMesh(path).mesh;
  RemeshOptions o;
  o.polish = -1;
  o.measureFidelity = false;
  o.sites.count = 500;
  try {
    const Topology after = analyzeTopology(remesh(femur, o, "femur").output);
    EXPECT_EQ(after.genus, analyzeTopology(femur).genus);
    EXPECT_TRUE(after.boundaryLoops.empty());
  } catch (const Error& e) {
    ADD_FAILURE() << e.what();
  }
}

// Every option's names read back as what they print, and a name not in the list is refused
// with the list (one table an enum: the parsers had nine hand-written copies).
TEST(Names, EachNameReadsBackAndAnUnknownOneListsThemAll) {
  for (CvtSolver s : kCvtSolvers) EXPECT_EQ(parseCvtSolver(toString(s)), s);
  for (PolishTarget t : kPolishTargets) EXPECT_EQ(parsePolishTarget(toString(t)), t);
  for (ParamMethod m : {ParamMethod::Auto, ParamMethod::Authalic, ParamMethod::Conformal, ParamMethod::MeanValue,
                        ParamMethod::Tutte, ParamMethod::Lscm})
    EXPECT_EQ(parseParamMethod(toString(m)), m);
  for (Border b : {Border::Square, Border::Circle}) EXPECT_EQ(parseBorder(toString(b)), b);
  for (DensityKind k : {DensityKind::Uniform, DensityKind::Area, DensityKind::Curvature})
    EXPECT_EQ(parseDensityKind(toString(k)), k);
  for (RemeshMethod m : {RemeshMethod::Relocate, RemeshMethod::Retriangulate}) EXPECT_EQ(parseRemeshMethod(toString(m)), m);
  // The input's own map is printed (recordings say which map was used) but is no method to ask for.
  EXPECT_STREQ(toString(ParamMethod::Given), "input-map");
  auto refusal = [](const auto& parse, const std::string& text) {
    try {
      parse(text);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(refusal(parseParamMethod, "input-map"),
            "unknown parameterization 'input-map' (auto, authalic, conformal, mean-value, tutte, lscm)");
  EXPECT_EQ(refusal(parseBorder, "Square"), "unknown border 'Square' (square, circle, rectangle)");
  EXPECT_EQ(refusal(parsePolishTarget, ""), "unknown polish target '' (voronoi, centroid, circumcenter)");
}

// The window's next run takes the settings within the command line's bounds; a recording's own
// counts (a chart's sites=18) are not, and reached the next Open mesh's run as they were.
TEST(Pipeline, SettingsAreKeptWithinTheCommandLinesBounds) {
  RemeshOptions o;
  o.sites.count = 18;
  o.simplifyTo = 5;
  o.polish = 1000;
  o.lloyd.maxIterations = 0;
  RemeshOptions kept = o;
  keepWithinCommandLineBounds(kept);
  EXPECT_EQ(kept.sites.count, kSmallestRemeshedShare);
  EXPECT_EQ(kept.simplifyTo, kSmallestRemeshedShare);
  EXPECT_EQ(kept.polish, kMostPolishPasses);
  EXPECT_EQ(kept.lloyd.maxIterations, 1);
  o.sites.count = o.simplifyTo = 0;  // as many as the input; no simplification
  keepWithinCommandLineBounds(o);
  EXPECT_EQ(o.sites.count, 0);
  EXPECT_EQ(o.simplifyTo, 0);
}

// A recording's settings read back as the options asked: the coarse input a run simplified a
// large input to was written as simplify=500, read back as asked, and --full-input was not
// written at all.
TEST(Pipeline, ARecordingsSettingsAreTheOptionsAsked) {
  const Mesh bumpy = readMesh(test::assetPath("bumpy_disk.off")).mesh;  // 1000 vertices
  RemeshOptions o;
  o.sites.count = 50;
  o.measureFidelity = false;
  const std::string coarse = remesh(bumpy, o, "bumpy").recording.settings;
  EXPECT_EQ(settingValue(coarse, "simplify"), "") << coarse;
  EXPECT_EQ(settingValue(coarse, "coarse-input"), "500") << coarse;
  EXPECT_EQ(optionsFromSettings(coarse).simplifyTo, 0);
  EXPECT_TRUE(optionsFromSettings(coarse).coarsenInput);
  o.coarsenInput = false;
  const std::string full = remesh(bumpy, o, "bumpy").recording.settings;
  EXPECT_EQ(settingValue(full, "coarse-input"), "") << full;
  EXPECT_FALSE(optionsFromSettings(full).coarsenInput) << full;
  o.coarsenInput = true;
  o.simplifyTo = 300;  // asked: written as asked
  EXPECT_EQ(optionsFromSettings(remesh(bumpy, o, "bumpy").recording.settings).simplifyTo, 300);
}

// Two grids, one of them bent along straight folds, its border straight in 3D and round in a
// mean-value map: three border samples in a row made an ear of no area, and remesh wrote a
// result that its own reader refused ("face 28 has zero area"; found by fuzzing); with
// --polish -1, "face 22 has zero area".
TEST(Pipeline, NoResultHasATriangleOfNoArea) {
  const std::string path = test::tempPath("bent_grids.off");
  test::writeText(path,
      "OFF\n"
      "32 36 0\n"
      "0 0 0\n"
      "0.33333333333333331 0 0\n"
      "0.66666666666666663 0 0\n"
      "1 0 0\n"
      "0 0.33333333333333331 0\n"
      "0.33333333333333331 0.33333333333333331 0\n"
      "0.66666666666666663 0.33333333333333331 0\n"
      "1 0.33333333333333331 0\n"
      "0 0.66666666666666663 0\n"
      "0.33333333333333331 0.66666666666666663 0\n"
      "0.66666666666666663 0.66666666666666663 0\n"
      "1 0.66666666666666663 0\n"
      "0 1 0\n"
      "0.33333333333333331 1 0\n"
      "0.66666666666666663 1 0\n"
      "1 1 0\n"
      "3 0 8.2462112512353212\n"
      "3.3333333333333335 0 8.2462112512353212\n"
      "3.6666666666666665 0 0\n"
      "4 0 2.0615528128088303\n"
      "3 0.33333333333333331 0\n"
      "3.3333333333333335 0.33333333333333331 8.2462112512353212\n"
      "3.6666666666666665 0.33333333333333331 0\n"
      "4 0.33333333333333331 2.0615528128088303\n"
      "3 0.66666666666666663 2.0615528128088303\n"
      "3.6666666666707894 1.0000000000041231 2.0615528128047074\n"
      "3.6666666666666665 0.66666666666666663 2.0615528128088303\n"
      "4 0.66666666666666663 0\n"
      "3 1 8.2462112512353212\n"
      "3.3333333333333335 1 0\n"
      "3.6666666666666665 1 8.2462112512353212\n"
      "4 1 8.2462112512353212\n"
      "3 0 1 5\n"
      "3 0 5 4\n"
      "3 1 2 6\n"
      "3 1 6 5\n"
      "3 2 3 7\n"
      "3 2 7 6\n"
      "3 4 5 9\n"
      "3 4 9 8\n"
      "3 5 6 10\n"
      "3 5 10 9\n"
      "3 6 7 11\n"
      "3 6 11 10\n"
      "3 8 9 13\n"
      "3 8 13 12\n"
      "3 9 10 14\n"
      "3 9 14 13\n"
      "3 10 11 15\n"
      "3 10 15 14\n"
      "3 16 17 21\n"
      "3 16 21 20\n"
      "3 17 18 22\n"
      "3 17 22 21\n"
      "3 18 19 23\n"
      "3 18 23 22\n"
      "3 20 21 25\n"
      "3 20 25 24\n"
      "3 21 22 26\n"
      "3 21 26 25\n"
      "3 22 23 27\n"
      "3 22 27 26\n"
      "3 24 25 29\n"
      "3 24 29 28\n"
      "3 25 26 30\n"
      "3 25 30 29\n"
      "3 26 27 31\n"
      "3 26 31 30\n"
      "");
  const Mesh input = readMesh(path).mesh;
  // Without the polish (or with its Delaunay flips alone) a fan of such samples made a pocket of
  // flat triangles, each beyond the next's longest edge: flipped away now.
  for (const int polish : {RemeshOptions{}.polish, 0, -1})
    for (const bool fit : {true, false}) {
      RemeshOptions o;
      o.param.method = ParamMethod::MeanValue;
      o.sites.count = 50;
      o.polish = polish;
      o.fit = fit;
      o.measureFidelity = false;
      const Mesh output = remesh(input, o, "bent_grids.off").output;
      EXPECT_NO_THROW(validateMesh(output, "result")) << "polish " << polish << ", fit " << fit;
    }
}

// A disk fanned around one vertex (a CAD part's cap, 1200 triangles): simplifying it first, as
// an input larger than ten vertices per vertex asked is, took time cubic in the fan (3000
// triangles: over a minute; found by fuzzing). It is remeshed as it is, which takes a second.
TEST(Pipeline, AFanTooLargeToSimplifyQuicklyIsRemeshedAsItIs) {
  Mesh fan;
  fan.points.emplace_back(0, 0, 0);
  const int n = 1200;
  for (int i = 0; i < n; ++i) fan.points.emplace_back(std::cos(2 * M_PI * i / n), std::sin(2 * M_PI * i / n), 0);
  for (int i = 0; i < n; ++i) fan.triangles.push_back({0, 1 + i, 1 + (i + 1) % n});
  ASSERT_GT(mostTrianglesAroundAVertex(fan), kMostTrianglesAroundAVertexToSimplify);
  RemeshOptions o;
  o.sites.count = 50;
  o.measureFidelity = false;
  const RemeshResult r = remesh(fan, o, "fan.off");
  EXPECT_EQ(r.coarseInput, 0);
  EXPECT_NO_THROW(validateMesh(r.output, "result"));
}

// A saddle over a polar grid whose rim is a 24-gon, coarser than the border of its result at 400
// vertices: the result's border edges cut off the rim's corners, and that was its Hausdorff
// distance (0.305% of the diagonal). Remeshed with the rim's 24 vertices kept as border samples
// (BorderTrial) it is 0.142%, and every corner of the rim is a vertex of the result.
TEST(Pipeline, ACoarseBorderThatTheResultCutsIsSampledAtItsCorners) {
  const Mesh saddle = test::polarDisk(24, 12, 0, [](double r, double a) { return 0.5 * r * r * std::cos(2 * a); });
  RemeshOptions o;
  o.sites.count = 400;
  const RemeshResult r = remesh(saddle, o, "saddle");
  ASSERT_TRUE(r.borderTrial.has_value());
  EXPECT_TRUE(r.borderTrial->failed.empty()) << r.borderTrial->failed;
  EXPECT_EQ(r.borderTrial->corners.size(), 24u);
  EXPECT_TRUE(r.borderTrial->keptWith);
  EXPECT_LT(r.borderTrial->withHausdorff, 0.8 * r.borderTrial->withoutHausdorff);
  EXPECT_EQ(r.fidelity.hausdorffPercent, r.borderTrial->withHausdorff);
  EXPECT_EQ(r.runs, 2);
  for (int i = 0; i < 24; ++i)
    EXPECT_LT(test::nearestDistance(r.output.points, saddle.points[saddle.vertexCount() - 24 + i]), 1e-9) << "corner " << i;
}

// What a part's recording is of, in words: a chart of a component names both.
TEST(Pipeline, ARecordingOfAPartSaysWhichPart) {
  EXPECT_EQ(recordedPartText("method=retriangulate sites=20"), "");
  EXPECT_EQ(recordedPartText("sites=194 part=chart-3-of-19"),
            "The iterations are of one part of the run, the largest: chart 3 of 19");
  EXPECT_EQ(recordedPartText("sites=194 part=chart-3-of-19,component-1-of-2 param-used=lscm"),
            "The iterations are of one part of the run, the largest: chart 3 of 19, in component 1 of 2");
}

// The same saddle beside a small flat disk, two components: the saddle's border trial is the
// run's (it was dropped, the report silent on the corners kept, and the inspector's Restart
// on the largest component sampled its border without them).
TEST(Pipeline, TheLargestComponentsBorderTrialIsTheRuns) {
  Mesh two = test::polarDisk(24, 12, 0, [](double r, double a) { return 0.5 * r * r * std::cos(2 * a); });
  append(two, test::moved(test::polarDisk(12, 4), 0.3, Vec3(5, 0, 0)));
  RemeshOptions o;
  o.sites.count = 440;
  const RemeshResult r = remesh(two, o, "saddle and disk");
  EXPECT_EQ(r.components, 2);
  ASSERT_TRUE(r.borderTrial.has_value());
  EXPECT_EQ(r.borderTrial->corners.size(), 24u);
  EXPECT_TRUE(r.borderTrial->keptWith);
  EXPECT_EQ(settingValue(r.recording.settings, "part"), "component-1-of-2");
}

// A flat eight-pointed star, its rim a 16-gon alternating between radius 1 and 0.87: its eight
// points (turning by 61 degrees) stay samples as any sharp corner does, but the eight reflex
// corners between them turn by 16 degrees only, and the result's border chords at 400 vertices
// crossed them outside the input (0.123% of the diagonal). No input vertex is off the result,
// so only the chords tell (borderCornersCut). With the rim's 16 vertices kept as samples,
// every one is a vertex of the result and it lies on the input.
TEST(Pipeline, TheReflexCornersOfACoarseBorderThatTheResultCutsAcrossAreSampled) {
  const Mesh star = test::starDisk(8, 0.87, 10);
  RemeshOptions o;
  o.sites.count = 400;
  const RemeshResult r = remesh(star, o, "star");
  ASSERT_TRUE(r.borderTrial.has_value());
  EXPECT_EQ(r.borderTrial->corners.size(), 16u);
  EXPECT_TRUE(r.borderTrial->keptWith);
  EXPECT_GT(r.borderTrial->withoutHausdorff, 0.1);
  EXPECT_LT(r.fidelity.hausdorffPercent, 1e-9);
  EXPECT_EQ(r.borderTrial->cornersMoved, 0);
  for (int i = 0; i < 16; ++i) EXPECT_LT(test::nearestDistance(r.output.points, test::starRim(8, 0.87, i)), 1e-9) << "corner " << i;
}

// A fan of 80 triangles under a zigzag rim (40 points of radius 1, 40 notches of 0.85), its
// apex raised: at 500 vertices the run with the rim's 80 vertices kept is kept (2.44% of the
// diagonal against 2.98%), but the polish then slid 36 notch corners along the border, where
// that raised a small angle, and the report said all 80 were kept. The trial counts those that
// are no vertex of the result's border.
TEST(Pipeline, TheBorderTrialCountsTheKeptCornersThatMovedOn) {
  const auto rim = [](int, int i) {
    const double a = 2 * M_PI * i / 80, r = i % 2 ? 0.85 : 1.0;
    return Vec3(r * std::cos(a), r * std::sin(a), 0);
  };
  const Mesh fan = test::polarGrid(1, 80, true, Vec3(0, 0, 0.2), rim);
  RemeshOptions o;
  o.sites.count = 500;
  const RemeshResult r = remesh(fan, o, "fan");
  ASSERT_TRUE(r.borderTrial.has_value());
  ASSERT_TRUE(r.borderTrial->keptWith);
  int moved = 0;
  for (int i = 0; i < 80; ++i) moved += test::nearestDistance(r.output.points, rim(1, i)) > 1e-6;
  EXPECT_GT(moved, 0);
  EXPECT_EQ(r.borderTrial->cornersMoved, moved);
}

// The run with the corners kept is kept where it meets as many bars and is closer by 1% at
// least: on CGAL's blobby clipped at 30% along y, at 500 vertices, both runs' farthest point was
// the same, its distances 1 bit apart, and the second run was kept for that.
TEST(Pipeline, TheBorderTrialKeepsARunThatIsCloserNotOneAsFar) {
  BorderTrial t;
  t.withBars = t.withoutBars = 3;
  t.withHausdorff = 0.617766376746383;
  t.withoutHausdorff = 0.6177663767463833;
  EXPECT_FALSE(t.withBetter());
  t.withHausdorff = 0.55;
  EXPECT_TRUE(t.withBetter());
  t.withBars = 2;
  EXPECT_FALSE(t.withBetter());
}

// A coarse input remeshed finer: CGAL's lion head as the bench makes it at 500 vertices,
// remeshed to 1000 and 2000, is as close to it as CGAL's remesher makes it. At 1000 a thin
// fin's tip, 2.6% of the diagonal from the result, was refused a snap: the relaxation around
// it left a 19-degree angle, and it was the Hausdorff distance (2.645%, over CGAL's 2.205%).
// The snap's rings now have their small angles raised before the check: 1.710%. At 2000 the
// farthest point was on a fin's crest, 1.9% from its nearest vertex (1.953%, over CGAL's
// 1.497%); the midpoints of the input's long edges are snapped to as well: 1.305%.
TEST(Pipeline, ACoarseInputRemeshedFinerKeepsItsTipsAsCgalDoes) {
  const std::string path = test::cgalSample("lion-head.off");
  SKIP_UNLESS_EXTRACTED(path);
  const Mesh input = benchInput(readMesh(path).mesh, 500, "lion-head");
  for (int size : {1000, 2000}) {
    RemeshOptions o;
    o.sites.count = size;
    const RemeshResult r = remesh(input, o, "lion-head");
    IsotropicOptions cgal;
    cgal.vertices = size;
    EXPECT_LT(r.fidelity.hausdorffPercent, measureFidelity(isotropicRemesh(input, cgal).mesh, input).hausdorffPercent)
        << size;
    EXPECT_GE(r.after.minAngle, 30.0) << size;
    EXPECT_GT(r.snappedTips, 0) << size;
  }
}

// The map auto chose and its border are the run's to tell: a strip whose LSCM map overlaps
// itself is mapped onto a rectangle, and the report, the recording (border-used, read back by
// recordedRun) and so the inspector say "rectangle border", not the circle asked.
TEST(Pipeline, ARunSaysWhichBorderItsMapHas) {
  RemeshOptions o;
  o.sites.count = 300;
  o.measureFidelity = false;
  const RemeshResult r = remesh(test::helicoidStrip(16, 80), o, "helicoid");
  EXPECT_EQ(r.paramUsed, ParamMethod::MeanValue);
  EXPECT_EQ(r.borderUsed, Border::Rectangle);
  EXPECT_NE(r.recording.settings.find(" border-used=rectangle"), std::string::npos) << r.recording.settings;
  EXPECT_EQ(recordedRun(r.recording).result.borderUsed, Border::Rectangle);
}
