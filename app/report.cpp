#include "report.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace lloydscope {

std::vector<double> roundTicks(double lo, double hi) {
  if (!(hi > lo)) return {lo};
  // The smallest step of 1, 2 or 5 times a power of ten that leaves at most six ticks.
  const double power = std::pow(10, std::floor(std::log10((hi - lo) / 6)));
  double step = 10 * power;
  for (double nice : {1.0, 2.0, 5.0})
    if (std::floor(hi / (nice * power) + 1e-9) - std::ceil(lo / (nice * power) - 1e-9) + 1 <= 6) {
      step = nice * power;
      break;
    }
  // Counted in steps, a hair's breadth of rounding allowed at either end (9.16e-5 / 2e-7 is
  // 458.00000000000006).
  std::vector<double> ticks;
  for (double k = std::ceil(lo / step - 1e-9); k <= std::floor(hi / step + 1e-9); ++k)
    ticks.push_back(k == 0 ? 0.0 : k * step);  // no -0
  return ticks;
}

std::vector<std::string> tickLabels(const std::vector<double>& values) {
  constexpr int kMostDecimals = 12;
  double largest = 0;
  for (double v : values) largest = std::max(largest, std::abs(v));
  const int leading = largest > 0 && std::isfinite(largest) ? static_cast<int>(std::floor(std::log10(largest))) : 0;
  // Scientific where fixed decimals would start with zeros or run long: one exponent for all.
  const bool scientific = leading < -2 || leading >= 5;
  const double unit = scientific ? std::pow(10.0, leading) : 1.0;
  const std::string suffix = scientific ? "e" + std::to_string(leading) : "";
  // The fewest decimals that write every value as it is (round values need few), all alike.
  int decimals = 0;
  for (; decimals < kMostDecimals; ++decimals) {
    const double quantum = std::pow(10.0, -decimals);
    bool exact = true;
    for (double v : values)
      exact = exact && std::abs(v / unit - std::round(v / unit / quantum) * quantum) <= 1e-6 * quantum;
    if (exact) break;
  }
  const std::string pattern = "%." + std::to_string(decimals) + "f";
  std::vector<std::string> labels;
  for (double v : values) labels.push_back(format(pattern.c_str(), v / unit) + suffix);
  return labels;
}

std::vector<std::string> wrapAtSpaces(const std::string& text, float width,
                                      const std::function<float(const std::string&)>& measure,
                                      const std::string& gap) {
  std::vector<std::string> lines;
  std::istringstream paragraphs(text);
  for (std::string paragraph; std::getline(paragraphs, paragraph);) {
    // A paragraph's indent stays on its first line (the table's " border-aware" row).
    const size_t indent = paragraph.find_first_not_of(' ');
    std::string line = indent == std::string::npos ? "" : paragraph.substr(0, indent);
    bool hasWords = false;
    for (size_t start = line.size(); start < paragraph.size();) {
      const size_t end = std::min(paragraph.find(gap, start), paragraph.size());
      const std::string word = paragraph.substr(start, end - start);
      start = end + gap.size();
      if (word.find_first_not_of(' ') == std::string::npos) continue;  // gaps in a row are one
      const std::string longer = hasWords ? line + gap + word : line + word;
      if (hasWords && measure(longer) > width) {
        lines.push_back(line);
        line = word;
      } else {
        line = longer;
      }
      hasWords = true;
    }
    lines.push_back(line);
  }
  if (lines.empty()) lines.emplace_back();  // "": one empty line
  return lines;
}

double PlotAxis::position(double value) const {
  const double onTicks = log && value <= 0 ? 0.0  // the row of zeros
                                           : ((log ? std::log10(value) : value) - lo) / (hi - lo);
  return kMargin + (1 - 2 * kMargin) * onTicks;
}

PlotAxis plotAxis(const std::vector<double>& values, const std::vector<std::vector<double>>& others,
                  double threshold, bool log) {
  PlotAxis axis;
  axis.log = log;
  double lo = INFINITY, hi = -INFINITY;
  bool zeros = false;
  const auto extend = [&](const std::vector<double>& series) {
    for (double v : series) {
      if (log && v <= 0) {
        zeros = true;
        continue;
      }
      lo = std::min(lo, log ? std::log10(v) : v);
      hi = std::max(hi, log ? std::log10(v) : v);
    }
  };
  extend(values);
  for (const std::vector<double>& series : others) extend(series);
  if (threshold > 0) {
    lo = std::min(lo, log ? std::log10(threshold) - 0.5 : threshold);
    hi = std::max(hi, log ? std::log10(threshold) : threshold);
  }
  if (!std::isfinite(lo) || !std::isfinite(hi)) lo = 0, hi = 1;  // nothing to plot (yet)
  if (!(hi > lo)) {  // one value (a first iteration): a range around it, not from it to it + 1
    const double spread = lo != 0 ? 0.01 * std::abs(lo) : 1.0;
    lo -= spread;
    hi += spread;
  }
  if (!log) {
    axis.lo = lo;
    axis.hi = hi;
    const std::vector<double> values = roundTicks(lo, hi);
    const std::vector<std::string> labels = tickLabels(values);
    for (size_t k = 0; k < values.size(); ++k) axis.ticks.push_back({values[k], labels[k]});
    return axis;
  }
  axis.lo = std::floor(lo) - (zeros ? 1 : 0);
  axis.hi = std::ceil(hi);
  // A tick a decade, or every few decades down from the top where there are more than fit: a
  // distance threshold of 1e-310 (which the command line takes) drew 300 labels over each other.
  const int top = static_cast<int>(axis.hi), bottom = static_cast<int>(axis.lo) + (zeros ? 1 : 0);
  const int step = std::max(1, (top - bottom + PlotAxis::kMostLogTicks - 2) / (PlotAxis::kMostLogTicks - 1));
  for (int decade = top; decade >= bottom; decade -= step)
    axis.ticks.insert(axis.ticks.begin(), {std::pow(10.0, decade), "1e" + std::to_string(decade)});
  if (zeros) axis.ticks.insert(axis.ticks.begin(), {0.0, "0"});
  return axis;
}

float FillScale::at(double value) const {
  if (flat()) return 0.0f;
  const double t = log ? std::log(std::max(value, lo) / lo) / std::log(hi / lo) : (value - lo) / (hi - lo);
  return static_cast<float>(std::clamp(t, 0.0, 1.0));
}

FillScale fillScale(const std::vector<double>& values) {
  FillScale scale;
  if (values.empty()) return scale;
  const auto [lo, hi] = std::minmax_element(values.begin(), values.end());
  scale.lo = *lo;
  scale.hi = *hi;
  if (!(scale.lo > 0 && scale.hi > 10 * scale.lo)) return scale;
  // Of the two scales, the one that puts the median cell nearer the middle of the bar: a fixed
  // factor (100) left a 99.9-fold spread linear, every cell but a few the lowest colour.
  std::vector<double> sorted = values;
  std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
  const double median = sorted[sorted.size() / 2];
  const float linear = scale.at(median);
  scale.log = true;
  const float logarithmic = scale.at(median);
  scale.log = std::abs(logarithmic - 0.5f) < std::abs(linear - 0.5f);
  return scale;
}

