// Reading, validating and writing triangle meshes in OFF, OBJ and PLY.
//
// A reader loads the whole file into memory and parses it into a RawMesh: points, and polygons
// whose indices are stored exactly as the file gives them (converted to 0-based). readMesh() then
// checks the polygons, fan-triangulates the larger ones, runs the same surface checks as
// validateMesh() and finally drops vertices no face uses. Messages number vertices and faces the
// way the file does (from 0 for OFF and PLY, from 1 for OBJ), so that a user can find them.
//
// Every problem is an Error("<path>: <problem>") on a single line.
#include "mesh_io.h"

#include "files.h"
#include "repair.h"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <optional>
#include <sstream>
#include <string_view>
#include <system_error>
#include <tuple>

namespace lloydscope {
namespace {

// ------------------------------------------------------------------------------------ messages

[[noreturn]] void fail(const std::string& path, const std::string& problem) {
  throw Error(path + ": " + problem);
}

std::string str(long long n) { return std::to_string(n); }

std::string plural(long long n, const char* one, const char* many) {
  return str(n) + " " + (n == 1 ? one : many);
}

// A token of the file as it may appear in a message: short and printable, so that even a
// binary file read as text gives a readable one-line message.
std::string shown(std::string_view token) {
  const size_t kMax = 32;
  std::string out = "'";
  for (char c : token.substr(0, kMax)) out += std::isprint(static_cast<unsigned char>(c)) ? c : '?';
  if (token.size() > kMax) out += "...";
  return out + "'";
}

bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v'; }

bool onlySpace(std::string_view text) { return std::all_of(text.begin(), text.end(), isSpace); }

std::string unknownExtension(const std::string& path) {
  const std::string ext = std::filesystem::path(path).extension().string();
  return (ext.empty() ? std::string("no extension") : "unknown extension " + shown(ext)) +
         " (expected .off, .obj or .ply)";
}

// ------------------------------------------------------------------------------------- numbers

// A leading '+', which from_chars does not take, gone; "" where a sign follows it ("+-1" was
// read as -1, which strtod refuses).
std::string_view withoutPlus(std::string_view token) {
  if (token.empty() || token[0] != '+') return token;
  token.remove_prefix(1);
  return !token.empty() && (token[0] == '-' || token[0] == '+') ? std::string_view() : token;
}

// The whole token must be a number. Out-of-range values become +-inf or 0 like strtod does,
// so that "1e999" is reported as a non-finite coordinate rather than as garbage.
bool parseDouble(std::string_view token, double& value) {
  token = withoutPlus(token);
  if (token.empty()) return false;
  const char* end = token.data() + token.size();
  const auto [stop, ec] = std::from_chars(token.data(), end, value);
  if (stop != end) return false;
  if (ec == std::errc::result_out_of_range) value = std::strtod(std::string(token).c_str(), nullptr);
  else if (ec != std::errc()) return false;
  return true;
}

bool parseInteger(std::string_view token, long long& value) {
  token = withoutPlus(token);
  if (token.empty()) return false;
  const char* end = token.data() + token.size();
  const auto [stop, ec] = std::from_chars(token.data(), end, value);
  return ec == std::errc() && stop == end;
}

// Digits past what a long long holds: parseInteger refuses them as it refuses a word, but they
// are a number, too large (2^63 was said to be "not an integer").
bool tooLargeAnInteger(std::string_view token) {
  long long ignored;
  if (parseInteger(token, ignored)) return false;
  if (!token.empty() && (token[0] == '+' || token[0] == '-')) token.remove_prefix(1);
  return !token.empty() && std::all_of(token.begin(), token.end(), [](char c) { return c >= '0' && c <= '9'; });
}

std::string whyNotAnInteger(std::string_view token) {
  return tooLargeAnInteger(token) ? " is too large a number" : " is not an integer";
}

// ----------------------------------------------------------------------------------- raw mesh

// What a reader produces: geometry plus polygons of any size, with 0-based indices that have
// not been range-checked yet (an OBJ face may name a vertex defined further down).
struct RawMesh {
  std::vector<Vec3> points;
  std::vector<long long> indices;       // all polygons, one after the other
  std::vector<size_t> polygonStart{0};  // polygon f is indices[polygonStart[f], polygonStart[f+1])
  int base = 0;                         // how the file numbers vertices and faces (1 for OBJ)

  long long polygonCount() const { return static_cast<long long>(polygonStart.size()) - 1; }
  void endPolygon() { polygonStart.push_back(indices.size()); }
};

// How messages number vertices and faces: as the file does, before triangulation.
struct Numbering {
  int base = 0;
  const std::vector<long long>* faceOfTriangle = nullptr;  // null: triangle t is face t

  long long vertex(long long v) const { return v + base; }
  long long face(size_t t) const {
    return (faceOfTriangle ? (*faceOfTriangle)[t] : static_cast<long long>(t)) + base;
  }
};

// ------------------------------------------------------------------------------- text reading

// Splits text into lines and lines into white-space separated tokens; '#' starts a comment,
// unless a '.' comes right before it: old Microsoft libraries wrote a NaN as "-1.#IND", which
// read as -1 and a comment, without a word. It is now a word that is no number.
class LineReader {
 public:
  // `continuations`: a line that ends in a backslash goes on on the next one (OBJ's rule).
  explicit LineReader(std::string_view text, bool continuations = false)
      : text_(text), continuations_(continuations) {}

  // Moves to the next line that has a token; false at the end of the text.
  bool next(std::vector<std::string_view>& tokens) {
    tokens.clear();
    while (pos_ < text_.size()) {
      size_t end = text_.find('\n', pos_);
      if (end == std::string_view::npos) end = text_.size();
      std::string_view line = text_.substr(pos_, end - pos_);
      pos_ = std::min(end + 1, text_.size());
      ++lineNumber_;
      line = withoutComment(line);
      const bool goesOn = continuations_ && endsInBackslash(line);
      split(line, tokens);
      if (goesOn) continue;
      if (!tokens.empty()) return true;
    }
    return !tokens.empty();
  }

  int lineNumber() const { return lineNumber_; }
  size_t position() const { return pos_; }  // first character after the current line

 private:
  static std::string_view withoutComment(std::string_view line) {
    for (size_t at = line.find('#'); at != std::string_view::npos; at = line.find('#', at + 1))
      if (at == 0 || line[at - 1] != '.') return line.substr(0, at);
    return line;
  }

  // Drops the backslash that ends `line` (white space after it aside), if there is one.
  static bool endsInBackslash(std::string_view& line) {
    size_t end = line.size();
    while (end > 0 && isSpace(line[end - 1])) --end;
    if (end == 0 || line[end - 1] != '\\') return false;
    line = line.substr(0, end - 1);
    return true;
  }

  // Appends the tokens of `line`.
  static void split(std::string_view line, std::vector<std::string_view>& tokens) {
    size_t i = 0;
    while (i < line.size()) {
      while (i < line.size() && isSpace(line[i])) ++i;
      const size_t start = i;
      while (i < line.size() && !isSpace(line[i])) ++i;
      if (i > start) tokens.push_back(line.substr(start, i - start));
    }
  }

  std::string_view text_;
  bool continuations_;
  size_t pos_ = 0;
  int lineNumber_ = 0;
};

std::string atLine(int line) { return "line " + str(line) + ": "; }

double numberAt(const std::string& path, int line, std::string_view token) {
  double value;
  if (!parseDouble(token, value)) fail(path, atLine(line) + shown(token) + " is not a number");
  return value;
}

long long integerAt(const std::string& path, int line, std::string_view token) {
  long long value;
  if (!parseInteger(token, value)) fail(path, atLine(line) + shown(token) + whyNotAnInteger(token));
  return value;
}

// ----------------------------------------------------------------------------- binary reading

// A binary file's header with its lines ended by CR alone reads as one line (loadFile keeps a
// binary file's CRs: its bytes 13 are numbers), the body's first bytes with it.
const char* const kBinaryHeaderEndsInCr =
    "bad header: its lines end in CR alone, which a binary file's cannot (save it with LF line ends)";

// The header line at the start of `line` is a keyword ("ply", "OFF BINARY") ended by CR alone.
bool endsInCrAlone(std::string_view line, std::string_view keyword) {
  return line.size() > keyword.size() + 1 && line.rfind(keyword, 0) == 0 && line[keyword.size()] == '\r' &&
         line[keyword.size() + 1] != '\n';
}

bool hostIsLittleEndian() {
  const std::uint16_t one = 1;
  unsigned char first;
  std::memcpy(&first, &one, 1);
  return first == 1;
}

// Reads fixed-size numbers in the file's byte order and never past the end of the data.
class BinaryReader {
 public:
  BinaryReader(std::string_view data, bool bigEndian)
      : data_(data), swap_(bigEndian == hostIsLittleEndian()) {}

