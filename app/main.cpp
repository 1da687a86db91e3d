// lloydscope: the command line. Every command runs headless; errors are one line on stderr.
#include "bench.h"
#include "files.h"
#include "gpu.h"
#include "headless.h"
#include "mesh_io.h"
#include "window.h"
#include "pipeline.h"
#include "png.h"
#include "report.h"
#include "simplify.h"

#include <CLI/CLI.hpp>

#include <malloc.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <limits>

using namespace lloydscope;

namespace {

struct RemeshArgs {
  std::string input, output, record, preset, method = "retriangulate", param, border, density,
      solver, polishTarget;
  int sites = 0, simplify = 0, polish = 3;
  int maxIterations = 0;
  double distanceThreshold = 0, percentThreshold = 0, alpha = 1, beta = 1, floor = 0.1;
  bool json = false, noFidelity = false, noResample = false, noSnap = false, noFit = false, noSlit = false,
       fullInput = false, repair = false;
};

// An option the run would ignore is said, a note on stderr each: --alpha without the curvature
// density, the polish's options with relocate, and the like were accepted and did nothing.
void noteIgnoredOptions(const CLI::App& cmd, const RemeshOptions& o) {
  const bool relocate = o.method == RemeshMethod::Relocate, noPolish = relocate || o.polish <= 0;
  const char* curvatureOnly = "it shapes the curvature density (--density curvature)";
  const char* retriangulateOnly = "it is retriangulate's, and relocate keeps the input's own triangles";
  const struct {
    const char* option;
    bool ignored;
    const char* why;
  } rules[] = {{"--alpha", o.density.kind != DensityKind::Curvature, curvatureOnly},
               {"--beta", o.density.kind != DensityKind::Curvature, curvatureOnly},
               {"--floor", o.density.kind != DensityKind::Curvature, curvatureOnly},
               {"--border", o.param.method == ParamMethod::Lscm, "LSCM's border is free"},
               {"--polish", relocate, retriangulateOnly},
               {"--polish-target", noPolish, "it is the polish's, and there is no polish to relax with"},
               {"--no-snap", noPolish, "the snaps follow the polish, and there is no polish"},
               {"--no-fit", relocate, retriangulateOnly},
               {"--no-resample", relocate, "relocate parameterizes the input itself always"},
               {"--no-slit", relocate, "relocate keeps the input's own triangles, a disk never slit"},
               {"--full-input", relocate || o.simplifyTo > 0 || o.sites.count <= 0,
                "only a run asking --sites of a larger input simplifies it first (not one with "
                "--simplify, nor relocate)"}};
  for (const auto& rule : rules)
    if (rule.ignored && cmd.count(rule.option) > 0)
      std::cerr << "note: " << rule.option << " has no effect here: " << rule.why << "\n";
}

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
  if (cmd.count("--floor")) o.density.floor = a.floor;
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
  o.simplifyTo = a.simplify;
  if (cmd.count("--polish")) o.polish = a.polish;
  if (a.noResample) o.resample = false;
  if (a.noSnap) o.snapToTips = false;
  if (a.noFit) o.fit = false;
  if (a.noSlit) o.slitDisks = false;
  if (a.fullInput) o.coarsenInput = false;
  if (cmd.count("--polish-target")) o.polishTarget = parsePolishTarget(a.polishTarget);
  noteIgnoredOptions(cmd, o);
  return o;
}

// The recording, the output and the input are three files: --record onto the input or the
// output replaced it with a recording, silently, and -o onto the input replaced it with the
// result (as --record onto it is refused, so is that: the input is the user's to keep).
void refuseSameFile(const RemeshArgs& a) {
  if (sameFile(a.output, a.input)) throw Error(a.output + ": --output would replace the input mesh; give it another name");
  if (sameFile(a.record, a.input)) throw Error(a.record + ": --record would replace the input mesh; give it another name");
  if (sameFile(a.record, a.output)) throw Error(a.record + ": --record and --output name the same file; give them two");
}

// An error as it is printed: one line, a line break in a file name or a value shown as \n, and
// any other control character as \xNN (an escape sequence in a name reached the terminal, a
// form feed or a vertical tab broke the line there), UTF-8's C1 controls (U+0080-U+009F, a CSI
// among them) too.
std::string oneLine(const std::string& message) {
  std::string line;
  const auto escape = [&](unsigned char byte) {
    char escaped[8];
    std::snprintf(escaped, sizeof escaped, "\\x%02x", byte);
    line += escaped;
  };
  for (size_t i = 0; i < message.size(); ++i) {
    const char c = message[i];
    const auto byte = static_cast<unsigned char>(c);
    const bool c1 = byte == 0xc2 && i + 1 < message.size() && (static_cast<unsigned char>(message[i + 1]) & 0xe0) == 0x80;
    if (c == '\n') {
      line += "\\n";
    } else if (c == '\r') {
      line += "\\r";
    } else if ((byte < 0x20 && c != '\t') || byte == 0x7f) {
      escape(byte);
    } else if (c1) {
      escape(byte);
      escape(static_cast<unsigned char>(message[++i]));
    } else {
      line += c;
    }
  }
  return line;
}

// What to add to a command-line error where a file's name starts with '-': CLI11 takes it
// for an option, and said only "mesh is required".
std::string dashedFileHint(int argc, char** argv) {
  for (int k = 1; k < argc; ++k) {
    const std::string arg = argv[k];
    if (arg == "--") break;  // what follows is read as names already
    std::error_code ignored;
    if (arg.size() > 1 && arg[0] == '-' && std::filesystem::exists(arg, ignored))
      return "; '" + arg + "' was read as an option: write ./" + arg + " for the file";
  }
  return {};
}

