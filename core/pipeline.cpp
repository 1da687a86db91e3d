#include "pipeline.h"

#include <chrono>
#include <sstream>

namespace lloydscope {

namespace {

class Stopwatch {
 public:
  double lap() {  // milliseconds since construction or the previous lap
    const auto now = std::chrono::steady_clock::now();
    const double ms = std::chrono::duration<double, std::milli>(now - last_).count();
    last_ = now;
    return ms;
  }

 private:
  std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

}  // namespace

RemeshOptions referencePreset(RemeshMethod method) {
  RemeshOptions o;
  o.method = method;
  o.param = {ParamMethod::Authalic, Border::Square};
  o.density.kind = DensityKind::Uniform;
  o.sites.fromInputVertices = true;
  o.lloyd = LloydOptions{};  // 1e-6 and 5%
  o.lloyd.solver = CvtSolver::Lloyd;
  return o;
}

Mesh buildOutput(const Mesh& input, const Domain& domain, RemeshMethod method,
                 const std::vector<Vec2>& fixedSites, const std::vector<Vec2>& movableSites,
                 const std::vector<int>& movableVertex) {
  if (method == RemeshMethod::Relocate) return relocate(input, domain, movableVertex, movableSites);
  return retriangulate(input, domain, fixedSites, movableSites);
}

RemeshResult remesh(const Mesh& input, const RemeshOptions& requested, const std::string& name) {
  RemeshOptions options = requested;
  // Relocation moves the input's own vertices: it needs one site per inside vertex.
  if (options.method == RemeshMethod::Relocate) options.sites.fromInputVertices = true;

  RemeshResult result;
  Stopwatch total, stage;
  const Parameterization param = parameterize(input, options.param, name);
  result.paramUsed = param.method;
  result.distortion = param.distortion;
  result.ms.parameterize = stage.lap();

  std::vector<double> density = computeDensity(input, param.uv, options.density);
  Domain domain(param.uv, input.triangles, density);
  result.ms.density = stage.lap();

  InitialSites sites = initialSites(input, param, domain, options.sites);
  result.ms.sites = stage.lap();

  LloydSolver solver(domain, sites.fixed, sites.movable, options.lloyd);
  solver.run();
  result.iterations = static_cast<int>(solver.iterations().size());
  result.converged = solver.converged();
  result.ms.lloyd = stage.lap();

  result.output = buildOutput(input, domain, options.method, solver.fixedSites(),
                              solver.movableSites(), sites.movableVertex);
  result.ms.remesh = stage.lap();

  result.before = measureQuality(input);
  result.after = measureQuality(result.output);
  if (options.measureFidelity) result.fidelity = measureFidelity(result.output, input);
  result.ms.metrics = stage.lap();
  result.ms.total = total.lap();

  Recording& r = result.recording;
  r.settings = describe(options);
  r.method = options.method;
  r.distanceThreshold = options.lloyd.distanceThreshold;
  r.percentThreshold = options.lloyd.percentThreshold;
  r.input = input;
  r.uv = param.uv;
  r.density = std::move(density);
  r.fixedSites = solver.fixedSites();
  r.movableVertex = sites.movableVertex;
  r.iterations = solver.takeIterations();
  return result;
}

std::string describe(const RemeshOptions& o) {
  std::ostringstream s;
  s << "method=" << toString(o.method) << " param=" << toString(o.param.method)
    << " border=" << toString(o.param.border) << " density=" << toString(o.density.kind);
  if (o.density.kind == DensityKind::Curvature)
    s << " alpha=" << o.density.alpha << " beta=" << o.density.beta;
  s << " sites="
    << (o.sites.fromInputVertices ? std::string("input-vertices")
        : o.sites.count > 0       ? std::to_string(o.sites.count)
                                  : std::string("as-many-as-input"))
    << " solver=" << toString(o.lloyd.solver)
    << " distance-threshold=" << o.lloyd.distanceThreshold
    << " percent-threshold=" << o.lloyd.percentThreshold
    << " max-iterations=" << o.lloyd.maxIterations;
  return s.str();
}

const char* toString(RemeshMethod method) {
  return method == RemeshMethod::Relocate ? "relocate" : "retriangulate";
}

RemeshMethod parseRemeshMethod(const std::string& text) {
  if (text == "relocate") return RemeshMethod::Relocate;
  if (text == "retriangulate") return RemeshMethod::Retriangulate;
  throw Error("unknown method '" + text + "' (relocate, retriangulate)");
}

}  // namespace lloydscope