  template <class T>
  bool get(T& value) {
    if (remaining() < sizeof(T)) return false;
    unsigned char bytes[sizeof(T)];
    std::memcpy(bytes, data_.data() + pos_, sizeof(T));
    if (swap_) std::reverse(bytes, bytes + sizeof(T));
    std::memcpy(&value, bytes, sizeof(T));
    pos_ += sizeof(T);
    return true;
  }

  bool skip(size_t bytes) {
    if (remaining() < bytes) return false;
    pos_ += bytes;
    return true;
  }

  size_t remaining() const { return data_.size() - pos_; }
  std::string_view rest() const { return data_.substr(pos_); }

 private:
  std::string_view data_;
  size_t pos_ = 0;
  bool swap_;
};

// ---------------------------------------------------------------------------------------- OFF

// Which prefixes of "OFF" we read: colours (C), normals (N) and texture coordinates (ST) only
// add values at the end of a vertex line, which are ignored. 4OFF and nOFF are not 3D.
bool isSupportedOffKeyword(std::string_view keyword) {
  static const char* const kKeywords[] = {"OFF",    "COFF",   "NOFF",   "CNOFF",   "NCOFF",
                                          "STOFF",  "STCOFF", "STNOFF", "STCNOFF", "STNCOFF"};
  return std::find(std::begin(kKeywords), std::end(kKeywords), keyword) != std::end(kKeywords);
}

// A count in a header (OFF's counts, a PLY element's), `what` naming it.
int headerCount(const std::string& path, int line, std::string_view token, const std::string& what) {
  long long value;
  if (!parseInteger(token, value)) {
    fail(path, "bad header: " + atLine(line) + what + " count " + shown(token) + whyNotAnInteger(token));
  }
  if (value < 0 || value > INT_MAX) {
    fail(path, "bad header: " + atLine(line) + what + " count " + str(value) +
                   " is impossible");
  }
  return static_cast<int>(value);
}

// Reserves room for at most as many vertices as the remaining bytes can hold, so that a corrupt
// count cannot make us allocate gigabytes; reading then stops where the data really ends and
// says so.
void reservePoints(RawMesh& raw, long long count, size_t remainingBytes, size_t bytesPerVertex) {
  raw.points.reserve(static_cast<size_t>(std::min<long long>(count, remainingBytes / bytesPerVertex)));
}

RawMesh readBinaryOff(const std::string& path, std::string_view data) {
  BinaryReader in(data, /*bigEndian=*/true);
  std::int32_t nv, nf, ne;
  if (!in.get(nv) || !in.get(nf) || !in.get(ne)) {
    fail(path, "file is truncated: the binary OFF counts are cut short");
  }
  if (nv < 0 || nf < 0) {
    fail(path, "bad header: negative count (" + str(nv) + " vertices, " + str(nf) + " faces)");
  }
  RawMesh raw;
  reservePoints(raw, nv, in.remaining(), 12);
  for (int i = 0; i < nv; ++i) {
    float x, y, z;
    if (!in.get(x) || !in.get(y) || !in.get(z)) {
      fail(path, "file is truncated: it ends inside vertex " + str(i) + " of " + str(nv));
    }
    raw.points.emplace_back(x, y, z);
  }
  for (int f = 0; f < nf; ++f) {
    const auto truncated = [&] { return "file is truncated: it ends inside face " + str(f) + " of " + str(nf); };
    std::int32_t n;
    if (!in.get(n)) fail(path, truncated());
    if (n < 0) fail(path, "face " + str(f) + " has a negative vertex count (" + str(n) + ")");
    if (static_cast<size_t>(n) > in.remaining() / 4) fail(path, truncated());
    for (int k = 0; k < n; ++k) {
      std::int32_t v = 0;
      in.get(v);  // room was checked above
      raw.indices.push_back(v);
    }
    raw.endPolygon();
    std::int32_t colours;
    if (!in.get(colours)) fail(path, truncated());
    if (colours < 0) fail(path, "face " + str(f) + " has a negative colour count (" + str(colours) + ")");
    if (!in.skip(4 * static_cast<size_t>(colours))) fail(path, truncated());
  }
  if (!onlySpace(in.rest())) {
    fail(path, "header says " + plural(nf, "face", "faces") + " but the file has more data");
  }
  return raw;
}

// Geomview's OFF is free format: a plain OFF file may hold several vertices on a line. Its
// vertices then, three numbers each, whole on their lines, two or more on some line; and its
// faces, a line each: the vertex count, the indices, then a colour. Nothing where `body` is not
// so: a vertex line one number short (damage) read as a vertex over two lines, without a word.
std::optional<RawMesh> readFreeFormatOff(std::string_view body, int nv, int nf) {
  LineReader lines(body);
  std::vector<std::string_view> tokens;
  size_t at = 0;  // the next vertex's first number in `tokens`
  RawMesh raw;
  bool packed = false;
  for (int i = 0; i < nv; ++i, at += 3) {
    if (at == tokens.size()) {  // a new line: whole vertices
      if (!lines.next(tokens) || tokens.size() % 3 != 0) return std::nullopt;
      at = 0;
      packed = packed || tokens.size() > 3;
    }
    Vec3 p;
    for (int c = 0; c < 3; ++c)
      if (!parseDouble(tokens[at + c], p[c])) return std::nullopt;
    raw.points.push_back(p);
  }
  if (!packed || at != tokens.size()) return std::nullopt;
  for (int f = 0; f < nf; ++f) {  // a line each: a face one index short took the next line's
    long long n, v;
    if (!lines.next(tokens) || !parseInteger(tokens[0], n) || n < 0 || n >= static_cast<long long>(tokens.size()))
      return std::nullopt;
    for (long long k = 1; k <= n; ++k) {
      if (!parseInteger(tokens[k], v)) return std::nullopt;
      raw.indices.push_back(v);
    }
    raw.endPolygon();
  }
  if (lines.next(tokens)) return std::nullopt;
  return raw;
}

RawMesh readOffLines(const std::string& path, LineReader& lines, int nv, int nf, size_t bodySize);

RawMesh readOff(const std::string& path, std::string_view text) {
  LineReader lines(text);
  std::vector<std::string_view> tokens;
  if (!lines.next(tokens)) fail(path, "bad header: the file has only comments, no 'OFF' line");
  // "OFF500 938 0": the vertex count written against the keyword (as in ModelNet40's files).
  const size_t digits = tokens[0].find_first_of("0123456789");
  if (digits != std::string_view::npos && digits > 0 && isSupportedOffKeyword(tokens[0].substr(0, digits))) {
    tokens.insert(tokens.begin() + 1, tokens[0].substr(digits));
    tokens[0] = tokens[0].substr(0, digits);
  }
  if (!isSupportedOffKeyword(tokens[0])) {
    fail(path, "bad header: expected 'OFF' (or COFF, NOFF, ...) but the file starts with " +
                   shown(tokens[0]));
  }
  if (tokens.size() >= 2 && tokens[1] == "BINARY") {
    if (tokens[0] != "OFF") fail(path, "bad header: only plain 'OFF BINARY' is supported as binary OFF");
    if (endsInCrAlone(text.substr(tokens[0].data() - text.data()), "OFF BINARY")) fail(path, kBinaryHeaderEndsInCr);
    return readBinaryOff(path, text.substr(lines.position()));
  }

  // The counts may follow the keyword on the same line ("OFF 8 6 12") or be on the next line.
  std::vector<std::string_view> counts(tokens.begin() + 1, tokens.end());
  if (counts.empty() && !lines.next(counts)) fail(path, "bad header: the vertex and face counts are missing");
  if (counts.size() < 2 || counts.size() > 3) {
    fail(path, "bad header: " + atLine(lines.lineNumber()) +
                   "expected 'vertices faces edges' counts, found " + plural(counts.size(), "value", "values"));
  }
  const int nv = headerCount(path, lines.lineNumber(), counts[0], "vertex");
  const int nf = headerCount(path, lines.lineNumber(), counts[1], "face");
  if (counts.size() == 3) headerCount(path, lines.lineNumber(), counts[2], "edge");  // unused, but must be sane
  const bool plain = tokens[0] == "OFF";
  const std::string_view body = text.substr(lines.position());
  try {
    return readOffLines(path, lines, nv, nf, body.size());
  } catch (const Error&) {
    if (plain)
      if (std::optional<RawMesh> raw = readFreeFormatOff(body, nv, nf)) return std::move(*raw);
    throw;
  }
}

// Whether a vertex line reads as a face: a count of three or more, then as many whole indices
// and nothing else. Where the header's vertex count is more than the file has, the last of
// its "vertices" are faces: a header's counts swapped (72 49 for 49 72) read 23 faces as
// vertices and kept the mesh's last 49 faces, with no error.
bool readsAsFace(const std::vector<std::string_view>& tokens) {
  long long n = 0, index = 0;
  if (tokens.size() < 4 || !parseInteger(tokens[0], n) || n != static_cast<long long>(tokens.size()) - 1) return false;
  return std::all_of(tokens.begin() + 1, tokens.end(),
                     [&](std::string_view t) { return parseInteger(t, index) && index >= 0; });
}

// An OFF file's vertices and faces, a line each (values after a vertex's three or a face's
// indices are colours, normals ... which we do not need), from the line after the counts on.
RawMesh readOffLines(const std::string& path, LineReader& lines, int nv, int nf, size_t bodySize) {
  std::vector<std::string_view> tokens;
  RawMesh raw;
  reservePoints(raw, nv, bodySize, 6);  // "0 0 0\n"
  size_t widest = 0;  // the most numbers on one vertex line, and where
  int widestLine = 0;
  size_t firstWidth = 0;  // the first vertex line's numbers: the last, a face, has more
  for (int i = 0; i < nv; ++i) {
    if (!lines.next(tokens)) {
      // Several vertices written on one line read as one: say where, not just "truncated".
      fail(path, "file is truncated: header says " + plural(nv, "vertex", "vertices") + " but the file ends after " +
                     str(i) +
                     (widest > 7 ? " (a line is one vertex, and line " + str(widestLine) + " holds " +
                                       str(widest) + " numbers)"
                                 : ""));
    }
    const int line = lines.lineNumber();
    if (tokens.size() > widest) widest = tokens.size(), widestLine = line;
    if (tokens.size() < 3) {
      fail(path, atLine(line) + "vertex " + str(i) + " has " + plural(tokens.size(), "coordinate", "coordinates") +
                     " (expected 3)");
    }
    raw.points.emplace_back(numberAt(path, line, tokens[0]), numberAt(path, line, tokens[1]),
                            numberAt(path, line, tokens[2]));
    if (i == 0) firstWidth = tokens.size();
    // The last "vertex" a face (a free-format file's vertices, six numbers on a line, are
    // wider than a face that ran into them: readFreeFormatOff says what is wrong there).
    if (i == nv - 1 && firstWidth < tokens.size() && readsAsFace(tokens)) {
      std::string text;
      for (std::string_view t : tokens) text += (text.empty() ? "" : " ") + std::string(t);
      fail(path, atLine(line) + "vertex " + str(i) + " reads as a face ('" + text + "'): the header's counts (" +
                     plural(nv, "vertex", "vertices") + ", " + plural(nf, "face", "faces") +
                     ") do not match the file");
    }
  }
  for (int f = 0; f < nf; ++f) {
    if (!lines.next(tokens)) {
      fail(path, "file is truncated: header says " + plural(nf, "face", "faces") +
                     " but the file ends after " + str(f));
    }
    const int line = lines.lineNumber();
    long long n;
    if (!parseInteger(tokens[0], n)) {
      fail(path, atLine(line) + "face " + str(f) + " should start with its vertex count, found " +
                     shown(tokens[0]) + " (more vertex lines than the header says?)");
    }
    if (n < 0) fail(path, atLine(line) + "face " + str(f) + " has a negative vertex count (" + str(n) + ")");
    if (n > static_cast<long long>(tokens.size()) - 1) {
      fail(path, atLine(line) + "face " + str(f) + " should have " + str(n) + " vertices but lists " +
                     str(tokens.size() - 1));
    }
    // Values after the indices are a colour, which we do not need.
    for (long long k = 1; k <= n; ++k) raw.indices.push_back(integerAt(path, line, tokens[k]));
    raw.endPolygon();
  }
  if (lines.next(tokens)) {
    fail(path, "header says " + plural(nf, "face", "faces") + " but the file has more data (" +
                   atLine(lines.lineNumber()) + shown(tokens[0]) + ")");
  }
  return raw;
}

// ---------------------------------------------------------------------------------------- OBJ

// "12", "12/4", "12//7", "12/4/7" and negative (relative) forms; returns the 0-based index.
long long objIndex(const std::string& path, int line, long long face, std::string_view token,
                   long long verticesSoFar) {
  // The texture and normal indices are not used, but must be numbers (or left out): "1/x/y"
  // and "1/1/1/1" were read as vertex 1, where "v 0.0abc" is refused.
  std::vector<std::string_view> parts;
  for (size_t start = 0;;) {
    const size_t slash = token.find('/', start);
    parts.push_back(token.substr(start, slash == std::string_view::npos ? slash : slash - start));
    if (slash == std::string_view::npos) break;
    start = slash + 1;
  }
  long long index, unused;
  const bool wellFormed = parts.size() <= 3 && parseInteger(parts[0], index) &&
                          std::all_of(parts.begin() + 1, parts.end(),
                                      [&](std::string_view p) { return p.empty() || parseInteger(p, unused); });
  if (!wellFormed)
    fail(path, atLine(line) + shown(token) +
                   (parts.size() <= 3 && tooLargeAnInteger(parts[0]) ? " is too large a number for a vertex index"
                        : " is not a vertex index (v, v/vt, v//vn or v/vt/vn)"));
  if (index == 0) fail(path, atLine(line) + "face " + str(face) + " uses vertex 0 (OBJ counts vertices from 1)");
  if (index > 0) return index - 1;  // may refer to a later vertex; range-checked after reading
  if (index < -verticesSoFar) {
    fail(path, "face " + str(face) + " uses vertex " + str(index) + " but only " +
                   plural(verticesSoFar, "vertex precedes", "vertices precede") + " it");
  }
  return verticesSoFar + index;
}

RawMesh readObj(const std::string& path, std::string_view text) {
  if (text.find('\0') != std::string_view::npos) {
    fail(path, "bad header: this is not a text OBJ file (it contains binary data)");
  }
  RawMesh raw;
  raw.base = 1;
  LineReader lines(text, /*continuations=*/true);
  std::vector<std::string_view> tokens;
  while (lines.next(tokens)) {
    const int line = lines.lineNumber();
    if (tokens[0] == "v") {
      if (tokens.size() < 4) {
        fail(path, atLine(line) + "vertex " + str(raw.points.size() + 1) + " has " +
                       plural(tokens.size() - 1, "coordinate", "coordinates") + " (expected 3)");
      }
      raw.points.emplace_back(numberAt(path, line, tokens[1]), numberAt(path, line, tokens[2]),
                              numberAt(path, line, tokens[3]));
    } else if (tokens[0] == "f") {
      const long long face = raw.polygonCount() + 1;
      for (size_t k = 1; k < tokens.size(); ++k) {
        raw.indices.push_back(objIndex(path, line, face, tokens[k], raw.points.size()));
      }
      raw.endPolygon();
    }
    // Texture coordinates, normals, groups, materials, lines ... do not matter here.
  }
  return raw;
}

// ---------------------------------------------------------------------------------------- PLY

enum class PlyType { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };
enum class PlyFormat { Ascii, BinaryLittleEndian, BinaryBigEndian };

std::optional<PlyType> plyType(std::string_view name) {
  static const std::pair<const char*, PlyType> kNames[] = {
      {"char", PlyType::Int8},     {"int8", PlyType::Int8},       {"uchar", PlyType::UInt8},
      {"uint8", PlyType::UInt8},   {"short", PlyType::Int16},     {"int16", PlyType::Int16},
      {"ushort", PlyType::UInt16}, {"uint16", PlyType::UInt16},   {"int", PlyType::Int32},
      {"int32", PlyType::Int32},   {"uint", PlyType::UInt32},     {"uint32", PlyType::UInt32},
      {"float", PlyType::Float32}, {"float32", PlyType::Float32}, {"double", PlyType::Float64},
      {"float64", PlyType::Float64}};
  for (const auto& [typeName, type] : kNames) {
    if (name == typeName) return type;
  }
  return std::nullopt;
}

bool isIntegerType(PlyType type) { return type != PlyType::Float32 && type != PlyType::Float64; }

struct PlyProperty {
  std::string name;
  PlyType type = PlyType::Float32;  // of the items, for a list
  bool isList = false;
  PlyType countType = PlyType::UInt8;
};

struct PlyElement {
  std::string name;
  long long count = 0;
  std::vector<PlyProperty> properties;

