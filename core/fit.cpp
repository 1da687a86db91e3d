#include "fit.h"

#include "metrics.h"
#include "ring_moves.h"
#include "projection.h"
#include "topology.h"

#include <Eigen/Sparse>

#include <algorithm>
#include <array>
#include <map>
#include <set>

namespace lloydscope {

namespace {

std::vector<Vec3> vertexNormals(const Mesh& mesh) {
  std::vector<Vec3> normals(mesh.points.size(), Vec3::Zero());
  for (const Triangle& t : mesh.triangles)
    for (int v : t) normals[v] += faceNormal(mesh, t);
  for (Vec3& n : normals) n = n.norm() > 0 ? Vec3(n.normalized()) : Vec3::Zero();
  return normals;
}

// A point where the mesh is sampled: the mean of some of its vertices (one, an edge's two or a
// triangle's three), weighted by the part of the surface it stands for.
struct Sample {
  std::vector<int> corners;
  double weight = 0;
};

// One sample per vertex, edge and triangle, weighted as the rule for triangles that is exact for
// cubics weighs corners, edge midpoints and centres (1/20, 2/15 and 9/20 of the area): the
// distance to a curved surface grows from the corners inwards, and the centre weighs most.
std::vector<Sample> samplesOf(const Mesh& mesh) {
  std::vector<Sample> samples(mesh.points.size());
  for (size_t v = 0; v < samples.size(); ++v) samples[v].corners = {static_cast<int>(v)};
  std::map<std::pair<int, int>, size_t> edgeSample;
  for (const Triangle& t : mesh.triangles) {
    const double area = faceNormal(mesh, t).norm() / 2;
    for (int k = 0; k < 3; ++k) {
      samples[t[k]].weight += area / 20;
      const auto edge = std::minmax(t[k], t[(k + 1) % 3]);
      const auto [at, added] = edgeSample.emplace(edge, samples.size());
      if (added) samples.push_back({{edge.first, edge.second}, 0});
      samples[at->second].weight += 2 * area / 15;
    }
    samples.push_back({{t[0], t[1], t[2]}, 9 * area / 20});
  }
  return samples;
}

// The moves t_v of the vertices along their directions that minimize the weighted squared
// distances of the samples to their targets, measured along each sample's own direction (the
// targets held where they are: one Gauss-Newton step; a sample moves by the mean of its
// corners' moves). Fixed vertices do not move.
Eigen::VectorXd leastSquaresMoves(int vertexCount, const std::vector<Sample>& samples, const std::vector<Vec3>& at,
                                  const std::vector<Vec3>& along, const std::vector<Vec3>& targets,
                                  const std::vector<Vec3>& directions, const std::vector<bool>& fixed) {
  std::vector<Eigen::Triplet<double>> entries;
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(vertexCount);
  double diagonal = 0;  // the sum of the squared shares: the scale of the system's diagonal
  for (size_t i = 0; i < samples.size(); ++i) {
    const Sample& s = samples[i];
    const double d = (targets[i] - at[i]).dot(along[i]);
    // The sample moves by sum over its corners of share * (d_v . n) * t_v along n.
    for (int u : s.corners) {
      const double a = directions[u].dot(along[i]) / s.corners.size();
      diagonal += s.weight * a * a;
      if (fixed[u]) continue;
      rhs[u] += s.weight * a * d;
      for (int v : s.corners)
        if (!fixed[v]) entries.emplace_back(u, v, s.weight * a * directions[v].dot(along[i]) / s.corners.size());
    }
  }
  // Fixed vertices' rows and columns are the identity, their moves zero. A small pull towards
  // no move keeps the system definite where samples say little.
  const double damping = 1e-3 * diagonal / std::max(1, vertexCount);
  for (int v = 0; v < vertexCount; ++v) entries.emplace_back(v, v, fixed[v] ? 1.0 : damping);
  Eigen::SparseMatrix<double> system(vertexCount, vertexCount);
  system.setFromTriplets(entries.begin(), entries.end());
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(system);
  if (solver.info() != Eigen::Success) return Eigen::VectorXd::Zero(vertexCount);
  Eigen::VectorXd moves = solver.solve(rhs);
  if (!moves.allFinite()) moves.setZero();
  return moves;
}

// Each vertex's move along its normal that brings the samples nearest to their closest points
// on the input, measured along each sample's normal.
Eigen::VectorXd normalMoves(const Mesh& mesh, const std::vector<Vec3>& normals, const std::vector<Sample>& samples,
                            const std::vector<bool>& fixed, const SurfaceProjection& projection, int threads) {
  std::vector<Vec3> at(samples.size()), along(samples.size());
  for (size_t i = 0; i < samples.size(); ++i) {
    at[i] = along[i] = Vec3::Zero();
    for (int v : samples[i].corners) {
      at[i] += mesh.points[v] / static_cast<double>(samples[i].corners.size());
      along[i] += normals[v];
    }
    if (along[i].norm() > 0) along[i].normalize();
  }
  return leastSquaresMoves(mesh.vertexCount(), samples, at, along, projection.closestPoints(at, threads), normals,
                           fixed);
}

// One edge of the border, the way its triangle goes round it, and the triangle's third corner.
struct BorderEdge {
  int from, to, inside;
};

// An edge is on the border where no other triangle around its first end has its second.
std::vector<BorderEdge> borderEdgesOf(const Mesh& mesh) {
  const Rings rings(mesh);
  std::vector<BorderEdge> edges;
  for (int f = 0; f < mesh.faceCount(); ++f) {
    const Triangle& t = mesh.triangles[f];
    for (int k = 0; k < 3; ++k) {
      const int a = t[k], b = t[(k + 1) % 3];
      bool shared = false;
      for (int i = rings.offset[a]; i < rings.offset[a + 1] && !shared; ++i) {
        const Triangle& u = mesh.triangles[rings.faces[i]];
        shared = rings.faces[i] != f && (u[0] == b || u[1] == b || u[2] == b);
      }
      if (!shared) edges.push_back({a, b, t[(k + 2) % 3]});
    }
  }
  return edges;
}

// Per border vertex, the direction across the border away from the surface, in the plane of
// its border triangles (zero inside): the mean of its two border edges' own.
std::vector<Vec3> outwardDirections(const Mesh& mesh, const std::vector<BorderEdge>& edges) {
  std::vector<Vec3> outward(mesh.points.size(), Vec3::Zero());
  for (const BorderEdge& e : edges) {
    const Vec3 along = (mesh.points[e.to] - mesh.points[e.from]).normalized();
    Vec3 away = 0.5 * (mesh.points[e.from] + mesh.points[e.to]) - mesh.points[e.inside];
    away -= away.dot(along) * along;
    if (away.norm() == 0) continue;
    outward[e.from] += away.normalized();
    outward[e.to] += away.normalized();
  }
  for (Vec3& o : outward)
    if (o.norm() > 0) o.normalize();
  return outward;
}

Vec3 closestOnSegment(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 ab = b - a;
  const double length2 = ab.squaredNorm();
  return a + (length2 > 0 ? std::clamp((p - a).dot(ab) / length2, 0.0, 1.0) : 0.0) * ab;
}

// The input's border as loops of points in order, segment k of a loop from its point k to the
// next. Searched by brute force: borders are short beside surfaces.
class InputBorder {
 public:
  explicit InputBorder(const Mesh& input) {
    for (const std::vector<int>& loop : analyzeTopology(input).boundaryLoops) {
      std::vector<Vec3>& points = loops_.emplace_back();
      for (int v : loop) points.push_back(input.points[v]);
    }
  }

