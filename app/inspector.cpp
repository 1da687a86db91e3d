#include "inspector.h"

#include <glm/matrix.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/mat4x4.hpp>

#include "files.h"
#include "keys.h"
#include "text.h"
#include "mesh_io.h"
#include "names.h"
#include "png.h"
#include "report.h"
#include "topology.h"

#include <backends/imgui_impl_vulkan.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <set>

namespace lloydscope {

namespace {

VkCommandBuffer gCommandBuffer = VK_NULL_HANDLE;

// No backgrounds: the panes tile the window and the frame is cleared to ImGui's window colour.
// On lavapipe every blended full-window layer costs milliseconds.
constexpr ImGuiWindowFlags kPaneFlags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                                        ImGuiWindowFlags_NoCollapse |
                                        ImGuiWindowFlags_NoSavedSettings |
                                        ImGuiWindowFlags_NoBackground;

// Seams (where a surface that is not a disk was cut open) in both views: purple, no other
// layer uses it.
constexpr ImU32 kSeamColor = IM_COL32(150, 40, 190, 255);
constexpr ImU32 kFarthestColor = IM_COL32(230, 30, 30, 255);  // where the result strays most

ImU32 rgb(float r, float g, float b, float a = 1.0f) {
  return ImGui::ColorConvertFloat4ToU32(ImVec4(r, g, b, a));
}

// Minimum angle 0..60 degrees: red (bad) through yellow (30) to green (equilateral).
std::array<float, 3> angleColor(double degrees) {
  const float t = static_cast<float>(std::clamp(degrees / 60.0, 0.0, 1.0));
  if (t < 0.5f) {
    const float s = t / 0.5f;
    return {0.85f + 0.1f * s, 0.2f + 0.6f * s, 0.15f + 0.05f * s};
  }
  const float s = (t - 0.5f) / 0.5f;
  return {0.95f - 0.65f * s, 0.8f - 0.05f * s, 0.2f + 0.2f * s};
}

// A perceptually ordered map (viridis-like) for cell quantities, t in 0..1.
ImU32 quantityColor(float t, float alpha = 1.0f) {
  t = std::clamp(t, 0.0f, 1.0f);
  const float r = 0.27f + t * (0.99f - 0.27f) * t;
  const float g = 0.0f + 0.9f * t;
  const float b = 0.33f + 0.4f * std::sin(3.1f * (1.0f - t)) * (1.0f - t);
  return rgb(r, g, b, alpha);
}

// The panes are fixed windows: a layout that stays put for a lecture and for snapshots.
void beginPane(const char* name, const ImVec2& pos, const ImVec2& size,
               ImGuiWindowFlags extra = 0) {
  ImGui::SetNextWindowPos(pos);
  ImGui::SetNextWindowSize(size);
  ImGui::Begin(name, nullptr, kPaneFlags | extra);
}

// The file a path names, without the folders: what the header and the captions call a mesh.
std::string fileNameOf(const std::string& path) { return path.substr(path.find_last_of('/') + 1); }

// ImGui 1.86 names only a few letter keys; the platform's key codes for letters are
// consecutive (GLFW's are), so the others are found from A's.
bool letterKeyPressed(char letter) {
  return ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_A) + (letter - 'A'), false);
}
bool letterPressed(char letter) { return keysAreCommands() && letterKeyPressed(letter); }

// Panes that are one drawing area: a scroll bar would only eat into it.
constexpr ImGuiWindowFlags kCanvasPaneFlags =
    ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoScrollWithMouse;

// A size a button may take: ImGui aborts on one of no size, which a pane with no room left
// (a window narrower than the left pane, 300x200) gives.
ImVec2 drawable(ImVec2 size) { return ImVec2(std::max(size.x, 2.0f), std::max(size.y, 2.0f)); }

// ImGui::SameLine() where an item `width` wide still fits on the line, else nothing (it starts
// the next): at --ui-scale 1.5 the left pane's "retriangulate" and "triangle" ran under its
// scroll bar, cut off.
void sameLineIfFits(float width) {
  // Where the pane clips its items: half its padding right of its content (ImGui's
  // InnerClipRect), where "retriangulate" ended at --ui-scale 1.
  const float right = ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x +
                      std::floor(0.5f * ImGui::GetStyle().WindowPadding.x);
  if (ImGui::GetItemRectMax().x + ImGui::GetStyle().ItemSpacing.x + width <= right) ImGui::SameLine();
}
float radioWidth(const char* label) {
  return ImGui::GetFrameHeight() + ImGui::GetStyle().ItemInnerSpacing.x + ImGui::CalcTextSize(label).x;
}
float buttonWidth(const char* label) { return ImGui::CalcTextSize(label).x + 2 * ImGui::GetStyle().FramePadding.x; }

// The rest of the pane as a drawing area: its top-left corner and size.
std::pair<ImVec2, ImVec2> canvasArea() {
  return {ImGui::GetCursorScreenPos(), drawable(ImGui::GetContentRegionAvail())};
}

constexpr float kColorBarWidth = 12.0f;
constexpr float kFillBarHeight = 90.0f;

void drawColorBar(ImDrawList* dl, ImVec2 at, float width, float height, const char* top, const char* bottom,
                  const std::function<ImU32(float)>& color) {
  const int steps = 24;
  for (int i = 0; i < steps; ++i) {
    const float t0 = static_cast<float>(i) / steps, t1 = static_cast<float>(i + 1) / steps;
    dl->AddRectFilled(ImVec2(at.x, at.y + height * (1 - t1)), ImVec2(at.x + width, at.y + height * (1 - t0)),
                      color(0.5f * (t0 + t1)));
  }
  dl->AddRect(at, ImVec2(at.x + width, at.y + height), rgb(0.2f, 0.2f, 0.2f));
  const float font = ImGui::GetFontSize();
  boxedText(dl, ImVec2(at.x + width + 4, at.y - 0.45f * font), top);
  boxedText(dl, ImVec2(at.x + width + 4, at.y + height - 0.6f * font), bottom);
}

// The valence fill's kinds, from the most over a regular vertex's valence to the most under
// it: a diverging map, red where cells have too many sides, blue too few, regular pale.
struct ValenceKind {
  ImU32 color;
  const char* label;  // inside; on the border, two less
};
const std::array<ValenceKind, 5>& valenceKinds() {
  static const std::array<ValenceKind, 5> kinds = {{{rgb(0.65f, 0.08f, 0.08f), "8+"},
                                                    {rgb(0.96f, 0.45f, 0.35f), "7"},
                                                    {rgb(0.9f, 0.9f, 0.86f), "6"},
                                                    {rgb(0.4f, 0.62f, 0.95f), "5"},
                                                    {rgb(0.08f, 0.22f, 0.65f), "4-"}}};
  return kinds;
}
ImU32 valenceColor(const VertexValence& s) {
  if (!s.isVertex()) return rgb(0.6f, 0.6f, 0.6f);
  return valenceKinds()[2 - std::clamp(s.offset(), -2, 2)].color;
}

// A legend for a few kinds: a swatch each, top to bottom, its label beside it; as tall as a
// colour bar where the pane has the room, else in as many columns as it takes to fit `room` (in
// presentation mode at 960x600 the 2D pane's own legend hid the last swatch).
void drawSwatches(ImDrawList* dl, ImVec2 at, float room, const std::array<ValenceKind, 5>& kinds) {
  const float font = ImGui::GetFontSize();
  const int count = static_cast<int>(kinds.size());
  const float step = std::max(kFillBarHeight / count, 0.9f * font);
  const int rows = std::clamp(static_cast<int>(room / step), 1, count);
  float labelWidth = 0;
  for (const ValenceKind& kind : kinds) labelWidth = std::max(labelWidth, ImGui::CalcTextSize(kind.label).x);
  const float columnWidth = kColorBarWidth + 4 + labelWidth + 8;
  for (int i = 0; i < count; ++i) {
    const float x = at.x + (i / rows) * columnWidth, y = at.y + (i % rows) * step;
    const ImVec2 a(x, y + 1), b(x + kColorBarWidth, y + step - 1);
    dl->AddRectFilled(a, b, kinds[i].color);
    dl->AddRect(a, b, rgb(0.2f, 0.2f, 0.2f));
    boxedText(dl, ImVec2(b.x + 4, 0.5f * (a.y + b.y) - 0.5f * font), kinds[i].label);
  }
}

void drawMeshCallback(const ImDrawList*, const ImDrawCmd* cmd) {
  const auto* draw = static_cast<const std::pair<const MeshRenderer*, MeshDraw>*>(cmd->UserCallbackData);
  draw->first->draw(gCommandBuffer, draw->second);
}

}  // namespace

