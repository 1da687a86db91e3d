#include "flips.h"

#include <algorithm>
#include <tuple>

namespace lloydscope {

bool notDelaunay(const Quad& q) {
  return cornerAnglesDeg(q.c, q.a, q.b)[0] + cornerAnglesDeg(q.d, q.b, q.a)[0] > 180.0 + 1e-9;
}

bool doubledWhenStitched(const Quad& q) { return q.doubledWhenStitched; }

bool raisesSmallestAngle(const Quad& q) { return q.smallestAfter() > q.smallestBefore() + 1e-6; }

bool raisesRegularityAbove(const Quad& q, double degrees) {
  return q.irregularityAfter < q.irregularityBefore && q.smallestAfter() >= degrees;
}
constexpr double kValenceFlipAngle = 25.0;  // (see raisesRegularity())
bool raisesRegularity(const Quad& q) { return raisesRegularityAbove(q, kValenceFlipAngle); }

EdgeFlips::EdgeFlips(Mesh& mesh, const std::vector<int>* stitched) : mesh_(mesh), stitched_(stitched) {
  if (stitched_)
    for (const Triangle& t : mesh_.triangles)
      for (int k = 0; k < 3; ++k) ++stitchedEdges_[stitchedEdge(t[k], t[(k + 1) % 3])];
  facesOf_.resize(mesh_.vertexCount());
  for (int f = 0; f < mesh_.faceCount(); ++f)
    for (int v : mesh_.triangles[f]) facesOf_[v].push_back(f);
  VertexEdges edges = vertexEdges(mesh_);
  valence_ = std::move(edges.valence);
  border_ = std::move(edges.onBoundary);
}

std::optional<EdgeFlips::Candidate> EdgeFlips::candidate(int a, int b) const {
  const int f1 = faceWith(a, b), f2 = faceWith(b, a);
  if (f1 < 0 || f2 < 0) return std::nullopt;  // border, or gone
  const int c = third(f1, a, b), d = third(f2, a, b);
  if (c < 0 || d < 0 || c == d || faceWith(c, d) >= 0 || faceWith(d, c) >= 0) return std::nullopt;
  if (stitched_ && ((border_[c] && border_[d]) || stitchedEdges_.count(stitchedEdge(c, d))))
    return std::nullopt;
  const Quad quad{mesh_.points[a], mesh_.points[b], mesh_.points[c], mesh_.points[d],
                  deviation(a, 0) + deviation(b, 0) + deviation(c, 0) + deviation(d, 0),
                  deviation(a, -1) + deviation(b, -1) + deviation(c, 1) + deviation(d, 1),
                  irregular(a, 0) + irregular(b, 0) + irregular(c, 0) + irregular(d, 0),
                  irregular(a, -1) + irregular(b, -1) + irregular(c, 1) + irregular(d, 1),
                  stitched_ && stitchedEdges_.at(stitchedEdge(a, b)) > 2};
  return Candidate{a, b, c, d, f1, f2, mesh_.triangles[f1], mesh_.triangles[f2], quad};
}

bool EdgeFlips::folds(const Candidate& k) const {
  const Vec3 before = faceNormal(mesh_, k.before1).normalized() + faceNormal(mesh_, k.before2).normalized();
  const Vec3 m1 = faceNormal(mesh_, {k.c, k.a, k.d}), m2 = faceNormal(mesh_, {k.d, k.b, k.c});
  const Vec3 &a = mesh_.points[k.a], &b = mesh_.points[k.b], &c = mesh_.points[k.c], &d = mesh_.points[k.d];
  const double flat = 1e-12 * (d - c).norm();
  return m1.dot(before) <= 0 || m2.dot(before) <= 0 || m1.norm() <= flat * (a - c).norm() ||
         m2.norm() <= flat * (b - d).norm();
}

std::vector<std::pair<int, int>> EdgeFlips::edgesAround(std::initializer_list<int> vertices) const {
  std::vector<std::pair<int, int>> edges;
  for (int v : vertices)
    for (int f : facesOf_[v])
      for (int k = 0; k < 3; ++k) {
        const int a = mesh_.triangles[f][k], b = mesh_.triangles[f][(k + 1) % 3];
        if (faceWith(b, a) >= 0) edges.emplace_back(std::min(a, b), std::max(a, b));
      }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  return edges;
}

int EdgeFlips::faceWith(int a, int b) const {
  for (int f : facesOf_[a]) {
    const Triangle& t = mesh_.triangles[f];
    for (int k = 0; k < 3; ++k)
      if (t[k] == a && t[(k + 1) % 3] == b) return f;
  }
  return -1;
}

void EdgeFlips::replace(const Candidate& k, const Triangle& t1, const Triangle& t2, int sign) {
  mesh_.triangles[k.f1] = t1;
  mesh_.triangles[k.f2] = t2;
  valence_[k.a] += sign, valence_[k.b] += sign, valence_[k.c] -= sign, valence_[k.d] -= sign;
  // a leaves f2 and b f1 (or come back); c joins f2 and d f1 (or leave).
  for (auto [v, from, to] : {std::tuple{k.a, k.f2, -1}, std::tuple{k.b, k.f1, -1},
                             std::tuple{k.c, -1, k.f2}, std::tuple{k.d, -1, k.f1}}) {
    if (sign > 0) std::swap(from, to);
    std::vector<int>& faces = facesOf_[v];
    if (from >= 0) faces.erase(std::find(faces.begin(), faces.end(), from));
    if (to >= 0) faces.push_back(to);
  }
  if (stitched_) {  // an inside edge is the side of two triangles
    const auto gone = sign < 0 ? stitchedEdge(k.a, k.b) : stitchedEdge(k.c, k.d);
    const auto made = sign < 0 ? stitchedEdge(k.c, k.d) : stitchedEdge(k.a, k.b);
    if ((stitchedEdges_[gone] -= 2) <= 0) stitchedEdges_.erase(gone);
    stitchedEdges_[made] += 2;
  }
}

int flipEdges(Mesh& mesh, const FlipRule& rule, const std::vector<int>* stitched,
              const std::vector<bool>* region) {
  EdgeFlips flips(mesh, stitched);
  std::vector<std::pair<int, int>> work;  // edges to check, each direction once
  for (const Triangle& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      if (a < b && (!region || (*region)[a] || (*region)[b])) work.emplace_back(a, b);
    }
  int made = 0;
  // Flipping on a surface need not terminate as in the plane: bound the work.
  for (size_t budget = 20 * mesh.triangles.size() + 100; !work.empty() && budget > 0; --budget) {
    const auto [a, b] = work.back();
    work.pop_back();
    const std::optional<EdgeFlips::Candidate> k = flips.candidate(a, b);
    if (!k || !rule(k->quad) || flips.folds(*k)) continue;
    flips.flip(*k);
    for (auto [u, v] : {std::pair{a, k->c}, std::pair{a, k->d}, std::pair{b, k->c}, std::pair{b, k->d}})
      if (!region || (*region)[u] || (*region)[v]) work.emplace_back(std::min(u, v), std::max(u, v));
    ++made;
  }
  return made;
}

int changeOf(const EdgeFlips::Candidate& k, int v) {
  return (v == k.c || v == k.d) - (v == k.a || v == k.b);
}

constexpr int kMaxMoveFlips = 4;  // (see relaxedValenceMoves())
// How many of the sequences a first flip starts are tried, best first: the best may be refused
// (its relaxation lowers the angles, or its chords leave the surface) where the next would do.
// On the 36 disks of issue 5's sweep: all bars met on 30 with two (28 with one, 29 with three,
// 28 with all), mean irregularity 11.47 -> 11.17% (11.14% with three), the mean smallest angle
// 33.06 -> 33.34 degrees; at 0.75 of their sizes 23 met with one and two, 22 with three;
// 0-7% more time for the whole run at 1000 vertices.
constexpr size_t kMovesPerFirstFlip = 2;

namespace {

// The gainful continuations of one first flip, searched depth first with the flips made.
class MoveSearch {
 public:
  MoveSearch(EdgeFlips& flips, double degrees) : flips_(flips), degrees_(degrees) {}