std::string sitesLeftOutNote(int iteration, size_t sites, size_t vertices) {
  if (vertices >= sites) return "";
  const size_t left = sites - vertices;
  return "It. " + std::to_string(iteration) + ": " + std::to_string(left) +
         (left == 1 ? " site lies" : " sites lie") + " outside the border samples' polygon, in no triangle";
}

namespace {

// The number of the series 1, 2, 5, 10, 20, 50 ... nearest `x` (> 0) from above, or from below.
double oneTwoFiveAtLeast(double x) {
  const double power = std::pow(10, std::floor(std::log10(x)));
  for (double nice : {1.0, 2.0, 5.0})
    if (x <= nice * power) return nice * power;
  return 10 * power;
}
double oneTwoFiveAtMost(double x) {
  const double power = std::pow(10, std::floor(std::log10(x)));
  for (double nice : {5.0, 2.0})
    if (nice * power <= x) return nice * power;
  return power;
}

}  // namespace

double arrowMagnification(double typicalPixels, double longestPixels, double spacingPixels) {
  const double wanted = std::min(spacingPixels / std::max(typicalPixels, 1e-12),
                                 2 * spacingPixels / std::max(longestPixels, 1e-12));
  if (!(wanted > 1)) return 1;
  return std::min(oneTwoFiveAtMost(wanted), 1e6);
}

int tickStep(int count, int fitting) {
  return static_cast<int>(std::max(1.0, tickStep(static_cast<double>(count), fitting)));
}

double tickStep(double span, int fitting) { return oneTwoFiveAtLeast(span / std::clamp(fitting, 1, 6)); }

std::vector<double> elapsedMs(const std::vector<IterationRecord>& iterations) {
  std::vector<double> at;
  double sum = 0;
  for (const IterationRecord& it : iterations) {
    at.push_back(sum);
    sum += it.milliseconds;
  }
  return at;
}

std::string curveLegend(const char* solver, bool thisRun, bool firstCompared, const std::vector<IterationRecord>& its,
                        bool converged, bool withTime) {
  const size_t n = its.size();
  std::string text = std::string(solver) +
                     (thisRun ? ", this run: " + std::to_string(n) + (n == 1 ? " iteration" : " iterations")
                              : (firstCompared ? ", same start: " : ": ") + std::to_string(n));
  if (withTime) {
    double ms = 0;
    for (const IterationRecord& it : its) ms += it.milliseconds;
    // Two digits under 10 ms: a run of a tenth of a millisecond read "0 ms" beside its curve.
    text += format(ms < 10 ? ", %.2g" : ", %.0f", ms) + " ms";
  }
  return converged ? text : text + ", not converged";
}

int nearestIndex(const std::vector<double>& at, double x) {
  if (at.empty()) return -1;
  const auto after = std::lower_bound(at.begin(), at.end(), x);
  if (after == at.begin()) return 0;
  if (after == at.end()) return static_cast<int>(at.size()) - 1;
  const auto before = after - 1;
  return static_cast<int>((x - *before < *after - x ? before : after) - at.begin());
}

namespace {

struct Row {
  const char* label;
  const char* pattern;
  double QualityMetrics::*field;
};
const Row kRows[] = {
    {"Irregularity (%)", "%.1f", &QualityMetrics::irregularPercent},
    {"Irregularity, boundary-aware (%)", "%.1f", &QualityMetrics::irregularBoundaryAware},
    {"Min angle (deg)", "%.1f", &QualityMetrics::minAngle},
    {"Avg. min angle (deg)", "%.1f", &QualityMetrics::avgMinAngle},
    {"Triangles under 30 deg (%)", "%.1f", &QualityMetrics::percentUnder30},
    {"Max angle (deg)", "%.1f", &QualityMetrics::maxAngle},
    {"Curvature (60-deg defects, %)", "%.1f", &QualityMetrics::curvatureDefects},
};

void line(std::ostringstream& out, const std::string& label, const std::string& a,
          const std::string& b) {
  char buffer[160];
  std::snprintf(buffer, sizeof buffer, "| %-34s | %10s | %10s |\n", label.c_str(), a.c_str(),
                b.c_str());
  out << buffer;
}

}  // namespace

nlohmann::json toJson(const QualityMetrics& m) {
  return {{"vertices", m.vertices},
          {"faces", m.faces},
          {"boundary_vertices", m.boundaryVertices},
          {"irregular_percent", m.irregularPercent},
          {"irregular_boundary_aware_percent", m.irregularBoundaryAware},
          {"min_angle_deg", m.minAngle},
          {"avg_min_angle_deg", m.avgMinAngle},
          {"percent_under_30_deg", m.percentUnder30},
          {"max_angle_deg", m.maxAngle},
          {"curvature_defects_percent", m.curvatureDefects},
          {"curvature_defects_on_border_percent", m.curvatureDefectsOnBorder},
          {"angle_histogram_10deg", m.angleHistogram},
          {"folded_edges", m.foldedEdges()},
          {"min_angle_off_sharp_corners_deg", m.minAngleOffSharpCorners},
          {"sharpest_border_corner_deg",
           m.boundaryVertices > 0 ? nlohmann::json(m.sharpestBorderCorner) : nlohmann::json(nullptr)}};
}

nlohmann::json toJson(const Fidelity& f) {
  return {{"hausdorff_percent_diagonal", f.hausdorffPercent},
          {"rms_percent_diagonal", f.rmsPercent},
          {"samples", f.samples},
          {"farthest_point", {f.farthestPoint.x(), f.farthestPoint.y(), f.farthestPoint.z()}},
          {"farthest_on", f.farthestOnReference ? "input" : "output"}};
}

namespace {

// A settings line (core's describe(), as the text report and a recording write it) as an
// object: one key a word ('-' read as '_'), numbers as numbers, yes/no as booleans. Every
// setting the line names is there, and only those (alpha, beta and floor with the curvature
// density, polish and fit with retriangulate ...).
nlohmann::json settingsJson(const std::string& line) {
  nlohmann::json settings = nlohmann::json::object();
  for (auto [key, value] : settingPairs(line)) {
    std::replace(key.begin(), key.end(), '-', '_');
    const char* const end = value.data() + value.size();
    long long integer = 0;
    double real = 0;
    if (value == "yes" || value == "no")
      settings[key] = value == "yes";
    else if (const auto read = std::from_chars(value.data(), end, integer); read.ec == std::errc() && read.ptr == end)
      settings[key] = integer;
    else if (const auto read = std::from_chars(value.data(), end, real); read.ec == std::errc() && read.ptr == end)
      settings[key] = real;
    else
      settings[key] = value;
  }
  return settings;
}

// A trial's distance, null where it was not measured (the trials measure only where the
// distances decide).
nlohmann::json measuredOrNull(bool measured, double hausdorffPercent) {
  return measured ? nlohmann::json(hausdorffPercent) : nlohmann::json();
}

}  // namespace