void Inspector::recordFrame(VkCommandBuffer cmd, VkRenderPass pass, VkFramebuffer framebuffer,
                            VkExtent2D extent) {
  VkClearValue clear[2] = {};
  clear[0].color = {{0.94f, 0.94f, 0.94f, 1.0f}};  // StyleColorsLight's WindowBg
  clear[1].depthStencil = {1.0f, 0};
  VkRenderPassBeginInfo begin{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
  begin.renderPass = pass;
  begin.framebuffer = framebuffer;
  begin.renderArea = {{0, 0}, extent};
  begin.clearValueCount = 2;
  begin.pClearValues = clear;
  vkCmdBeginRenderPass(cmd, &begin, VK_SUBPASS_CONTENTS_INLINE);
  gpu::setRenderArea(extent, ImGui::GetDrawData()->FramebufferScale.x);
  gCommandBuffer = cmd;
  ImGui_ImplVulkan_RenderDrawData(ImGui::GetDrawData(), cmd);
  vkCmdEndRenderPass(cmd);
}

namespace {

Mesh largestComponent(const Mesh& mesh) {
  std::vector<Mesh> parts = splitComponents(mesh);
  auto byArea = [](const Mesh& a, const Mesh& b) { return surfaceArea(a) < surfaceArea(b); };
  return std::move(*std::max_element(parts.begin(), parts.end(), byArea));
}

// The last item (a view's canvas) was let go of after a click, not a drag of 3 px or more.
bool clickedNotDragged() {
  return ImGui::IsItemDeactivated() && ImGui::IsMouseReleased(ImGuiMouseButton_Left) &&
         ImGui::GetIO().MouseDragMaxDistanceSqr[0] < 9.0f;
}

// How much longer the lesson's Move stage draws the arrows s -> c of the movable sites (the
// view's first `fixedCount` are fixed): arrowMagnification of a typical and the longest, by the
// site spacing. Ratios of lengths, the same in the domain's units as in pixels.
double moveArrowScale(const IterationView& view, size_t fixedCount) {
  std::vector<double> lengths;
  for (size_t i = fixedCount; i < view.sites.size(); ++i) lengths.push_back((view.cells[i].centroid - view.sites[i]).norm());
  if (lengths.empty()) return 1;
  std::sort(lengths.begin(), lengths.end());
  return arrowMagnification(lengths[lengths.size() / 2], lengths.back(), 1.0 / std::sqrt(view.sites.size() + 1.0));
}

}  // namespace

Inspector::Inspector(gpu::Context& gpu, VkRenderPass renderPass, std::string meshName,
                     RemeshOptions options, RemeshResult result, std::optional<Mesh> input)
    : renderer_(gpu, renderPass),
      meshName_(fileNameOf(meshName)),
      shownPath_(meshName),
      options_(std::move(options)), asked_{options_.slitDisks, options_.resample}, result_(std::move(result)),
      replay_(std::make_unique<Replay>(result_.recording)), input_(std::move(input)),
      canvas_(gpu, renderPass) {
  result_.recording = Recording{};  // the replay holds it
  // Before a chart or component stands for the input.
  inputTopology_ = input_ ? analyzeTopology(*input_) : replay_->surface();
  if (!result_.resampleDropped.empty()) runNotes_ = withNoteFirst(withoutResamplingText(result_.resampleDropped), "");
  // remesh() kept a nearly closed disk whole: so does Restart (a session makes one run).
  if (result_.slitTrial && result_.cut.seamEdges == 0) options_.slitDisks = false;
  noteFirst(slitTrialText(result_));
  // Likewise a disk kept as remeshed without the first resampling, or with the corners of its
  // coarse border kept as samples.
  if (result_.firstPassTrial && result_.firstPassTrial->keptWithout) options_.resample = false;
  if (result_.borderTrial && result_.borderTrial->keptWith) options_.sites.keptBorderPoints = result_.borderTrial->corners;
  // And an input simplified because it failed as it was.
  if (!result_.fullInputFailed.empty()) options_.simplifyTo = simplifiedAfterFailure_ = verticesAsked(options_);
  settings_ = options_;
  keepWithinCommandLineBounds(settings_);  // a recording's own (a chart's 18 sites) are not
  noteFirst(firstPassTrialText(result_));
  noteFirst(borderTrialText(result_));
  noteFirst(fullInputFailedText(result_.fullInputFailed, options_.simplifyTo));
  noteFirst(coarseInputText(result_.coarseInput, result_.before.vertices));
  noteTheResult();
  inputCharts_ = result_.charts;
  inputComponents_ = result_.components;
  if (result_.charts > 0) {
    if (input_) input_ = result_.largestChart;  // what the panes show, and Restart steps
    runNotes_ = withNoteFirst(chartTrialText(result_) + ": the panes, the iteration column and Restart follow the "
                              "largest chart (on its own); the input and final columns and \"show the final result\" "
                              "are the whole surface",
                              runNotes_);
  } else if (result_.chartTrial) {
    noteFirst(chartTrialText(result_));  // kept as one disk, and why
  }
  if (result_.components > 1) {
    if (input_) input_ = largestComponent(*input_);  // what the panes show, and Restart steps
    runNotes_ = withNoteFirst(meshName_ + " has " + std::to_string(result_.components) +
                                  " connected components, each remeshed on its own: the panes, the iteration "
                                  "column and Restart follow the largest; the input and final columns and \"show "
                                  "the final result\" are all of them",
                              runNotes_);
  }
  std::snprintf(meshPath_, sizeof meshPath_, "%s", meshName.c_str());
  std::snprintf(recordingPath_, sizeof recordingPath_, "run.lsrec");
  iteration_ = replay_->iterationCount() - 1;
  fitCamera();
  ImFontAtlas* fonts = ImGui::GetIO().Fonts;
  for (int k = 1; k < std::min(fonts->Fonts.Size, 3); ++k) presentationFonts_[k - 1] = fonts->Fonts[k];
}

Inspector::~Inspector() {
  stopComparing();
  stopRun();
}

void Inspector::noteFirst(const std::string& text) {
  runNotes_ = withNoteFirst(text, runNotes_);
}

// What the final result itself calls for a word on: the same for a run opened from the command
// line and one made here (Restart and Run, Open mesh), which showed none of them.
void Inspector::noteTheResult() {
  noteFirst(vertexCountText(result_, options_));
  noteFirst(farFromTheInputText(result_.fidelity));
  noteFirst(foldsText(result_.before, result_.after));
  noteFirst(sharpCornerText(result_.before, result_.after));
  noteFirst(pinholeText(result_.after));
  noteFirst(tipText(result_.after));
  noteFirst(curvatureText(result_.after));
}

namespace {
std::vector<CvtSolver> otherSolvers(CvtSolver solver) {
  std::vector<CvtSolver> others;
  for (CvtSolver s : kCvtSolvers)
    if (s != solver) others.push_back(s);
  return others;
}

// Each solver's curves and legend have one colour, whichever run it is: plain Lloyd grey,
// L-BFGS blue, Newton purple (green is the threshold line's, red the current iteration's).
ImVec4 solverColour(CvtSolver solver) {
  switch (solver) {
    case CvtSolver::Lloyd: return {0.38f, 0.38f, 0.38f, 1};  // 5.4:1 on the light background (0.55: 2.9:1)
    case CvtSolver::Lbfgs: return {0.15f, 0.3f, 0.7f, 1};
    case CvtSolver::Newton: return {0.62f, 0.3f, 0.72f, 1};
  }
  return {0, 0, 0, 1};
}
}  // namespace

std::vector<Inspector::Comparison> Inspector::relaxWithOtherSolvers(const Recording& recording,
                                                                    const LloydOptions& run,
                                                                    const std::atomic<bool>* stop) {
  std::vector<Comparison> runs;
  for (CvtSolver solver : otherSolvers(run.solver)) {
    if (stop && *stop) break;
    LloydOptions o = run;
    o.solver = solver;
    o.distanceThreshold = recording.distanceThreshold;
    o.percentThreshold = recording.percentThreshold;
    runs.push_back({solver, relaxAgain(recording, o, stop)});
  }
  return runs;
}

void Inspector::compareSolvers() {
  stopComparing();
  comparisons_ = relaxWithOtherSolvers(replay_->recording(), options_.lloyd, nullptr);
}

void Inspector::startComparing() {
  stopComparing();
  comparisons_.clear();
  // The settings are copied (Restart changes options_); the recording stays until
  // stopComparing(), which everything that changes the replay calls first.
  comparing_.start(
      [this, &recording = replay_->recording(), run = options_.lloyd](const std::atomic<bool>& stop) {
        compared_ = relaxWithOtherSolvers(recording, run, &stop);
      },
      [this] {
        if (wake_) wake_();  // the window may be waiting for events: the curves are news
      });
}

void Inspector::stopComparing() {
  comparing_.stop();
  compared_.clear();
}

// Step and Run change the run a comparison started from: it stops, and says so (its curves
// never came, and nothing said why).
void Inspector::stopComparingForARun() {
  if (comparing_.started() && !comparing_.finished())
    showMessage("Compare stopped: Step and Run change the run it compares with; press it again after the run.");
  stopComparing();
}

void Inspector::openReplay(Recording recording) {
  stopComparing();
  comparisons_.clear();  // of another run
  replay_ = std::make_unique<Replay>(std::move(recording));
  // A lesson's plan and an exported sequence's numbers are of the replay before (Restart in a
  // lesson kept playing the old plan, clamped to iteration 0).
  if (lesson_.playing()) toggleLesson();
  if (exportJob_ && exportJob_->sequence()) showMessage("the sequence was not saved: another run was opened before its last picture");
  exportJob_.reset();
  exportRequest_.reset();   // the frame drawn now is of the new replay
  pictureFiles_.reset();    // the pictures made so far are not saved
  uploaded_ = Shown3D{};
  measuredIteration_ = edgesIteration_ = -1;
  canvasKey_ = CanvasKey{};
  iteration_ = std::max(0, replay_->iterationCount() - 1);
  exportFirst_ = 0;  // a sequence of the whole run, unless the user asks less (it read 0 to 0)
  exportLast_.reset();
  fitCamera();
  fit2D();  // another domain: the last one's zoom showed a corner of it, or nothing
}

void Inspector::fit2D() { view2D_ = PlaneView{}; }

void Inspector::startSession(const Mesh& input, const std::string& name) {
  stopComparing();
  stopRun();
  // Made before the replay on show changes: where it fails, the last run's iterations stay. As
  // remesh() makes its run: without the first pass, or simplified, where that fails.
  StartedSession started = lloydscope::startSession(input, settings_, name);
  started.session->step();  // the panes need one iteration to show
  forgetResult();
  // The Settings pane's, from now on the run's; without the first pass where it went without
  // (the lesson said the map was of a rough first remeshing), simplified where it was.
  options_ = started.used;
  session_ = std::move(started.session);
  if (!started.resampleDropped.empty()) runNotes_ = withNoteFirst(withoutResamplingText(started.resampleDropped), "");
  if (!started.fullInputFailed.empty()) {
    settings_.simplifyTo = simplifiedAfterFailure_ = options_.simplifyTo;
    noteFirst(fullInputFailedText(started.fullInputFailed, options_.simplifyTo));
  }
  result_.paramUsed = session_->paramUsed();
  result_.borderUsed = session_->borderUsed();
  result_.distortion = session_->distortion();
  // The 2D pane shows the simplified input's map.
  noteFirst(coarseInputText(session_->coarseInput(), input.vertexCount()));
  Recording header = session_->header();
  header.iterations.push_back(session_->iterationRecord(0));
  openReplay(std::move(header));
  // No site to move (a domain its border samples fill): the run is over, Step and Run have
  // nothing to do, and the result is ready.
  if (session_->finished()) finishSession();
}

// A new run or recording: nothing of the last run's result (its final column, distances,
// notes) stays on show; the input's own numbers do, and the map until a session names its own.
void Inspector::forgetResult() {
  RemeshResult kept;
  kept.before = result_.before;
  kept.paramUsed = result_.paramUsed;
  kept.borderUsed = result_.borderUsed;
  kept.distortion = result_.distortion;
  result_ = std::move(kept);
  selection_.forgetFinal();
  runNotes_.clear();
}

void Inspector::startRun() {
  if (!session_ || running() || session_->finished()) return;
  stopComparingForARun();  // the run appends to the replay the comparison reads
  if (lesson_.playing()) toggleLesson();  // its plan is of the iterations before the run
  run_.start([this](const std::atomic<bool>& stop) {
    while (!stop && !session_->finished()) {
      IterationRecord record = session_->step();
      std::lock_guard<std::mutex> lock(pendingMutex_);
      pending_.push_back(std::move(record));
    }
  });
}

void Inspector::stopRun() {
  run_.requestStop();
  joinWorker();
}

void Inspector::stopRunAndFinish() {
  stopRun();
  if (session_ && session_->finished()) finishSession();
}

void Inspector::joinWorker() {
  const std::string error = run_.join();
  collectIterations();
  if (!error.empty()) runFailed(error);
}

void Inspector::runFailed(const std::string& why) {
  showMessage("The run stopped at iteration " + std::to_string(replay_->iterationCount() - 1) + ": " + why);
  session_.reset();
}

void Inspector::collectIterations() {
  std::vector<IterationRecord> fresh;
  {
    std::lock_guard<std::mutex> lock(pendingMutex_);
    fresh.swap(pending_);
  }
  if (fresh.empty()) return;
  const bool following = iteration_ + 1 >= replay_->iterationCount();
  for (IterationRecord& r : fresh) replay_->append(std::move(r));
  if (following) setIteration(replay_->iterationCount() - 1);
}

// A finished run: the final result's metrics for the table. The session is spent.
void Inspector::finishSession() {
  try {
    result_ = session_->finish();
    result_.recording = Recording{};  // the replay holds its iterations already
    noteTheResult();
  } catch (const Error& e) {  // the seams did not stitch: the iterations stay to look at
    forgetResult();
    runNotes_ = withNoteFirst(std::string(e.what()) + (usesResampling(options_) ? " (inspect --no-resample makes it without "
                                                                                 "the first resampling, as remesh does by itself)"
                                                                               : ""),
                              "");
  }
  session_.reset();
}

void Inspector::setIteration(int k) {
  iteration_ = std::clamp(k, 0, std::max(0, replay_->iterationCount() - 1));
}

void Inspector::prepare() {
  currentQuality();
  cellEdges();
}

void Inspector::pick3D(const ImVec2& mouse, const ImVec2& p0, const ImVec2& extent, float top) {
  if (layers().input3D) return;  // triangles are the result's
  const auto [viewProjection, eye] = camera_.matrices(gpu_, extent.x, extent.y, top);
  const glm::mat4 inverse = glm::inverse(viewProjection);
  const float x = (mouse.x - p0.x) / extent.x * 2 - 1, y = (mouse.y - p0.y) / extent.y * 2 - 1;
  const glm::vec4 far = inverse * glm::vec4(x, y, 1.0f, 1.0f);
  const glm::vec3 through = glm::vec3(far) / far.w - eye;  // the same way in the GPU's frame as in the mesh's
  const int hit = triangleOnRay(resultIn3D(), gpu_.from(eye), Vec3(through.x, through.y, through.z));
  if (finalShown()) selection_.toggleFinalTriangle(hit);
  else selection_.toggleTriangle(replay_->view(iteration_), hit);
}

const Mesh& Inspector::resultIn3D() const {
  return finalShown() ? result_.output : replay_->view(iteration_).output;
}

void Inspector::pinCell(int cell) {
  const int count = static_cast<int>(replay_->view(iteration_).sites.size());
  if (cell < 0 || cell >= count)
    throw Error("cell " + std::to_string(cell) + " does not exist (" + std::to_string(count) +
                " sites, numbered from 0)");
  selection_.pinCell(cell);
}

void Inspector::pinTriangle(int triangle) {
  const int count = static_cast<int>(resultIn3D().triangles.size());
  if (triangle < 0 || triangle >= count)
    throw Error("triangle " + std::to_string(triangle) + " does not exist (" +
                (finalShown() ? "the final result" : "the result at iteration " + std::to_string(iteration_)) +
                " has " + std::to_string(count) + ", numbered from 0)");
  if (finalShown()) selection_.pinFinalTriangle(triangle);
  else selection_.pinTriangle(replay_->view(iteration_), triangle);
}

void Inspector::pinWorstTriangle() {
  if (const int worst = worstTriangle(resultIn3D()); worst >= 0) pinTriangle(worst);
}

void Inspector::pick2D(const Vec2& uv) {
  const IterationView& view = replay_->view(iteration_);
  if (pickTriangles2D_) selection_.toggleTriangle(view, triangleAtUV(view, uv));
  else selection_.toggleCell(cellAt(replay_->domain(), view, uv));
}

void Inspector::hoverTooltip2D(const Vec2& uv) {
  const IterationView& view = replay_->view(iteration_);
  const int cell = cellAt(replay_->domain(), view, uv);
  if (cell < 0) return;
  const BoundedCell& c = view.cells[cell];
  ImGui::BeginTooltip();
  ImGui::Text("cell %d%s", cell, cell < static_cast<int>(replay_->recording().fixedSites.size())
                                     ? " (fixed border site)" : "");
  ImGui::Text("area %.3e  mass %.3e", c.area, c.mass);
  ImGui::Text("site to centroid %.2e", (c.centroid - view.sites[cell]).norm());
  ImGui::TextDisabled("%s", pickTriangles2D_             ? "click to pin or unpin the triangle here"
                            : selection_.cellPinned(cell) ? "click to unpin"
                                                          : "click to pin");
  ImGui::EndTooltip();
}

std::string Inspector::cameraText() const { return camera_.text(); }

void Inspector::setCamera(const std::string& text) {
  camera_ = OrbitCamera::parse(text);
  fitPending_ = false;
}

constexpr NamedValue<CellFill> kFillNames[] = {{CellFill::None, "none"},         {CellFill::Mass, "mass"},
                                               {CellFill::Area, "area"},         {CellFill::Energy, "energy"},
                                               {CellFill::ToCentroid, "distance"}, {CellFill::Moved, "moved"},
                                               {CellFill::Valence, "valence"}};

CellFill parseCellFill(const std::string& name) { return parseName(kFillNames, name, "fill"); }
const char* toString(CellFill fill) { return nameOf(kFillNames, fill); }

std::optional<CellFill> stageFill(std::optional<Stage> stage) {
  if (stage == Stage::Valence) return CellFill::Valence;
  return std::nullopt;
}

Pane parsePane(const std::string& name) {
  constexpr NamedValue<Pane> kPaneNames[] = {
      {Pane::Window, "window"}, {Pane::View3D, "3d"}, {Pane::Domain2D, "2d"}, {Pane::Plots, "plots"}};
  return parseName(kPaneNames, name, "pane");
}

std::string exportPath(const ExportJob& job, int iteration) {
  if (!job.sequence()) return job.path;
  char number[16];
  std::snprintf(number, sizeof number, "_%04d", iteration);
  return std::string(job.path).insert(job.path.size() - 4, number);
}

void refuseReplacing(const std::string& path, const std::string& shown, const std::string& what) {
  if (sameFile(path, shown))
    throw Error(path + ": the " + what + " would replace " + shown + ", the file shown; give it another name");
}

void refuseReplacing(const ExportJob& job, const std::string& shown) {
  if (!job.sequence()) return refuseReplacing(job.path, shown, "picture");
  // Of a sequence's names only the one with the shown file's own number can be it: one check,
  // not one per picture (--iterations 0:2000000000 ran for minutes before its range was refused).
  std::error_code ignored;
  const std::string name =
      std::filesystem::weakly_canonical(std::filesystem::absolute(shown, ignored), ignored).filename().string();
  const size_t dot = name.rfind('.'), underscore = name.rfind('_', dot);
  if (dot == std::string::npos || underscore == std::string::npos) return;
  const std::string digits = name.substr(underscore + 1, dot - underscore - 1);
  if (digits.empty() || digits.size() > 9 || !std::all_of(digits.begin(), digits.end(), ::isdigit)) return;
  if (const int k = std::stoi(digits); k >= job.first && k <= job.last)
    refuseReplacing(exportPath(job, k), shown, "picture");
}

void Inspector::startExport(ExportJob job) {
  // Its pictures would have joined the one running's, and been saved with the next sequence.
  if (exporting()) throw Error(job.path + ": a picture is being saved; wait for it");
  requirePngPath(job.path);
  refuseReplacing(job, shownPath_);
  const int count = replay_->iterationCount();
  const std::string range = "iterations " + std::to_string(job.first) + ":" + std::to_string(job.last);
  if (job.sequence() && job.last < job.first)
    throw Error(range + ": FIRST comes after LAST (the pictures go from FIRST up to LAST)");
  if (job.sequence() && job.last >= count)
    throw Error(meshName() + ": " + range + " do not exist: expected FIRST:LAST within 0:" + std::to_string(count - 1) +
                " (" + std::to_string(count) + " recorded)");
  // Every picture's name, before the first is saved: a folder named as the third stopped the
  // sequence there, the first two written (or replaced).
  for (int k = job.first; k >= 0 && k <= job.last; ++k) requireWritable(exportPath(job, k));
  exportNext_ = job.sequence() ? job.first : iteration_;
  iterationBeforeExport_ = iteration_;
  exportJob_ = std::move(job);
}

void Inspector::savePicture(const std::vector<unsigned char>& png) {
  if (!exportJob_ || !exportRequest_) return;  // ended meanwhile (another run opened)
  if (!pictureFiles_) pictureFiles_ = std::make_unique<FileBatch>();
  pictureFiles_->add(exportRequest_->path, [&](std::ostream& out) {
    out.write(reinterpret_cast<const char*>(png.data()), png.size());
  });
  if (!exportJob_->sequence() || exportNext_ >= exportJob_->last) {  // a picture alone, or a sequence's last
    pictureFiles_->commit();
    pictureFiles_.reset();
  }
  exported();
}

void Inspector::exported(const std::string& error) {
  if (!error.empty()) pictureFiles_.reset();  // none of its pictures replaces a file
  // The bar is hidden while pictures are made (they leave it out): a sequence says so at its end.
  const bool sequence = exportJob_ && exportJob_->sequence();
  if (exportRequest_) {
    if (!error.empty())
      showMessage(error);
    else if (!sequence)
      showMessage(pictureSavedText(exportRequest_->path, 1, exportRequest_->path));
    else if (exportNext_ >= exportJob_->last)
      showMessage(pictureSavedText(exportRequest_->path, exportJob_->last - exportJob_->first + 1,
                                   exportPath(*exportJob_, exportJob_->first)));
  }
  exportRequest_.reset();
  if (error.empty() && exportJob_ && exportJob_->sequence() && exportNext_ < exportJob_->last) {
    ++exportNext_;
  } else {
    // A sequence leaves the timeline where it was (it stayed on the last picture saved).
    if (exportJob_ && exportJob_->sequence()) setIteration(iterationBeforeExport_);
    exportJob_.reset();
  }
}

void OpeningView::applyTo(Inspector& inspector) const {
  try {
    const int count = inspector.iterationCount();
    if (iteration >= count)  // it showed the last one, as if that had been asked
      throw Error("iteration " + std::to_string(iteration) + " does not exist (" + std::to_string(count) +
                  " recorded, numbered from 0)");
    // A stage shown alone is at the lesson's iteration for it, unless one is asked: Load showed
    // the input beside the plots and the status bar of a converged run (iteration 159).
    if (iteration >= 0) inspector.setIteration(iteration);
    else if (stage) inspector.setIteration(stageIteration(*stage, count));
    // Before the pins: the stage decides which result the 3D view shows, and so which one a
    // triangle is pinned in (--stage result --select-worst pinned the iteration's, unseen); and
    // before showFinal(), which fits the view to it (the Result stage of two components framed
    // the largest one's, off centre).
    inspector.showStage(stage);
    inspector.showFinal(final);
    if (fill) inspector.setFill(*fill);
    for (int cell : cells) inspector.pinCell(cell);
    for (int triangle : triangles) inspector.pinTriangle(triangle);
    if (worstTriangle) inspector.pinWorstTriangle();
  } catch (const Error& e) {  // an iteration, a cell or a triangle the file has none of
    throw Error(inspector.meshName() + ": " + e.what());
  }
  if (!camera.empty()) inspector.setCamera(camera);
  inspector.setPresentation(presentation);
  if (compareSolvers) inspector.compareSolvers();
  inspector.setRepairOnOpen(repair);
  inspector.showTimings(timings);
  inspector.plotAgainstTime(plotTime);
}

// The mesh the 3D pane fits: the final result where it is shown (with several components, all
// of them), else the surface the recording is about.
const Mesh& Inspector::fittedMesh() const {
  return finalShown() ? result_.output : replay_->recording().input;
}

void Inspector::fitCamera() {
  const auto [lo, hi] = boundingBox(fittedMesh());
  camera_.lookAtBox(lo, hi);
  fitPending_ = true;  // the distance, once the pane's shape is known
}

// Drawn over the mesh, with no depth test: a seam behind the surface is left out. Its facing
// alone hid the seams of a chart seen from behind, an open sheet whose back is in view.
void Inspector::drawSeams3D(ImDrawList* dl, const ScreenOf3D& screen, const Vec3& eye) const {
  ImVec2 a, b;
  for (const auto& [from, to] : seam3D_)
    if (!seamSurface_->hides(eye, 0.5 * (from + to)) && screen(from, a) && screen(to, b))
      dl->AddLine(a, b, kSeamColor, (presentation_ ? 4.0f : 3.0f) * markScale());
}

const QualityMetrics& Inspector::currentQuality() {
  if (measuredIteration_ != iteration_ || measuredMethod_ != replay_->method()) {
    quality_ = measureQuality(replay_->view(iteration_).measured());
    measuredIteration_ = iteration_;
    measuredMethod_ = replay_->method();
  }
  return quality_;
}

void Inspector::uploadMesh() {
  const IterationView& view = replay_->view(iteration_);
  const Layers shown = layers();
  // The mesh the user opened; from a recording alone, the mesh that was parameterized.
  const bool final = finalShown();
  const Mesh& mesh = final                        ? result_.output
                     : !shown.input3D             ? view.output
                     : input_ && !shown.mapped3D ? *input_
                                                  : replay_->recording().input;
  std::vector<std::array<float, 3>> colors;
  for (const Triangle& t : mesh.triangles) {
    if (!colorByAngle_) {
      colors.push_back({0.78f, 0.8f, 0.85f});
      continue;
    }
    const auto a = cornerAnglesDeg(mesh.points[t[0]], mesh.points[t[1]], mesh.points[t[2]]);
    colors.push_back(angleColor(*std::min_element(a.begin(), a.end())));
  }
  // The GPU's frame: the mesh's box, centred and of size 1.
  const auto [lo, hi] = boundingBox(mesh);
  gpu_ = GpuFrame::ofBox(lo, hi);
  renderer_.upload(mesh, colors, gpu_.origin, gpu_.scale);
  // The seams on the mesh shown; on the user's own mesh (never cut), those of the mesh that was
  // parameterized, whose border vertices lie on it.
  const Mesh& cut = !shown.input3D ? view.output : replay_->recording().input;
  seam3D_.clear();
  std::set<std::pair<int, int>> seams;
  if (!replay_->seams().empty() && !final) {  // the final result is stitched: no seam is apart
    std::vector<std::pair<int, int>> ofTheResult;
    if (!shown.input3D) ofTheResult = seamEdges(cut, seamTolerance(cut));
    const auto& apart = shown.input3D ? replay_->seams() : ofTheResult;
    seams.insert(apart.begin(), apart.end());
  }
  if (!final)  // a chart's seams with the others, either way round
    for (const auto& [a, b] : !shown.input3D ? replay_->sharedSeamsOnOutput() : replay_->recording().sharedSeams) {
      seams.insert({a, b});
      seams.insert({b, a});
    }
  for (const Triangle& t : cut.triangles)
    for (int k = 0; k < 3; ++k)
      if (seams.count({t[k], t[(k + 1) % 3]})) seam3D_.push_back({cut.points[t[k]], cut.points[t[(k + 1) % 3]]});
  seamSurface_.reset();
  if (!seam3D_.empty()) seamSurface_.emplace(cut);
  std::vector<Marker> marks;
  const Shown3D now = shown3D();
  // With the valence fill, the irregular sites are dots of its colours, as their cells are in
  // 2D (the 5s where the surface bulges, the 7s at its saddles); without the sites (the final
  // result shown), the irregular vertices of the mesh shown. First: a site's square at the
  // same depth after it would cover its middle.
  auto markIrregular = [&](const Vec3& at, const VertexValence& s) {
    if (s.irregular()) marks.push_back(marker(gpu_.to(at), 7.0f, MarkerShape::Dot, valenceColor(s)));
  };
  if (now.valences && now.sites && !final) {
    const std::vector<VertexValence> valences = siteValences(view);
    for (size_t i = 0; i < valences.size(); ++i) markIrregular(view.liftedSites[i], valences[i]);
  } else if (now.valences) {
    const std::vector<VertexValence> valences = vertexValences(mesh);
    for (int v = 0; v < mesh.vertexCount(); ++v) markIrregular(mesh.points[v], valences[v]);
  }
  // The Lift stage is about these sites: each on a white halo, which a projector shows over the
  // input's dark wire (3 px squares alone were lost in it).
  if (now.sites && !final)
    for (const Vec3& s : view.liftedSites) {
      if (now.lift) marks.push_back(marker(gpu_.to(s), 7.0f, MarkerShape::Dot, rgb(1.0f, 1.0f, 1.0f)));
      marks.push_back(marker(gpu_.to(s), now.lift ? 4.0f : 3.0f, MarkerShape::Square, rgb(0.1f, 0.15f, 0.45f)));
    }
  renderer_.uploadMarkers(marks);
  uploaded_ = now;
}

CellFill Inspector::fillShown() const { return stageFill(stage_).value_or(fill_); }

bool Inspector::cellsFilled() const { return fillShown() != CellFill::None && layers().cells2D; }

Inspector::Shown3D Inspector::shown3D() const {
  const Layers shown = layers();
  return {iteration_,   shown.input3D,   shown.mapped3D, shown.sites3D, finalShown(),
          colorByAngle_, cellsFilled() && fillShown() == CellFill::Valence, replay_->method(), stage_ == Stage::Lift};
}

float Inspector::markScale() const {
  return presentation_ ? presentationTextSize(ImGui::GetIO().DisplaySize.y) / presentationTextSize(0) : 1.0f;
}

void Inspector::showMessage(std::string text) {
  message_ = inWindowWords(std::move(text));
  messageShownAt_ = ImGui::GetTime();  // the same error twice is news too
}

// Long enough to read it twice at a lecture's pace.
double Inspector::messageSecondsLeft() const {
  if (message_.empty()) return 0;
  return std::max(0.0, 6.0 + 0.06 * message_.size() - (ImGui::GetTime() - messageShownAt_));
}

// Light text on a dark box across the views' foot, over whatever is there (the foreground).
void Inspector::messageOverlay(const ImVec2& pos, float width) {
  // Not in an export's pictures: the next picture showed the last one's "saved ...".
  if (messageSecondsLeft() <= 0 || exporting()) return;
  const float margin = 8, pad = 6, font = ImGui::GetFontSize();
  const float wrap = std::max(1.0f, width - 2 * (margin + pad));
  const ImVec2 text = ImGui::GetFont()->CalcTextSizeA(font, FLT_MAX, wrap, message_.c_str());
  const ImVec2 top(pos.x + margin, pos.y - margin - text.y - 2 * pad);
  ImDrawList* dl = ImGui::GetForegroundDrawList();
  dl->AddRectFilled(top, ImVec2(pos.x + width - margin, pos.y - margin), rgb(0.12f, 0.12f, 0.14f), 4.0f);
  dl->AddText(ImGui::GetFont(), font, ImVec2(top.x + pad, top.y + pad), rgb(1, 1, 1), message_.c_str(), nullptr, wrap);
}

double Inspector::secondsToChange() const {
  if (running() || exportJob_ || fitPending_) return 0;
  double seconds = std::numeric_limits<double>::infinity();
  if (const double message = messageSecondsLeft(); message > 0) seconds = message;  // then it goes
  if (playing_) seconds = std::min<double>(seconds, std::max(0.0f, 1.0f - playClock_) / playSpeed_);
  if (lesson_.playing()) seconds = std::min<double>(seconds, lesson_.secondsToNextStep() / (playSpeed_ / 10.0f));
  return seconds;
}

void Inspector::frame() {
  if (comparing_.started() && comparing_.finished()) {
    // Out of memory, say: said in the window, as a file error is.
    const std::string error = comparing_.join();
    if (error.empty()) comparisons_ = std::move(compared_);
    else showMessage("Compare: " + error);
    compared_.clear();
  }
  collectIterations();
  if (session_ && run_.started() && run_.finished()) stopRunAndFinish();
  // The time since the last frame goes to what was playing then, before the keys change it:
  // the window sleeps between a lesson's steps, and a stage skipped to got the time it had
  // slept on the last one. A frame after one that did not animate (the one that starts
  // playback) counts none: it must not jump ahead by the time the window slept.
  const float elapsed = animatedLastFrame_ ? ImGui::GetIO().DeltaTime : 0.0f;
  if (playing_) {
    playClock_ += elapsed * playSpeed_;
    while (playing_ && playClock_ >= 1.0f) {  // a long sleep plays to the last iteration, no further
      playClock_ -= 1.0f;
      if (iteration_ + 1 >= replay_->iterationCount()) playing_ = false;
      else setIteration(iteration_ + 1);
    }
    if (!playing_) playClock_ = 0;
  }
  if (lesson_.playing()) lesson_.advance(elapsed * playSpeed_ / 10.0f);  // 10 it/s: a lecture's pace
  handleKeys();
  if (lesson_.playing()) {
    setIteration(lesson_.current().iteration);
    stage_ = lesson_.current().stage;
  }
  if (exportJob_ && exportJob_->sequence()) setIteration(exportNext_);
  // Presentation mode's type grows with the window: the font drawn nearest the size, scaled to it.
  const float textSize = presentationTextSize(ImGui::GetIO().DisplaySize.y);
  ImFont* presentationFont = presentationFonts_[presentationFonts_[1] && textSize > 31.5f ? 1 : 0];
  const bool bigFont = presentation_ && presentationFont;
  if (bigFont) ImGui::PushFont(presentationFont);
  // The fonts are drawn at the screen's density (addInspectorFonts), the layout is in units.
  const float unitsPerPixel = 1.0f / ImGui::GetIO().DisplayFramebufferScale.x;
  ImGui::GetIO().FontGlobalScale = !presentation_ ? unitsPerPixel
                                   : bigFont      ? textSize / presentationFont->FontSize
                                                  : 1.6f * textSize / 21.0f * unitsPerPixel;  // ImGui's own font, 13 units
  // Presentation: no controls pane, a taller timeline; a lesson stage adds its caption on top.
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  const float line = ImGui::GetTextLineHeightWithSpacing();
  const float left = presentation_ ? 0.0f : std::max(280.0f, display.x * 0.23f);
  std::optional<Caption> shownCaption;
  float captionHeight = 0;
  if (stage_) {
    const CaptionFacts facts = captionFacts();
    const auto captionOf = [&](Stage stage) {
      Caption c = caption(stage, facts);
      if (!bigFont) {  // ImGui's small font drew the subscripts as grey smudges
        c.formula = inlineIndices(c.formula);
        c.numbers = inlineIndices(c.numbers);
      }
      return c;
    };
    shownCaption = captionOf(*stage_);
    // As tall as the tallest stage's, so that the panes under it keep their place from stage to
    // stage (at 960x600 they moved by up to 18 pixels as the lesson went on).
    for (int stage = 0; stage <= static_cast<int>(Stage::Valence); ++stage)
      captionHeight = std::max(captionHeight, captionPaneHeight(captionOf(static_cast<Stage>(stage)), display.x - left));
  }
  const float timelineHeight = (presentation_ ? 2 * line + 30 : 64.0f) + (timelineWrapped_ ? ImGui::GetFrameHeightWithSpacing() : 0);
  // Presentation: the plots' header, titles and tick labels are in the large font, and a fixed
  // share of the height left their frames 76 pixels tall at 1280x800 (51 with Compare's
  // legends, two labels on each axis): those rows, then frames of a sixth of the height.
  const float plotsHeight = presentation_ ? (comparisons_.empty() ? 3 : 4) * line + std::max(110.0f, display.y / 6)
                                          : std::max(170.0f, display.y * 0.27f);
  const float viewsHeight = display.y - captionHeight - timelineHeight - plotsHeight;
  const float viewWidth = (display.x - left) / 2;
  const float viewsTop = captionHeight, plotsTop = captionHeight + viewsHeight;
  const float rects[4][4] = {{0, 0, display.x, display.y},
                             {left, viewsTop, viewWidth, viewsHeight},
                             {left + viewWidth, viewsTop, display.x - left - viewWidth, viewsHeight},
                             {left, plotsTop, display.x - left, plotsHeight}};
  if (exportJob_) {
    const float* rect = rects[static_cast<int>(exportJob_->pane)];
    const auto pixels = [&](int k) {  // the layout's units in the framebuffer's pixels (rounding kept off)
      return static_cast<int>(rect[k] * ImGui::GetIO().DisplayFramebufferScale.x + 1e-3f);
    };
    exportRequest_ = ExportRequest{exportPath(*exportJob_, exportNext_), {pixels(0), pixels(1), pixels(2), pixels(3)}};
  }
  if (!presentation_) controlsPane(ImVec2(0, 0), ImVec2(left, display.y));
  if (shownCaption) captionPane(*shownCaption, ImVec2(left, 0), ImVec2(display.x - left, captionHeight));
  viewPane3D(ImVec2(left, viewsTop), ImVec2(viewWidth, viewsHeight));
  domainPane2D(ImVec2(left + viewWidth, viewsTop), ImVec2(display.x - left - viewWidth, viewsHeight));
  plotsPane(ImVec2(left, plotsTop), ImVec2(display.x - left, plotsHeight));
  timelinePane(ImVec2(left, plotsTop + plotsHeight), ImVec2(display.x - left, timelineHeight));
  messageOverlay(ImVec2(left, plotsTop), display.x - left);
  if (bigFont) ImGui::PopFont();
  animatedLastFrame_ = animating();
}

bool Inspector::mapIsOfTheInput() const {
  const Mesh& mapped = replay_->recording().input;
  return input_ && mapped.points.size() == input_->points.size() && mapped.triangles == input_->triangles;
}

bool Inspector::finalShown() const {
  if (result_.output.triangles.empty()) return false;
  // The lesson's Result stage at the last iteration shows what remesh writes, as its caption
  // quotes it (it showed the last iteration's mesh before the clean-up, and quoted that).
  if (stage_) return *stage_ == Stage::Result && iteration_ == replay_->iterationCount() - 1;
  return showFinal_;
}

Layers Inspector::layers() const {
  if (stage_) return layersFor(*stage_);
  Layers l;
  l.input3D = showInput_;
  l.sites3D = !showInput_;
  l.triangles2D = showTriangles_;
  l.cells2D = l.sites2D = l.centroids2D = true;
  l.arrows2D = showArrows_;
  return l;
}

void Inspector::toggleLesson() {
  // A stage opened alone (inspect --stage) ends as a lesson does: the button said "Lesson ends
  // it", and started a lesson from its first stage.
  if (lesson_.playing() || stage_) {
    lesson_.stop();
    stage_.reset();
    return;
  }
  // The lesson's plan is made of the iterations there are: started during a run, it ended on
  // an iteration of the run's first second and stayed there.
  if (running()) {
    showMessage("A lesson plays a finished run: Stop the run, or let it finish, then start the lesson.");
    return;
  }
  playing_ = false;
  lesson_.start(lessonPlan(replay_->iterationCount()));
}

CaptionFacts Inspector::captionFacts() {
  CaptionFacts f;
  f.mesh = meshName_;
  f.surface = inputTopology_.describe();
  f.disk = inputTopology_.isDisk();
  // A live run (after Restart) has no result yet: its replay has the seams.
  f.seamEdges = std::max<int>(result_.cut.seamEdges, replay_->seams().size());
  f.charts = inputCharts_;
  f.input = result_.before;
  f.inputIsMapped = !input_;
  f.cleanedUp = finalShown();
  f.result = f.cleanedUp ? result_.after : currentQuality();
  f.param = toString(result_.paramUsed);
  f.border = borderPhrase(result_.paramUsed, result_.borderUsed);
  f.solver = toString(options_.lloyd.solver);
  f.density = toString(options_.density.kind);
  f.method = toString(replay_->method());
  f.firstPass = usesResampling(options_) && result_.resampleDropped.empty() &&
                !(result_.firstPassTrial && result_.firstPassTrial->keptWithout);
  f.distortion = result_.distortion;
  f.iteration = iteration_;
  f.iterations = replay_->iterationCount();
  // A run after Restart, stepped or stopped, has not converged (the Lift stage said "3
  // iterations to convergence" after three Steps). Of the iterations on show: the session's
  // solver is the worker's while it runs.
  f.converged = session_ ? replay_->recording().converged() : result_.converged;
  const IterationRecord& it = replay_->recording().iterations[iteration_];
  f.energy = it.energy;
  f.maxToCentroid = it.maxDisplacement;
  // From the view, not from the 2D pane's last drawing: drawn after the caption, it gave each
  // picture of an exported sequence the magnification of the picture before.
  if (stage_ == Stage::Move)
    f.arrowScale = moveArrowScale(replay_->view(iteration_), replay_->recording().fixedSites.size());
  f.percentMoving = 100.0 * it.fractionMoving;
  if (stage_ == Stage::Valence) {  // of the mesh its percentage is of: a seam sample's two sites are one vertex
    const IrregularCounts irregular = irregularCounts(replay_->view(iteration_).measured());
    f.fives = irregular.fives;
    f.sevens = irregular.sevens;
    f.otherIrregular = irregular.others;
  }
  // The cell pinned last (pinning a second one while the class looks on, the caption stayed on
  // the first), unless this run lacks it (cell 900 after a restart with 500 sites read "Cell -1").
  if (!selection_.cells().empty())
    if (const CellDetails d = describeCell(replay_->recording(), replay_->domain(), replay_->view(iteration_),
                                           selection_.cells().back());
        d.index >= 0)
      f.cell = d;
  return f;
}

std::string Inspector::captionTitle(const Caption& c) const {
  return c.title + (lesson_.paused() && lesson_.playing() ? " (paused: Space plays on)" : "");
}

// Three lines at least; more where the caption wraps to more (at 960x600 in presentation the last
// line was cut off). The pane is the tallest stage's (layout), so that the panes under it stay put.
float Inspector::captionPaneHeight(const Caption& c, float width) const {
  const ImGuiStyle& style = ImGui::GetStyle();
  const float text = captionTextHeight(captionTitle(c), c.formula, c.numbers, width - 2 * style.WindowPadding.x);
  return std::max(3 * ImGui::GetTextLineHeightWithSpacing() + 20, text + 2 * style.WindowPadding.y + 4);
}

void Inspector::captionPane(const Caption& c, const ImVec2& pos, const ImVec2& size) {
  beginPane("Lesson", pos, size, ImGuiWindowFlags_NoTitleBar | kCanvasPaneFlags);
  ImDrawList* dl = ImGui::GetWindowDrawList();
  dl->AddRectFilled(pos, ImVec2(pos.x + size.x, pos.y + size.y), rgb(1.0f, 0.98f, 0.9f));
  captionText(captionTitle(c), c.formula, c.numbers);
  ImGui::End();
}

void Inspector::handleKeys() {
  ImGuiIO& io = ImGui::GetIO();
  // From a text field too (Export PNG's name, typed, is saved at once).
  if (io.KeyCtrl && letterKeyPressed('Q')) closeRequested_ = true;
  if (io.KeyCtrl && letterKeyPressed('S') && !exporting()) saveExport({exportPath_, static_cast<Pane>(exportPane_)});
  if (closeListOnEscape() || !keysAreCommands()) return;
  // During a lesson the keys move through its stages (the lesson sets the iteration each
  // frame); otherwise through the iterations.
  const auto go = [&](long by) {
    if (lesson_.playing()) lesson_.skip(by);
    else setIteration(static_cast<int>(std::clamp<long>(iteration_ + by, 0, std::numeric_limits<int>::max())));
  };
  const long step = io.KeyShift ? 10 : 1, all = std::numeric_limits<int>::max();
  if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_LeftArrow))) go(-step);
  if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_RightArrow))) go(step);
  if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Home))) go(-all);
  if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_End))) go(all);
  if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape))) selection_.clear();
  if (letterPressed('P')) presentation_ = !presentation_;
  if (letterPressed('L')) toggleLesson();
  if (letterPressed('T')) plotTime_ = !plotTime_;  // classroom mode has no box to tick
  if (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Space), false)) togglePlay();
}

