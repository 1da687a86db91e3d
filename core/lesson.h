// The classroom lesson: the pipeline told as stages (load, parameterize, then Voronoi,
// centroids and move for each iteration, then lift, the result and its valences), what each
// stage shows, and the caption that names it with the formulas in use and their numbers.
#pragma once

#include "inspection.h"
#include "metrics.h"
#include "parameterization.h"

#include <optional>
#include <string>
#include <vector>

namespace lloydscope {

// Valence: the result's irregular vertices, its cells filled by valence (the inspector's
// "valence" fill), and why they are where they are.
enum class Stage { Load, Parameterize, Voronoi, Centroids, Move, Lift, Result, Valence };

const char* toString(Stage stage);            // "load", "parameterize", ...
Stage parseStage(const std::string& name);    // throws Error naming the choices

// What the panes show at a stage: the stages reveal the method one layer at a time.
struct Layers {
  bool input3D = false;      // the input mesh, not the result
  // With input3D: the mesh that was parameterized (a rough first remeshing of the input, say),
  // the one the 2D pane shows flattened, not the input as opened.
  bool mapped3D = false;
  bool sites3D = false;      // the sites lifted to the surface
  bool triangles2D = false;  // the parameter triangles
  bool cells2D = false, sites2D = false, centroids2D = false, arrows2D = false;
  bool operator==(const Layers& o) const {
    return input3D == o.input3D && mapped3D == o.mapped3D && sites3D == o.sites3D && triangles2D == o.triangles2D &&
           cells2D == o.cells2D && sites2D == o.sites2D && centroids2D == o.centroids2D &&
           arrows2D == o.arrows2D;
  }
};
Layers layersFor(Stage stage);
// The iteration a stage is shown at when none is asked (inspect --stage): Load and
// Parameterize come before any step, at 0 as in the lesson; the others at the last of
// `iterationCount`, inspect's own default (where the lesson shows Lift and Result).
int stageIteration(Stage stage, int iterationCount);

// One step of the lesson: a stage, at an iteration, for some seconds (at speed 1).
struct LessonStep {
  Stage stage;
  int iteration;
  float seconds;
};

// Load and parameterize, then Voronoi, centroids and move for the first `slowIterations`
// iterations one at a time, then the other iterations quickly, then lift, the result and its
// valences.
std::vector<LessonStep> lessonPlan(int iterationCount, int slowIterations = 3);

// Plays a plan: advance() by the frame's seconds times a speed factor. Paused, it stays on its
// step (a lecturer stops at a stage to work one cell's numbers with the class); skip() goes
// back or on by whole steps, paused or not, each shown from its start.
class LessonPlayer {
 public:
  void start(std::vector<LessonStep> plan);
  void stop() { plan_.clear(); }
  bool playing() const { return !plan_.empty(); }
  void togglePause() { paused_ = !paused_; }
  bool paused() const { return paused_; }
  // On its last step, which stays on screen until the lesson is ended: nothing moves.
  bool atLastStep() const { return playing() && next_ + 1 == plan_.size(); }
  // How much more advance() the current step takes before the next one shows (in its
  // seconds; infinite on the last step, or paused): until then the picture stays.
  float secondsToNextStep() const;
  // A frame's time: called once a frame, before its keys' skip().
  void advance(float seconds);
  // From the step on screen (the one before this frame's advance(): a step that came due in
  // the frame of a key press was never shown, and → skipped it), clamped to the first and the
  // last step.
  void skip(long steps);
  const LessonStep& current() const { return plan_.at(next_); }

 private:
  std::vector<LessonStep> plan_;
  size_t next_ = 0, shown_ = 0;
  float clock_ = 0;
  bool paused_ = false;
};

// The numbers a caption quotes.
struct CaptionFacts {
  std::string mesh;
  // What the input is (Topology::describe) and how it was opened up: seam edges cut (or slit
  // into a disk), or charts flattened one by one.
  std::string surface = "a topological disk";
  bool disk = true;
  int seamEdges = 0, charts = 0;
  QualityMetrics input, result;
  std::string param, solver, method, density;  // as the settings name them
  std::string border = "free border";  // the map's (borderPhrase)
  bool firstPass = false;  // the map is of a rough first remeshing, whose vertices are the first sites
  bool cleanedUp = false;  // `result` is the final one, after the clean-up on the surface
  // `input` is the mesh that was parameterized, not the one opened (a recording holds no
  // input; its map's mesh may be a first remeshing, as good as the result)
  bool inputIsMapped = false;
  Distortion distortion;
  int iteration = 0, iterations = 0;
  bool converged = true;  // the run met its thresholds in `iterations`
  // The largest distance from a movable site to its centroid (a Lloyd step's largest move, not
  // an L-BFGS or Newton step's), and the % of movable sites farther than the threshold.
  double energy = 0, maxToCentroid = 0, percentMoving = 0;
  double arrowScale = 1;  // the Move stage's arrows are drawn so many times as long
  std::optional<CellDetails> cell;  // the cell pinned last, if any
  // The Valence stage: the iteration's result's irregular vertices, 5s and 7s inside and the
  // others (further off, or on the border).
  int fives = 0, sevens = 0, otherIrregular = 0;
};

struct Caption {
  std::string title;     // "3  Voronoi", the stage and its number
  std::string formula;   // what happens, with the formula in use
  std::string numbers;   // the formula with this iteration's (or the pinned cell's) numbers
};
Caption caption(Stage stage, const CaptionFacts& facts);

}  // namespace lloydscope