nlohmann::json toJson(const RemeshResult& r, const RemeshOptions& o) {
  nlohmann::json output = toJson(r.after);
  // null where it was not measured (--no-fidelity): zeros would read as a perfect fit
  output["fidelity"] = r.fidelity.samples > 0 ? toJson(r.fidelity) : nlohmann::json();
  nlohmann::json settings = settingsJson(describe(o));
  settings["param_used"] = toString(r.paramUsed);
  if (!isFreeBorder(r.paramUsed)) settings["border_used"] = toString(r.borderUsed);
  // Where either way failed, nothing was compared.
  const bool chartsMeasured = r.chartTrial && r.chartTrial->failed.empty() && r.chartTrial->oneCutFailed.empty() &&
                              r.chartTrial->distancesDecide();
  return {{"settings", settings},
          {"input", toJson(r.before)},
          {"output", output},
          {"components", r.components},
          {"components_kept", r.componentsKept},
          {"slit_trial", r.slitTrial ? nlohmann::json{{"slit_avg_min_angle_deg", r.slitTrial->slit},
                                                      {"whole_avg_min_angle_deg", r.slitTrial->whole},
                                                      {"slit_bars_met", r.slitTrial->slitBars},
                                                      {"whole_bars_met", r.slitTrial->wholeBars},
                                                      {"slit_hausdorff_percent", measuredOrNull(r.slitTrial->bothMeetTheBars(), r.slitTrial->slitHausdorff)},
                                                      {"whole_hausdorff_percent", measuredOrNull(r.slitTrial->bothMeetTheBars(), r.slitTrial->wholeHausdorff)},
                                                      {"kept", r.cut.seamEdges > 0 ? "slit" : "whole"}}
                                     : nlohmann::json()},
          {"charts", r.charts},
          {"chart_trial", r.chartTrial ? nlohmann::json{{"charts", r.chartTrial->charts},
                                                        {"one_cut_avg_min_angle_deg", r.chartTrial->oneCutAvgMinAngle},
                                                        {"charts_avg_min_angle_deg", r.chartTrial->chartsAvgMinAngle},
                                                        {"one_cut_hausdorff_percent", measuredOrNull(chartsMeasured, r.chartTrial->oneCutHausdorff)},
                                                        {"charts_hausdorff_percent", measuredOrNull(chartsMeasured, r.chartTrial->chartsHausdorff)},
                                                        {"one_cut_bars_met", r.chartTrial->oneCutBars},
                                                        {"charts_bars_met", r.chartTrial->chartsBars},
                                                        {"one_cut_folds", r.chartTrial->oneCutFolds},
                                                        {"charts_fold", r.chartTrial->chartsFold},
                                                        {"kept", r.charts > 0 ? "charts" : "one-cut"},
                                                        {"failed", r.chartTrial->failed},
                                                        {"one_cut_failed", r.chartTrial->oneCutFailed},
                                                        {"for_bars", r.chartTrial->forBars}}
                                       : nlohmann::json()},
          {"first_pass_trial", r.firstPassTrial ? nlohmann::json{{"with_bars_met", r.firstPassTrial->withBars},
                                                                 {"without_bars_met", r.firstPassTrial->withoutBars},
                                                                 {"with_hausdorff_percent", measuredOrNull(r.firstPassTrial->distancesDecide(), r.firstPassTrial->withHausdorff)},
                                                                 {"without_hausdorff_percent", measuredOrNull(r.firstPassTrial->distancesDecide(), r.firstPassTrial->withoutHausdorff)},
                                                                 {"kept", r.firstPassTrial->keptWithout ? "without" : "with"},
                                                                 {"failed", r.firstPassTrial->failed}}
                                               : nlohmann::json()},
          {"border_trial", r.borderTrial ? nlohmann::json{{"corners", r.borderTrial->corners.size()},
                                                          {"without_bars_met", r.borderTrial->withoutBars},
                                                          {"with_bars_met", r.borderTrial->withBars},
                                                          {"without_hausdorff_percent", measuredOrNull(r.borderTrial->failed.empty(), r.borderTrial->withoutHausdorff)},
                                                          {"with_hausdorff_percent", measuredOrNull(r.borderTrial->failed.empty(), r.borderTrial->withHausdorff)},
                                                          {"kept", r.borderTrial->keptWith ? "with" : "without"},
                                                          {"corners_moved", r.borderTrial->cornersMoved},
                                                          {"failed", r.borderTrial->failed}}
                                         : nlohmann::json()},
          {"coarse_input_vertices", r.coarseInput},
          {"runs", r.runs},
          {"iterations", r.iterations},
          {"converged", r.converged},
          {"snapped_tips", r.snappedTips},
          {"held_back", r.heldBack},
          {"fit", {{"vertices_moved", r.fit.moved},
                   {"border_vertices_moved", r.fit.borderMoved},
                   {"mean_percent_diagonal", r.fit.meanPercent},
                   {"max_percent_diagonal", r.fit.maxPercent}}},
          {"resample_dropped", r.resampleDropped.empty() ? nlohmann::json() : nlohmann::json(r.resampleDropped)},
          {"full_input_failed", r.fullInputFailed.empty() ? nlohmann::json() : nlohmann::json(r.fullInputFailed)},
          {"distortion",
           {{"min_area_ratio", r.distortion.minAreaRatio},
            {"max_area_ratio", r.distortion.maxAreaRatio},
            {"mean_log_area_ratio", r.distortion.meanLogAreaRatio},
            {"mean_angle_error_deg", r.distortion.meanAngleErrorDeg}}},
          {"cut",
           {{"seam_edges", r.cut.seamEdges},
            {"extremity_cuts", r.cut.extremityCuts},
            {"area_spread", r.cut.areaSpread > 0 ? nlohmann::json(r.cut.areaSpread) : nlohmann::json()}}},
          {"milliseconds",
           {{"simplify", r.ms.simplify},
            {"cut", r.ms.cut},
            {"resample", r.ms.resample},
            {"parameterize", r.ms.parameterize},
            {"density", r.ms.density},
            {"sites", r.ms.sites},
            {"lloyd", r.ms.lloyd},
            {"remesh", r.ms.remesh},
            {"compared", r.ms.compared},
            {"metrics", r.ms.metrics},
            {"total", r.ms.total}}}};
}

std::string pictureSavedText(const std::string& path, int pictures, const std::string& firstPath) {
  if (pictures <= 1) return "saved " + path;
  return "saved " + std::to_string(pictures) + " pictures, " + firstPath + " to " + path;
}

std::string inWindowWords(std::string text) {
  const std::pair<std::string, std::string> words[] = {
      {"(--repair fixes this)", "(ticking \"repair\" fixes this)"},
      {"(use --method retriangulate)", "(choose method: retriangulate under Settings)"},
      {"--simplify to fewer vertices", "a smaller \"simplify to\" under Settings"},
      {"--param tutte or mean-value", "the tutte or mean-value parameterization under Settings"},
      {"--param tutte or ", "the tutte parameterization under Settings or "},
      {"ask for more (--sites)", "ask for more (sites, under Settings)"}};
  for (const auto& [flag, here] : words)
    if (const size_t at = text.find(flag); at != std::string::npos) text.replace(at, flag.size(), here);
  return text;
}