// Play or pause: the lesson where one is playing, else the iterations (from the first again
// once at the last).
void Inspector::togglePlay() {
  if (lesson_.playing()) return lesson_.togglePause();
  if (!playing_ && iteration_ + 1 >= replay_->iterationCount()) setIteration(0);
  playing_ = !playing_;
}

void Inspector::controlsPane(const ImVec2& pos, const ImVec2& size) {
  beginPane("Lloydscope", pos, size);
  runSummary();
  qualityTable();
  runStatus();
  selectionControls();
  viewControls();
  cameraControls();
  settingsControls();
  fileControls();
  exportControls();
  ImGui::End();
}

// The mesh, the run's settings and sites, and which result the panes show.
void Inspector::runSummary() {
  wrappedText("Mesh: " + meshName_);
  if (const std::string part = recordedPartText(replay_->recording().settings); !part.empty()) wrappedText(part);
  wrappedText(std::string("Parameterization: ") + toString(result_.paramUsed) + " (" +
              borderPhrase(result_.paramUsed, result_.borderUsed) + "), density: " +
              toString(options_.density.kind) + ", solver: " + toString(options_.lloyd.solver));
  ImGui::Text("Sites: %zu fixed, %zu movable", replay_->recording().fixedSites.size(),
              replay_->recording().iterations.empty()
                  ? size_t(0)
                  : replay_->recording().iterations[0].sites.size());
  ImGui::TextUnformatted(thresholdsText(options_.lloyd).c_str());
  ImGui::Separator();
  int method = replay_->method() == RemeshMethod::Relocate ? 0 : 1;
  ImGui::TextUnformatted("Result");
  sameLineIfFits(radioWidth("relocate"));
  // Greyed, with why, where the run's sites are not the input's vertices: clicked, it did
  // nothing, and its explanation showed for one frame.
  const bool canRelocate = replay_->canRelocate();
  if (!canRelocate) ImGui::BeginDisabled();
  if (ImGui::RadioButton("relocate", &method, 0)) replay_->setMethod(RemeshMethod::Relocate);
  if (!canRelocate) ImGui::EndDisabled();
  sameLineIfFits(radioWidth("retriangulate"));
  if (ImGui::RadioButton("retriangulate", &method, 1)) replay_->setMethod(RemeshMethod::Retriangulate);
  if (!canRelocate) greyedText(relocateNeedsText(input_.has_value()));

}

