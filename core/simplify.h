// Making an input the right size: quadric edge collapse (Garland-Heckbert) down to a target,
// and Loop subdivision up to one, both from CGAL.
#pragma once

#include "mesh.h"

#include <string>

namespace lloydscope {

struct SimplifyOptions {
  // The target: the first of these that is set (> 0).
  int vertices = 0;
  int faces = 0;
  double ratio = 0;  // of the input's vertices, in (0, 1]
};

struct SimplifyResult {
  Mesh mesh;
  int collapses = 0;
  double milliseconds = 0;
  // Where it stopped above the size asked, at how many and why ("" where it reached it): a
  // closed surface at --vertices 3 stopped at 14 without a word.
  std::string stoppedShort;
};

// Collapses the cheapest edges by the quadric error of Garland and Heckbert until the target
// is met or no edge can go. The border stays the border: a border edge collapses to a point of
// itself (after earlier collapses a chord of the input's border, so that a curved border's
// vertices may come off it a little: 0.36% of the diagonal on the sphere cap at 30 vertices),
// an edge with one border end to that end, and no edge joining two border vertices through the
// inside collapses (it would pinch the surface). No collapse turns a triangle around it by 90
// degrees or more (several collapses may still turn one over between them, and the input's own
// folds stay). A mesh far from the origin is simplified about
// its own centre: the quadrics lose its detail there. Throws Error naming `name` for a target
// that is not positive; one not smaller gives the input as it is.
SimplifyResult simplify(const Mesh& input, const SimplifyOptions& options, const std::string& name);
// Whether simplify() would collapse anything at all (its target under the input's size): a
// caller warns of a slow one first. Throws Error as simplify() does on the options.
bool simplifyCollapses(const Mesh& input, const SimplifyOptions& options, const std::string& name);

// The most triangles around one vertex for which the edge collapse is quick: CGAL costs every
// edge around a vertex again after each collapse there, each from that vertex's whole ring, in
// time cubic in their number (a polar grid of 5 rings with a hub of 1000 triangles, halved:
// 1.3 s; 2000: 9.6 s; 3000: 32 s).
constexpr int kMostTrianglesAroundAVertexToSimplify = 1000;
int mostTrianglesAroundAVertex(const Mesh& mesh);

// Loop subdivision rounds until the mesh has at least `vertices` vertices.
Mesh subdivideTo(const Mesh& input, int vertices);

// A model brought to `size` vertices as issue 5's bench prepares its inputs: Loop-subdivided
// to twice that if it is smaller, then quadric-simplified (simplify()).
Mesh benchInput(const Mesh& model, int size, const std::string& name);

}  // namespace lloydscope
