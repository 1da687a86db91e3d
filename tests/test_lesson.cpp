#include "lesson.h"
#include "test_support.h"

#include <algorithm>
#include <limits>

using namespace lloydscope;

TEST(Lesson, PlanTellsThePipelineInOrder) {
  const std::vector<LessonStep> plan = lessonPlan(5, 3);
  ASSERT_EQ(plan.size(), 2u + 3 * 3 + 2 + 3);
  EXPECT_EQ(plan[0].stage, Stage::Load);
  EXPECT_EQ(plan[1].stage, Stage::Parameterize);
  const Stage cycle[] = {Stage::Voronoi, Stage::Centroids, Stage::Move};
  for (int k = 0; k < 3; ++k)
    for (int s = 0; s < 3; ++s) {
      EXPECT_EQ(plan[2 + 3 * k + s].stage, cycle[s]);
      EXPECT_EQ(plan[2 + 3 * k + s].iteration, k);
    }
  EXPECT_EQ(plan[11].iteration, 3);
  EXPECT_EQ(plan[12].iteration, 4);
  EXPECT_LT(plan[12].seconds, plan[2].seconds);  // the later iterations go by quickly
  EXPECT_EQ(plan[13].stage, Stage::Lift);
  EXPECT_EQ(plan[14].stage, Stage::Result);
  EXPECT_EQ(plan.back().stage, Stage::Valence);
  EXPECT_EQ(plan.back().iteration, 4);
}

TEST(Lesson, PlayerAdvancesAndStopsOnTheLastStage) {
  LessonPlayer player;
  EXPECT_FALSE(player.playing());
  player.start(lessonPlan(4, 1));
  EXPECT_EQ(player.current().stage, Stage::Load);
  player.advance(3.9f);
  EXPECT_EQ(player.current().stage, Stage::Load);
  player.advance(0.2f);
  EXPECT_EQ(player.current().stage, Stage::Parameterize);
  player.advance(4.0f + 3.0f);  // past parameterize and the first Voronoi
  EXPECT_EQ(player.current().stage, Stage::Centroids);
  EXPECT_FALSE(player.atLastStep());
  // The window sleeps until the next step shows.
  EXPECT_FLOAT_EQ(player.secondsToNextStep(), player.current().seconds - 0.1f);  // 0.1 s into Centroids
  player.togglePause();
  EXPECT_EQ(player.secondsToNextStep(), std::numeric_limits<float>::infinity());
  player.togglePause();
  player.advance(1000.0f);
  EXPECT_TRUE(player.playing());
  EXPECT_EQ(player.current().stage, Stage::Valence);
  EXPECT_EQ(player.current().iteration, 3);
  // Nothing moves any more: the window may sleep on the result beside the slides.
  EXPECT_TRUE(player.atLastStep());
  EXPECT_EQ(player.secondsToNextStep(), std::numeric_limits<float>::infinity());
  player.stop();
  EXPECT_FALSE(player.atLastStep());
  EXPECT_FALSE(player.playing());
}

// Paused, the lesson stays on its stage however long the frames run; a new lesson starts
// unpaused.
TEST(Lesson, APausedLessonStaysOnItsStage) {
  LessonPlayer player;
  player.start(lessonPlan(4, 1));
  player.togglePause();
  EXPECT_TRUE(player.paused());
  player.advance(1000.0f);
  EXPECT_EQ(player.current().stage, Stage::Load);
  player.togglePause();
  player.advance(4.1f);
  EXPECT_EQ(player.current().stage, Stage::Parameterize);
  player.togglePause();
  player.start(lessonPlan(4, 1));
  EXPECT_FALSE(player.paused());
}

// The arrow keys during a lesson: a whole step back or on, from its start, paused or not;
// Home and End skip past either end and stop there.
TEST(Lesson, SkipGoesBackAndOnByWholeSteps) {
  LessonPlayer player;
  player.skip(1);  // no lesson: nothing to do
  EXPECT_FALSE(player.playing());
  player.start(lessonPlan(4, 1));
  player.skip(1);
  EXPECT_EQ(player.current().stage, Stage::Parameterize);
  player.advance(3.9f);  // Parameterize shown from its start: 4 s
  EXPECT_EQ(player.current().stage, Stage::Parameterize);
  player.skip(-5);
  EXPECT_EQ(player.current().stage, Stage::Load);
  player.togglePause();
  player.skip(5);  // paused: Parameterize; Voronoi, Centroids, Move at iteration 0; Move at 1
  EXPECT_EQ(player.current().stage, Stage::Move);
  EXPECT_EQ(player.current().iteration, 1);
  EXPECT_TRUE(player.paused());
  player.advance(1000.0f);
  EXPECT_EQ(player.current().iteration, 1);
  player.skip(std::numeric_limits<int>::max());
  EXPECT_EQ(player.current().stage, Stage::Valence);
  player.skip(-std::numeric_limits<int>::max());
  EXPECT_EQ(player.current().stage, Stage::Load);
}