// The report's Table II: the input, this iteration's result and the final one.
void Inspector::qualityTable() {
  ImGui::Separator();
  // The final result (what remesh writes: the iteration's mesh after the clean-up on the
  // surface, stitched or put together from its charts) where the run finished and measured it.
  const QualityMetrics& finalResult = result_.after;
  const bool showFinal = finalResult.vertices > 0;
  // A recording holds the mesh its map is of (a first remeshing of the input, say), not the input.
  const char* first = input_ ? "Input" : "Mapped";
  // A run's lines take as many rows as its result's will: the Files section under them jumped
  // by 30 pixels as the run ended, under the pointer that had clicked Open mesh.
  const bool finalComing = showFinal || session_;
  wrappedText(std::string(input_ ? "Input" : "The mesh the map is of (a recording holds no input)") +
              (finalComing ? ", the current iteration's result and the final one, after the clean-up "
                             "(the report's Table II)"
                           : " and the current iteration's result (the report's Table II)"));
  const QualityMetrics& current = currentQuality();
  const std::string iterationHeader = "It. " + std::to_string(iteration_);
  const int columnCount = showFinal ? 3 : 2;
  const QualityMetrics* columns[] = {&result_.before, &current, &finalResult};
  // The rows formatted first, for the columns' widths (numberColumnWidth).
  std::vector<std::pair<const char*, std::array<std::string, 3>>> rows;
  auto row = [&](const char* label, const auto& value) {
    std::array<std::string, 3> cells;
    for (int k = 0; k < columnCount; ++k) cells[k] = value(*columns[k]);
    rows.emplace_back(label, cells);
  };
  auto oneDecimal = [](double QualityMetrics::*m) {
    return [m](const QualityMetrics& q) { return format("%.1f", q.*m); };
  };
  row("Vertices", [](const QualityMetrics& q) { return std::to_string(q.vertices); });
  row("Faces", [](const QualityMetrics& q) { return std::to_string(q.faces); });
  row("Irregular %", oneDecimal(&QualityMetrics::irregularPercent));
  row(" border-aware", oneDecimal(&QualityMetrics::irregularBoundaryAware));
  row("Min angle", oneDecimal(&QualityMetrics::minAngle));
  row("Avg min angle", oneDecimal(&QualityMetrics::avgMinAngle));
  row("Under 30\u00b0 %", oneDecimal(&QualityMetrics::percentUnder30));
  if (ImGui::BeginTable("metrics", columnCount + 1, ImGuiTableFlags_Borders | ImGuiTableFlags_RowBg)) {
    ImGui::TableSetupColumn("", ImGuiTableColumnFlags_WidthStretch);
    const char* headers[] = {first, iterationHeader.c_str(), "Final"};
    for (int k = 0; k < columnCount; ++k) {
      std::vector<std::string> values;
      for (const auto& r : rows) values.push_back(r.second[k]);
      ImGui::TableSetupColumn(headers[k], ImGuiTableColumnFlags_WidthFixed, numberColumnWidth(headers[k], values));
    }
    ImGui::TableHeadersRow();
    for (const auto& [label, cells] : rows) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      wrappedText(label);  // in a narrow pane (960x600) a long label ran into its value
      for (int k = 0; k < columnCount; ++k) {
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(cells[k].c_str());
      }
    }
    ImGui::EndTable();
  }
  if (replay_->method() == RemeshMethod::Retriangulate) {
    const IterationView& view = replay_->view(iteration_);
    const std::string leftOut = sitesLeftOutNote(iteration_, view.sites.size(), view.output.points.size());
    if (!leftOut.empty()) greyedText(leftOut);
  }
}