  // The sequences starting with `first` (made by the caller) that leave fewer vertices
  // irregular (or as many, nearer regular), each of its flips keeping its angles; best first.
  std::vector<ValenceMove> movesAfter(const EdgeFlips::Candidate& first) {
    made_ = {first};
    change_.clear();
    count(first, +1);
    found_.clear();
    extend(kMaxMoveFlips - 1);
    std::stable_sort(found_.begin(), found_.end(), [](const ValenceMove& p, const ValenceMove& q) {
      return p.gain > q.gain || (p.gain == q.gain && p.edges.size() < q.edges.size());
    });
    return found_;
  }

  // The flips looked at since the search was made.
  size_t examined() const { return examined_; }

 private:
  void count(const EdgeFlips::Candidate& k, int sign) {
    for (int v : {k.a, k.b, k.c, k.d}) {
      auto it = std::find_if(change_.begin(), change_.end(), [v](const auto& p) { return p.first == v; });
      if (it == change_.end()) it = change_.insert(change_.end(), {v, 0});
      it->second += sign * changeOf(k, v);
    }
  }
  // What the flips made, and `next` after them, gain over the mesh before the first. (The
  // valences now are those before the first plus change_.)
  ValenceGain gainWith(const EdgeFlips::Candidate& next) const {
    ValenceGain gain;
    for (const auto& [v, now] : change_) gain.add(flips_, v, -now, changeOf(next, v));
    for (int v : {next.a, next.b, next.c, next.d})
      if (std::none_of(change_.begin(), change_.end(), [v](const auto& p) { return p.first == v; }))
        gain.add(flips_, v, 0, changeOf(next, v));
    return gain;
  }
  // Next flips next to the last one: a gainful one ends a sequence; one that loses no
  // irregular vertex goes on while flips are left. The angles are checked last (the costly
  // part, and seldom needed).
  void extend(int flipsLeft) {
    const EdgeFlips::Candidate last = made_.back();  // a copy: made_ grows below
    for (const auto& [x, y] : flips_.edgesAround({last.a, last.b, last.c, last.d})) {
      if (std::minmax(x, y) == std::minmax(last.c, last.d)) continue;  // the way back
      ++examined_;
      const std::optional<EdgeFlips::Candidate> next = flips_.candidate(x, y);
      if (!next) continue;
      const ValenceGain withNext = gainWith(*next);
      const std::pair<int, int>& gain = withNext.value();
      if (withNext.improves()) {
        if (flips_.keeps(*next, degrees_)) {
          ValenceMove& move = found_.emplace_back(ValenceMove{{}, gain});
          for (const EdgeFlips::Candidate& k : made_) move.edges.emplace_back(k.a, k.b);
          move.edges.emplace_back(x, y);
        }
      } else if (flipsLeft > 1 && gain.first >= 0 && flips_.keeps(*next, degrees_)) {
        flips_.flip(*next);
        made_.push_back(*next);
        count(*next, +1);
        extend(flipsLeft - 1);
        count(*next, -1);
        made_.pop_back();
        flips_.undo(*next);
      }
    }
  }

