// Cutting a surface open into one topological disk along a cut graph (issue 6): closed
// surfaces, several boundary loops, handles. The disk can then be parameterized; its border
// holds each cut edge twice.
#pragma once

#include "mesh.h"
#include "topology.h"

#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace lloydscope {

// Copies of one seam sample are at the same point: within this fraction of the diagonal.
constexpr double kSeamTolerance = 1e-9;
// How far apart two copies of one seam sample of `mesh` may be: kSeamTolerance of its diagonal,
// or where it lies far from the origin, a few of its coordinates' rounding steps (each copy is
// lifted through triangles of its own side): an annulus 10^8 from the origin, its size 1,
// did not stitch back, its copies 1.5e-8 apart against a tolerance of 2e-9.
double seamTolerance(const Mesh& mesh);

struct CutSummary {
  int seamEdges = 0;      // cut edges inside the surface (each is two border edges of the disk)
  int extremityCuts = 0;  // slits added to bound the distortion
  // The conformal (LSCM) map's area scale on the disk, its 99th percentile over its 1st (over the
  // vertices; the extremes are a vertex or two): how much more it shrinks one part of the
  // surface than another. 0: not measured (a disk not offered slits: relocate, --no-slit).
  double areaSpread = 0;
};

struct CutResult {
  Mesh disk;                 // a topological disk
  std::vector<int> original;  // per disk vertex, the input vertex it is a copy of
  std::vector<std::pair<int, int>> seam;  // the cut edges, as input vertex pairs (a < b)
  // Per disk vertex: on a seam, and a node of the cut graph (where seams and the input's
  // border meet, branch or end: degree other than 2). What SiteOptions needs to sample both
  // copies of every seam alike.
  std::vector<bool> onSeam, seamNode;
  CutSummary summary;
  Topology topology;  // of the surface that was cut: what stitching must give back
};

struct CutOptions {
  // Slits are added from the most shrunken vertex while the area spread is above this, each
  // kept only if it lowers the spread by a tenth or more.
  double maxAreaSpread = 20;
  int maxExtremityCuts = 12;
  // A disk is slit only where its own map's spread is above slitDisksAbove (then, as any
  // surface, while it is above maxAreaSpread), and the slits are kept only if they bring it
  // under keepDiskSlitsUnder: a nearly closed shape (CGAL's lion head at 2-3 10^3, the
  // mannequin at 6 10^4, a camel head at 5 10^4 .. 2 10^5), whose far side the map to a disk
  // shrinks so much that the cells there come out irregular. remesh() makes such a disk whole
  // too and keeps the better result (the slits through a terrain's peaks cost).
  double slitDisksAbove = 1e3;
  double keepDiskSlitsUnder = 1e4;
  // Unless the whole disk's spread is above this: its map then has triangles too small for
  // doubles (the fold test's 1e-14 of the total area, core/parameterization), and any slits are
  // better than none (CGAL's camel clipped in half, four legs: 8 10^22 whole, 3 10^4 slit twice).
  double keepDiskSlitsOver = 1e10;
  // Called once where a disk's spread is above slitDisksAbove, before its slits are tried
  // (they take most of the cut's time on a large scan): remesh() starts the run that keeps it
  // whole then, beside them.
  std::function<void()> slittingDisk;
};

// The cut, in two parts. Topological: the border loops joined one by one to the nearest by
// shortest paths, then around each handle the shortest loop a tree-cotree construction offers
// (a closed genus-0 surface gets a slit between two extremities instead). Geometric: while
// the conformal map of the disk shrinks one part far more than another, a shortest path
// from the most shrunken vertex to the cut (geometry images' cut augmentation) -- a short cut
// through a nearly closed shape makes any map to a disk useless (shared/notes/cgal.md).
// A disk that needs no slit comes back unchanged. The mesh must be a valid manifold with one
// connected component; throws Error("<name>: ...") otherwise.
CutResult cutToDisk(const Mesh& mesh, const std::string& name, const CutOptions& options = {});

// Per point, the first of the points within `tolerance` of it (and of those, and so on) among
// those `among` flags (empty: all), or itself.
std::vector<int> firstCopies(const std::vector<Vec3>& points, const std::vector<bool>& among, double tolerance);

// Per vertex of a remeshed disk, the vertex it becomes when stitched: the first of the border
// vertices within `tolerance` of it (the copies of one seam sample), or itself.
std::vector<int> seamPartners(const Mesh& disk, double tolerance);

// The border edges of a cut or remeshed disk that have a twin on the other copy of their seam
// (both ends partners of the twin's ends): the seams, for the inspector to draw. Each edge is
// (a, b) in the border's order; the original border's own edges are not among them.
std::vector<std::pair<int, int>> seamEdges(const Mesh& disk, double tolerance);

// Merges the border vertices of a remeshed disk that lie within `tolerance` of each other (the
// copies of each seam sample): the cut surface's topology back. Vertices keep their order.
// `seamVertex`, if given, receives per vertex of the result whether it was on a seam;
// `vertexOf`, per vertex of the disk, its vertex in the result (both copies of a seam sample
// the one they became; -1 for a vertex that went).
Mesh stitchSeams(const Mesh& disk, double tolerance, std::vector<bool>* seamVertex = nullptr,
                 std::vector<int>* vertexOf = nullptr);

// Leaves no triangle of no area, which no reader of the result takes: drops each flat ear of
// the border (three border samples in a row on a straight border, which a map with a round
// border bent into an ear, the middle one in no other triangle) and its middle vertex, then
// flips away each flat triangle that has a triangle with area beyond its longest edge (a fan of
// such samples bent into a pocket).
void dropFlatTriangles(Mesh& mesh);

// Removes the stitched surface's (nearly) flat triangles -- a vertex lifted onto a seam where
// the map shrinks the surface most -- by CGAL's edge flips and collapses (caps with an angle over
// 179.5 degrees, needles 10^4 times longer than wide). Returns how many flat ones are left.
int removeFlatTriangles(Mesh& mesh);

}  // namespace lloydscope