  const PlyProperty* find(std::string_view propertyName) const {
    for (const PlyProperty& p : properties) {
      if (p.name == propertyName) return &p;
    }
    return nullptr;
  }
};

struct PlyHeader {
  PlyFormat format = PlyFormat::Ascii;
  std::vector<PlyElement> elements;
  size_t bodyStart = 0;  // offset of the first byte after "end_header\n"
  int bodyLine = 0;      // line number of the body's first line (ASCII)

  const PlyElement* find(std::string_view name) const {
    for (const PlyElement& e : elements) {
      if (e.name == name) return &e;
    }
    return nullptr;
  }
};

PlyType plyTypeAt(const std::string& path, int line, std::string_view name) {
  const std::optional<PlyType> type = plyType(name);
  if (!type) fail(path, "bad header: " + atLine(line) + "unknown property type " + shown(name));
  return *type;
}

// The header is read line by line without the LineReader: '#' is not a comment in PLY and the
// binary body must start exactly after "end_header\n".
PlyHeader readPlyHeader(const std::string& path, std::string_view text) {
  PlyHeader header;
  bool sawFormat = false;
  size_t pos = 0;
  std::vector<std::string_view> tokens;
  for (int line = 1;; ++line) {
    if (pos >= text.size()) fail(path, "bad header: no 'end_header' line");
    size_t end = text.find('\n', pos);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view lineText = text.substr(pos, end - pos);
    pos = std::min(end + 1, text.size());

    tokens.clear();
    for (size_t i = 0; i < lineText.size();) {
      while (i < lineText.size() && isSpace(lineText[i])) ++i;
      const size_t start = i;
      while (i < lineText.size() && !isSpace(lineText[i])) ++i;
      if (i > start) tokens.push_back(lineText.substr(start, i - start));
    }

    if (line == 1) {
      if (endsInCrAlone(lineText, "ply")) fail(path, kBinaryHeaderEndsInCr);
      if (tokens.size() != 1 || tokens[0] != "ply") {
        fail(path, "bad header: a PLY file must start with a 'ply' line");
      }
      continue;
    }
    if (tokens.empty() || tokens[0] == "comment" || tokens[0] == "obj_info") continue;
    const std::string_view keyword = tokens[0];
    if (keyword == "end_header") {
      header.bodyStart = pos;
      header.bodyLine = line + 1;
      break;
    }
    if (keyword == "format") {
      if (tokens.size() != 3 || tokens[2] != "1.0") {
        fail(path, "bad header: " + atLine(line) + "expected 'format <kind> 1.0'");
      }
      if (tokens[1] == "ascii") header.format = PlyFormat::Ascii;
      else if (tokens[1] == "binary_little_endian") header.format = PlyFormat::BinaryLittleEndian;
      else if (tokens[1] == "binary_big_endian") header.format = PlyFormat::BinaryBigEndian;
      else fail(path, "bad header: " + atLine(line) + "unknown format " + shown(tokens[1]));
      sawFormat = true;
    } else if (keyword == "element") {
      if (tokens.size() != 3) fail(path, "bad header: " + atLine(line) + "expected 'element <name> <count>'");
      const int count = headerCount(path, line, tokens[2], "element " + shown(tokens[1]));
      header.elements.push_back({std::string(tokens[1]), count, {}});
    } else if (keyword == "property") {
      if (header.elements.empty()) fail(path, "bad header: " + atLine(line) + "property before any element");
      PlyProperty property;
      if (tokens.size() == 5 && tokens[1] == "list") {
        property.isList = true;
        property.countType = plyTypeAt(path, line, tokens[2]);
        property.type = plyTypeAt(path, line, tokens[3]);
        property.name = tokens[4];
        if (!isIntegerType(property.countType)) {
          fail(path, "bad header: " + atLine(line) + "a list length must have an integer type");
        }
      } else if (tokens.size() == 3) {
        property.type = plyTypeAt(path, line, tokens[1]);
        property.name = tokens[2];
      } else {
        fail(path, "bad header: " + atLine(line) + "expected 'property <type> <name>' or "
                   "'property list <type> <type> <name>'");
      }
      header.elements.back().properties.push_back(property);
    } else {
      fail(path, "bad header: " + atLine(line) + "unexpected " + shown(keyword));
    }
  }
  if (!sawFormat) fail(path, "bad header: no 'format' line");
  for (const PlyElement& element : header.elements) {
    // An element without properties takes no bytes, so its count could not be checked.
    if (element.properties.empty() && element.count > 0) {
      fail(path, "bad header: element " + shown(element.name) + " has no properties");
    }
  }
  return header;
}

// Hands out property values one by one from the ASCII tokens or the binary data of the body.
class PlyValues {
 public:
  PlyValues(const std::string& path, std::string_view body, PlyFormat format, int firstLine)
      : path_(path), body_(body), format_(format), binary_(body, format == PlyFormat::BinaryBigEndian),
        line_(firstLine) {}

