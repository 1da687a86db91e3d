#include "bench.h"

#include "files.h"
#include "isotropic.h"
#include "mesh_io.h"
#include "pipeline.h"
#include "report.h"
#include "simplify.h"
#include "stopwatch.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <sstream>

namespace lloydscope {

namespace {

struct Row {
  std::string model, method;
  std::string failed;  // why the method gave no mesh, if it did not
  int size = 0, iterations = 0;
  double milliseconds = 0;  // the method's own work, measuring excluded
  QualityMetrics before, after;
  Fidelity fidelity;
  StageTimes stages;        // Lloydscope's rows only
};

Row lloydscopeRow(const std::string& model, int size, const std::string& method,
                  const Mesh& input, const RemeshOptions& options) {
  RemeshResult r;
  try {
    r = remesh(input, options, model);
  } catch (const Error& e) {  // one method failing on one input is a result, not the end
    Row row{model, method};
    row.size = size;
    row.failed = e.what();
    row.before = measureQuality(input);  // what it was given, as a row that ran says
    return row;
  }
  Row row{model, method, "", size, r.iterations};
  row.milliseconds = r.ms.total - r.ms.metrics;
  row.before = r.before;
  row.after = r.after;
  row.fidelity = r.fidelity;
  row.stages = r.ms;
  return row;
}

Row isotropicRow(const std::string& model, int size, const Mesh& input) {
  IsotropicOptions o;
  o.vertices = size;
  const IsotropicResult r = isotropicRemesh(input, o);
  Row row{model, "cgal isotropic", "", size, 10};
  row.milliseconds = r.milliseconds;
  row.before = measureQuality(input);
  row.after = measureQuality(r.mesh);
  row.fidelity = measureFidelity(r.mesh, input);
  return row;
}

// A CSV field: quoted where it holds a comma, a quote or a line break (a model's file name may),
// inner quotes doubled.
std::string csvField(const std::string& text) {
  if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

// A markdown table cell: '|' escaped, line breaks made spaces (a model's file name may hold them).
std::string cell(const std::string& text) {
  std::string escaped;
  for (char c : text) escaped += c == '|' ? std::string("\\|") : c == '\n' || c == '\r' ? std::string(" ") : std::string(1, c);
  return escaped;
}

std::string name(const std::string& path) {
  std::string n = path.substr(path.find_last_of('/') + 1);
  return n.substr(0, n.find_last_of('.'));
}

// The defaults' row of the stage table: the input's size, the time of each stage, CGAL's.
std::string stageTimesRow(const Row& row, const Row& peer) {
  std::string line = "| " + cell(row.model) + " | " + std::to_string(row.size) + " | " + std::to_string(row.before.vertices) +
                     " | " + std::to_string(row.before.faces) + " | ";
  if (!row.failed.empty()) {  // the stages' and the total's cells left empty
    line += "failed |";
    for (int cell = 0; cell < 8; ++cell) line += " |";
    return line + " " + format("%.0f", peer.milliseconds) + " |";
  }
  const StageTimes& t = row.stages;
  for (double ms : {t.simplify, t.cut, t.resample, t.parameterize, t.density + t.sites, t.lloyd, t.remesh, t.compared,
                    row.milliseconds, peer.milliseconds})
    line += format("%.0f", ms) + " | ";
  return line.substr(0, line.size() - 1);
}

// Issue 5's bar for a Lloydscope row, next to CGAL's row on the same input.
std::string verdict(const Row& row, const Row& peer) {
  if (!row.failed.empty()) return "failed: " + row.failed;
  std::string missed;
  if (row.after.irregularBoundaryAware > kMostIrregularPercent) missed += " irregular>15%";
  if (!meetsMinAngleBar(row.after, row.before)) missed += " min<30";
  if (row.after.avgMinAngle < kLeastAvgMinAngle) missed += " avg<53";
  if (row.fidelity.hausdorffPercent > peer.fidelity.hausdorffPercent) missed += " hausdorff>cgal";
  return missed.empty() ? "all met" : "missed:" + missed;
}

// Issue 5's four bars met, as verdict() counts them.
bool allBarsMet(const Row& row, const Row& peer) { return verdict(row, peer) == "all met"; }

// One line per method, over every model and size it ran on: the mean irregularity (border-aware)
// and its range, the smallest angle of all, the mean average smallest angle, the mean Hausdorff
// distance, the mean iterations and time, and on how many inputs all four bars are met: what
// each step of the defaults buys, the variants each leaving one out. `rows` holds each input's
// rows in turn, CGAL's last.
std::string methodSummary(const std::vector<Row>& rows) {
  struct Totals {
    int runs = 0, failed = 0, allMet = 0;
    double irregular = 0, leastIrregular = INFINITY, mostIrregular = 0, smallestAngle = INFINITY;
    double avgMinAngle = 0, hausdorff = 0, iterations = 0, milliseconds = 0;
  };
  std::vector<std::string> methods;
  std::map<std::string, Totals> totals;
  for (size_t first = 0; first < rows.size();) {
    size_t peer = first;  // CGAL's row closes each input's rows
    while (rows[peer].method != "cgal isotropic") ++peer;
    for (size_t i = first; i <= peer; ++i) {
      const Row& row = rows[i];
      if (!totals.count(row.method)) methods.push_back(row.method);
      Totals& t = totals[row.method];
      if (!row.failed.empty()) {
        ++t.failed;
        continue;
      }
      ++t.runs;
      t.allMet += allBarsMet(row, rows[peer]);
      t.irregular += row.after.irregularBoundaryAware;
      t.leastIrregular = std::min(t.leastIrregular, row.after.irregularBoundaryAware);
      t.mostIrregular = std::max(t.mostIrregular, row.after.irregularBoundaryAware);
      t.smallestAngle = std::min(t.smallestAngle, row.after.minAngle);
      t.avgMinAngle += row.after.avgMinAngle;
      t.hausdorff += row.fidelity.hausdorffPercent;
      t.iterations += row.iterations;
      t.milliseconds += row.milliseconds;
    }
    first = peer + 1;
  }
  std::string table =
      "| method | runs | irregular % (b-aware), mean (range) | min angle, of all | avg min angle, mean | "
      "Hausdorff %, mean | iterations, mean | ms, mean | all four bars met |\n"
      "|---|---|---|---|---|---|---|---|---|\n";
  for (const std::string& method : methods) {
    const Totals& t = totals[method];
    std::string runs = std::to_string(t.runs);
    if (t.failed > 0) runs += " of " + std::to_string(t.runs + t.failed);
    if (t.runs == 0) {
      table += "| " + method + " | " + runs + " | | | | | | | 0 |\n";
      continue;
    }
    const double n = t.runs;
    table += "| " + method + " | " + runs + " | " +
             format("%.1f (%.1f-%.1f)", t.irregular / n, t.leastIrregular, t.mostIrregular) + " | " +
             format("%.1f", t.smallestAngle) + " | " + format("%.2f", t.avgMinAngle / n) + " | " +
             format("%.3f", t.hausdorff / n) + " | " + format("%.0f", t.iterations / n) + " | " +
             format("%.0f", t.milliseconds / n) + " | " + std::to_string(t.allMet) + " |\n";
  }
  return table;
}

// The defaults changed one way each, to show what that step buys: on a prepared input, the
// polish, the snaps, the fit, the solver, the first pass, the method (the input's own vertices
// moved, its triangles kept) and the report's preset; on a model
// as it comes, simplifying it first (the others would take minutes on a large input).
std::vector<std::pair<std::string, RemeshOptions>> variants(const RemeshOptions& defaults,
                                                            const BenchOptions& options) {
  std::vector<std::pair<std::string, RemeshOptions>> all;
  const auto add = [&](const std::string& flags, const std::function<void(RemeshOptions&)>& change) {
    RemeshOptions o = defaults;
    change(o);
    all.emplace_back(flags, o);
  };
  if (options.asIs) {
    add("--full-input", [](RemeshOptions& o) { o.coarsenInput = false; });
    return all;
  }
  add("--polish -1", [](RemeshOptions& o) { o.polish = -1; });
  add("--no-snap", [](RemeshOptions& o) { o.snapToTips = false; });
  add("--no-fit", [](RemeshOptions& o) { o.fit = false; });
  add("--solver newton", [](RemeshOptions& o) { o.lloyd.solver = CvtSolver::Newton; });
  add("--no-resample", [](RemeshOptions& o) { o.resample = false; });
  add("--method relocate", [](RemeshOptions& o) { o.method = RemeshMethod::Relocate; });
  if (options.reference)
    all.emplace_back("--preset reference", referencePreset(RemeshMethod::Retriangulate));
  return all;
}

// The main table: every row, the report's Tables I and II before and after, and the distances.
void printRows(const std::vector<Row>& rows) {
  std::cout << "| model | size | method | vertices | faces | iterations | ms | irregular % (b-aware) "
               "| min angle | avg min angle | < 30 deg % | Hausdorff % | RMS % |\n"
               "|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const Row& r : rows)
    if (!r.failed.empty())
      std::cout << "| " << cell(r.model) << " | " << r.size << " | " << r.method << " | failed: "
                << cell(r.failed) << " ||||||||||\n";  // and the nine cells after it, empty
    else
      std::cout << "| " << cell(r.model) << " | " << r.size << " | " << r.method << " | "
              << r.after.vertices << " | " << r.after.faces << " | " << r.iterations << " | "
              << format("%.0f", r.milliseconds) << " | "
              << format("%.1f", r.before.irregularBoundaryAware) << " -> "
              << format("%.1f", r.after.irregularBoundaryAware) << " | "
              << format("%.1f", r.before.minAngle) << " -> " << format("%.1f", r.after.minAngle)
              << " | " << format("%.1f", r.before.avgMinAngle) << " -> "
              << format("%.1f", r.after.avgMinAngle) << " | "
              << format("%.1f", r.after.percentUnder30) << " | "
              << format("%.3f", r.fidelity.hausdorffPercent) << " | "
              << format("%.3f", r.fidelity.rmsPercent) << " |\n";
}

// Every row with its stage times, for a spreadsheet.
std::string csvText(const std::vector<Row>& rows) {
  std::ostringstream csv;
  csv << "model,size,method,vertices,faces,vertices_before,faces_before,iterations,ms,irregular_before,irregular_after,"
         "irregular_all_after,min_angle_before,min_angle_after,avg_min_angle_before,"
         "avg_min_angle_after,under30_percent,hausdorff_percent,rms_percent,ms_simplify,ms_cut,ms_resample,"
         "ms_parameterize,ms_density,ms_sites,ms_lloyd,ms_remesh,ms_other_way,failed\n";
  for (const Row& r : rows) {
    // A failed row's results, and CGAL's stages, are empty, as in the markdown: zeros were
    // averaged in as results by a spreadsheet.
    const bool ran = r.failed.empty(), staged = ran && r.method.rfind("lloydscope", 0) == 0;
    const auto of = [](bool known, double value) {
      std::ostringstream field;
      if (known) field << value;
      return field.str();
    };
    csv << csvField(r.model) << "," << r.size << "," << r.method << "," << of(ran, r.after.vertices) << ","
        << of(ran, r.after.faces) << "," << r.before.vertices << "," << r.before.faces << "," << of(ran, r.iterations) << ","
        << of(ran, r.milliseconds) << "," << r.before.irregularBoundaryAware << "," << of(ran, r.after.irregularBoundaryAware)
        << "," << of(ran, r.after.irregularPercent) << "," << r.before.minAngle << "," << of(ran, r.after.minAngle) << ","
        << r.before.avgMinAngle << "," << of(ran, r.after.avgMinAngle) << "," << of(ran, r.after.percentUnder30) << ","
        << of(ran, r.fidelity.hausdorffPercent) << "," << of(ran, r.fidelity.rmsPercent) << ",";
    for (double ms : {r.stages.simplify, r.stages.cut, r.stages.resample, r.stages.parameterize, r.stages.density,
                      r.stages.sites, r.stages.lloyd, r.stages.remesh, r.stages.compared})
      csv << of(staged, ms) << ",";
    csv << csvField(r.failed) << "\n";
  }
  return csv.str();
}

// The models to run: those given, or CGAL's disk samples that ./build.sh extracted.
std::vector<std::string> benchModels(const BenchOptions& options) {
  std::vector<std::string> models = options.models;
  if (models.empty())
    for (const char* sample : {"nefertiti", "mushroom", "three_peaks", "lion-head", "mannequin-devil"}) {
      const std::string path = std::string(LLOYDSCOPE_SOURCE_DIR) + "/data/cgal/" + sample + ".off";
      if (std::ifstream(path).good()) models.push_back(path);
    }
  if (models.empty())
    throw Error("bench: no models (give mesh files, or run ./build.sh to extract CGAL's samples)");
  return models;
}

std::string savedInputPath(const BenchOptions& options, const std::string& model, int size) {
  return options.saveInputs + "/" + name(model) + "_" + std::to_string(size) + ".off";
}

// The CSV's folder checked, and a CSV or prepared input that would replace a model (a_30.off,
// saving a.off at 30), a CSV under a mesh's name, a CSV onto a prepared input, or two models of
// one name saved onto each other, refused: before any model is run, so that a bad one fails in a moment, not after
// minutes of the others' work.
void checkOutputs(const BenchOptions& options, const std::vector<std::string>& models) {
  requireWritable(options.csv);
  for (const std::string& path : models)
    if (sameFile(options.csv, path)) throw Error(options.csv + ": --csv would replace the input mesh; give it another name");
  if (!options.saveInputs.empty()) {
    makeFolder(options.saveInputs);
    for (const std::string& path : models)
      for (int size : options.sizes) {
        const std::string saved = savedInputPath(options, path, size);
        if (sameFile(saved, options.csv)) throw Error(saved + ": --csv and --save-inputs name the same file; give them two");
        for (const std::string& other : models) {
          if (sameFile(saved, other))
            throw Error(saved + ": --save-inputs would replace the input mesh " + other + "; save them elsewhere");
          if (other != path && name(other) == name(path))
            throw Error(path + " and " + other + ": --save-inputs would save both as " + saved + "; rename one");
        }
      }
  }
  requireNoMeshExtension(options.csv, "the table", ".csv");  // any other mesh
}

}  // namespace

void runBench(const BenchOptions& options) {
  const std::vector<std::string> models = benchModels(options);
  checkOutputs(options, models);  // and every model read (and validated) below, before any is run
  std::vector<Mesh> meshes;
  for (const std::string& path : models) {
    ReadResult read = readMesh(path, ReadOptions{options.repair});
    for (const std::string& note : read.notes) std::cerr << "note: " << note << "\n";
    meshes.push_back(std::move(read.mesh));
  }

  std::vector<Row> rows;
  std::ostringstream verdicts, stages;
  for (size_t m = 0; m < models.size(); ++m) {
    const std::string& path = models[m];
    const Mesh& model = meshes[m];
    for (int size : options.sizes) {
      const Mesh input = options.asIs ? model : benchInput(model, size, path);
      if (!options.saveInputs.empty())
        writeMesh(input, savedInputPath(options, path, size));
      const Row peer = isotropicRow(name(path), size, input);
      RemeshOptions defaults;  // a prepared input has the size already
      if (options.asIs) defaults.sites.count = size;
      const Row best = lloydscopeRow(name(path), size, "lloydscope", input, defaults);
      rows.push_back(best);
      for (const auto& [flags, variant] : variants(defaults, options))
        rows.push_back(lloydscopeRow(name(path), size, "lloydscope " + flags, input, variant));
      rows.push_back(peer);
      verdicts << "| " << cell(name(path)) << " | " << size << " | "
               << (best.failed.empty() ? format("%.2f", best.milliseconds / peer.milliseconds) : "-")
               << " | "
               << verdict(best, peer) << " |\n";
      stages << stageTimesRow(best, peer) << "\n";
      std::cerr << name(path) << " " << size << " done\n";
    }
  }

  printRows(rows);
  std::cout << "\nLloydscope (defaults) against CGAL on the same input: time ratio (<= 1 is the "
               "target) and the quality bar (irregular <= 15%, min >= 30 but at the input's own border "
               "corners sharper than that, avg >= 53, Hausdorff <= CGAL's)\n\n"
               "| model | size | time ratio | quality |\n|---|---|---|---|\n"
            << verdicts.str();
  std::cout << "\nWhere the time goes: the input (the report's Table I before), then Lloydscope's stages "
               "(defaults, ms) and CGAL's whole run. The other way: the runs a result was compared with "
               "and not kept (a nearly closed disk is made slit and whole, alongside, so the total is "
               "less than the sum; a result that misses a bar is made again without the first pass, "
               "then chart by chart)\n\n"
               "| model | size | input vertices | input faces | simplify | cut | resample | parameterize | "
               "density, sites | lloyd | remesh | the other way | total | cgal |\n"
               "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n"
            << stages.str();
  std::cout << "\nEach method over every input (the defaults, each variant leaving one step out, CGAL's "
               "remesher): what each step buys\n\n"
            << methodSummary(rows);

  const std::string csv = csvText(rows);
  writeAtomically(options.csv, [&](std::ostream& out) { out << csv; });
  std::cout << "\nCSV: " << options.csv << "\n";
}

// Iteration 0 searches without hints and sorts the sites; iterations 1.. are timed.
constexpr int kStepIterations = 11;

void runStepBench(const BenchOptions& options) {
  const std::string path = options.models.empty()
                               ? std::string(LLOYDSCOPE_SOURCE_DIR) + "/assets/bumpy_disk.off"
                               : options.models.front();
  ReadResult read = readMesh(path, ReadOptions{options.repair});
  for (const std::string& note : read.notes) std::cerr << "note: " << note << "\n";
  const Mesh input = std::move(read.mesh);
  // What recording every iteration costs, in a file of its own: "<csv>.lsrec" replaced and then
  // deleted a user's file of that name (or wrote through a link of that name).
  const TemporaryFile file(".lsrec");
  Recording recording;
  std::cout << "| sites | density | threads | median ms per iteration | µs per site, median | "
               "µs per site, best |\n|---|---|---|---|---|---|\n";
  for (DensityKind density : {DensityKind::Uniform, DensityKind::Area})
    for (int threads : {1, 0}) {
      RemeshOptions o;
      o.sites.count = options.stepSites;
      o.density.kind = density;
      o.lloyd.solver = CvtSolver::Lloyd;
      o.lloyd.threads = threads;
      o.lloyd.maxIterations = kStepIterations;
      o.polish = -1;
      o.measureFidelity = false;
      RemeshSession session(input, o, path);
      std::vector<double> ms;
      for (int k = 0; k < kStepIterations; ++k) {
        const double t = session.step().milliseconds;
        if (k > 0) ms.push_back(t);
      }
      std::sort(ms.begin(), ms.end());
      const double median = ms[ms.size() / 2];
      std::cout << "| " << options.stepSites << " | " << toString(density) << " | "
                << (threads == 0 ? std::string("all") : std::to_string(threads)) << " | "
                << format("%.1f", median) << " | "
                << format("%.2f", 1000.0 * median / options.stepSites) << " | "
                << format("%.2f", 1000.0 * ms.front() / options.stepSites) << " |\n";
      if (density == DensityKind::Area && threads == 0) recording = session.finish().recording;
    }
  // What recording every iteration costs, in memory and in a file, and reading it back.
  saveRecording(recording, file.path());
  std::ifstream in(file.path(), std::ios::binary | std::ios::ate);
  const double fileBytes = static_cast<double>(in.tellg());
  Stopwatch load;
  const Recording loaded = loadRecording(file.path());
  const double loadMs = load.lap();
  double memoryBytes = 0, readMs = 0;
  for (const IterationRecord& it : loaded.iterations) {
    memoryBytes += sizeof(std::uint32_t) * it.sites.raw().size() + sizeof(IterationRecord);
    Stopwatch read;
    const std::vector<Vec2> sites = allSites(loaded.fixedSites, it.sites);
    readMs = std::max(readMs, read.lap());
  }
  const double perSiteIteration =
      double(recording.iterations.size()) * (recording.fixedSites.size() + recording.iterations[0].sites.size());
  std::cout << "\n| recording | bytes per site per iteration, memory | file (with the mesh) | "
               "ms to read an iteration, worst | ms to load the file |\n|---|---|---|---|---|\n"
            << "| " << recording.iterations.size() << " iterations of " << options.stepSites
            << " sites | " << format("%.2f", memoryBytes / perSiteIteration) << " | "
            << format("%.2f", fileBytes / perSiteIteration) << " | " << format("%.2f", readMs)
            << " | " << format("%.0f", loadMs) << " |\n";
}

}  // namespace lloydscope