// JSON as the commands print it; bytes of a file name that are not UTF-8 become U+FFFD (they
// made dump() throw, an "internal error" after the run's files were written).
std::string printable(const nlohmann::json& j) { return j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace); }

Mesh load(const std::string& path, bool repair) {
  ReadResult read = readMesh(path, ReadOptions{repair});
  for (const std::string& note : read.notes) std::cerr << "note: " << note << "\n";
  return std::move(read.mesh);
}

// Before a simplification that would seem to hang: CGAL's edge collapse takes time cubic in the
// triangles around a vertex (a hub of 3000: half a minute; kMostTrianglesAroundAVertexToSimplify).
void noteASlowSimplification(const Mesh& mesh, const std::string& name) {
  const int around = mostTrianglesAroundAVertex(mesh);
  if (around > kMostTrianglesAroundAVertexToSimplify)
    std::cerr << "note: " << name << ": one vertex has " << around
              << " triangles around it, and simplifying takes time cubic in that number (seconds at 1000, half a "
                 "minute at 3000)\n";
}

// The mesh to remesh with `o` (remesh, inspect and bench-frames alike), noting --simplify over its
// size where its own vertices are the sites (relocate, the report's preset): there is nothing
// to coarsen, and no vertex is added (the result had the input's 500 for the 1000 asked, said
// nowhere, and the report blamed the clean-up).
Mesh loadToRemesh(const RemeshArgs& a, const RemeshOptions& o) {
  Mesh input = load(a.input, a.repair);
  const bool relocate = o.method == RemeshMethod::Relocate;
  if ((relocate || o.sites.fromInputVertices) && o.simplifyTo > input.vertexCount())
    std::cerr << "note: --simplify " << o.simplifyTo << " has no effect here: the input has " << input.vertexCount()
              << " vertices, and they are the sites (" << (relocate ? "relocate moves them" : "the report's preset starts from them")
              << ")\n";
  else if (o.simplifyTo > 0 && simplifyCollapses(input, {o.simplifyTo}, a.input))
    noteASlowSimplification(input, a.input);
  return input;
}

int runRemesh(const RemeshArgs& a, const CLI::App& cmd) {
  const RemeshOptions options = remeshOptions(a, cmd);
  // Where the files cannot be saved, say so now, not after minutes of work.
  if (!a.output.empty()) requireMeshWritable(a.output);
  refuseSameFile(a);
  // After the refusals that say more (onto the input, onto the output).
  if (!a.record.empty()) requireRecordingName(a.record), requireWritable(a.record);
  const Mesh input = loadToRemesh(a, options);
  const RemeshResult result = remesh(input, options, a.input);
  // Both or neither: where either cannot be written, neither file there is replaced (the output
  // was, then the recording failed; the other way round, the recording was).
  FileBatch files;
  if (!a.record.empty()) saveRecording(result.recording, a.record, files);
  if (!a.output.empty()) writeMesh(result.output, a.output, files);
  files.commit();
  if (a.json)
    std::cout << printable(toJson(result, options)) << "\n";
  else
    std::cout << remeshReport(result, options);
  return 0;
}

void addRepairFlag(CLI::App& cmd, bool& repair) {
  cmd.add_flag("--repair", repair,
               "Weld vertices at the same position (an unwelded seam), remove faces of zero area, "
               "turn faces that face the other way; a note says what changed (by default such an "
               "input is refused)");
}

// A number from `low` to `high`, not "nan" or "inf" (CLI11's PositiveNumber and Range let NaN
// through: every comparison with it is false).
CLI::Validator finiteNumber(double low, const std::string& expected,
                            double high = std::numeric_limits<double>::max()) {
  return CLI::Validator(
      [=](std::string& text) -> std::string {
        double value = 0;
        if (CLI::detail::lexical_cast(text, value) && std::isfinite(value) && value >= low && value <= high) return "";
        return "expected " + expected + ", not '" + text + "'";
      },
      expected.substr(expected.find(' ') + 1));  // "number from 0.5 to 4" in the help, not "NUMBER"
}
// A whole number from `low` up (CLI11's Range said "Value abc not in range" of a word).
CLI::Validator wholeNumber(int low, int high = std::numeric_limits<int>::max()) {
  const bool bounded = high < std::numeric_limits<int>::max();
  const std::string range = bounded ? "from " + std::to_string(low) + " to " + std::to_string(high)
                                    : ">= " + std::to_string(low);
  // An unbounded count still ends where an int does: "expected a whole number >= 1, not
  // '99999999999'" read as if the number were too small.
  const std::string tooLarge = "from " + std::to_string(low) + " to " + std::to_string(high);
  return CLI::Validator(
      [=](std::string& text) -> std::string {
        // Decimal digits only: CLI11 reads "0x20" as 32 and "1e3" not at all.
        const bool decimal = !text.empty() && text.find_first_not_of("0123456789", text[0] == '-') == std::string::npos &&
                             text != "-";
        long long value = 0;
        const bool read = decimal && CLI::detail::lexical_cast(text, value);
        if (read && value >= low && value <= high) return "";
        const bool large = decimal && text[0] != '-' && (!read || value > high);
        return "expected a whole number " + (large ? tooLarge : range) + ", not '" + text + "'";
      },
      bounded ? std::to_string(low) + ".." + std::to_string(high) : ">= " + std::to_string(low));
}
const CLI::Validator kPositiveCount = wholeNumber(1);
// A value given empty (`-o ''`, an unset variable) was taken as none given: the run wrote no
// file, saved no inputs (--save-inputs), one picture (--iterations), the default size or view.
CLI::Validator nonEmpty(const std::string& expected, const std::string& name = "") {
  return CLI::Validator(
      [expected](std::string& text) -> std::string { return text.empty() ? "expected " + expected + ", not an empty one" : ""; },
      name);
}
const CLI::Validator kFileName = nonEmpty("a file name", "FILE");
// The vertices a run is asked for (core/sites); the most relaxation passes it polishes with
// (the default is 3) and frames bench-frames times: more is a slip of the keyboard that would
// run for hours.
const CLI::Validator kVerticesAsked = wholeNumber(kSmallestRemeshedShare, kMostRemeshedVertices);
constexpr int kMostFrames = 100000;