  // False when the data ends before the value.
  bool read(PlyType type, double& value) {
    return format_ == PlyFormat::Ascii ? readToken(type, value) : readBinary(type, value);
  }

  size_t remaining() const { return format_ == PlyFormat::Ascii ? body_.size() - pos_ : binary_.remaining(); }
  // ASCII: a value follows on the line of the last one read (a row longer than its header says,
  // or rows packed on one line).
  bool moreOnThisLine() const {
    if (format_ != PlyFormat::Ascii) return false;
    size_t at = pos_;
    while (at < body_.size() && isSpace(body_[at]) && body_[at] != '\n') ++at;
    return at < body_.size() && body_[at] != '\n';
  }
  int line() const { return line_; }
  std::string_view rest() const { return format_ == PlyFormat::Ascii ? body_.substr(pos_) : binary_.rest(); }

 private:
  bool readToken(PlyType type, double& value) {
    while (pos_ < body_.size() && isSpace(body_[pos_])) {
      if (body_[pos_] == '\n') ++line_;
      ++pos_;
    }
    if (pos_ == body_.size()) return false;
    const size_t start = pos_;
    while (pos_ < body_.size() && !isSpace(body_[pos_])) ++pos_;
    const std::string_view token = body_.substr(start, pos_ - start);
    if (isIntegerType(type)) value = static_cast<double>(integerAt(path_, line_, token));
    else value = numberAt(path_, line_, token);
    return true;
  }

  template <class T>
  bool readAs(double& value) {
    T v;
    if (!binary_.get(v)) return false;
    value = static_cast<double>(v);
    return true;
  }

  bool readBinary(PlyType type, double& value) {
    switch (type) {
      case PlyType::Int8: return readAs<std::int8_t>(value);
      case PlyType::UInt8: return readAs<std::uint8_t>(value);
      case PlyType::Int16: return readAs<std::int16_t>(value);
      case PlyType::UInt16: return readAs<std::uint16_t>(value);
      case PlyType::Int32: return readAs<std::int32_t>(value);
      case PlyType::UInt32: return readAs<std::uint32_t>(value);
      case PlyType::Float32: return readAs<float>(value);
      case PlyType::Float64: return readAs<double>(value);
    }
    return false;
  }

