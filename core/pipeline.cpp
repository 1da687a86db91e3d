#include "pipeline.h"

#include "charts.h"
#include "flips.h"
#include "last_steps.h"
#include "mesh_io.h"
#include "names.h"
#include "polish.h"
#include "simplify.h"
#include "stopwatch.h"
#include "topology.h"

#include <algorithm>
#include <atomic>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <future>
#include <limits>
#include <numeric>
#include <set>
#include <sstream>
#include <thread>
#include <tuple>

namespace lloydscope {

RemeshOptions referencePreset(RemeshMethod method) {
  RemeshOptions o;
  o.method = method;
  o.param = {ParamMethod::Authalic, Border::Square, {}};
  o.density.kind = DensityKind::Uniform;
  o.sites.fromInputVertices = true;
  o.lloyd = LloydOptions{};  // 1e-6 and 5%
  o.lloyd.solver = CvtSolver::Lloyd;
  o.polish = -1;  // the report had no clean-up
  o.fit = false;
  o.resample = false;
  return o;
}

namespace {

// Relocation moves the input's own vertices: it needs one site per inside vertex, and the
// input itself as the parameterized surface. A resampled surface's own vertices are the sites.
RemeshOptions effective(RemeshOptions options) {
  if (options.method == RemeshMethod::Relocate) options.sites.fromInputVertices = true;
  if (options.sites.fromInputVertices) options.resample = false;
  return options;
}

// Whether the input's own vertices are the sites (relocate, the report's preset).
bool sitesAreInputVertices(const RemeshOptions& o) { return effective(o).sites.fromInputVertices; }

// What RemeshOptions::coarsenInput simplifies `input` to: 0 where it is not simplified (the
// caller's simplifyTo stands, the sites are the input's own vertices, a chart's seam samples are
// numbered by its vertices, it is small enough, or it has a fan of triangles around a vertex
// too large to simplify quickly: a CAD disk's hub of 3000 took over a minute to simplify, and
// a second to remesh as it is).
int coarseTarget(const RemeshOptions& o, const Mesh& input) {
  if (!o.coarsenInput || o.simplifyTo > 0 || o.sites.count <= 0 || sitesAreInputVertices(o) || !o.sites.onSeam.empty())
    return 0;
  const int size = coarseInputSize(o.sites.count);
  if (input.vertexCount() <= size || mostTrianglesAroundAVertex(input) > kMostTrianglesAroundAVertexToSimplify)
    return 0;
  return size;
}

RemeshOptions withCoarseInput(RemeshOptions options, const Mesh& input) {
  if (const int coarse = coarseTarget(options, input)) options.simplifyTo = coarse;
  return options;
}

// How many vertices `input` is simplified to before a run with `options`: the caller's
// simplifyTo, else coarsenInput's; 0: none.
int simplifyTarget(const RemeshOptions& options, const Mesh& input) {
  return options.simplifyTo > 0 ? options.simplifyTo : coarseTarget(options, input);
}

// `input` simplified to `target` vertices (0: as it is), or as `prepared` holds it where the
// caller made that already.
Mesh simplifiedTo(const Mesh& input, int target, const PreparedInput* prepared, const std::string& name) {
  if (target <= 0) return input;
  return prepared && prepared->simplified() ? *prepared->simplified() : simplify(input, {target}, name).mesh;
}

}  // namespace

RemeshSession::RemeshSession(const Mesh& input, const RemeshOptions& options,
                             const std::string& name, const PreparedInput* prepared,
                             const std::function<void()>& slittingDisk)
    : options_(withCoarseInput(effective(options), input)),
      coarsened_(options_.simplifyTo != options.simplifyTo),
      name_(name),
      original_(input),
      ownPrepared_(prepared ? nullptr : std::make_unique<const PreparedInput>(original_, std::nullopt)),
      prepared_(prepared ? prepared : ownPrepared_.get()),
      input_([&] {
        Stopwatch stage;
        Mesh mesh = simplifiedTo(input, options_.simplifyTo, prepared, name);
        ms_.simplify = stage.lap();
        const Topology topology = analyzeTopology(mesh);
        if (topology.components > 1)
          throw Error(name + ": it has " + topology.describe() +
                      "; a session steps one surface (lloydscope remesh does each on its own)");
        if (options_.method == RemeshMethod::Relocate) {
          if (topology.isDisk()) return mesh;
          throw Error(name + ": relocate keeps the input's triangles and needs a disk; this is " +
                      topology.describe() + " (use --method retriangulate)");
        }
        if (topology.isDisk() && !options_.slitDisks) return mesh;
        // A nearly closed disk is slit open too (CutOptions::slitDisksAbove); the seams are
        // stitched again in buildOutput().
        CutResult cut;  // no seam: the mesh as it is
        CutOptions how;
        how.slittingDisk = slittingDisk;
        try {
          cut = cutToDisk(mesh, name, how);
        } catch (const Error&) {
          if (!topology.isDisk()) throw;  // the slits are an improvement for a disk, not a need
        }
        ms_.cut = stage.lap();
        cutSummary_ = cut.summary;  // measured, slit or not (a disk kept whole said a spread of 1)
        if (cut.seam.empty()) return mesh;
        cut_ = std::move(cut);
        return std::move(cut_->disk);  // input_ holds it; nothing reads it there again
      }()),
      resampled_([&]() -> std::optional<Resampling> {
        if (!options_.resample) return std::nullopt;
        Stopwatch stage;
        // No finer than the input: more sites than that are sampled on the resampled surface.
        // On a cut surface the resampled vertices are the sites, whose seam samples match.
        SiteOptions sites = seamSites();
        sites.count = seamed() ? siteCount() : std::min(siteCount(), input_.vertexCount());
        ResampleOptions how;
        how.fallback = options_.param.fallback;
        Resampling r = resample(input_, sites, options_.density, how, name);
        ms_.resample = stage.lap();
        return r;
      }()),
      param_([&] {
        Stopwatch stage;
        ParamOptions o = options_.param;
        // Where LSCM folds on the resampled surface, its points in the input's map -- if that
        // map is conformal too; the mean value map of the resampled surface (no slivers)
        // distorts less than its points in the mean value map of the input.
        // (A chart's projection, ParamOptions::fallback, is as good: nearly isometric.)
        if (resampled_) {
          const ParamMethod used = resampled_->param.method;
          o.fallback.clear();  // of the input's vertices, not the resampled surface's
          if (isFreeBorder(used)) o.fallback = resampled_->mesh.uv;
        }
        Parameterization p = parameterize(surface(), o, name);
        ms_.parameterize = stage.lap();
        return p;
      }()),
      density_([&] {
        Stopwatch stage;
        Density d = computeDensity(surface(), param_.uv, options_.density);
        ms_.density = stage.lap();
        return d;
      }()),
      domain_([&] {
        Stopwatch stage;  // the domain's adjacency and spatial index count with the density
        Domain d(param_.uv, surface().triangles, density_);
        ms_.density += stage.lap();
        return d;
      }()) {
  Stopwatch stage;
  SiteOptions siteOptions = seamSites();
  siteOptions.count = siteCount();
  // The resampled surface's vertices are already well spread: where there are as many of them
  // as sites, they are where Lloyd starts.
  if (resampled_) {
    siteOptions.onSeam.clear();  // of the input's vertices, not the resampled surface's
    siteOptions.seamNode.clear();
    if (seamed() || siteCount() <= input_.vertexCount()) siteOptions.fromInputVertices = true;
  }
  sites_ = initialSites(surface(), param_, domain_, siteOptions, name_);
  ms_.sites = stage.lap();
  solver_ = std::make_unique<LloydSolver>(domain_, sites_.fixed, sites_.movable, options_.lloyd);
}

const IterationRecord& RemeshSession::step() {
  const IterationRecord& record = solver_->step();
  ms_.lloyd += record.milliseconds;
  return record;
}

bool RemeshSession::finished() const {
  return converged() || iterationCount() >= options_.lloyd.maxIterations;
}

Recording RemeshSession::header() const {
  Recording r;
  // The settings asked, and what the run made of them: the coarse input it simplified to (as
  // simplify=N, it read back as asked) and the map "auto" chose.
  RemeshOptions asked = options_;
  if (coarsened_) asked.simplifyTo = 0;
  // The border "auto" fell back to, where it is not the one asked (a rectangle).
  const bool otherBorder = !isFreeBorder(param_.method) && param_.border != options_.param.border;
  r.settings = describe(asked) + (coarsened_ ? " coarse-input=" + std::to_string(options_.simplifyTo) : "") +
               " param-used=" + toString(param_.method) +
               (otherBorder ? std::string(" border-used=") + toString(param_.border) : "");
  r.method = options_.method;
  r.distanceThreshold = options_.lloyd.distanceThreshold;
  r.percentThreshold = options_.lloyd.percentThreshold;
  r.input = surface();
  r.uv = param_.uv;
  r.density = density_;
  r.fixedSites = solver_->fixedSites();
  r.movableVertex = sites_.movableVertex;
  if (options_.sites.sharesSeams()) r.sharedSeams = sharedSeamEdges(surface(), input_, options_.sites.onSeam);
  return r;
}

namespace {
// The last steps, on the whole result (stitched where it was cut): the snaps to the tips it cut
// off; valence flips that leave no angle of the two new triangles under 35 degrees
// (flipToRegularity: the relaxation, the repair and the snaps move vertices after the polish's
// own valence flips and leave some to make, 9 of the 83 irregular vertices of CGAL's mushroom
// at 500 vertices); the valence moves that need a relaxation after them, or two flips
// (relaxedValenceMoves: on 36 disks, mean irregularity 15.5 -> 13.3%, smallest angles and their
// mean up too); the vertices of triangles under 35 degrees moved where their smallest angle is
// largest (raiseSmallAngles: on the 36 disks, the mean smallest angle 29.6 -> 31.5 degrees);
// a border corner under 60 degrees with a site in its wedge made an ear (earsAtSharpCorners: on
// 194 of CGAL's samples clipped at 30 and 70% of their height, at 1000 vertices, 179 met the
// three bars instead of 177, the poly's 30.6-degree corner 15.3 -> 30.6 degrees);
// where a border edge is left too short, its collapse, and those steps again
// (collapseShortBorderEdges: on the 36 disks, 25 meet all bars instead of 23, Homer clipped in
// half at 2000 vertices 16.4 -> 32.5 degrees, the man at 500 23.7 -> 33.1; collapsing first,
// before the flips, left the man at 19.6 degrees); every vertex moved where its triangles'
// mean smallest angle is largest, their smallest angle kept (raiseMeanAngles: on the 36 disks,
// the average smallest angle up by 0.65 degrees on average); the vertices of the triangle
// that strays farthest from the input moved where its chords come nearer (bringNearer: on the
// bench, the Hausdorff distance down on 8 of 15 inputs, by up to 11%); then the fit to the input.
void stepsOnTheInput(Mesh& result, const SearchableSurface& original, const RemeshOptions& o, RemeshResult& done) {
  if (o.polish > 0) {
    std::vector<int> tips = o.snapToTips ? snapToTips(result, original) : std::vector<int>();
    done.snappedTips = static_cast<int>(tips.size());
    const auto regularize = [&] {
      flipToRegularity(result);
      relaxedValenceMoves(result, original, tips);
      raiseSmallAngles(result, original, tips);
      earsAtSharpCorners(result, original, tips);
    };
    regularize();
    if (collapseShortBorderEdges(result, original, tips) > 0) regularize();
    raiseMeanAngles(result, original, tips);
    bringNearer(result, original, tips);
  }
  if (!o.fit) return;
  FitOptions fit;
  fit.threads = o.lloyd.threads;
  done.fit = fitToSurface(result, original, fit);
}

// The steps above where asked, then, with or without them, the triangles of no area mended: a
// map with a round border makes ears and pockets of samples in a row on a straight border,
// triangles of no area that a reader of the result refuses (dropFlatTriangles).
void lastSteps(Mesh& result, const PreparedInput& input, const RemeshOptions& o, RemeshResult& done) {
  if (o.polish > 0 || o.fit) stepsOnTheInput(result, input.search(), o, done);
  dropFlatTriangles(result);
}

// A result stitched back from a cut disk or from charts: its seams relaxed on `surface`, its
// flat triangles removed, then the last steps against `original`.
void finishStitched(Mesh& stitched, const std::vector<bool>& seamVertex, const Mesh& surface,
                    const PreparedInput& original, const RemeshOptions& o, RemeshResult& done) {
  if (o.polish > 0) polishSeams(stitched, seamVertex, surface, o.polish);
  removeFlatTriangles(stitched);
  lastSteps(stitched, original, o, done);
}
}  // namespace

Mesh RemeshSession::buildOutput(RemeshResult& result) const {
  const std::vector<Vec2>& movable = solver_->movableSites();
  if (options_.method == RemeshMethod::Relocate) {
    Relocation relocated = relocate(input_, domain_, sites_.movableVertex, movable);
    result.heldBack = relocated.heldBack;
    return std::move(relocated.mesh);
  }
  // A chart's border samples must be where the neighbouring chart's are, which lifting them
  // through a map nearly flat at the border may miss (onto an inside edge): they are put on
  // the border's edges themselves (the one disk of a cut gives both copies the same lift).
  const bool sharedSeams = options_.sites.sharesSeams();
  LiftedMesh output = retriangulate(surface(), domain_, solver_->fixedSites(), movable, name_,
                                    sharedSeams ? sites_.fixedPoints : std::vector<Vec3>{});
  SurfaceMap map{surface(), domain_};
  if (resampled_) {
    // From the resampled surface's chords onto the input surface itself; its border onto the
    // input's own border (also where the polish slides a border vertex along it), but where it
    // holds seams, whose two copies must land alike: as lifted.
    map.lift = [this](const Location& l) {
      if (!seamed() && domain_.onBorder(l))
        if (const std::optional<Vec3> p = resampled_->borderToInput(input_, l.triangle, l.weights)) return *p;
      return resampled_->toInput(input_, l.triangle, l.weights);
    };
    // A chart's border samples are the resampled chart's own border vertices, already there.
    const int exact = sharedSeams ? static_cast<int>(sites_.fixed.size()) : 0;
    for (int v = exact; v < output.mesh.vertexCount(); ++v)
      output.mesh.points[v] = map.at(domain_.locate(output.uv[v]));
  }
  if (options_.polish >= 0) {
    PolishOptions o;
    o.iterations = options_.polish;
    o.target = options_.polishTarget;
    o.seams = seamed();
    polish(output, map, surfaceDensity(surface(), param_.uv, density_), o);
  } else if (seamed()) {
    prepareSeams(output, map);
  }
  if (!cut_) {
    // A chart's last steps are the whole surface's, once its charts are stitched (remeshCharts).
    if (!seamed()) lastSteps(output.mesh, *prepared_, options_, result);
    return std::move(output.mesh);
  }
  // Both copies of every seam sample are at the same place: one vertex again.
  std::vector<bool> seamVertex;
  Mesh stitched = stitchSeams(output.mesh, seamTolerance(output.mesh), &seamVertex);
  finishStitched(stitched, seamVertex, input_, *prepared_, options_, result);
  requireStitched(stitched, cut_->topology, siteCount(), name_);
  return stitched;
}

int verticesAsked(const RemeshOptions& o) { return o.sites.count > 0 ? o.sites.count : o.simplifyTo; }

void requireStitched(const Mesh& stitched, const Topology& want, int verticesWanted, const std::string& name) {
  try {
    // Its problems are the result's, not the input's: "(tetra.off: the mesh has no faces)" said
    // the input, which has four, had none.
    validateMesh(stitched, "the stitched result");
    const Topology got = analyzeTopology(stitched);
    std::set<Triangle> faces;  // the same three vertices twice: two sides of one triangle
    for (Triangle t : stitched.triangles) {
      std::sort(t.begin(), t.end());
      if (!faces.insert(t).second) throw Error("two triangles have the same corners");
    }
    if (2 * stitched.vertexCount() < verticesWanted)
      throw Error("only " + std::to_string(stitched.vertexCount()) + " of " +
                  std::to_string(verticesWanted) + " vertices are left");
    if (got.genus == want.genus && got.boundaryLoops.size() == want.boundaryLoops.size() &&
        got.components == 1)
      return;
    throw Error(got.describe());
  } catch (const Error& e) {
    throw Error(name + ": the remeshed seams did not stitch back into " + want.describe() +
                " (" + e.what() + "); cutting this surface open is not reliable yet");
  }
}

int RemeshSession::siteCount() const {
  const int wanted = verticesAsked(options_);
  if (wanted <= 0) return input_.vertexCount();
  if (!cut_) return wanted;
  // A cut surface's disk holds each seam sample twice: one more site per sample, which sets
  // the border's spacing (the inside's count is then made exact from the samples themselves:
  // SiteOptions::stitchedCount). The input's seams have as many copies as the disk has
  // vertices more than the surface; the result's are as many times more as its edges are
  // shorter: the square root of the ratio of vertex counts.
  const int surfaceVertices = *std::max_element(cut_->original.begin(), cut_->original.end()) + 1;
  const double copies = input_.vertexCount() - surfaceVertices;
  return wanted + static_cast<int>(std::lround(copies * std::sqrt(static_cast<double>(wanted) / surfaceVertices)));
}

SiteOptions RemeshSession::seamSites() const {
  SiteOptions sites = options_.sites;  // a chart's seams (core/charts), per input vertex
  if (!cut_) return sites;
  sites.stitchedCount = verticesAsked(options_);
  sites.seamNode = cut_->seamNode;
  sites.onSeam = cut_->onSeam;
  if (!options_.sites.onSeam.empty())
    for (size_t v = 0; v < cut_->original.size(); ++v) {
      const int was = cut_->original[v];
      sites.onSeam[v] = sites.onSeam[v] || options_.sites.onSeam[was];
      sites.seamNode[v] = sites.seamNode[v] || options_.sites.seamNode[was];
    }
  return sites;
}

RemeshResult RemeshSession::finish() {
  RemeshResult result;
  result.paramUsed = param_.method;
  result.borderUsed = param_.border;
  result.distortion = param_.distortion;
  result.cut = cutSummary_;
  result.ms = ms_;
  result.iterations = iterationCount();
  result.converged = converged();
  result.coarseInput = coarseInput();
  Stopwatch stage;
  result.output = buildOutput(result);
  result.ms.remesh = stage.lap();
  result.before = measureQuality(original());
  result.after = measureQuality(result.output);
  if (options_.measureFidelity) result.fidelity = measureFidelity(result.output, prepared_->search());
  result.ms.metrics = stage.lap();
  result.ms.total = result.ms.simplify + result.ms.cut + result.ms.resample + result.ms.parameterize + result.ms.density + result.ms.sites +
                    result.ms.lloyd + result.ms.remesh + result.ms.metrics;
  result.recording = header();
  result.recording.iterations = solver_->takeIterations();
  return result;
}

namespace {

// `attempt(options)`, and where it fails with the first pass, `attempt` without it, its
// result's resampleDropped saying why (the last error where both fail). The first pass is an
// improvement, not a need: where the run fails with it (every map of the resampled surface
// collapses a part the cut's slits did not reach, as on CGAL's triceratops; or its seams do not
// stitch, as on the turbine), it runs without. remesh()'s runs and startSession()'s sessions
// alike.
template <class Attempt>
auto withOrWithoutFirstPass(const RemeshOptions& options, const std::string& name, Attempt attempt) {
  if (!usesResampling(options)) return attempt(options);
  try {
    return attempt(options);
  } catch (const Error& e) {
    auto made = attempt(withoutResampling(options));
    made.resampleDropped = problemOf(e, name);
    return made;
  }
}

// What ends a run that another one made needless (remeshDisk()): not an Error, so that no
// fallback runs it again.
struct RunNotNeeded {};

// The hooks of a run that goes beside another (remeshDisk()).
struct RunHooks {
  std::function<void(RemeshSession&)> started;  // with each session as soon as it is built (and its cut known)
  std::function<void()> slittingDisk;           // RemeshSession's
  const std::atomic<bool>* notNeeded = nullptr;  // once set, the run ends at its next step: RunNotNeeded
};

// `prepared`: as RemeshSession takes it.
RemeshResult remeshOnce(const Mesh& input, const RemeshOptions& options, const std::string& name,
                        const RunHooks& hooks = {}, const PreparedInput* prepared = nullptr) {
  auto run = [&](const RemeshOptions& o) {
    Stopwatch total;
    RemeshSession session(input, o, name, prepared, hooks.slittingDisk);
    if (hooks.started) hooks.started(session);
    while (!session.finished()) {
      if (hooks.notNeeded && *hooks.notNeeded) throw RunNotNeeded{};
      session.step();
    }
    RemeshResult result = session.finish();
    result.ms.total = total.lap();
    return result;
  };
  return withOrWithoutFirstPass(options, name, run);
}

// A part of the surface remeshed on its own (`kind` "chart" or "component", `number` of `count`)
// added to the whole's counts and times; the largest by area (`largest` so far) gives its
// recording, which says so (part=), and map. Returns whether it was that.
bool addPart(RemeshResult& whole, RemeshResult& part, const std::string& kind, int number, int count, double area,
             double& largest) {
  const std::string label = kind + " " + std::to_string(number);
  whole.iterations += part.iterations;
  whole.converged = whole.converged && part.converged;
  if (!part.resampleDropped.empty())
    whole.resampleDropped += (whole.resampleDropped.empty() ? "" : "; ") + (label + ": " + part.resampleDropped);
  whole.ms += part.ms;
  if (area <= largest) return false;
  largest = area;
  whole.recording = std::move(part.recording);
  // A chart of a component: part=chart-3-of-19,component-1-of-2.
  const std::string mark = kind + "-" + std::to_string(number) + "-of-" + std::to_string(count);
  std::string& settings = whole.recording.settings;
  if (const std::string within = settingValue(settings, "part"); within.empty())
    settings += " part=" + mark;
  else
    settings.replace(settings.find(" part=" + within), 6 + within.size(), " part=" + within + "," + mark);
  whole.paramUsed = part.paramUsed;
  whole.borderUsed = part.borderUsed;
  whole.distortion = part.distortion;
  return true;
}

// The run a trial did not keep counts in the kept one's times: its own work as `compared`, its
// measuring as metrics.
void countTheOtherRun(RemeshResult& kept, const RemeshResult& other) {
  kept.runs += other.runs;
  kept.ms.compared += other.ms.total - other.ms.metrics;
  kept.ms.metrics += other.ms.metrics;
}

// Once: a result a trial measured already keeps its distances.
void measureFidelityOf(RemeshResult& result, const PreparedInput& input) {
  if (result.fidelity.samples > 0) return;
  Stopwatch stage;
  result.fidelity = measureFidelity(result.output, input.search());
  const double ms = stage.lap();
  result.ms.metrics += ms;
  result.ms.total += ms;
}

// Both measured against the input (each once): their Hausdorff distances, % of the diagonal,
// `a`'s first.
std::pair<double, double> hausdorffOfBoth(RemeshResult& a, RemeshResult& b, const PreparedInput& input) {
  measureFidelityOf(a, input);
  measureFidelityOf(b, input);
  return {a.fidelity.hausdorffPercent, b.fidelity.hausdorffPercent};
}

// remeshCharts' refusal where its charts, small ones merged into their neighbours, come to one.
struct OneChartCoversIt : Error {
  using Error::Error;
};

}  // namespace

// Each chart gets its share of the vertices by area and half its seam samples more (each is
// also another chart's), its border sampled at the whole surface's spacing so that both sides
// of a seam get the same samples; its projection is the map tried where LSCM folds. The
// stitched seams are relaxed (polishSeams) and snapped to tips.
RemeshResult remeshCharts(const Mesh& input, const RemeshOptions& options, const std::string& name,
                          const PreparedInput* prepared, const ChartOptions& charting) {
  Stopwatch wall, stage;
  RemeshResult result;
  result.coarseInput = coarseTarget(options, input);
  const Mesh mesh = simplifiedTo(input, simplifyTarget(options, input), prepared, name);
  result.ms.simplify = stage.lap();
  const int asked = verticesAsked(options) > 0 ? verticesAsked(options) : mesh.vertexCount();
  const Charts charts = splitIntoCharts(mesh, asked, charting);
  if (charts.charts.size() < 2) throw OneChartCoversIt(name + ": one chart covers it");
  const double area = surfaceArea(mesh);
  const double spacing = equilateralEdgeLength(area, asked);
  result.ms.cut = stage.lap();
  result.charts = static_cast<int>(charts.charts.size());
  result.cut.seamEdges = charts.seamEdges;
  result.converged = true;
  // Each chart's share of the area, and half its seams' samples (each seam is sampled on both
  // sides) and its nodes'.
  std::vector<double> areas;
  std::vector<int> counts;
  for (const Chart& chart : charts.charts) {
    areas.push_back(surfaceArea(chart.mesh));
    counts.push_back(std::max(1, static_cast<int>(std::lround(asked * areas.back() / area + 0.5 * chart.seamLength / spacing +
                                                              chart.nodeSamples))));
  }
  // Seams far longer than the vertices asked span (charts up a spike a million times as tall as
  // wide) run away with the run, as a border does (core/sites).
  const long long total = std::accumulate(counts.begin(), counts.end(), 0LL);
  if (total > static_cast<long long>(kMostBorderPerVertex) * std::max(asked, kSmallestRemeshedShare))
    throw Error(name + ": " + std::to_string(asked) + " vertices are too few for it chart by chart: at their spacing " +
                "the charts take " + std::to_string(total) + " (over " + std::to_string(kMostBorderPerVertex) +
                " times as many)");
  Mesh pieces;
  double largest = -1;
  for (size_t i = 0; i < charts.charts.size(); ++i) {
    const Chart& chart = charts.charts[i];
    const std::string chartName =
        name + " (chart " + std::to_string(i + 1) + " of " + std::to_string(charts.charts.size()) + ")";
    validateMesh(chart.mesh, chartName);
    const double chartArea = areas[i];
    RemeshOptions o = options;
    o.simplifyTo = 0;
    o.sites.count = counts[i];
    o.sites.onSeam = chart.onSeam;
    o.sites.seamNode = chart.seamNode;
    o.sites.spacing = spacing;
    o.param.fallback = chart.uv;
    o.slitDisks = false;
    o.measureFidelity = false;
    RemeshResult r = remeshOnce(chart.mesh, o, chartName);
    append(pieces, r.output);
    if (addPart(result, r, "chart", static_cast<int>(i) + 1, static_cast<int>(charts.charts.size()), chartArea, largest))
      result.largestChart = chart.mesh;
  }
  stage.lap();
  std::vector<bool> seamVertex;
  Mesh stitched = stitchSeams(pieces, seamTolerance(pieces), &seamVertex);
  const PreparedInput own(input, std::nullopt);
  finishStitched(stitched, seamVertex, mesh, prepared ? *prepared : own, options, result);
  requireStitched(stitched, analyzeTopology(mesh), asked, name);
  result.output = std::move(stitched);
  result.ms.remesh += stage.lap();
  result.before = measureQuality(input);
  result.after = measureQuality(result.output);
  result.ms.metrics += stage.lap();
  result.ms.total = wall.lap();
  return result;
}

namespace {

// remeshCharts, and where its charts fail, again with smaller ones allowed (a chart too small
// for its share of the vertices is merged into a neighbour, ChartOptions::smallestShare, and the
// union can bend more than any map of it holds, or leave seams that do not stitch: CGAL's bull
// clipped at 70% of its height, the camel clipped so, the man clipped front to back), down to
// a quarter of the share at first. With `evenOneChart`, also where the charts came to one: where
// the one disk failed, any charts are better than none; where it holds, the surface is one
// chart at this size (a tall cone of 33 vertices, in 5 smaller charts, had 87). The last
// failure is thrown.
RemeshResult remeshChartsSmallerWhereTheyFail(const Mesh& input, const RemeshOptions& options, const std::string& name,
                                              const PreparedInput& prepared, bool evenOneChart) {
  constexpr int kSmallestChartShare = 5;
  for (ChartOptions charting;; charting.smallestShare /= 2) {
    const bool last = charting.smallestShare / 2 < kSmallestChartShare;
    try {
      return remeshCharts(input, options, name, &prepared, charting);
    } catch (const OneChartCoversIt&) {
      if (last || !evenOneChart) throw;
    } catch (const Error&) {
      if (last) throw;
    }
  }
}

// The surface remeshed chart by chart too (remeshCharts), and the charts kept in `kept`'s place
// if ChartTrial::chartsBetter(); both are measured against the input where that reads the
// distances (ChartTrial::distancesDecide()). Where no conformal map of the one disk holds
// (LSCM folds or its border overlaps itself, and a map with a fixed border takes over: CGAL's
// cow and elephant, parts with many handles, the back half of a body whose arms curl over it),
// its cells come out stretched, and the charts are rounder; on a CAD part with sharp edges
// (CGAL's spool, rotor, lion) the charts' seams follow the edges, and the charts are closer.
// `forBars`: see ChartTrial::forBars. `options` measure no fidelity (the trial measures where it
// decides).
void tryCharts(RemeshResult& kept, const Mesh& input, const RemeshOptions& options, const std::string& name,
               const PreparedInput& prepared, bool forBars = false) {
  try {
    RemeshResult charted = remeshChartsSmallerWhereTheyFail(input, options, name, prepared, /*evenOneChart=*/false);
    ChartTrial trial;
    trial.forBars = forBars;
    trial.charts = charted.charts;
    trial.oneCutAvgMinAngle = kept.after.avgMinAngle;
    trial.chartsAvgMinAngle = charted.after.avgMinAngle;
    trial.oneCutBars = barsMet(kept.after, kept.before);
    trial.chartsBars = barsMet(charted.after, charted.before);
    trial.oneCutFolds = foldsAnew(kept.after, kept.before) > 0;
    trial.chartsFold = foldsAnew(charted.after, charted.before) > 0;
    if (trial.distancesDecide())
      std::tie(trial.oneCutHausdorff, trial.chartsHausdorff) = hausdorffOfBoth(kept, charted, prepared);
    if (trial.chartsBetter()) std::swap(kept, charted);
    kept.chartTrial = trial;
    countTheOtherRun(kept, charted);
  } catch (const Error& e) {  // a chart failed, or its seams did not stitch: the one cut stands
    kept.chartTrial = ChartTrial{};
    kept.chartTrial->forBars = forBars;
    kept.chartTrial->failed = problemOf(e, name);
  }
}

// Where the one cut fails (every map of it folds or collapses: a badly shaped input whose
// protrusions the slits do not all reach, as CGAL's bull clipped lengthwise, 3 of 98 clipped
// halves of CGAL's samples), the surface chart by chart: each chart is nearly flat, and its own
// projection holds (at 500 vertices, a leg of the bull clipped at 70% of its height was one
// chart whose normals spread over 170 degrees, and even Tutte's map collapsed triangles of it:
// smaller charts hold). If they all fail, the one cut's error stands.
RemeshResult chartsInstead(const Mesh& input, const RemeshOptions& options, const std::string& name,
                           const PreparedInput& prepared, const Error& oneCut) {
  try {
    RemeshResult charted = remeshChartsSmallerWhereTheyFail(input, options, name, prepared, /*evenOneChart=*/true);
    charted.chartTrial = ChartTrial{};
    charted.chartTrial->charts = charted.charts;
    charted.chartTrial->chartsAvgMinAngle = charted.after.avgMinAngle;
    charted.chartTrial->chartsBars = barsMet(charted.after, charted.before);
    charted.chartTrial->oneCutFailed = problemOf(oneCut, name);
    return charted;
  } catch (const Error& e) {
    // Both ways said: the one disk's problem alone hid why the charts failed too.
    throw Error(std::string(oneCut.what()) + "; chart by chart it failed too: " + problemOf(e, name));
  }
}

// A disk slit open (a nearly closed shape, CutOptions::slitDisksAbove) is made whole too, and
// the better result kept (SlitTrial::wholeBetter): slits through a shape's far side (CGAL's
// mannequin, a camel head, the lion head at 1000 vertices) pay, through the peaks of a terrain
// (CGAL's three peaks) they cost. The other run's time counts. If the slit run fails (its seams
// do not stitch), the whole one stands alone. Both are measured against the input only where
// both meet the three bars (the distance then decides).
RemeshResult remeshDisk(const Mesh& input, const RemeshOptions& options, const std::string& name,
                        const PreparedInput& prepared) {
  RemeshOptions slitOptions = options, wholeOptions = options;
  slitOptions.measureFidelity = wholeOptions.measureFidelity = false;
  if (!options.slitDisks) return remeshOnce(input, wholeOptions, name, {}, &prepared);
  wholeOptions.slitDisks = false;
  // Once the slit run's cut is to try slits, the whole run goes on beside it on another thread,
  // each with half the cores for its cells (a core each on two: 1.4-1.6x faster than one after
  // the other with both cores each, on CGAL's lion head and mannequin). It starts before the
  // slits are tried, not once they are made: on a large scan they take most of the cut's time,
  // and the slit run's first pass follows (the face scan at 1000 vertices: 0.8 s). Where the
  // slits are left out after all, the slit run is the whole one, and the other ends at its next
  // step. Neither's result depends on its threads.
  const int half = std::max(1, static_cast<int>(std::thread::hardware_concurrency()) / 2);
  const int shared = options.lloyd.threads > 0 ? std::max(1, options.lloyd.threads / 2) : half;
  // Declared before `whole`: its destructor waits for the run, which reads the flag till it ends.
  std::atomic<bool> wholeNotNeeded{false};
  std::future<RemeshResult> whole;
  const auto startWhole = [&] {
    if (whole.valid()) return;
    wholeOptions.lloyd.threads = shared;
    RunHooks hooks;
    hooks.notNeeded = &wholeNotNeeded;
    whole = std::async(std::launch::async, [&, hooks] { return remeshOnce(input, wholeOptions, name, hooks, &prepared); });
  };
  RunHooks slitHooks;
  slitHooks.slittingDisk = startWhole;
  // A disk's cut slits only after saying so (slittingDisk): a slit session has the run beside.
  slitHooks.started = [&](RemeshSession& session) {
    if (session.isCut()) session.setThreads(shared);  // also a retry without the first pass
    else wholeNotNeeded = true;
  };
  RemeshResult kept;
  try {
    kept = remeshOnce(input, slitOptions, name, slitHooks, &prepared);
  } catch (const Error&) {
    // As it would have been without slits. A slit run that never slit (its cut never said so,
    // or its session was not cut) was the whole run, and that failed: made again, it failed
    // again, twice (with and without the first pass).
    if (!whole.valid() || wholeNotNeeded) throw;
    kept = whole.get();
  }
  if (kept.cut.seamEdges > 0 && whole.valid()) {
    try {
      RemeshResult other = whole.get();
      SlitTrial trial{kept.after.avgMinAngle, other.after.avgMinAngle, barsMet(kept.after, kept.before),
                      barsMet(other.after, other.before)};
      if (trial.bothMeetTheBars())
        std::tie(trial.slitHausdorff, trial.wholeHausdorff) = hausdorffOfBoth(kept, other, prepared);
      if (trial.wholeBetter()) std::swap(kept, other);
      kept.slitTrial = trial;
      countTheOtherRun(kept, other);
    } catch (const Error&) {
      // the slit one stands alone
    }
  }
  return kept;
}

// The disk remeshed without the first pass too where its result misses a bar, and that kept if
// FirstPassTrial::withoutBetter(); both are measured against the input where that reads the
// distances (FirstPassTrial::distancesDecide()).
void tryWithoutFirstPass(RemeshResult& kept, const Mesh& input, const RemeshOptions& options, const std::string& name,
                         const PreparedInput& prepared) {
  // Without the polish the bars are not what a run aims at (`--polish -1` shows what it buys).
  if (!usesResampling(options) || options.polish <= 0 || !kept.resampleDropped.empty() || barsMet(kept.after, kept.before) == 3)
    return;
  // A nearly closed disk is made slit open and whole again: the way the slit trial kept with the
  // first pass alone would save a fifth of the time (the camel head at 500: 3.2 -> 2.8 s), but
  // the way it did not keep can be the better without it (CGAL's triceratops clipped in half at
  // 1000 with one polish pass: all three bars instead of one).
  FirstPassTrial trial;
  trial.withBars = barsMet(kept.after, kept.before);
  RemeshResult other;
  try {
    other = remeshDisk(input, withoutResampling(options), name, prepared);
  } catch (const Error& e) {
    trial.failed = problemOf(e, name);
    kept.firstPassTrial = trial;
    return;
  }
  trial.withoutBars = barsMet(other.after, other.before);
  if (trial.distancesDecide())
    std::tie(trial.withHausdorff, trial.withoutHausdorff) = hausdorffOfBoth(kept, other, prepared);
  trial.keptWithout = trial.withoutBetter();
  if (trial.keptWithout) std::swap(kept, other);
  kept.firstPassTrial = trial;
  countTheOtherRun(kept, other);
}

// How many of `points` no border vertex of `m` is at (to a millionth of its diagonal, as the
// sites keep them): kept corners that the polish's slides or the merges of short border edges
// moved on, where that raised a small angle (a zigzag border's notches).
int offTheBorder(const std::vector<Vec3>& points, const Mesh& m) {
  const std::vector<bool> border = vertexEdges(m).onBoundary;
  const double samePoint = 1e-6 * boundingBoxDiagonal(m);
  std::vector<Vec3> borderPoints;
  for (int v = 0; v < m.vertexCount(); ++v)
    if (border[v]) borderPoints.push_back(m.points[v]);
  return static_cast<int>(std::count_if(points.begin(), points.end(), [&](const Vec3& p) {
    return std::none_of(borderPoints.begin(), borderPoints.end(),
                        [&](const Vec3& q) { return (p - q).norm() <= samePoint; });
  }));
}

// The disk remeshed again with the corners of the input's border that the kept result's border
// cuts (off or across) kept as border samples (borderCornersCut), and that kept if
// BorderTrial::withBetter().
// Only where the kept result is one disk, not slit open nor in charts (whose seams take their
// own samples), made as the defaults make it (the polish after retriangulating, the border
// resampled).
void tryKeepingBorderCorners(RemeshResult& kept, const Mesh& input, const RemeshOptions& options,
                             const std::string& name, const PreparedInput& prepared) {
  if (options.polish <= 0 || options.method != RemeshMethod::Retriangulate ||
      sitesAreInputVertices(options) || kept.cut.seamEdges > 0 || kept.charts > 0)
    return;
  std::vector<Vec3> corners = borderCornersCut(kept.output, prepared.search());
  if (corners.empty()) return;
  RemeshOptions again = options;
  again.slitDisks = false;  // kept whole
  if (!kept.resampleDropped.empty() || (kept.firstPassTrial && kept.firstPassTrial->keptWithout))
    again = withoutResampling(again);
  again.sites.keptBorderPoints = corners;
  BorderTrial trial;
  trial.corners = std::move(corners);
  trial.withoutBars = barsMet(kept.after, kept.before);
  RemeshResult other;
  try {
    other = remeshOnce(input, again, name, {}, &prepared);
  } catch (const Error& e) {
    trial.failed = problemOf(e, name);
    kept.borderTrial = std::move(trial);
    return;
  }
  trial.withBars = barsMet(other.after, other.before);
  std::tie(trial.withoutHausdorff, trial.withHausdorff) = hausdorffOfBoth(kept, other, prepared);
  trial.keptWith = trial.withBetter();
  if (trial.keptWith) {  // the first run's trials stand for this one's too
    other.slitTrial = kept.slitTrial;
    other.firstPassTrial = kept.firstPassTrial;
    other.chartTrial = kept.chartTrial;
    other.resampleDropped = kept.resampleDropped;
    std::swap(kept, other);
    trial.cornersMoved = offTheBorder(trial.corners, kept.output);
  }
  kept.borderTrial = std::move(trial);
  countTheOtherRun(kept, other);
}

// A disk is remeshed as one (remeshDisk), a surface of another topology cut open to one disk;
// either is remeshed chart by chart too (tryCharts), a disk only where its map is not
// conformal (not with a map or first pass the user chose: the charts need the automatic map);
// a disk whose result still misses a bar without the first pass too (tryWithoutFirstPass), and
// if it misses one either way, chart by chart (ChartTrial::forBars). On the 136 halves of
// CGAL's samples under 200 vertices, at 500, that took those meeting the three bars from 92 to
// 117 (corners, crosses, polyhedra: the charts' seams follow their sharp edges); on the 93
// larger ones from 74 / 81 / 86 to 75 / 82 / 86 at 500 / 1000 / 2000.
RemeshResult remeshSurface(const Mesh& input, bool disk, const RemeshOptions& options, const std::string& name) {
  Stopwatch wall;
  RemeshOptions once = options;
  once.measureFidelity = false;
  // Simplified once for all the runs, charts too (each would otherwise simplify it again: 0.35 s
  // a run on a face of 26,000 vertices); the input's search built once for them all.
  const int simplifyTo = simplifyTarget(options, input);
  std::optional<Mesh> simplified;
  if (simplifyTo > 0) simplified = simplify(input, {simplifyTo}, name).mesh;
  const PreparedInput prepared(input, std::move(simplified));
  const double simplifyMs = wall.lap();
  const bool chartsAllowed = options.param.method == ParamMethod::Auto && usesResampling(options);
  RemeshResult kept;
  bool oneCutFailed = false;
  try {
    kept = disk ? remeshDisk(input, once, name, prepared) : remeshOnce(input, once, name, {}, &prepared);
  } catch (const Error& e) {
    if (!chartsAllowed) throw;
    kept = chartsInstead(input, once, name, prepared, e);
    oneCutFailed = true;
  }
  if (chartsAllowed && kept.charts == 0 && (!disk || !isFreeBorder(kept.paramUsed)))
    tryCharts(kept, input, once, name, prepared);
  // A one cut that failed failed without the first pass too (remeshOnce makes both): made
  // without it again, it failed again (CGAL's camel clipped by a plane, at 1000 vertices: 0.8 s of 3.9).
  if (disk && !oneCutFailed) tryWithoutFirstPass(kept, input, once, name, prepared);
  if (disk && chartsAllowed && !kept.chartTrial && barsMet(kept.after, kept.before) < 3)
    tryCharts(kept, input, once, name, prepared, /*forBars=*/true);
  if (disk) tryKeepingBorderCorners(kept, input, once, name, prepared);
  kept.ms.simplify += simplifyMs;
  if (options.measureFidelity) measureFidelityOf(kept, prepared);
  else kept.fidelity = Fidelity{};  // a trial measured it to choose; the user asked for none
  kept.ms.total = simplifyMs + wall.lap();  // every run, side by side or one after the other
  return kept;
}

// Each connected component on its own, with its share (by area) of the vertices asked for; the
// results side by side, measured together against the whole input. The largest component's
// recording, map and cut stand for the run.
RemeshResult remeshComponents(const Mesh& input, const RemeshOptions& options, const std::string& name) {
  const std::vector<Mesh> parts = splitComponents(input);
  const double totalArea = surfaceArea(input);
  RemeshResult result;
  result.components = static_cast<int>(parts.size());
  result.runs = 0;
  result.converged = true;
  double largest = -1;
  int relaxedOn = 0;  // vertices of the surfaces remeshed: a component's simplified input, or itself
  bool simplifiedAny = false;
  for (size_t i = 0; i < parts.size(); ++i) {
    const double area = surfaceArea(parts[i]);
    auto share = [&](int count) { return static_cast<int>(std::lround(count * area / totalArea)); };
    const int asked = verticesAsked(options);
    if (asked > 0 && share(asked) < kSmallestRemeshedShare && parts[i].vertexCount() <= kSmallestRemeshedShare) {
      append(result.output, parts[i]);
      ++result.componentsKept;
      relaxedOn += parts[i].vertexCount();
      continue;
    }
    RemeshOptions o = options;
    if (options.simplifyTo > 0) o.simplifyTo = std::max(kSmallestRemeshedShare, share(options.simplifyTo));
    if (options.sites.count > 0) o.sites.count = std::max(kSmallestRemeshedShare, share(options.sites.count));
    o.measureFidelity = false;
    const std::string partName =
        name + " (component " + std::to_string(i + 1) + " of " + std::to_string(parts.size()) + ")";
    RemeshResult r = remeshSurface(parts[i], analyzeTopology(parts[i]).isDisk(), o, partName);
    result.runs += r.runs;
    append(result.output, r.output);
    relaxedOn += r.coarseInput > 0 ? r.coarseInput : parts[i].vertexCount();
    simplifiedAny = simplifiedAny || r.coarseInput > 0;
    result.snappedTips += r.snappedTips;
    result.heldBack += r.heldBack;
    result.fit += r.fit.scaled(boundingBoxDiagonal(parts[i]) / boundingBoxDiagonal(input));
    // (The total is timed around them all, in remesh().) The largest component's cut, charts and
    // trials go with its recording and map: a component remeshed chart by chart was said to be
    // one disk, and one chart's map the component's.
    if (addPart(result, r, "component", static_cast<int>(i) + 1, static_cast<int>(parts.size()), area, largest)) {
      result.cut = r.cut;
      result.slitTrial = r.slitTrial;
      result.charts = r.charts;
      result.largestChart = std::move(r.largestChart);
      result.chartTrial = r.chartTrial;
      result.firstPassTrial = r.firstPassTrial;
      result.borderTrial = r.borderTrial;
    }
  }
  if (simplifiedAny) result.coarseInput = relaxedOn;
  Stopwatch stage;
  result.before = measureQuality(input);
  result.after = measureQuality(result.output);
  if (options.measureFidelity) result.fidelity = measureFidelity(result.output, input);
  result.ms.metrics += stage.lap();
  return result;
}

}  // namespace

namespace {
// Two digits, or as many more as `x` needs not to read as `limit`, the bound it is past, in two
// (a strip's area of 9.99e-07 against the least, 1e-06, read "1e-06 (the least is 1e-06)").
std::string shortNumber(double x, double limit = std::nan("")) {
  const auto digits = [](double v, int n) {
    char text[32];
    std::snprintf(text, sizeof text, "%.*g", n, v);
    return std::string(text);
  };
  std::string text = digits(x, 2);
  for (int n = 3; n <= 17 && text == digits(limit, 2); ++n) text = digits(x, n);
  return text;
}
}  // namespace

void requireExactPredicatesRange(const Mesh& input, const std::string& name, const std::string& task) {
  double largest = 0;
  for (const Vec3& p : input.points) largest = std::max(largest, p.cwiseAbs().maxCoeff());
  if (largest > kLargestCoordinate)
    throw Error(name + ": coordinates as large as " + shortNumber(largest, kLargestCoordinate) + " are beyond what can be " + task +
                " in double precision (up to " + shortNumber(kLargestCoordinate) + "); scale the mesh down");
  const double diagonal = boundingBoxDiagonal(input);
  if (diagonal < kSmallestDiagonal)
    throw Error(name + ": too small to be " + task + " in double precision: its bounding box's diagonal is " +
                shortNumber(diagonal, kSmallestDiagonal) + " (the least is " + shortNumber(kSmallestDiagonal) + "); scale it up");
  if (largest > kFarthestPerSize * diagonal)
    throw Error(name + ": too far from the origin for its size: " + shortNumber(largest / diagonal, kFarthestPerSize) +
                " times its diagonal away (at most " + shortNumber(kFarthestPerSize) +
                "), double precision leaves too few digits for its shape; move it nearer");
}

namespace {
// A vertex farther from the middle of the surface (the median of its vertices, coordinate by
// coordinate) than this many times as far as 99% of its vertices are: a stray one.
constexpr double kStrayDistance = 100;

// "(x, y, z)", six digits each: a vertex named by where it is, as the file has it (by its
// number it was the reader's, counted from 0 once unused vertices were dropped: an OBJ's line
// 53 was "vertex 50").
std::string pointText(const Vec3& p) {
  std::ostringstream text;
  text << '(' << p.x() << ", " << p.y() << ", " << p.z() << ')';
  return text.str();
}

// A stray vertex (a scan's outlier, a coordinate typed wrong) pulls its triangles into a needle
// far longer than the surface, which the border's samples or the last steps' ears then follow
// for minutes (the bumpy disk with one vertex 1000 times as far: over 200 s, for a result that
// is mostly needle). Under 100 vertices the 99% are all of them: nothing to tell.
void requireNoStrayVertex(const Mesh& input, const std::string& name) {
  std::vector<char> used(input.vertexCount(), 0);
  for (const Triangle& t : input.triangles)
    for (int v : t) used[v] = 1;
  std::vector<int> vertices;
  for (int v = 0; v < input.vertexCount(); ++v)
    if (used[v]) vertices.push_back(v);
  if (vertices.size() < 100) return;
  Vec3 middle;
  std::vector<double> coordinate(vertices.size());
  for (int axis = 0; axis < 3; ++axis) {
    for (size_t i = 0; i < vertices.size(); ++i) coordinate[i] = input.points[vertices[i]][axis];
    std::nth_element(coordinate.begin(), coordinate.begin() + coordinate.size() / 2, coordinate.end());
    middle[axis] = coordinate[coordinate.size() / 2];
  }
  std::vector<double> distance(vertices.size());
  for (size_t i = 0; i < vertices.size(); ++i) distance[i] = (input.points[vertices[i]] - middle).norm();
  const size_t farthest = std::max_element(distance.begin(), distance.end()) - distance.begin();
  const double stray = distance[farthest];
  const auto reachOfMost = distance.begin() + static_cast<long>(0.99 * static_cast<double>(distance.size() - 1));
  std::nth_element(distance.begin(), reachOfMost, distance.end());
  if (*reachOfMost > 0 && stray > kStrayDistance * *reachOfMost)
    throw Error(name + ": the vertex at " + pointText(input.points[vertices[farthest]]) + " is " +
                std::to_string(static_cast<long long>(stray / *reachOfMost)) +
                " times as far from the middle of the surface as 99% of its vertices (at most " +
                std::to_string(static_cast<int>(kStrayDistance)) +
                "): a stray vertex, whose triangles make a needle; remove it or move it back");
}
}  // namespace

void requireRemeshableSize(const Mesh& input, const Topology& topology, int vertices, const std::string& name) {
  requireExactPredicatesRange(input, name, "remeshed");
  requireNoStrayVertex(input, name);
  const double diagonal = boundingBoxDiagonal(input);
  const double area = surfaceArea(input);
  if (area < kThinnestArea * diagonal * diagonal)
    throw Error(name + ": too thin to remesh: its area is " + shortNumber(area / (diagonal * diagonal), kThinnestArea) +
                " times its bounding box's diagonal squared (the least is " + shortNumber(kThinnestArea) +
                "): a sliver of a surface, or a vertex far off the rest");
  // The border is sampled at the spacing of the vertices asked (core/sites), however many that
  // takes: beyond ten times as many as asked (20 at least, as a run asks), a sliver's border
  // runs away with the run (a strip 10^6 to 1 took 16,751 vertices for 81, in 31 s).
  double borderLength = 0;
  for (const std::vector<int>& loop : topology.boundaryLoops) borderLength += loopLength(input, loop);
  vertices = std::max(vertices, kSmallestRemeshedShare);
  const double spacing = equilateralEdgeLength(area, vertices);
  if (borderLength > static_cast<double>(kMostBorderPerVertex) * vertices * spacing)
    throw Error(name + ": " + std::to_string(vertices) + " vertices are too few for it: at their spacing its border alone takes " +
                std::to_string(static_cast<long long>(std::ceil(borderLength / spacing))) + " (over " +
                std::to_string(kMostBorderPerVertex) + " times as many); ask for more (--sites), or look for a sliver or " +
                "a vertex far off the rest");
}

namespace {

// Whether remesh() makes a run that failed again on the input simplified to the vertices asked
// (RemeshResult::fullInputFailed): where sites are asked, fewer than the input has, and neither
// --simplify nor --full-input was given (nor the input's own vertices are the sites: relocate).
bool simplifyingMayHelp(const RemeshOptions& o, const Mesh& input) {
  return o.simplifyTo == 0 && o.coarsenInput && o.sites.count > 0 && !sitesAreInputVertices(o) &&
         input.vertexCount() > o.sites.count;
}

// A run that failed as it is and again simplified to `asked` vertices: both problems, then the
// last run's advice ("; try ...": the first's, between them, read as the end).
Error bothFailed(const Error& asItIs, const Error& simplified, int asked, const std::string& name) {
  const std::string last = simplified.what();
  const size_t advice = last.find("; try");
  return Error(name + ": " + problemOf(asItIs, name) + "; simplified to " + std::to_string(asked) +
               " vertices first, it failed too: " + problemOf(simplified, name) +
               (advice == std::string::npos ? "" : last.substr(advice)));
}

// `attempt(options)`, and where it fails and simplifying may help, `attempt` of the options
// simplified to the sites asked, its result's fullInputFailed saying why; where that fails too,
// both problems (bothFailed). remesh()'s runs and startSession()'s sessions alike.
template <class Attempt>
auto asItIsOrSimplified(const Mesh& input, const RemeshOptions& options, const std::string& name, Attempt attempt) {
  try {
    return attempt(options);
  } catch (const Error& e) {
    if (!simplifyingMayHelp(options, input)) throw;
    RemeshOptions simplified = options;
    simplified.simplifyTo = options.sites.count;
    try {
      auto made = attempt(simplified);
      made.fullInputFailed = problemOf(e, name);
      return made;
    } catch (const Error& again) {
      throw bothFailed(e, again, options.sites.count, name);
    }
  }
}

}  // namespace

StartedSession startSession(const Mesh& input, const RemeshOptions& options, const std::string& name) {
  const auto session = [&](const RemeshOptions& o) -> StartedSession {
    return {std::make_unique<RemeshSession>(input, o, name), o, "", ""};
  };
  // Several components: no try helps (a session steps one surface).
  if (analyzeTopology(input).components > 1) return session(options);
  return asItIsOrSimplified(input, options, name, [&](const RemeshOptions& o) {
    return withOrWithoutFirstPass(o, name, session);
  });
}

RemeshResult remesh(const Mesh& input, const RemeshOptions& options, const std::string& name) {
  const int asked = verticesAsked(options);
  if (asked > 0 && asked < kSmallestRemeshedShare)
    throw Error(name + ": " + std::to_string(asked) + " vertices asked; a surface is remeshed to " +
                std::to_string(kSmallestRemeshedShare) + " at least");
  const Topology topology = analyzeTopology(input);
  requireRemeshableSize(input, topology, asked > 0 ? asked : input.vertexCount(), name);
  const auto remeshWith = [&](const RemeshOptions& o) {
    if (topology.components <= 1) return remeshSurface(input, topology.isDisk(), o, name);
    Stopwatch total;
    RemeshResult result = remeshComponents(input, o, name);
    result.ms.total = total.lap();
    return result;
  };
  Stopwatch wall;
  RemeshResult result = asItIsOrSimplified(input, options, name, remeshWith);
  // Made simplified: the failed run's time counts too (in no stage).
  if (!result.fullInputFailed.empty()) result.ms.total = wall.lap();
  return result;
}

int coarseInputSize(int vertices) {
  // On issue 5's 36 originals (CGAL's five disks, the face, the camel head and five CGAL
  // surfaces clipped in half, each at 500, 1000 and 2000 vertices; 18 of the 36 simplified):
  // all bars met on 32 instead of 30 (also the Hausdorff bar against CGAL's remesher on the
  // original), mean smallest angle 34.77 -> 34.89 degrees, Hausdorff distance 1.455 -> 1.351%,
  // the 18 runs 155 -> 106 s. Ten per vertex without the cap also met 32, six 32 (smaller
  // angles), twenty 29. The camel head subdivided to 45,000 vertices at 2000: 37 s at ten per
  // vertex, 16 s with the cap; at 1000, 66 s as it is, 18 s simplified.
  constexpr int kPerVertex = 10, kCap = 10000, kPerVertexOverCap = 5;
  return std::min(kPerVertex * vertices, std::max(kCap, kPerVertexOverCap * vertices));
}

bool meetsMoreBars(int bars, double hausdorff, int otherBars, double otherHausdorff) {
  return bars > otherBars && hausdorff <= 1.25 * otherHausdorff;
}

bool ChartTrial::chartsBetter() const {
  if (oneCutFolds != chartsFold) return oneCutFolds;
  if (meetsMoreBars(chartsBars, chartsHausdorff, oneCutBars, oneCutHausdorff)) return true;
  if (forBars) return false;
  if (meetsMoreBars(oneCutBars, oneCutHausdorff, chartsBars, chartsHausdorff)) return false;
  const bool rounder = chartsAvgMinAngle > oneCutAvgMinAngle && chartsHausdorff <= kFartherBy * oneCutHausdorff;
  const bool closer = chartsHausdorff <= kCloserBy * oneCutHausdorff && chartsAvgMinAngle >= oneCutAvgMinAngle - kRounderBy;
  // And the other way round: much rounder, and not much farther.
  const bool muchRounder = chartsAvgMinAngle >= oneCutAvgMinAngle + kRounderBy && kCloserBy * chartsHausdorff <= oneCutHausdorff;
  return rounder || closer || muchRounder;
}

bool SlitTrial::wholeBetter() const {
  if (wholeBars != slitBars) return wholeBars > slitBars;
  if (bothMeetTheBars()) return wholeHausdorff < slitHausdorff;
  return whole > slit;
}

bool FirstPassTrial::withoutBetter() const {
  return meetsMoreBars(withoutBars, withoutHausdorff, withBars, withHausdorff);
}

bool usesResampling(const RemeshOptions& options) { return effective(options).resample; }

RemeshOptions withoutResampling(RemeshOptions options) {
  options.resample = false;
  return options;
}

std::string problemOf(const Error& e, const std::string& name) {
  std::string problem = e.what();  // "<name>: <problem>; try <advice>"
  if (problem.rfind(name + ": ", 0) == 0) problem.erase(0, name.size() + 2);
  return problem.substr(0, problem.find("; try"));
}

namespace {

// The shortest text that reads back as the same double (the stream's six digits gave a
// recording's threshold 1.234567e-06 back as 1.23457e-06), and 1e-06 still as "1e-06".
std::string exactly(double value) {
  char text[32];
  return std::string(text, std::to_chars(text, text + sizeof text, value).ptr);
}

}  // namespace

std::string describe(const RemeshOptions& options) {
  const RemeshOptions o = effective(options);  // what runs: relocate has no first pass, for one
  std::ostringstream s;
  if (o.simplifyTo > 0) s << "simplify=" << o.simplifyTo << " ";
  s << "method=" << toString(o.method) << " resample=" << (o.resample ? "yes" : "no") << " param=" << toString(o.param.method)
    << " border=" << toString(o.param.border) << " density=" << toString(o.density.kind);
  if (o.density.kind == DensityKind::Curvature)
    s << " alpha=" << exactly(o.density.alpha) << " beta=" << exactly(o.density.beta)
      << " floor=" << exactly(o.density.floor);
  s << " sites="
    << (o.sites.fromInputVertices ? std::string("input-vertices")
        : o.sites.count > 0       ? std::to_string(o.sites.count)
                                  : std::string("as-many-as-input"))
    << " solver=" << toString(o.lloyd.solver)
    << " distance-threshold=" << exactly(o.lloyd.distanceThreshold)
    << " percent-threshold=" << exactly(o.lloyd.percentThreshold)
    << " max-iterations=" << o.lloyd.maxIterations;
  if (o.method == RemeshMethod::Retriangulate) {
    s << " polish=" << o.polish;
    if (o.polish > 0) s << " polish-target=" << toString(o.polishTarget) << " snap=" << (o.snapToTips ? "yes" : "no");
    s << " fit=" << (o.fit ? "yes" : "no");
    if (!o.slitDisks) s << " slit-disks=no";
  }
  if (!o.coarsenInput) s << " full-input=yes";
  return s.str();
}

std::vector<std::pair<std::string, std::string>> settingPairs(const std::string& settings) {
  std::vector<std::pair<std::string, std::string>> pairs;
  std::istringstream words(settings);
  for (std::string word; words >> word;)
    if (const size_t equals = word.find('='); equals != std::string::npos)
      pairs.emplace_back(word.substr(0, equals), word.substr(equals + 1));
  return pairs;
}

std::string settingValue(const std::string& settings, const std::string& key) {
  for (const auto& [name, value] : settingPairs(settings))
    if (name == key) return value;
  return "";
}

RemeshOptions optionsFromSettings(const std::string& settings) {
  RemeshOptions o;
  // Each key describe() writes, parsed back where the line has it.
  std::string key;  // the setting being read
  auto with = [&](const char* name, const std::function<void(const std::string&)>& set) {
    key = name;
    if (const std::string value = settingValue(settings, key); !value.empty()) set(value);
  };
  // The whole value, a finite number, or an error: std::stoi took "max-iterations=12abc" for 12.
  const auto number = [&](const std::string& v, auto parse) {
    size_t used = 0;
    try {
      if (const auto n = parse(v, &used); used == v.size() && std::isfinite(n)) return n;
    } catch (const std::logic_error&) {  // std::stoi and std::stod's
    }
    throw Error("setting " + key + "=" + v + " is not a number");
  };
  const auto integer = [&](const std::string& v) {
    return number(v, [](const std::string& text, size_t* used) { return std::stoi(text, used); });
  };
  // strtod, not std::stod, which throws on a subnormal: the command line's
  // --distance-threshold 1e-310 made a recording that did not read back.
  const auto real = [&](const std::string& v) {
    return number(v, [](const std::string& text, size_t* used) {
      char* end = nullptr;
      const double value = std::strtod(text.c_str(), &end);
      *used = static_cast<size_t>(end - text.c_str());
      return value;
    });
  };
  // As the command line takes them: a recording's max-iterations=2147483647 and its threshold
  // of 1e-300 made the inspector's Compare run for ever.
  const auto within = [&](auto value, double low, double high, const char* range) {
    if (!(value >= low && value <= high))
      throw Error("setting " + key + "=" + settingValue(settings, key) + " is not " + range);
    return value;
  };
  const auto nonNegative = [&](const std::string& v) { return within(real(v), 0, INFINITY, "a number >= 0"); };
  // A chart's or a component's run records its own share of the vertices (18 of 25 asked):
  // not the command line's range; its border and seams take at most a few times the most asked.
  const auto count = [&](const std::string& v) {
    return within(integer(v), 1, 10.0 * kMostRemeshedVertices, "a count of vertices a run records (1 to 10000000)");
  };
  auto yes = [](const std::string& v) { return v == "yes"; };
  with("simplify", [&](const std::string& v) { o.simplifyTo = count(v); });
  with("method", [&](const std::string& v) { o.method = parseRemeshMethod(v); });
  with("resample", [&](const std::string& v) { o.resample = yes(v); });
  with("param", [&](const std::string& v) { o.param.method = parseParamMethod(v); });
  with("border", [&](const std::string& v) { o.param.border = parseBorder(v); });
  with("density", [&](const std::string& v) { o.density.kind = parseDensityKind(v); });
  with("alpha", [&](const std::string& v) { o.density.alpha = nonNegative(v); });
  with("beta", [&](const std::string& v) { o.density.beta = nonNegative(v); });
  with("floor", [&](const std::string& v) { o.density.floor = nonNegative(v); });
  with("sites", [&](const std::string& v) {
    o.sites.fromInputVertices = v == "input-vertices";
    o.sites.count = v == "input-vertices" || v == "as-many-as-input" ? 0 : count(v);
  });
  with("solver", [&](const std::string& v) { o.lloyd.solver = parseCvtSolver(v); });
  with("distance-threshold", [&](const std::string& v) {
    o.lloyd.distanceThreshold = within(real(v), std::numeric_limits<double>::denorm_min(), INFINITY, "a number > 0");
  });
  with("percent-threshold", [&](const std::string& v) {
    o.lloyd.percentThreshold = within(real(v), 0, 100, "a percentage from 0 to 100");
  });
  with("max-iterations", [&](const std::string& v) {
    o.lloyd.maxIterations = within(integer(v), 1, kMostIterations, "an iteration count the command line takes");
  });
  with("polish", [&](const std::string& v) { o.polish = within(integer(v), -1, kMostPolishPasses, "from -1 to 100"); });
  with("polish-target", [&](const std::string& v) { o.polishTarget = parsePolishTarget(v); });
  with("snap", [&](const std::string& v) { o.snapToTips = yes(v); });
  with("fit", [&](const std::string& v) { o.fit = yes(v); });
  with("slit-disks", [&](const std::string& v) { o.slitDisks = yes(v); });
  with("full-input", [&](const std::string& v) { o.coarsenInput = !yes(v); });
  return o;
}

void keepWithinCommandLineBounds(RemeshOptions& o) {
  const auto asked = [](int n) { return n > 0 ? std::clamp(n, kSmallestRemeshedShare, kMostRemeshedVertices) : 0; };
  o.simplifyTo = asked(o.simplifyTo);
  o.sites.count = asked(o.sites.count);
  o.polish = std::clamp(o.polish, -1, kMostPolishPasses);
  o.lloyd.maxIterations = std::clamp(o.lloyd.maxIterations, 1, kMostIterations);
}

std::string recordedPartText(const std::string& settings) {
  std::string text, word;
  std::istringstream marks(settingValue(settings, "part"));
  while (std::getline(marks, word, ',')) {  // chart-3-of-19
    std::replace(word.begin(), word.end(), '-', ' ');
    text += (text.empty() ? "" : ", in ") + word;
  }
  return text.empty() ? "" : "The iterations are of one part of the run, the largest: " + text;
}

ParamMethod recordedParamMethod(const std::string& settings) {
  const std::string used = settingValue(settings, "param-used");
  if (used.empty()) return optionsFromSettings(settings).param.method;
  // The input's own map (where no other held) is no method to ask for: parseParamMethod refuses it.
  return used == toString(ParamMethod::Given) ? ParamMethod::Given : parseParamMethod(used);
}

Border recordedBorder(const std::string& settings) {
  const std::string used = settingValue(settings, "border-used");
  return used.empty() ? optionsFromSettings(settings).param.border : parseBorder(used);
}

RecordedRun recordedRun(Recording recording) {
  RecordedRun run;
  run.options = optionsFromSettings(recording.settings);
  RemeshResult& r = run.result;
  r.paramUsed = recordedParamMethod(recording.settings);
  r.borderUsed = recordedBorder(recording.settings);
  r.distortion = measureDistortion(recording.input, recording.uv);
  r.before = measureQuality(recording.input);
  r.iterations = static_cast<int>(recording.iterations.size());
  r.converged = recording.converged();
  r.recording = std::move(recording);
  return run;
}

constexpr NamedValue<RemeshMethod> kRemeshMethodNames[] = {{RemeshMethod::Relocate, "relocate"},
                                                            {RemeshMethod::Retriangulate, "retriangulate"}};

const char* toString(RemeshMethod method) { return nameOf(kRemeshMethodNames, method); }

RemeshMethod parseRemeshMethod(const std::string& text) { return parseName(kRemeshMethodNames, text, "method"); }

}  // namespace lloydscope
