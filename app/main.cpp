// lloydscope: the command line. Every command runs headless; errors are one line on stderr.
#include "mesh_io.h"
#include "pipeline.h"
#include "report.h"

#include <CLI/CLI.hpp>

#include <iostream>

using namespace lloydscope;

namespace {

struct RemeshArgs {
  std::string input, output, record, preset, method = "retriangulate", param, border, density,
      solver;
  int sites = 0;
  int maxIterations = 0;
  double distanceThreshold = 0, percentThreshold = 0, alpha = 1, beta = 1;
  bool json = false, noFidelity = false;
};

// The preset first, then whatever the user named explicitly on top of it.
RemeshOptions remeshOptions(const RemeshArgs& a, const CLI::App& cmd) {
  const RemeshMethod method = parseRemeshMethod(a.method);
  RemeshOptions o;
  if (a.preset == "reference") o = referencePreset(method);
  else if (!a.preset.empty() && a.preset != "best")
    throw Error("unknown preset '" + a.preset + "' (best, reference)");
  o.method = method;
  if (cmd.count("--param")) o.param.method = parseParamMethod(a.param);
  if (cmd.count("--border")) o.param.border = parseBorder(a.border);
  if (cmd.count("--density")) o.density.kind = parseDensityKind(a.density);
  if (cmd.count("--alpha")) o.density.alpha = a.alpha;
  if (cmd.count("--beta")) o.density.beta = a.beta;
  if (cmd.count("--sites")) {
    if (method == RemeshMethod::Relocate)
      throw Error("--sites cannot be used with --method relocate, which moves the input's own "
                  "vertices");
    o.sites.fromInputVertices = false;
    o.sites.count = a.sites;
  }
  if (cmd.count("--solver")) o.lloyd.solver = parseCvtSolver(a.solver);
  if (cmd.count("--max-iterations")) o.lloyd.maxIterations = a.maxIterations;
  if (cmd.count("--distance-threshold")) o.lloyd.distanceThreshold = a.distanceThreshold;
  if (cmd.count("--percent-threshold")) o.lloyd.percentThreshold = a.percentThreshold;
  o.measureFidelity = !a.noFidelity;
  return o;
}

Mesh load(const std::string& path) {
  ReadResult read = readMesh(path);
  for (const std::string& note : read.notes) std::cerr << "note: " << note << "\n";
  return std::move(read.mesh);
}

int runRemesh(const RemeshArgs& a, const CLI::App& cmd) {
  const RemeshOptions options = remeshOptions(a, cmd);
  const Mesh input = load(a.input);
  const RemeshResult result = remesh(input, options, a.input);
  if (!a.output.empty()) writeMesh(result.output, a.output);
  if (!a.record.empty()) saveRecording(result.recording, a.record);
  if (a.json)
    std::cout << toJson(result, options).dump(2) << "\n";
  else
    std::cout << remeshReport(result, options);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Lloydscope: variational surface remeshing by weighted Lloyd relaxation"};
  app.require_subcommand(1);

  RemeshArgs r;
  CLI::App* remeshCmd = app.add_subcommand("remesh", "Remesh a disk-topology triangle mesh");
  remeshCmd->add_option("input", r.input, "Input mesh (OFF, OBJ or PLY)")->required();
  remeshCmd->add_option("-o,--output", r.output, "Output mesh (OFF, OBJ or PLY)");
  remeshCmd->add_option("--preset", r.preset,
                        "best (default) or reference: the report's settings (authalic, square "
                        "border, uniform density, input vertices as sites)");
  remeshCmd->add_option("--method", r.method, "relocate or retriangulate (default)");
  remeshCmd->add_option("--param", r.param,
                        "auto (default: lscm, or mean-value where lscm folds), authalic, conformal, mean-value, tutte or lscm");
  remeshCmd->add_option("--border", r.border, "square or circle (default), for the fixed-border methods");
  remeshCmd->add_option("--density", r.density, "uniform, area (default) or curvature");
  remeshCmd->add_option("--alpha", r.alpha, "curvature density: weight of |K|");
  remeshCmd->add_option("--beta", r.beta, "curvature density: weight of H^2");
  remeshCmd->add_option("--sites", r.sites, "number of vertices of the result")
      ->check(CLI::PositiveNumber);
  remeshCmd->add_option("--solver", r.solver,
                        "lbfgs (default: quasi-Newton, converges in far fewer iterations) or "
                        "lloyd (the reference's)");
  remeshCmd->add_option("--max-iterations", r.maxIterations, "at most this many Lloyd iterations")
      ->check(CLI::PositiveNumber);
  remeshCmd->add_option("--distance-threshold", r.distanceThreshold,
                        "a site moving less than this (fraction of the domain size) is still")
      ->check(CLI::PositiveNumber);
  remeshCmd->add_option("--percent-threshold", r.percentThreshold,
                        "converged when fewer than this % of the sites move")
      ->check(CLI::Range(0.0, 100.0));
  remeshCmd->add_option("--record", r.record, "Save every Lloyd iteration to this file");
  remeshCmd->add_flag("--json", r.json, "Print the results as one JSON object");
  remeshCmd->add_flag("--no-fidelity", r.noFidelity, "Skip the Hausdorff/RMS measurement");

  std::string metricsMesh, metricsReference;
  bool metricsJson = false;
  CLI::App* metricsCmd = app.add_subcommand("metrics", "Measure a mesh's quality");
  metricsCmd->add_option("mesh", metricsMesh, "Mesh to measure")->required();
  metricsCmd->add_option("--reference", metricsReference,
                         "Also measure Hausdorff and RMS distance to this mesh");
  metricsCmd->add_flag("--json", metricsJson, "Print JSON");

  std::string recordingPath;
  bool infoJson = false;
  CLI::App* infoCmd = app.add_subcommand("info", "Summarize a recording");
  infoCmd->add_option("recording", recordingPath, "Recording file (from remesh --record)")
      ->required();
  infoCmd->add_flag("--json", infoJson, "Print JSON");

  CLI11_PARSE(app, argc, argv);

  try {
    if (remeshCmd->parsed()) return runRemesh(r, *remeshCmd);
    if (metricsCmd->parsed()) {
      const Mesh mesh = load(metricsMesh);
      const QualityMetrics quality = measureQuality(mesh);
      Fidelity fidelity;
      const bool withReference = !metricsReference.empty();
      if (withReference) fidelity = measureFidelity(mesh, load(metricsReference));
      if (metricsJson) {
        nlohmann::json j = toJson(quality);
        if (withReference) j["fidelity"] = toJson(fidelity);
        std::cout << j.dump(2) << "\n";
      } else {
        std::cout << metricsReport(quality, withReference ? &fidelity : nullptr);
      }
      return 0;
    }
    if (infoCmd->parsed()) {
      const Recording recording = loadRecording(recordingPath);
      if (infoJson)
        std::cout << recordingSummary(recording).dump(2) << "\n";
      else
        std::cout << recordingReport(recording);
      return 0;
    }
  } catch (const Error& e) {
    std::cerr << "lloydscope: " << e.what() << "\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "lloydscope: internal error: " << e.what() << "\n";
    return 2;
  }
  return 0;
}