// The options that say how a mesh is remeshed, under a heading of their own in the help: a
// recording, which replays its own run, refuses them (refuseRemeshingOptions).
constexpr const char* kRemeshing = "Remeshing";

// " (default 1e-06)": an option's help says its default, taken from the options themselves.
std::string defaultIs(double value) {
  std::ostringstream text;
  text << " (default " << value << ")";
  return text.str();
}

void addRemeshOptions(CLI::App& cmd, RemeshArgs& r) {
  cmd.option_defaults()->group(kRemeshing);
  cmd.add_option("--polish", r.polish,
                 "retriangulate's clean-up in 3D: -1 none, 0 Delaunay flips, K flips and K "
                 "relaxation passes on the surface (default 3)")
      ->check(wholeNumber(-1, kMostPolishPasses));
  cmd.add_option("--polish-target", r.polishTarget,
                 "where the polish moves each vertex: centroid (default: of its ring's triangles), "
                 "voronoi (of its Voronoi cell in its ring) or circumcenter (optimal Delaunay)");
  cmd.add_option("--simplify", r.simplify,
                 "Quadric edge collapse to N vertices first (the border stays the border), and "
                 "N vertices in the result (a coarser input is remeshed finer)")
      ->check(kVerticesAsked);
  cmd.add_option("--preset", r.preset,
                 "best (default) or reference: the report's settings (authalic, square border, "
                 "uniform density, input vertices as sites, plain Lloyd)")
      ->check(nonEmpty("best or reference"));
  cmd.add_option("--method", r.method, "relocate or retriangulate (default)");
  cmd.add_option("--param", r.param,
                 "auto (default: lscm, or mean-value where lscm folds, on a rectangle where the border has four "
                 "corners, then on --border), authalic, conformal, "
                 "mean-value, tutte or lscm");
  cmd.add_option("--border", r.border,
                 "square, circle (default) or rectangle (for a border with four corners, as a strip's: its sides as "
                 "long as the border between them), for the fixed-border methods");
  cmd.add_option("--density", r.density, "uniform, area (default) or curvature");
  const DensityOptions density;
  const LloydOptions lloyd;
  cmd.add_option("--alpha", r.alpha, "curvature density: weight of |K|" + defaultIs(density.alpha))->check(finiteNumber(0, "a number >= 0"));
  cmd.add_option("--beta", r.beta, "curvature density: weight of H^2" + defaultIs(density.beta))->check(finiteNumber(0, "a number >= 0"));
  cmd.add_option("--floor", r.floor, "curvature density: added everywhere, in units of the mean curvature term (larger: more uniform)" +
                     defaultIs(density.floor))
      ->check(finiteNumber(0, "a number >= 0"));
  cmd.add_option("--sites", r.sites, "number of vertices of the result (the clean-up may add or remove a few: the report says; "
                 "default: as many as the input has)")
      ->check(kVerticesAsked);
  cmd.add_option("--solver", r.solver,
                 "lbfgs (default: quasi-Newton, converges in far fewer iterations), lloyd (the "
                 "reference's) or newton (exact Hessian: fewer iterations still, each dearer)");
  cmd.add_option("--max-iterations", r.maxIterations, "at most this many iterations of the solver (--solver: Lloyd's, L-BFGS's or Newton's steps)" + defaultIs(lloyd.maxIterations))
      ->check(wholeNumber(1, kMostIterations));
  cmd.add_option("--distance-threshold", r.distanceThreshold,
                 "a site farther than this from its centroid (a fraction of the domain's size) is still "
                 "moving" + defaultIs(lloyd.distanceThreshold))
      // Any number above 0, as the message says (1e-310, under the smallest normal double, was
      // refused as not > 0) and as a recording and the inspector's settings take.
      ->check(finiteNumber(std::numeric_limits<double>::denorm_min(), "a number > 0"));
  cmd.add_option("--percent-threshold", r.percentThreshold,
                 "converged when fewer than this % of the sites are still moving (0: never, the run goes on to "
                 "--max-iterations)" + defaultIs(lloyd.percentThreshold))
      ->check(finiteNumber(0, "a percentage from 0 to 100", 100));
  cmd.add_flag("--no-resample", r.noResample,
               "Parameterize the input itself, not a rough first remeshing of it");
  cmd.add_flag("--no-snap", r.noSnap,
               "Leave out the first step after the polish, which snaps a vertex onto each thin tip of "
               "the input the result would cut off");
  cmd.add_flag("--no-fit", r.noFit,
               "Leave out the fit: by default retriangulate's last step moves the vertices along their "
               "normals, and the border's across the border, so that the result lies closer to the "
               "input, angles kept. Without it every vertex stays on the input, or, where the input was "
               "simplified first (--simplify, or a large input), on it or on that simplification");
  cmd.add_flag("--no-slit", r.noSlit,
               "Keep a nearly closed disk whole (by default it is also remeshed slit open, and the "
               "result meeting more of the quality bars kept; where both meet them, the closer to the "
               "input; else the larger average smallest angle)");
  cmd.add_flag("--full-input", r.fullInput,
               "Remesh a large input as it is (by default it is simplified first to 10 vertices per "
               "vertex asked, but to no more than 10,000 or 5 per vertex asked, whichever is larger; "
               "the last steps and the distances are against the input itself either way)");
  cmd.add_flag("--no-fidelity", r.noFidelity, "Skip the Hausdorff/RMS measurement");
  addRepairFlag(cmd, r.repair);
  cmd.option_defaults()->group("Options");
}

