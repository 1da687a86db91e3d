#include "charts.h"
#include "mesh_io.h"
#include "metrics.h"
#include "parameterization.h"
#include "pipeline.h"
#include "replay.h"
#include "test_support.h"
#include "topology.h"

#include <map>
#include <set>

using namespace lloydscope;

namespace {

// The charts of the torus with no merging: each as grown within the cone.
Charts unmergedTorusCharts() {
  ChartOptions options;
  options.smallestShare = 0;
  return splitIntoCharts(test::torus(), 1000, options);
}

// A disk whose rim waves up and down (z = r^3 sin 5t): its border is longer than a flat disk's
// would be, so a conformal map with a free border overlaps itself, as a lettuce leaf laid flat.
Mesh ruffledDisk() {
  return test::polarDisk(72, 12, 0, [](double r, double t) { return r * r * r * std::sin(5 * t); });
}

}  // namespace

TEST(Charts, AreDisksThatCoverEveryFaceOnce) {
  const Mesh torus = test::torus();
  for (int share : {0, 20, 200}) {
    ChartOptions options;
    options.smallestShare = share;
    const Charts charts = splitIntoCharts(torus, 1000, options);
    ASSERT_GE(charts.charts.size(), 2u) << share;
    std::multiset<Triangle> covered;
    for (const Chart& chart : charts.charts) {
      ASSERT_NO_THROW(validateMesh(chart.mesh, "chart"));
      EXPECT_TRUE(analyzeTopology(chart.mesh).isDisk()) << analyzeTopology(chart.mesh).describe();
      for (Triangle t : chart.mesh.triangles) {
        for (int& v : t) v = chart.original[v];
        covered.insert(t);
      }
    }
    EXPECT_EQ(covered.size(), torus.triangles.size());
    EXPECT_EQ(covered, std::multiset<Triangle>(torus.triangles.begin(), torus.triangles.end()));
  }
}

TEST(Charts, MergingSmallOnesLeavesFewer) {
  ChartOptions options;
  options.smallestShare = 200;  // each chart at least a fifth of the surface
  const size_t merged = splitIntoCharts(test::torus(), 1000, options).charts.size();
  EXPECT_LT(merged, unmergedTorusCharts().charts.size());
  EXPECT_LE(merged, 5u);
}

TEST(Charts, ProjectionsOfUnmergedChartsTurnNoTriangleOver) {
  for (const Chart& chart : unmergedTorusCharts().charts) {
    ASSERT_EQ(chart.uv.size(), chart.mesh.points.size());
    for (const Triangle& t : chart.mesh.triangles)
      EXPECT_GT(triangleArea(chart.uv[t[0]], chart.uv[t[1]], chart.uv[t[2]]), 0);
  }
}

// Both sides of a seam must sample it alike: each surface vertex on a chart border shared with
// another chart is on a seam, and a node or not, in every chart that has it.
TEST(Charts, EveryChartSeesTheSameSeamsAndNodes) {
  const Charts charts = splitIntoCharts(test::torus(), 1000);
  std::map<int, std::set<std::pair<bool, bool>>> flags;  // surface vertex -> (onSeam, node)
  std::map<int, int> chartsAt;
  for (const Chart& chart : charts.charts)
    for (size_t v = 0; v < chart.original.size(); ++v) {
      flags[chart.original[v]].insert({chart.onSeam[v], chart.seamNode[v]});
      ++chartsAt[chart.original[v]];
    }
  int nodes = 0;
  for (const auto& [vertex, seen] : flags) {
    EXPECT_EQ(seen.size(), 1u) << vertex;
    EXPECT_EQ(seen.begin()->first, chartsAt[vertex] > 1) << vertex;
    nodes += seen.begin()->second;
  }
  EXPECT_GT(nodes, 0);
  EXPECT_GT(charts.seamEdges, 0);
}

