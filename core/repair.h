// Repairing the defects of a triangle soup that readMesh() refuses but files often have: a seam
// left unwelded, faces of zero area, faces turned the wrong way. Only when `--repair` asks.
#pragma once

#include "mesh.h"

namespace lloydscope {

struct RepairResult {
  Mesh mesh;
  // Vertices merged into another at the same position, less the copies made where fans of faces
  // only touch at a vertex (negative: a pinched vertex was split).
  int weldedVertices = 0;
  int droppedFaces = 0;    // faces left with a repeated corner by the welding, or repeating another
  int degenerateFaces = 0; // faces of zero area, collapsed or flipped away
  int turnedFaces = 0;     // faces turned to match their neighbours
  bool changed() const { return weldedVertices || droppedFaces || degenerateFaces || turnedFaces; }
};

// Welds vertices at exactly the same position, drops the faces that then repeat a corner or
// repeat another face, orients the faces consistently (a copy of a vertex where fans of faces
// only touch there, as a surface touching itself has), and removes the remaining zero-area faces
// by collapsing or flipping an edge: CGAL's repair_polygon_soup, orient_polygon_soup and
// remove_degenerate_faces. A mesh none of this changes comes back as it is.
RepairResult repairMesh(const Mesh& mesh);

}  // namespace lloydscope
