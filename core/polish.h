// A last clean-up of a retriangulated surface, in 3D. The 2D relaxation makes cells round in
// the parameter domain; where the map stretches, they are not round on the surface. The polish
// relaxes on the surface itself: Delaunay edge flips, then Lloyd-like passes that move each
// inside vertex towards the centre of its ring within its tangent plane, mapped back onto the
// input surface through its parameter point (so it never leaves the surface), then flips again.
#pragma once

#include "projection.h"
#include "remesh.h"

#include <functional>
#include <string>
#include <vector>

namespace lloydscope {

enum class PolishTarget {
  Voronoi,       // the centroid of its Voronoi cell within its ring (a Lloyd step on the mesh)
  Centroid,      // the area-weighted centroid of the ring's triangles (a Lloyd step)
  Circumcenter,  // the area-weighted circumcentre (optimal Delaunay triangulation, Chen & Xu)
};

struct PolishOptions {
  int iterations = 3;  // flip-and-relax passes; 0: flips only
  PolishTarget target = PolishTarget::Centroid;
  // Then passes of valence-improving flips (where no angle falls under 25 degrees), each
  // followed by a relaxation pass, which rounds the flipped triangles again. 5 passes at 25
  // degrees met issue 5's bars on 8 of the bench's 15 inputs, 2 at 30 degrees on 6.
  int valencePasses = 5;
  // Then passes over the triangles with small angles only: vertex moves and edge flips that
  // raise the smallest angle around them.
  int repairPasses = 3;
  // In those passes the border's vertices may slide along the border (not on a cut surface,
  // nor off a corner): across a sharp corner the border is sampled evenly into a wedge, whose
  // strip of triangles has a smaller angle than the corner's.
  bool slideBorder = true;
  // The border holds seams that will be stitched (core/cut): no flip may join two border
  // vertices or double an edge of the stitched mesh, and no flat triangle loses a vertex.
  bool seams = false;
};

// The surface the polish keeps its vertices on, seen through a parameter domain.
struct SurfaceMap {
  const Mesh& mesh;      // the parameterized mesh: its triangles give the local Jacobians
  const Domain& domain;  // its parameter domain
  // The surface point at a location of the domain; empty: barycentric on `mesh`'s triangles.
  std::function<Vec3(const Location&)> lift = {};
  Vec3 at(const Location& l) const;
};

// The border stays where it is: its edges do not flip, and its vertices only slide along it
// where that raises a small angle (PolishOptions::slideBorder). A flat triangle (under 10
// degrees) that nothing else fixes loses an edge: a vertex fewer. `surfaceDensity` (of the
// domain's triangles; empty: uniform) weights the centres so that a density that asked for
// smaller cells keeps them. Vertices keep their order (but for merged ones, and on a cut surface a few
// added at the end where an edge that stitching would double is split); mesh.uv follows.
void polish(LiftedMesh& mesh, const SurfaceMap& surface, const Density& surfaceDensity,
            const PolishOptions& options);

// A stitched surface's seams relaxed (core/cut): polish() cannot move a vertex of a seam, as its
// copies on the disk must stay together; once stitched it is an inside vertex like any other.
// The seam vertices and their neighbours move towards their ring's centroid within their
// tangent plane, onto `surface` by closest point, unless that folds their ring or drops its
// smallest angle under the lesser of what it was and 30 degrees; Delaunay flips follow each
// pass, valence flips (as in polish) the last.
void polishSeams(Mesh& stitched, const std::vector<bool>& seamVertex, const Mesh& surface, int passes);

// Where a thin tip of the surface (a horn, a finger, an ear) ends between the result's vertices,
// the result cuts it off, and the Hausdorff distance is what it cut. In each round the input
// vertices farther than half an edge length from the result, farthest first and two edge
// lengths apart (32 at most), each take the nearest inside corner of the result's triangle
// closest to them, which is snapped there and stays while the two rings around it relax on
// `surface` (as polishSeams does, flipping only there). A snap is made if it turns none of the
// vertex's triangles over, and kept if the smallest angle of the triangles around stays at the
// lesser of the mesh's smallest angle and 30 degrees, or, whatever the angles, if the tip was
// more than an edge length away. A refused tip is not tried again. Returns the vertices snapped.
std::vector<int> snapToTips(Mesh& result, const SearchableSurface& surface, int rounds = 3);

// Whether moving v to `to` turns one of its triangles over (its normal by more than 90
// degrees). A spike's triangles turn steeply from the ring's normal: only this is ruled out.
bool turnsOver(const Mesh& m, const Rings& rings, int v, const Vec3& to);
// The smallest angle, in degrees, of v's triangles with v moved to `to`.
double smallestAngleOfRing(const Mesh& m, const Rings& rings, int v, const Vec3& to);

// Flips interior edges whose two opposite angles sum to more than 180 degrees (the 3D
// Delaunay criterion) where the flip neither duplicates an edge nor folds the surface.
// Returns the number of flips.
int flipToDelaunay(Mesh& mesh);

// Valence flips on a finished surface: where the squared deviation of the four valences from
// regular falls, no more of them are irregular, the two new triangles keep every angle at
// `smallestAngle` degrees or more, and the surface does not fold. Returns the number of flips.
// 35 degrees: on 36 disks (the bench's 15, a face scan, a camel head, CGAL's closed samples
// clipped in half) 30 met as many of issue 5's bars but took smallest angles of 35-37 degrees
// down to 30-33.
constexpr double kLastValenceFlipAngle = 35.0;
int flipToRegularity(Mesh& mesh, double smallestAngle = kLastValenceFlipAngle);

// Valence moves on a finished surface that flipToRegularity() cannot make: one flip, or up to
// four where the first alone gains nothing (the first ones move a 5-7 pair of valences along,
// none of them leaving more vertices irregular, until it meets another defect; the last cancels
// them). Each is tried with the two rings around it relaxed on `surface` (by
// closest point; the border and the `pinned` vertices stay), its flips making angles down to
// `degrees`. It is kept where it leaves fewer vertices irregular (or as many, nearer regular)
// and the triangles around it end with no angle under the lesser of their smallest before and
// 30 degrees, their smallest angles' mean lower by a quarter of a degree at most, and neither
// their chords nor the input's vertices under them farther apart than before (or than three
// quarters of the farthest anywhere): a flip across a ridge cuts the ridge off. Returns how many were kept.
// 20 degrees: on 36 disks (as for kLastValenceFlipAngle) 15, 20 and 25 met as many of issue 5's
// bars, at 1 and at 0.75 times their sizes. Up to four flips instead of two: all bars met on 28
// of the 36 instead of 26 (23 instead of 19 at 0.75 times their sizes), mean irregularity
// 13.0 -> 11.5% (up to three: 12.1%; up to five: 11.25%, no more bars met). No move may push a
// vertex more than two neighbours off regular, farther than it was (an 8 to a 9 for two
// vertices made regular): where the angles around were small already, that left them so
// (CGAL's lion in charts, 14 deg); the search goes on past such a sequence, as past one that
// gains nothing. Of the sequences a first flip starts, the best two are tried (the best may be
// refused where the next would do): all bars met on 30 of the 36 instead of 28.
int relaxedValenceMoves(Mesh& mesh, const SearchableSurface& surface, const std::vector<int>& pinned = {},
                        double degrees = 20.0);

// Where small angles are left: each free vertex (not on the border, not `pinned`) of a triangle
// with an angle under `below` degrees, worst first, moves to the point of the surface near it
// (a compass search in its tangent plane, by closest point; none of its triangles may face
// over 84 degrees from their mean normal, or, where they already do, around a tip or on a sharp
// ridge, turn over) where its triangles' smallest angle is largest, and their mean smallest
// angle no more than a quarter of a degree under what it was before the step (the vertex's own
// moves; a neighbour's may lower it too). A move is kept where, as for relaxedValenceMoves(),
// neither the chords nor the input's vertices under them end farther apart than before (or
// than three quarters of the farthest anywhere). Returns the moves kept. 35 degrees (as the
// polish's repair): on the 36 disks, 23 met all of issue 5's bars (22 without the step) and the
// mean smallest angle went 29.64 -> 31.50 degrees (30.76 at 30 degrees); at 0.75 times their
// sizes 17 (17), 30.31 -> 32.14 degrees.
int raiseSmallAngles(Mesh& mesh, const SearchableSurface& surface, const std::vector<int>& pinned = {},
                     double below = 35.0);

// Each free vertex (not on the border, not `pinned`), those of the smallest angles first,
// moves to the point of the surface near it (as raiseSmallAngles() searches) where its
// triangles' mean smallest angle is largest, their smallest angle no lower than it was, where
// the chords and the input's vertices under them end no farther apart than before (or than
// three quarters of the farthest anywhere). Returns the moves kept. On the 36 disks of issue 5's sweep: the mean
// of the average smallest angles 54.19 -> 54.84 degrees, all bars met on 26 instead of 25 (at
// 0.75 of their sizes 54.06 -> 54.67 degrees, 19 instead of 18); a second pass added 0.17
// degrees on nefertiti at 1000 for 60 ms more; letting the smallest angle fall to 35 degrees
// (where it was over that) added 0.2 more and took the minima down to 35.
int raiseMeanAngles(Mesh& mesh, const SearchableSurface& surface, const std::vector<int>& pinned = {});

// A border edge under 0.7 of the mean edge length (two samples the border had to keep close
// together: the seam nodes of two charts near a corner of the border) leaves a thin triangle
// on it. Each, shortest first, loses one end, merged into the other, where that end is no
// further than 0.3 edge lengths from the chord that replaces its two border edges,
// the mesh stays a disk around it and unfolded, and, with the two rings around relaxed on
// `surface`, the smallest angle of the triangles that changed rises. `pinned` vertices stay;
// where an edge collapses, the mesh's unused vertices are dropped and `pinned` renumbered with
// it. Returns how many edges were collapsed.
int collapseShortBorderEdges(Mesh& mesh, const SearchableSurface& surface, std::vector<int>& pinned);

// Merges an inside vertex of each triangle under 10 degrees into a neighbour along the
// triangle's shortest edge it can go (keeping the mesh manifold and unfolded); the merged
// vertices are left unused. Returns how many were merged.
int collapseFlatTriangles(Mesh& mesh);

const char* toString(PolishTarget target);
PolishTarget parsePolishTarget(const std::string& text);  // throws Error on unknown names

}  // namespace lloydscope