// A step that comes due in the frame of a key press was never on screen: → goes to it, ←
// back from the step shown (the window, asleep until the next step, wakes for both at once).
TEST(Lesson, SkipGoesFromTheStepOnScreen) {
  LessonPlayer player;
  player.start(lessonPlan(4, 1));
  player.advance(3.9f);
  EXPECT_EQ(player.current().stage, Stage::Load);
  player.advance(0.2f);  // Parameterize comes due in this frame, and → is pressed in it
  player.skip(1);
  EXPECT_EQ(player.current().stage, Stage::Parameterize);
  player.advance(4.1f);  // Voronoi comes due, and ← is pressed
  player.skip(-1);
  EXPECT_EQ(player.current().stage, Stage::Load);
  player.advance(0.0f);
  player.skip(1);  // two presses in two frames: two steps on
  player.advance(0.0f);
  player.skip(1);
  EXPECT_EQ(player.current().stage, Stage::Voronoi);
}

TEST(Lesson, StagesRevealOneLayerAtATime) {
  const Layers load = layersFor(Stage::Load), voronoi = layersFor(Stage::Voronoi),
               centroids = layersFor(Stage::Centroids), move = layersFor(Stage::Move),
               result = layersFor(Stage::Result);
  EXPECT_TRUE(load.input3D);
  EXPECT_FALSE(load.mapped3D);  // the mesh as opened
  EXPECT_FALSE(load.cells2D || load.sites2D || load.triangles2D);
  EXPECT_TRUE(layersFor(Stage::Parameterize).triangles2D);
  // From Parameterize on, the 3D pane shows the mesh the 2D pane shows flattened (on
  // nefertiti, the input beside its rough first remeshing's map: two triangulations).
  EXPECT_TRUE(layersFor(Stage::Parameterize).mapped3D && voronoi.mapped3D && layersFor(Stage::Lift).mapped3D);
  EXPECT_TRUE(voronoi.cells2D && voronoi.sites2D && !voronoi.centroids2D);
  EXPECT_TRUE(centroids.centroids2D && !centroids.arrows2D);
  EXPECT_TRUE(move.arrows2D);
  EXPECT_FALSE(result.input3D);
  EXPECT_TRUE(layersFor(Stage::Valence) == result);  // the same panes, the cells filled by valence
}

TEST(Lesson, CaptionsQuoteThePinnedCell) {
  CaptionFacts facts;
  facts.iterations = 10;
  facts.iteration = 2;
  facts.solver = "lloyd";
  CellDetails cell;
  cell.index = 42;
  cell.shoelaceArea = 1.234567e-3;
  cell.mass = 2.345678e-3;
  cell.centroid = Vec2(0.2345678, 0.75);
  facts.cell = cell;
  const Caption voronoi = caption(Stage::Voronoi, facts);
  EXPECT_EQ(voronoi.title, "3  Voronoi");
  EXPECT_NE(voronoi.numbers.find("Cell 42"), std::string::npos);
  // Seven digits: a class works c out from M and the moment.
  EXPECT_NE(voronoi.numbers.find("1.234567e-03"), std::string::npos) << voronoi.numbers;
  const Caption centroids = caption(Stage::Centroids, facts);
  EXPECT_NE(centroids.numbers.find("2.345678e-03"), std::string::npos) << centroids.numbers;
  EXPECT_NE(centroids.numbers.find("(0.234568, 0.750000)"), std::string::npos) << centroids.numbers;
  EXPECT_NE(caption(Stage::Move, facts).formula.find("Lloyd"), std::string::npos);
  facts.solver = "newton";
  EXPECT_EQ(caption(Stage::Move, facts).formula.rfind("Newton", 0), 0u);
  facts.solver = "lbfgs";
  EXPECT_EQ(caption(Stage::Move, facts).formula.rfind("L-BFGS", 0), 0u);
  facts.cell.reset();
  EXPECT_NE(caption(Stage::Voronoi, facts).numbers.find("Iteration 2 (0-9)"), std::string::npos);
}