// A recording is replayed with the settings it was made with: an option that would remesh, or
// show the final result it lacks, is refused, not shown as if it had been used (--solver newton
// relabelled an L-BFGS run; --final was ignored).
void refuseRemeshingOptions(const CLI::App& cmd, const std::string& recording) {
  for (const CLI::Option* option : cmd.get_options())
    if (option->get_group() == kRemeshing && option->count() > 0)
      throw Error(recording + ": " + option->get_name() +
                  " applies to a mesh; a recording replays its own run, with the settings it was made with "
                  "(lloydscope info shows them)");
  // The final result is the clean-up's, made after the last iteration: a recording does not hold it.
  if (const CLI::Option* final = cmd.get_option_no_throw("--final"); final && final->count() > 0)
    throw Error(recording + ": --final applies to a mesh; a recording holds the iterations of its run, "
                "not the final result (remesh -o writes that)");
}

// "A<separator>B", digits alone on both sides (no sign, no space: " 0:5" and " 960x600" were
// taken by one parser and not the other); nullopt for any other form. A side too large for a
// long long reads as its largest, which every range asked refuses.
std::optional<std::pair<long long, long long>> digitsPair(const std::string& text, char separator) {
  const size_t at = text.find(separator);
  if (at == std::string::npos) return std::nullopt;
  const auto side = [](std::string_view digits) -> std::optional<long long> {
    if (digits.empty() || digits.find_first_not_of("0123456789") != std::string_view::npos) return std::nullopt;
    long long value = 0;
    if (std::from_chars(digits.data(), digits.data() + digits.size(), value).ec != std::errc())
      return std::numeric_limits<long long>::max();
    return value;
  };
  const auto a = side(std::string_view(text).substr(0, at)), b = side(std::string_view(text).substr(at + 1));
  if (!a || !b) return std::nullopt;
  return std::make_pair(*a, *b);
}

// "1280x800" -> width, height, within the sizes renderScreenshot() takes (bench-frames took
// any: 100000x100000 went on to ask Vulkan for 40 GB).
void parseSize(const std::string& text, int& width, int& height) {
  if (text.empty()) return;
  const auto size = digitsPair(text, 'x');
  if (!size) throw Error("--size must look like 1280x800, not '" + text + "'");
  const auto [w, h] = *size;
  if (!pictureSizeAllowed(w, h)) throw Error("--size must be " + pictureSizes() + ", not '" + text + "'");
  width = static_cast<int>(w);
  height = static_cast<int>(h);
}

// A mesh is remeshed first (and kept in `input`); a recording is replayed as it is.
RemeshResult openForInspection(const RemeshArgs& a, const CLI::App& cmd, RemeshOptions& options,
                               std::optional<Mesh>* input = nullptr) {
  const std::string& in = a.input;
  // By its name (as the mesh formats are, in any case: a damaged x.LSREC was told to be opened
  // with inspect), or by its first bytes where it was saved under another (--record takes any but a mesh's).
  // Its refusal of the remeshing options comes before they are read: notes that they had no
  // effect came first, and an unknown --param value's error instead.
  if (lowercaseExtension(in) == ".lsrec" || isRecording(in)) {
    refuseRemeshingOptions(cmd, in);
    RecordedRun run = recordedRun(loadRecording(in));  // its settings checked there
    options = run.options;
    return std::move(run.result);
  }
  // A recording saved as run.rec and cut short was refused for its "unknown extension '.rec'".
  if (!isMeshExtension(lowercaseExtension(in)) && std::filesystem::is_regular_file(in))
    throw Error(in + ": neither a mesh (.off, .obj or .ply) nor a Lloydscope recording (its first bytes are not a "
                     "recording's: another file, or a recording cut short or damaged)");
  options = remeshOptions(a, cmd);
  Mesh mesh = loadToRemesh(a, options);
  RemeshResult result = remesh(mesh, options, in);
  if (result.recording.iterations.empty())  // the panes show iterations (it crashed)
    throw Error(in + ": nothing to show: no iteration was run (" + kNoIterationWhy + ")");
  if (input) *input = std::move(mesh);
  return result;
}