std::string withoutResamplingText(const std::string& problem) {
  return "Made without the first resampling (as with --no-resample), which failed: " + problem;
}

namespace {
// A trial's note where the run with the border's corners kept replaced the result it was made
// for (its figures are that result's): said so first. (CGAL-like saddle at 230: "a bar was missed
// with it ... 0.193%" of a result replaced by one meeting all three, 0.106% from the input.)
std::string ofTheResultReplaced(const RemeshResult& r, std::string text) {
  if (!r.borderTrial || !r.borderTrial->keptWith || text.empty()) return text;
  text[0] = static_cast<char>(std::tolower(static_cast<unsigned char>(text[0])));
  return "Before the border's corners were kept: " + text;
}
}  // namespace

std::string slitTrialText(const RemeshResult& r) {
  if (!r.slitTrial) return "";
  const SlitTrial& t = *r.slitTrial;
  // Why, as SlitTrial::wholeBetter() decides: a kept result with the smaller average angle
  // read as the worse one kept.
  const std::string why =
      t.slitBars != t.wholeBars
          ? "; bars met (irregular, smallest angle, average) " + std::to_string(t.slitBars) + " slit, " +
                std::to_string(t.wholeBars) + " whole: the one meeting more kept"
      : t.bothMeetTheBars() ? "; both meet the three bars, the closer kept: Hausdorff " +
                                  format("%.3f", t.slitHausdorff) + "% slit, " + format("%.3f", t.wholeHausdorff) +
                                  "% whole"
                            : "; as many bars met (" + std::to_string(t.slitBars) + "), the rounder kept";
  return ofTheResultReplaced(
      r, std::string(r.cut.seamEdges > 0 ? "Kept slit open" : "Kept whole") +
             " (remeshed both slit open and whole: its map to a disk shrinks part of it over " +
             std::to_string(static_cast<long>(CutOptions{}.slitDisksAbove)) + " times): average smallest angle " +
             format("%.1f", t.slit) + " deg slit, " + format("%.1f", t.whole) + " deg whole" + why);
}

std::string chartTrialText(const RemeshResult& r) {
  if (!r.chartTrial) return "";
  const ChartTrial& t = *r.chartTrial;
  if (!t.failed.empty())
    return ofTheResultReplaced(r, "Kept as one disk (remeshed chart by chart too, which failed: " + t.failed + ")");
  if (!t.oneCutFailed.empty())
    return "Remeshed chart by chart, in " + std::to_string(t.charts) + " charts (as one disk it failed: " +
           t.oneCutFailed + ")";
  return ofTheResultReplaced(
      r, std::string(r.charts > 0 ? "Kept chart by chart" : "Kept as one disk") +
             (t.forBars ? " (a bar was missed as one disk: remeshed chart by chart too): average smallest angle "
                        : " (remeshed both ways, as one disk and chart by chart): average smallest angle ") +
             format("%.1f", t.chartsAvgMinAngle) + " deg in " + std::to_string(t.charts) + " charts, " +
             format("%.1f", t.oneCutAvgMinAngle) + " deg one disk" +
             (t.distancesDecide() ? "; Hausdorff " + format("%.3f", t.chartsHausdorff) + "% and " +
                                        format("%.3f", t.oneCutHausdorff) + "%"
                                  : "") +
             "; bars met (irregular, smallest angle, average) " + std::to_string(t.chartsBars) + " and " +
             std::to_string(t.oneCutBars) +
             (t.distancesDecide() || t.oneCutFolds != t.chartsFold ? "" : ": not more in charts") +
             (t.oneCutFolds == t.chartsFold ? ""
              : t.oneCutFolds              ? "; one disk folds back on itself, the charts do not"
                                           : "; the charts fold back on themselves, one disk does not"));
}

std::string firstPassTrialText(const RemeshResult& r) {
  if (!r.firstPassTrial) return "";
  const FirstPassTrial& t = *r.firstPassTrial;
  if (!t.failed.empty())
    return ofTheResultReplaced(
        r, "Kept with the first resampling (a bar was missed with it: remeshed without it too, which failed: " +
               t.failed + ")");
  return ofTheResultReplaced(
      r, std::string(t.keptWithout ? "Kept without the first resampling" : "Kept with the first resampling") +
             " (a bar was missed with it: remeshed without it too): bars met (irregular, smallest angle, average) " +
             std::to_string(t.withBars) + " with, " + std::to_string(t.withoutBars) + " without" +
             (t.distancesDecide() ? "; Hausdorff " + format("%.3f", t.withHausdorff) + "% and " +
                                        format("%.3f", t.withoutHausdorff) + "%"
                                  : ": not more without"));
}

std::string borderTrialText(const RemeshResult& r) {
  if (!r.borderTrial) return "";
  const BorderTrial& t = *r.borderTrial;
  const std::string corners = std::to_string(t.corners.size()) + " corners of the input's coarse border";
  if (!t.failed.empty())
    return "Kept as sampled (its border cut corners of the input's: remeshed with " + corners +
           " kept too, which failed: " + t.failed + ")";
  const std::string moved = t.cornersMoved > 0 ? ", " + std::to_string(t.cornersMoved) +
                                                     " of them no longer vertices of its border (slid along it or merged since, for the angles)"
                                               : "";
  return std::string(t.keptWith ? "Kept with " + corners + " as border samples" + moved : "Kept as sampled") +
         " (its border cut corners of the input's: remeshed with them kept too): Hausdorff " +
         format("%.3f", t.withHausdorff) + "% with, " + format("%.3f", t.withoutHausdorff) +
         "% without; bars met (irregular, smallest angle, average) " + std::to_string(t.withBars) + " and " +
         std::to_string(t.withoutBars);
}

std::string fullInputFailedText(const std::string& problem, int vertices) {
  if (problem.empty()) return "";
  const std::string asked = std::to_string(vertices);
  return "Simplified to " + asked + " vertices first (as --simplify " + asked + " does), as the input as it is failed: " +
         problem + "; the snaps, the fit and the distances are against the input itself";
}

std::string coarseInputText(int coarse, int inputVertices) {
  if (coarse <= 0) return "";
  return "Simplified to " + std::to_string(coarse) + " vertices first (the input has " +
         std::to_string(inputVertices) + ": more than " + std::to_string(coarse) +
         " for the vertices asked; --full-input to keep it); the snaps, the fit and the distances are "
         "against the input itself";
}

std::string domainLegend(bool sites, bool centroids, bool seams, bool clicksPinTriangles) {
  std::string legend;
  auto add = [&](const char* part) { legend += (legend.empty() ? "" : "  ") + std::string(part); };
  if (sites) add("dots: sites");
  if (centroids) add("rings: centroids");
  if (sites) add(seams ? "squares: fixed" : "squares: fixed border sites");
  if (seams) add("purple: seams");
  if (clicksPinTriangles) add("a click pins a triangle");
  return legend;
}