// The last stage quotes what remesh writes, after the clean-up, and says so (it quoted the last
// iteration's mesh before the clean-up: 22% irregular where the result has 19%).
TEST(Lesson, TheResultCaptionSaysWhetherItIsCleanedUp) {
  CaptionFacts facts;
  facts.method = "retriangulate";
  facts.result.irregularPercent = 19.3;
  EXPECT_EQ(caption(Stage::Result, facts).formula.find("cleaned up"), std::string::npos);
  facts.cleanedUp = true;
  const Caption c = caption(Stage::Result, facts);
  EXPECT_NE(c.formula.find("cleaned up on the surface"), std::string::npos) << c.formula;
  EXPECT_NE(c.numbers.find("→ 19%"), std::string::npos) << c.numbers;
}

// The first caption says what the input is and how it was opened into a disk: it said "a
// topological disk" for the closed eight too.
TEST(Lesson, TheLoadCaptionSaysWhatTheSurfaceIsAndHowItWasOpened) {
  CaptionFacts facts;
  EXPECT_EQ(caption(Stage::Load, facts).formula, "The input: a triangle mesh of a topological disk.");
  facts.surface = "a closed surface of genus 2";
  facts.disk = false;
  facts.seamEdges = 40;
  EXPECT_EQ(caption(Stage::Load, facts).formula,
            "The input: a triangle mesh of a closed surface of genus 2, cut open along seams "
            "(purple) into a topological disk.");
  facts.charts = 5;
  EXPECT_NE(caption(Stage::Load, facts).formula.find("split into 5 charts"), std::string::npos);
  CaptionFacts slit;
  slit.seamEdges = 12;
  EXPECT_NE(caption(Stage::Load, slit).formula.find("slit along seams"), std::string::npos);
}

// "Nearly equilateral" only where the result's numbers say so (relocate on a closed surface,
// or an early iteration, can be worse than the input).
TEST(Lesson, TheResultCaptionClaimsNearlyEquilateralOnlyWhenItIs) {
  CaptionFacts facts;
  facts.method = "retriangulate";
  facts.result.avgMinAngle = 54.8;
  EXPECT_NE(caption(Stage::Result, facts).formula.find("nearly equilateral"), std::string::npos);
  facts.result.avgMinAngle = 31.0;
  EXPECT_EQ(caption(Stage::Result, facts).formula.find("nearly equilateral"), std::string::npos);
}

// A recording holds the mesh that was parameterized (a first remeshing, as regular as the
// result), not the input: "irregular 33% → 34%" under "a new mesh of nearly equilateral
// triangles" read as the result being worse than the input.
TEST(Lesson, TheResultCaptionSaysWhatARecordingComparesWith) {
  CaptionFacts facts;
  facts.method = "retriangulate";
  EXPECT_EQ(caption(Stage::Result, facts).numbers.find("parameterized"), std::string::npos);
  facts.inputIsMapped = true;
  EXPECT_NE(caption(Stage::Result, facts).numbers.find("from the mesh that was parameterized"), std::string::npos);
}

// A recording's Load stage quoted the mapped mesh's numbers under "The input" (531 vertices,
// 34% irregular, for a 25,905-vertex face); uniform density makes up for no distortion; a
// fixed cell's |c − s| in the Move stage is not a move (it was ten times the largest move).
TEST(Lesson, CaptionsSayWhatTheirNumbersAreOf) {
  CaptionFacts facts;
  EXPECT_EQ(caption(Stage::Load, facts).formula.rfind("The input: ", 0), 0u);
  facts.inputIsMapped = true;
  EXPECT_EQ(caption(Stage::Load, facts).formula.rfind("The mesh that was parameterized", 0), 0u);
  facts.density = "area";
  EXPECT_NE(caption(Stage::Parameterize, facts).numbers.find("The density ρ makes up for it."), std::string::npos);
  facts.density = "uniform";
  EXPECT_EQ(caption(Stage::Parameterize, facts).numbers.find("The density ρ makes up"), std::string::npos);
  EXPECT_NE(caption(Stage::Parameterize, facts).numbers.find("nothing makes up for it"), std::string::npos);
  CellDetails cell;
  cell.index = 50;
  cell.fixed = true;
  facts.cell = cell;
  EXPECT_NE(caption(Stage::Move, facts).numbers.find("cell 50 (a fixed border site: it does not move)"),
            std::string::npos);
}