// glibc hands the top of its heap back to the system whenever 128 KiB are free there, and the
// pipeline frees and takes again tens of megabytes (sparse systems, search trees, sample sets)
// many times a run: each time taken again, the pages fault in anew (7% of a run's time in the
// kernel on the face scan). Kept, the face and the camel head at 1000 vertices take 15-20%
// less time.
void keepFreedMemory() {
  mallopt(M_TRIM_THRESHOLD, 512 << 20);
  mallopt(M_TOP_PAD, 64 << 20);
}

// What a command printed was lost where the standard output could not take it (a full disk,
// a closed stream): said, with exit code 1, not 0 with the file the user asked for empty.
int withOutputChecked(int code) {
  if (std::cout.flush()) return code;
  std::cerr << "lloydscope: the standard output could not be written (a full disk, or a closed stream)\n";
  return code == 0 ? 1 : code;
}

// One struct a command: its arguments, the options that fill them (add) and its work (run).

struct RemeshCommand {
  CLI::App* cmd = nullptr;
  RemeshArgs args;

  void add(CLI::App& app) {
    cmd = app.add_subcommand("remesh", "Remesh a triangle mesh (a surface that is not a disk is cut open first)");
    cmd->add_option("input", args.input, "Input mesh (OFF, OBJ or PLY)")->required();
    cmd->add_option("-o,--output", args.output, "Output mesh (OFF, OBJ or PLY)")->check(kFileName);
    cmd->add_option("--record", args.record, "Save every iteration (of the solver, --solver) to this file (any name but a mesh's .off, .obj or .ply; .lsrec by custom)")->check(kFileName);
    cmd->add_flag("--json", args.json, "Print the results as one JSON object");
    addRemeshOptions(*cmd, args);
  }
  int run() const { return runRemesh(args, *cmd); }
};

struct InspectCommand {
  CLI::App* cmd = nullptr;
  RemeshArgs args;
  ScreenshotOptions shot;
  std::string size, pane = "window", iterations, fill, stage;
  bool noTimings = false;
  double uiScale = 0;  // none given: the screen's in a window, 1 in a picture

  void add(CLI::App& app) {
    cmd = app.add_subcommand("inspect", "Open the inspector on a mesh or a recording; with --screenshot, render it "
                                        "headless to a PNG and exit");
    cmd->add_option("input", args.input, "Mesh (OFF, OBJ, PLY) or recording (remesh --record, .lsrec)")->required();
    // The window's hint line has room for the stepping keys only; the others were in the guide
    // alone.
    cmd->footer(
        "Keys in the window: <- -> an iteration (Shift: ten; in a lesson, a stage), Home/End the first/last, "
        "Space play/pause, P presentation (classroom) mode, T the plots against time or iterations, L the "
        "lesson, Escape unpin every cell and triangle, F (over the 3D or 2D view) fit it, Ctrl+S save the "
        "iteration as a picture, Ctrl+Q close.");
    // What only a picture has is refused without one (a window ignored it in silence).
    CLI::Option* screenshot =
        cmd->add_option("--screenshot", shot.picture.path, "Render offscreen to this PNG and exit")->check(kFileName);
    cmd->add_option("--pane", pane, "With --screenshot: window (default), 3d, 2d or plots")->needs(screenshot);
    CLI::Option* pictures =
        cmd->add_option("--iterations", iterations, "With --screenshot: FIRST:LAST, one numbered PNG per iteration")
            ->needs(screenshot)
            ->check(nonEmpty("FIRST:LAST"));
    cmd->add_option("--iteration", shot.view.iteration, "Iteration to show (default: the last)")
        ->check(wholeNumber(0))
        ->excludes(pictures);
    CLI::Option* final = cmd->add_flag("--final", shot.view.final,
                                       "The 3D pane shows the final result (what remesh writes), with a red ring "
                                       "where it is farthest from the input");
    cmd->add_option("--select-cell", shot.view.cells, "Pin this cell (repeatable)")->check(wholeNumber(0));
    cmd->add_option("--select-triangle", shot.view.triangles,
                    "Pin this triangle of the result (with --final: of the final result; repeatable)")
        ->check(wholeNumber(0));
    // Not with --iterations: it pinned the last iteration's worst in every picture.
    cmd->add_flag("--select-worst", shot.view.worstTriangle,
                  "Pin the triangle with the smallest angle in the result at the iteration shown (with --final: in the final result)")
        ->excludes(pictures);
    cmd->add_option("--fill", fill,
                    "What colours the 2D cells: none, mass, area, energy, distance (site to "
                    "centroid), moved (since the iteration before) or valence (of the site's vertex in "
                    "the result: 5s blue, 7s red)");
    cmd->add_flag("--compare-solvers", shot.view.compareSolvers,
                  "Also relax the run's start with the other two solvers and plot their curves");
    cmd->add_flag("--presentation", shot.view.presentation,
                  "Classroom mode: large fonts, thick lines, no controls pane");
    // A stage shows the result its lesson step shows (the Result stage: the final one).
    cmd->add_option("--stage", stage,
                    "Show one stage of the lesson with its caption: load, parameterize, "
                    "voronoi, centroids, move, lift, result or valence")
        ->excludes(final);
    cmd->add_option("--camera", shot.view.camera,
                    "3D view as \"yaw pitch distance x y z\": angles in radians, the distance from "
                    "the point x y z looked at (the inspector's Copy view)")
        ->check(nonEmpty("\"yaw pitch distance x y z\""));
    cmd->add_option("--size", size, "With --screenshot: picture size WxH, " + pictureSizes() + " (default 1280x800)")
        ->needs(screenshot)
        ->check(nonEmpty("WxH"));
    cmd->add_flag("--validation", shot.validation, "Enable the Vulkan validation layer; fail if it reports anything");
    CLI::Option* noTimingsFlag = cmd->add_flag(
        "--no-timings", noTimings, "Leave timings out of the picture (or the window), so that it is the same on every run");
    cmd->add_flag("--plot-time", shot.view.plotTime,
                  "The convergence plots against time (the milliseconds of Lloyd's iterations, as recorded), "
                  "not iterations: which solver converges sooner, not in fewer steps")
        ->excludes(noTimingsFlag);
    cmd->add_option("--ui-scale", uiScale,
                    "Draw the inspector this many times as large, for a screen that many times as dense as "
                    "96 dpi (default: in a window the screen's own scale, from its Xft.dpi; in a picture 1, "
                    "and --size is in pixels)")
        ->check(finiteNumber(0.5, "a number from 0.5 to 4", 4.0));
    addRemeshOptions(*cmd, args);
  }

