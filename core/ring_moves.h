// Local changes of a triangle mesh on a surface, which the polish (core/polish) and the last
// steps (core/last_steps) share: where a vertex's ring wants it, whether a move keeps its ring
// unfolded and its angles, relaxation passes on a surface, and a vertex merged into a neighbour.
#pragma once

#include "mesh.h"
#include "projection.h"

#include <string>
#include <utility>
#include <vector>

namespace lloydscope {

enum class PolishTarget {
  Voronoi,       // the centroid of its Voronoi cell within its ring (a Lloyd step on the mesh)
  Centroid,      // the area-weighted centroid of the ring's triangles (a Lloyd step)
  Circumcenter,  // the area-weighted circumcentre (optimal Delaunay triangulation, Chen & Xu)
};
constexpr PolishTarget kPolishTargets[] = {PolishTarget::Voronoi, PolishTarget::Centroid, PolishTarget::Circumcenter};
const char* toString(PolishTarget target);
PolishTarget parsePolishTarget(const std::string& text);  // throws Error on unknown names

// Where the ring of `v` wants it, projected onto its tangent plane: a 3D displacement.
// `normal` receives the ring's unit normal.
Vec3 relaxationMove(const Mesh& m, const Rings& rings, const std::vector<double>& weight, int v,
                    PolishTarget target, Vec3& normal);

// The unit normal of v's ring: its triangles' normals summed (weighted by their areas); zero
// where they cancel.
Vec3 ringNormal(const Mesh& m, const Rings& rings, int v);

// Whether moving `v` to `to` leaves every triangle of its ring facing along `up` (the ring's
// normal): not folded. Measured against the ring, not each triangle's old normal, so that a
// triangle that was folded (a vertex near the border, lifted beyond the border's chord) may
// unfold.
bool keepsRingUnfolded(const Mesh& m, const Rings& rings, int v, const Vec3& to, const Vec3& up);

// The smallest angle of v's ring with v moved to `to`, or -1 if that folds the ring.
double ringSmallestAngle(const Mesh& m, const Rings& rings, int v, const Vec3& to,
                         const Vec3& up);

// Whether moving v to `to` turns one of its triangles over (its normal by more than 90
// degrees). A spike's triangles turn steeply from the ring's normal: only this is ruled out.
bool turnsOver(const Mesh& m, const Rings& rings, int v, const Vec3& to);
// The smallest angle, in degrees, of v's triangles with v moved to `to`.
double smallestAngleOfRing(const Mesh& m, const Rings& rings, int v, const Vec3& to);

// Each border vertex's neighbours along the border, the one before and after (-1: inside).
std::pair<std::vector<int>, std::vector<int>> borderNeighbours(const Mesh& m);

// Merges `from` into `to` if that keeps the mesh manifold (the two share no neighbour but the
// third corners of the triangles on their edge: two inside, one on the border -- the link
// condition) and folds none of the triangles that keep `from`.
bool mergeVertex(Mesh& m, int from, int to);
// The marker mergeVertex() leaves where a triangle went (its three corners the same), and their
// erasure.
inline bool isMergeMarker(const Triangle& t) { return t[0] == t[1]; }
void eraseMergedTriangles(Mesh& m);

// Merges an inside vertex of each triangle under 10 degrees into a neighbour along the
// triangle's shortest edge it can go (keeping the mesh manifold and unfolded); the merged
// vertices are left unused. Returns how many were merged.
int collapseFlatTriangles(Mesh& mesh);

// A relaxation pass: each movable vertex that is not `fixed` (the border, at least) towards its
// ring's centroid within its tangent plane, onto `surface` by closest point, unless that folds
// its ring or drops its smallest angle under the lesser of what it was and 30 degrees (then half
// the way, or a quarter).
void relaxOnce(Mesh& m, const std::vector<bool>& movable, const std::vector<bool>& fixed,
               const SurfaceProjection& surface);

// Passes of relaxOnce() of the `movable` vertices, Delaunay flips after each, then valence flips
// and a last relaxation. With `local`, flips only touch edges at the movable vertices, and no
// valence flip is made (they may lower angles to 25 degrees).
void relaxOnSurface(Mesh& m, const std::vector<bool>& movable, const SurfaceProjection& surface,
                    int passes, bool local = false);

// `marked` and the vertices that share a triangle with one.
std::vector<bool> withNeighbours(const Mesh& m, const std::vector<bool>& marked);

// The smallest angle of the triangles that touch a marked vertex.
double smallestAngleAround(const Mesh& m, const std::vector<bool>& marked);
double meanEdgeLength(const Mesh& m);

}  // namespace lloydscope
