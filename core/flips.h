// Edge flips on a triangle mesh: the rules that ask for one, the state that makes them, and the
// search for valence moves (a flip, or a few that move a 5-7 pair of valences next to another
// defect and cancel them). The polish (core/polish) and the last steps (core/last_steps) flip
// with them.
#pragma once

#include "mesh.h"
#include "metrics.h"

#include <algorithm>
#include <functional>
#include <initializer_list>
#include <map>
#include <optional>
#include <utility>
#include <vector>

namespace lloydscope {

// What a flip rule sees of edge (a, b) between triangles (a, b, c) and (b, a, d), which the
// flip would turn into (c, a, d) and (d, b, c).
struct Quad {
  Vec3 a, b, c, d;
  // How far the four vertices' valences are from regular (6 inside, 4 on the border), summed
  // as squares, before and after the flip; and how many of them are irregular.
  int irregularityBefore, irregularityAfter;
  int irregularBefore, irregularAfter;
  // On a cut surface: edge (a, b) and another become one edge of the stitched mesh (an inside
  // vertex joined to both copies of a seam sample), which would have 4 triangles.
  bool doubledWhenStitched;
  double smallestBefore() const { return std::min(smallestAngleDeg(a, b, c), smallestAngleDeg(b, a, d)); }
  double smallestAfter() const { return std::min(smallestAngleDeg(c, a, d), smallestAngleDeg(d, b, c)); }
};
using FlipRule = std::function<bool(const Quad& q)>;

bool notDelaunay(const Quad& q);  // the two angles opposite the edge sum to over 180 degrees
bool doubledWhenStitched(const Quad& q);
bool raisesSmallestAngle(const Quad& q);
// Valence flips (as in Botsch and Kobbelt's remesher) where no angle of the pair falls under
// `degrees`.
bool raisesRegularityAbove(const Quad& q, double degrees);
// In the polish, down to 25 degrees: the relaxation and the repair after them lift the angles
// again.
bool raisesRegularity(const Quad& q);

// The state edge flips need: the face of each directed edge, the valences, and on a cut surface
// (`stitched`: seamPartners() of the mesh) how many triangle sides each edge of the stitched
// mesh has.
class EdgeFlips {
 public:
  // Edge (a, b) of faces f1 = (a, b, c) and f2 = (b, a, d), which a flip turns into (c, a, d)
  // and (d, b, c); `quad` is what a rule sees of it.
  struct Candidate {
    int a, b, c, d, f1, f2;
    Triangle before1, before2;
    Quad quad;
  };

  EdgeFlips(Mesh& mesh, const std::vector<int>* stitched);

  // The flip of (a, b), if (a, b) is an inside edge whose flip would duplicate no edge; on a
  // cut surface, join no two border vertices and make no edge that stitching would double (an
  // inside vertex joined to both copies of a seam sample).
  std::optional<Candidate> candidate(int a, int b) const;

  // Whether the two new triangles would face away from the two old ones (or be flat: the sine
  // of their angle at c or d under 1e-12, whatever the mesh's scale).
  bool folds(const Candidate& k) const;

  // Whether the flip keeps every angle of the two new triangles at `degrees` or more and does
  // not fold the surface.
  bool keeps(const Candidate& k, double degrees) const {
    return k.quad.smallestAfter() >= degrees && !folds(k);
  }

  void flip(const Candidate& k) { replace(k, {k.c, k.a, k.d}, {k.d, k.b, k.c}, -1); }
  void undo(const Candidate& k) { replace(k, k.before1, k.before2, +1); }

  // How far v's valence, changed by `change`, is from regular (6 inside, 4 on the border).
  int deviation(int v, int change) const {
    const int off = valence_[v] + change - (border_[v] ? 4 : 6);
    return off * off;
  }
  int irregular(int v, int change) const { return deviation(v, change) > 0 ? 1 : 0; }

  const std::vector<int>& facesAt(int v) const { return facesOf_[v]; }

  // The inside edges of the faces at `vertices`, each once as (a, b) with a < b: those at the
  // vertices and those of the rim, whose other face is not in the list.
  std::vector<std::pair<int, int>> edgesAround(std::initializer_list<int> vertices) const;

