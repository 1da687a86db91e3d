// Saving a file whole or not at all, and finding out before a long run that it cannot be saved;
// reading one whole, up to a size.
#pragma once

#include <cstdint>
#include <filesystem>
#include <functional>
#include <istream>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

namespace lloydscope {

// Writes `path` through a temporary of its own beside it (".lloydscope-<pid>-<n>"), renamed onto
// it once complete: a file already there is replaced whole or not at all, keeping its
// permissions, and refused where they do not let it be written (a read-only file); a link is
// written through, to its target. `write` fills the stream (binary).
// Throws Error("<path>: cannot write ...") saying why.
void writeAtomically(const std::string& path, const std::function<void(std::ostream&)>& write);

// Files saved together, each as writeAtomically saves one: add() writes a file's temporary,
// commit() renames them all onto their files. Where an add() throws, or commit() never comes,
// no file is replaced (remesh -o on a full disk replaced the --record file it had saved first,
// then failed); where a rename fails, those before it are put back (through a second name
// for each file replaced; the message says which, if any, could not be). A device
// (/dev/stdout) has no temporary: add() writes into it at once.
class FileBatch {
 public:
  FileBatch();
  ~FileBatch();  // removes the temporaries not renamed
  FileBatch(const FileBatch&) = delete;
  FileBatch& operator=(const FileBatch&) = delete;
  void add(const std::string& path, const std::function<void(std::ostream&)>& write);
  void commit();

 private:
  struct Staged;
  std::vector<std::unique_ptr<Staged>> staged_;
};

// While one is alive, Ctrl+C or kill (SIGINT, SIGTERM, SIGHUP) waits: when the last goes, the
// temporaries in flight are removed and the run ends by that signal. FileBatch::commit() renames
// under one, so that an interruption between two renames cannot leave its files half replaced
// and the second names that would put them back removed.
class InterruptionsDeferred {
 public:
  InterruptionsDeferred();
  ~InterruptionsDeferred();
  InterruptionsDeferred(const InterruptionsDeferred&) = delete;
  InterruptionsDeferred& operator=(const InterruptionsDeferred&) = delete;
};

// Throws the Error writeAtomically would end with where its temporary cannot be made (no such
// folder, no permission, a read-only file there) or `path` is a folder: checked before a run that may take minutes.
// Leaves nothing behind.
void requireWritable(const std::string& path);
// The part of that which opens nothing: a folder, no name, or one longer than a file name may be.
void requireFileName(const std::string& path);

// A new empty file of a name of its own in the system's temporary folder (TMPDIR, else /tmp),
// ending in `suffix`, removed when this goes, or when the run is interrupted (Ctrl+C, kill):
// `bench --lloyd-step` left one behind at each error and each Ctrl+C. Throws Error where none
// can be made.
class TemporaryFile {
 public:
  explicit TemporaryFile(const std::string& suffix);
  ~TemporaryFile();
  TemporaryFile(const TemporaryFile&) = delete;
  TemporaryFile& operator=(const TemporaryFile&) = delete;
  const std::string& path() const { return path_; }

 private:
  struct RemovedIfInterrupted;
  std::string path_;
  std::unique_ptr<RemovedIfInterrupted> removedIfInterrupted_;
};

// `path`'s extension in lower case (".off" for "x.OFF"; "" for none): formats are told by it.
std::string lowercaseExtension(const std::string& path);

// Whether two names (non-empty) are one file, there or not yet: "x.off", "./x.off", "sub/../x.off"
// and its absolute path are, and so are a link and its target (not there yet, too).
bool sameFile(const std::string& a, const std::string& b);

// Where a write of `path` goes: through links, link after link, to their target, there or not
// yet. Throws Error("<path>: cannot write: ...") for a loop of links.
std::filesystem::path targetOf(const std::string& path);

// Makes the folder `path` and the folders above it where missing. Throws Error("<path>: cannot
// make the folder (why)") where it cannot be made or is a file.
void makeFolder(const std::string& path);

// The whole of `path` (opened as `in`), at most `mostBytes` of it: beyond, Error("<path>: larger
// than <size>, more than <what> takes"), before reading where the file says its size (a link to
// /dev/zero, which never ends, grew until memory ran out). A device is refused unread
// (Error("<path>: is a device, not <what>")); a pipe is read. Throws Error("<path>: cannot read
// the file (read error)") where reading fails.
std::string readWhole(std::istream& in, const std::string& path, std::uint64_t mostBytes, const std::string& what);

}  // namespace lloydscope
