// Everything needed to replay a Lloyd run: the domain, the fixed sites and every iteration.
// Saved as a versioned binary file with a checksum.
#pragma once

#include "lloyd.h"
#include "remesh.h"

#include <atomic>
#include <string>
#include <vector>

namespace lloydscope {

class FileBatch;  // core/files.h

struct Recording {
  // 2: sites as grid indices (8 bytes a site), centroids recomputed rather than stored.
  // 3: the density per triangle corner.
  // 4: the seams shared with other charts.
  static constexpr std::uint32_t kVersion = 4;

  std::string settings;  // the settings that produced it, one line ("param=conformal ...")
  RemeshMethod method = RemeshMethod::Retriangulate;
  double distanceThreshold = 1e-6, percentThreshold = 5.0;
  Mesh input;                      // the disk mesh that was parameterized
  std::vector<Vec2> uv;            // per input vertex
  Density density;                 // per input triangle, at its corners
  std::vector<Vec2> fixedSites;    // border samples, counter-clockwise
  std::vector<int> movableVertex;  // input vertex each movable site started at, or -1
  // A chart of a surface remeshed chart by chart (core/charts): the border edges of `input`
  // (vertex pairs) on seams with the other charts, whose twins are in other recordings.
  std::vector<std::pair<int, int>> sharedSeams;
  std::vector<IterationRecord> iterations;

  Domain domain() const { return Domain(uv, input.triangles, density); }
  bool converged() const { return convergedAt(iterations, percentThreshold); }
  // The cells of iteration k, recomputed from its sites: bit-identical to those of the run.
  // `hints` as computeCells takes them.
  std::vector<BoundedCell> cells(const Domain& domain, int iteration, bool keepGeometry,
                                 CellHints* hints = nullptr) const;
};

// The recorded run's start (its first iteration's sites), relaxed again with `options` (another
// solver, say): the iterations of that run, to compare convergence curves. `stop`, when set
// (from another thread), ends it after the iteration under way: the iterations so far. The
// recording is read before the first iteration only.
std::vector<IterationRecord> relaxAgain(const Recording& recording, const LloydOptions& options,
                                        const std::atomic<bool>* stop = nullptr);

// Why a run may have no iteration: a surface of several components, each too small for its
// share of the vertices asked, is kept as it is.
constexpr const char* kNoIterationWhy = "every part of the mesh was kept as it is, too small for its share of the vertices asked";

// Written through a temporary and renamed (writeAtomically), so an existing file is replaced
// whole or not at all. Throws Error("<path>: ...") where the run has no iteration, or the
// recording would not read back (loadRecording's checks): nothing is written then. Takes one
// copy of the file's bytes beside the recording while it saves, and for the check one of its
// mesh, map and first iteration.
void saveRecording(const Recording& recording, const std::string& path);
// The same, saved with the other files of `batch` (FileBatch, core/files.h) when it commits.
void saveRecording(const Recording& recording, const std::string& path, FileBatch& batch);
// Throws Error("<path>: ...") where `path`, or the file a link there leads to, has a mesh's
// extension (.off, .obj, .ply): a recording saved so replaced the mesh (the window's Save
// recording, given the input's name by mistake, wrote a recording over it). saveRecording checks
// it; remesh --record and the window's Save recording before they stop or start anything.
void requireRecordingName(const std::string& path);
// saveRecording without its checks: the damaged files the tests of loadRecording's refusals make.
void saveRecordingUnchecked(const Recording& recording, const std::string& path);
// The largest recording read: 5000 iterations of 100,000 sites at 8 bytes a site. (A link to
// /dev/zero is read that far, into as much memory, before it is refused.)
constexpr std::uint64_t kLargestRecording = 4'000'000'000;
// Throws Error("<path>: ...") for a missing, truncated, corrupt, other-version or too large file.
Recording loadRecording(const std::string& path);
// Whether the file starts as a recording does, whatever its name (remesh --record takes any but
// a mesh's, and older versions took those too);
// false for a pipe, which it leaves unread for its reader (a recording through one is told by
// its name).
bool isRecording(const std::string& path);

}  // namespace lloydscope
