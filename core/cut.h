// Cutting a surface open into one topological disk along a cut graph (issue 6): closed
// surfaces, several boundary loops, handles. The disk can then be parameterized; its border
// holds each cut edge twice.
#pragma once

#include "mesh.h"

#include <string>
#include <utility>
#include <vector>

namespace lloydscope {

struct CutResult {
  Mesh disk;                 // a topological disk
  std::vector<int> original;  // per disk vertex, the input vertex it is a copy of
  std::vector<std::pair<int, int>> seam;  // the cut edges, as input vertex pairs (a < b)
  // Per disk vertex: on a seam, and a node of the cut graph (where seams and the input's
  // border meet, branch or end: degree other than 2). What SiteOptions needs to sample both
  // copies of every seam alike.
  std::vector<bool> onSeam, seamNode;
};

// The cut graph: the edges that no dual spanning tree (a breadth-first walk over the faces
// from face 0) crosses, pruned of dangling branches; the input's own boundary edges stay.
// What remains joins the boundary loops and runs around every handle. A closed surface of
// genus 0 has none left, and is slit instead along shortest paths joining three of its
// extremities (each the vertex farthest from the ones before), so that no region is enclosed
// by a short cut (shared/notes/cgal.md: a small hole makes every map to a disk useless).
// A disk comes back unchanged. The mesh must be a valid manifold with one connected
// component; throws Error("<name>: ...") otherwise.
CutResult cutToDisk(const Mesh& mesh, const std::string& name);

// Per vertex of a remeshed disk, the vertex it becomes when stitched: the first of the border
// vertices within `tolerance` of it (the copies of one seam sample), or itself.
std::vector<int> seamPartners(const Mesh& disk, double tolerance);

// Merges the border vertices of a remeshed disk that lie within `tolerance` of each other (the
// copies of each seam sample): the cut surface's topology back. Vertices keep their order.
Mesh stitchSeams(const Mesh& disk, double tolerance);

}  // namespace lloydscope