  // Plain `lloydscope`: the inspector on the default mesh.
  int runDefault() {
    args.input = LLOYDSCOPE_SOURCE_DIR "/assets/bumpy_disk.off";
    requireDisplay();
    RemeshOptions options;
    std::optional<Mesh> input;
    RemeshResult result = openForInspection(args, *cmd, options, &input);
    return runWindow(args.input, options, std::move(result), false, std::move(input));
  }

  int run() {
    parseSize(size, shot.width, shot.height);
    if (uiScale > 0) shot.uiScale = uiScale;
    shot.view.timings = !noTimings;
    shot.picture.pane = parsePane(pane);
    if (cmd->count("--stage")) shot.view.stage = parseStage(stage);
    if (cmd->count("--fill")) shot.view.fill = parseCellFill(fill);
    requireShownInPane();
    requireFillShown();
    shot.view.repair = args.repair;
    if (!iterations.empty()) parseIterations();
    RemeshOptions options;
    std::optional<Mesh> input;
    if (shot.picture.path.empty()) {
      requireDisplay();  // before minutes of work that no window would show
      RemeshResult result = openForInspection(args, *cmd, options, &input);
      return runWindow(args.input, options, std::move(result), shot.validation, std::move(input), shot.view, uiScale);
    }
    requirePictureSize(shot.width, shot.height, shot.uiScale);  // before minutes of work
    requirePinsShownAtStage();
    requirePngPath(shot.picture.path);  // its folder too (numbered pictures go there as well)
    // A sequence's names, as far as a run has iterations: a folder named as one was found only
    // after the run (the window's export checks them all before its first picture).
    for (int k = shot.picture.first; k >= 0 && k <= shot.picture.last && k - shot.picture.first < kMostIterations; ++k)
      requireFileName(exportPath(shot.picture, k));
    refuseReplacing(shot.picture, args.input);
    RemeshResult result = openForInspection(args, *cmd, options, &input);
    renderScreenshot(args.input, options, std::move(result), shot, std::move(input));
    return 0;
  }

  // A picture of one pane shows what that pane draws: an option for the others is refused
  // (--pane plots with --fill, --camera, --final and --select-worst made the same picture as
  // without them).
  void requireShownInPane() const {
    const Pane only = shot.picture.pane;
    const struct {
      const char* option;
      const char* view;
      bool shown;
    } rules[] = {{"--fill", "the 2D view (the valence fill marks the 3D view's vertices too)",
                  only == Pane::Domain2D || (only == Pane::View3D && shot.view.fill == CellFill::Valence)},
                 {"--camera", "the 3D view", only == Pane::View3D},
                 {"--final", "the 3D view", only == Pane::View3D},
                 {"--select-cell", "the 2D and 3D views", only != Pane::Plots},
                 {"--select-triangle", "the 2D and 3D views", only != Pane::Plots},
                 {"--select-worst", "the 2D and 3D views", only != Pane::Plots}};
    if (only == Pane::Window) return;
    for (const auto& rule : rules)
      if (!rule.shown && cmd->count(rule.option) > 0)
        throw Error(std::string(rule.option) + " has nothing to show in --pane " + pane + ": it is for " + rule.view);
  }

  // A stage draws its own layers: a fill it would not show is refused, not left out in silence.
  void requireFillShown() const {
    if (!shot.view.stage || !shot.view.fill || *shot.view.fill == CellFill::None) return;
    const std::string stageName = toString(*shot.view.stage);
    if (const std::optional<CellFill> own = stageFill(shot.view.stage); own && *own != *shot.view.fill)
      throw Error("--fill " + fill + ": the " + stageName + " stage fills the cells by " + toString(*own));
    if (!layersFor(*shot.view.stage).cells2D)
      throw Error("--fill " + fill + ": the " + stageName + " stage shows no cells to fill");
  }

  // The stages before Voronoi draw no cells and no result: a picture of one with a pin showed
  // it nowhere, exit 0. (A window may open there, pins and all, for the stages after.)
  void requirePinsShownAtStage() const {
    if (!shot.view.stage || layersFor(*shot.view.stage).sites2D) return;
    for (const char* option : {"--select-cell", "--select-triangle", "--select-worst"})
      if (cmd->count(option) > 0)
        throw Error(std::string(option) + " has nothing to show at --stage " + stage + ": it draws no cells and no result");
  }

