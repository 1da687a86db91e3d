// How the command line shows results: tables like the reference's Table II, and JSON.
#pragma once

#include "inspection.h"
#include "lesson.h"
#include "pipeline.h"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <functional>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

namespace lloydscope {

// Numbers in a printf pattern ("%.1f"), up to 160 characters. Floating point only: an int
// passed for a %f would be read as a double's bits.
template <typename... Values>
std::string format(const char* pattern, Values... values) {
  static_assert((std::is_floating_point_v<Values> && ...), "format takes floating-point numbers");
  char text[160];
  std::snprintf(text, sizeof text, pattern, values...);
  return text;
}

// Round values for a linear axis's ticks from `lo` to `hi`: steps of 1, 2 or 5 times a power
// of ten, six ticks at most (evenly spaced from the smallest value to the largest, the
// energy axis read 9.26, 9.23, 9.21, 9.18, 9.16e-5: uneven to the eye).
std::vector<double> roundTicks(double lo, double hi);
// Labels for tick values, all with the same decimals, the fewest that write each as it is.
// Values under 10^-2 or from 10^5 on are written with one exponent for all: 2.020e-4 ..
// 2.035e-4 (as %g wrote them, 0.0002017 .. 0.000203 .. 0.0002035, they differed in length).
std::vector<std::string> tickLabels(const std::vector<double>& values);
// A plot's y axis over a run's values and other runs': its range, its ticks and where a value
// sits on it. A linear axis has round ticks inside the values' range; a log axis has every
// power of ten, and values of 0 or less (the last iteration of a run with no site still
// moving) sit on a row of their own under the lowest decade, labelled 0: left out, the curve
// ended above the threshold it had reached. A threshold (> 0) is inside the range, half a
// decade over its bottom on a log axis (on it, the green line read as the axis). The range
// keeps a margin from the plot's frame: a curve along it (100% moving all along, the last
// energy) read as the frame, in grey (Lloyd's colour) not at all.
struct PlotAxis {
  static constexpr double kMargin = 0.07;  // of the plot's height, under and over the range
  static constexpr int kMostLogTicks = 8;  // decades labelled on a log axis, the row of zeros aside
  bool log = false;
  double lo = 0, hi = 1;  // the range; log10 of it on a log axis
  struct Tick {
    double value;
    std::string label;
  };
  std::vector<Tick> ticks;  // bottom to top
  // 0 at the bottom of the plot, 1 at its top.
  double position(double value) const;
};
PlotAxis plotAxis(const std::vector<double>& values, const std::vector<std::vector<double>>& others,
                  double threshold, bool log);

// How a cell fill's values map to colours (0 the lowest colour, 1 the highest): linear from
// the smallest value to the largest, or over their logarithms where all are positive, the
// largest is over 10 times the smallest, and the logarithm puts the median cell nearer the
// middle of the bar (one cell of the camel head, 3·10⁶ times the smallest mass, left every
// other cell the lowest colour).
struct FillScale {
  double lo = 0, hi = 0;
  bool log = false;
  bool flat() const { return !(hi > lo); }  // every value the same (moved, at iteration 0)
  float at(double value) const;             // 0 where flat
};
FillScale fillScale(const std::vector<double>& values);

// Under the table, where an iteration's result has fewer vertices than there are sites:
// "It. 0: 1 site lies outside the border samples' polygon, in no triangle" (at iteration 0
// without the first pass, an input vertex near the border may; the table's 999 vertices beside
// 1000 sites went unexplained). "" where every site is a vertex.
std::string sitesLeftOutNote(int iteration, size_t sites, size_t vertices);

// How much the lesson's Move stage lengthens its arrows s → c: a typical one (`typical`
// pixels long) to about a site spacing, the longest to two at most, by 1, 2 or 5 times a power
// of ten (1 where they are that long already). After the first iterations a move is a fraction
// of a pixel, under the dots: the stage promised arrows no one could see.
double arrowMagnification(double typicalPixels, double longestPixels, double spacingPixels);

// The step between labelled ticks along `count` iterations: 1, 2 or 5 times a power of ten, the
// smallest that labels at most six of them and no more than `fitting` (how many labels fit side
// by side). Steps of 20 along 230 iterations ran "100120140..." together.
int tickStep(int count, int fitting);
// The same along a span of time (> 0), in steps that may be under 1.
double tickStep(double span, int fitting);

// Where each iteration is on a plot against time: the milliseconds of the steps before it (0 at
// iteration 0), the recorded steps' own times.
std::vector<double> elapsedMs(const std::vector<IterationRecord>& iterations);
// The index of the value of `at` (ascending) nearest `x`, the later one of two as near (along
// iterations 0, 1, 2 ..., x rounded); -1 where `at` is empty.
int nearestIndex(const std::vector<double>& at, double x);

// Which curve of the convergence plots is which run: "lbfgs, this run: 160 iterations", then
// "lloyd, same start: 1000, not converged" and "newton: 54" for the runs compared with it (the
// first of them says they start alike); plotted against time, each with its total time
// (", 185 ms"): how soon it converged. `converged` false: any run, this one too, ends with
// ", not converged".
std::string curveLegend(const char* solver, bool thisRun, bool firstCompared, const std::vector<IterationRecord>& its,
                        bool converged, bool withTime);

// `text` in lines no wider than `width` by `measure`, broken at `gap`s and at its own line
// breaks only: ImGui 1.86 also breaks after '.' and ',', inside numbers ("Hausdorff 1." then
// "906%" on the next line). A word (what lies between gaps) wider than the line has a line of its
// own; one line at least. A gap of two spaces keeps a legend's items ("dots: sites  rings:
// centroids") whole.
std::vector<std::string> wrapAtSpaces(const std::string& text, float width,
                                      const std::function<float(const std::string&)>& measure,
                                      const std::string& gap = " ");

nlohmann::json toJson(const QualityMetrics& m);
nlohmann::json toJson(const Fidelity& f);
nlohmann::json toJson(const RemeshResult& r, const RemeshOptions& options);
nlohmann::json recordingSummary(const Recording& r);

// An error's text as the inspector's window shows it: its command-line advice in the window's
// words ("(--repair fixes this)": "(ticking \"repair\" fixes this)"; --simplify, --param,
// --sites and --method: their fields under Settings).
std::string inWindowWords(std::string text);

// What the window says once `pictures` are saved, the last at `path` (a sequence's together,
// from `firstPath` on: it said "saved" of each picture while none was yet).
std::string pictureSavedText(const std::string& path, int pictures, const std::string& firstPath);
// "Made without the first resampling ..., which failed: <problem>" (RemeshResult::resampleDropped).
std::string withoutResamplingText(const std::string& problem);
// "Kept slit open (remeshed both slit open and whole: ...): ..." (RemeshResult::slitTrial), or
// "" when the disk was not tried both ways.
std::string slitTrialText(const RemeshResult& r);
// "Kept without the first resampling (...): bars met ... with, ... without; Hausdorff ..."
// (RemeshResult::firstPassTrial), or "" if there was no such trial.
std::string firstPassTrialText(const RemeshResult& r);
// "Kept with N corners of the input's coarse border as border samples (...): Hausdorff ...% with,
// ...% without; bars met ..." (RemeshResult::borderTrial), or "" if there was no such trial.
std::string borderTrialText(const RemeshResult& r);
// "Simplified to N vertices first (as --simplify N does), as the input as it is failed: <problem>"
// (RemeshResult::fullInputFailed, `vertices` the sites asked), or "" for no problem.
std::string fullInputFailedText(const std::string& problem, int vertices);
// "Simplified to N vertices first ..." where RemeshOptions::coarsenInput simplified an input of
// `inputVertices` to `coarse` (> 0); "" elsewhere.
std::string coarseInputText(int coarse, int inputVertices);
// "Kept chart by chart (...)" or "Kept as one disk (...)"; empty without a chart trial.
std::string chartTrialText(const RemeshResult& r);

// "Hausdorff 0.335%, RMS 0.030% of diagonal", or that it was not measured (--no-fidelity):
// no sample taken, which zeros would hide.
std::string distanceText(const Fidelity& f);
// The inspector's line for the result it shows: distanceText where that was measured, or where
// --no-fidelity (`asked` false) left it out; while a run goes on, that its distances come at
// the end; else none (a recording opened alone, or a run whose seams did not stitch), whatever
// --no-fidelity says.
std::string shownDistanceText(const Fidelity& f, bool asked, bool running);

// The 2D pane's legend for what it draws: the sites (dots, and the fixed ones as squares), the
// centroids (rings), and a cut surface's seams; and that a click pins a triangle, where the
// choice is not in sight (classroom mode hides it: the lesson's "click a large cell" pinned a
// triangle, with no sign why).
std::string domainLegend(bool sites, bool centroids, bool seams, bool clicksPinTriangles = false);

// What the 3D view shows, in its top-left label.
struct ViewLabel3D {
  bool final = false;          // the final result, after the clean-up
  // Its distance to the input, where measured (a red ring marks where); none: --no-fidelity (it
  // read "farthest from the input, 0.00%", with no ring).
  std::optional<double> hausdorffPercent;
  bool result = false;         // else an iteration's result
  int iteration = 0;
  std::string method;
  bool input = false;          // else the input as the user opened it, or the mesh that was mapped
  int charts = 0;              // > 0: the input stands for its largest chart of so many
  int components = 1;          // > 1: for its largest component of so many
  bool simplified = false;     // charts of the input simplified first (--simplify)
};
std::string viewLabel3D(const ViewLabel3D& shown);

// The controls pane's view switches as they should read: what the views show (during a lesson,
// what its stage set; the Result stage showed the final result beside an unticked "show the
// final result").
struct ViewSwitches {
  bool triangles = false, arrows = false, input = false, final = false;
};
ViewSwitches viewSwitches(const Layers& shown, bool finalShown);
// Where the sites are under 6 pixels apart on screen, a blob of dots and rings (1000 sites in
// presentation mode at 960x600): "sites as close as 3 px: the mouse wheel zooms in"; else "".
std::string crowdedSitesHint(float spacing);
// How far apart the sites are where they are closest (the cells of the smallest twentieth,
// as hexagons), in the domain's units; 0 without cells. Of cells[first..]: the fixed border
// sites' cells, first, are slivers the border clips ("as close as 2 px" on the elephant, whose
// sites were 20 px apart).
double closeSiteSpacing(const std::vector<BoundedCell>& cells, size_t first);

// The selection panel's tables, label and value per row: a pinned cell's numbers (enough for a
// class to check its centroid by hand) and a pinned triangle's. `mapped`: a triangle of an
// iteration's result, with its UV numbers and its corners' sites; else of the final result.
using DetailRows = std::vector<std::pair<std::string, std::string>>;
DetailRows cellRows(const CellDetails& d);
DetailRows triangleRows(const TriangleDetails& d, bool mapped);
// The pins of one kind ("cell", "triangle") that `where` ("this iteration") cannot show, for it
// has `count` of them: "Cells 100, 120 pinned: this iteration has 20 cells, numbered from 0.";
// empty where every pin shows. After Restart with fewer sites the earlier pins were hidden, and
// the panel showed nothing at all, not even how to pin.
std::string pinsNotShown(const std::vector<int>& pinned, size_t count, const std::string& kind,
                         const std::string& where);
// Where a lesson stage draws no cells, or no result, and such pins are listed beside it: that
// the stage leaves them out ("The load stage draws no cells and no result: the pins show at the
// stages that do."); else "". `cellsOut` / `trianglesOut`: pins of that kind the stage leaves out.
std::string pinsLeftOutByStage(const std::string& stage, bool cellsOut, bool trianglesOut);

// Where the result strays farther than kFarFromTheInputPercent of the diagonal from the input
// (the results here are 0.1-3%): a warning that says so, and what may help; else empty.
constexpr double kFarFromTheInputPercent = 10;
std::string farFromTheInputText(const Fidelity& f);
// A warning where the result folds back on itself (QualityMetrics::folds) where the input does
// not (foldsAnew), else "".
std::string foldsText(const QualityMetrics& before, const QualityMetrics& after);
// Where the result's smallest angle is under 30 degrees at a sharp corner of the border that the
// input has too: that the bar is out of reach there, where, and the smallest angle elsewhere;
// else "".
std::string sharpCornerText(const QualityMetrics& before, const QualityMetrics& after);
// Why the inspector's relocate is greyed (the run's sites are not the input's vertices), and
// what gives a run that can: a new run where the input is open (`canRun`); a recording alone
// has no Settings and cannot run (it was told to choose them and press Restart, both missing).
std::string relocateNeedsText(bool canRun);
// Where the result's smallest angle is under 30 degrees beside a hole shorter than its mean
// edge (QualityMetrics::minAngleHoleEdges): that the hole, kept, leaves needles; else "".
std::string pinholeText(const QualityMetrics& after);
// Where the smallest angle is under 30 at an inside vertex whose angles sum to under 90 (a
// spike's apex: 69 degrees, its three angles 21.6 and the bar missed without a word): why.
std::string tipText(const QualityMetrics& after);
// Where the result is over kMostIrregularPercent irregular and the surface curves for its
// vertices by as much (QualityMetrics::curvatureDefects): that equilateral triangles would be
// as irregular there, and what may help; else "".
std::string curvatureText(const QualityMetrics& after);

// The inspector's notes on how a result was made: `note` put before `notes`, each a sentence on
// a line of its own (run together as one paragraph, four trials' notes read as one, and "bars
// met ... 2 and 2. The smallest angle" as a count). An empty note adds nothing.
std::string withNoteFirst(const std::string& note, const std::string& notes);

// Where a retriangulated result has more or fewer vertices than were asked: both counts, and
// why; else empty.
std::string vertexCountText(const RemeshResult& r, const RemeshOptions& options);

// "Thresholds: 1e-06, 5%": the run's convergence thresholds as given, not rounded.
std::string thresholdsText(const LloydOptions& options);
// A count of iterations with their numbers, as the timeline has them: "110 iterations (0-109)",
// "1 iteration (0)" ("Stopped at 4 iterations" read as one more than the timeline's "0-3").
std::string iterationsText(int count);

// "L-BFGS iterations: 160 (converged)", named by the solver's steps (a Newton run said "Lloyd
// iterations"): a surface remeshed in parts (components, charts) sums its parts' iterations,
// and says so: 251 for 8 charts at --max-iterations 40 read as over it.
std::string iterationsLine(const RemeshResult& r, CvtSolver solver);

// Input and output side by side.
std::string qualityTable(const QualityMetrics& before, const QualityMetrics& after,
                         const Fidelity* fidelity);
std::string remeshReport(const RemeshResult& r, const RemeshOptions& options);
std::string metricsReport(const QualityMetrics& m, const Fidelity* fidelity);
std::string recordingReport(const Recording& r);

}  // namespace lloydscope
