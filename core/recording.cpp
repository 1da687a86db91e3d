#include "recording.h"

#include "files.h"
#include "mesh_io.h"
#include "pipeline.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>

namespace lloydscope {

namespace {

constexpr char kMagic[8] = {'L', 'L', 'O', 'Y', 'D', 'R', 'E', 'C'};
constexpr size_t kHeaderSize = sizeof(kMagic) + 4 + 8;  // magic, version, payload size
constexpr size_t kChecksumSize = 8;

std::uint64_t fnv1a(const char* data, size_t size) {
  std::uint64_t hash = 1469598103934665603ull;
  for (size_t i = 0; i < size; ++i) {
    hash ^= static_cast<unsigned char>(data[i]);
    hash *= 1099511628211ull;
  }
  return hash;
}

// Little-endian host assumed (x86-64, arm64); the format stores native doubles and integers.
// Appends values' bytes; or, counting, only how many they would be (a first pass that sizes
// the buffer: grown by doubling, it held up to twice the payload while the last doubling
// copied it).
class Writer {
 public:
  explicit Writer(bool counting = false) : counting_(counting) {}
  template <class T>
  void put(const T& value) {
    putBytes(&value, sizeof(T));
  }
  void putBytes(const void* data, size_t size) {
    if (counting_) counted_ += size;
    else bytes_.append(static_cast<const char*>(data), size);
  }
  void putString(const std::string& s) {
    put<std::uint32_t>(static_cast<std::uint32_t>(s.size()));
    putBytes(s.data(), s.size());
  }
  void putPoints(const std::vector<Vec2>& points) {
    put<std::uint32_t>(static_cast<std::uint32_t>(points.size()));
    for (const Vec2& p : points) put(p.x()), put(p.y());
  }
  std::string& bytes() { return bytes_; }
  size_t counted() const { return counted_; }

 private:
  bool counting_;
  size_t counted_ = 0;
  std::string bytes_;
};

// Every read is bounds-checked: a damaged payload is an error, never a crash.
class Reader {
 public:
  Reader(const std::string& bytes, size_t begin, size_t end, const std::string& path)
      : bytes_(bytes), at_(begin), end_(end), path_(path) {}
  template <class T>
  T get() {
    need(sizeof(T));
    T value;
    std::memcpy(&value, bytes_.data() + at_, sizeof(T));
    at_ += sizeof(T);
    return value;
  }
  std::uint32_t getCount(size_t bytesPerItem) {
    const auto n = get<std::uint32_t>();
    need(static_cast<size_t>(n) * bytesPerItem);
    return n;
  }
  std::string getString() {
    const auto n = getCount(1);
    std::string s = bytes_.substr(at_, n);
    at_ += n;
    return s;
  }
  std::vector<Vec2> getPoints() {
    std::vector<Vec2> points(getCount(16));
    for (Vec2& p : points) {
      const double x = get<double>(), y = get<double>();
      p = Vec2(x, y);
    }
    return points;
  }
  bool done() const { return at_ == end_; }

