// A last clean-up of a retriangulated surface, in 3D. The 2D relaxation makes cells round in
// the parameter domain; where the map stretches, they are not round on the surface. The polish
// relaxes on the surface itself: Delaunay edge flips, then Lloyd-like passes that move each
// inside vertex towards the centre of its ring within its tangent plane, mapped back onto the
// input surface through its parameter point (so it never leaves the surface), then flips again.
#pragma once

#include "remesh.h"
#include "ring_moves.h"

#include <functional>
#include <string>
#include <vector>

namespace lloydscope {

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

// A disk cut open from a surface (its border holds seams), made ready for stitching: edges
// that stitching would make edges of three triangles or more are flipped away, or split where
// no flip can (a few vertices added). The polish begins with it; a run without the polish
// needs it too (without it the femur's seams did not stitch). Returns seamPartners().
std::vector<int> prepareSeams(LiftedMesh& mesh, const SurfaceMap& surface);

}  // namespace lloydscope
