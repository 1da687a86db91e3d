// The inspector's panes, drawn with Dear ImGui: 3D view, 2D parameter domain with the bounded
// Voronoi cells, convergence plots, timeline, controls and results. All linked to one current
// iteration of a recording; windowed and headless front ends both call frame().
#pragma once

#include "background_task.h"
#include "canvas_renderer.h"
#include "files.h"
#include "mesh_renderer.h"
#include "orbit_camera.h"
#include "plane_view.h"
#include "pipeline.h"
#include "png.h"
#include "report.h"
#include "lesson.h"
#include "replay.h"
#include "selection.h"
#include "topology.h"

#include <imgui.h>

#include <atomic>
#include <functional>
#include <limits>
#include <mutex>
#include <optional>
#include <memory>
#include <string>
#include <tuple>

namespace lloydscope {

// What colours the 2D cells: Moved is how far each site went from iteration k-1 to k, where
// the diagram is still changing; Valence the valence of each site's vertex in the iteration's
// result, regular or how far from it (an inside cell's number of sides).
enum class CellFill { None, Mass, Area, Energy, ToCentroid, Moved, Valence };
// "none", "mass", "area", "energy", "distance" (to the centroid), "moved", "valence"; throws Error.
CellFill parseCellFill(const std::string& name);
const char* toString(CellFill fill);
// A lesson stage's own fill, where it has one (the Valence stage's): the cells get it, whatever
// fill is chosen (which shows where a stage draws cells and has none: Layers::cells2D).
std::optional<CellFill> stageFill(std::optional<Stage> stage);

class Inspector;

// What an export saves: the whole window or one pane.
enum class Pane { Window, View3D, Domain2D, Plots };
Pane parsePane(const std::string& name);  // "window", "3d", "2d", "plots"; throws Error

// A PNG of the current frame, or a numbered sequence over iterations first..last (for slides
// and GIFs): path "out.png" gives out_0000.png, out_0001.png, ... named by iteration.
struct ExportJob {
  std::string path;
  Pane pane = Pane::Window;
  int first = -1, last = -1;  // -1: just the current iteration
  bool sequence() const { return first >= 0; }
};
// The file the picture of `iteration` goes to.
std::string exportPath(const ExportJob& job, int iteration);
// Throws Error where `path`, a file the inspector saves (`what`: "picture", "recording"), is
// `shown`, the mesh or recording open (a screenshot named like it replaced the user's file with
// a PNG); the same for each file `job` writes.
void refuseReplacing(const std::string& path, const std::string& shown, const std::string& what);
void refuseReplacing(const ExportJob& job, const std::string& shown);

// One picture the front end must save: after rendering the frame, read it back, encode `crop`
// of it (encodePng, which names `path` in its errors), and give it to Inspector::savePicture(),
// or say why it could not to Inspector::exported().
struct ExportRequest {
  std::string path;
  PixelRect crop;  // in framebuffer pixels
};

// What the inspector opens on beyond the recording, from the command line: the same for the
// window and for headless pictures.
struct OpeningView {
  int iteration = -1;                 // -1: the last
  std::vector<int> cells, triangles;  // pinned
  bool worstTriangle = false;         // pin the triangle with the smallest angle too
  std::string camera;                 // "yaw pitch distance x y z"; empty: fit to the mesh
  bool presentation = false;          // classroom mode
  std::optional<Stage> stage;         // show this stage of the lesson, with its caption
  bool compareSolvers = false;        // also the other solvers' curves (Inspector::compareSolvers)
  bool final = false;                 // the 3D pane shows the final result (showFinal)
  std::optional<CellFill> fill;       // what colours the 2D cells
  bool repair = false;                // "Open mesh" repairs what it reads (--repair)
  bool timings = true;                // off: no milliseconds shown, so a picture is the same on every run
  bool plotTime = false;              // the convergence plots against time, not iterations
  void applyTo(Inspector& inspector) const;
};

// The smallest room the inspector lays out in, in units: under it the panes are too small to
// read (at 640x480 the plots' titles ran into each other, the timeline's buttons were cut off).
constexpr int kSmallestLayoutWidth = 960, kSmallestLayoutHeight = 600;

class Inspector {
 public:
  // `result` is the finished run the inspector opens on (its recording drives every pane).
  // With the input mesh, the controls can change the settings and step or run again.
  Inspector(gpu::Context& gpu, VkRenderPass renderPass, std::string meshName,
            RemeshOptions options, RemeshResult result, std::optional<Mesh> input = {});
  ~Inspector();