  const std::string& path_;
  std::string_view body_;
  PlyFormat format_;
  BinaryReader binary_;
  size_t pos_ = 0;  // ASCII only
  int line_;        // ASCII only
};

// The integer list of vertex indices of a face element, or of triangle strips: null where there
// is no such element; an error where it has no such list.
const PlyProperty* indexList(const std::string& path, const PlyElement* element) {
  if (!element) return nullptr;
  const PlyProperty* list = element->find("vertex_indices");
  if (!list) list = element->find("vertex_index");
  if (!list || !list->isList || !isIntegerType(list->type))
    fail(path, "bad header: the " + element->name + " element has no integer 'vertex_indices' list");
  return list;
}

// The triangles of a strip (PLY's "tristrips", as MeshLab writes them): -1 ends a strip, and
// every other triangle of a strip turns the other way so that all face one way. A triangle on
// two equal indices joins two strips: it is no face.
void addStrip(const std::vector<long long>& strip, RawMesh& raw) {
  for (size_t i = 0, start = 0; i < strip.size(); ++i) {
    if (strip[i] == -1) start = i + 1;
    if (strip[i] == -1 || i < start + 2) continue;
    long long a = strip[i - 2], b = strip[i - 1];
    const long long c = strip[i];
    if ((i - start) % 2 == 1) std::swap(a, b);
    if (a == b || b == c || a == c) continue;
    raw.indices.insert(raw.indices.end(), {a, b, c});
    raw.endPolygon();
  }
}

RawMesh readPly(const std::string& path, std::string_view text) {
  const PlyHeader header = readPlyHeader(path, text);
  const PlyElement* vertexElement = header.find("vertex");
  if (!vertexElement) fail(path, "bad header: no 'vertex' element");
  const PlyProperty* xyz[3] = {vertexElement->find("x"), vertexElement->find("y"), vertexElement->find("z")};
  for (int c = 0; c < 3; ++c) {
    if (!xyz[c] || xyz[c]->isList) fail(path, std::string("bad header: the vertex element has no '") + "xyz"[c] + "' property");
  }
  const PlyElement *faceElement = header.find("face"), *stripElement = header.find("tristrips");
  if (!faceElement && !stripElement)
    fail(path, "the mesh has no faces (the header declares no 'face' or 'tristrips' element)");
  // Strips without indices beside faces (another program's own element) are no matter.
  const bool stripsIndexed = stripElement && (stripElement->find("vertex_indices") || stripElement->find("vertex_index"));
  const PlyProperty *indexProperty = indexList(path, faceElement),
                    *stripProperty = stripsIndexed || !faceElement ? indexList(path, stripElement) : nullptr;

  const std::string_view body = text.substr(header.bodyStart);
  RawMesh raw;
  reservePoints(raw, vertexElement->count, body.size(), vertexElement->properties.size());
  PlyValues values(path, body, header.format, header.bodyLine);
  // The first row that a value follows on its line: where the body stops matching its header,
  // said with the error that follows from it ("line 29: '1.0' is not an integer" named the
  // face that read a vertex's extra column, not the vertex).
  std::string longRow;
  std::vector<long long> strip;
  try {
    for (const PlyElement& element : header.elements) {
      const bool isVertex = &element == vertexElement;
      for (long long i = 0; i < element.count; ++i) {
        const auto truncated = [&] {
          fail(path, "file is truncated: it ends inside " + element.name + " " + str(i) + " of " + str(element.count));
        };
        Vec3 point = Vec3::Zero();
        for (const PlyProperty& property : element.properties) {
          double value = 0;
          if (!values.read(property.isList ? property.countType : property.type, value)) truncated();
          if (!property.isList) {
            for (int c = 0; c < 3; ++c) {
              if (isVertex && &property == xyz[c]) point[c] = value;
            }
            continue;
          }
          if (value < 0) fail(path, element.name + " " + str(i) + " has a list of negative length");
          // Every item takes at least one byte: refuse a length the remaining data cannot hold.
          if (value > static_cast<double>(values.remaining())) truncated();
          const bool isFace = &property == indexProperty, isStrip = &property == stripProperty;
          const bool isIndexList = isFace || isStrip;
          strip.clear();
          for (long long k = 0; k < static_cast<long long>(value); ++k) {
            double item = 0;
            if (!values.read(property.type, item)) truncated();
            if (!isIndexList) continue;
            // Past long long's range the cast is undefined (9223372036854775807 read back as
            // -9223372036854775808); no mesh reaches 2^62 vertices anyway.
            if (!(std::abs(item) < 0x1p62))
              fail(path, element.name + " " + str(i) + " has a vertex index past any mesh's size");
            (isFace ? raw.indices : strip).push_back(static_cast<long long>(item));
          }
          if (isFace) raw.endPolygon();
          if (isStrip) addStrip(strip, raw);
        }
        if (isVertex) raw.points.push_back(point);
        if (longRow.empty() && values.moreOnThisLine())
          longRow = "line " + str(values.line()) + " (" + element.name + " " + str(i) +
                    ") holds more values than the header declares for a " + element.name;
      }
    }
    if (!onlySpace(values.rest())) fail(path, "the file has more data than its header declares");
  } catch (const Error& e) {
    if (longRow.empty()) throw;
    throw Error(std::string(e.what()) + "; " + longRow);
  }
  return raw;
}

// -------------------------------------------------------------------------------------- checks

void checkHasFaces(long long faceCount, const std::string& name) {
  if (faceCount == 0) fail(name, "the mesh has no faces");
}

// Past this, squares overflow double precision and every length is infinite (a triangle of
// coordinates 1e308 read "face 0 has zero area"). Under the other, a cross product's squared
// length (a length to the fourth) underflows: at 1e-80 across a grid's smallest angle read 48.5
// degrees for 46.6, at 1e-100 "face 0 has zero area".
constexpr double kLargestMeasurableCoordinate = 1e150, kSmallestMeasurableSize = 1e-75;
// A shape this many times its size from the origin keeps two digits of its own at most: a unit
// grid 1e16 away read "face 0 has zero area".
constexpr double kFarthestMeasurable = 1e14;

void checkMeasurable(const std::vector<Vec3>& points, const std::string& name, int base) {
  for (size_t i = 0; i < points.size(); ++i) {
    if (!points[i].allFinite()) fail(name, "vertex " + str(i + base) + " has a non-finite coordinate");
    if (const double largest = points[i].cwiseAbs().maxCoeff(); largest > kLargestMeasurableCoordinate) {
      const auto asWritten = [](double x) {
        std::ostringstream text;
        text << x;
        return text.str();
      };
      fail(name, "vertex " + str(i + base) + " has a coordinate of " + asWritten(largest) +
                     ", too large to measure in double precision (lengths overflow past 1e+150; Lloydscope "
                     "takes coordinates up to " + asWritten(kLargestCoordinate) + "); scale the mesh down");
    }
  }
  const auto [lo, hi] = boundingBox(points);
  // stableNorm: the plain norm's square underflowed to 0 at 1e-170 across ("zero area").
  const double size = (hi - lo).stableNorm();
  if (size > 0 && size < kSmallestMeasurableSize) {
    std::ostringstream text;
    text << "the mesh is " << size << " across (its bounding box's diagonal), too small to measure in double "
         << "precision (lengths to the fourth underflow under " << kSmallestMeasurableSize
         << "; Lloydscope takes a diagonal of " << kSmallestDiagonal << " at least); scale it up";
    fail(name, text.str());
  }
  const double farthest = std::max(lo.cwiseAbs().maxCoeff(), hi.cwiseAbs().maxCoeff());
  if (size > 0 && farthest > kFarthestMeasurable * size) {
    std::ostringstream text;
    text << "the mesh lies " << farthest / size << " times its size (its bounding box's diagonal) from the origin: "
         << "double precision keeps too few digits of its shape (Lloydscope takes " << kFarthestPerSize
         << " times at most); move it nearer";
    fail(name, text.str());
  }
}

// A polygon that lists a vertex twice in a row, or ends where it started (a triangle written as
// the quad "a b c c" by an exporter of quads only; "a b c a"): its corners without those
// repeats, in `corners`. False, and `corners` left alone, where there are none.
bool withoutRepeatsInARow(const long long* v, size_t n, std::vector<long long>& corners) {
  const auto repeat = [&](size_t i) { return v[i] == v[(i + n - 1) % n]; };
  if (n < 2) return false;
  bool any = false;
  for (size_t i = 0; i < n && !any; ++i) any = repeat(i);
  if (!any) return false;
  corners.clear();
  for (size_t i = 0; i < n; ++i)
    if (!repeat(i)) corners.push_back(v[i]);
  return true;
}

// Size, index range and repeated vertices of one face, before any geometry is looked at. With
// `repeatsAllowed` (the repair drops such a face), a repeated vertex is returned, not refused;
// `fromFile`: the refusal says that the repair would drop it.
template <class Index>
bool checkFaceIndices(const Index* v, size_t n, long long face, size_t vertexCount, int base,
                      const std::string& name, bool repeatsAllowed = false, bool fromFile = false) {
  const std::string faceName = "face " + str(face + base);
  if (n < 3) fail(name, faceName + " has " + plural(n, "vertex", "vertices") + " (at least 3 are needed)");
  for (size_t i = 0; i < n; ++i) {
    if (v[i] < 0 || static_cast<unsigned long long>(v[i]) >= vertexCount) {
      fail(name, faceName + " uses vertex " + str(static_cast<long long>(v[i]) + base) + " but there are " +
                     plural(vertexCount, "vertex", "vertices"));
    }
  }
  const auto repeatedVertex = [&](long long v) {
    if (repeatsAllowed) return true;
    fail(name, faceName + " uses vertex " + str(v + base) + " twice" +
                   (fromFile ? " (--repair drops such faces, or reads a face that lists it twice in a row with it once)"
                             : ""));
  };
  if (n <= 8) {  // the usual case, without allocating
    for (size_t i = 0; i < n; ++i) {
      for (size_t j = i + 1; j < n; ++j) {
        if (v[i] == v[j]) return repeatedVertex(v[i]);
      }
    }
    return false;
  }
  std::vector<long long> sorted(v, v + n);
  std::sort(sorted.begin(), sorted.end());
  const auto repeated = std::adjacent_find(sorted.begin(), sorted.end());
  return repeated != sorted.end() && repeatedVertex(*repeated);
}

// Pairs of used vertices at exactly the same position, each pair once, in order of position.
std::vector<std::pair<int, int>> coincidentVertices(const Mesh& mesh) {
  std::vector<bool> isUsed(mesh.points.size(), false);
  for (const Triangle& t : mesh.triangles)
    for (int v : t) isUsed[v] = true;
  std::vector<int> used;
  for (int v = 0; v < mesh.vertexCount(); ++v)
    if (isUsed[v]) used.push_back(v);
  const auto byPosition = [&](int a, int b) {
    const Vec3 &p = mesh.points[a], &q = mesh.points[b];
    return std::tie(p.x(), p.y(), p.z(), a) < std::tie(q.x(), q.y(), q.z(), b);
  };
  std::sort(used.begin(), used.end(), byPosition);
  std::vector<std::pair<int, int>> pairs;
  for (size_t i = 1; i < used.size(); ++i)
    if (mesh.points[used[i - 1]] == mesh.points[used[i]]) pairs.emplace_back(used[i - 1], used[i]);
  return pairs;
}

// The zero-area message, naming two corners at the same position if the face has them.
std::string zeroAreaProblem(const Mesh& mesh, size_t t, const Numbering& numbering) {
  const Triangle& f = mesh.triangles[t];
  std::string problem = "face " + str(numbering.face(t)) + " has zero area";
  for (int k = 0; k < 3; ++k) {
    const int a = f[k], b = f[(k + 1) % 3];
    if (mesh.points[a] == mesh.points[b])
      return problem + ": its vertices " + str(numbering.vertex(std::min(a, b))) + " and " +
             str(numbering.vertex(std::max(a, b))) + " are at the same position";
  }
  return problem;
}

// One side of an edge as seen from a triangle.
struct HalfEdge {
  int lo, hi;         // the edge's vertices, lo < hi
  int triangle;
  bool forward;       // the triangle goes lo -> hi
};

// Whether the faces can be turned to agree across every edge: each face's turn follows from a
// neighbour's, and a Moebius strip's come back round turned the other way. `halfEdges` sorted
// by edge, each edge of two faces at most.
bool orientable(int faceCount, const std::vector<HalfEdge>& halfEdges) {
  std::vector<std::vector<std::pair<int, bool>>> across(faceCount);  // neighbour, and whether it must turn
  for (size_t i = 0; i + 1 < halfEdges.size(); ++i) {
    const HalfEdge &x = halfEdges[i], &y = halfEdges[i + 1];
    if (x.lo != y.lo || x.hi != y.hi) continue;
    across[x.triangle].emplace_back(y.triangle, x.forward == y.forward);
    across[y.triangle].emplace_back(x.triangle, x.forward == y.forward);
  }
  std::vector<int> turned(faceCount, -1);
  for (int start = 0; start < faceCount; ++start) {
    if (turned[start] >= 0) continue;
    turned[start] = 0;
    for (std::vector<int> stack = {start}; !stack.empty();) {
      const int f = stack.back();
      stack.pop_back();
      for (const auto& [g, turn] : across[f]) {
        const int wanted = turned[f] ^ static_cast<int>(turn);
        if (turned[g] < 0) {
          turned[g] = wanted;
          stack.push_back(g);
        } else if (turned[g] != wanted) {
          return false;
        }
      }
    }
  }
  return true;
}

// Every triangle's three half edges, sorted by edge.
std::vector<HalfEdge> sortedHalfEdges(const Mesh& mesh) {
  std::vector<HalfEdge> halfEdges;
  halfEdges.reserve(3 * mesh.triangles.size());
  for (int t = 0; t < mesh.faceCount(); ++t) {
    for (int k = 0; k < 3; ++k) {
      const int a = mesh.triangles[t][k], b = mesh.triangles[t][(k + 1) % 3];
      halfEdges.push_back({std::min(a, b), std::max(a, b), t, a < b});
    }
  }
  std::sort(halfEdges.begin(), halfEdges.end(), [](const HalfEdge& x, const HalfEdge& y) {
    return std::tie(x.lo, x.hi, x.triangle) < std::tie(y.lo, y.hi, y.triangle);
  });
  return halfEdges;
}

constexpr const char* kNotOrientable =
    "the surface is not orientable (a Moebius strip, say): no turning of its faces makes them agree across every edge";

void checkEdges(const Mesh& mesh, const std::string& name, const Numbering& numbering) {
  const std::vector<HalfEdge> halfEdges = sortedHalfEdges(mesh);
  const auto edgeName = [&](const HalfEdge& h) {
    return "edge " + str(numbering.vertex(h.lo)) + "-" + str(numbering.vertex(h.hi));
  };
  // Non-manifold edges first: an orientation is meaningless where three faces meet.
  for (size_t i = 0; i < halfEdges.size();) {
    size_t j = i;
    while (j < halfEdges.size() && halfEdges[j].lo == halfEdges[i].lo && halfEdges[j].hi == halfEdges[i].hi) ++j;
    if (j - i > 2) fail(name, edgeName(halfEdges[i]) + " is shared by " + str(j - i) + " faces");
    i = j;
  }
  for (size_t i = 0; i + 1 < halfEdges.size(); ++i) {
    const HalfEdge &x = halfEdges[i], &y = halfEdges[i + 1];
    if (x.lo == y.lo && x.hi == y.hi && x.forward == y.forward) {
      // No turning of faces mends a Moebius strip: its message said only that two faces disagree.
      if (!orientable(mesh.faceCount(), halfEdges)) fail(name, kNotOrientable);
      fail(name, "faces " + str(numbering.face(x.triangle)) + " and " + str(numbering.face(y.triangle)) +
                     " have opposite orientations across " + edgeName(x));
    }
  }
}

// Number of fans around one vertex, given the far edge b -> c of each incident triangle
// (v, b, c). With manifold, consistently oriented edges each b starts at most one far edge,
// so the fans are chains (open fans, walked from a start nobody points to) and cycles.
int countFans(std::vector<std::pair<int, int>>& farEdges) {
  std::sort(farEdges.begin(), farEdges.end());
  std::vector<int> targets;
  for (const auto& e : farEdges) targets.push_back(e.second);
  std::sort(targets.begin(), targets.end());

  std::vector<bool> walked(farEdges.size(), false);
  const auto edgeFrom = [&](int vertex) -> size_t {
    const auto it = std::lower_bound(farEdges.begin(), farEdges.end(), std::make_pair(vertex, INT_MIN));
    return (it != farEdges.end() && it->first == vertex) ? static_cast<size_t>(it - farEdges.begin()) : farEdges.size();
  };
  const auto walk = [&](size_t e) {
    while (e < farEdges.size() && !walked[e]) {
      walked[e] = true;
      e = edgeFrom(farEdges[e].second);
    }
  };
  int fans = 0;
  for (size_t e = 0; e < farEdges.size(); ++e) {
    if (!std::binary_search(targets.begin(), targets.end(), farEdges[e].first)) {
      ++fans;
      walk(e);
    }
  }
  for (size_t e = 0; e < farEdges.size(); ++e) {
    if (!walked[e]) {
      ++fans;
      walk(e);
    }
  }
  return fans;
}

void checkVertexFans(const Mesh& mesh, const std::string& name, const Numbering& numbering) {
  // Triangles around each vertex, in compressed rows.
  std::vector<int> start(mesh.points.size() + 1, 0);
  for (const Triangle& t : mesh.triangles) {
    for (int v : t) ++start[v + 1];
  }
  for (size_t v = 0; v < mesh.points.size(); ++v) start[v + 1] += start[v];
  std::vector<int> corners(start.back());
  std::vector<int> fill(start.begin(), start.end() - 1);
  for (int t = 0; t < mesh.faceCount(); ++t) {
    for (int k = 0; k < 3; ++k) corners[fill[mesh.triangles[t][k]]++] = 3 * t + k;
  }

  std::vector<std::pair<int, int>> farEdges;
  for (int v = 0; v < mesh.vertexCount(); ++v) {
    farEdges.clear();
    for (int i = start[v]; i < start[v + 1]; ++i) {
      const Triangle& t = mesh.triangles[corners[i] / 3];
      const int k = corners[i] % 3;
      farEdges.emplace_back(t[(k + 1) % 3], t[(k + 2) % 3]);
    }
    const int fans = countFans(farEdges);
    if (fans > 1) {
      fail(name, "vertex " + str(numbering.vertex(v)) + " is non-manifold (" +
                     (fans == 2 ? std::string("two") : str(fans)) + " fans of faces meet there)");
    }
  }
}

// Everything that needs positions and connectivity; indices are known to be valid. Returns
// the inside vertices it allowed at the same position (coincidentVertices()).
std::vector<std::pair<int, int>> checkSurface(const Mesh& mesh, const std::string& name,
                                              const Numbering& numbering) {
  // What a file holds was checked for faces as it was read; this is for what a repair left
  // (faces all of zero area, all collapsed away).
  if (mesh.triangles.empty()) fail(name, "no faces remain (all were dropped or of zero area)");
  // A face on two vertices at the same position has zero area: said as such first.
  for (size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Triangle& f = mesh.triangles[t];
    if (hasZeroArea(mesh.points[f[0]], mesh.points[f[1]], mesh.points[f[2]]))
      fail(name, zeroAreaProblem(mesh, t, numbering));
  }
  // Inside vertices at the same position are allowed: a surface may touch itself at a point
  // (CGAL's cow does once). On a border they are an unwelded seam, a crack, a triangle soup,
  // whose pieces would be remeshed apart, or a border that touches itself (two corners of it
  // at one point, or one vertex the repair split there, where fans of faces met): refused.
  const std::vector<bool> border = vertexEdges(mesh).onBoundary;
  const std::vector<std::pair<int, int>> coincident = coincidentVertices(mesh);
  for (const auto& [a, b] : coincident)
    if (border[a] || border[b])
      fail(name, "vertices " + str(numbering.vertex(a)) + " and " + str(numbering.vertex(b)) +
                     " are at the same position on a border (an unwelded seam, a crack, or the border "
                     "touching itself at a point)");
  checkEdges(mesh, name, numbering);
  checkVertexFans(mesh, name, numbering);
  return coincident;
}

// ------------------------------------------------------------------------------------- repair

// Repairs result.mesh, notes what changed, and numbers from 0 what it renumbered. Returns
// whether it changed the mesh.
bool repairInto(ReadResult& result, const std::string& path, Numbering& numbering) {
  RepairResult repaired = repairMesh(result.mesh);
  if (!repaired.changed()) return false;
  std::vector<std::string> changes;
  const int welded = repaired.weldedVertices;
  if (welded > 0) changes.push_back(plural(welded, "vertex", "vertices") + " welded to another at the same position");
  if (welded < 0) changes.push_back(plural(-welded, "vertex", "vertices") + " split where fans of faces only touched");
  if (repaired.droppedFaces > 0)
    changes.push_back(plural(repaired.droppedFaces, "face", "faces") + " with a corner or a face repeated dropped");
  if (repaired.degenerateFaces > 0)
    changes.push_back(plural(repaired.degenerateFaces, "face", "faces") + " of zero area collapsed or flipped away");
  if (repaired.turnedFaces > 0)
    changes.push_back(plural(repaired.turnedFaces, "face", "faces") + " turned to match " +
                      (repaired.turnedFaces == 1 ? "its" : "their") + " neighbours");
  std::string note = path + ": repaired: ";
  for (size_t i = 0; i < changes.size(); ++i) note += (i > 0 ? "; " : "") + changes[i];
  result.notes.push_back(note);
  result.mesh = std::move(repaired.mesh);
  numbering = Numbering{};  // the file's numbers no longer apply
  return true;
}

// checkSurface() on what was read. What it refuses is repaired if `repair` asks, checked again
// and refused only if still wrong; else the message says whether the repair would fix it.
std::vector<std::pair<int, int>> checkOrRepair(ReadResult& result, const std::string& path, Numbering& numbering,
                                               bool repair) {
  try {
    return checkSurface(result.mesh, path, numbering);
  } catch (const Error& e) {
    if (repair) {
      const Mesh before = result.mesh;
      const bool renumbered = repairInto(result, path, numbering);
      try {
        return checkSurface(result.mesh, path, numbering);
      } catch (const Error& left) {
        // No turning of faces mends a Moebius strip: the repair cut it open, and the cut's two
        // sides were refused as "vertices 61 and 150 at the same position", of a file of 120.
        if (!orientable(before.faceCount(), sortedHalfEdges(before)))
          fail(path, std::string(kNotOrientable) + ", which the repair cannot mend");
        // A vertex the repair split has a number the file does not.
        throw Error(std::string(left.what()) + " (left after the repair" +
                    (renumbered && !result.mesh.triangles.empty() ? ", which numbered the vertices and faces anew, from 0)"
                                                                  : ")"));
      }
    }
    try {
      checkSurface(repairMesh(result.mesh).mesh, path, Numbering{});
    } catch (const Error&) {
      throw e;
    }
    throw Error(std::string(e.what()) + " (--repair fixes this)");
  }
}

// ------------------------------------------------------------------------------ triangulation

// Splits polygon v[0..n) by ear clipping in the plane of its `normal`, for a polygon no fan from
// a corner splits (concave: an L, a C, a spiral). False where no ear is left to clip: the
// polygon crosses itself. Quadratic or worse in n: kMostClippedCorners at most.
constexpr size_t kMostClippedCorners = 1000;  // a 1000-gon: 0.1 s

bool clipEars(const long long* v, size_t n, const std::vector<Vec3>& points, const Vec3& normal,
              std::vector<Triangle>& out) {
  const auto p = [&](size_t i) -> const Vec3& { return points[v[i]]; };
  const auto turn = [&](size_t a, size_t b, size_t c) { return (p(b) - p(a)).cross(p(c) - p(a)).dot(normal); };
  std::vector<size_t> prev(n), next(n);
  for (size_t i = 0; i < n; ++i) prev[i] = (i + n - 1) % n, next[i] = (i + 1) % n;
  // An ear: a convex corner whose triangle holds no other corner (on its sides included).
  const auto isEar = [&](size_t b) {
    const size_t a = prev[b], c = next[b];
    if (turn(a, b, c) <= 0) return false;
    for (size_t q = next[c]; q != a; q = next[q]) {
      if (p(q) == p(a) || p(q) == p(b) || p(q) == p(c)) continue;
      if (turn(a, b, q) >= 0 && turn(b, c, q) >= 0 && turn(c, a, q) >= 0) return false;
    }
    return true;
  };
  std::vector<Triangle> ears;
  size_t b = 0, left = n, tried = 0;
  const auto corner = [&](size_t i) { return static_cast<int>(v[i]); };
  while (left > 3) {
    if (!isEar(b)) {
      b = next[b];
      if (++tried > left) return false;
      continue;
    }
    ears.push_back({corner(prev[b]), corner(b), corner(next[b])});
    next[prev[b]] = next[b];
    prev[next[b]] = prev[b];
    b = prev[b];
    --left;
    tried = 0;
  }
  if (turn(prev[b], b, next[b]) <= 0) return false;
  ears.push_back({corner(prev[b]), corner(b), corner(next[b])});
  out.insert(out.end(), ears.begin(), ears.end());
  return true;
}

// Splits polygon v[0..n) into a fan from the corner that makes its smallest triangle largest
// (areas signed along the polygon's Newell normal). Any fan of a strictly convex polygon is
// fine, but corners on a straight side need the right start; star-shaped polygons get a fan
// from their kernel when one of their corners is in it, other polygons are clipped ear by ear
// (a spiral's best fan turned three triangles over, a C's had one of zero area). Returns what
// is wrong with a polygon it cannot split ("" where it could).
std::string triangulatePolygon(const long long* v, size_t n, const std::vector<Vec3>& points,
                               std::vector<Triangle>& out) {
  if (n == 3) {  // keep triangles exactly as the file has them
    out.push_back({static_cast<int>(v[0]), static_cast<int>(v[1]), static_cast<int>(v[2])});
    return "";
  }
  const auto p = [&](size_t i) -> const Vec3& { return points[v[i % n]]; };
  Vec3 normal = Vec3::Zero(), centre = Vec3::Zero();
  for (size_t i = 0; i < n; ++i) {
    normal += p(i).cross(p(i + 1));
    centre += p(i) / static_cast<double>(n);
  }
  // A bow tie's two halves cancel in its normal; corners all on a line span nothing (their fan
  // is refused after reading for its zero area).
  double spanned = 0;
  for (size_t i = 0; i < n; ++i) spanned += (p(i) - centre).cross(p(i + 1) - centre).norm();
  const std::string crosses = "is a polygon that crosses itself (no split of it into triangles keeps them all "
                              "facing one way)";
  if (spanned > 0 && normal.norm() <= 1e-12 * spanned) return crosses;

  // Trying every start is quadratic; huge polygons only try a few hundred evenly spaced ones.
  const size_t step = std::max<size_t>(1, n / 256);
  size_t bestStart = 0;
  double bestSmallest = -std::numeric_limits<double>::infinity();
  for (size_t s = 0; s < n; s += step) {
    double smallest = std::numeric_limits<double>::infinity();
    for (size_t i = 1; i + 1 < n && smallest > bestSmallest; ++i) {
      smallest = std::min(smallest, (p(s + i) - p(s)).cross(p(s + i + 1) - p(s)).dot(normal));
    }
    if (smallest > bestSmallest) {
      bestSmallest = smallest;
      bestStart = s;
    }
  }
  // Ear clipping where no fan will do; a fan with a triangle of zero area (corners on a line)
  // is refused as such by the checks after reading.
  if (bestSmallest <= 0 && n <= kMostClippedCorners && clipEars(v, n, points, normal, out)) return "";
  if (bestSmallest < 0)
    return n <= kMostClippedCorners ? crosses
                                    : "is a concave polygon of " + str(n) + " corners, more than are split here (" +
                                          str(kMostClippedCorners) + "): split it into triangles first";
  for (size_t i = 1; i + 1 < n; ++i) {
    out.push_back({static_cast<int>(v[bestStart]), static_cast<int>(v[(bestStart + i) % n]),
                   static_cast<int>(v[(bestStart + i + 1) % n])});
  }
  return "";
}

// ------------------------------------------------------------------------------ file handling

// Before its name is looked at: a missing file or a folder without an extension ("remesh d")
// was said to have no extension.
void requireFileThere(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (ec && ec != std::errc::no_such_file_or_directory) fail(path, "cannot access the file (" + ec.message() + ")");
  if (!fs::exists(status)) fail(path, "no such file");
  if (fs::is_directory(status)) fail(path, "is a directory, not a mesh file");
}

// `path` as read whole; readMesh has made sure it is there and a file.
std::string loadFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(path, std::string("cannot read the file (") + std::strerror(errno) + ")");
  std::string data = readWhole(in, path, kLargestMeshFile, "a mesh file");
  // A UTF-8 byte order mark (some editors write one) is not part of the first line: an OBJ's
  // first vertex was lost with it, an OFF's header refused.
  if (data.rfind("\xEF\xBB\xBF", 0) == 0) data.erase(0, 3);
  // Lines ended by CR alone (classic Mac OS) are lines: an OBJ written so was one line, a
  // comment, and refused as "the mesh has no faces". So they were where the file had no LF;
  // one LF at its end made it one line again. Only in text: a binary file's numbers hold zero
  // bytes (a face's count, 3, as 4 bytes), and its bytes 13 were coordinates and indices,
  // changed without a word. CRs before an LF are no line ends: CR CR LF (a CRLF file converted
  // twice) was two, and messages counted lines twice; CR CR alone is two (a blank line).
  if (data.find('\0') == std::string::npos)
    for (size_t i = 0, end; i < data.size(); i = end) {
      end = i + 1;
      if (data[i] != '\r') continue;
      while (end < data.size() && data[end] == '\r') ++end;
      if (end == data.size() || data[end] != '\n') std::fill(data.begin() + i, data.begin() + end, '\n');
    }
  if (onlySpace(data)) fail(path, "the file is empty");
  return data;
}

void writeOff(std::ostream& out, const Mesh& mesh) {
  out << "OFF\n" << mesh.vertexCount() << ' ' << mesh.faceCount() << " 0\n";
  for (const Vec3& p : mesh.points) out << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
  for (const Triangle& t : mesh.triangles) out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
}

void writeObj(std::ostream& out, const Mesh& mesh) {
  for (const Vec3& p : mesh.points) out << "v " << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
  for (const Triangle& t : mesh.triangles) {
    out << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
  }
}

void writePly(std::ostream& out, const Mesh& mesh) {
  out << "ply\nformat ascii 1.0\n"
      << "element vertex " << mesh.vertexCount() << "\n"
      << "property double x\nproperty double y\nproperty double z\n"
      << "element face " << mesh.faceCount() << "\n"
      << "property list uchar int vertex_indices\nend_header\n";
  for (const Vec3& p : mesh.points) out << p.x() << ' ' << p.y() << ' ' << p.z() << '\n';
  for (const Triangle& t : mesh.triangles) out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
}

}  // namespace