// CGAL's elephant (closed, genus 3) cut to one disk: LSCM folds, and the mean-value map of
// that disk stretches the cells (47.9 degrees on average at 1000 vertices). Chart by chart it
// comes out rounder and closer, with the same topology.
TEST(Charts, AClosedSurfaceNoMapOfOneCutHoldsIsRemeshedChartByChart) {
  const std::string path = test::cgalSample("elephant.off");
  SKIP_UNLESS_EXTRACTED(path);
  const Mesh input = readMesh(path).mesh;
  RemeshOptions options;
  options.simplifyTo = 1000;
  const RemeshResult r = remesh(input, options, "elephant");
  ASSERT_TRUE(r.chartTrial.has_value());
  EXPECT_GT(r.charts, 1);
  EXPECT_GT(r.chartTrial->chartsAvgMinAngle, r.chartTrial->oneCutAvgMinAngle + 2);
  EXPECT_LT(r.chartTrial->chartsHausdorff, r.chartTrial->oneCutHausdorff);
  EXPECT_GE(r.after.avgMinAngle, 50);
  EXPECT_LT(r.fidelity.hausdorffPercent, 2.0);
  const Topology got = analyzeTopology(r.output), want = analyzeTopology(input);
  EXPECT_EQ(got.genus, want.genus);
  EXPECT_EQ(got.boundaryLoops.size(), 0u);
  EXPECT_EQ(got.components, 1);
  EXPECT_NEAR(r.output.vertexCount(), 1000, 20);
  // The recording is the largest chart's: on a closed surface its whole border is seams with
  // the other charts, for the inspector to draw on the map and on each iteration's mesh.
  size_t borderEdges = 0;
  for (const auto& loop : analyzeTopology(r.recording.input).boundaryLoops) borderEdges += loop.size();
  EXPECT_EQ(r.recording.sharedSeams.size(), borderEdges);
  Replay replay(r.recording);
  EXPECT_EQ(replay.sharedSeamsOnOutput().size(), r.recording.sharedSeams.size());  // 974 without Chart::nodeSamples
  // Edges of the mesh each method shows, retriangulate's (numbered by site) and relocate's
  // (numbered as the chart, whose border vertices come first, in the fixed sites' order).
  auto onOutput = [&] {
    std::set<std::pair<int, int>> edges;
    for (const Triangle& t : replay.view(replay.iterationCount() - 1).output.triangles)
      for (int k = 0; k < 3; ++k) edges.insert(std::minmax(t[k], t[(k + 1) % 3]));
    int missing = 0;
    for (const auto& [a, b] : replay.sharedSeamsOnOutput()) missing += !edges.count(std::minmax(a, b));
    return missing;
  };
  EXPECT_EQ(onOutput(), 0);
  ASSERT_TRUE(replay.canRelocate());
  replay.setMethod(RemeshMethod::Relocate);
  EXPECT_EQ(onOutput(), 0);
}

// A disk no conformal map holds (LSCM's border overlaps itself, and the mean-value map on a
// circle takes over) is remeshed chart by chart too, as a closed surface would be, and the
// better kept; a disk LSCM maps is not.
TEST(Charts, ADiskNoConformalMapHoldsIsRemeshedChartByChartToo) {
  const Mesh ruffled = ruffledDisk();
  ParamOptions lscm;
  lscm.method = ParamMethod::Lscm;
  EXPECT_THROW(parameterize(ruffled, lscm, "ruffled"), Error);
  RemeshOptions options;
  options.sites.count = 300;
  const RemeshResult r = remesh(ruffled, options, "ruffled");
  ASSERT_TRUE(r.chartTrial.has_value());
  EXPECT_EQ(r.chartTrial->failed, "");
  EXPECT_GT(r.chartTrial->charts, 1);
  EXPECT_EQ(r.charts > 0, r.chartTrial->chartsBetter());
  EXPECT_DOUBLE_EQ(r.after.avgMinAngle, r.charts > 0 ? r.chartTrial->chartsAvgMinAngle
                                                     : r.chartTrial->oneCutAvgMinAngle);
  EXPECT_TRUE(analyzeTopology(r.output).isDisk());

  const RemeshResult flat = remesh(test::grid(12), options, "grid");
  EXPECT_EQ(flat.paramUsed, ParamMethod::Lscm);
  EXPECT_FALSE(flat.chartTrial.has_value());
}

// The smallest angle of the triangles with an edge on m's border.
double smallestAngleOnTheBorder(const Mesh& m) {
  std::set<std::pair<int, int>> border;  // (a < b)
  for (const std::vector<int>& loop : analyzeTopology(m).boundaryLoops)
    for (size_t i = 0; i < loop.size(); ++i) border.insert(std::minmax(loop[i], loop[(i + 1) % loop.size()]));
  double smallest = 180;
  for (const Triangle& t : m.triangles)
    for (int k = 0; k < 3; ++k)
      if (border.count(std::minmax(t[k], t[(k + 1) % 3]))) {
        const auto angles = cornerAnglesDeg(m.points[t[0]], m.points[t[1]], m.points[t[2]]);
        smallest = std::min(smallest, std::min({angles[0], angles[1], angles[2]}));
      }
  return smallest;
}