  struct Place {
    int loop = -1, segment = 0;
  };
  // The segment nearest to p.
  Place nearest(const Vec3& p) const {
    Place best;
    double bestDistance = INFINITY;
    for (size_t l = 0; l < loops_.size(); ++l)
      for (size_t k = 0; k < loops_[l].size(); ++k) {
        const double d = (closestOnSegment(p, point(l, k), point(l, k + 1)) - p).squaredNorm();
        if (d < bestDistance) bestDistance = d, best = {static_cast<int>(l), static_cast<int>(k)};
      }
    return best;
  }
  // The point nearest to p of the arc from one place to the other, the shorter way round.
  Vec3 closestOnArc(const Vec3& p, Place from, Place to) const {
    const int n = static_cast<int>(loops_[from.loop].size());
    int forward = (to.segment - from.segment + n) % n;
    if (forward > n - forward) std::swap(from, to), forward = n - forward;
    Vec3 best = p;
    double bestDistance = INFINITY;
    for (int i = 0; i <= forward; ++i) {
      const int k = (from.segment + i) % n;
      const Vec3 q = closestOnSegment(p, point(from.loop, k), point(from.loop, k + 1));
      if ((q - p).squaredNorm() < bestDistance) bestDistance = (q - p).squaredNorm(), best = q;
    }
    return best;
  }
  bool empty() const { return loops_.empty(); }

