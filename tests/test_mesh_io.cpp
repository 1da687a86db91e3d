// Reading, validating and writing meshes: one test per kind of bad input, round trips for every
// format, and a crude fuzz test (random bytes and cut-off files must give an Error, not a crash).

#include "mesh_io.h"
#include "test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

namespace lloydscope {
namespace {

namespace fs = std::filesystem;
using test::tempPath;

std::string writeFile(const std::string& name, const std::string& content) {
  const std::string path = tempPath(name);
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << content;
  return path;
}

// The message of the Error readMesh() throws, or "" when it throws none.
std::string readError(const std::string& path) {
  try {
    readMesh(path);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

// Reading `path` fails with a one-line message that starts with the path and contains `word`.
void expectReadError(const std::string& path, const std::string& word) {
  const std::string message = readError(path);
  ASSERT_FALSE(message.empty()) << "no error for " << path;
  EXPECT_EQ(message.rfind(path + ": ", 0), 0u) << message;
  EXPECT_NE(message.find(word), std::string::npos) << "'" << word << "' missing from: " << message;
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

void expectFileError(const std::string& name, const std::string& content, const std::string& word) {
  SCOPED_TRACE(name);
  expectReadError(writeFile(name, content), word);
}

std::string validateError(const Mesh& mesh) {
  try {
    validateMesh(mesh, "mesh");
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

// Binary encoders for the hand-written binary files.
template <class T>
void append(std::string& out, T value, bool bigEndian) {
  unsigned char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  const std::uint16_t one = 1;
  const bool hostLittle = *reinterpret_cast<const unsigned char*>(&one) == 1;
  if (bigEndian == hostLittle) std::reverse(bytes, bytes + sizeof(T));
  out.append(reinterpret_cast<const char*>(bytes), sizeof(T));
}

// A unit square of two triangles (ASCII OFF), the smallest valid input.
const char* const kSquareOff =
    "OFF\n"
    "4 2 0\n"
    "0 0 0\n"
    "1 0 0\n"
    "1 1 0\n"
    "0 1 0\n"
    "3 0 1 2\n"
    "3 0 2 3\n";

std::string binaryOffSquare() {
  std::string data = "OFF BINARY\n";
  for (std::int32_t count : {4, 2, 0}) append(data, count, true);
  const float xyz[4][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  for (const auto& p : xyz) {
    for (float c : p) append(data, c, true);
  }
  const std::int32_t faces[2][3] = {{0, 1, 2}, {0, 2, 3}};
  for (const auto& f : faces) {
    append<std::int32_t>(data, 3, true);
    for (std::int32_t v : f) append(data, v, true);
    append<std::int32_t>(data, 0, true);  // no colour
  }
  return data;
}

// Little- or big-endian PLY with extra vertex properties of several types, a second list in the
// face element and an extra element, all of which must be skipped by their type sizes.
std::string binaryPlySquare(bool bigEndian) {
  std::string data = std::string("ply\nformat ") + (bigEndian ? "binary_big_endian" : "binary_little_endian") +
                     " 1.0\n"
                     "comment written by hand\n"
                     "element vertex 4\n"
                     "property uchar flags\n"
                     "property double x\n"
                     "property double y\n"
                     "property float z\n"
                     "property short label\n"
                     "property list uchar float weights\n"
                     "element face 2\n"
                     "property list int uint vertex_index\n"
                     "property list uchar float texcoord\n"
                     "element edge 1\n"
                     "property int vertex1\n"
                     "property int vertex2\n"
                     "end_header\n";
  const double xyz[4][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0.25}};
  for (const auto& p : xyz) {
    append<std::uint8_t>(data, 7, bigEndian);
    append<double>(data, p[0], bigEndian);
    append<double>(data, p[1], bigEndian);
    append<float>(data, static_cast<float>(p[2]), bigEndian);
    append<std::int16_t>(data, -3, bigEndian);
    append<std::uint8_t>(data, 2, bigEndian);
    append<float>(data, 0.5f, bigEndian);
    append<float>(data, 1.5f, bigEndian);
  }
  const std::uint32_t faces[2][3] = {{0, 1, 2}, {0, 2, 3}};
  for (const auto& f : faces) {
    append<std::int32_t>(data, 3, bigEndian);
    for (std::uint32_t v : f) append(data, v, bigEndian);
    append<std::uint8_t>(data, 6, bigEndian);
    for (int k = 0; k < 6; ++k) append<float>(data, 0.0f, bigEndian);
  }
  append<std::int32_t>(data, 0, bigEndian);
  append<std::int32_t>(data, 1, bigEndian);
  return data;
}

void expectUnitSquare(const Mesh& mesh, double lastZ = 0.0) {
  ASSERT_EQ(mesh.vertexCount(), 4);
  ASSERT_EQ(mesh.faceCount(), 2);
  EXPECT_EQ(mesh.points[2], Vec3(1, 1, 0));
  EXPECT_EQ(mesh.points[3], Vec3(0, 1, lastZ));
  EXPECT_EQ(mesh.triangles[0], (Triangle{0, 1, 2}));
  EXPECT_EQ(mesh.triangles[1], (Triangle{0, 2, 3}));
}

// Coordinates that only survive a round trip with all 17 significant digits.
Mesh awkwardMesh() {
  Mesh mesh;
  mesh.points = {{0.1, 1.0 / 3.0, -2.0 / 7.0}, {1e-300 + 1.0, 0.2, 3.14159265358979}, {0.7, 1e10 / 3.0, 0.3},
                 {-5.5, 0.123456789012345678, 1.0 / 9.0}};
  mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  return mesh;
}

// ----------------------------------------------------------------------------- valid inputs

TEST(MeshIo, ReadsAsciiOffWithCommentsAndColours) {
  const std::string path = writeFile("comments.off",
                                     "# a comment before the header\n"
                                     "OFF # keyword\n"
                                     "\n"
                                     "# counts next\n"
                                     "4 2 5\n"
                                     "0 0 0\n"
                                     "1 0 0   # a vertex\n"
                                     "1 1 0\n"
                                     "0 1 0\r\n"
                                     "3 0 1 2 255 0 0\n"
                                     "3 0 2 3\n"
                                     "\n# trailing comment\n");
  const ReadResult result = readMesh(path);
  expectUnitSquare(result.mesh);
  EXPECT_TRUE(result.notes.empty());
}

// Lines ended by CR alone (classic Mac OS): the OBJ was read as one line and refused as "the
// mesh has no faces".
TEST(MeshIo, ReadsLinesEndedByCarriageReturnsAlone) {
  expectUnitSquare(readMesh(writeFile("mac.obj", "# square\rv 0 0 0\rv 1 0 0\rv 1 1 0\rv 0 1 0\rf 1 2 3\rf 1 3 4\r")).mesh);
  expectUnitSquare(readMesh(writeFile("mac.off", "OFF\r4 2 0\r0 0 0\r1 0 0\r1 1 0\r0 1 0\r3 0 1 2\r3 0 2 3\r")).mesh);
  // CR CR LF (a CRLF file converted twice) ends a line once: messages counted lines twice.
  expectReadError(writeFile("crcrlf.off", "OFF\r\r\n3 1 0\r\r\n0 0 0\r\r\n1 x 0\r\r\n0 1 0\r\r\n3 0 1 2\r\r\n"),
                  "line 4: 'x' is not a number");
  // But CR CR alone is two line ends, a blank line between: it was one.
  expectReadError(writeFile("mac_blank.off", "OFF\r\r3 1 0\r0 0 0\r1 x 0\r0 1 0\r3 0 1 2\r"), "line 5: 'x' is not a number");
  // So they are where one LF ends the file, or its first line: both read as the lines between.
  expectUnitSquare(readMesh(writeFile("mac_lf.obj", "v 0 0 0\rv 1 0 0\rv 1 1 0\rv 0 1 0\rf 1 2 3\rf 1 3 4\n")).mesh);
  expectUnitSquare(readMesh(writeFile("lf_mac.off", "OFF\n4 2 0\r0 0 0\r1 0 0\r1 1 0\r0 1 0\r3 0 1 2\r3 0 2 3\r")).mesh);
}

// A binary PLY whose header ends its lines in CR alone: its bytes 13 were read as line ends
// and made 10, and a square of side 13 came out of side 10 and 13, without a word.
std::string binaryPlyOfSide13(const std::string& lineEnd) {
  std::string data;
  for (const char* line : {"ply", "format binary_little_endian 1.0", "element vertex 4", "property uchar x",
                           "property uchar y", "property uchar z", "element face 2",
                           "property list uchar int vertex_indices", "end_header"})
    data += line + lineEnd;
  for (const std::array<std::uint8_t, 3>& p : {std::array<std::uint8_t, 3>{0, 0, 0}, {13, 0, 0}, {13, 13, 0}, {0, 13, 0}})
    for (std::uint8_t c : p) append(data, c, false);
  for (const std::array<std::int32_t, 3>& f : {std::array<std::int32_t, 3>{0, 1, 2}, {0, 2, 3}}) {
    append<std::uint8_t>(data, 3, false);
    for (std::int32_t v : f) append(data, v, false);
  }
  return data;
}

TEST(MeshIo, BinaryBytesAreNeverReadAsLineEnds) {
  for (const std::string& lineEnd : {std::string("\n"), std::string("\r\n")}) {
    const Mesh mesh = readMesh(writeFile("side13.ply", binaryPlyOfSide13(lineEnd))).mesh;
    ASSERT_EQ(mesh.vertexCount(), 4);
    EXPECT_EQ(mesh.points[2], Vec3(13, 13, 0));
  }
  expectReadError(writeFile("side13_cr.ply", binaryPlyOfSide13("\r")), "lines end in CR alone");
  // A binary OFF's header likewise (it was read as one line, and said to be cut short).
  std::string offWithCr = binaryOffSquare();
  offWithCr[offWithCr.find('\n')] = '\r';
  expectReadError(writeFile("square_cr.off", offWithCr), "lines end in CR alone");
  offWithCr.insert(offWithCr.find('\r') + 1, "\n");  // CR LF
  expectUnitSquare(readMesh(writeFile("square_crlf.off", offWithCr)).mesh);
}

TEST(MeshIo, ReadsOffVariantsAndCountsOnTheKeywordLine) {
  expectUnitSquare(readMesh(writeFile("counts.off", "OFF 4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3"))
                       .mesh);
  // The vertex count against the keyword, as in ModelNet40's files: it was "bad header".
  expectUnitSquare(readMesh(writeFile("glued.off", "OFF4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3"))
                       .mesh);
  // Free format, as Geomview reads it: two vertices on a line, a face's colour after its
  // indices. It was "file is truncated" (the faces read as vertices).
  expectUnitSquare(readMesh(writeFile("free.off", "OFF\n4 2 0\n0 0 0  1 0 0\n1 1 0  0 1 0\n3 0 1 2 1 0 0\n3 0 2 3\n"))
                       .mesh);
  // But a vertex line a number short is damage, not a vertex over two lines: with integer
  // coordinates and face colours, free format read it as another mesh, without a word.
  expectReadError(writeFile("short.off", "OFF\n4 2 0\n0 0 0\n1 0\n1 1 0\n0 1 0\n3 3 1 2 0 0 0\n3 0 2 3 0 0 0\n"),
                  "line 4: vertex 1 has 2 coordinates (expected 3)");
  // Nor is a face line one index short a face over two lines (it took the next line's first).
  expectReadError(writeFile("short_face.off", "OFF\n4 2 0\n0 0 0  1 0 0\n1 1 0  0 1 0\n3 0 1\n3 0 2 3\n3 1 2 3\n"),
                  "file is truncated");
  // Its first word is an OFF file's, the count against it: named .obj, it is said so.
  expectReadError(writeFile("glued_off.obj", "OFF4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n"),
                  "its first word is that of an OFF");
  expectUnitSquare(readMesh(writeFile("colours.COFF.off",
                                      "COFF\n4 2 0\n0 0 0 1 0 0 1\n1 0 0 1 0 0 1\n1 1 0 1 0 0 1\n"
                                      "0 1 0 1 0 0 1\n3 0 1 2\n3 0 2 3\n"))
                       .mesh);
}

TEST(MeshIo, ReadsHandWrittenBinaryOff) {
  const ReadResult result = readMesh(writeFile("square_binary.off", binaryOffSquare()));
  expectUnitSquare(result.mesh);
}

TEST(MeshIo, ReadsObjWithSlashesNegativeIndicesAndQuads) {
  const std::string path = writeFile("quads.obj",
                                     "# two quads side by side\n"
                                     "mtllib none.mtl\n"
                                     "o grid\n"
                                     "v 0 0 0\nv 1 0 0\nv 2 0 0\n"
                                     "v 0 1 0\nv 1 1 0\nv 2 1 0\n"
                                     "vt 0 0\nvn 0 0 1\n"
                                     "s off\n"
                                     "f 1/1/1 2/1/1 5/1/1 4/1/1\n"
                                     "f -5//1 -4//1 -1//1 -2//1\n");
  const ReadResult result = readMesh(path);
  EXPECT_EQ(result.mesh.vertexCount(), 6);
  EXPECT_EQ(result.mesh.faceCount(), 4);
  ASSERT_EQ(result.notes.size(), 1u);
  EXPECT_EQ(result.notes[0], path + ": 2 polygons with more than 3 vertices were triangulated");
  // All triangles keep the quads' counter-clockwise orientation.
  for (const Triangle& t : result.mesh.triangles) {
    const Vec3 n = (result.mesh.points[t[1]] - result.mesh.points[t[0]])
                       .cross(result.mesh.points[t[2]] - result.mesh.points[t[0]]);
    EXPECT_GT(n.z(), 0.0);
  }
}

// Some editors start a text file with a UTF-8 byte order mark: an OBJ lost its first vertex
// to it (its faces then pointed one past the end), an OFF's header was refused.
// A line that ends in a backslash goes on on the next (the OBJ format's rule, which Blender
// reads): "f 1 2 \" was refused as "'\' is not a vertex index".
TEST(MeshIo, AnObjLineEndingInABackslashGoesOn) {
  expectUnitSquare(
      readMesh(writeFile("continued.obj", "v 0 0 0\nv 1 0\\\r\n0\nv 1 1 0\nv 0 1 0\nf 1 2 \\\n  3 # a comment\nf 1\\\n3 4\\\n"))
          .mesh);
}

// Triangle strips (MeshLab writes them): "the mesh has no faces" where they were the faces.
TEST(MeshIo, ReadsPlyTriangleStrips) {
  const std::string header =
      "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
      "element tristrips 1\nproperty list int int vertex_indices\nend_header\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n";
  // One strip; two cut by -1; two joined by a repeated index. Every other triangle of a strip
  // turns the other way, so that both face up.
  // Beside faces, a strips element without indices (another program's own) is no matter.
  EXPECT_EQ(readMesh(writeFile("flags.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                                            "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
                                            "element tristrips 1\nproperty int flags\nend_header\n0 0 0\n1 0 0\n0 1 0\n"
                                            "3 0 1 2\n7\n"))
                .mesh.faceCount(),
            1);
  for (const char* strip : {"4 1 2 0 3", "7 1 2 0 -1 0 2 3", "7 1 2 0 0 0 2 3"}) {
    SCOPED_TRACE(strip);
    const Mesh mesh = readMesh(writeFile("strips.ply", header + strip + "\n")).mesh;
    ASSERT_EQ(mesh.vertexCount(), 4);
    ASSERT_EQ(mesh.faceCount(), 2);
    for (const Triangle& t : mesh.triangles)
      EXPECT_GT((mesh.points[t[1]] - mesh.points[t[0]]).cross(mesh.points[t[2]] - mesh.points[t[0]]).z(), 0);
  }
}

TEST(MeshIo, AByteOrderMarkIsNotPartOfTheFirstLine) {
  const std::string bom = "\xEF\xBB\xBF";
  const std::string obj = writeFile("bom.obj", bom + "v 5 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 3\nf 2 4 3\n");
  const Mesh fromObj = readMesh(obj).mesh;
  ASSERT_EQ(fromObj.vertexCount(), 4);
  EXPECT_EQ(fromObj.points[0], Vec3(5, 0, 0));
  const std::string off = writeFile("bom.off", bom + "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  EXPECT_EQ(readMesh(off).mesh.faceCount(), 1);
}

TEST(MeshIo, ConvexPolygonWithStraightCornerGetsNoZeroAreaTriangle) {
  // Vertex 1 lies on the side from 0 to 2: a fan from vertex 0 would make triangle 0-1-2 flat.
  const std::string path = writeFile("pentagon.off", "OFF\n5 1 0\n0 0 0\n1 0 0\n2 0 0\n2 2 0\n0 2 0\n5 0 1 2 3 4\n");
  const ReadResult result = readMesh(path);
  EXPECT_EQ(result.mesh.faceCount(), 3);
  ASSERT_EQ(result.notes.size(), 1u);
  EXPECT_EQ(result.notes[0], path + ": 1 polygon with more than 3 vertices was triangulated");
}

// A concave polygon no fan from one of its corners splits is clipped ear by ear: a spiral's
// best fan turned three of its triangles over (their areas added to 14, not 10), a C's had one
// of zero area ("face 1 has zero area"). A polygon that crosses itself is refused by name.
TEST(MeshIo, AConcavePolygonIsSplitIntoTrianglesAllFacingOneWay) {
  const auto splitArea = [](const Mesh& m) {
    double signedArea = 0, unsignedArea = 0;
    for (const Triangle& t : m.triangles) {
      const double z = (m.points[t[1]] - m.points[t[0]]).cross(m.points[t[2]] - m.points[t[0]]).z() / 2;
      signedArea += z;
      unsignedArea += std::abs(z);
    }
    EXPECT_NEAR(signedArea, unsignedArea, 1e-12);  // all facing one way
    return signedArea;
  };
  const std::string spiral = writeFile(
      "spiral.obj", "v 0 0 0\nv 4 0 0\nv 4 4 0\nv 1 4 0\nv 1 2 0\nv 2 2 0\nv 2 3 0\nv 3 3 0\nv 3 1 0\nv 0 1 0\n"
                    "f 1 2 3 4 5 6 7 8 9 10\n");
  const Mesh spiralMesh = readMesh(spiral).mesh;
  EXPECT_EQ(spiralMesh.faceCount(), 8);
  EXPECT_NEAR(splitArea(spiralMesh), 10, 1e-12);
  const std::string c = writeFile("c.obj", "v 0 0 0\nv 3 0 0\nv 3 1 0\nv 1 1 0\nv 1 2 0\nv 3 2 0\nv 3 3 0\nv 0 3 0\n"
                                           "f 1 2 3 4 5 6 7 8\n");
  EXPECT_NEAR(splitArea(readMesh(c).mesh), 7, 1e-12);
  expectFileError("bowtie.obj", "v 0 0 0\nv 1 1 0\nv 1 0 0\nv 0 1 0\nf 1 2 3 4\n",
                  "face 1 is a polygon that crosses itself");
  expectFileError("crossing.obj", "v 0 0 0\nv 4 0 0\nv 4 4 0\nv 1 4 0\nv 3 -1 0\nf 1 2 3 4 5\n",
                  "face 1 is a polygon that crosses itself");
  // A concave polygon past what is clipped here: refused, not split into faces turned over.
  std::string star;
  const int corners = 1002;
  for (int i = 0; i < corners; ++i) {
    const double angle = 2 * M_PI * i / corners, radius = i % 2 ? 1.5 : 1.0;
    star += "v " + std::to_string(radius * std::cos(angle)) + " " + std::to_string(radius * std::sin(angle)) + " 0\n";
  }
  star += "f";
  for (int i = 1; i <= corners; ++i) star += " " + std::to_string(i);
  expectFileError("star.obj", star + "\n", "face 1 is a concave polygon of 1002 corners, more than are split here (1000)");
}

TEST(MeshIo, ReadsAsciiPlyWithExtraPropertiesAndElements) {
  const std::string path = writeFile("square_ascii.ply",
                                     "ply\n"
                                     "format ascii 1.0\n"
                                     "comment hand written\n"
                                     "element vertex 4\n"
                                     "property float x\n"
                                     "property uchar red\n"
                                     "property float y\n"
                                     "property double z\n"
                                     "element face 2\n"
                                     "property list uchar int vertex_indices\n"
                                     "property int flags\n"
                                     "element material 1\n"
                                     "property list int float values\n"
                                     "end_header\n"
                                     "0 255 0 0\n1 255 0 0\n1 255 1 0\n0 255 1 0.25\n"
                                     "3 0 1 2 9\n3 0 2 3 9\n"
                                     "2 0.5 0.75\n");
  expectUnitSquare(readMesh(path).mesh, 0.25);
}

TEST(MeshIo, ReadsBinaryLittleEndianPly) {
  expectUnitSquare(readMesh(writeFile("square_le.ply", binaryPlySquare(false))).mesh, 0.25);
}

TEST(MeshIo, ReadsBinaryBigEndianPly) {
  expectUnitSquare(readMesh(writeFile("square_be.ply", binaryPlySquare(true))).mesh, 0.25);
}

TEST(MeshIo, ExtensionIsCaseInsensitive) {
  expectUnitSquare(readMesh(writeFile("upper.OFF", kSquareOff)).mesh);
}

TEST(MeshIo, RemovesUnreferencedVerticesWithANote) {
  const std::string path =
      writeFile("unused.off", "OFF\n6 2 0\n9 9 9\n0 0 0\n1 0 0\n5 5 5\n1 1 0\n0 1 0\n3 1 2 4\n3 1 4 5\n");
  const ReadResult result = readMesh(path);
  expectUnitSquare(result.mesh);
  ASSERT_EQ(result.notes.size(), 1u);
  EXPECT_EQ(result.notes[0], path + ": 2 vertices used by no face were removed");
}

// -------------------------------------------------------------------------------- round trips

void expectRoundTrip(const std::string& name) {
  SCOPED_TRACE(name);
  const Mesh mesh = awkwardMesh();
  const std::string folder = test::emptyFolder("round_" + name), path = folder + "/" + name;
  writeMesh(mesh, path);
  EXPECT_EQ(test::filesIn(folder), std::vector<std::string>{name});  // no temporary stays
  const ReadResult result = readMesh(path);
  EXPECT_TRUE(result.notes.empty());
  EXPECT_EQ(result.mesh.triangles, mesh.triangles);
  ASSERT_EQ(result.mesh.points.size(), mesh.points.size());
  for (size_t i = 0; i < mesh.points.size(); ++i) EXPECT_EQ(result.mesh.points[i], mesh.points[i]) << i;
}

TEST(MeshIo, RoundTripOff) { expectRoundTrip("round.off"); }
TEST(MeshIo, RoundTripObj) { expectRoundTrip("round.obj"); }
TEST(MeshIo, RoundTripPly) { expectRoundTrip("round.ply"); }

TEST(MeshIo, WriteReplacesAnExistingFile) {
  const std::string path = writeFile("replace.off", "old content");
  writeMesh(awkwardMesh(), path);
  EXPECT_EQ(readMesh(path).mesh.faceCount(), 2);
}

TEST(MeshIo, WriteFailuresSayCannotWriteAndLeaveNoTemporaryFile) {
  const std::string missingDir = tempPath("no_such_dir") + "/out.off";
  const std::string missing = test::errorOf([&] { writeMesh(awkwardMesh(), missingDir); }, "a missing folder");
  EXPECT_EQ(missing.rfind(missingDir + ": cannot write", 0), 0u) << missing;
  const std::string folder = test::emptyFolder("write_failures");
  const std::string badExtension = folder + "/out.stl";
  const std::string stl = test::errorOf([&] { writeMesh(awkwardMesh(), badExtension); }, "an .stl");
  EXPECT_EQ(stl.rfind(badExtension + ": cannot write", 0), 0u) << stl;
  EXPECT_TRUE(test::filesIn(folder).empty());
  // Writing onto a directory is refused, leaving no temporary.
  const std::string directory = folder + "/a_directory.off";
  fs::create_directories(directory + "/inside");
  EXPECT_THROW(writeMesh(awkwardMesh(), directory), Error);
  EXPECT_EQ(test::filesIn(folder), std::vector<std::string>{"a_directory.off"});
}

// ------------------------------------------------------------------ one test per kind of error

// Said as such whatever the name: a missing file or a folder of no extension was said to have
// none ("remesh d").
TEST(MeshIoErrors, MissingFile) {
  expectReadError(tempPath("does_not_exist.off"), "no such file");
  expectReadError(tempPath("does_not_exist"), "no such file");
}

TEST(MeshIoErrors, DirectoryIsNotAMesh) {
  for (const std::string name : {"folder.obj", "folder"}) {
    const std::string path = tempPath(name);
    fs::create_directories(path);
    expectReadError(path, "is a directory, not a mesh file");
  }
}

// Root reads any file: as root (CI, where it was skipped) the read is made by a child that
// has become nobody first. The children end with _Exit: exit() would run the static
// destructor that removes this process's temporary folder, which the parent still uses.
TEST(MeshIoErrors, UnreadableFile) {
  const std::string path = writeFile("unreadable.off", kSquareOff);
  fs::permissions(path, fs::perms::none);
  EXPECT_EXIT(
      {
        if (geteuid() == 0 && (setresgid(65534, 65534, 65534) != 0 || setresuid(65534, 65534, 65534) != 0))
          std::_Exit(3);
        try {
          readMesh(path);
        } catch (const Error& e) {
          const std::string message = e.what();
          std::_Exit(message.rfind(path + ": cannot read", 0) == 0 ? 0 : 2);
        }
        std::_Exit(1);
      },
      ::testing::ExitedWithCode(0), "");
  fs::permissions(path, fs::perms::owner_all);
}

TEST(MeshIoErrors, EmptyFile) {
  expectFileError("empty.off", "", "empty");
  expectFileError("blank.ply", " \n\n", "empty");
}

// A file whose first word says it is of another format (an OFF named .obj was refused as "the
// mesh has no faces", which named nothing wrong).
TEST(MeshIoErrors, AFileOfAnotherFormatThanItsExtensionSays) {
  expectFileError("cube.obj", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
                  "its first word is that of an OFF file, not of an OBJ one: rename it .off");
  expectFileError("cube.off", "ply\nformat ascii 1.0\nend_header\n",
                  "its first word is that of a PLY file, not of an OFF one: rename it .ply");
  expectFileError("cube.ply", "  COFF\n3 1 0\n", "rename it .off");
}

TEST(MeshIoErrors, UnknownExtension) {
  expectFileError("mesh.stl", kSquareOff, "unknown extension '.stl'");
  expectFileError("mesh", kSquareOff, "no extension");
  // `remesh run.lsrec`: said to be a recording, and what opens one.
  expectFileError("run.lsrec", "LSREC", "a recording, not a mesh (.off, .obj or .ply): lloydscope inspect or info opens it");
}

// An output that is a folder is said to be one, not to have no extension ("-o results/"); a
// pipe of the wrong extension is refused for it, not written into.
TEST(MeshIoErrors, AFolderToWriteAMeshToIsSaidToBeOne) {
  const std::string pipe = test::tempPath("pipe.txt");
  std::remove(pipe.c_str());
  ASSERT_EQ(mkfifo(pipe.c_str(), 0600), 0);
  const std::string pipeRefused = test::errorOf([&] { requireMeshWritable(pipe); }, "a pipe of .txt");
  EXPECT_NE(pipeRefused.find("unknown extension '.txt'"), std::string::npos) << pipeRefused;
  std::remove(pipe.c_str());
  const std::string folder = test::emptyFolder("out_folder");
  EXPECT_EQ(test::errorOf([&] { requireMeshWritable(folder); }, "a folder"), folder + ": cannot write: it is a folder");
}

TEST(MeshIoErrors, BadHeader) {
  expectFileError("header.off", "OFX\n3 1 0\n", "bad header");
  expectFileError("counts.off", "OFF\n4 two 0\n", "bad header");
  expectFileError("negative.off", "OFF\n-4 2 0\n", "bad header");
  expectFileError("header.ply", "plx\nformat ascii 1.0\nend_header\n", "bad header");
  expectFileError("format.ply", "ply\nformat ascii 2.0\nend_header\n", "bad header");
  expectFileError("type.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty real x\nend_header\n",
                  "unknown property type");
  expectFileError("noend.ply", "ply\nformat ascii 1.0\nelement vertex 1\n", "end_header");
  // A count past what a file can hold is named as the OFF header's is.
  expectFileError("count.ply", "ply\nformat ascii 1.0\nelement vertex 99999999999\nproperty float x\nend_header\n",
                  "line 3: element 'vertex' count 99999999999 is impossible");
  expectFileError("negative.ply", "ply\nformat ascii 1.0\nelement face -3\nend_header\n",
                  "line 3: element 'face' count -3 is impossible");
  expectFileError("text_count.ply", "ply\nformat ascii 1.0\nelement face many\nend_header\n",
                  "line 3: element 'face' count 'many' is not an integer");
  expectFileError("noz.ply",
                  "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
                  "element face 0\nproperty list uchar int vertex_indices\nend_header\n0 0\n",
                  "no 'z' property");
}

TEST(MeshIoErrors, TruncatedFile) {
  expectFileError("few_vertices.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n", "header says 4 vertices but the file ends after 2");
  // A PLY row with a column more than its header declares: the error its data leads to says
  // where the rows stopped matching (it named only a later line's value).
  const std::string ply = "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
                          "property float z\nelement face 2\nproperty list uchar int vertex_indices\nend_header\n";
  expectFileError("extra_column.ply", ply + "0 0 0 1.0\n1 0 0 1.0\n1 1 0 1.0\n0 1 0 1.0\n3 0 1 2\n3 0 2 3\n",
                  "; line 10 (vertex 0) holds more values than the header declares for a vertex");
  // Vertices run together on one line read as one: the line is named (it said "truncated" alone).
  expectFileError("one_line.off", "OFF\n4 2 0\n0 0 0 1 0 0 0 1 0 1 1 0\n3 0 1 2 3 1 3 2\n",
                  "file ends after 2 (a line is one vertex, and line 3 holds 12 numbers)");
  expectFileError("few_faces.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n", "truncated");
  expectFileError("few_faces.ply",
                  "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                  "property float z\nelement face 2\nproperty list uchar int vertex_indices\nend_header\n"
                  "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 1\n",
                  "truncated");
  const std::string binaryOff = binaryOffSquare();
  expectFileError("cut_binary.off", binaryOff.substr(0, binaryOff.size() - 6), "truncated");
  const std::string binaryPly = binaryPlySquare(false);
  expectFileError("cut_binary.ply", binaryPly.substr(0, binaryPly.size() - 3), "truncated");
}

TEST(MeshIoErrors, AbsurdCountsAreRefusedBeforeAllocating) {
  expectFileError("huge.off", "OFF\n2000000000 2000000000 0\n0 0 0\n", "truncated");
  std::string binary = "OFF BINARY\n";
  for (std::int32_t count : {2000000000, 2000000000, 0}) append(binary, count, true);
  expectFileError("huge_binary.off", binary, "truncated");
  expectFileError("huge.ply",
                  "ply\nformat binary_little_endian 1.0\nelement vertex 2000000000\nproperty double x\n"
                  "property double y\nproperty double z\nelement face 1\n"
                  "property list int int vertex_indices\nend_header\n",
                  "truncated");
  // A face claiming a huge list length.
  std::string ply =
      "ply\nformat binary_little_endian 1.0\nelement vertex 0\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\nproperty list int int vertex_indices\nend_header\n";
  append<std::int32_t>(ply, 1000000000, false);
  append<std::int32_t>(ply, 0, false);
  expectFileError("huge_list.ply", ply, "truncated");
  expectFileError("huge_face.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2000000000 0 1 2\n", "should have");
  // Refused before allocating: read again with 512 MB more address space than the test has,
  // where reserving 2e9 points (48 GB) would throw std::bad_alloc (on a machine that
  // overcommits, the refusal above came either way).
  const auto readUnderALimit = [] {
    long pages = 0;
    std::ifstream("/proc/self/statm") >> pages;
    const rlim_t limit = static_cast<rlim_t>(pages) * sysconf(_SC_PAGESIZE) + (rlim_t(512) << 20);
    const rlimit bound{limit, limit};
    if (setrlimit(RLIMIT_AS, &bound) != 0) std::_Exit(4);
    for (const char* name : {"huge.off", "huge_binary.off", "huge.ply", "huge_list.ply", "huge_face.off"}) {
      try {
        readMesh(tempPath(name));
        std::_Exit(3);  // read: not refused
      } catch (const Error&) {
      } catch (const std::bad_alloc&) {
        std::_Exit(2);  // allocated first
      }
    }
    std::_Exit(0);
  };
  EXPECT_EXIT(readUnderALimit(), ::testing::ExitedWithCode(0), "");
}

// A header that claims more vertices than the file has reads its first faces as vertices: the
// last "vertex" reads as a face, and the file is refused (a header's counts swapped, 72 49 for
// 49 72, kept the last 49 of the 72 faces with no error; one vertex too many said "truncated").
TEST(MeshIoErrors, AFaceReadAsAVertexSaysTheCountsAreWrong) {
  const std::string square = "0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n";
  expectFileError("one_face_as_vertex.off", "OFF\n5 1 0\n" + square,
                  "line 7: vertex 4 reads as a face ('3 0 1 2'): the header's counts (5 vertices, 1 face) do not "
                  "match the file");
  expectFileError("one_vertex_too_many.off", "OFF\n5 2 0\n" + square, "vertex 4 reads as a face");
  // Vertices on integer coordinates with a fourth value are vertices all the same.
  EXPECT_EQ(readMesh(writeFile("four_values.off", "OFF\n3 1 0\n3 0 1 2\n4 0 1 2\n3 1 1 2\n3 0 1 2\n")).mesh.vertexCount(), 3);
}

TEST(MeshIoErrors, MoreDataThanTheHeaderSays) {
  expectFileError("extra.off", std::string(kSquareOff) + "3 1 2 3\n", "header says 2 faces but the file has more data");
  expectFileError("extra_binary.off", binaryOffSquare() + "garbage", "more data");
  expectFileError("extra.ply",
                  "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                  "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
                  "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 1 2\n",
                  "more data");
}

TEST(MeshIoErrors, NumberDoesNotParse) {
  expectFileError("word.off", "OFF\n3 1 0\n0 0 0\n1 x 0\n0 1 0\n3 0 1 2\n", "line 4: 'x' is not a number");
  expectFileError("suffix.obj", "v 0 0 0\nv 1 0 0abc\nv 0 1 0\nf 1 2 3\n", "'0abc' is not a number");
  expectFileError("index.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1.5 2\n", "'1.5' is not an integer");
  expectFileError("index.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 b 3\n", "'b' is not a vertex index");
  // Digits past 2^63 - 1 are a number, too large: not "not an integer", as a word is.
  expectFileError("huge.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 99999999999999999999\n",
                  "'99999999999999999999' is too large a number for a vertex index");
  expectFileError("huge.off", "OFF\n9223372036854775808 1 0\n", "vertex count '9223372036854775808' is too large a number");
  expectFileError("huge_index.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 -99999999999999999999\n",
                  "'-99999999999999999999' is too large a number");
  // The texture and normal indices too, which are not used (both were read as vertex 1).
  expectFileError("texture.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/x/y 2 3\n", "'1/x/y' is not a vertex index");
  expectFileError("slashes.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1/1/1/1 2 3\n", "'1/1/1/1' is not a vertex index");
  // A '#' within a number is no comment: old Microsoft libraries wrote NaN as -1.#IND, read
  // as -1 without a word, and infinity as 1.#INF, which left "1 coordinate" on its line.
  expectFileError("msvc_nan.obj", "v 0 0 0\nv 1 0 0\nv 0 1 -1.#IND\nf 1 2 3\n", "'-1.#IND' is not a number");
  // A comment against a word still is one (Geomview and tinyobjloader read it so).
  EXPECT_EQ(readMesh(writeFile("glued.obj", "v 0 0 0#c\nv 1 0 0\nv 0 1 0\nf 1 2 3#c\n")).mesh.faceCount(), 1);
  expectFileError("msvc_inf.off", "OFF\n3 1 0\n0 0 0\n1.#INF 0 0\n0 1 0\n3 0 1 2\n", "line 4: '1.#INF' is not a number");
  // A sign after the plus: strtod refuses "+-1", which was read as -1.
  expectFileError("plus_minus.obj", "v 0 0 0\nv 1 +-1 0\nv 0 1 0\nf 1 2 3\n", "'+-1' is not a number");
  expectFileError("plus_minus_index.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf +-3 2 3\n", "'+-3' is not a vertex index");
  expectFileError("word.ply",
                  "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                  "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
                  "0 0 0\n1 zero 0\n0 1 0\n3 0 1 2\n",
                  "'zero' is not a number");
}

TEST(MeshIoErrors, NonFiniteCoordinate) {
  expectFileError("nan.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 nan 0\n3 0 1 2\n", "vertex 2 has a non-finite coordinate");
  expectFileError("inf.obj", "v 0 0 0\nv 1e999 0 0\nv 0 1 0\nf 1 2 3\n", "vertex 2 has a non-finite coordinate");
  // Finite, but their squares are not ("face 0 has zero area", before).
  expectFileError("huge.off", "OFF\n3 1 0\n0 0 0\n1e308 0 0\n0 -1e308 0\n3 0 1 2\n",
                  "vertex 1 has a coordinate of 1e+308, too large to measure in double precision (lengths overflow past "
                  "1e+150; Lloydscope takes coordinates up to 1e+30); scale the mesh down");
  // Nor those of a mesh so small that its lengths to the fourth underflow ("face 0 has zero
  // area", before); one merely small is read.
  expectFileError("tiny.off", "OFF\n3 1 0\n0 0 0\n1e-100 0 0\n0 1e-100 0\n3 0 1 2\n",
                  "the mesh is 1.41421e-100 across (its bounding box's diagonal), too small to measure in double "
                  "precision (lengths to the fourth underflow under 1e-75; Lloydscope takes a diagonal of 1e-30 at least); "
                  "scale it up");
  EXPECT_EQ(readMesh(writeFile("small.off", "OFF\n3 1 0\n0 0 0\n1e-70 0 0\n0 1e-70 0\n3 0 1 2\n")).mesh.faceCount(), 1);
  // So small that the diagonal's square underflows itself: "face 0 has zero area" before.
  expectFileError("tinier.off", "OFF\n3 1 0\n0 0 0\n1e-170 0 0\n0 1e-170 0\n3 0 1 2\n",
                  "the mesh is 1.41421e-170 across (its bounding box's diagonal), too small to measure");
  // A shape far from the origin for its size keeps too few digits ("face 0 has zero area" at
  // 1e16 before); one nearer is read.
  expectFileError("far.off", "OFF\n3 1 0\n1e16 0 0\n1.0000000000000004e16 0 0\n1e16 4 0\n3 0 1 2\n",
                  "times its size (its bounding box's diagonal) from the origin: double precision keeps too few "
                  "digits of its shape (Lloydscope takes 1e+12 times at most); move it nearer");
  EXPECT_EQ(readMesh(writeFile("near.off", "OFF\n3 1 0\n1e12 0 0\n1.000000000001e12 0 0\n1e12 1 0\n3 0 1 2\n")).mesh.faceCount(), 1);
}

TEST(MeshIoErrors, FaceIndexOutOfRange) {
  expectFileError("range.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 900\n",
                  "face 0 uses vertex 900 but there are 3 vertices");
  expectFileError("negative.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n", "uses vertex -1");
  // OBJ messages count from 1, like the file.
  expectFileError("range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 3 9\n",
                  "face 2 uses vertex 9 but there are 3 vertices");
  expectFileError("relative.obj", "v 0 0 0\nv 1 0 0\nf -1 -2 -3\nv 0 1 0\n", "face 1 uses vertex -3");
  expectFileError("zero.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n", "uses vertex 0");
  // A PLY index at long long's end: read through a double, its cast back was undefined (it came
  // out as -9223372036854775808).
  expectFileError("huge.ply",
                  "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                  "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
                  "0 0 0\n1 0 0\n0 1 0\n3 0 1 9223372036854775807\n",
                  "face 0 has a vertex index past any mesh's size");
}

TEST(MeshIoErrors, FaceWithTooFewVertices) {
  expectFileError("two.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2 0 1\n", "face 0 has 2 vertices");
  expectFileError("two.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2\n", "face 2 has 2 vertices");
}

TEST(MeshIoErrors, RepeatedVertexInAFace) {
  expectFileError("repeat.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 1\n",
                  "face 0 uses vertex 1 twice (--repair drops such faces, or reads a face that lists it twice in a "
                  "row with it once)");
}

// The repair drops a face that uses a vertex twice (here the square's third face), and says so;
// a file of nothing else still has no faces.
TEST(MeshIo, TheRepairDropsAFaceUsingAVertexTwice) {
  const std::string path = writeFile("repeat_repaired.off", "OFF\n4 3 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n"
                                                            "3 0 1 2\n3 0 2 3\n3 0 1 1\n");
  const ReadResult r = readMesh(path, ReadOptions{true});
  EXPECT_EQ(r.mesh.faceCount(), 2);
  ASSERT_EQ(r.notes.size(), 1u);
  EXPECT_EQ(r.notes[0], path + ": repaired: 1 face using a vertex twice dropped");
  const std::string only = writeFile("repeat_only.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 1\n");
  EXPECT_THROW(readMesh(only, ReadOptions{true}), Error);
}

// A polygon that lists a vertex twice in a row ("a b c c": a triangle, as an exporter of quads
// writes it) or ends where it started ("a b c a") is read by the repair with the vertex once:
// it was dropped, which left a hole.
TEST(MeshIo, TheRepairReadsAFaceListingAVertexTwiceInARowWithItOnce) {
  const std::string path = writeFile("quad_as_triangle.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n"
                                                             "4 0 1 2 2\n4 0 2 3 0\n");
  const ReadResult r = readMesh(path, ReadOptions{true});
  EXPECT_EQ(r.mesh.faceCount(), 2);
  ASSERT_EQ(r.notes.size(), 1u);
  EXPECT_EQ(r.notes[0], path + ": repaired: 2 faces listing a vertex twice in a row read with it once");
  expectReadError(path, "face 0 uses vertex 2 twice");
}

TEST(MeshIoErrors, ZeroAreaFace) {
  expectFileError("flat.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n0.3 0.7 0\n3 0 1 2\n3 1 3 2\n",
                  "face 1 has zero area");
  // A polygon with all corners on a line: the message names the polygon as the file numbers it.
  expectFileError("flat_polygon.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 2 0 0\nv 3 0 0\nv 4 0 0\nf 1 2 3\nf 4 5 6 2\n",
                  "face 2 has zero area");
}

TEST(MeshIoErrors, AFaceOnTwoVerticesAtTheSamePosition) {
  expectFileError("duplicate.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n1 0 0\n3 0 1 2\n3 1 3 2\n",
                  "face 1 has zero area: its vertices 1 and 3 are at the same position");
}

// On a border, two vertices at one place are an unwelded seam or a crack (here two faces on top
// of each other through a copy of a vertex, and two triangles meeting at a corner).
TEST(MeshIoErrors, BorderVerticesAtTheSamePosition) {
  expectFileError("overlap.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n1 0 0\n3 0 1 2\n3 0 3 2\n",
                  "vertices 1 and 3 are at the same position on a border");
  expectFileError("corner.off",
                  "OFF\n6 2 0\n0 0 0\n1 0 0\n0 1 0\n0 0 0\n-1 0 0\n0 -1 0\n3 0 1 2\n3 3 4 5\n",
                  "vertices 0 and 3 are at the same position on a border");
}

// A closed surface may touch itself at a point (CGAL's cow.off does, once): each copy has its
// own faces, so the mesh is a manifold; it is read, with a note. Here two tetrahedra touching
// at a corner.
TEST(MeshIo, InsideVerticesAtTheSamePositionWithTheirOwnFacesAreKept) {
  const std::string path = writeFile(
      "touching.off",
      "OFF\n8 8 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n0 0 0\n-1 0 0\n0 -1 0\n0 0 -1\n"
      "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n"
      "3 4 5 6\n3 4 7 5\n3 4 6 7\n3 5 7 6\n");
  const ReadResult result = readMesh(path);
  EXPECT_EQ(result.mesh.vertexCount(), 8);
  ASSERT_EQ(result.notes.size(), 1u);
  EXPECT_EQ(result.notes[0], path + ": vertices 0 and 4 are at the same position, each with its "
                                    "own faces inside the surface: it touches itself there");
}

// What the repair would fix says so; what it would not (two triangles meeting at a corner
// through two copies of it: welded, a bow tie, split again) does not.
TEST(MeshIoErrors, AProblemTheRepairFixesSaysSo) {
  expectFileError("needle.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n1 0 0\n3 0 1 2\n3 1 3 2\n",
                  "are at the same position (--repair fixes this)");
  const std::string corner = writeFile(
      "pinch.off", "OFF\n6 2 0\n0 0 0\n1 0 0\n0 1 0\n0 0 0\n-1 0 0\n0 -1 0\n3 0 1 2\n3 3 4 5\n");
  EXPECT_EQ(readError(corner).find("--repair"), std::string::npos) << readError(corner);
}

TEST(MeshIo, TheRepairReadsWhatTheChecksRefuseAndSaysWhatItChanged) {
  const std::string path = writeFile(
      "repairable.off", "OFF\n6 3 0\n0 0 0\n1 0 0\n0 1 0\n1 0 0\n1 1 0\n0 1 0\n"
                        "3 0 1 2\n3 1 3 2\n3 3 4 5\n");
  const ReadResult r = readMesh(path, ReadOptions{true});
  EXPECT_EQ(r.mesh.vertexCount(), 4);
  EXPECT_EQ(r.mesh.faceCount(), 2);
  ASSERT_EQ(r.notes.size(), 1u);
  EXPECT_EQ(r.notes[0], path + ": repaired: 2 vertices welded to another at the same position; "
                               "1 face with a corner or a face repeated dropped");
  // A sound file reads the same with the repair as without, and without a note.
  const std::string sound = writeFile("sound.off", kSquareOff);
  EXPECT_TRUE(readMesh(sound, ReadOptions{true}).notes.empty());
  EXPECT_EQ(readMesh(sound, ReadOptions{true}).mesh.triangles, readMesh(sound).mesh.triangles);
}

TEST(MeshIoErrors, WhatTheRepairLeavesIsStillRefused) {
  const std::string corner = writeFile(
      "pinch_repaired.off", "OFF\n6 2 0\n0 0 0\n1 0 0\n0 1 0\n0 0 0\n-1 0 0\n0 -1 0\n3 0 1 2\n3 3 4 5\n");
  // Two corners at one point: not a seam the repair should weld (the message named a seam only,
  // the one thing the guide says --repair fixes).
  const std::string pinch = test::errorOf([&] { readMesh(corner, ReadOptions{true}); }, "a pinched corner repaired");
  EXPECT_NE(pinch.find("same position on a border (an unwelded seam, a crack, or the border touching itself at a point) "
                       "(left after the repair)"),
            std::string::npos) << pinch;
  // Two triangles on one vertex: the repair splits it, and the copy has a number the file does
  // not (a Moebius strip's said "vertices 2 and 12" of a file of 12).
  const std::string bowtie = test::errorOf(
      [&] { readMesh(writeFile("bowtie.off", "OFF\n5 2 0\n0 0 0\n1 0 0\n0 1 0\n-1 0 0\n0 -1 0\n3 0 1 2\n3 0 3 4\n"),
                     ReadOptions{true}); },
      "a bowtie repaired");
  EXPECT_NE(bowtie.find("(left after the repair, which numbered the vertices and faces anew, from 0)"), std::string::npos)
      << bowtie;
  // A Moebius strip: no turning of its faces mends it, and the repair says so (it cut the strip
  // open and refused the cut's two sides as vertices at one place).
  std::string moebius = "OFF\n12 12 0\n";
  for (int i = 0; i < 6; ++i)
    for (double w : {0.3, -0.3}) {
      const double u = 2 * M_PI * i / 6, r = 1 + w * std::cos(u / 2);
      moebius += std::to_string(r * std::cos(u)) + " " + std::to_string(r * std::sin(u)) + " " +
                 std::to_string(w * std::sin(u / 2)) + "\n";
    }
  for (int i = 0; i < 6; ++i) {
    const int t = 2 * i, b = 2 * i + 1, nextT = i < 5 ? t + 2 : 1, nextB = i < 5 ? b + 2 : 0;  // the twist
    moebius += "3 " + std::to_string(t) + " " + std::to_string(b) + " " + std::to_string(nextB) + "\n3 " +
               std::to_string(t) + " " + std::to_string(nextB) + " " + std::to_string(nextT) + "\n";
  }
  // As read: not orientable, which no turning of faces mends (it said two faces disagreed).
  expectReadError(writeFile("moebius_as_is.off", moebius), "the surface is not orientable (a Moebius strip, say)");
  const std::string repaired = test::errorOf([&] { readMesh(writeFile("moebius.off", moebius), ReadOptions{true}); },
                                              "a Moebius strip repaired");
  EXPECT_NE(repaired.find("the surface is not orientable (a Moebius strip, say): no turning of its faces makes them agree "
                          "across every edge, which the repair cannot mend"),
            std::string::npos)
      << repaired;
}

// A mesh whose faces all have zero area leaves nothing to repair into: refused as it is read,
// and the refusal does not say the repair fixes it (bench --repair subdivided the empty mesh
// for ever; metrics, simplify and remesh took it).
TEST(MeshIoErrors, NothingLeftAfterTheRepairIsRefused) {
  const char* collinear = "OFF\n4 2 0\n0 0 0\n1 0 0\n2 0 0\n3 0 0\n3 0 1 2\n3 1 3 2\n";
  const std::string path = writeFile("collinear.off", collinear);
  const std::string flat = test::errorOf([&] { readMesh(path, ReadOptions{true}); }, "collinear faces repaired");
  EXPECT_NE(flat.find("no faces remain (all were dropped or of zero area) (left after the repair)"), std::string::npos) << flat;
  EXPECT_EQ(readError(path).find("--repair"), std::string::npos) << readError(path);
}

TEST(MeshIoErrors, NonManifoldEdge) {
  expectFileError("fin.off",
                  "OFF\n5 3 0\n0 0 0\n1 0 0\n0.5 1 0\n0.5 -1 0\n0.5 0 1\n3 0 1 2\n3 1 0 3\n3 0 1 4\n",
                  "edge 0-1 is shared by 3 faces");
}

TEST(MeshIoErrors, NonManifoldVertex) {
  // Two triangles touching only at vertex 0 (a bow tie).
  expectFileError("bowtie.off", "OFF\n5 2 0\n0 0 0\n1 0 0\n1 1 0\n-1 0 0\n-1 -1 0\n3 0 1 2\n3 0 3 4\n",
                  "vertex 0 is non-manifold (two fans of faces meet there)");
}

TEST(MeshIoErrors, InconsistentOrientation) {
  expectFileError("flipped.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 3 2\n",
                  "faces 0 and 1 have opposite orientations across edge 0-2");
}

TEST(MeshIoErrors, NoFaces) {
  expectFileError("points.off", "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n", "the mesh has no faces");
  expectFileError("points.obj", "v 0 0 0\nv 1 0 0\n", "no faces");
  expectFileError("points.ply",
                  "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
                  "property float z\nend_header\n0 0 0\n",
                  "no faces");
}

TEST(MeshIoErrors, BinaryDataInATextObj) {
  expectFileError("binary.obj", std::string("v 0 0 0\n\0\x01\x02", 11), "binary");
}

// Random bytes, random bytes after a valid header, and valid files cut at every length must all
// give an Error (or, for some cuts, a valid mesh) and never crash, hang or allocate wildly.
TEST(MeshIoErrors, GarbageNeverCrashes) {
  std::mt19937 random(12345);
  const std::vector<std::pair<std::string, std::string>> seeds = {
      {"fuzz.off", kSquareOff},
      {"fuzz_binary.off", binaryOffSquare()},
      {"fuzz.ply", binaryPlySquare(false)},
      {"fuzz_be.ply", binaryPlySquare(true)},
      {"fuzz.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n"}};
  // What is read is a valid mesh; what is refused is one line naming the file (the cut
  // files' errors were caught and not looked at).
  auto readsOrSaysWhy = [](const std::string& path) {
    try {
      const Mesh mesh = readMesh(path).mesh;
      EXPECT_NO_THROW(validateMesh(mesh, path)) << path;
    } catch (const Error& e) {
      const std::string message = e.what();
      EXPECT_EQ(message.find('\n'), std::string::npos) << message;
      EXPECT_EQ(message.rfind(path + ": ", 0), 0u) << message;
    }
  };
  for (const auto& [name, valid] : seeds) {
    const std::string path = tempPath(name);
    for (size_t cut = 0; cut < valid.size(); ++cut) {
      writeFile(name, valid.substr(0, cut));
      readsOrSaysWhy(path);
    }
    for (int round = 0; round < 200; ++round) {
      std::string bytes = valid;
      const int flips = 1 + static_cast<int>(random() % 8);
      for (int k = 0; k < flips; ++k) bytes[random() % bytes.size()] = static_cast<char>(random() % 256);
      writeFile(name, bytes);
      readsOrSaysWhy(path);
    }
  }
}

// ---------------------------------------------------------------------------- validateMesh

TEST(ValidateMesh, AcceptsAValidMeshAndRefusesAnUnusedVertex) {
  Mesh mesh = awkwardMesh();
  EXPECT_EQ(validateError(mesh), "");
  mesh.points.emplace_back(5, 5, 5);
  EXPECT_EQ(validateError(mesh), "mesh: vertex 4 is not used by any face");
}

TEST(ValidateMesh, ChecksTrianglesItself) {
  Mesh mesh = awkwardMesh();
  EXPECT_EQ(validateError(Mesh{mesh.points, {}}), "mesh: the mesh has no faces");
  mesh.triangles[1] = {0, 2, 7};
  EXPECT_EQ(validateError(mesh), "mesh: face 1 uses vertex 7 but there are 4 vertices");
  mesh.triangles[1] = {0, 2, 2};
  EXPECT_EQ(validateError(mesh), "mesh: face 1 uses vertex 2 twice");
  mesh.triangles[1] = {0, 3, 2};
  EXPECT_EQ(validateError(mesh), "mesh: faces 0 and 1 have opposite orientations across edge 0-2");
}

}  // namespace
}  // namespace lloydscope