// Where the run is, how far the result is from the input, how it was made, and Compare.
void Inspector::runStatus() {
  const std::string iterations = iterationsText(replay_->iterationCount());
  // Two lines at least, which every state takes at 960 and wider: the controls under them keep
  // their place (a state of three lines, in a narrower pane, still moves them).
  if (session_ && running())
    wrappedTextInLines("Running: " + iterations + " so far", 2);
  else if (session_ && session_->finished())  // for the frame before finishSession() (a second)
    wrappedTextInLines("Done after " + iterations + ": the clean-up on the surface follows", 2);
  else if (session_)
    wrappedTextInLines("Stopped after " + iterations + ": Step or Run goes on", 2);
  else
    wrappedTextInLines("Final: " + iterations + (replay_->recording().converged() ? ", converged" : ", not converged"), 2);
  wrappedTextInLines(shownDistanceText(result_.fidelity, options_.measureFidelity, session_ != nullptr), 2);
  if (showTimings_ && !session_ && result_.ms.total > 0)  // a recording opened alone has no times
    ImGui::Text("Time: %.0f ms (Lloyd %.0f ms)", result_.ms.total, result_.ms.lloyd);
  else if (showTimings_ && session_)
    ImGui::TextUnformatted("Time: when the run has finished");
  // How this result was made (trials, a simplified input) or why its run failed: beside the
  // numbers it explains, not under the controls.
  if (!runNotes_.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(0.45f, 0.2f, 0.0f, 1.0f));
    wrappedText(runNotes_);
    ImGui::PopStyleColor();
  }
  const std::vector<CvtSolver> others = otherSolvers(options_.lloyd.solver);
  const std::string withOthers = std::string("with ") + toString(others[0]) + " and " + toString(others[1]);
  // Their curves join the convergence plots when done. During a run the button waits (it was
  // hidden, and a class did not know it was there).
  const bool comparing = comparing_.started();
  if (comparing || running()) ImGui::BeginDisabled();
  if (ImGui::Button(((comparing ? "Comparing " : "Compare ") + withOthers + (comparing ? "..." : "")).c_str()))
    startComparing();
  if (comparing || running()) ImGui::EndDisabled();
  if (running() && ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
    ImGui::SetTooltip("After the run: Stop it, or let it finish");
}

void Inspector::selectionControls() {
  if (ImGui::CollapsingHeader("Selection", ImGuiTreeNodeFlags_DefaultOpen)) {
    int pick = pickTriangles2D_ ? 1 : 0;
    ImGui::TextUnformatted("2D click pins a");
    sameLineIfFits(radioWidth("cell"));
    ImGui::RadioButton("cell", &pick, 0);
    sameLineIfFits(radioWidth("triangle"));
    ImGui::RadioButton("triangle", &pick, 1);
    pickTriangles2D_ = pick == 1;
    if (ImGui::Button("Pin the worst triangle")) pinWorstTriangle();
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("The triangle with the smallest angle in the result the 3D view shows: this iteration's, or the final one (--select-worst)");
    if (stage_) {  // pins listed below, beside a stage that draws them in neither view
      const bool resultDrawn = iterationResultIn2D() || iterationResultIn3D();
      if (const std::string note = pinsLeftOutByStage(toString(*stage_), !layers().cells2D && !selection_.cells().empty(),
                                                      !resultDrawn && selection_.trianglesPinned());
          !note.empty())
        greyedText(note);
    }
    selection_.detailsPanel(replay_->recording(), replay_->domain(), replay_->view(iteration_), result_.output);
  }
}

