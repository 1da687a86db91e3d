// From relaxed sites back to a 3D mesh.
#pragma once

#include "domain.h"

#include <string>
#include <vector>

namespace lloydscope {

enum class RemeshMethod { Relocate, Retriangulate };

// The 3D point of the input surface at parameter point p (barycentric coordinates in the
// parameter triangle that holds p; points outside the domain go to its closest point).
// `hint`, a triangle at or near p (as computeCells reports), skips the spatial search.
Vec3 lift(const Mesh& input, const Domain& domain, const Vec2& p, int hint = -1);

// The reference's area-based method: the input's connectivity, each inside vertex moved to the
// site that started at it (movableVertex[i] started site i, now at sites[i]) and lifted to the
// surface. Where sites have moved past one another, the input's triangles no longer fit them:
// moved all the way, a vertex would turn triangles over (139 of the bumpy disk's 1908 faced
// the other way in 3D). So a vertex goes towards its site only as far as its triangles stay
// unfolded in the domain and no sliver (5 degrees: with none, the edge of a fold left the bumpy
// disk a 0.0-degree angle; with 15, 679 of its 910 vertices stopped short, the average smallest
// angle 28.3 degrees instead of 30.6), in sweeps over the vertices (a neighbour's move may let
// it go further); `heldBack` counts those left short of their sites. The bumpy disk: 2 faces
// the other way in 3D, 291 vertices short.
struct Relocation {
  Mesh mesh;
  std::vector<Vec2> uv;  // per vertex, its parameter point
  int heldBack = 0;
};
Relocation relocate(const Mesh& input, const Domain& domain, const std::vector<int>& movableVertex,
                    const std::vector<Vec2>& sites);

// A mesh on the input surface whose vertices each sit at a known point of the domain.
struct LiftedMesh {
  Mesh mesh;
  std::vector<Vec2> uv;  // per vertex, its parameter point
};

// The reference's alternative: a new mesh, the constrained Delaunay triangulation of the
// border samples (in order, counter-clockwise, joined by constraint edges) and the movable
// sites, restricted to the domain and lifted to 3D. Vertices: border samples, then sites.
// `borderPoints`, if not empty, are the border samples' points (InitialSites::fixedPoints),
// taken as they are. Throws Error("<name>: ...") where the border crosses itself or has fewer
// than 3 samples.
LiftedMesh retriangulate(const Mesh& input, const Domain& domain,
                         const std::vector<Vec2>& border, const std::vector<Vec2>& movableSites,
                         const std::string& name, const std::vector<Vec3>& borderPoints = {});

// The 2D triangles of retriangulate(), before lifting (same vertex order); throws Error where
// the border crosses itself or has fewer than 3 samples. Of border samples at the same place,
// the last is in the triangles, the others in none.
std::vector<Triangle> triangulateSites(const std::vector<Vec2>& border,
                                       const std::vector<Vec2>& movableSites);

}  // namespace lloydscope