// CGAL's lion (5 boundary loops) at 2000 vertices, remeshed chart by chart: where two charts'
// seams meet its border close together, the border edge between them is short and the
// triangle on it thin (17.6 degrees without collapseShortBorderEdges in the last steps).
TEST(Charts, ShortBorderEdgesBetweenSeamsCollapse) {
  const std::string path = test::cgalSample("lion.off");
  SKIP_UNLESS_EXTRACTED(path);
  RemeshOptions options;
  options.simplifyTo = 2000;
  options.measureFidelity = false;
  const RemeshResult r = remeshCharts(readMesh(path).mesh, options, path);
  EXPECT_GT(r.charts, 1);
  EXPECT_GT(smallestAngleOnTheBorder(r.output), 20.0);
}

// Which of the two results remesh() keeps: the charts where they are rounder and not much
// farther, or much rounder and not much farther, or much closer and nearly as round (the spool: 1.60% against 2.41%, 1.1 deg less).
// A chart's border is all seams with its neighbours: its last steps (the snaps to tips, the
// valence flips on the finished surface, the fit) wait until the charts are stitched, where
// they see the whole surface and the seams are inside it.
TEST(Charts, AChartsLastStepsWaitForTheStitch) {
  const Mesh disk = readMesh(test::assetPath("bumpy_disk.off")).mesh;
  RemeshOptions whole;
  whole.sites.count = 300;
  whole.measureFidelity = false;
  RemeshOptions chart = whole;
  chart.sites.onSeam = vertexEdges(disk).onBoundary;
  chart.sites.seamNode.assign(disk.vertexCount(), false);
  chart.sites.spacing = 0.08;
  ASSERT_TRUE(chart.sites.sharesSeams());
  auto finished = [&](const RemeshOptions& o) {
    RemeshSession session(disk, o, "bumpy");
    while (!session.finished()) session.step();
    return session.finish();
  };
  EXPECT_GT(finished(whole).fit.moved, 0);
  const RemeshResult r = finished(chart);
  EXPECT_EQ(r.fit.moved, 0);
  EXPECT_EQ(r.snappedTips, 0);
}