// What the 2D and 3D views draw.
void Inspector::viewControls() {
  ImGui::Separator();
  // During a lesson its stage sets what the views show: the switches say what it set, greyed
  // (the Result stage showed the final result beside an unticked "show the final result").
  const ViewSwitches shown = viewSwitches(layers(), finalShown());
  bool triangles = shown.triangles, arrows = shown.arrows, showInput = shown.input, finalOn = shown.final;
  if (stage_) {
    ImGui::BeginDisabled();
    wrappedText("The lesson's stage sets the views (Lesson ends it):");
  }
  ImGui::TextUnformatted("2D view");
  if (ImGui::Checkbox("parameter triangles", &triangles)) showTriangles_ = triangles;
  if (ImGui::Checkbox("site -> centroid arrows", &arrows)) showArrows_ = arrows;
  const char* fills[] = {"no fill", "mass", "area", "energy", "distance to centroid",
                         "moved since k-1", "valence"};
  // A fill shows over the lesson's cells too; a stage with no cells, or its own fill, keeps it
  // greyed at the fill it shows (the Valence stage read "no fill" beside cells filled by valence,
  // and a choice there did nothing).
  const bool fillChosen = !stage_ || (layers().cells2D && !stageFill(stage_));
  int fill = static_cast<int>(fillShown());
  if (stage_ && fillChosen) ImGui::EndDisabled();
  if (ImGui::Combo("cell fill", &fill, fills, IM_ARRAYSIZE(fills)) && fillChosen) fill_ = static_cast<CellFill>(fill);
  if (stage_ && fillChosen) ImGui::BeginDisabled();
  ImGui::TextUnformatted("3D view");
  // One or the other, the last ticked (ticking the input under the final result did nothing, and
  // the input came back when the final result was unticked).
  const auto setFinal = [&](bool on) {
    showFinal_ = on;
    if (result_.components > 1 || inputCharts_ > 0) fitCamera();
  };
  if (ImGui::Checkbox("show the input instead", &showInput)) {
    showInput_ = showInput;
    if (showInput && showFinal_) setFinal(false);
  }
  if (result_.output.triangles.empty() && !stage_) ImGui::BeginDisabled();
  // With several components, or charts, the final result is larger than the surface the panes
  // follow (the largest component or chart): the view fits the one shown.
  if (ImGui::Checkbox("show the final result", &finalOn)) {
    setFinal(finalOn);
    if (finalOn) showInput_ = false;
  }
  if (result_.output.triangles.empty() || stage_) ImGui::EndDisabled();
  bool byAngle = colorByAngle_;
  if (ImGui::Checkbox("colour by minimum angle", &byAngle)) colorByAngle_ = byAngle;
  ImGui::Checkbox("wireframe", &wireframe_);
  ImGui::TextUnformatted("Convergence plots");
  bool time = plotsAgainstTime();
  if (!showTimings_) ImGui::BeginDisabled();
  if (ImGui::Checkbox("against time (ms), not iterations", &time)) plotTime_ = time;
  if (!showTimings_) ImGui::EndDisabled();
  if (!showTimings_ && ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
    ImGui::SetTooltip("Timings are off (--no-timings)");
}

void Inspector::cameraControls() {
  if (ImGui::Button("Fit view (F)")) fitCamera();
  sameLineIfFits(buttonWidth("Copy view"));
  if (ImGui::Button("Copy view")) ImGui::SetClipboardText(cameraText().c_str());
  sameLineIfFits(buttonWidth("Paste view"));
  if (ImGui::Button("Paste view")) {
    const char* text = ImGui::GetClipboardText();
    try {
      setCamera(text ? text : "");
      message_.clear();
    } catch (const Error& e) {
      showMessage(e.what());
    }
  }
}

// An export asked for from the window: its start, or why not, in the message line.
void Inspector::saveExport(ExportJob job) {
  try {
    startExport(std::move(job));
    showMessage(std::string("saving ") + exportPath_);
  } catch (const Error& e) {
    showMessage(e.what());
  }
}

void Inspector::exportControls() {
  if (!ImGui::CollapsingHeader("Export PNG")) return;
  ImGui::SetNextItemWidth(-1);
  ImGui::InputText("##export", exportPath_, sizeof exportPath_);
  ImGui::SetNextItemWidth(110);
  ImGui::Combo("pane", &exportPane_, "window\0" "3D view\0" "2D view\0" "plots\0");
  const Pane pane = static_cast<Pane>(exportPane_);
  const bool saving = exporting();  // a click below starts one: the same for both ends
  if (saving) ImGui::BeginDisabled();
  if (ImGui::Button("Save this iteration (Ctrl+S)")) saveExport({exportPath_, pane});
  ImGui::SetNextItemWidth(60);
  // Iterations are numbered from 0: a negative one, which ExportJob reads as "the current
  // iteration alone", saved one unnumbered picture for a sequence -5 to 1.
  if (ImGui::InputInt("##first", &exportFirst_, 0)) exportFirst_ = std::max(0, exportFirst_);
  ImGui::SameLine();
  ImGui::TextUnformatted("to");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(60);
  // The last iteration, as a run grows, until the user types another.
  int last = exportLast_.value_or(replay_->iterationCount() - 1);
  if (ImGui::InputInt("##last", &last, 0)) exportLast_ = last = std::max(0, last);
  ImGui::SameLine();
  if (ImGui::Button("Save sequence")) saveExport({exportPath_, pane, exportFirst_, last});
  if (saving) ImGui::EndDisabled();
  greyedText("a sequence is numbered: name_0000.png, ...");  // wrapped: TextDisabled ran off the pane
}

void Inspector::settingsControls() {
  if (!input_ || !ImGui::CollapsingHeader("Settings (remesh again)")) return;
  auto combo = [](const char* label, int& value, const char* items) {
    ImGui::SetNextItemWidth(130);
    return ImGui::Combo(label, &value, items);
  };
  ImGui::SetNextItemWidth(130);
  ImGui::InputInt("simplify to (0: no)", &settings_.simplifyTo, 100, 1000);
  int param = static_cast<int>(settings_.param.method);
  if (combo("parameterization", param, "auto\0authalic\0conformal\0mean-value\0tutte\0lscm\0"))
    settings_.param.method = static_cast<ParamMethod>(param);
  int border = static_cast<int>(settings_.param.border);
  if (combo("border", border, "square\0circle\0rectangle\0")) settings_.param.border = static_cast<Border>(border);
  int density = static_cast<int>(settings_.density.kind);
  if (combo("density", density, "uniform\0area\0curvature\0"))
    settings_.density.kind = static_cast<DensityKind>(density);
  // A weight as the command line takes it, finite and not negative (the step buttons went
  // below 0, and a negative weight made negative densities), else the one before.
  const auto weight = [](const char* label, double& value) {
    const double before = value;
    ImGui::SetNextItemWidth(130);
    if (ImGui::InputDouble(label, &value, 0.1, 1.0, "%.2f") && !(value >= 0 && std::isfinite(value))) value = before;
  };
  if (settings_.density.kind == DensityKind::Curvature) {
    weight("alpha", settings_.density.alpha);
    weight("beta", settings_.density.beta);
  }
  int method = settings_.method == RemeshMethod::Relocate ? 0 : 1;
  if (combo("method", method, "relocate\0retriangulate\0"))
    settings_.method = method == 0 ? RemeshMethod::Relocate : RemeshMethod::Retriangulate;
  int solver = static_cast<int>(settings_.lloyd.solver);  // in CvtSolver's order
  if (combo("solver", solver, "lloyd\0lbfgs\0newton\0"))
    settings_.lloyd.solver = static_cast<CvtSolver>(solver);
  bool own = settings_.sites.fromInputVertices;
  if (ImGui::Checkbox("sites = input vertices", &own)) settings_.sites.fromInputVertices = own;
  if (!own) {
    ImGui::SetNextItemWidth(130);
    ImGui::InputInt("sites (0: as input)", &settings_.sites.count, 100, 1000);
  }
  // Within the command line's bounds: a distance above 0, a percentage from 0 to 100, at most
  // kMostIterations (the run is recorded whole: one that never converges grows to its limit).
  ImGui::SetNextItemWidth(130);
  const double distance = settings_.lloyd.distanceThreshold;
  if (ImGui::InputDouble("distance thr.", &settings_.lloyd.distanceThreshold, 0, 0, "%.1e") &&
      !(settings_.lloyd.distanceThreshold > 0 && std::isfinite(settings_.lloyd.distanceThreshold)))
    settings_.lloyd.distanceThreshold = distance;
  ImGui::SetNextItemWidth(130);
  ImGui::InputDouble("percent thr.", &settings_.lloyd.percentThreshold, 1, 5, "%.1f");
  if (!(settings_.lloyd.percentThreshold >= 0)) settings_.lloyd.percentThreshold = 0;  // NaN too
  settings_.lloyd.percentThreshold = std::min(settings_.lloyd.percentThreshold, 100.0);
  ImGui::SetNextItemWidth(130);
  ImGui::InputInt("polish (-1: none)", &settings_.polish, 1, 1);
  ImGui::SetNextItemWidth(130);
  ImGui::InputInt("max iterations", &settings_.lloyd.maxIterations, 10, 100);
  keepWithinCommandLineBounds(settings_);
  // Wrapped: the pane is narrower than the line (it ran past its edge).
  greyedText("then Restart below the plots: the run on screen keeps its own settings until then");
}

void Inspector::fileControls() {
  if (!ImGui::CollapsingHeader("Files")) return;
  ImGui::SetNextItemWidth(-1);
  ImGui::InputText("##mesh", meshPath_, sizeof meshPath_);
  const std::string samples[] = {"assets/bumpy_disk.off", "assets/sphere_cap.off",
                                 "assets/jittered_grid.off", "data/cgal/nefertiti.off",
                                 "data/cgal/mushroom.off"};
  ImGui::SetNextItemWidth(170);
  if (ImGui::BeginCombo("##samples", "bundled meshes")) {
    for (const std::string& sample : samples)
      if (ImGui::Selectable(sample.c_str()))
        std::snprintf(meshPath_, sizeof meshPath_, "%s/%s", LLOYDSCOPE_SOURCE_DIR, sample.c_str());
    ImGui::EndCombo();
  }
  ImGui::SameLine();
  const bool open = ImGui::Button("Open mesh");
  ImGui::Checkbox("repair the mesh as it is opened", &repairOnOpen_);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("Weld vertices at one position, drop zero-area faces, turn faces\n"
                      "against their neighbours (--repair); a note says what changed");
  if (open) {
    try {
      // Read before the run is stopped (startSession stops it): a missing or bad file left
      // the run stopped, at iteration 206, beside its error.
      ReadResult read = readMesh(meshPath_, ReadOptions{repairOnOpen_});
      const std::string name = fileNameOf(meshPath_);
      settings_.slitDisks = asked_.slitDisks;  // not what remesh() chose for the previous mesh
      settings_.resample = asked_.resample;
      settings_.sites.keptBorderPoints.clear();  // the last mesh's corners
      if (simplifiedAfterFailure_ > 0 && settings_.simplifyTo == simplifiedAfterFailure_) settings_.simplifyTo = 0;  // a typed one stays
      simplifiedAfterFailure_ = 0;
      // An earlier file's error or save; before the run opens, whose own messages stay (a
      // sequence it ends unsaved said so, then went unseen).
      message_.clear();
      try {
        startSession(read.mesh, name);
      } catch (const Error& e) {
        // The last run stays on show, under its own name (the new mesh's name and numbers
        // beside its panes said they were the new mesh's).
        throw Error(std::string(e.what()) + "; still showing " + meshName_);
      }
      input_ = std::move(read.mesh);
      meshName_ = name;
      shownPath_ = meshPath_;
      inputTopology_ = analyzeTopology(*input_);
      inputCharts_ = 0;  // a session makes one run, of one disk
      inputComponents_ = 1;
      result_.before = measureQuality(*input_);
      for (const std::string& note : read.notes) noteFirst(note);
      startRun();
    } catch (const Error& e) {
      showMessage(e.what());
    }
  }
  ImGui::SetNextItemWidth(-1);
  ImGui::InputText("##recording", recordingPath_, sizeof recordingPath_);
  if (ImGui::Button("Save recording")) {
    try {
      refuseReplacing(recordingPath_, shownPath_, "recording");
      requireRecordingName(recordingPath_);  // before the run stops for it
      stopRunAndFinish();
      saveRecording(replay_->recording(), recordingPath_);
      showMessage(std::string("saved ") + recordingPath_);
    } catch (const Error& e) {
      showMessage(e.what());
    }
  }
  ImGui::SameLine();
  if (ImGui::Button("Open recording")) {
    try {
      RecordedRun run = recordedRun(loadRecording(recordingPath_));  // before the run stops, as for a mesh
      stopRun();
      session_.reset();
      input_.reset();
      inputCharts_ = 0;
      inputComponents_ = 1;
      forgetResult();
      // Its own name, settings, map and iterations, as `inspect` opens it (the last run's name,
      // solver and thresholds stayed on show, and Compare ran the recording's own solver again).
      options_ = run.options;
      settings_ = options_;
      keepWithinCommandLineBounds(settings_);  // the next mesh's run
      asked_ = {options_.slitDisks, options_.resample};
      simplifiedAfterFailure_ = 0;
      result_ = std::move(run.result);
      message_.clear();  // as for a mesh
      openReplay(std::move(result_.recording));
      result_.recording = Recording{};  // the replay holds it
      inputTopology_ = replay_->surface();
      meshName_ = fileNameOf(recordingPath_);
      shownPath_ = recordingPath_;
    } catch (const Error& e) {
      showMessage(e.what());
    }
  }
}

void Inspector::viewPane3D(const ImVec2& pos, const ImVec2& size) {
  beginPane("3D view", pos, size, kCanvasPaneFlags);
  const auto [p0, extent] = canvasArea();
  ImGui::InvisibleButton("canvas3d", extent,
                         ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight);
  ImGuiIO& io = ImGui::GetIO();
  if (ImGui::IsItemActive() && ImGui::IsMouseDragging(ImGuiMouseButton_Left))
    camera_.orbit(io.MouseDelta.x, io.MouseDelta.y);
  if (ImGui::IsItemHovered() && io.MouseWheel != 0) camera_.zoom(io.MouseWheel, boundingBoxDiagonal(fittedMesh()));
  if (ImGui::IsItemHovered() && letterPressed('F'))
    fitCamera();

  const Layers shown = layers();
  const bool final = finalShown();
  ViewLabel3D facts;
  facts.final = final;
  if (result_.fidelity.samples > 0) facts.hausdorffPercent = result_.fidelity.hausdorffPercent;
  facts.result = !shown.input3D;
  facts.iteration = iteration_;
  facts.method = toString(replay_->method());
  facts.input = input_ && (!shown.mapped3D || mapIsOfTheInput());
  facts.charts = inputCharts_;
  facts.components = inputComponents_;
  facts.simplified = options_.simplifyTo > 0 || result_.coarseInput > 0;
  // Wrapped in the pane (the final result's ran past its edge at 960 pixels), the colour bar
  // under it. The mesh is centred and fitted in the pane under the label (at 960x600 the two
  // lines of the final result's label covered the top of the lion's head).
  const std::string wrapped = wrappedLines(viewLabel3D(facts), extent.x - 20);
  const float labelBand = std::min(ImGui::CalcTextSize(wrapped.c_str()).y + 8, 0.3f * extent.y);
  if (!(uploaded_ == shown3D())) uploadMesh();

  if (clickedNotDragged()) pick3D(io.MousePos, p0, extent, labelBand);  // not the end of an orbit
  if (fitPending_) {
    camera_.distance = camera_.fittingDistance(fittedMesh().points, extent.x, extent.y - labelBand);
    fitPending_ = false;
  }
  const auto [viewProjection, eyeAt] = camera_.matrices(gpu_, extent.x, extent.y, labelBand);

  ImDrawList* dl = ImGui::GetWindowDrawList();
  MeshDraw& draw = meshCallback_.second;
  meshCallback_.first = &renderer_;
  draw.wireframe = wireframe_;
  draw.wireWidth = (presentation_ ? 2.2f : 1.2f) * markScale();
  draw.markerScale = markScale();
  std::copy(glm::value_ptr(viewProjection), glm::value_ptr(viewProjection) + 16,
            draw.viewProjection.begin());
  draw.viewport[0] = p0.x;
  draw.viewport[1] = p0.y;
  draw.viewport[2] = extent.x;
  draw.viewport[3] = extent.y;
  dl->AddCallback(drawMeshCallback, &meshCallback_);
  dl->AddCallback(ImDrawCallback_ResetRenderState, nullptr);
  dl->PushClipRect(p0, ImVec2(p0.x + extent.x, p0.y + extent.y), true);
  auto toScreen = [&](const Vec3& p, ImVec2& screen) {
    const glm::vec4 c = viewProjection * glm::vec4(glmOf(gpu_.to(p)), 1.0f);
    if (c.w <= 0) return false;
    screen = ImVec2(p0.x + (c.x / c.w * 0.5f + 0.5f) * extent.x,
                    p0.y + (c.y / c.w * 0.5f + 0.5f) * extent.y);
    return true;
  };
  const Vec3 eye = gpu_.from(eyeAt);  // the mesh's frame
  drawSeams3D(dl, toScreen, eye);
  if (final) {
    ImVec2 at;  // drawn over the mesh: where the result strays farthest is often behind a tip
    if (result_.fidelity.samples > 0 && toScreen(result_.fidelity.farthestPoint, at)) {
      const float r = (presentation_ ? 14.0f : 9.0f) * markScale(), width = (presentation_ ? 4.0f : 2.5f) * markScale();
      // On a white halo: over red (0°) triangles the red ring was lost.
      dl->AddCircle(at, r, IM_COL32(255, 255, 255, 230), 24, width + 3.0f);
      dl->AddCircle(at, r, kFarthestColor, 24, width);
    }
  }
  // Pinned cells lie on the input surface, under the final result too (they were not drawn
  // over it); pinned triangles are the iteration's result's or the final result's, each drawn
  // over its own mesh, or the iteration's over the input between its lifted sites (the Voronoi
  // to Lift stages).
  selection_.draw3D(dl, replay_->recording(), replay_->domain(), replay_->view(iteration_), toScreen, eye,
                    shown.cells2D, pinnedTrianglesIn3D());
  if (final) selection_.drawFinal3D(dl, result_.output, toScreen, eye);
  dl->PopClipRect();

  boxedText(dl, ImVec2(p0.x + 8, p0.y + 4), wrapped.c_str());
  if (colorByAngle_)
    drawColorBar(dl, ImVec2(p0.x + 10, p0.y + ImGui::CalcTextSize(wrapped.c_str()).y + 0.5f * ImGui::GetFontSize() + 4.5f),
                 kColorBarWidth * markScale(), kFillBarHeight * markScale(), "60 deg", "0 deg", [](float t) {
                   const auto c = angleColor(60.0 * t);
                   return rgb(c[0], c[1], c[2]);
                 });
  ImGui::End();
}

const std::vector<std::pair<Vec2, Vec2>>& Inspector::cellEdges() {
  if (edgesIteration_ != iteration_) {
    cellEdges_ = voronoiEdges(replay_->domain(), replay_->view(iteration_).cells);
    edgesIteration_ = iteration_;
  }
  return cellEdges_;
}

void Inspector::domainPane2D(const ImVec2& pos, const ImVec2& size) {
  beginPane("2D parameter domain", pos, size, kCanvasPaneFlags);
  const auto [p0, extent] = canvasArea();
  ImGui::InvisibleButton("canvas2d", extent, ImGuiButtonFlags_MouseButtonLeft);
  ImGuiIO& io = ImGui::GetIO();
  // The domain fits above the legend (in large type it covered the domain's foot), which takes
  // two lines where the pane is narrower than it (960x600).
  const Layers shown = layers();
  const bool seams = !replay_->seams().empty() || !replay_->recording().sharedSeams.empty();
  const std::string legend = wrappedLines(
      domainLegend(shown.sites2D, shown.centroids2D, seams, presentation_ && pickTriangles2D_), extent.x - 16, "  ");
  const ImVec2 legendSize = ImGui::CalcTextSize(legend.c_str());
  const float legendHeight = legendSize.y;
  // A fill's legend (its name over a colour bar, top left) has its own room too: over the
  // domain it hid a square domain's corner cells.
  const bool filled = cellsFilled();
  const float fillTop = filled ? fillLegendTop() : 0.0f;
  const float fillLeft = filled ? fillLegendWidth() : 0.0f;
  const float fitWidth = std::max(1.0f, extent.x - fillLeft);
  const float fitHeight = std::max(1.0f, extent.y - legendHeight - 10 - fillTop);
  const auto [lo, hi] = boundingBox(replay_->domain().uv());
  const PaneFit fit = fitBox(lo, hi, glm::vec2(p0.x + fillLeft + fitWidth / 2, p0.y + fillTop + fitHeight / 2),
                             fitWidth, fitHeight);
  if (ImGui::IsItemActive() && ImGui::IsMouseDragging(ImGuiMouseButton_Left))
    view2D_.pan += glm::vec2(io.MouseDelta.x, io.MouseDelta.y);
  const glm::vec2 mouse(io.MousePos.x, io.MousePos.y);
  if (ImGui::IsItemHovered() && io.MouseWheel != 0) view2D_.zoomAt(io.MouseWheel, mouse, fit);
  if (ImGui::IsItemHovered() && letterPressed('F')) fit2D();
  const float scale = fit.base * view2D_.zoom;
  auto screen = [&](const Vec2& uv) {
    const glm::vec2 at = view2D_.toScreen(uv, fit);
    return ImVec2(at.x, at.y);
  };
  const ImVec2 center = screen(Vec2(0.5, 0.5));  // the canvas draws about the unit square's middle
  const Vec2 mouseUV = view2D_.toDomain(mouse, fit);
  // Cells and triangles are offered where they are drawn: the lesson's load stage, which draws
  // neither, offered one to pin under the pointer.
  const bool picks = pickTriangles2D_ ? iterationResultIn2D() : layers().cells2D;
  if (picks && clickedNotDragged())
    pick2D(mouseUV);  // not the end of a pan
  else if (picks && ImGui::IsItemHovered() && !ImGui::IsItemActive())
    hoverTooltip2D(mouseUV);

  ImDrawList* dl = ImGui::GetWindowDrawList();
  dl->PushClipRect(p0, ImVec2(p0.x + extent.x, p0.y + extent.y), true);
  const CanvasKey key{iteration_, fillShown(), layers(), presentation_, scale, replay_->method()};
  if (!(key == canvasKey_)) {
    canvas_.upload(buildCanvas(scale));
    canvasKey_ = key;
  }
  CanvasDraw draw{{p0.x, p0.y, extent.x, extent.y}, center.x, center.y, scale};
  draw.lineWidth = presentation_ ? 2.0f : 1.0f;
  canvasCallback_ = {&canvas_, draw};
  dl->AddCallback(
      [](const ImDrawList*, const ImDrawCmd* cmd) {
        const auto* d = static_cast<const std::pair<const CanvasRenderer*, CanvasDraw>*>(cmd->UserCallbackData);
        d->first->draw(gCommandBuffer, d->second);
      },
      &canvasCallback_);
  dl->AddCallback(ImDrawCallback_ResetRenderState, nullptr);
  // The domain's border, thick, on top (a few hundred lines: ImDrawList is fine for those).
  const Domain& domain = replay_->domain();
  for (size_t t = 0; t < domain.triangles().size(); ++t)
    for (int k = 0; k < 3; ++k)
      if (domain.neighbours()[t][(k + 2) % 3] < 0) {
        const Triangle& tri = domain.triangles()[t];
        dl->AddLine(screen(domain.uv()[tri[k]]), screen(domain.uv()[tri[(k + 1) % 3]]),
                    rgb(0.15f, 0.15f, 0.15f), 2.0f);
      }
  const float legendTop = p0.y + extent.y - legendHeight - 5;
  selection_.draw2D(dl, replay_->recording(), replay_->view(iteration_), screen, scale, shown.cells2D,
                    iterationResultIn2D(),
                    {ImVec4(p0.x + 6, legendTop, p0.x + 10 + legendSize.x, legendTop + legendSize.y)});
  if (filled) fillLegend(dl, ImVec2(p0.x + 10, p0.y + 4), legendTop - 4);
  boxedText(dl, ImVec2(p0.x + 8, legendTop), legend.c_str());
  // Sites a few pixels apart are a blob of dots and rings (1000 sites in presentation mode at
  // 960x600): the pane says how to see them. Where they are closest, not on average: a map
  // squeezes some parts of the surface (the camel head's middle, 2-5 px where the mean was 9).
  // In the room right of the domain where there is some (a wide, low pane); where there is
  // none, over its corner only while the mouse, which can zoom, is over the pane (it hid cells
  // in every picture of a small pane, where no mouse can zoom). In classroom mode only while
  // the mouse is there: on a slide it was a column of five words beside the diagram.
  const float room = p0.x + extent.x - screen(hi).x - 12;
  if (const std::string text = crowdedSitesHint(
          closeSiteSpacing(replay_->view(iteration_).cells, replay_->recording().fixedSites.size()) * scale);
      shown.sites2D && !text.empty() && ((room >= 80 && !presentation_) || ImGui::IsWindowHovered())) {
    const std::string hint = wrappedLines(text, room >= 80 ? room : 0.5f * extent.x);
    boxedText(dl, ImVec2(p0.x + extent.x - ImGui::CalcTextSize(hint.c_str()).x - 8, p0.y + 4 + (filled ? fillLegendTop() : 0.0f)),
              hint.c_str());
  }
  dl->PopClipRect();
  ImGui::End();
}

// What the cells' colours mean: the quantity, and its colour bar (or its one value).
void Inspector::fillLegend(ImDrawList* dl, const ImVec2& at, float bottom) const {
  constexpr const char* kNames[] = {"", "mass M = ∫ ρ dA", "area in (u, v)", "energy ∫ ρ |x - s|² dA",
                                    "distance |c - s|", "moved since k-1", "valence (on the border: 2 less)"};
  const CellFill fill = fillShown();
  const ImVec2 barAt(at.x, at.y + fillLegendTop() - 4);
  const float room = bottom - barAt.y;
  if (fill == CellFill::Valence) {
    boxedText(dl, at, kNames[static_cast<int>(fill)]);
    drawSwatches(dl, barAt, room, valenceKinds());
    return;
  }
  const std::string name = std::string(kNames[static_cast<int>(fill)]) + (fillScale_.log ? " (log scale)" : "");
  if (fillScale_.flat()) {
    boxedText(dl, at, (name + ": " + format("%.2e", fillScale_.lo) + " for every cell").c_str());
    return;
  }
  boxedText(dl, at, name.c_str());
  // Shorter where the pane is low (its lower label hangs under it), down to two lines of labels.
  const float font = ImGui::GetFontSize();
  const float height = std::clamp(room - 0.4f * font, 2.0f * font, kFillBarHeight * markScale());
  drawColorBar(dl, barAt, kColorBarWidth * markScale(), height, format("%.2e", fillScale_.hi).c_str(),
               format("%.2e", fillScale_.lo).c_str(), [](float t) { return quantityColor(t); });
}

// The legend's name line, and its colour bar with the labels beside it ("2.48e-03").
float Inspector::fillLegendTop() const { return 1.5f * ImGui::GetFontSize() + 4.5f; }
float Inspector::fillLegendWidth() const {
  return 10 + kColorBarWidth * markScale() + 4 + ImGui::CalcTextSize("0.00e-00").x + 8;
}

// Each cell's colour under the fill: its kind of valence, or its quantity on fillScale_.
std::vector<ImU32> Inspector::cellColors(const IterationView& view) {
  std::vector<ImU32> colors;
  const CellFill fill = fillShown();
  if (fill == CellFill::Valence) {
    for (const VertexValence& s : siteValences(view)) colors.push_back(valenceColor(s));
    return colors;
  }
  auto quantity = [&](size_t i) {
    const BoundedCell& c = view.cells[i];
    switch (fill) {
      case CellFill::Mass: return c.mass;
      case CellFill::Area: return c.area;
      case CellFill::Energy: return c.energy;
      case CellFill::Moved: return siteMoved(replay_->recording(), view.index, i);
      default: return (c.centroid - view.sites[i]).norm();
    }
  };
  // The fixed border sites never move: their distance to the centroid, 10^3 times the
  // movable sites' at convergence, made the scale and left every movable cell one colour.
  // They are grey, outside the scale, for the two quantities of the sites' moves.
  const bool movableOnly = fill == CellFill::ToCentroid || fill == CellFill::Moved;
  const size_t first = movableOnly ? replay_->recording().fixedSites.size() : 0;
  std::vector<double> values;
  for (size_t i = first; i < view.cells.size(); ++i) values.push_back(quantity(i));
  fillScale_ = fillScale(values);
  for (size_t i = 0; i < view.cells.size(); ++i)
    colors.push_back(i < first ? rgb(0.85f, 0.85f, 0.85f) : quantityColor(fillScale_.at(quantity(i)), 0.85f));
  return colors;
}

CanvasGeometry Inspector::buildCanvas(float scale) {
  CanvasGeometry g;
  const Domain& domain = replay_->domain();
  const IterationView& view = replay_->view(iteration_);
  const size_t fixedCount = replay_->recording().fixedSites.size();
  const bool filled = cellsFilled();
  if (filled) {
    const std::vector<ImU32> colors = cellColors(view);
    for (size_t i = 0; i < view.cells.size(); ++i)
      for (const CellPiece& piece : view.cells[i].pieces)
        for (size_t k = 1; k + 1 < piece.polygon.size(); ++k)
          g.fill(piece.polygon[0], piece.polygon[k], piece.polygon[k + 1], colors[i]);
  }
  // A projector washes colours out: darker lines, stronger colours, bigger marks.
  const bool strong = presentation_;
  // Pixels between sites: on average (the domain's area shared among them), and around each
  // movable site (from its cell's area; a border site's cell is cut in half, and its square
  // shrank out of sight: the average). A map is scaled to the unit square, which a strip's fills
  // along its length only, and squeezes parts of the surface (a face's nose): there marks sized
  // for the unit square's average covered the cells, and merged into dark blobs.
  const bool cellsKnown = view.cells.size() == view.sites.size() && !view.cells.empty();
  double domainArea = 0;
  for (const BoundedCell& cell : view.cells) domainArea += cell.area;
  const float spacing = cellsKnown ? scale * static_cast<float>(std::sqrt(domainArea / view.cells.size()))
                                   : scale / std::sqrt(static_cast<float>(view.sites.size()) + 1);
  const auto spacingAt = [&](size_t i) {
    return cellsKnown && i >= fixedCount ? scale * static_cast<float>(std::sqrt(view.cells[i].area)) : spacing;
  };
  // Over a fill, the light triangles were the brightest lines in the pane: faint there.
  // Over a fill, cells a few pixels across were all lines and dots (the Valence stage at
  // 960x600 showed a dark blue disk): as the 3D view's wire, they fade from 10 pixels down to 4.
  const float seen = filled ? std::clamp((spacing - 4.0f) / 6.0f, 0.15f, 1.0f) : 1.0f;
  const ImU32 triangleColor = strong ? rgb(0.62f, 0.64f, 0.7f, filled ? 0.4f * seen : 1.0f)
                                     : rgb(0.82f, 0.84f, 0.88f, filled ? 0.3f * seen : 1.0f);
  const ImU32 edgeColor = strong ? rgb(0.0f, 0.1f, 0.45f, seen) : rgb(0.2f, 0.35f, 0.7f, seen);
  const ImU32 orange = strong ? rgb(0.95f, 0.25f, 0.0f) : rgb(0.85f, 0.3f, 0.1f);
  const ImU32 siteColor = strong ? rgb(0.0f, 0.0f, 0.0f, seen) : rgb(0.1f, 0.15f, 0.45f, seen);
  const Layers shown = layers();
  if (shown.triangles2D)
    for (size_t t = 0; t < domain.triangles().size(); ++t) {
      const Triangle& tri = domain.triangles()[t];
      for (int k = 0; k < 3; ++k)
        if (tri[k] < tri[(k + 1) % 3] || domain.neighbours()[t][(k + 2) % 3] < 0)
          g.line(domain.uv()[tri[k]], domain.uv()[tri[(k + 1) % 3]], triangleColor);
    }
  if (shown.cells2D)
    for (const auto& [p, q] : cellEdges()) g.line(p, q, edgeColor);
  // Where a surface that is not a disk was cut open: both copies of every seam.
  const Recording& recording = replay_->recording();
  for (const auto& [a, b] : replay_->seams())
    g.thickLine(recording.uv[a], recording.uv[b], strong ? 7.0f : 5.0f, kSeamColor);
  for (const auto& [a, b] : recording.sharedSeams)  // a chart's, with the other charts
    g.thickLine(recording.uv[a], recording.uv[b], strong ? 7.0f : 5.0f, kSeamColor);
  // Dots a sixth of the site spacing around them: the cells stay visible between them.
  const auto radius = [&](size_t i) { return std::clamp(0.16f * spacingAt(i), 1.2f, 6.0f) * (strong ? 1.3f : 1.0f); };
  // The lesson's Move stage is about the arrows: too short to see, they are drawn longer.
  const double arrowScale = stage_ == Stage::Move ? moveArrowScale(view, fixedCount) : 1.0;
  for (size_t i = 0; i < view.sites.size() && shown.sites2D; ++i) {
    const Vec2& s = view.sites[i];
    const float r = radius(i);
    if (i < fixedCount) {
      g.point(s, r, MarkerShape::Square, rgb(0.35f, 0.35f, 0.35f));
      continue;
    }
    const Vec2& c = view.cells[i].centroid;
    const Vec2 tip = s + arrowScale * (c - s);
    const Vec2 d = (tip - s) * scale;  // in pixels, v up
    const float length = static_cast<float>(d.norm());
    if (shown.arrows2D && length > 1.0f) {
      g.line(s, tip, orange);
      const float ux = static_cast<float>(d.x()) / length, uy = -static_cast<float>(d.y()) / length;
      const float h = std::min(5.0f, 0.5f * length);  // screen y points down: flip v
      g.markTriangle(tip, {0, 0, -h * ux + 0.5f * h * uy, -h * uy - 0.5f * h * ux,
                         -h * ux - 0.5f * h * uy, -h * uy + 0.5f * h * ux},
                     orange);
    }
    if (shown.centroids2D) g.point(c, r + 1.0f, MarkerShape::Ring, orange);
    g.point(s, r, MarkerShape::Dot, siteColor);
  }
  return g;
}

namespace {

// A plot's title, and a shorter one for where the plot is too narrow for it (a small window,
// or presentation mode's large font): titles ran into each other.
struct PlotTitle {
  const char* full;
  const char* brief;
};

// One curve of a plot: `values` at `at` (the iterations, or the milliseconds before each one).
struct Curve {
  std::vector<double> values, at;
  ImU32 colour;
};

// A plot with axes and ticks over the whole recording; returns the iteration clicked, or -1.
// `run` is the run's curve; `others`, drawn behind it, other runs' (none: empty). Along x, the
// iterations, or (`unit` "ms") the time. Its lines and dot `marks` times as thick as at 800 px
// (Inspector::markScale).
int plot(const PlotTitle& heading, const Curve& run, const std::vector<Curve>& others, const char* unit,
         bool logScale, double threshold, int current, const ImVec2& asked, float marks) {
  ImDrawList* dl = ImGui::GetWindowDrawList();
  const ImVec2 p0 = ImGui::GetCursorScreenPos();
  const ImVec2 size = drawable(asked);
  ImGui::InvisibleButton(heading.full, size);
  const bool active = ImGui::IsItemActive();
  std::vector<std::vector<double>> otherValues;
  for (const Curve& c : others) otherValues.push_back(c.values);
  const PlotAxis axis = plotAxis(run.values, otherValues, threshold, logScale);
  const bool time = *unit != '\0';
  double span = run.at.empty() ? 0 : run.at.back();  // of x: the last iteration, or the longest time
  for (const Curve& c : others)
    if (!c.at.empty()) span = std::max(span, c.at.back());
  float widest = 0;
  for (const PlotAxis::Tick& tick : axis.ticks) widest = std::max(widest, ImGui::CalcTextSize(tick.label.c_str()).x);
  const float font = ImGui::GetFontSize();  // 13 px, or larger when presenting
  const float left = std::max(4.5f * font, widest + 8), right = 8, top = font + 5, bottom = font + 9;
  const ImVec2 a(p0.x + left, p0.y + top), b(p0.x + size.x - right, p0.y + size.y - bottom);
  dl->AddRectFilled(p0, ImVec2(p0.x + size.x, p0.y + size.y), rgb(1, 1, 1));
  dl->AddRect(a, b, rgb(0.5f, 0.5f, 0.5f));
  // The full title where it fits over the plot, else the brief one, cut at the plot's edge.
  const char* title = ImGui::CalcTextSize(heading.full).x <= size.x - left ? heading.full : heading.brief;
  dl->PushClipRect(p0, ImVec2(p0.x + size.x, p0.y + size.y), true);
  dl->AddText(ImVec2(p0.x + left, p0.y + 1), rgb(0.1f, 0.1f, 0.1f), title);
  dl->PopClipRect();
  if (run.values.empty()) return -1;
  // The curves keep a few pixels from the frame's sides: the last iteration lay on the right
  // frame, which hid the last step of every curve (the % curve ended over the green line it had
  // crossed) and half its dot.
  const float inset = 0.5f * font;
  auto x = [&](double at) {
    return a.x + inset + static_cast<float>(span > 0 ? at / span : 0.5) * (b.x - a.x - 2 * inset);
  };
  auto y = [&](double v) { return b.y - static_cast<float>(axis.position(v)) * (b.y - a.y); };
  // Every tick's line, but only every `every`-th label where they would overlap (a short plot:
  // presentation mode's large font on a projector's 1024x768 printed them over each other).
  float spacing = b.y - a.y;
  for (size_t i = 1; i < axis.ticks.size(); ++i)
    spacing = std::min(spacing, y(axis.ticks[i - 1].value) - y(axis.ticks[i].value));
  const int every = std::max(1, static_cast<int>(std::ceil(font / std::max(spacing, 1.0f))));
  for (size_t i = 0; i < axis.ticks.size(); ++i) {
    const float ty = y(axis.ticks[i].value);
    dl->AddLine(ImVec2(a.x - 4, ty), ImVec2(b.x, ty), rgb(0.9f, 0.9f, 0.9f));
    if (i % every == 0)
      dl->AddText(ImVec2(p0.x + 2, ty - 0.5f * font), rgb(0.3f, 0.3f, 0.3f), axis.ticks[i].label.c_str());
  }
  // X ticks: iterations, or milliseconds (the last label with the unit), as many labels as fit
  // side by side, six at most.
  const auto xTick = [&](double at, const std::string& label) {
    dl->AddLine(ImVec2(x(at), b.y), ImVec2(x(at), b.y + 4), rgb(0.3f, 0.3f, 0.3f));
    // Centred under the tick, but inside the pane (presentation mode's "200" read "20").
    const float width = ImGui::CalcTextSize(label.c_str()).x;
    const float labelLeft = std::min(x(at) - 0.5f * width, p0.x + size.x - width - 1);
    dl->AddText(ImVec2(labelLeft, b.y + 5), rgb(0.3f, 0.3f, 0.3f), label.c_str());
  };
  if (!time) {
    const int n = static_cast<int>(span) + 1;
    const float labelWidth = ImGui::CalcTextSize(std::to_string(n - 1).c_str()).x + 0.5f * font;
    const int step = tickStep(n, static_cast<int>((b.x - a.x) / labelWidth));
    for (int k = 0; k < n; k += step) xTick(k, std::to_string(k));
  } else if (span > 0) {
    const std::string widestLabel = format("%.0f", span) + " " + unit;  // as wide as a round one
    const double step = tickStep(span, static_cast<int>((b.x - a.x) / (ImGui::CalcTextSize(widestLabel.c_str()).x + 0.5f * font)));
    const int last = static_cast<int>(std::floor(span / step * (1 + 1e-9)));
    for (int i = 0; i <= last; ++i) xTick(i * step, format("%g", i * step) + (i == last ? std::string(" ") + unit : ""));
  }
  dl->PushClipRect(a, b, true);
  if (threshold > 0) dl->AddLine(ImVec2(a.x, y(threshold)), ImVec2(b.x, y(threshold)), rgb(0.2f, 0.6f, 0.2f), 1.5f * marks);
  auto polyline = [&](const Curve& c) {
    std::vector<ImVec2> line;
    for (size_t k = 0; k < c.values.size(); ++k) line.emplace_back(x(c.at[k]), y(c.values[k]));
    dl->AddPolyline(line.data(), static_cast<int>(line.size()), c.colour, 0, 1.5f * marks);
  };
  for (const Curve& c : others) polyline(c);
  polyline(run);
  const bool onTheRun = current < static_cast<int>(run.values.size());
  const float cx = x(onTheRun ? run.at[current] : current);
  dl->AddLine(ImVec2(cx, a.y), ImVec2(cx, b.y), rgb(0.85f, 0.3f, 0.1f), 2.0f * marks);
  if (onTheRun) dl->AddCircleFilled(ImVec2(cx, y(run.values[current])), 4.0f * marks, rgb(0.85f, 0.3f, 0.1f));
  dl->PopClipRect();
  if (active) {
    const float mx = ImGui::GetIO().MousePos.x;
    return nearestIndex(run.at, (mx - a.x - inset) / (b.x - a.x - 2 * inset) * span);
  }
  return -1;
}

}  // namespace

void Inspector::plotsPane(const ImVec2& pos, const ImVec2& size) {
  beginPane("Convergence", pos, size, kCanvasPaneFlags);
  const bool time = plotsAgainstTime();
  struct Curves {  // of one run
    Curve energy, displacement, moving;
    Curves(const std::vector<IterationRecord>& its, ImU32 colour, bool time) {
      std::vector<double> at = time ? elapsedMs(its) : std::vector<double>();
      for (const IterationRecord& it : its) {
        if (!time) at.push_back(static_cast<double>(at.size()));
        energy.values.push_back(it.energy);
        displacement.values.push_back(it.maxDisplacement);
        moving.values.push_back(100.0 * it.fractionMoving);
      }
      for (Curve* c : {&energy, &displacement, &moving}) {
        c->at = at;
        c->colour = colour;
      }
    }
  };
  const Curves run(replay_->recording().iterations, ImGui::ColorConvertFloat4ToU32(solverColour(options_.lloyd.solver)),
                   time);
  std::vector<Curve> energy, displacement, moving;  // the other runs'
  if (!comparisons_.empty()) {  // which curve is which
    const std::vector<IterationRecord>& its = replay_->recording().iterations;
    // A run still going (a session not finished) is not yet "not converged".
    const bool converged = (session_ && !session_->finished()) || replay_->recording().converged();
    ImGui::TextColored(solverColour(options_.lloyd.solver), "%s",
                       curveLegend(toString(options_.lloyd.solver), true, false, its, converged, time).c_str());
    for (size_t k = 0; k < comparisons_.size(); ++k) {
      const Comparison& c = comparisons_[k];
      const Curves other(c.iterations, ImGui::ColorConvertFloat4ToU32(solverColour(c.solver)), time);
      energy.push_back(other.energy);
      displacement.push_back(other.displacement);
      moving.push_back(other.moving);
      const bool converged = convergedAt(c.iterations, replay_->recording().percentThreshold);
      const std::string legend = curveLegend(toString(c.solver), false, k == 0, c.iterations, converged, time);
      // On the same line where it fits, else on the next (at 960 wide, Newton's was cut to "newton:").
      const std::string spaced = "  " + legend;
      const bool fits = ImGui::GetItemRectMax().x + ImGui::GetStyle().ItemSpacing.x + ImGui::CalcTextSize(spaced.c_str()).x <=
                        ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x;
      if (fits) ImGui::SameLine();
      ImGui::TextColored(solverColour(c.solver), "%s", (fits ? spaced : legend).c_str());
    }
  }
  const char* unit = time ? "ms" : "";
  const ImVec2 avail = ImGui::GetContentRegionAvail();
  const ImVec2 each((avail.x - 2 * ImGui::GetStyle().ItemSpacing.x) / 3, avail.y);
  int jump = plot({"CVT energy", "CVT energy"}, run.energy, energy, unit, false, 0, iteration_, each, markScale());
  ImGui::SameLine();
  int k = plot({"max distance site-centroid (log)", "max |c - s| (log)"}, run.displacement, displacement, unit, true,
               replay_->recording().distanceThreshold, iteration_, each, markScale());
  if (k >= 0) jump = k;
  ImGui::SameLine();
  k = plot({"% sites farther than threshold (log)", "% moving (log)"}, run.moving, moving, unit, true,
           replay_->recording().percentThreshold, iteration_, each, markScale());
  if (k >= 0) jump = k;
  if (jump >= 0) setIteration(jump);
  ImGui::End();
}

void Inspector::timelinePane(const ImVec2& pos, const ImVec2& size) {
  beginPane("Timeline", pos, size, ImGuiWindowFlags_NoTitleBar);
  const int last = std::max(0, replay_->iterationCount() - 1);
  if (ImGui::Button("|<")) setIteration(0);
  ImGui::SameLine();
  if (ImGui::Button("<")) setIteration(iteration_ - 1);
  ImGui::SameLine();
  const bool moving = lesson_.playing() ? !lesson_.paused() : playing_;
  if (steadyButton(moving ? "Pause" : "Play", {"Pause", "Play"})) togglePlay();
  ImGui::SameLine();
  if (ImGui::Button(">")) setIteration(iteration_ + 1);
  ImGui::SameLine();
  if (ImGui::Button(">|")) setIteration(last);
  ImGui::SameLine();
  const bool running = this->running();
  if (!input_) ImGui::BeginDisabled();
  if (ImGui::Button("Restart")) {  // from initial sites, with the settings
    try {
      startSession(*input_, meshName_);
    } catch (const Error& e) {
      showMessage(e.what());
    }
  }
  if (!input_) ImGui::EndDisabled();
  ImGui::SameLine();
  const bool canStep = session_ && !running && !session_->finished();
  if (!canStep) ImGui::BeginDisabled();
  if (ImGui::Button("Step")) {
    stopComparingForARun();
    if (lesson_.playing()) toggleLesson();  // as for Run: its plan is of the iterations before
    try {
      replay_->append(session_->step());
      setIteration(replay_->iterationCount() - 1);
      if (session_->finished()) finishSession();
    } catch (const std::exception& e) {  // out of memory, say: said as a run's failure is (it ended the program)
      runFailed(e.what());
    }
  }
  ImGui::SameLine();
  if (ImGui::Button("Run")) startRun();
  if (!canStep) ImGui::EndDisabled();
  ImGui::SameLine();
  if (!running) ImGui::BeginDisabled();
  if (ImGui::Button("Stop")) stopRunAndFinish();
  if (!running) ImGui::EndDisabled();
  ImGui::SameLine();
  const bool lessonWaits = running && !lesson_.playing();
  if (lessonWaits) ImGui::BeginDisabled();
  if (steadyButton(lesson_.playing() || stage_ ? "End lesson" : "Lesson", {"End lesson", "Lesson"})) toggleLesson();
  if (lessonWaits) ImGui::EndDisabled();
  if (lessonWaits && ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
    ImGui::SetTooltip("After the run: Stop it, or let it finish");
  ImGui::SameLine();
  if (steadyButton(presentation_ ? "Controls" : "Present", {"Controls", "Present"})) presentation_ = !presentation_;
  ImGui::SameLine();
  // The speed slider and its label keep their room, in the font's units (a fixed 180 px cut
  // "it/s" off in presentation mode's large font). Where the buttons leave the iteration slider
  // less than 16 characters (it shrank to a stub at 960 px), both go to a row of their own, and
  // the pane grows by a row from the next frame on.
  const ImGuiStyle& style = ImGui::GetStyle();
  const float speedWidth = 5 * ImGui::GetFontSize();
  const float speedRoom = speedWidth + style.ItemInnerSpacing.x + ImGui::CalcTextSize("it/s").x + style.ItemSpacing.x;
  timelineWrapped_ = ImGui::GetContentRegionAvail().x - speedRoom < 16 * ImGui::GetFontSize();
  if (timelineWrapped_) ImGui::NewLine();
  ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x - speedRoom);
  int k = iteration_;
  if (ImGui::SliderInt("##iteration", &k, 0, last, "iteration %d")) setIteration(k);
  ImGui::SameLine();
  ImGui::SetNextItemWidth(speedWidth);
  // Clamped: Ctrl+click typed 0 or less, which stopped playback or ran the lesson backwards.
  ImGui::SliderFloat("it/s", &playSpeed_, 1.0f, 60.0f, "%.0f", ImGuiSliderFlags_AlwaysClamp);
  const IterationRecord& it = replay_->recording().iterations[iteration_];
  // Numbered from 0: "of 159" read as one fewer than the 160 iterations the controls pane counts.
  // The keys' reminder is left out where the line would not fit (960x600).
  char status[256];
  std::snprintf(status, sizeof status, "iteration %d (0-%d)   energy %.6e   max |c - s| %.2e   %.1f%% moving   %s",
                iteration_, last, it.energy, it.maxDisplacement, 100.0 * it.fractionMoving,
                showTimings_ ? format("%.1f ms   ", it.milliseconds).c_str() : "");
  const std::string withKeys = std::string(status) + "keys: <- -> (Shift: 10), Home, End, Space";
  const bool fits = ImGui::CalcTextSize(withKeys.c_str()).x <= ImGui::GetContentRegionAvail().x;
  ImGui::TextUnformatted(fits ? withKeys.c_str() : status);
  ImGui::End();
}

}  // namespace lloydscope