std::string viewLabel3D(const ViewLabel3D& shown) {
  if (shown.final)
    return shown.hausdorffPercent
               ? format("final result (red ring: farthest from the input, %.2f%%)", *shown.hausdorffPercent)
               : "final result (its distance to the input not measured)";
  if (shown.result) return "result at iteration " + std::to_string(shown.iteration) + " (" + shown.method + ")";
  if (!shown.input) return "the mesh that was parameterized";
  // A surface made in charts: the panes follow its largest, of the input simplified where it was
  // (labelled "input mesh", its colours sat beside a caption quoting the whole input's angles).
  const std::string whose = shown.simplified ? "the simplified input's" : "the input's";
  if (shown.charts > 0) return whose + " largest chart (of\u00a0" + std::to_string(shown.charts) + ")";
  if (shown.components > 1) return whose + " largest component (of\u00a0" + std::to_string(shown.components) + ")";
  return "input mesh";
}

ViewSwitches viewSwitches(const Layers& shown, bool finalShown) {
  ViewSwitches s;
  s.triangles = shown.triangles2D;
  s.arrows = shown.arrows2D;
  s.input = shown.input3D && !shown.mapped3D && !finalShown;  // not the mesh that was mapped
  s.final = finalShown;
  return s;
}

std::string crowdedSitesHint(float spacing) {
  if (!(spacing > 0 && spacing < 6.0f)) return "";
  // Under a pixel with its tenths: the camel head's middle read "as close as 0 px", and
  // under a tenth the femur's "0.0 px".
  if (spacing < 0.1f) return "sites under 0.1 px apart: the mouse wheel zooms in";
  return format(spacing < 1 ? "sites as close as %.1f px: the mouse wheel zooms in"
                            : "sites as close as %.0f px: the mouse wheel zooms in",
                spacing);
}

double closeSiteSpacing(const std::vector<BoundedCell>& cells, size_t first) {
  std::vector<double> areas;
  for (size_t i = first; i < cells.size(); ++i)
    if (cells[i].area > 0) areas.push_back(cells[i].area);
  if (areas.empty()) return 0;
  const auto twentieth = areas.begin() + areas.size() / 20;
  std::nth_element(areas.begin(), twentieth, areas.end());
  return std::sqrt(2 * *twentieth / std::sqrt(3.0));  // a regular hexagon's: area √3/2 d²
}

std::string distanceText(const Fidelity& f) {
  if (f.samples == 0) return "Distance to the input not measured (--no-fidelity)";
  return "Hausdorff " + format("%.3f", f.hausdorffPercent) + "%, RMS " + format("%.3f", f.rmsPercent) +
         "% of diagonal";
}

std::string shownDistanceText(const Fidelity& f, bool asked, bool running) {
  if (running) return "Distances to the input: measured when the run has finished";
  if (f.samples > 0 || !asked) return distanceText(f);
  return "Distances to the input: none for what is shown (a recording keeps its iterations only)";
}

namespace {
std::string pointText(const Vec3& p) {
  return "(" + format("%.4g", p.x()) + ", " + format("%.4g", p.y()) + ", " + format("%.4g", p.z()) + ")";
}
}  // namespace

std::string farthestPointText(const Fidelity& f) {
  return pointText(f.farthestPoint) +
         (f.farthestOnReference ? " on the input (the result passes farthest from it there)"
                                : " on the result (it strays farthest from the input there)");
}

DetailRows cellRows(const CellDetails& d) {
  // Six decimals, and seven digits for the sums, the mass and the moment: a class checks c
  // by hand from them, and from five digits the quotient differed from c in its last one.
  DetailRows rows = {
      {"site s", format("%.6f %.6f", d.site.x(), d.site.y())},
      {"centroid c", format("%.6f %.6f", d.centroid.x(), d.centroid.y())},
      {"s, 3D", format("%.3f %.3f %.3f", d.site3D.x(), d.site3D.y(), d.site3D.z())},
      {"c, 3D", format("%.3f %.3f %.3f", d.centroid3D.x(), d.centroid3D.y(), d.centroid3D.z())},
      {"area, UV", format("%.4e", d.area)},
      {"area, surface", format("%.4e", d.surfaceArea)},
      {"A = 1/2 sum c_i", format("%.6e", d.shoelaceArea)},
      {"sum (x_i+x_i+1)c_i", format("%.6e", d.shoelaceSums.x())},
      {"sum (y_i+y_i+1)c_i", format("%.6e", d.shoelaceSums.y())}};
  if (d.shoelaceArea > 0)  // the unweighted centroid: c itself with a uniform density
    rows.emplace_back("sums / 6A", format("%.6f %.6f", d.shoelaceSums.x() / (6 * d.shoelaceArea),
                                           d.shoelaceSums.y() / (6 * d.shoelaceArea)));
  rows.emplace_back("M = int rho", format("%.6e", d.mass));
  rows.emplace_back("int x rho, u", format("%.6e", d.moment.x()));  // a row each: two in one
  rows.emplace_back("int x rho, v", format("%.6e", d.moment.y()));  // were cut off at 960 px
  rows.emplace_back("c = int x rho/M", d.mass > 0 ? format("%.6f %.6f", d.moment.x() / d.mass,
                                                            d.moment.y() / d.mass)
                                                  : std::string("- (no mass)"));
  rows.emplace_back("E=int rho|x-s|^2", format("%.3e", d.energy));
  rows.emplace_back("|c - s|", format("%.3e", d.toCentroid));
  rows.emplace_back("moved since k-1", format("%.3e", d.moved));
  rows.emplace_back("neighbours", std::to_string(d.neighbours));
  rows.emplace_back("valence, result", d.valence >= 0 ? std::to_string(d.valence) : "- (no vertex)");
  rows.emplace_back("param. triangles", std::to_string(d.pieces));
  return rows;
}

DetailRows triangleRows(const TriangleDetails& d, bool mapped) {
  DetailRows rows;
  rows.emplace_back("angles, 3D", format("%.1f %.1f %.1f", d.angles3D[0], d.angles3D[1], d.angles3D[2]));
  if (mapped)
    rows.emplace_back("angles, UV", format("%.1f %.1f %.1f", d.anglesUV[0], d.anglesUV[1], d.anglesUV[2]));
  rows.emplace_back("minimum angle", format("%.1f", d.minAngle));
  rows.emplace_back("area, 3D", format("%.4e", d.area3D));
  if (mapped) {
    rows.emplace_back("area, UV", format("%.4e", d.areaUV));
    rows.emplace_back("area share 3D / UV", format("%.3f", d.areaDistortion));  // each over its mesh's total
  }
  // A corner's valence, and its site on a row of its own: together, "site 12, valence 4
  // (border)" was the widest value and squeezed every label onto two lines. Regular is 6
  // inside, 4 on the border (the guide says so).
  for (int k = 0; k < 3; ++k)
    rows.emplace_back("vertex " + std::to_string(d.corners[k]),
                      "valence " + std::to_string(d.valences[k]) + (d.onBorder[k] ? ", border" : ""));
  if (!mapped) return rows;
  // Retriangulate: every corner is a site. Relocate: the inside vertices moved towards their
  // sites (short of them where they would fold), the border ones are theirs.
  std::string sites;
  for (int k = 0; k < 3; ++k) {
    if (k > 0) sites += ", ";
    if (d.sites[k] < 0) sites += "- (not moved)";
    else sites += std::to_string(d.sites[k]) + (d.atSite[k] ? "" : " (short of it)");
  }
  rows.emplace_back("their sites", sites);
  return rows;
}

