#include "mesh_io.h"
#include "inspection.h"
#include "replay.h"
#include "topology.h"
#include "test_support.h"

using namespace lloydscope;

// A recording holds the disk its map is of: its surface is that disk, stitched back where it
// was cut open (a torus, here, of genus 1 and closed; a disk the pipeline did not cut, as it is).
TEST(Replay, ARecordingsSurfaceIsItsDiskStitched) {
  const RemeshOptions o = test::shortRun(300, 2);
  const Topology torus = Replay(remesh(test::torus(), o, "torus").recording).surface();
  EXPECT_EQ(torus.genus, 1);
  EXPECT_TRUE(torus.boundaryLoops.empty());
  EXPECT_TRUE(Replay(remesh(test::grid(10), o, "grid").recording).surface().isDisk());
}

TEST(Replay, ShowsExactlyWhatTheSolverComputed) {
  RemeshOptions o;
  o.measureFidelity = false;
  o.lloyd.maxIterations = 15;
  const Mesh input = readMesh(test::assetPath("jittered_grid.off")).mesh;
  const RemeshResult run = remesh(input, o, "grid");
  Replay replay(run.recording);
  ASSERT_EQ(replay.iterationCount(), 15);
  for (int k : {14, 3, 0, 9}) {  // any order
    const IterationView& v = replay.view(k);
    EXPECT_EQ(v.index, k);
    const IterationRecord& it = run.recording.iterations[k];
    ASSERT_EQ(v.cells.size(), run.recording.fixedSites.size() + it.sites.size());
    // The solver's own numbers, bit for bit: its energy and largest site-to-centroid move.
    double energy = 0, largest = 0;
    for (const BoundedCell& c : v.cells) energy += c.energy;
    for (size_t i = 0; i < it.sites.size(); ++i) {
      const BoundedCell& cell = v.cells[run.recording.fixedSites.size() + i];
      EXPECT_EQ(v.sites[run.recording.fixedSites.size() + i], it.sites[i]);
      largest = std::max(largest, (cell.centroid - it.sites[i]).norm());
      EXPECT_FALSE(cell.pieces.empty());
    }
    EXPECT_EQ(energy, it.energy);
    EXPECT_EQ(largest, it.maxDisplacement);
    EXPECT_EQ(v.liftedSites.size(), v.sites.size());
    EXPECT_NO_THROW(validateMesh(v.output, "view"));
  }
  // The same k again: nothing recomputed (a mark left in the view stays; comparing the two
  // references' addresses could not fail, the view being one member).
  const_cast<IterationView&>(replay.view(9)).cells[0].area = -1;
  EXPECT_EQ(replay.view(9).cells[0].area, -1);
  EXPECT_GT(replay.view(8).cells[0].area, 0);
  EXPECT_EQ(replay.view(1000).index, 14);      // clamped
}

TEST(Replay, RelocateOnlyWhereSitesAreInputVertices) {
  RemeshOptions o = referencePreset(RemeshMethod::Relocate);
  o.measureFidelity = false;
  o.lloyd.maxIterations = 3;
  const Mesh input = readMesh(test::assetPath("jittered_grid.off")).mesh;
  Replay relocated(remesh(input, o, "grid").recording);
  EXPECT_TRUE(relocated.canRelocate());
  EXPECT_EQ(relocated.method(), RemeshMethod::Relocate);
  EXPECT_EQ(relocated.view(2).output.triangles, input.triangles);
  // Every vertex is a site, the border's the fixed ones: a border cell's valence is shown (it
  // was -1, as if its site had no vertex).
  const IterationView& view = relocated.view(2);
  const int fixedCount = static_cast<int>(relocated.recording().fixedSites.size());
  for (int v = 0; v < view.output.vertexCount(); ++v) {
    ASSERT_GE(view.outputSite[v], 0) << v;
    if (view.outputSite[v] < fixedCount) EXPECT_EQ(view.sites[view.outputSite[v]], view.outputUV[v]) << v;
  }
  const int borderVertex = static_cast<int>(
      std::find(view.outputSite.begin(), view.outputSite.end(), 0) - view.outputSite.begin());
  EXPECT_EQ(describeCell(relocated.recording(), relocated.domain(), view, 0).valence,
            vertexEdges(view.output).valence[borderVertex]);
  relocated.setMethod(RemeshMethod::Retriangulate);
  EXPECT_EQ(relocated.method(), RemeshMethod::Retriangulate);

  RemeshOptions sampled;  // sites drawn from the density, on the input itself
  sampled.resample = false;
  sampled.measureFidelity = false;
  sampled.lloyd.maxIterations = 3;
  Replay replay(remesh(input, sampled, "grid").recording);
  EXPECT_FALSE(replay.canRelocate());
  replay.setMethod(RemeshMethod::Relocate);
  EXPECT_EQ(replay.method(), RemeshMethod::Retriangulate);

  // A fan of a 24-gon: every vertex on the border, no site to move. Its relocate run's recording
  // relocates (the inspector greyed it, saying the run had placed its own sites).
  Mesh fan;
  for (int i = 0; i < 24; ++i) fan.points.emplace_back(std::cos(2 * M_PI * i / 24), std::sin(2 * M_PI * i / 24), 0);
  for (int i = 1; i + 1 < 24; ++i) fan.triangles.push_back({0, i, i + 1});
  RemeshOptions relocate;
  relocate.method = RemeshMethod::Relocate;
  relocate.measureFidelity = false;
  Replay still(remesh(fan, relocate, "fan").recording);
  ASSERT_EQ(still.recording().iterations.front().sites.size(), 0u);
  EXPECT_TRUE(still.canRelocate());
  EXPECT_EQ(still.method(), RemeshMethod::Relocate);
  EXPECT_EQ(still.view(0).output.triangles, fan.triangles);
}

TEST(Replay, GrowsWhileARunGoesOn) {
  RemeshOptions o;
  o.measureFidelity = false;
  const Mesh input = readMesh(test::assetPath("jittered_grid.off")).mesh;
  RemeshSession session(input, o, "grid");
  Recording header = session.header();
  header.iterations.push_back(session.step());
  Replay replay(std::move(header));
  EXPECT_EQ(replay.view(0).index, 0);
  for (int k = 1; k <= 3; ++k) replay.append(session.step());
  EXPECT_EQ(replay.iterationCount(), 4);
  EXPECT_EQ(replay.view(3).sites.size(), replay.view(0).sites.size());
  EXPECT_EQ(replay.view(3).index, 3);
}

// A surface cut open: each iteration's mesh is measured stitched, as the result will be (no
// border vertices left on a torus), and a disk's is not stitched at all.
TEST(Replay, ACutSurfacesIterationsAreStitched) {
  const Mesh torus = test::torus();
  RemeshOptions o;
  o.lloyd.maxIterations = 3;
  o.measureFidelity = false;
  Replay replay(remesh(torus, o, "torus").recording);
  const IterationView& view = replay.view(2);
  ASSERT_FALSE(view.stitched.triangles.empty());
  EXPECT_EQ(measureQuality(view.stitched).boundaryVertices, 0);
  EXPECT_GT(measureQuality(view.output).boundaryVertices, 0);
  const Topology t = analyzeTopology(view.stitched);
  EXPECT_EQ(t.genus, 1);
  EXPECT_TRUE(t.boundaryLoops.empty());

  Replay disk(remesh(test::grid(8), o, "grid").recording);
  EXPECT_TRUE(disk.view(1).stitched.triangles.empty());
}