// ------------------------------------------------------------------------------------ public API

void validateMesh(const Mesh& mesh, const std::string& name) {
  checkHasFaces(mesh.faceCount(), name);
  checkMeasurable(mesh.points, name, 0);
  std::vector<bool> used(mesh.points.size(), false);
  for (int f = 0; f < mesh.faceCount(); ++f) {
    checkFaceIndices(mesh.triangles[f].data(), 3, f, mesh.points.size(), 0, name);
    for (int v : mesh.triangles[f]) used[v] = true;
  }
  const auto unused = std::find(used.begin(), used.end(), false);
  if (unused != used.end()) fail(name, "vertex " + str(unused - used.begin()) + " is not used by any face");
  checkSurface(mesh, name, Numbering{});
}

// The extension a file's first word says it should have: ".ply" for "ply", ".off" for an OFF
// header (OFF, COFF, NOFF, STOFF, 4OFF ...), else "" (an OBJ starts with anything).
std::string extensionByContent(std::string_view text) {
  const size_t start = std::find_if_not(text.begin(), text.end(), isSpace) - text.begin();
  std::string_view word = text.substr(start, std::find_if(text.begin() + start, text.end(), isSpace) - text.begin() - start);
  while (!word.empty() && word.back() >= '0' && word.back() <= '9') word.remove_suffix(1);  // OFF500: a count against it
  if (word == "ply") return ".ply";
  const bool off = word.size() >= 3 && word.size() <= 8 && word.substr(word.size() - 3) == "OFF";
  return off ? ".off" : "";
}