std::string qualityTable(const QualityMetrics& before, const QualityMetrics& after,
                         const Fidelity* fidelity) {
  std::ostringstream out;
  line(out, "", "Input", "Output");
  out << "|------------------------------------|------------|------------|\n";
  line(out, "Vertices", std::to_string(before.vertices), std::to_string(after.vertices));
  line(out, "Faces", std::to_string(before.faces), std::to_string(after.faces));
  for (const Row& row : kRows)
    line(out, row.label, format(row.pattern, before.*row.field),
         format(row.pattern, after.*row.field));
  if (fidelity) {
    line(out, "Hausdorff distance (% diagonal)", "", format("%.3f", fidelity->hausdorffPercent));
    line(out, "RMS distance (% diagonal)", "", format("%.3f", fidelity->rmsPercent));
  }
  return out.str();
}

std::string pinsLeftOutByStage(const std::string& stage, bool cellsOut, bool trianglesOut) {
  if (!cellsOut && !trianglesOut) return "";
  const std::string what = cellsOut && trianglesOut ? "no cells and no result" : cellsOut ? "no cells" : "no result";
  return "The " + stage + " stage draws " + what + ": the pins show at the stages that do.";
}

std::string pinsNotShown(const std::vector<int>& pinned, size_t count, const std::string& kind,
                         const std::string& where) {
  std::string missing;
  int n = 0;
  for (int index : pinned)
    if (index < 0 || static_cast<size_t>(index) >= count) {
      missing += (n++ ? ", " : " ") + std::to_string(index);
    }
  if (n == 0) return "";
  std::string heading = kind + (n > 1 ? "s" : "");
  heading[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(heading[0])));
  const std::string has = count == 0 ? "has no " + kind + "s"
                                     : "has " + std::to_string(count) + " " + kind + (count > 1 ? "s" : "") +
                                           ", numbered from 0";
  return heading + missing + " pinned: " + where + " " + has + ".";
}

std::string farFromTheInputText(const Fidelity& f) {
  if (!(f.hausdorffPercent > kFarFromTheInputPercent)) return "";
  // A tall cone of 33 vertices, 32 of them on its border, came out a flat disk, said nowhere.
  return "Warning: the result strays " + format("%.1f", f.hausdorffPercent) +
         "% of the diagonal from the input: too few vertices for its shape there; more vertices "
         "asked may follow it";
}

std::string foldsText(const QualityMetrics& before, const QualityMetrics& after) {
  const int anew = foldsAnew(after, before);
  if (anew == 0) return "";
  // The lion head's ear at 1000 vertices: two triangles bridging the ear's rim, folded 179
  // degrees onto each other, seen by no angle (an independent check found them).
  return "Warning: the result folds back on itself at " + std::to_string(anew) + " edge" +
         (anew > 1 ? "s" : "") + " (its triangles turn more than " + format("%.0f", kFoldDegrees) +
         " degrees there), where the input folds nowhere that much: a part thinner than its triangles "
         "(an ear, a fin); more vertices asked may follow it";
}

std::string sharpCornerText(const QualityMetrics& before, const QualityMetrics& after) {
  // The smallest angle fills a corner of the border alone, at a corner of the input's (CGAL's
  // holes model clipped in half: its cut grazes a hole's rim, 13 degrees).
  if (after.minAngle >= kLeastMinAngle || after.minAngleOffSharpCorners <= after.minAngle) return "";
  const auto corner = std::find_if(after.sharpCorners.begin(), after.sharpCorners.end(), filledByOneTriangle);
  if (corner == after.sharpCorners.end()) return "";
  const BorderCorner* own = inputCornerKept(before, *corner);
  if (!own) return "";
  // Other corners of the input's that one triangle fills under 30 (a horn's two far corners of
  // 29.6 degrees beside its tip: "no angle elsewhere is under 30" was said).
  const long others = std::count_if(after.sharpCorners.begin(), after.sharpCorners.end(), filledByOneTriangle) - 1;
  const std::string elsewhere =
      meetsMinAngleBar(after, before)
          ? (others > 0 ? "no angle elsewhere is under 30 but at " + std::to_string(others) +
                              " more of the input's own sharp corners (the trials count the bar as met)"
                        : "no angle elsewhere is under 30 (the trials count the bar as met)")
      : after.minAngleOffSharpCorners < kLeastMinAngle
          ? "elsewhere the smallest angle is " + format("%.1f", after.minAngleOffSharpCorners) + " degrees"
          : "but another corner of the result is sharper than the input's there";
  // Wider than the input's corner (a horn whose sides bend away from its 21.5-degree tip: 25.4),
  // the chords to the next border samples make the angle: closer ones might reach 30.
  const bool wider = corner->degrees > own->degrees + kCornerSlackDegrees;
  return "The smallest angle, " + format("%.1f", corner->degrees) + " degrees, is at a corner of the input's border (" +
         format("%.1f", own->degrees) + " degrees at " + pointText(own->at) + ")" +
         (wider ? ", which one triangle fills, its sides the chords to the border's next samples; "
                : ", kept as it is: one triangle fills the corner, so no remeshing that keeps the border reaches 30 "
                  "there; ") +
         elsewhere;
}

std::string relocateNeedsText(bool canRun) {
  return std::string("Relocate needs the input's vertices as sites: ") +
         (canRun ? "under Settings choose method relocate, then Restart and Run."
                 : "this recording's run placed its own. Open one recorded by remesh --method relocate "
                   "--record <file>.");
}

std::string pinholeText(const QualityMetrics& after) {
  if (after.minAngle >= kLeastMinAngle || after.minAngleHoleEdges == 0) return "";
  return "The smallest angle, " + format("%.1f", after.minAngle) + " degrees, at " + pointText(after.minAngleAt) +
         ", is beside a hole of " + std::to_string(after.minAngleHoleEdges) + " border edges, " +
         format("%.3g", after.minAngleHoleLength) + " long in all, under half the mean edge (" +
         format("%.3g", after.meanEdge) +
         "): a hole is kept, with 3 border vertices at least, so the triangles around one this small are "
         "needles (a pinhole in a scan; close it to remesh it away)";
}

std::string tipText(const QualityMetrics& after) {
  if (after.minAngle >= kLeastMinAngle || after.minAngleTipSum <= 0) return "";
  return "The smallest angle, " + format("%.1f", after.minAngle) + " degrees, at " + pointText(after.minAngleAt) +
         ", is at a tip of the surface: the angles around that inside vertex sum to " +
         format("%.0f", after.minAngleTipSum) +
         " degrees, under the 90 that three angles of 30 need, so no triangles around a vertex there can all "
         "reach 30";
}