  // "Open mesh" reads with the repair (core/repair), its notes shown in the message line.
  void setRepairOnOpen(bool on) { repairOnOpen_ = on; }
  // Classroom mode: large fonts, thick lines and marks, high contrast, no controls pane.
  void setPresentation(bool on) { presentation_ = on; }
  void setFill(CellFill fill) { fill_ = fill; }
  // Shows one stage of the lesson (its layers and caption); none: everything, no caption.
  void showStage(std::optional<Stage> stage) { stage_ = stage; }
  // The 3D pane shows the final result (polished, stitched, snapped: what remesh writes) with a
  // red ring where it is farthest from the input, instead of an iteration's mesh. Only once
  // the run has finished; off in a lesson stage.
  void showFinal(bool on) {  // and the view fits it (with several components, all of them)
    showFinal_ = on;
    fitCamera();
  }
  // Builds one frame of the whole window (ImGui::NewFrame() must have been called).
  void frame();
  // Ctrl+Q was pressed: the window closes (a picture made headless has no keys).
  bool closeRequested() const { return closeRequested_; }
  // Seconds until the picture changes without input: 0 while a run, an export or the first
  // view's fit goes on, the time to playback's next iteration, the lesson's next step or a
  // message's going, infinity where nothing moves on its own. The window waits for input until
  // then.
  double secondsToChange() const;
  bool animating() const { return secondsToChange() < std::numeric_limits<double>::infinity(); }
  // Called from another thread when something the window shows is ready (the comparison's
  // curves): the window draws a frame though it waits for input.
  void setWake(std::function<void()> wake) { wake_ = std::move(wake); }
  // The CPU work of the current iteration's panes (its cells, lifted mesh, metrics and cell
  // edges), cached for frame(). Front ends call it while the previous frame renders: on two
  // cores, scrubbing then overlaps the geometry with lavapipe's rasterization.
  void prepare();
  void setIteration(int k);
  // Relaxes the run's start again with the other solvers (Lloyd and Newton for L-BFGS, ...)
  // and draws their curves beside the run's in the convergence pane. Blocks while they run
  // (the window's Compare button runs them on a thread of their own).
  void compareSolvers();
  // Off for reproducible pictures: timings differ from run to run.
  void showTimings(bool show) { showTimings_ = show; }
  // The convergence plots against the time the iterations took (each run's own, as recorded),
  // not the iterations: Newton's fewer iterations each cost more (the T key, or the box under
  // "Convergence plots"). Not while timings are off.
  void plotAgainstTime(bool on) { plotTime_ = on; }
  bool plotsAgainstTime() const { return plotTime_ && showTimings_; }
  int iteration() const { return iteration_; }
  int iterationCount() const { return replay_->iterationCount(); }
  const std::string& meshName() const { return meshName_; }  // the file, not where it lives
  // Pins a cell, or a triangle of the result the 3D view shows (the current iteration's, or the
  // final one); throws Error (one line) if there is no such one.
  void pinCell(int cell);
  void pinTriangle(int triangle);
  void pinWorstTriangle();  // of the result the 3D view shows: the iteration's or the final one
  // The 3D camera as one line of text ("yaw pitch distance x y z"), to save and restore a view.
  std::string cameraText() const;
  void setCamera(const std::string& text);  // throws Error on a malformed line
  // Exports: the frames that frame() draws next are saved, one per iteration of the job.
  void startExport(ExportJob job);  // throws Error on a bad path or range
  const std::optional<ExportRequest>& exportRequest() const { return exportRequest_; }
  bool exporting() const { return exportJob_.has_value(); }
  // Saves the picture asked for, through one FileBatch: one alone replaces its file at once; a
  // sequence's wait in temporaries until its last is made, then are renamed onto their files
  // together: one that cannot be written (a full disk) leaves every file as it was. A
  // sequence's 3rd picture on a full disk had replaced the first two and left the rest old.
  // Throws Error naming the file; the caller ends the job with exported(why), or with the
  // inspector (headless).
  void savePicture(const std::vector<unsigned char>& png);
  // The picture could not be made (`error`, one line, ends the job and is shown), or was saved.
  void exported(const std::string& error = {});
  // Records the frame ImGui::Render() produced into `framebuffer`: clears it and draws every
  // pane, our own pipelines included (ImGui 1.86 passes its draw callbacks no command buffer,
  // so this is where they get it).
  static void recordFrame(VkCommandBuffer cmd, VkRenderPass pass, VkFramebuffer framebuffer,
                          VkExtent2D extent);

