#include "lesson.h"

#include "names.h"

#include <algorithm>
#include <limits>
#include <cstdio>

namespace lloydscope {

namespace {

template <typename... Args>
std::string format(const char* pattern, Args... args) {
  char text[512];
  std::snprintf(text, sizeof text, pattern, args...);
  return text;
}

}  // namespace

constexpr NamedValue<Stage> kStageNames[] = {
    {Stage::Load, "load"}, {Stage::Parameterize, "parameterize"}, {Stage::Voronoi, "voronoi"},
    {Stage::Centroids, "centroids"}, {Stage::Move, "move"}, {Stage::Lift, "lift"}, {Stage::Result, "result"},
    {Stage::Valence, "valence"}};

const char* toString(Stage stage) { return nameOf(kStageNames, stage); }

Stage parseStage(const std::string& name) { return parseName(kStageNames, name, "stage"); }

Layers layersFor(Stage stage) {
  Layers l;
  l.input3D = stage < Stage::Result;
  l.mapped3D = stage != Stage::Load;  // from Parameterize on, the mesh the map is of
  l.sites3D = stage >= Stage::Voronoi;
  l.triangles2D = stage != Stage::Load;
  l.cells2D = stage >= Stage::Voronoi;
  l.sites2D = stage >= Stage::Voronoi;
  l.centroids2D = stage >= Stage::Centroids && stage <= Stage::Move;
  l.arrows2D = stage == Stage::Move;
  return l;
}

int stageIteration(Stage stage, int iterationCount) {
  return stage <= Stage::Parameterize ? 0 : std::max(0, iterationCount - 1);
}

std::vector<LessonStep> lessonPlan(int iterationCount, int slowIterations) {
  std::vector<LessonStep> plan = {{Stage::Load, 0, 4.0f}, {Stage::Parameterize, 0, 4.0f}};
  for (int k = 0; k < iterationCount; ++k) {
    if (k < slowIterations) {
      plan.push_back({Stage::Voronoi, k, 3.0f});
      plan.push_back({Stage::Centroids, k, 3.0f});
      plan.push_back({Stage::Move, k, 3.0f});
    } else {
      plan.push_back({Stage::Move, k, 0.1f});
    }
  }
  const int last = std::max(0, iterationCount - 1);
  plan.push_back({Stage::Lift, last, 4.0f});
  plan.push_back({Stage::Result, last, 6.0f});
  plan.push_back({Stage::Valence, last, 8.0f});
  return plan;
}

void LessonPlayer::start(std::vector<LessonStep> plan) {
  plan_ = std::move(plan);
  next_ = shown_ = 0;
  clock_ = 0;
  paused_ = false;
}

void LessonPlayer::advance(float seconds) {
  shown_ = next_;
  if (!playing() || paused_) return;
  clock_ += seconds;
  while (clock_ >= plan_[next_].seconds) {
    clock_ -= plan_[next_].seconds;
    if (next_ + 1 == plan_.size()) {  // the last step stays on screen
      clock_ = 0;
      return;
    }
    ++next_;
  }
}

float LessonPlayer::secondsToNextStep() const {
  if (!playing() || paused_ || atLastStep()) return std::numeric_limits<float>::infinity();
  return std::max(0.0f, plan_[next_].seconds - clock_);
}

void LessonPlayer::skip(long steps) {
  if (!playing()) return;
  const long last = static_cast<long>(plan_.size()) - 1;
  next_ = shown_ = static_cast<size_t>(std::clamp(static_cast<long>(shown_) + steps, 0L, last));
  clock_ = 0;
}

// An average smallest angle from which the triangles are called nearly equilateral (60°: all
// equilateral; the report's results reach 43°, CGAL's remesher 51-53°).
constexpr double kNearlyEquilateral = 50;

Caption caption(Stage stage, const CaptionFacts& f) {
  Caption c;
  constexpr const char* kTitles[] = {"Load", "Parameterize", "Voronoi", "Centroids",
                                     "Move", "Lift",         "Result",  "Valence"};
  c.title = format("%d  %s", static_cast<int>(stage) + 1, kTitles[static_cast<int>(stage)]);
  const CellDetails* cell = f.cell ? &*f.cell : nullptr;
  switch (stage) {
    case Stage::Load:
      c.formula = std::string(f.inputIsMapped ? "The mesh that was parameterized (a recording holds no input): "
                                              : "The input: ") +
                  "a triangle mesh of " + f.surface +
                  (f.charts > 0 ? format(", split into %d charts flattened one by one (the panes "
                                         "show the largest)", f.charts)
                   : f.seamEdges == 0 ? std::string()
                   : f.disk ? ", slit along seams (purple) where its map would stretch most"
                            : ", cut open along seams (purple) into a topological disk") +
                  ".";
      c.numbers = format("%s: %d vertices, %d triangles, %.0f%% irregular vertices, "
                         "smallest angle %.1f°, average smallest angle %.1f°",
                         f.mesh.c_str(), f.input.vertices, f.input.faces, f.input.irregularPercent,
                         f.input.minAngle, f.input.avgMinAngle);
      break;
    case Stage::Parameterize:
      c.formula = format("The %s map flattens %s onto the plane (%s): every "
                         "point of the surface gets coordinates (u, v).",
                         f.param.c_str(),
                         f.firstPass ? "a rough first remeshing of the disk (its vertices are the first sites)" : "the disk",
                         f.border.c_str());
      c.numbers = format("Area distortion r = (3D area share) / (UV area share): %.2f to %.2f; "
                         "mean |ln r| = %.2f.%s",
                         f.distortion.minAreaRatio, f.distortion.maxAreaRatio,
                         f.distortion.meanLogAreaRatio,
                         f.density == "uniform" ? " The density is uniform: nothing makes up for it."
                         : f.density == "curvature" ? " The density ρ follows the curvature (and makes up for it)."
                                                    : " The density ρ makes up for it.");
      break;
    case Stage::Voronoi:
      c.formula = "Each site sᵢ owns the points nearer to it than to any other site, clipped "
                  "to the domain: its Voronoi cell Vᵢ.";
      c.numbers = cell ? format("Cell %d: area A = ½ Σ (xⱼ yⱼ₊₁ − xⱼ₊₁ yⱼ) = %.6e, "
                                "%d neighbours", cell->index, cell->shoelaceArea, cell->neighbours)
                       // As the status bar numbers them: "2 of 190" read as one fewer than the
                       // 191 iterations the Lift caption and the controls pane count.
                       : format("Iteration %d (0-%d). Pin a cell to see its numbers.", f.iteration,
                                f.iterations - 1);
      break;
    case Stage::Centroids:
      c.formula = "Each cell's centroid weighs its points by the density: "
                  "cᵢ = ∫ x ρ dA / ∫ ρ dA (rings).";
      // Seven digits, as the Selection table: with four, the class's M and moment gave a c
      // that differed from the one quoted in its fifth digit.
      // The quotient on a line of its own: at 960 px the one line broke inside a number.
      c.numbers = cell ? format("Cell %d: M = ∫ ρ dA = %.6e, ∫ x ρ dA = (%.6e, %.6e)\n"
                                "c = ∫ x ρ dA / M = (%.6f, %.6f)", cell->index, cell->mass, cell->moment.x(),
                                cell->moment.y(), cell->centroid.x(), cell->centroid.y())
                       : format("Iteration %d: energy E = Σ ∫ ρ |x − sᵢ|² dA = %.4e",
                                f.iteration, f.energy);
      break;
    case Stage::Move:
      c.formula = f.solver == "lloyd"
                      ? "Lloyd: every site moves to its centroid, sᵢ ← cᵢ (arrows), and the "
                        "cells are drawn again."
                  : f.solver == "newton"
                      ? "Newton: the sites take a step with the energy's exact second derivatives, "
                        "down its gradient 2 Mᵢ (sᵢ − cᵢ) (arrows: sᵢ → cᵢ)."
                      : "L-BFGS: the sites take a quasi-Newton step down the energy, whose "
                        "gradient is 2 Mᵢ (sᵢ − cᵢ) (arrows: sᵢ → cᵢ).";
      // |c − s|, not "move": only Lloyd's step moves a site by it (the fill "moved since k-1"
      // showed larger moves than this "largest move" under L-BFGS).
      // Its spaces do not break (U+00A0): a wrapped caption ended a line with "|c".
      c.numbers = format("Iteration %d: E = %.4e, largest |c\u00a0−\u00a0s| %.2e, %.1f%% of the sites still "
                         "moving (|c\u00a0−\u00a0s| over the threshold)",
                         f.iteration, f.energy, f.maxToCentroid, f.percentMoving);
      if (f.arrowScale > 1) c.numbers += format("; arrows drawn %g times as long", f.arrowScale);
      if (cell)
        c.numbers += format("; cell %d%s: |c\u00a0−\u00a0s| = %.2e", cell->index,
                            cell->fixed ? " (a fixed border site: it does not move)" : "", cell->toCentroid);
      break;
    case Stage::Lift:
      c.formula = "Each site returns to the surface through the barycentric coordinates of "
                  "the parameter triangle that holds it.";
      c.numbers = cell ? format("Cell %d: s = (%.4f, %.4f) → (%.4f, %.4f, %.4f)", cell->index,
                                cell->site.x(), cell->site.y(), cell->site3D.x(),
                                cell->site3D.y(), cell->site3D.z())
                       : f.converged ? format("%d iterations to convergence.", f.iterations)
                                     : format("%d iterations, not converged.", f.iterations);
      break;
    case Stage::Result:
      c.formula = f.method == "relocate"
                      ? "Relocate: the input's vertices move towards their lifted sites (short of "
                        "them where a triangle would turn over); the connectivity stays."
                  : std::string("Retriangulate: the Delaunay triangulation of the sites, lifted") +
                        (f.cleanedUp ? ", then cleaned up on the surface (edge flips, relaxation)" : "") +
                        // Said only where the numbers below bear it out.
                        (f.result.avgMinAngle >= kNearlyEquilateral ? ": a new mesh of nearly equilateral triangles."
                                                                    : ": a new mesh.");
      c.numbers = format("%d vertices; %sirregular %.0f%% → %.0f%%; smallest angle %.1f° → "
                         "%.1f°; average smallest angle %.1f° → %.1f°",
                         f.result.vertices,
                         f.inputIsMapped ? "from the mesh that was parameterized (a recording holds no input): " : "",
                         f.input.irregularPercent, f.result.irregularPercent,
                         f.input.minAngle, f.result.minAngle, f.input.avgMinAngle,
                         f.result.avgMinAngle);
      break;
    case Stage::Valence:
      c.formula = "Angles sum to 360° around a vertex, less the surface's curvature there: with 60° "
                  "angles a 5 (blue) sits where it bulges, a 7 (red) at a saddle. A 5 beside a 7 "
                  "cancel: the relaxation (any solver) leaves such pairs where rows of cells meet.";
      // "Border-aware": the Result stage's figure counts every border vertex as irregular.
      c.numbers = format("Iteration %d: %d fives, %d sevens, %d other%s: %.1f%% irregular (border-aware); "
                         "curvature asks for %.1f%%",
                         f.iteration, f.fives, f.sevens, f.otherIrregular, f.otherIrregular == 1 ? "" : "s",
                         f.result.irregularBoundaryAware, f.result.curvatureDefects);
      break;
  }
  return c;
}

}  // namespace lloydscope