std::string curvatureText(const QualityMetrics& after) {
  // CGAL's armadillo halved along y at 500 vertices: 19% irregular, its curvature 24 units
  // per 100 vertices; at 1000, 11% and 16 units.
  if (!(after.irregularBoundaryAware > kMostIrregularPercent && after.curvatureDefects > kMostIrregularPercent))
    return "";
  // Mostly the border's turns (a flat gear, a jagged rim): the surface inside may be flat.
  if (2 * after.curvatureDefectsOnBorder > after.curvatureDefects)
    return format("%.1f", after.irregularBoundaryAware) + "% of the vertices are irregular where the border turns by " +
           format("%.1f", after.curvatureDefectsOnBorder) +
           " units of 60 degrees per 100 vertices at this size (the surface inside curves by " +
           format("%.1f", after.curvatureDefects - after.curvatureDefectsOnBorder) +
           "): equilateral triangles on these vertices would leave about as many irregular (a border vertex of 3 "
           "neighbours where the border bends out, of 5 where it bends in); more vertices share the turns";
  return format("%.1f", after.irregularBoundaryAware) + "% of the vertices are irregular where the surface curves by " +
         format("%.1f", after.curvatureDefects) +
         " units of 60 degrees per 100 vertices at this size: equilateral triangles on these vertices would "
         "leave about as many irregular (a 5 where the surface bulges, a 7 at a saddle); more vertices share "
         "the curvature";
}

std::string withNoteFirst(const std::string& note, const std::string& notes) {
  if (note.empty()) return notes;
  const std::string sentence = note.back() == '.' ? note : note + ".";
  return notes.empty() ? sentence : sentence + "\n" + notes;
}

std::string iterationsText(int count) {
  return std::to_string(count) + (count == 1 ? " iteration (0)" : " iterations (0-" + std::to_string(count - 1) + ")");
}

std::string thresholdsText(const LloydOptions& options) {
  // In %g: "%.0e, %.0f%%" showed 1.5e-06 and 2.5 as "2e-06, 2%", beside "2.3% moving" and
  // "converged".
  return format("Thresholds: %g, %g%%", options.distanceThreshold, options.percentThreshold);
}

std::string vertexCountText(const RemeshResult& r, const RemeshOptions& options) {
  const int asked = verticesAsked(options), got = r.after.vertices;
  // No final result (a recording opened alone: the inspector said "0 vertices for the 200 asked").
  // The input's own vertices are the sites (the report's preset): --simplify over its size left
  // it as it was (a note says so as the run starts), and no clean-up changed their number.
  if (asked <= 0 || got <= 0 || got == asked || options.method != RemeshMethod::Retriangulate ||
      options.sites.fromInputVertices)
    return {};
  // A border far longer than the surface is wide (a strip, a ribbon) takes more samples at their
  // spacing than were asked: the clean-up was blamed for a strip's 1002 of 300.
  // A strip 10^4 long and 1 wide at 500: 4040, its triangles 5 times as long as the strip is wide,
  // and the note said fewer vertices would have made them so.
  if (got > asked && r.after.boundaryVertices > asked)
    return std::to_string(got) + " vertices for the " + std::to_string(asked) + " asked: its border alone takes " +
           std::to_string(r.after.boundaryVertices) +
           " at their spacing (a border far longer than the surface is wide: a strip, a ribbon, a star of "
           "thin spikes); fewer would leave its triangles longer and thinner still" +
           (r.after.avgMinAngle < kLeastAvgMinAngle
                ? "; they are thin even so (average smallest angle " + format("%.1f", r.after.avgMinAngle) +
                      " degrees): more vertices asked (--sites) round them"
                : "");
  // A border that takes over half of them is sampled with the inside at one spacing, kept under
  // twice the surface's mean width (core/sites): a square with 160 teeth on its border, 3000
  // asked, got 4364, and the clean-up was blamed for "a few".
  if (got > asked + asked / 10 && 2 * r.after.boundaryVertices > asked)
    return std::to_string(got) + " vertices for the " + std::to_string(asked) + " asked: its border takes " +
           std::to_string(r.after.boundaryVertices) +
           " of them, sampled with the inside at a spacing kept under twice the surface's mean width (a border long "
           "for the surface inside it: a strip, a ribbon, a jagged outline); farther apart, its triangles would be "
           "longer and thinner";
  return std::to_string(got) + " vertices for the " + std::to_string(asked) +
         " asked: the clean-up adds or removes a few (seams stitched, short border edges merged, "
         "flat triangles removed)" +
         (r.charts > 0 ? ", and each chart's share is rounded" : "") +
         (r.components > 1 ? ", and each component's share is rounded, to " + std::to_string(kSmallestRemeshedShare) +
                                 " at least"
                           : "") +
         (r.componentsKept > 0 ? ", and components too small for their share are kept as they are" : "");
}

std::string iterationsLine(const RemeshResult& r, CvtSolver solver) {
  const char* steps = solver == CvtSolver::Lloyd ? "Lloyd" : solver == CvtSolver::Lbfgs ? "L-BFGS" : "Newton";
  const std::string parts = r.components > 1 ? ", all components together"
                            : r.charts > 0   ? ", all " + std::to_string(r.charts) + " charts together (the recording is the largest one's)"
                                             : "";
  return std::string(steps) + " iterations: " + std::to_string(r.iterations) + parts + (r.converged ? " (converged)" : " (not converged)");
}

