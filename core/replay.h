// One recorded iteration at a time, as the inspector shows it: the cells of that iteration and
// the mesh its sites make, computed when the iteration is chosen and not before.
#pragma once

#include "pipeline.h"

namespace lloydscope {

struct IterationView {
  int index = -1;
  std::vector<Vec2> sites;         // all of them: fixed first, then movable
  std::vector<BoundedCell> cells;  // with geometry, in site order
  std::vector<Vec3> liftedSites;   // on the input surface
  Mesh output;                     // what these sites would give as the result
  std::vector<Vec2> outputUV;      // where each output vertex lies in the parameter domain
  std::vector<int> outputSite;     // the site each output vertex is, or -1
  // On a surface that was cut open (its parameterized mesh has seams): `output` with its seams
  // stitched, and per vertex of `output` its vertex there (stitchSeams' vertexOf); empty otherwise.
  Mesh stitched;
  std::vector<int> stitchedVertex;
  // What the inspector measures: the stitched surface where there is one.
  const Mesh& measured() const { return stitched.triangles.empty() ? output : stitched; }
  // The vertex of measured() that vertex v of `output` is (-1: none).
  int measuredVertex(int v) const { return stitched.triangles.empty() ? v : stitchedVertex[v]; }
};

class Replay {
 public:
  // Shows the result the way the recording was made (relocate or retriangulate).
  explicit Replay(Recording recording);
  // Switches between the two where the recording allows relocate (sites from input vertices).
  void setMethod(RemeshMethod method);
  // Whether it does: every movable site is an inside vertex of the input (remesh --method
  // relocate, or the reference preset); other runs' sites have no vertex to move.
  bool canRelocate() const;

  const Recording& recording() const { return recording_; }
  // Where the parameterized mesh was cut open (seamEdges() of recording().input): empty for a
  // disk the pipeline did not cut.
  const std::vector<std::pair<int, int>>& seams() const { return seams_; }
  // The surface the recording is of: its disk, stitched back where it was cut open (the lesson
  // called a recording of the eight, of genus 2, "a topological disk").
  Topology surface() const;
  // A chart's seams with the other charts (Recording::sharedSeams), as edges of the views'
  // output meshes (retriangulate: its border vertices are the fixed sites, in order).
  const std::vector<std::pair<int, int>>& sharedSeamsOnOutput() const { return sharedOnOutput_; }
  const Domain& domain() const { return domain_; }
  RemeshMethod method() const { return method_; }
  int iterationCount() const { return static_cast<int>(recording_.iterations.size()); }

  // A new iteration from a run in progress.
  void append(IterationRecord record) { recording_.iterations.push_back(std::move(record)); }

  // The view of iteration k (clamped to the recorded range), recomputed only when k changes.
  const IterationView& view(int k);

 private:
  Recording recording_;
  Domain domain_;
  RemeshMethod method_;
  std::vector<std::pair<int, int>> seams_, sharedOnOutput_;
  std::vector<int> borderSite_;  // each input vertex's fixed site (its own parameter point), or -1
  IterationView view_;
  CellHints hints_;  // each site's parameter triangle in the last view: nearby iterations
                            // start their searches there
};

}  // namespace lloydscope