 private:
  void controlsPane(const ImVec2& pos, const ImVec2& size);
  void saveExport(ExportJob job);
  void runSummary();
  void qualityTable();
  void runStatus();
  void selectionControls();
  void viewControls();
  void viewPane3D(const ImVec2& pos, const ImVec2& size);
  void domainPane2D(const ImVec2& pos, const ImVec2& size);
  void plotsPane(const ImVec2& pos, const ImVec2& size);
  void timelinePane(const ImVec2& pos, const ImVec2& size);
  void captionPane(const Caption& c, const ImVec2& pos, const ImVec2& size);
  float captionPaneHeight(const Caption& c, float width) const;  // as tall as it wraps to
  std::string captionTitle(const Caption& c) const;              // "5 Move (paused: ...)"
  CaptionFacts captionFacts();
  Layers layers() const;  // the lesson stage's, or the display switches'
  void toggleLesson();
  void togglePlay();
  void handleKeys();
  void pick2D(const Vec2& uv);
  void pick3D(const ImVec2& mouse, const ImVec2& p0, const ImVec2& extent, float top);
  void hoverTooltip2D(const Vec2& uv);
  void cameraControls();
  void settingsControls();
  void fileControls();
  // Live runs: a session steps on a worker thread; its iterations reach the replay here.
  // Starts one of `input` with the Settings pane's settings and shows it; throws Error where
  // none can start, leaving the replay on show as it was (a run or a comparison in progress is
  // stopped first either way).
  void startSession(const Mesh& input, const std::string& name);
  // Puts `text` (if any) before the run's notes so far.
  void noteFirst(const std::string& text);
  void noteTheResult();  // the final result's own notes (folds, far from the input ...)
  // Before a new run or recording: the last run's result, and its notes, are not shown with it.
  void forgetResult();
  // A worker steps the session, or has stopped and is not joined yet (the frame joins it): Step
  // and Run wait for the join.
  bool running() const { return run_.started(); }
  void startRun();
  void stopRun();
  // Stop as the user asks it (Stop, Save recording) and as a run that ended is joined: a session
  // that the worker's last step finished is finished here (Stop in the frame the run ended left
  // it "Done after 1000 iterations: the clean-up on the surface follows", Step and Run greyed).
  void stopRunAndFinish();
  void joinWorker();  // the worker's iterations collected, and what ended it said
  // The run failed (`why`): the iterations so far stay to look at; the session is spent.
  void runFailed(const std::string& why);
  void collectIterations();
  void finishSession();
  void openReplay(Recording recording);
  void stopComparingForARun();
  void uploadMesh();
  void drawSeams3D(ImDrawList* dl, const ScreenOf3D& screen, const Vec3& eye) const;
  const QualityMetrics& currentQuality();  // of the current iteration's result, cached
  const std::vector<std::pair<Vec2, Vec2>>& cellEdges();  // of the current iteration, cached
  CanvasGeometry buildCanvas(float scale);  // the 2D pane's lines, fills and marks
  std::vector<ImU32> cellColors(const IterationView& view);  // under the fill
  CellFill fillShown() const;  // the user's, or the lesson stage's (Valence)
  bool cellsFilled() const;    // the 2D cells are shown, with a fill
  // Where the iteration's result (and its pinned triangles) is drawn: in 2D with the sites, in 3D
  // where the view shows neither the input nor the final result.
  bool iterationResultIn2D() const { return layers().sites2D; }
  bool iterationResultIn3D() const { return !layers().input3D && !finalShown(); }
  // The iteration's pinned triangles are drawn over its result in 3D, or, where the stage shows
  // the input there, over the input between its lifted sites, their corners (the Voronoi to
  // Lift stages drew them in 2D alone).
  bool pinnedTrianglesIn3D() const { return iterationResultIn3D() || (layers().sites3D && !finalShown()); }
  void fitCamera();
  void fit2D();  // the whole domain in the 2D pane, as it opens