 private:
  void need(size_t n) {
    if (n > end_ - at_) throw Error(path_ + ": damaged recording (a count runs past the data)");
  }
  const std::string& bytes_;
  size_t at_, end_;
  const std::string& path_;
};

void encodeInto(Writer& w, const Recording& r) {
  w.putString(r.settings);
  w.put<std::uint8_t>(r.method == RemeshMethod::Relocate ? 0 : 1);
  w.put(r.distanceThreshold);
  w.put(r.percentThreshold);
  w.put<std::uint32_t>(static_cast<std::uint32_t>(r.input.points.size()));
  for (const Vec3& p : r.input.points) w.put(p.x()), w.put(p.y()), w.put(p.z());
  w.put<std::uint32_t>(static_cast<std::uint32_t>(r.input.triangles.size()));
  for (const Triangle& t : r.input.triangles) w.put(t[0]), w.put(t[1]), w.put(t[2]);
  w.putPoints(r.uv);
  for (const auto& corners : r.density)
    for (double d : corners) w.put(d);
  w.putPoints(r.fixedSites);
  w.put<std::uint32_t>(static_cast<std::uint32_t>(r.movableVertex.size()));
  for (int v : r.movableVertex) w.put(v);
  w.put<std::uint32_t>(static_cast<std::uint32_t>(r.sharedSeams.size()));
  for (const auto& [a, b] : r.sharedSeams) w.put(a), w.put(b);
  w.put<std::uint32_t>(static_cast<std::uint32_t>(r.iterations.size()));
  for (const IterationRecord& it : r.iterations) {
    w.put(it.index);
    w.put(it.energy);
    w.put(it.maxDisplacement);
    w.put(it.meanDisplacement);
    w.put(it.fractionMoving);
    w.put(it.milliseconds);
    w.put<std::uint32_t>(static_cast<std::uint32_t>(it.sites.size()));
    const std::vector<std::uint32_t>& coordinates = it.sites.raw();
    w.putBytes(coordinates.data(), coordinates.size() * sizeof(std::uint32_t));
  }
}

std::string encodePayload(const Recording& r) {
  Writer size(/*counting=*/true), w;
  encodeInto(size, r);
  w.bytes().reserve(size.counted());
  encodeInto(w, r);
  return std::move(w.bytes());
}

// How far a recorded map may stray from the unit square it was scaled to (rounding).
constexpr double kUnitSquareSlack = 1e-9;
// Beyond it a cell's integrals overflow (a density of 1e308 made a centroid NaN, and CGAL's
// exact point location stopped the inspector with SIGFPE); no map distorts areas by so much.
constexpr double kLargestDensity = 1e100;
// A site is at most the unit square's diagonal from its centroid, both in the square.
const double kLargestDisplacement = std::sqrt(2.0) * (1 + kUnitSquareSlack);
// Longer than any run takes (about four months): more overflowed the plots' time axis.
constexpr double kLongestIterationMs = 1e10;

// What the replay takes for granted, which a file of the right size and checksum may still
// break (made by another program, or edited): each broke it with a crash.
void checkContents(const Recording& r, const std::string& path) {
  const auto damaged = [&](const std::string& why) { throw Error(path + ": damaged recording (" + why + ")"); };
  const auto allFinite = [](const auto& values) {
    return std::all_of(values.begin(), values.end(), [](const auto& v) { return v.allFinite(); });
  };
  if (r.iterations.empty()) damaged("no iterations");
  // The settings line is describe()'s, which the inspector and info read back and print: a
  // value no option takes, or a control character sent to the terminal, is damage.
  if (!std::all_of(r.settings.begin(), r.settings.end(), [](char c) { return c >= ' ' && c <= '~'; }))
    damaged("its settings hold a character no run writes");
  RemeshOptions recorded;
  try {
    recorded = optionsFromSettings(r.settings);
    recordedParamMethod(r.settings);
    recordedBorder(r.settings);
  } catch (const Error& e) {
    damaged(e.what());
  }
  if (r.input.triangles.empty()) damaged("no triangles");
  if (!allFinite(r.input.points) || !allFinite(r.uv) || !allFinite(r.fixedSites))
    damaged("a coordinate is not a finite number");
  // As every command takes a mesh: at 1e300 the 3D view was empty and the smallest angle 180.
  try {
    requireExactPredicatesRange(r.input, "its surface", "replayed");
  } catch (const Error& e) {
    damaged(e.what());
  }
  // As the command line takes them: a run never records others (the plots drew a threshold of
  // -1 nowhere, and one of 200% over the top of the plot).
  if (!(std::isfinite(r.distanceThreshold) && r.distanceThreshold > 0 && r.percentThreshold >= 0 &&
        r.percentThreshold <= 100))
    damaged("a threshold is not one a run takes (a distance above 0, a percentage from 0 to 100)");
  // The settings line and the numbers the replay reads are of one run: a picture said
  // "Thresholds: 1e-06" beside a threshold line drawn at 1e308.
  const bool thresholdsSet = !settingValue(r.settings, "distance-threshold").empty();
  if (thresholdsSet && (recorded.lloyd.distanceThreshold != r.distanceThreshold || recorded.lloyd.percentThreshold != r.percentThreshold))
    damaged("its thresholds differ from its settings'");
  if (!settingValue(r.settings, "method").empty() && recorded.method != r.method) damaged("its method differs from its settings'");
  // The map as parameterize() leaves it: scaled to the unit square, counter-clockwise, no
  // triangle turned over (mirrored, it crashed the replay's point location; scaled by 1e-150
  // it raised a floating-point exception there; border sites 1e300 away made it hang).
  const double area = mapArea(r.input, r.uv);
  if (!(area > 0)) damaged("its parameter domain has no area");
  const auto [lo, hi] = boundingBox(r.uv);
  const auto inSquare = [&](const Vec2& p) {
    return p.x() >= -kUnitSquareSlack && p.y() >= -kUnitSquareSlack && p.x() <= 1 + kUnitSquareSlack &&
           p.y() <= 1 + kUnitSquareSlack;
  };
  if (!inSquare(lo) || !inSquare(hi) || (hi - lo).maxCoeff() < 1 - kUnitSquareSlack)
    damaged("its parameter domain is not scaled to the unit square");
  if (!std::all_of(r.fixedSites.begin(), r.fixedSites.end(), inSquare))
    damaged("a border site lies outside the unit square");
  // Every iteration's result is triangulated inside them: where they cross, the replay failed
  // with an error that named no file.
  try {
    triangulateSites(r.fixedSites, {});
  } catch (const Error& e) {
    damaged(e.what());
  }
  for (const Triangle& t : r.input.triangles)
    if (triangleArea(r.uv[t[0]], r.uv[t[1]], r.uv[t[2]]) < -kFlatAreaShare * area)
      damaged("a parameter triangle is turned over");
  for (const auto& corners : r.density)
    for (double d : corners)
      if (!std::isfinite(d) || d < 0 || d > kLargestDensity) damaged("a density is negative, not a finite number or over 1e100");
  const size_t sites = r.iterations.front().sites.size();
  if (!r.movableVertex.empty() && r.movableVertex.size() != sites) damaged("its sites' vertices are not one per site");
  for (int v : r.movableVertex)
    if (v < -1 || v >= r.input.vertexCount()) damaged("a site's vertex is out of range");
}

// Which iterations decodePayload keeps: all, or the first alone (the others read and checked,
// then dropped: what saving checks, without a second copy of the recording).
enum class Keep { AllIterations, FirstIteration };

Recording decodePayload(Reader& in, const std::string& path, Keep keep = Keep::AllIterations) {
  Recording r;
  r.settings = in.getString();
  const std::uint8_t method = in.get<std::uint8_t>();
  if (method > 1) throw Error(path + ": damaged recording (its method is neither relocate nor retriangulate)");
  r.method = method == 0 ? RemeshMethod::Relocate : RemeshMethod::Retriangulate;
  r.distanceThreshold = in.get<double>();
  r.percentThreshold = in.get<double>();
  r.input.points.resize(in.getCount(24));
  for (Vec3& p : r.input.points) {
    const double x = in.get<double>(), y = in.get<double>(), z = in.get<double>();
    p = Vec3(x, y, z);
  }
  r.input.triangles.resize(in.getCount(12));
  for (Triangle& t : r.input.triangles)
    for (int& v : t) {
      v = in.get<int>();
      if (v < 0 || v >= r.input.vertexCount())
        throw Error(path + ": damaged recording (a triangle index is out of range)");
    }
  r.uv = in.getPoints();
  if (r.uv.size() != r.input.points.size())
    throw Error(path + ": damaged recording (UV count differs from vertex count)");
  r.density.resize(r.input.triangles.size());
  for (auto& corners : r.density)
    for (double& d : corners) d = in.get<double>();
  r.fixedSites = in.getPoints();
  if (r.fixedSites.size() < 3)  // a disk's border: the replay triangulates inside it
    throw Error(path + ": damaged recording (fewer than 3 border sites)");
  r.movableVertex.resize(in.getCount(4));
  for (int& v : r.movableVertex) v = in.get<int>();
  r.sharedSeams.resize(in.getCount(8));
  for (auto& [a, b] : r.sharedSeams) {
    a = in.get<int>();
    b = in.get<int>();
    if (std::min(a, b) < 0 || std::max(a, b) >= r.input.vertexCount())
      throw Error(path + ": damaged recording (a seam vertex is out of range)");
  }
  const size_t count = in.getCount(48);
  r.iterations.resize(keep == Keep::AllIterations ? count : std::min<size_t>(count, 1));
  IterationRecord dropped;
  for (size_t i = 0; i < count; ++i) {
    IterationRecord& it = i < r.iterations.size() ? r.iterations[i] : dropped;
    it.index = in.get<int>();
    it.energy = in.get<double>();
    it.maxDisplacement = in.get<double>();
    it.meanDisplacement = in.get<double>();
    it.fractionMoving = in.get<double>();
    it.milliseconds = in.get<double>();
    // What a run measures is never negative, nor a fraction over 1 (info printed "nan"), nor
    // a distance over the domain's diagonal (the log plots drew hundreds of labels at 1e308).
    const auto measure = [](double v, double most) { return std::isfinite(v) && v >= 0 && v <= most; };
    if (!measure(it.energy, INFINITY) || !measure(it.maxDisplacement, kLargestDisplacement) ||
        !measure(it.meanDisplacement, kLargestDisplacement) || !measure(it.milliseconds, kLongestIterationMs) ||
        !measure(it.fractionMoving, 1))
      throw Error(path + ": damaged recording (an iteration's energy, distances, share moving or time is out of range)");
    // Its place: info listed an iteration -2147483648.
    if (it.index != static_cast<int>(i)) throw Error(path + ": damaged recording (an iteration is out of order)");
    std::vector<std::uint32_t> coords(2 * size_t(in.getCount(8)));
    for (std::uint32_t& q : coords) q = in.get<std::uint32_t>();
    it.sites = PackedSites::fromRaw(std::move(coords));
    if (it.sites.size() != r.iterations.front().sites.size())
      throw Error(path + ": damaged recording (iterations differ in their number of sites)");
    // A share of the sites: a whole number of them (5e-324 drew 300 decades of labels).
    const double moving = it.fractionMoving * static_cast<double>(it.sites.size()), whole = std::round(moving);
    if (std::abs(moving - whole) > 1e-6 || (whole == 0) != (it.fractionMoving == 0))
      throw Error(path + ": damaged recording (an iteration's share moving is no whole number of sites)");
  }
  if (!in.done()) throw Error(path + ": damaged recording (unexpected data after the end)");
  checkContents(r, path);
  return r;
}

}  // namespace

std::vector<BoundedCell> Recording::cells(const Domain& domain, int iteration,
                                          bool keepGeometry, CellHints* hints) const {
  return computeCells(domain, allSites(fixedSites, iterations.at(iteration).sites),
                      keepGeometry ? CellDetail::Geometry : CellDetail::Integrals,
                      hints);
}

std::vector<IterationRecord> relaxAgain(const Recording& recording, const LloydOptions& options,
                                        const std::atomic<bool>* stop) {
  if (recording.iterations.empty()) return {};
  const Domain domain = recording.domain();
  LloydSolver solver(domain, recording.fixedSites, recording.iterations.front().sites.unpack(),
                     options);
  solver.run(stop);
  return solver.takeIterations();
}

namespace {

// The header, the payload and its checksum, written one after the other: the payload is not
// copied into one string with them (a second copy of the recording while it is saved).
void addToBatch(const std::string& payload, const std::string& path, FileBatch& batch) {
  Writer header, checksum;
  header.bytes().append(kMagic, sizeof(kMagic));
  header.put<std::uint32_t>(Recording::kVersion);
  header.put<std::uint64_t>(payload.size());
  checksum.put<std::uint64_t>(fnv1a(payload.data(), payload.size()));
  batch.add(path, [&](std::ostream& out) {
    const auto write = [&](const std::string& part) {
      out.write(part.data(), static_cast<std::streamsize>(part.size()));
    };
    write(header.bytes());
    write(payload);
    write(checksum.bytes());
  });
}

}  // namespace

void saveRecording(const Recording& recording, const std::string& path) {
  FileBatch batch;
  saveRecording(recording, path, batch);
  batch.commit();
}

void requireRecordingName(const std::string& path) { requireNoMeshExtension(path, "a recording", ".lsrec"); }

void saveRecording(const Recording& recording, const std::string& path, FileBatch& batch) {
  requireRecordingName(path);
  if (recording.iterations.empty())
    throw Error(path + ": nothing to record: no iteration was run (" + kNoIterationWhy + ")");
  const std::string payload = encodePayload(recording);
  // What is saved reads back: a recording the replay would refuse is not written.
  try {
    Reader in(payload, 0, payload.size(), path);
    decodePayload(in, path, Keep::FirstIteration);
  } catch (const Error& e) {
    throw Error(std::string(e.what()) + "; not saved: the run made a recording that would not read back");
  }
  addToBatch(payload, path, batch);
}

void saveRecordingUnchecked(const Recording& recording, const std::string& path) {
  FileBatch batch;
  addToBatch(encodePayload(recording), path, batch);
  batch.commit();
}

bool isRecording(const std::string& path) {
  // A pipe is read once: its first bytes, read here, were gone for the reader of the mesh
  // (or it waited for a second writer that never came). Only a file is looked into.
  std::error_code ignored;
  if (!std::filesystem::is_regular_file(path, ignored)) return false;
  char start[sizeof(kMagic)] = {};
  std::ifstream file(path, std::ios::binary);
  return file.read(start, sizeof start) && std::memcmp(start, kMagic, sizeof(kMagic)) == 0;
}

Recording loadRecording(const std::string& path) {
  std::error_code ignored;  // a folder opens, then fails to read with an "internal error"
  if (std::filesystem::is_directory(path, ignored)) throw Error(path + ": is a folder, not a recording");
  std::ifstream file(path, std::ios::binary);
  if (!file) throw Error(path + ": cannot open the recording (missing or unreadable)");
  const std::string bytes = readWhole(file, path, kLargestRecording, "a recording");
  if (bytes.size() < sizeof(kMagic) || std::memcmp(bytes.data(), kMagic, sizeof(kMagic)) != 0)
    throw Error(path + ": not a Lloydscope recording");
  if (bytes.size() < kHeaderSize)
    throw Error(path + ": truncated recording (the header is incomplete)");
  std::uint32_t version;
  std::uint64_t payloadSize;
  std::memcpy(&version, bytes.data() + sizeof(kMagic), 4);
  std::memcpy(&payloadSize, bytes.data() + sizeof(kMagic) + 4, 8);
  if (version != Recording::kVersion)
    throw Error(path + ": recording version " + std::to_string(version) +
                " is not supported (this build reads version " +
                std::to_string(Recording::kVersion) + ")");
  const size_t available = bytes.size() - kHeaderSize;
  // A size past any recording's is a damaged header, not a cut file (2^64 - 1 bytes read
  // "truncated recording (... bytes, expected 19)": the sum wrapped round).
  if (payloadSize > kLargestRecording)
    throw Error(path + ": damaged recording (its header gives " + std::to_string(payloadSize) +
                " bytes of data, more than any recording holds)");
  if (payloadSize > available || available - payloadSize < kChecksumSize)
    throw Error(path + ": truncated recording (" + std::to_string(bytes.size()) + " bytes, " +
                "expected " + std::to_string(kHeaderSize + payloadSize + kChecksumSize) + ")");
  if (available - payloadSize > kChecksumSize)
    throw Error(path + ": damaged recording (unexpected data after the end)");
  std::uint64_t checksum;
  std::memcpy(&checksum, bytes.data() + kHeaderSize + payloadSize, 8);
  if (checksum != fnv1a(bytes.data() + kHeaderSize, payloadSize))
    throw Error(path + ": corrupt recording (checksum mismatch)");
  Reader in(bytes, kHeaderSize, kHeaderSize + payloadSize, path);
  return decodePayload(in, path);
}

}  // namespace lloydscope