// The map of a run with the first pass is the rough remeshing's, and the caption says so: it
// is why the sites start evenly spread.
// The Move stage's number is the largest |c − s|: it was called the largest move, and under
// L-BFGS the sites moved farther than it (the fill "moved since k-1" reached 1.67e-03 where
// the "largest move" was 1.06e-03).
TEST(Lesson, TheMoveCaptionSaysItsNumberIsTheDistanceToTheCentroid) {
  CaptionFacts facts;
  facts.maxToCentroid = 1.06e-3;
  const std::string numbers = caption(Stage::Move, facts).numbers;
  EXPECT_NE(numbers.find("largest |c\u00a0−\u00a0s| 1.06e-03"), std::string::npos) << numbers;
  EXPECT_EQ(numbers.find("move "), std::string::npos) << numbers;
}

// inspect --stage load showed the input beside the plots and the status bar of the converged
// run (iteration 159): the stages before any step are at iteration 0, as in the lesson.
TEST(Lesson, AStageShownAloneIsAtTheIterationItIsAbout) {
  const std::vector<LessonStep> plan = lessonPlan(160);
  for (Stage stage : {Stage::Load, Stage::Parameterize, Stage::Lift, Stage::Result, Stage::Valence}) {
    const auto first = std::find_if(plan.begin(), plan.end(), [&](const LessonStep& s) { return s.stage == stage; });
    ASSERT_NE(first, plan.end());
    EXPECT_EQ(stageIteration(stage, 160), first->iteration) << static_cast<int>(stage);
  }
  EXPECT_EQ(stageIteration(Stage::Load, 160), 0);
  EXPECT_EQ(stageIteration(Stage::Voronoi, 160), 159);
  EXPECT_EQ(stageIteration(Stage::Move, 1), 0);
}

TEST(Lesson, TheParameterizeCaptionSaysWhichMeshWasFlattened) {
  CaptionFacts facts;
  facts.param = "lscm";
  EXPECT_EQ(caption(Stage::Parameterize, facts).formula.find("first remeshing"), std::string::npos);
  facts.firstPass = true;
  EXPECT_NE(caption(Stage::Parameterize, facts).formula.find("first remeshing"), std::string::npos);
}

TEST(Lesson, StageNamesRoundTrip) {
  for (Stage s : {Stage::Load, Stage::Parameterize, Stage::Voronoi, Stage::Centroids, Stage::Move,
                  Stage::Lift, Stage::Result, Stage::Valence})
    EXPECT_EQ(parseStage(toString(s)), s);
  EXPECT_THROW(parseStage("lunch"), Error);
}

// The Lift stage says whether the run converged: after Restart and three Steps it said
// "3 iterations to convergence".
TEST(Lesson, TheLiftCaptionSaysWhetherTheRunConverged) {
  CaptionFacts facts;
  facts.iterations = 3;
  facts.converged = false;
  EXPECT_EQ(caption(Stage::Lift, facts).numbers, "3 iterations, not converged.");
  facts.iterations = 160;
  facts.converged = true;
  EXPECT_EQ(caption(Stage::Lift, facts).numbers, "160 iterations to convergence.");
}

// The Valence stage counts the iteration's irregular vertices by kind and quotes the curvature
// the surface asks for, beside the irregularity they make.
TEST(Lesson, TheValenceCaptionCountsTheIrregularVertices) {
  CaptionFacts facts;
  facts.iteration = 159;
  facts.result.irregularBoundaryAware = 12.6;
  facts.result.curvatureDefects = 1.6;
  facts.fives = 64;
  facts.sevens = 60;
  facts.otherIrregular = 2;
  const Caption c = caption(Stage::Valence, facts);
  EXPECT_EQ(c.title, "8  Valence");
  EXPECT_NE(c.formula.find("a 5 (blue) sits where it bulges, a 7 (red) at a saddle"), std::string::npos) << c.formula;
  EXPECT_EQ(c.numbers, "Iteration 159: 64 fives, 60 sevens, 2 others: 12.6% irregular (border-aware); "
                       "curvature asks for 1.6%");
  facts.otherIrregular = 1;
  EXPECT_NE(caption(Stage::Valence, facts).numbers.find(", 1 other:"), std::string::npos);
}
