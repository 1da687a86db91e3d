// Reading and writing OFF (ASCII and binary), OBJ and PLY (ASCII and binary) triangle meshes.
// Reading validates: any problem is an Error whose message is one line naming the file.
#pragma once

#include "mesh.h"

#include <cstdint>
#include <string>
#include <vector>

namespace lloydscope {

class FileBatch;  // core/files.h

struct ReadResult {
  Mesh mesh;
  // Things that were repaired rather than refused, one line each, e.g.
  // "face.obj: 12 quads and 3 pentagons were triangulated".
  std::vector<std::string> notes;
};

struct ReadOptions {
  // Weld, collapse and turn what the checks refuse (core/repair), and say so in the notes; a
  // mesh the checks accept is not touched.
  bool repair = false;
};

// The largest mesh file read: about 40 million triangles as binary PLY, 20 million as OFF.
constexpr std::uint64_t kLargestMeshFile = 2'000'000'000;

// Whether `ext` (lowercaseExtension's: ".off") is one meshes are read and written by: .off, .obj
// or .ply. (A recording or a table is never saved under one: it would replace a mesh.)
bool isMeshExtension(const std::string& ext);
// Throws Error("<path>: <what> is not saved under a mesh's extension ...; name it <suggested>")
// where `path`, or the file a link there leads to, has a mesh's extension: `what` ("a
// recording") saved so would replace a mesh with what no mesh reader reads.
void requireNoMeshExtension(const std::string& path, const std::string& what, const std::string& suggested);

// Reads by extension (.off, .obj, .ply; case-insensitive) and validates with validateMesh().
// A problem that the repair would fix says so ("... (--repair fixes this)"). A file larger than
// kLargestMeshFile is refused.
ReadResult readMesh(const std::string& path, const ReadOptions& options = {});

// Checks what every later stage relies on and throws Error("<name>: <problem>") otherwise:
// finite coordinates, indices in range, no zero-area faces, no vertex used by no face, manifold
// edges and vertices, consistently oriented faces. Two inside vertices may be at the same
// position (a surface that touches itself), each with its own faces; two border vertices not.
void validateMesh(const Mesh& mesh, const std::string& name);

// Writes by extension. The file appears complete or not at all (temporary file, then rename).
void writeMesh(const Mesh& mesh, const std::string& path);
// The same, saved with the other files of `batch` (FileBatch, core/files.h) when it commits.
void writeMesh(const Mesh& mesh, const std::string& path, FileBatch& batch);
// Throws the Error writeMesh would for `path` (an extension it does not write, a folder it
// cannot write in: requireWritable), before a run that may take minutes.
void requireMeshWritable(const std::string& path);

}  // namespace lloydscope