TEST(Charts, AreKeptWhereTheyMeetMoreBarsOrAreRounderOrCloser) {
  auto trial = [](double chartsAngle, double oneCutAngle, double chartsDistance, double oneCutDistance,
                  int chartsBars = 0, int oneCutBars = 0, bool forBars = false, bool oneCutFolds = false,
                  bool chartsFold = false) {
    ChartTrial t;
    t.forBars = forBars;
    t.oneCutFolds = oneCutFolds;
    t.chartsFold = chartsFold;
    t.chartsBars = chartsBars;
    t.oneCutBars = oneCutBars;
    t.chartsAvgMinAngle = chartsAngle;
    t.oneCutAvgMinAngle = oneCutAngle;
    t.chartsHausdorff = chartsDistance;
    t.oneCutHausdorff = oneCutDistance;
    return t.chartsBetter();
  };
  EXPECT_TRUE(trial(52.0, 48.0, 1.05, 1.0));   // rounder, a little farther
  EXPECT_FALSE(trial(50.0, 48.5, 1.2, 1.0));   // rounder, but farther
  EXPECT_TRUE(trial(53.6, 49.1, 0.693, 0.617));  // Homer's clipped half: much rounder, 1.12x as far
  EXPECT_FALSE(trial(51.1, 48.8, 1.642, 1.252)); // CGAL's dino: much rounder, but 1.31x as far
  EXPECT_TRUE(trial(53.2, 54.3, 1.60, 2.41));  // the spool: closer, nearly as round
  EXPECT_FALSE(trial(52.0, 54.5, 0.5, 1.0));   // closer, but much less round
  EXPECT_FALSE(trial(54.0, 54.0, 0.9, 1.0));   // as round and a little closer: not worth it
  // More of issue 5's bars met decides first: CGAL's anchor, its one cut 1.2 deg at worst.
  EXPECT_TRUE(trial(53.6, 51.9, 1.243, 1.124, 2, 1));
  EXPECT_FALSE(trial(53.6, 51.9, 1.243, 1.124, 1, 2));
  EXPECT_FALSE(trial(53.6, 51.9, 1.243, 1.124, 2, 2));  // as many: 1.7 deg rounder, 1.11x as far
  EXPECT_FALSE(trial(53.4, 51.7, 1.645, 1.207, 2, 1));  // CGAL's dino: more bars, but 1.36x as far
  EXPECT_TRUE(trial(53.2, 54.3, 1.60, 2.41, 1, 2));     // the spool: fewer bars, but far closer
  // Tried only for the bars a disk missed: only more bars keep the charts.
  EXPECT_FALSE(trial(53.2, 54.3, 1.60, 2.41, 1, 2, true));
  EXPECT_FALSE(trial(51.8, 53.3, 1.565, 2.293, 0, 2, true));  // the armadillo's half at 500: closer
  EXPECT_FALSE(trial(53.6, 51.9, 1.243, 1.124, 2, 2, true));
  EXPECT_TRUE(trial(57.7, 46.6, 0.240, 0.916, 3, 2, true));   // the octahedron's half at 500
  // A result that folds back on itself where the input does not is broken, however close: a
  // flat annulus at 700, its one disk turned a triangle over (0.2 degrees).
  EXPECT_TRUE(trial(55.0, 52.2, 0.143, 0.077, 3, 1, false, true, false));
  EXPECT_TRUE(trial(55.0, 52.2, 0.143, 0.077, 0, 1, true, true, false));  // tried for the bars too
  EXPECT_FALSE(trial(57.7, 46.6, 0.240, 0.916, 3, 2, true, false, true));  // the charts fold
  EXPECT_FALSE(trial(55.0, 52.2, 0.143, 0.077, 3, 1, false, true, true));  // both: as without
}

// Four faces of an octahedron, open: a pyramid whose map to one disk held. As one disk its
// result misses a bar at 500 vertices with the first pass and without (an average smallest
// angle of 46.6 degrees: the cells bend over its edges); chart by chart, one face each, it
// meets all three.
// Four faces of an octahedron, folded at right angles: a disk no one map of which meets the bars.
Mesh halfOctahedron() {
  Mesh pyramid;
  pyramid.points = {{0, 0, 2}, {0, 2, 0}, {-2, 0, 0}, {0, -2, 0}, {0, 0, -2}};
  pyramid.triangles = {{3, 0, 2}, {2, 0, 1}, {1, 4, 2}, {2, 4, 3}};
  return pyramid;
}

TEST(Charts, ADiskThatMissesABarEitherWayIsRemeshedChartByChartToo) {
  const Mesh pyramid = halfOctahedron();
  RemeshOptions o;
  o.sites.count = 500;
  const RemeshResult r = remesh(pyramid, o, "octahedron_0.off");
  ASSERT_TRUE(r.chartTrial.has_value());
  EXPECT_TRUE(r.chartTrial->forBars);
  EXPECT_LT(r.chartTrial->oneCutBars, 3);
  EXPECT_EQ(r.charts, 4);
  EXPECT_LE(r.after.irregularBoundaryAware, 15.0);
  EXPECT_GE(r.after.minAngle, 30.0);
  EXPECT_GE(r.after.avgMinAngle, 53.0);
  EXPECT_TRUE(analyzeTopology(r.output).isDisk());
}

// Two of them, side by side: the larger's charts, its chart trial and its largest chart stand
// for the run, as its recording and map do (it was said to be one disk, and one chart's map
// its whole map).
TEST(Charts, ComponentsSayTheChartsTheLargestWasRemeshedIn) {
  Mesh two = halfOctahedron();
  append(two, test::moved(halfOctahedron(), 0.5, Vec3(10, 0, 0)));
  RemeshOptions o;
  o.sites.count = 600;
  o.measureFidelity = false;
  const RemeshResult r = remesh(two, o, "two half octahedra");
  ASSERT_EQ(r.components, 2);
  EXPECT_EQ(r.charts, 4);
  ASSERT_TRUE(r.chartTrial.has_value());
  EXPECT_TRUE(r.chartTrial->forBars);
  EXPECT_GT(r.largestChart.vertexCount(), 0);
}