 private:
  std::pair<int, int> stitchedEdge(int a, int b) const {
    const int sa = (*stitched_)[a], sb = (*stitched_)[b];
    return {std::min(sa, sb), std::max(sa, sb)};
  }
  int third(int f, int a, int b) const {
    for (int v : mesh_.triangles[f])
      if (v != a && v != b) return v;
    return -1;
  }
  // The face with the directed edge a -> b, found among a's faces; -1 where there is none.
  int faceWith(int a, int b) const;
  // Sets faces f1, f2 of `k` to t1, t2; `sign` -1 for the flip, +1 for its undoing.
  void replace(const Candidate& k, const Triangle& t1, const Triangle& t2, int sign);

  Mesh& mesh_;
  const std::vector<int>* stitched_;
  std::map<std::pair<int, int>, int> stitchedEdges_;  // each triangle side counted once
  std::vector<std::vector<int>> facesOf_;              // each vertex's faces
  std::vector<int> valence_;
  std::vector<bool> border_;
};

// Flips interior edges where `rule` asks and the flip neither duplicates an edge nor folds the
// surface. On a cut surface (`stitched`: seamPartners() of the mesh), nor joins two border
// vertices, nor makes an edge that stitching would double (an inside vertex joined to both
// copies of a seam sample). With `region`, only edges with an end in it. Returns the number
// of flips.
int flipEdges(Mesh& mesh, const FlipRule& rule, const std::vector<int>* stitched = nullptr,
              const std::vector<bool>* region = nullptr);

// A flip, or a sequence of up to kMaxMoveFlips where the first alone makes no vertex more
// regular: a 5-7 pair of valences moved (glided) next to another defect, the last flip
// cancelling them. `edges` in the order they flip, each in the mesh as the flips before it
// left it.
struct ValenceMove {
  std::vector<std::pair<int, int>> edges;
  std::pair<int, int> gain;  // (fewer irregular vertices, less squared deviation)
};

// What changing some valences gains: fewer irregular vertices, then less squared deviation;
// and whether a vertex ends more than two neighbours off regular that was not that far before
// (see relaxedValenceMoves()). The single flips, the search and tryMove() share it.
class ValenceGain {
 public:
  // v's valence changed from (what it is now + from) to (what it is now + to).
  void add(const EdgeFlips& flips, int v, int from, int to) {
    gain_.first += flips.irregular(v, from) - flips.irregular(v, to);
    gain_.second += flips.deviation(v, from) - flips.deviation(v, to);
    tooFar_ |= flips.deviation(v, to) > std::max(4, flips.deviation(v, from));
  }
  const std::pair<int, int>& value() const { return gain_; }
  // Whether it makes the valences better: fewer vertices irregular, or as many nearer regular,
  // none pushed too far.
  bool improves() const { return gain_ > std::pair{0, 0} && !tooFar_; }

 private:
  std::pair<int, int> gain_{0, 0};
  bool tooFar_ = false;
};

// A flip's valence changes: -1 at the ends of the edge it takes away, +1 at those it makes.
int changeOf(const EdgeFlips::Candidate& k, int v);

// How many flips the search for sequences of valence moves may look at in one call, per
// vertex of the mesh. Around vertices of valence 10 and more nearly every flip is worth
// looking at, and the search branches on all their edges: CGAL's cheese (closed, genus 133;
// 175 vertices of valence 10-29 at 500) looked at 10,000-24,000 a vertex and took 79 s. The
// 93 halves of issue 5's sweep look at 1,100 at most (the blade's at 1000; most under 400),
// so none of them changes.
constexpr size_t kSearchPerVertex = 2000;

// The valence moves that leave fewer vertices irregular (or as many, nearer regular) whose
// flips neither fold the surface nor make an angle under `degrees`: every such flip, and for
// every other flip the best two sequences it starts (kMovesPerFirstFlip), if any, while the
// search has looked at no more than `searchPerVertex` flips a vertex; best first. With `near`,
// only those whose first edge has an end in it. The mesh is left as it was.
std::vector<ValenceMove> valenceMoves(EdgeFlips& flips, const Mesh& mesh, double degrees,
                                      const std::vector<bool>* near = nullptr,
                                      size_t searchPerVertex = kSearchPerVertex);

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

}  // namespace lloydscope