std::string remeshReport(const RemeshResult& r, const RemeshOptions& o) {
  std::ostringstream out;
  out << "Settings: " << describe(o) << "\n\n";
  out << qualityTable(r.before, r.after, o.measureFidelity ? &r.fidelity : nullptr) << "\n";
  if (o.measureFidelity) {
    out << "Hausdorff distance reached at " << farthestPointText(r.fidelity) << "\n";
    if (const std::string far = farFromTheInputText(r.fidelity); !far.empty()) out << far << "\n";
  }
  if (const std::string folds = foldsText(r.before, r.after); !folds.empty()) out << folds << "\n";
  if (const std::string corner = sharpCornerText(r.before, r.after); !corner.empty()) out << corner << "\n";
  if (const std::string pinhole = pinholeText(r.after); !pinhole.empty()) out << pinhole << "\n";
  if (const std::string tip = tipText(r.after); !tip.empty()) out << tip << "\n";
  if (const std::string curved = curvatureText(r.after); !curved.empty()) out << curved << "\n";
  if (const std::string count = vertexCountText(r, o); !count.empty()) out << count << "\n";
  if (r.components > 1)
    out << "Remeshed " << r.components - r.componentsKept << " of " << r.components
        << " connected components, each on its own (the lines below on the map and the cut, and the"
        << " recording, are the largest one's)"
        << (r.componentsKept > 0 ? "; " + std::to_string(r.componentsKept) + " with " + std::to_string(kSmallestRemeshedShare) + " vertices or fewer, too small for their share, kept as they are" : "")
        << "\n";
  out << iterationsLine(r, o.lloyd.solver) << "\n";
  if (r.componentsKept < r.components)  // all kept as they are: nothing was parameterized
    out << "Parameterization" << (r.charts > 0 ? " (largest chart)" : "") << ": " << toString(r.paramUsed) << " ("
        << borderPhrase(r.paramUsed, r.borderUsed) << "), area ratio: " << format("%.3g", r.distortion.minAreaRatio) << " .. "
        << format("%.3g", r.distortion.maxAreaRatio)
        << ", mean angle error: " << format("%.1f", r.distortion.meanAngleErrorDeg) << " deg\n";
  if (!r.resampleDropped.empty()) out << withoutResamplingText(r.resampleDropped) << "\n";
  if (!r.fullInputFailed.empty()) out << fullInputFailedText(r.fullInputFailed, verticesAsked(o)) << "\n";
  if (r.charts > 0)
    out << "Split into " << r.charts << " charts along " << r.cut.seamEdges << " seam edges\n";
  else if (r.cut.seamEdges > 0)
    out << "Cut open along " << r.cut.seamEdges << " edges (" << r.cut.extremityCuts
        << (r.cut.extremityCuts == 1 ? " slit" : " slits") << " through extremities), conformal area spread " << format("%.3g", r.cut.areaSpread)
        << "\n";
  if (r.slitTrial) out << slitTrialText(r) << "\n";
  if (r.firstPassTrial) out << firstPassTrialText(r) << "\n";
  if (r.borderTrial) out << borderTrialText(r) << "\n";
  if (r.coarseInput > 0) out << coarseInputText(r.coarseInput, r.before.vertices) << "\n";
  if (r.chartTrial) out << chartTrialText(r) << "\n";
  if (r.snappedTips > 0)
    out << "Snapped onto tips of the input the result had cut off: " << r.snappedTips
        << (r.snappedTips == 1 ? " vertex\n" : " vertices\n");
  if (r.heldBack > 0)
    out << "Relocated: " << r.heldBack << (r.heldBack == 1 ? " vertex" : " vertices")
        << " held short of their sites (moved all the way, they would turn the input's triangles "
           "over or into slivers; retriangulate makes new ones)\n";
  if (r.fit.moved > 0)
    out << "Fitted to the input: " << r.fit.moved - r.fit.borderMoved << " vertices moved along their normals, "
        << r.fit.borderMoved << " on the border across it, " << format("%.3f", r.fit.meanPercent) << "% of the diagonal on average, at most " << format("%.3f", r.fit.maxPercent)
        << "%\n";
  out << "Time (ms): " << (r.ms.simplify > 0 ? "simplify " + format("%.1f", r.ms.simplify) + ", " : "")
      << (r.ms.cut > 0 ? "cut " + format("%.1f", r.ms.cut) + ", " : "")
      << (r.ms.resample > 0 ? "resample " + format("%.1f", r.ms.resample) + ", " : "")
      << "parameterize " << format("%.1f", r.ms.parameterize) << ", density "
      << format("%.1f", r.ms.density) << ", sites " << format("%.1f", r.ms.sites) << ", lloyd "
      << format("%.1f", r.ms.lloyd) << ", remesh " << format("%.1f", r.ms.remesh)
      << (r.ms.compared > 0 ? std::string(r.slitTrial ? ", the other way (alongside) " : ", the other way ") + format("%.1f", r.ms.compared) : "") << ", metrics "
      << format("%.1f", r.ms.metrics) << ", total " << format("%.1f", r.ms.total)
      << (r.runs > 1 ? " (" + std::to_string(r.runs) + " runs)" : "") << "\n";
  return out.str();
}

std::string metricsReport(const QualityMetrics& m, const Fidelity* fidelity) {
  std::ostringstream out;
  // A markdown table, as remesh's: without its header row it rendered as lines of text.
  out << "| Measure | Value |\n|---|---|\n";
  out << "| Vertices | " << m.vertices << " |\n| Faces | " << m.faces << " |\n";
  for (const Row& row : kRows) out << "| " << row.label << " | " << format(row.pattern, m.*row.field) << " |\n";
  if (fidelity) {
    out << "| Hausdorff distance (% diagonal) | " << format("%.3f", fidelity->hausdorffPercent)
        << " |\n| RMS distance (% diagonal) | " << format("%.3f", fidelity->rmsPercent) << " |\n";
  }
  return out.str();
}

nlohmann::json recordingSummary(const Recording& r) {
  nlohmann::json iterations = nlohmann::json::array();
  for (const IterationRecord& it : r.iterations)
    iterations.push_back({{"index", it.index},
                          {"energy", it.energy},
                          // Of the movable sites; a site's distance to its centroid, which is how
                          // far Lloyd's step moves it, not L-BFGS's or Newton's.
                          {"max_site_centroid_distance", it.maxDisplacement},
                          {"mean_site_centroid_distance", it.meanDisplacement},
                          {"percent_moving", 100.0 * it.fractionMoving},
                          {"milliseconds", it.milliseconds}});
  return {{"settings", settingsJson(r.settings)},
          {"parameterized_vertices", r.input.vertexCount()},  // the mesh the map is of, not always the input
          {"parameterized_faces", r.input.faceCount()},
          {"fixed_sites", r.fixedSites.size()},
          {"movable_sites", r.iterations.empty() ? 0 : r.iterations.front().sites.size()},
          {"distance_threshold", r.distanceThreshold},
          {"percent_threshold", r.percentThreshold},
          {"converged", r.converged()},
          {"iterations", iterations}};
}

std::string recordingReport(const Recording& r) {
  const nlohmann::json s = recordingSummary(r);
  std::ostringstream out;
  out << "Settings: " << r.settings << "\n";
  if (const std::string part = recordedPartText(r.settings); !part.empty()) out << part << "\n";
  out << "Parameterized mesh: " << r.input.vertexCount() << " vertices, " << r.input.faceCount()
      << " faces (the input, or its rough first remeshing, simplification or cut as the settings say)\n"
      << "Sites: " << s["fixed_sites"] << " fixed (border samples, never moved), " << s["movable_sites"]
      << " movable (the distances and % moving below are theirs)\n"
      << "Iterations: " << r.iterations.size()
      << (s["converged"].get<bool>() ? " (converged)" : " (not converged)") << "\n\n"
      << "| iteration | CVT energy | largest site-centroid distance | mean site-centroid distance | % moving | ms |\n"
      << "|---|---|---|---|---|---|\n";
  for (const IterationRecord& it : r.iterations)
    out << "| " << it.index << " | " << format("%.6e", it.energy) << " | "
        << format("%.3e", it.maxDisplacement) << " | " << format("%.3e", it.meanDisplacement)
        << " | " << format("%.1f", 100.0 * it.fractionMoving) << " | "
        << format("%.2f", it.milliseconds) << " |\n";
  return out.str();
}

}  // namespace lloydscope