  // --iterations FIRST:LAST
  void parseIterations() {
    const auto range = digitsPair(iterations, ':');
    constexpr long long kLargest = std::numeric_limits<int>::max();  // 0:4294967296 wrapped to 0:0
    if (!range || range->first > kLargest || range->second > kLargest)
      throw Error("--iterations: expected FIRST:LAST, e.g. 0:20, not '" + iterations + "'");
    const auto [first, last] = *range;
    if (first > last)
      throw Error("--iterations: FIRST comes after LAST in '" + iterations + "' (the pictures go from FIRST up to LAST)");
    shot.picture.first = static_cast<int>(first);
    shot.picture.last = static_cast<int>(last);
  }
};

struct FrameBenchCommand {
  CLI::App* cmd = nullptr;
  RemeshArgs args;
  std::string size;
  int frames = 100;

  void add(CLI::App& app) {
    cmd = app.add_subcommand("bench-frames", "Median frame time of the inspector while scrubbing a run's iterations (headless)");
    cmd->add_option("input", args.input, "Mesh")->required();
    cmd->add_option("--frames", frames, "Frames to time" + defaultIs(frames))->check(wholeNumber(1, kMostFrames));
    cmd->add_option("--size", size, "Frame size WxH, " + pictureSizes() + " (default 1280x800)")
        ->check(nonEmpty("WxH"));
    addRemeshOptions(*cmd, args);
  }

  int run() const {
    int width = 1280, height = 800;
    parseSize(size, width, height);
    RemeshOptions options;
    RemeshResult result = openForInspection(args, *cmd, options);
    const size_t sites = result.recording.fixedSites.size() +
                         (result.recording.iterations.empty() ? 0 : result.recording.iterations[0].sites.size());
    const int iterations = result.iterations;
    auto median = [](std::vector<double> v) {
      std::sort(v.begin(), v.end());
      return v[v.size() / 2];
    };
    const FrameTimes still = benchmarkScrub(args.input, options, result, width, height, frames, false);
    const FrameTimes scrub = benchmarkScrub(args.input, options, std::move(result), width, height, frames, true);
    std::printf("| sites | iterations | size | frames | median ms, still | median ms, scrubbing | "
                "max ms, scrubbing |\n|---|---|---|---|---|---|---|\n"
                "| %zu | %d | %dx%d | %d | %.1f | %.1f | %.1f |\n",
                sites, iterations, width, height, frames, median(still.milliseconds), median(scrub.milliseconds),
                *std::max_element(scrub.milliseconds.begin(), scrub.milliseconds.end()));
    return 0;
  }
};

struct BenchCommand {
  CLI::App* cmd = nullptr;
  BenchOptions options;
  bool noReference = false;

  void add(CLI::App& app) {
    cmd = app.add_subcommand("bench", "Lloydscope against CGAL's isotropic_remeshing on prepared inputs (markdown, CSV)");
    cmd->add_option("models", options.models, "Meshes (default: CGAL's disk samples in data/cgal)");
    // The comparison's own options, which --lloyd-step's timing alone does without (they were
    // accepted and ignored: no CSV written, no input saved).
    CLI::Option* comparisonOnly[] = {
        cmd->add_option("--sizes", options.sizes, "Vertex counts (default 500 1000 2000)")->check(kVerticesAsked),
        cmd->add_option("--csv", options.csv, "CSV output (default bench.csv)")->check(kFileName),
        cmd->add_option("--save-inputs", options.saveInputs, "Also write each prepared input to DIR/<model>_<size>.off")
            ->check(nonEmpty("a folder", "DIR")),
        cmd->add_flag("--no-reference", noReference, "Leave out the report's preset (slow)"),
        cmd->add_flag("--as-is", options.asIs,
                      "Use the models as they come, not prepared: each remeshed to each size "
                      "(--sites), with the defaults and --full-input, beside CGAL's remesher on it")};
    addRepairFlag(*cmd, options.repair);
    CLI::Option* step = cmd->add_option("--lloyd-step", options.stepSites,
                                        "Instead: time one Lloyd iteration at N sites (one core and all), on "
                                        "the one model given (default: the bundled bumpy disk)")
                            ->check(kVerticesAsked);
    for (CLI::Option* option : comparisonOnly) step->excludes(option);
  }

  int run() {
    if (options.stepSites > 0 && options.models.size() > 1)
      throw Error("--lloyd-step times one mesh; " + std::to_string(options.models.size()) + " were given");
    options.reference = !noReference;
    if (options.stepSites > 0) runStepBench(options);
    else runBench(options);
    return 0;
  }
};

struct SimplifyCommand {
  CLI::App* cmd = nullptr;
  std::string input, output;
  SimplifyOptions target;
  bool repair = false;

  void add(CLI::App& app) {
    cmd = app.add_subcommand("simplify", "Quadric edge collapse (Garland-Heckbert) to a target size, the border kept a border");
    cmd->add_option("input", input, "Mesh (OFF, OBJ, PLY)")->required();
    cmd->add_option("-o,--output", output, "Where to write the result")->required()->check(kFileName);
    auto* size = cmd->add_option_group("target", "one of");
    size->add_option("--vertices", target.vertices, "Target number of vertices")->check(kPositiveCount);
    size->add_option("--faces", target.faces, "Target number of faces")->check(kPositiveCount);
    size->add_option("--ratio", target.ratio, "Target fraction of the vertices, in (0, 1]")
        ->check(finiteNumber(std::numeric_limits<double>::denorm_min(), "a fraction in (0, 1]", 1));
    size->require_option(1);
    addRepairFlag(*cmd, repair);
  }