  EdgeFlips& flips_;
  const double degrees_;
  std::vector<EdgeFlips::Candidate> made_;
  std::vector<std::pair<int, int>> change_;  // valence change of each vertex the flips touch
  std::vector<ValenceMove> found_;
  size_t examined_ = 0;
};

}  // namespace

std::vector<ValenceMove> valenceMoves(EdgeFlips& flips, const Mesh& mesh, double degrees,
                                      const std::vector<bool>* near, size_t searchPerVertex) {
  std::vector<std::pair<int, int>> edges;
  for (const Triangle& t : mesh.triangles)
    for (int k = 0; k < 3; ++k)
      if (t[k] < t[(k + 1) % 3] && (!near || (*near)[t[k]] || (*near)[t[(k + 1) % 3]]))
        edges.emplace_back(t[k], t[(k + 1) % 3]);
  std::vector<ValenceMove> moves;
  MoveSearch search(flips, degrees);
  const size_t budget = searchPerVertex * mesh.vertexCount();
  for (const auto& [a, b] : edges) {
    const std::optional<EdgeFlips::Candidate> first = flips.candidate(a, b);
    if (!first) continue;
    ValenceGain alone;
    for (int v : {first->a, first->b, first->c, first->d}) alone.add(flips, v, 0, changeOf(*first, v));
    if (alone.improves()) {
      if (flips.keeps(*first, degrees)) moves.push_back({{{a, b}}, alone.value()});
      continue;
    }
    // A sequence starts where the first flip moves a 5-7 pair of valences: its quad holds two
    // irregular vertices (starting from one as well made no difference on 36 disks, and
    // doubled the search).
    if (first->quad.irregularBefore < 2 || search.examined() >= budget || !flips.keeps(*first, degrees)) continue;
    flips.flip(*first);
    std::vector<ValenceMove> after = search.movesAfter(*first);
    after.resize(std::min<size_t>(after.size(), kMovesPerFirstFlip));
    moves.insert(moves.end(), after.begin(), after.end());
    flips.undo(*first);
  }
  std::stable_sort(moves.begin(), moves.end(),
                   [](const ValenceMove& p, const ValenceMove& q) { return p.gain > q.gain; });
  return moves;
}

int flipToDelaunay(Mesh& mesh) { return flipEdges(mesh, notDelaunay); }

int flipToRegularity(Mesh& mesh, double smallestAngle) {
  // Nothing relaxes after these flips: what they leave is what issue 5 counts, irregular
  // vertices (a flip that takes a valence 8 to 7 and a 6 to 7 lowers the squared deviation but
  // makes one more of them) and the smallest angle.
  return flipEdges(mesh, [smallestAngle](const Quad& q) {
    return raisesRegularityAbove(q, smallestAngle) && q.irregularAfter <= q.irregularBefore;
  });
}

}  // namespace lloydscope