  MeshRenderer renderer_;
  std::string meshName_;
  GpuFrame gpu_;  // of the 3D pane's mesh, set as it is uploaded
  std::string shownPath_;  // the mesh or recording open, with its folder: no export or save replaces it
  RemeshOptions options_;   // the run on screen's: the header, the captions and Compare describe it
  RemeshOptions settings_;  // the Settings pane's, for the next Restart or Open mesh
  bool repairOnOpen_ = false;
  // What remesh() may choose otherwise for a mesh (a nearly closed disk kept whole, a disk kept
  // without the first pass), as given: the next mesh opened starts from them (it ran without the
  // first pass because the last one had, and nothing in Settings showed it).
  struct Asked {
    bool slitDisks, resample;
  } asked_;
  // > 0: remesh() simplified the input to this many vertices, as it failed as it was
  // (RemeshResult::fullInputFailed): the next mesh opened is not, unless typed under Settings.
  int simplifiedAfterFailure_ = 0;
  RemeshResult result_;
  std::unique_ptr<Replay> replay_;
  std::optional<Mesh> input_;
  // Of the mesh opened, before a chart stood for it; of a recording's surface, stitched.
  Topology inputTopology_;
  int inputCharts_ = 0;  // > 0: the panes and Restart follow the largest of so many charts
  int inputComponents_ = 1;  // > 1: ... the largest of so many components (Restart forgets result_'s)
  std::unique_ptr<RemeshSession> session_;
  BackgroundTask run_;  // steps session_
  std::mutex pendingMutex_;
  std::vector<IterationRecord> pending_;  // from the worker, not yet in the replay
  // What the last action did, or why it could not: over the foot of the views for a while, in
  // presentation mode too. Under the controls, it moved them (the pane scrolled to it, and the
  // next click landed on another control), and presentation mode hid it.
  std::string message_;
  double messageShownAt_ = 0;  // ImGui::GetTime()
  void showMessage(std::string text);
  double messageSecondsLeft() const;
  void messageOverlay(const ImVec2& pos, float width);
  std::string runNotes_;                  // how the result was made, or why its run failed: under the table
  struct Comparison {  // another solver's run from the same first sites
    CvtSolver solver;
    std::vector<IterationRecord> iterations;
  };
  std::vector<Comparison> comparisons_;  // the other solvers', if compared
  // The other solvers' runs from the start of `recording`, whose run used `run`; `stop` ends
  // them early.
  static std::vector<Comparison> relaxWithOtherSolvers(const Recording& recording, const LloydOptions& run,
                                                       const std::atomic<bool>* stop);
  // The Compare button's runs take seconds: they go on a thread of their own; once it has
  // finished, frame() shows their curves.
  void startComparing();
  void stopComparing();  // before the replay changes: the runs read its first iteration
  BackgroundTask comparing_;
  std::vector<Comparison> compared_;  // comparing_'s, until frame() takes them
  std::function<void()> wake_;  // the window's: draw a frame even if no input comes
  bool animatedLastFrame_ = false;
  char meshPath_[512] = {}, recordingPath_[512] = {};
  CanvasRenderer canvas_;
  // What the 2D pane's geometry was built for: rebuilt when any of it changes.
  struct CanvasKey {
    int iteration = -1;
    CellFill fill = CellFill::None;
    Layers layers;
    bool presentation = false;
    float scale = 0;
    // The valence fill is of the result, which relocate and retriangulate make differently.
    RemeshMethod method = RemeshMethod::Retriangulate;
    bool operator==(const CanvasKey& o) const {
      return iteration == o.iteration && fill == o.fill && scale == o.scale &&
             presentation == o.presentation && layers == o.layers && method == o.method;
    }
  };
  CanvasKey canvasKey_;
  FillScale fillScale_;  // of the cells' fill, as the canvas was last built
  void fillLegend(ImDrawList* dl, const ImVec2& at, float bottom) const;  // above `bottom`
  float fillLegendTop() const;    // the 2D pane's room for the legend: its name's line
  float fillLegendWidth() const;  // and, under it, its colour bar's strip
  int iteration_ = 0;
  int measuredIteration_ = -1;
  RemeshMethod measuredMethod_ = RemeshMethod::Retriangulate;
  QualityMetrics quality_;
  std::vector<std::pair<Vec2, Vec2>> cellEdges_;
  std::vector<std::pair<Vec3, Vec3>> seam3D_;  // of the mesh uploaded to the 3D pane
  std::optional<SurfaceProjection> seamSurface_;  // which they lie on, to hide those behind it
  int edgesIteration_ = -1;
  bool showInput_ = false, showFinal_ = false;
  // What the 3D pane's buffers show: uploaded again when what it should show differs.
  struct Shown3D {
    int iteration = -1;
    bool input = false, mapped = false, sites = false, final = false, byAngle = false, valences = false;
    RemeshMethod method = RemeshMethod::Retriangulate;
    bool lift = false;  // the lesson's Lift stage: its sites haloed
    auto tied() const { return std::tie(iteration, input, mapped, sites, final, byAngle, valences, method, lift); }
    bool operator==(const Shown3D& o) const { return tied() == o.tied(); }
  };
  Shown3D uploaded_;
  Shown3D shown3D() const;
  bool finalShown() const;
  const Mesh& resultIn3D() const;  // the final result or the iteration's, as the 3D view shows
  // The map is of the mesh opened itself (no first remeshing, cut or simplification).
  bool mapIsOfTheInput() const;  // showFinal_, and there is a final result, and no lesson stage
  const Mesh& fittedMesh() const;
  bool wireframe_ = true, colorByAngle_ = true, showArrows_ = true, showTriangles_ = true;
  bool playing_ = false, showTimings_ = true, plotTime_ = false;
  float playSpeed_ = 10.0f, playClock_ = 0.0f;
  CellFill fill_ = CellFill::None;
  OrbitCamera camera_;
  bool fitPending_ = false;  // fitCamera() waits for the 3D pane's size to set the distance
  Selection selection_;
  std::optional<ExportJob> exportJob_;
  int exportNext_ = 0, iterationBeforeExport_ = 0;
  std::optional<ExportRequest> exportRequest_;
  std::unique_ptr<FileBatch> pictureFiles_;  // the pictures made and not yet saved (a sequence's, until its last)
  bool closeRequested_ = false;
  char exportPath_[512] = "lloydscope.png";
  int exportPane_ = 0, exportFirst_ = 0;
  std::optional<int> exportLast_;  // none: the sequence ends at the last iteration, whatever it is
  void exportControls();
  bool pickTriangles2D_ = false;  // a click in the 2D view pins a result triangle, not a cell
  bool presentation_ = false;
  // How much larger than at 800 px presentation mode draws the 3D view's lines and marks, the
  // colour bars and the plots' lines: they grow with its type (presentationTextSize); 1 outside
  // it. (On a 3840x2160 screen its type was 56 px, its curves 1.5 px, its valence dots 7 px, its
  // colour bar squeezed between its labels.) The 2D view's marks go by the sites' spacing.
  float markScale() const;
  // The timeline's iteration slider has a row of its own: the buttons left it too little room
  // in the last frame (a narrow window, or presentation mode's large font).
  bool timelineWrapped_ = false;
  ImFont* presentationFonts_[2] = {};  // 21 and 42 px; null: the default font, scaled
  std::optional<Stage> stage_;
  LessonPlayer lesson_;
  PlaneView view2D_;
  // What the draw callbacks of the current frame read (they must outlive ImGui::Render()).
  std::pair<const MeshRenderer*, MeshDraw> meshCallback_;
  std::pair<const CanvasRenderer*, CanvasDraw> canvasCallback_;
};

}  // namespace lloydscope