 private:
  const Vec3& point(size_t loop, size_t k) const { return loops_[loop][k % loops_[loop].size()]; }
  std::vector<std::vector<Vec3>> loops_;
};

// Each sample's closest point on the input's border, searched only along the arc between the
// places nearest to the sample's corners (the shorter way round): elsewhere the border may
// pass nearer, across a narrow gap (between lips), but that is another part of it.
std::vector<Vec3> closestBorderPoints(const Mesh& mesh, const std::vector<Sample>& samples,
                                      const std::vector<Vec3>& at, const InputBorder& border) {
  std::map<int, InputBorder::Place> place;
  for (const Sample& s : samples)
    for (int v : s.corners)
      if (!place.count(v)) place[v] = border.nearest(mesh.points[v]);
  std::vector<Vec3> closest(samples.size());
  for (size_t i = 0; i < samples.size(); ++i) {
    const InputBorder::Place from = place[samples[i].corners.front()], to = place[samples[i].corners.back()];
    closest[i] = from.loop == to.loop ? border.closestOnArc(at[i], from, to) : at[i];
  }
  return closest;
}

// Each border vertex's move across the border that brings the border's samples (its vertices
// and edge midpoints, weighted as Simpson's rule weighs them along each edge) nearest to the
// input's border, measured across it: the border's chords cross the input's curved border
// instead of cutting inside it (or, where it curves in, outside).
Eigen::VectorXd borderMoves(const Mesh& mesh, const Mesh& input, const std::vector<BorderEdge>& edges,
                            const std::vector<Vec3>& outward, const std::vector<bool>& fixed) {
  std::vector<Sample> samples;
  std::map<int, size_t> vertexSample;
  for (const BorderEdge& e : edges) {
    const double length = (mesh.points[e.to] - mesh.points[e.from]).norm();
    samples.push_back({{e.from, e.to}, 2 * length / 3});
    for (int v : {e.from, e.to}) {
      const auto [at, added] = vertexSample.emplace(v, samples.size());
      if (added) samples.push_back({{v}, 0});
      samples[at->second].weight += length / 6;
    }
  }
  std::vector<Vec3> at(samples.size(), Vec3::Zero()), across(samples.size(), Vec3::Zero());
  for (size_t i = 0; i < samples.size(); ++i)
    for (int v : samples[i].corners) {
      at[i] += mesh.points[v] / static_cast<double>(samples[i].corners.size());
      across[i] += outward[v];
    }
  for (Vec3& a : across)
    if (a.norm() > 0) a.normalize();
  // (On a single arc, three quarters of the move would put the chord halfway, where the
  // farthest on either side is least; on the 93 clipped halves of docs/bench_log.md at 1000
  // vertices the whole move came nearer on 10 and farther on 2.)
  const InputBorder border(input);
  if (border.empty()) return Eigen::VectorXd::Zero(mesh.vertexCount());
  const std::vector<Vec3> targets = closestBorderPoints(mesh, samples, at, border);
  return leastSquaresMoves(mesh.vertexCount(), samples, at, across, targets, outward, fixed);
}

// Accepts each vertex's move along its direction, whole, else half or a quarter of it, where it
// turns none of its triangles over and leaves their smallest angle at `keepAngle` or more, or
// no smaller than it was (the others' moves were solved for with this one whole, so a part of
// it is a compromise, still closer than none).
void makeMoves(Mesh& mesh, const Eigen::VectorXd& moves, const std::vector<Vec3>& directions, double keepAngle) {
  const Rings rings(mesh);
  for (int v = 0; v < mesh.vertexCount(); ++v) {
    if (moves[v] == 0) continue;
    const double before = smallestAngleOfRing(mesh, rings, v, mesh.points[v]);
    for (double part = 1; part > 0.2; part /= 2) {
      const Vec3 to = mesh.points[v] + part * moves[v] * directions[v];
      if (turnsOver(mesh, rings, v, to)) continue;
      const double after = smallestAngleOfRing(mesh, rings, v, to);
      if (after >= keepAngle || after >= before) {
        mesh.points[v] = to;
        break;
      }
    }
  }
}

}  // namespace

FitResult& FitResult::operator+=(const FitResult& o) {
  if (moved + o.moved > 0) meanPercent = (meanPercent * moved + o.meanPercent * o.moved) / (moved + o.moved);
  moved += o.moved;
  borderMoved += o.borderMoved;
  maxPercent = std::max(maxPercent, o.maxPercent);
  return *this;
}

FitResult FitResult::scaled(double factor) const {
  FitResult r = *this;
  r.meanPercent *= factor;
  r.maxPercent *= factor;
  return r;
}

FitResult fitToSurface(Mesh& mesh, const SearchableSurface& input, const FitOptions& options) {
  const Mesh& surface = input.mesh;
  const int n = mesh.vertexCount();
  // A vertex on an input vertex (a tip snapped there, core/last_steps; a corner of the border)
  // stays on it.
  std::set<std::array<double, 3>> inputVertices;
  for (const Vec3& p : surface.points) inputVertices.insert({p.x(), p.y(), p.z()});
  std::vector<bool> onInputVertex(n, false);
  for (int v = 0; v < n; ++v) {
    const Vec3& p = mesh.points[v];
    onInputVertex[v] = inputVertices.count({p.x(), p.y(), p.z()}) > 0;
  }
  const std::vector<bool> border = vertexEdges(mesh).onBoundary;
  const std::vector<Vec3> start = mesh.points;
  std::vector<bool> fixed(n);
  // The border first, across itself, so that the inside's moves are solved for with it moved.
  if (options.border) {
    const std::vector<BorderEdge> edges = borderEdgesOf(mesh);
    const std::vector<Vec3> outward = outwardDirections(mesh, edges);
    for (int v = 0; v < n; ++v) fixed[v] = !border[v] || onInputVertex[v];
    makeMoves(mesh, borderMoves(mesh, surface, edges, outward, fixed), outward, options.keepAngle);
  }
  // Then the inside, along the normals.
  for (int v = 0; v < n; ++v) fixed[v] = border[v] || onInputVertex[v];
  const std::vector<Vec3> normals = vertexNormals(mesh);
  makeMoves(mesh, normalMoves(mesh, normals, samplesOf(mesh), fixed, input.projection, options.threads), normals,
            options.keepAngle);

  FitResult r;
  const double diagonal = boundingBoxDiagonal(surface);
  double sum = 0;
  for (int v = 0; v < n; ++v) {
    const double d = (mesh.points[v] - start[v]).norm();
    if (d <= 1e-9 * diagonal) continue;  // rounding (a flat strip's border: 1.4e-15 of 20), no move
    ++r.moved;
    r.borderMoved += border[v];
    sum += d;
    r.maxPercent = std::max(r.maxPercent, 100.0 * d / diagonal);
  }
  if (r.moved > 0) r.meanPercent = 100.0 * sum / r.moved / diagonal;
  return r;
}

}  // namespace lloydscope