  int run() const {
    if (sameFile(output, input)) throw Error(output + ": --output would replace the input mesh; give it another name");
    requireMeshWritable(output);
    const Mesh mesh = load(input, repair);
    // Beyond it the quadrics overflow: at 1e78 nothing collapsed, and the mesh was written as read.
    requireExactPredicatesRange(mesh, input, "simplified");
    if (simplifyCollapses(mesh, target, input)) noteASlowSimplification(mesh, input);
    const SimplifyResult s = simplify(mesh, target, input);
    writeMesh(s.mesh, output);
    std::cout << input << ": " << mesh.vertexCount() << " vertices, " << mesh.faceCount() << " faces -> "
              << s.mesh.vertexCount() << " vertices, " << s.mesh.faceCount() << " faces (" << s.collapses
              << " collapses, " << std::lround(s.milliseconds) << " ms)\n";
    if (!s.stoppedShort.empty()) std::cerr << "note: " << s.stoppedShort << "\n";
    return 0;
  }
};

struct MetricsCommand {
  CLI::App* cmd = nullptr;
  std::string mesh, reference;
  bool json = false, repair = false;

  void add(CLI::App& app) {
    cmd = app.add_subcommand("metrics", "Measure a mesh's quality");
    cmd->add_option("mesh", mesh, "Mesh to measure")->required();
    cmd->add_option("--reference", reference, "Also measure Hausdorff and RMS distance to this mesh");
    cmd->add_flag("--json", json, "Print JSON");
    addRepairFlag(*cmd, repair);
  }

  int run() const {
    const Mesh measured = load(mesh, repair);
    // Beyond it the angles overflow: at 1e78 every angle of a grid read 90 degrees.
    requireExactPredicatesRange(measured, mesh, "measured");
    const QualityMetrics quality = measureQuality(measured);
    Fidelity fidelity;
    const bool withReference = !reference.empty();
    if (withReference) {
      const Mesh against = load(reference, repair);
      requireExactPredicatesRange(against, reference, "measured");
      fidelity = measureFidelity(measured, against);
    }
    if (json) {
      nlohmann::json j = toJson(quality);
      if (withReference) j["fidelity"] = toJson(fidelity);
      std::cout << printable(j) << "\n";
    } else {
      std::cout << metricsReport(quality, withReference ? &fidelity : nullptr);
    }
    return 0;
  }
};

struct InfoCommand {
  CLI::App* cmd = nullptr;
  std::string recording;
  bool json = false;

  void add(CLI::App& app) {
    cmd = app.add_subcommand("info", "Summarize a recording");
    cmd->add_option("recording", recording, "Recording file (from remesh --record)")->required();
    cmd->add_flag("--json", json, "Print JSON");
  }

  int run() const {
    const Recording r = loadRecording(recording);
    if (json) std::cout << printable(recordingSummary(r)) << "\n";
    else std::cout << recordingReport(r);
    return 0;
  }
};

}  // namespace

int main(int argc, char** argv) {
  keepFreedMemory();
  CLI::App app{"Lloydscope: variational surface remeshing by weighted Lloyd relaxation"};
  app.require_subcommand(0, 1);
  RemeshCommand remesh;
  InspectCommand inspect;
  FrameBenchCommand frameBench;
  BenchCommand bench;
  SimplifyCommand simplify;
  MetricsCommand metrics;
  InfoCommand info;
  remesh.add(app);
  inspect.add(app);
  frameBench.add(app);
  bench.add(app);
  simplify.add(app);
  metrics.add(app);
  info.add(app);

  // A command-line error is one line, as every other error, with exit code 1 (CLI11's own
  // printed two and exited 105-109); --help prints the help and exits 0.
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success)) return withOutputChecked(app.exit(e));
    std::cerr << "lloydscope: " << oneLine(e.what() + dashedFileHint(argc, argv))
              << " (--help lists the options)\n";
    return 1;
  }

  const auto runChosen = [&] {
    if (remesh.cmd->parsed()) return remesh.run();
    if (inspect.cmd->parsed()) return inspect.run();
    if (frameBench.cmd->parsed()) return frameBench.run();
    if (bench.cmd->parsed()) return bench.run();
    if (simplify.cmd->parsed()) return simplify.run();
    if (metrics.cmd->parsed()) return metrics.run();
    if (info.cmd->parsed()) return info.run();
    return inspect.runDefault();
  };
  try {
    return withOutputChecked(runChosen());
  } catch (const Error& e) {
    std::cerr << "lloydscope: " << oneLine(e.what()) << "\n";
    return 1;
  } catch (const gpu::GpuError& e) {
    std::cerr << "lloydscope: " << oneLine(e.what()) << "\n";
    return 1;
  } catch (const std::bad_alloc&) {
    // The file the command was working on, as every other error names it.
    std::string file;
    for (const std::string* input : {&remesh.args.input, &inspect.args.input, &frameBench.args.input, &simplify.input,
                                     &metrics.mesh, &info.recording})
      if (file.empty()) file = *input;
    if (file.empty() && !bench.options.models.empty()) file = bench.options.models.front();
    std::cerr << "lloydscope: " << (file.empty() ? "" : oneLine(file) + ": ")
              << "out of memory: fewer vertices asked, or a smaller input, need less\n";
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "lloydscope: internal error: " << oneLine(e.what()) << "\n";
    return 2;
  }
}