bool isMeshExtension(const std::string& ext) { return ext == ".off" || ext == ".obj" || ext == ".ply"; }

void requireNoMeshExtension(const std::string& path, const std::string& what, const std::string& suggested) {
  // The name, and where it leads: run.lsrec, a link to mine.off, replaced the mesh.
  for (const std::string& name : {path, targetOf(path).string()}) {
    const std::string ext = lowercaseExtension(name);
    if (isMeshExtension(ext))
      throw Error(path + ": " + what + " is not saved under a mesh's extension (" + ext +
                  (name == path ? "" : ", through a link") + "): it would replace a mesh with what no mesh reader reads; name it " +
                  suggested);
  }
}

ReadResult readMesh(const std::string& path, const ReadOptions& options) {
  requireFileThere(path);
  const std::string ext = lowercaseExtension(path);
  // A recording given where a mesh goes: `remesh run.lsrec` is a natural first try.
  if (ext == ".lsrec") fail(path, "a recording, not a mesh (.off, .obj or .ply): lloydscope inspect or info opens it");
  if (!isMeshExtension(ext)) fail(path, unknownExtension(path));
  const std::string text = loadFile(path);
  // An OFF named .obj was refused as "the mesh has no faces", which named nothing wrong.
  if (const std::string says = extensionByContent(text); !says.empty() && says != ext)
    fail(path, "its first word is that of a" + std::string(says == ".off" ? "n OFF" : " PLY") +
                   " file, not of a" + (ext == ".obj" ? "n OBJ" : ext == ".off" ? "n OFF" : " PLY") +
                   " one: rename it " + says);
  const RawMesh raw = ext == ".off" ? readOff(path, text) : ext == ".obj" ? readObj(path, text) : readPly(path, text);

  checkHasFaces(raw.polygonCount(), path);
  checkMeasurable(raw.points, path, raw.base);
  ReadResult result;
  result.mesh.points = raw.points;
  std::vector<long long> faceOfTriangle;
  int polygons = 0, repeating = 0, shortened = 0;
  std::vector<long long> corners;  // a polygon without its repeats in a row, where the repair reads it so
  for (long long f = 0; f < raw.polygonCount(); ++f) {
    const long long* v = raw.indices.data() + raw.polygonStart[f];
    size_t n = raw.polygonStart[f + 1] - raw.polygonStart[f];
    if (options.repair && withoutRepeatsInARow(v, n, corners)) {
      if (corners.size() < 3) {  // "a b b": no face left
        ++repeating;
        continue;
      }
      ++shortened;
      v = corners.data();
      n = corners.size();
    }
    if (checkFaceIndices(v, n, f, raw.points.size(), raw.base, path, options.repair, /*fromFile=*/true)) {
      ++repeating;
      continue;
    }
    if (n > 3) ++polygons;
    if (const std::string problem = triangulatePolygon(v, n, raw.points, result.mesh.triangles); !problem.empty())
      fail(path, "face " + str(f + raw.base) + " " + problem);
    faceOfTriangle.resize(result.mesh.triangles.size(), f);
  }
  if (shortened > 0)
    result.notes.push_back(path + ": repaired: " + plural(shortened, "face", "faces") +
                           " listing a vertex twice in a row read with it once");
  if (repeating > 0)
    result.notes.push_back(path + ": repaired: " + plural(repeating, "face", "faces") + " using a vertex twice dropped");
  checkHasFaces(result.mesh.faceCount(), path);
  Numbering numbering{raw.base, &faceOfTriangle};
  const auto coincident = checkOrRepair(result, path, numbering, options.repair);

  if (polygons > 0) {
    result.notes.push_back(path + ": " + plural(polygons, "polygon", "polygons") + " with more than 3 vertices " +
                           (polygons == 1 ? "was" : "were") + " triangulated");
  }
  if (!coincident.empty()) {
    const std::string first = str(numbering.vertex(coincident[0].first)) + " and " +
                              str(numbering.vertex(coincident[0].second));
    result.notes.push_back(
        path + ": " +
        (coincident.size() == 1 ? "vertices " + first + " are"
                                : plural(static_cast<int>(coincident.size()), "pair", "pairs") +
                                      " of vertices (the first: " + first + ") are") +
        " at the same position, each with its own faces inside the surface: it touches itself there");
  }
  const int read = result.mesh.vertexCount();
  result.mesh = assemble(result.mesh.triangles, result.mesh.points);
  const int removed = read - result.mesh.vertexCount();
  if (removed > 0) {
    result.notes.push_back(path + ": " + plural(removed, "vertex", "vertices") + " used by no face " +
                           (removed == 1 ? "was" : "were") + " removed");
  }
  return result;
}

namespace {
void requireWritableExtension(const std::string& ext, const std::string& path) {
  if (!isMeshExtension(ext)) fail(path, "cannot write: " + unknownExtension(path));
}
}  // namespace

void requireMeshWritable(const std::string& path) {
  requireFileName(path);  // a folder is said to be one, not to have no extension
  requireWritableExtension(lowercaseExtension(path), path);
  requireWritable(path);  // last: the refusals above say more
}

void writeMesh(const Mesh& mesh, const std::string& path) {
  FileBatch batch;
  writeMesh(mesh, path, batch);
  batch.commit();
}

void writeMesh(const Mesh& mesh, const std::string& path, FileBatch& batch) {
  const std::string ext = lowercaseExtension(path);
  requireWritableExtension(ext, path);
  batch.add(path, [&](std::ostream& out) {
    out.imbue(std::locale::classic());  // a decimal point, whatever the global locale says
    out << std::setprecision(17);       // enough digits to read back the same doubles
    if (ext == ".off") writeOff(out, mesh);
    else if (ext == ".obj") writeObj(out, mesh);
    else writePly(out, mesh);
  });
}

}  // namespace lloydscope
