#include "sites.h"

#include "cut.h"
#include "metrics.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <tuple>

namespace lloydscope {

namespace {
// How many places the points are at: a seam sample's two copies, one place (as stitchSeams
// finds them).
int distinctPoints(const std::vector<Vec3>& points, double tolerance) {
  if (points.empty()) return 0;
  const std::vector<int> first = firstCopies(points, {}, tolerance);
  int distinct = 0;
  for (size_t i = 0; i < first.size(); ++i) distinct += first[i] == static_cast<int>(i);
  return distinct;
}

double uniform01(std::mt19937_64& rng) { return (rng() >> 11) * 0x1.0p-53; }

// A border vertex where the UV border turns by more than ~20 degrees (the corners of the
// square) must stay a sample, or resampling would cut the corner off the domain.
bool isCorner(const Vec2& prev, const Vec2& at, const Vec2& next) {
  const Vec2 a = (at - prev).normalized(), b = (next - at).normalized();
  return a.dot(b) < std::cos(20.0 * M_PI / 180.0);
}

// The sum of the corner angles at each vertex, degrees: 180 where a border runs straight on.
std::vector<double> angleSums(const Mesh& mesh) {
  std::vector<double> sum(mesh.vertexCount(), 0.0);
  for (const Triangle& t : mesh.triangles) {
    const auto angles = cornerAnglesDeg(mesh.points[t[0]], mesh.points[t[1]], mesh.points[t[2]]);
    for (int k = 0; k < 3; ++k) sum[t[k]] += angles[k];
  }
  return sum;
}

// A border vertex is a corner of the surface where its angles sum to more than kSurfaceTurn
// degrees from 180; a corner of the map where the border turns in the plane (isCorner); the
// map's corners come first, scored kMapCorner plus the surface's turn, then the points asked to
// be kept (SiteOptions::keptBorderPoints), then the surface's.
constexpr double kSurfaceTurn = 40.0, kMapCorner = 1000.0;

// A corner closer than kCornersApart spacings to a kept one would make a short border edge (a
// chamfer of a square corner is two corners of 135 degrees). The triangle on a border edge half
// a spacing long has an angle of 27-28 degrees at its inside corner (CGAL's bear and bunny
// clipped in half, at 500-2000 vertices).
constexpr double kCornersApart = 0.7;

// The border's point at 3D arc length `at` (`position`: each loop vertex's, the whole loop's last).
Vec3 borderPointAt(const Mesh& mesh, const std::vector<int>& loop, const std::vector<double>& position, double at) {
  const int n = static_cast<int>(loop.size());
  at -= position[n] * std::floor(at / position[n]);
  const int i = std::clamp(static_cast<int>(std::upper_bound(position.begin(), position.end(), at) - position.begin()) - 1, 0, n - 1);
  const double span = position[i + 1] - position[i];
  const double t = span > 0 ? std::clamp((at - position[i]) / span, 0.0, 1.0) : 0.0;
  return (1 - t) * mesh.points[loop[i]] + t * mesh.points[loop[(i + 1) % n]];
}

// A bump of the border narrower than the spacing (the tip of a clipped surface's border) falls
// between two samples, and the border edge between them cuts it off: that is the Hausdorff
// distance. A border vertex farther than kBumpStray spacings from the edge between the samples
// around it (the stretches sampled evenly, as below) becomes a corner too, the farthest first,
// and the stretches are sampled again, until none is. A corner of the map alone (`yields`: not
// of the surface) within kCornersApart spacings of it gives way to it (on CGAL's blobby clipped
// in half, one 0.007 from the bump's tip); any other corner there keeps it out.
constexpr double kBumpStray = 0.1;
void keepBumps(const Mesh& mesh, const std::vector<int>& loop, const std::vector<double>& position,
               double spacing, std::vector<bool> yields, std::vector<int>& corners) {
  const int n = static_cast<int>(loop.size());
  const double whole = position[n];
  auto apart = [&](int i, int j) {
    const double d = std::abs(position[i] - position[j]);
    return std::min(d, whole - d);
  };
  for (;;) {
    int bump = -1;
    double farthest = kBumpStray * spacing;
    for (size_t c = 0; c < corners.size(); ++c) {
      const int begin = corners[c], end = c + 1 < corners.size() ? corners[c + 1] : corners[0] + n;
      const double from = position[begin], to = end < n ? position[end] : whole + position[end - n];
      if (!(to > from)) continue;
      const int pieces = std::max(1, static_cast<int>(std::lround((to - from) / spacing)));
      for (int i = begin + 1; i < end; ++i) {
        const double here = i < n ? position[i] : whole + position[i - n];
        const int piece = std::min(pieces - 1, static_cast<int>((here - from) / (to - from) * pieces));
        const double stray = distanceToSegment(mesh.points[loop[i % n]],
                                               borderPointAt(mesh, loop, position, from + (to - from) * piece / pieces),
                                               borderPointAt(mesh, loop, position, from + (to - from) * (piece + 1) / pieces));
        if (stray <= farthest) continue;
        bool blocked = false;
        for (int k : corners) blocked = blocked || (!yields[k] && apart(i % n, k) < kCornersApart * spacing);
        if (!blocked) farthest = stray, bump = i % n;
      }
    }
    if (bump < 0) return;
    corners.erase(std::remove_if(corners.begin(), corners.end(),
                                 [&](int k) { return yields[k] && apart(bump, k) < kCornersApart * spacing; }),
                  corners.end());
    yields[bump] = false;  // it stays
    corners.insert(std::upper_bound(corners.begin(), corners.end(), bump), bump);
  }
}

// Beside a corner of the border sharper than kGradedCorner degrees, the samples on its two sides
// are spaced in a geometric progression from it, staggered between the sides, each gap about the
// wedge's width there: a strip of triangles across the wedge then has no angle under about 50
// degrees (20 degrees: ratio 1.43, 53; 30 degrees: 50; less under 11.5 degrees, where the ratio
// is held at 1.25: 36 at 5), where evenly spaced samples squeeze the triangles beside
// the corner's own (a 20-degree sector at 300 vertices: 22.9 degrees). Under 30 degrees only:
// a wider corner's strip is mended by the polish's border slides (polish.h), and graded it came
// out no better on the five clipped halves with such corners.
constexpr double kGradedCorner = 30.0;
// No less than 1.25 (a corner of 11.5 degrees): a sharper one would take over ten samples a
// side, and one squeezed to a point (a tiny input's first pass) hundreds.
double gradedRatio(double cornerDegrees) { return std::max(1.25, 1 + 2.5 * std::sin(cornerDegrees * M_PI / 360)); }

// The distances from such a corner of its side's graded samples, nearest first: down from
// where the gap reaches about a spacing to half a spacing; the side arriving at the corner
// (`arriving`) is staggered by the square root of the ratio.
std::vector<double> gradedFromCorner(double cornerDegrees, double spacing, bool arriving) {
  const double q = gradedRatio(cornerDegrees);
  std::vector<double> at;
  for (double x = spacing / (q - 1) * (arriving ? std::sqrt(q) : 1.0); x >= 0.5 * spacing; x /= q) at.push_back(x);
  std::reverse(at.begin(), at.end());
  return at;
}

}  // namespace

std::vector<double> borderSamplePositions(double length, double spacing, int pieces, double beginDegrees,
                                          double endDegrees) {
  std::vector<double> t;
  const auto graded = [&](double degrees, bool arriving) {
    if (degrees >= kGradedCorner) return std::vector<double>();
    std::vector<double> at = gradedFromCorner(degrees, spacing, arriving);
    at.erase(std::remove_if(at.begin(), at.end(), [&](double x) { return x > 0.5 * length; }), at.end());
    return at;
  };
  std::vector<double> fromBegin = graded(beginDegrees, false), fromEnd = graded(endDegrees, true);
  if (fromBegin.empty() && fromEnd.empty()) {
    for (int s = 0; s < pieces; ++s) t.push_back(length * s / pieces);
    return t;
  }
  // Two graded ends that meet mid-stretch (corners of different angles, a short stretch) could
  // leave their last samples a hair apart: the farther of the two goes until they are half a
  // spacing apart (13 and 20 degrees, 5.5 spacings apart: 0.005 spacings).
  while (!fromBegin.empty() && !fromEnd.empty() && length - fromEnd.back() - fromBegin.back() < 0.5 * spacing)
    (fromBegin.back() > fromEnd.back() ? fromBegin : fromEnd).pop_back();
  // The graded samples at both ends, evenly between them (as many times more as `pieces` is
  // more than the stretch's length in spacings).
  const double a = fromBegin.empty() ? 0.0 : fromBegin.back();
  const double b = length - (fromEnd.empty() ? 0.0 : fromEnd.back());
  const int byLength = std::max(1, static_cast<int>(std::lround(length / spacing)));
  const int middle = std::max(1, static_cast<int>(std::lround((b - a) / spacing))) * std::max(1, pieces / byLength);
  t.push_back(0.0);
  t.insert(t.end(), fromBegin.begin(), fromBegin.end());
  for (int s = 1; s < middle; ++s) t.push_back(a + (b - a) * s / middle);
  for (auto x = fromEnd.rbegin(); x != fromEnd.rend(); ++x) t.push_back(length - *x);
  return t;
}

namespace {

bool flagged(const std::vector<bool>& flags, int v) { return !flags.empty() && flags[v]; }

// The loop positions the border's samples must keep, ascending: the seams' nodes, the corners
// of the map, the points asked for (SiteOptions::keptBorderPoints) and the corners of the
// surface (`angles`: each vertex's angle sum), in that order where two are closer than
// kCornersApart spacings (only the first stays); then, on a surface without seams, the bumps
// the samples between would cut off (keepBumps). At least one.
std::vector<int> borderCorners(const Mesh& mesh, const Parameterization& param, const std::vector<double>& angles,
                               const std::vector<double>& position, double spacing, const SiteOptions& options) {
  const std::vector<int>& loop = param.boundaryLoop;
  const int n = static_cast<int>(loop.size());
  // Candidates, the domain's own corners before the surface's, sharper before blunter.
  std::vector<std::pair<double, int>> candidates;
  constexpr double kSeamNode = 3000.0, kKeptPoint = 500.0;
  const double samePoint = 1e-6 * boundingBoxDiagonal(mesh);
  const auto kept = [&](int v) {
    return std::any_of(options.keptBorderPoints.begin(), options.keptBorderPoints.end(),
                       [&](const Vec3& p) { return (mesh.points[v] - p).norm() <= samePoint; });
  };
  for (int i = 0; i < n; ++i) {
    const double turn = std::abs(angles[loop[i]] - 180.0);
    if (flagged(options.seamNode, loop[i]))
      candidates.emplace_back(kSeamNode, i);
    else if (flagged(options.onSeam, loop[i]))
      continue;
    else if (isCorner(param.uv[loop[(i + n - 1) % n]], param.uv[loop[i]], param.uv[loop[(i + 1) % n]]))
      candidates.emplace_back(kMapCorner + turn, i);
    else if (kept(loop[i]))
      candidates.emplace_back(kKeptPoint, i);
    else if (turn > kSurfaceTurn)
      candidates.emplace_back(turn, i);
  }
  std::sort(candidates.rbegin(), candidates.rend());
  std::vector<int> corners;
  for (const auto& [score, i] : candidates) {
    bool near = false;
    for (int c : corners) {
      const double apart = std::abs(position[i] - position[c]);
      near = near || std::min(apart, position[n] - apart) < kCornersApart * spacing;
    }
    if (score == kSeamNode) near = false;  // both copies of a seam need it
    if (!near) corners.push_back(i);
  }
  std::sort(corners.begin(), corners.end());
  if (corners.empty()) corners.push_back(0);
  if (options.onSeam.empty()) {  // (a seam's two copies must be sampled alike)
    std::vector<bool> yields(n, false);  // corners of the map only, not of the surface
    for (const auto& [score, i] : candidates) yields[i] = score >= kMapCorner && score <= kMapCorner + kSurfaceTurn;
    keepBumps(mesh, loop, position, spacing, yields, corners);
  }
  return corners;
}

// A stretch of the border loop from corner `begin` to corner `end` (loop positions; `end` past
// the loop's length where the stretch wraps), with the 3D length along it at each of its
// vertices.
struct Stretch {
  int begin = 0, end = 0;
  std::vector<double> length;
  int edges() const { return end - begin; }
};

// `count` samples of a stretch too short for the spacing at its own vertices, those nearest
// by arc length to even steps along it: alike on both copies of a seam.
void sampleAtVertices(const Mesh& mesh, const Parameterization& param, const Stretch& stretch, int count,
                      std::vector<Vec2>& samples, std::vector<Vec3>& points) {
  const std::vector<int>& loop = param.boundaryLoop;
  const int n = static_cast<int>(loop.size());
  const std::vector<double>& length = stretch.length;
  const auto pointAt = [&](int i) -> const Vec3& { return mesh.points[loop[(stretch.begin + i) % n]]; };
  for (int s = 0, last = 0; s < count; ++s) {
    const double target = length.back() * s / count;
    // Two vertices as near (the middle of 5 equal edges) go to the smaller point: the two
    // copies run the stretch in opposite directions, and each took the one nearer its start
    // (an open band's seam did not stitch).
    const auto nearer = [&](int i, int j) {
      const double di = std::abs(length[i] - target), dj = std::abs(length[j] - target);
      if (std::abs(di - dj) > 1e-9 * length.back()) return di < dj;
      const Vec3 &a = pointAt(i), &b = pointAt(j);
      return std::make_tuple(a.x(), a.y(), a.z()) < std::make_tuple(b.x(), b.y(), b.z());
    };
    int nearest = last + (s > 0);
    for (int i = nearest; i <= stretch.edges() - (count - s); ++i)
      if (nearer(i, nearest)) nearest = i;
    samples.push_back(param.uv[loop[(stretch.begin + nearest) % n]]);
    points.push_back(pointAt(nearest));
    last = nearest;
  }
}

// Samples along the border at 3D arc-length spacing close to `spacing`, corners kept
// (borderCorners). Their points on the surface go to `points`.
std::vector<Vec2> resampleBorder(const Mesh& mesh, const Parameterization& param,
                                 double spacing, const SiteOptions& options, std::vector<Vec3>& points) {
  const std::vector<int>& loop = param.boundaryLoop;
  const int n = static_cast<int>(loop.size());
  const std::vector<double> angles = angleSums(mesh);
  // The spacing in the map, on average over it.
  const double uvSpacing = spacing * std::sqrt(mapArea(mesh, param.uv) / surfaceArea(mesh));
  std::vector<double> position(n + 1, 0.0);  // 3D arc length from loop[0]
  for (int i = 0; i < n; ++i)
    position[i + 1] = position[i] + (mesh.points[loop[(i + 1) % n]] - mesh.points[loop[i]]).norm();
  const std::vector<int> corners = borderCorners(mesh, param, angles, position, spacing, options);

  std::vector<Vec2> samples;
  for (size_t c = 0; c < corners.size(); ++c) {
    Stretch stretch;
    stretch.begin = corners[c];
    stretch.end = c + 1 < corners.size() ? corners[c + 1] : corners[0] + n;
    const int begin = stretch.begin, end = stretch.end, edges = stretch.edges();
    std::vector<double>& length = stretch.length;
    length = {0.0};
    for (int i = begin; i < end; ++i)
      length.push_back(length.back() +
                       (mesh.points[loop[(i + 1) % n]] - mesh.points[loop[i % n]]).norm());
    // A stretch that starts at a seam node gets at least 2 pieces, 3 if it comes back to the
    // same point (as many as it has edges at most): two seams between the same nodes would
    // otherwise stitch into one edge shared by 4 triangles, and a seam that loops back to its
    // node, or a small hole of the input (a border loop the cut joined to the others at one
    // node), would close. Those extra samples are the stretch's own vertices: two on one
    // straight edge would make a flat ear.
    const bool fromNode = flagged(options.seamNode, loop[begin]) || flagged(options.seamNode, loop[end % n]);
    const bool closed = mesh.points[loop[begin]] == mesh.points[loop[end % n]];
    const int fewest = std::min(edges, !fromNode ? 1 : closed ? 3 : 2);
    const int byLength = static_cast<int>(std::lround(length.back() / spacing));
    if (fewest > byLength) {
      sampleAtVertices(mesh, param, stretch, fewest, samples, points);
      continue;
    }
    // Evenly by 3D arc length; more pieces where the border of the map strays from the chords
    // between them by over half a spacing (in the map): sites between a chord and the border
    // would lie outside the samples' polygon, in no triangle (a sphere with a small hole, on a
    // square at 2000 sites: its 3 samples made half the square a triangle, and 875 vertices).
    // Graded beside a sharp corner of the surface at either end, but not on a cut or charted
    // surface (sampled with its seams: their two copies run a stretch in opposite directions and
    // must be sampled alike).
    const auto cornerAt = [&](int corner) { return options.onSeam.empty() ? angles[loop[corner % n]] : 180.0; };
    const auto targets = [&](int pieces) {
      return borderSamplePositions(length.back(), spacing, pieces, cornerAt(begin), cornerAt(end));
    };
    const auto place = [&](const std::vector<double>& targets, std::vector<Vec2>& uvs, std::vector<Vec3>& at) {
      int segment = 0;
      for (const double target : targets) {
        while (segment + 1 < static_cast<int>(length.size()) - 1 && length[segment + 1] <= target)
          ++segment;
        const double span = length[segment + 1] - length[segment];
        const double t = span > 0 ? (target - length[segment]) / span : 0.0;
        const int a = loop[(begin + segment) % n], b = loop[(begin + segment + 1) % n];
        uvs.push_back((1 - t) * param.uv[a] + t * param.uv[b]);
        at.push_back((1 - t) * mesh.points[a] + t * mesh.points[b]);
      }
    };
    const auto strays = [&](const std::vector<double>& targets, const std::vector<Vec2>& uvs) {
      const int pieces = static_cast<int>(uvs.size());
      for (int i = 1; i < edges; ++i) {
        const int s = static_cast<int>(std::upper_bound(targets.begin(), targets.end(), length[i]) - targets.begin()) - 1;
        const Vec2 &a = uvs[s], &b = s + 1 < pieces ? uvs[s + 1] : param.uv[loop[end % n]];
        if (distanceToSegment(param.uv[loop[(begin + i) % n]], a, b) > 0.5 * uvSpacing) return true;
      }
      return false;
    };
    std::vector<Vec2> uvs;
    std::vector<Vec3> at;
    for (int pieces = std::max(1, byLength);; pieces *= 2) {
      uvs.clear();
      at.clear();
      const std::vector<double> where = targets(pieces);
      place(where, uvs, at);
      if (!options.onSeam.empty() || pieces > edges || !strays(where, uvs)) break;  // (seam copies: alike)
    }
    samples.insert(samples.end(), uvs.begin(), uvs.end());
    points.insert(points.end(), at.begin(), at.end());
  }
  return samples;
}

// `count` points drawn where a centroidal tessellation of the density puts them: in 2D its
// sites end up with a point density proportional to sqrt(rho) (Gersho: rho^(d/(d+2))), so a
// triangle is drawn with probability proportional to its area times sqrt(rho), then a uniform
// point inside it. Drawing by rho itself put 1/scale times too many sites where the map
// shrinks the surface by `scale`: on a cut knot, all of them at one end of the strip.
std::vector<Vec2> sampleDensity(const Domain& domain, int count, std::uint64_t seed) {
  const auto& uv = domain.uv();
  const auto& rho = domain.density();
  std::vector<double> cumulative;
  double total = 0;
  for (size_t i = 0; i < domain.triangles().size(); ++i) {
    const Triangle& t = domain.triangles()[i];
    total += std::abs(triangleArea(uv[t[0]], uv[t[1]], uv[t[2]])) *
             (std::sqrt(rho[i][0]) + std::sqrt(rho[i][1]) + std::sqrt(rho[i][2])) / 3.0;
    cumulative.push_back(total);
  }
  std::mt19937_64 rng(seed);
  std::vector<Vec2> points;
  for (int i = 0; i < count; ++i) {
    const Triangle& t = domain.triangles()[pickByShare(cumulative, uniform01(rng) * total)];
    const double s = uniform01(rng);
    points.push_back(pointInTriangle(uv[t[0]], uv[t[1]], uv[t[2]], s, uniform01(rng)));
  }
  return points;
}

}  // namespace

namespace {
// The spacing at which a border `borderLength` long, sampled at it, and the inside, at it too,
// take `count` vertices together: count = area / (sqrt(3) / 2 h^2) + borderLength / h. The
// inside's spacing alone (equilateralEdgeLength) left a border far longer than the surface is
// wide (a star of long thin spikes, a narrow ribbon) more samples than the count: none inside,
// the inside filled by fans of slivers (a star of 30 spikes at 1000 vertices: 1050, all on the
// border, its smallest angle 6 degrees).
double spacingWithTheBorder(double area, double borderLength, int count) {
  // count h^2 - borderLength h - a = 0, solved without the cancellation of the other form.
  const double a = 2 * area / std::sqrt(3.0);
  return (borderLength + std::sqrt(borderLength * borderLength + 4 * a * count)) / (2.0 * count);
}

// A border that takes over half the vertices asked at `spacing` (the inside's) sampled again
// at spacingWithTheBorder(), its length as sampled (its corners' graded samples too): the star
// of 30 spikes at 1000 vertices then has 75% of them on its border, and a second time round
// 72%, its triangles no better. But no more than twice as far apart as the surface is wide on
// average: a strip 1000 long and 1 wide, 300 vertices asked, its border sampled 2 apart (1002
// vertices, all on it, the smallest angle 41.9 degrees), was sampled 3.9 apart, 11.3 degrees.
// Where that is closer than before (the strip at 100), the border stays as it was.
void respaceALongBorder(const Mesh& mesh, const Parameterization& param, int count, const SiteOptions& options,
                        double& spacing, InitialSites& sites) {
  const double area = surfaceArea(mesh), border = spacing * sites.fixed.size();
  // A strip's width, of a surface as long as half its border (its length, not as sampled).
  const double width = 2 * area / loopLength(mesh, param.boundaryLoop);
  const double wider = std::min(spacingWithTheBorder(area, border, count), 2 * width);
  if (!(wider > spacing)) return;
  std::vector<Vec3> points;
  std::vector<Vec2> fixed = resampleBorder(mesh, param, wider, options, points);
  if (fixed.size() < 3) return;
  spacing = wider;
  sites.fixed = std::move(fixed);
  sites.fixedPoints = std::move(points);
}
}  // namespace

InitialSites initialSites(const Mesh& mesh, const Parameterization& param, const Domain& domain,
                          const SiteOptions& options, const std::string& name) {
  InitialSites sites;
  if (options.fromInputVertices) {
    for (int v : param.boundaryLoop) {
      sites.fixed.push_back(param.uv[v]);
      sites.fixedPoints.push_back(mesh.points[v]);
    }
    for (int v = 0; v < mesh.vertexCount(); ++v)
      if (!param.onBoundary[v]) {
        sites.movable.push_back(param.uv[v]);
        sites.movableVertex.push_back(v);
      }
    return sites;
  }
  const int count = options.count > 0 ? options.count : mesh.vertexCount();
  double spacing = options.spacing > 0 ? options.spacing : equilateralEdgeLength(surfaceArea(mesh), count);
  sites.fixed = resampleBorder(mesh, param, spacing, options, sites.fixedPoints);
  // Fewer than three samples: a border far shorter than the surface is wide (a small hole in a
  // closed surface, a spike or a fold inside a small border), nothing to triangulate.
  if (sites.fixed.size() < 3) {
    // The spacing that samples the border 3 times, and the count that gives it.
    const double border = loopLength(mesh, param.boundaryLoop), needed = border / 3;
    const double enough = std::ceil(count * (spacing / needed) * (spacing / needed));
    throw Error(name + ": at the spacing of " + std::to_string(count) + " vertices its border takes " +
                std::to_string(sites.fixed.size()) + (sites.fixed.size() == 1 ? " sample" : " samples") +
                " (3 at least), far too short for the surface inside it (a small hole, a spike, a fold); " +
                (enough <= kMostRemeshedVertices
                     ? "about " + std::to_string(static_cast<long long>(enough)) + " vertices would take 3"
                     : "it would take more than the " + std::to_string(kMostRemeshedVertices) + " vertices a run may be asked for"));
  }
  const long long most = static_cast<long long>(kMostBorderPerVertex) * std::max(count, kSmallestRemeshedShare);
  if (static_cast<long long>(sites.fixed.size()) > most)
    throw Error(name + ": " + std::to_string(count) + " vertices are too few for it: at their spacing its border" +
                (options.onSeam.empty() ? "" : ", with the slits that cut it open,") + " takes " +
                std::to_string(sites.fixed.size()) + " (over " + std::to_string(kMostBorderPerVertex) +
                " times as many); ask for more (--sites), or look for a spike or a sliver far longer than wide");
  if (options.spacing <= 0 && options.onSeam.empty() && 2 * sites.fixed.size() > static_cast<size_t>(count))
    respaceALongBorder(mesh, param, count, options, spacing, sites);
  const bool stitched = options.stitchedCount > 0;  // the border's seam copies become one vertex each
  const int border = stitched ? distinctPoints(sites.fixedPoints, seamTolerance(mesh))
                              : static_cast<int>(sites.fixed.size());
  const int asked = stitched ? options.stitchedCount : count;
  int inside = std::max(0, asked - border);
  // Where the map squashes the border (a tall cone's LSCM map is a lens), its samples are
  // doubled until they follow it in the plane, and they took every site: none was left inside,
  // and the cone came out a flat disk. The inside keeps at least what a border sampled by its
  // length alone would leave it.
  const long long byLength = std::max(3LL, std::llround(loopLength(mesh, param.boundaryLoop) / spacing));
  if (static_cast<long long>(sites.fixed.size()) > 2 * byLength)
    inside = std::max<long long>(inside, asked - byLength);
  sites.movable = sampleDensity(domain, inside, options.seed);
  sites.movableVertex.assign(sites.movable.size(), -1);
  return sites;
}

}  // namespace lloydscope
