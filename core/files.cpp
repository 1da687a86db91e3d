#include "files.h"

#include "mesh.h"

#include <atomic>
#include <cctype>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <thread>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace lloydscope {

// Where a write goes: through a link to its target (renaming onto the link replaced it with a
// file and left the target as it was), a target not there yet too (a link to a file to be made
// was replaced by the file), link after link; refused after as many as the system follows (a
// loop of links was replaced by a file).
std::filesystem::path targetOf(const std::string& path) {
  constexpr int kMostLinks = 40;  // Linux's MAXSYMLINKS
  std::filesystem::path target = path;
  std::error_code error;
  for (int links = 0; std::filesystem::is_symlink(target, error); ++links) {
    if (links == kMostLinks) throw Error(path + ": cannot write: " + std::strerror(ELOOP));
    const std::filesystem::path to = std::filesystem::read_symlink(target, error);
    if (error) break;
    target = to.is_absolute() ? to : target.parent_path() / to;
  }
  return target;
}

namespace {

// Says why no file could be made in the target's folder: a missing folder by its name, else the
// system's reason.
[[noreturn]] void cannotMake(const std::string& path, const std::filesystem::path& folder) {
  const std::string reason = std::strerror(errno);
  std::error_code unknown;  // a path longer than the system takes: no folder found, nor missing
  const bool there = std::filesystem::exists(folder, unknown);
  if (unknown) throw Error(path + ": cannot write (" + reason + ")");
  if (!there) throw Error(path + ": cannot write: there is no folder " + folder.string());
  throw Error(path + ": cannot write in " + folder.string() + " (" + reason + ")");
}

}  // namespace

// A long name failed only at the end, after the minutes of work it was to save.
void requireFileName(const std::string& path) {
  if (path.empty()) throw Error("cannot write a file of no name (an empty name was given)");
  std::error_code ignored;
  if (std::filesystem::is_directory(path, ignored)) throw Error(path + ": cannot write: it is a folder");
  const std::filesystem::path file(path);
  const std::string name = file.filename().string();
  const long longest = pathconf(file.has_parent_path() ? file.parent_path().c_str() : ".", _PC_NAME_MAX);
  if (longest > 0 && static_cast<long>(name.size()) > longest)
    throw Error(path + ": cannot write: its name is " + std::to_string(name.size()) +
                " bytes long, more than a file name may be here (" + std::to_string(longest) + ")");
}

namespace {

// A device, a pipe or a socket (or a link to one: /dev/null, /dev/stdout) is written into as it
// is: renaming a temporary onto it replaced it with a plain file (as root, /dev/null itself).
bool isSpecialFile(const std::string& path) {
  std::error_code error;
  const std::filesystem::file_status status = std::filesystem::status(path, error);  // through links
  return !error && std::filesystem::exists(status) && !std::filesystem::is_regular_file(status) &&
         !std::filesystem::is_directory(status);
}

// The temporaries being written, removed if the run is interrupted (Ctrl+C, kill) before they
// are renamed: a slot each, holding a copy of its name. A batch of n files takes 2n - 1 (its
// temporaries, and the second names kept while it commits), and a picture sequence is a batch
// of one picture per iteration, up to the 100,000 iterations a run may take: with 4 slots, Ctrl+C
// in a sequence of 40 pictures left 36 temporaries behind. The slots are lock-free atomics (a
// signal handler may read them), searched from where the last was taken or freed.
constexpr int kSlots = 1 << 18;
std::atomic<const char*> inFlight[kSlots];
static_assert(std::atomic<const char*>::is_always_lock_free);
std::atomic<int> slotsReached{0};  // one past the highest slot ever taken: what the handler reads
std::atomic<int> searchFrom{0};

std::atomic<int> deferring{0};        // InterruptionsDeferred alive
std::atomic<int> deferredSignal{0};   // the signal that came meanwhile
std::atomic<int> handling{0};         // handlers reading the slots: no name is freed under them
static_assert(std::atomic<int>::is_always_lock_free);

extern "C" void removeInFlightAndDie(int signal) {
  ++handling;
  if (deferring.load() > 0) {
    deferredSignal.store(signal);
    // The last deferral may have ended on another thread between the two looks: one side, the
    // one that takes the signal back, goes on with it.
    if (deferring.load() > 0 || deferredSignal.exchange(0) == 0) {
      --handling;
      return;
    }
  }
  const int reached = slotsReached.load();
  for (int k = 0; k < reached; ++k)
    if (const char* name = inFlight[k].load()) unlink(name);
  std::signal(signal, SIG_DFL);
  std::raise(signal);
}

// Not over a signal ignored (SIGHUP under nohup): the run would have ended by it.
void installRemovalAtInterruption() {
  static const bool installed = [] {
    for (int signal : {SIGINT, SIGTERM, SIGHUP}) {
      struct sigaction before {};
      if (sigaction(signal, nullptr, &before) == 0 && before.sa_handler == SIG_IGN) continue;
      std::signal(signal, removeInFlightAndDie);
    }
    return true;
  }();
  (void)installed;
}

class InFlight {
 public:
  explicit InFlight(const std::string& temporary) : name_(new char[temporary.size() + 1]) {
    installRemovalAtInterruption();
    std::memcpy(name_.get(), temporary.c_str(), temporary.size() + 1);
    const int start = searchFrom.load();
    for (int i = 0; i < kSlots && slot_ < 0; ++i) {
      const int k = (start + i) % kSlots;
      if (inFlight[k].load() != nullptr) continue;
      // The handler reads as far as slotsReached: it reaches k before k holds the name.
      for (int seen = slotsReached.load(); seen <= k && !slotsReached.compare_exchange_weak(seen, k + 1);) {
      }
      const char* empty = nullptr;
      if (inFlight[k].compare_exchange_strong(empty, name_.get())) slot_ = k;
    }
    if (slot_ >= 0) searchFrom.store(slot_ + 1);
  }
  ~InFlight() {
    if (slot_ < 0) return;
    inFlight[slot_].store(nullptr);
    while (handling.load() > 0) std::this_thread::yield();  // it may have read the name (it dies)
    for (int from = searchFrom.load(); slot_ < from && !searchFrom.compare_exchange_weak(from, slot_);) {
    }
  }
  InFlight(const InFlight&) = delete;
  InFlight& operator=(const InFlight&) = delete;

 private:
  std::unique_ptr<char[]> name_;
  int slot_ = -1;
};

// Makes "<folder>/<stem><pid>-<n><suffix>" with O_EXCL, the next n where one is taken (another
// run's, killed before it could remove it), with `mode` (less the umask). Sets `name`; returns
// the open descriptor, or -1 with errno set.
int createUnique(const std::filesystem::path& folder, const std::string& stem, const std::string& suffix,
                 mode_t mode, std::string& name) {
  static std::atomic<unsigned> made{0};
  for (;;) {
    name = (folder / (stem + std::to_string(getpid()) + "-" + std::to_string(made++) + suffix)).string();
    const int fd = open(name.c_str(), O_WRONLY | O_CREAT | O_EXCL, mode);
    if (fd >= 0 || errno != EEXIST) return fd;
  }
}

// A file already at `target` that this user may not write (a read-only file; root may write
// any) is refused: its folder let it be replaced, and it was, after the run, with a message
// naming a temporary already gone and no reason. Returns its permissions, which its
// replacement gets.
std::optional<mode_t> requireReplaceable(const std::string& path, const std::filesystem::path& target) {
  struct stat existing, folder;
  if (stat(target.c_str(), &existing) != 0) return std::nullopt;  // not there yet
  if (access(target.c_str(), W_OK) != 0) throw Error(path + ": cannot write (" + std::strerror(errno) + ")");
  // In a folder with the sticky bit (/tmp), only the file's owner or the folder's (or root) may
  // rename onto it: refused after the run, after the other file of its batch was replaced.
  const uid_t user = geteuid();
  if (stat(target.has_parent_path() ? target.parent_path().c_str() : ".", &folder) == 0 &&
      (folder.st_mode & S_ISVTX) && user != 0 && user != existing.st_uid && user != folder.st_uid)
    throw Error(path + ": cannot write: it is another user's, in a folder where only its owner may replace it");
  return existing.st_mode & 07777;
}

// A new empty file beside `target`, of a name no other writer takes: a fixed "<path>.tmp"
// deleted a user's file of that name, two runs writing one output shared it, and with a name
// near the system's limit it was too long. It has the permissions any new file gets (the
// umask's); where it replaces a file (`replacing`), its owner's alone while it is written, so
// that a private file's new contents are never readable by others.
std::string makeTemporary(const std::string& path, const std::filesystem::path& target, bool replacing) {
  const std::filesystem::path folder = target.has_parent_path() ? target.parent_path() : ".";
  std::string name;
  const int fd = createUnique(folder, ".lloydscope-", "", replacing ? 0600 : 0666, name);
  if (fd < 0) cannotMake(path, folder);
  close(fd);
  return name;
}

// Where a write of `path` goes: its target (through links), the permissions of the file it
// replaces (none: a new file), and an empty temporary beside it. The check before a run
// (requireWritable) and the write (FileBatch::add) make it alike: what the one passes, the
// other can do.
struct Destination {
  std::filesystem::path target;
  std::optional<mode_t> replacedMode;
  std::string temporary;
};

Destination destinationOf(const std::string& path) {
  Destination d;
  d.target = targetOf(path);
  d.replacedMode = requireReplaceable(path, d.target);
  d.temporary = makeTemporary(path, d.target, d.replacedMode.has_value());
  return d;
}

}  // namespace

// A temporary written beside its target, renamed onto it, or removed where that never comes.
struct FileBatch::Staged {
  std::string path, temporary;
  std::filesystem::path target;
  InFlight removedIfInterrupted;
  bool renamed = false;
  Staged(std::string p, std::string t, std::filesystem::path target)
      : path(std::move(p)), temporary(std::move(t)), target(std::move(target)), removedIfInterrupted(temporary) {}
  ~Staged() {
    if (!renamed) std::remove(temporary.c_str());
  }
};

FileBatch::FileBatch() = default;
FileBatch::~FileBatch() = default;

void FileBatch::add(const std::string& path, const std::function<void(std::ostream&)>& write) {
  requireFileName(path);
  if (isSpecialFile(path)) {
    std::ofstream out(path, std::ios::binary);
    if (out) write(out);
    out.close();
    if (!out) throw Error(path + ": cannot write (" + std::strerror(errno) + ")");
    return;
  }
  const Destination to = destinationOf(path);
  auto staged = std::make_unique<Staged>(path, to.temporary, to.target);
  std::ofstream out(staged->temporary, std::ios::binary | std::ios::trunc);
  if (!out) throw Error(path + ": cannot write " + staged->temporary + " (" + std::strerror(errno) + ")");
  write(out);  // out of memory, say: the temporary goes with `staged`
  out.close();
  if (!out)  // the writer's own failure (the PNG encoder's), or the disk's
    throw Error(path + ": cannot write " + staged->temporary + " (disk full?)");
  // The file it replaces keeps its permissions, set once written (a read-only one's would
  // not have let it be written).
  if (to.replacedMode && chmod(staged->temporary.c_str(), *to.replacedMode) != 0)
    throw Error(path + ": cannot keep its permissions (" + std::strerror(errno) + ")");
  staged_.push_back(std::move(staged));
}

namespace {

// A second name for the file at `target`, beside it, to put it back by if a later rename of its
// batch fails; removed when this goes.
class KeptFile {
 public:
  explicit KeptFile(const std::filesystem::path& target) : target_(target) {
    struct stat existing;
    existed_ = lstat(target.c_str(), &existing) == 0;
    if (!existed_) return;
    std::string name;
    const std::filesystem::path folder = target.has_parent_path() ? target.parent_path() : ".";
    const int fd = createUnique(folder, ".lloydscope-kept-", "", 0600, name);
    if (fd < 0) return;
    close(fd);
    // link() makes no name that is there already: the empty file made for the name goes first.
    if (std::remove(name.c_str()) == 0 && link(target.c_str(), name.c_str()) == 0) {
      kept_ = name;
      removedIfInterrupted_.emplace(name);
    }
  }
  ~KeptFile() {
    if (!kept_.empty()) std::remove(kept_.c_str());
  }
  KeptFile(const KeptFile&) = delete;
  KeptFile& operator=(const KeptFile&) = delete;
  // The target as it was: the kept file renamed back onto it, or, where there was none, the new
  // one removed. False where that could not be done (the system made no second name).
  bool putBack() {
    if (!existed_) return std::remove(target_.c_str()) == 0;
    if (kept_.empty() || std::rename(kept_.c_str(), target_.c_str()) != 0) return false;
    kept_.clear();
    return true;
  }

 private:
  std::filesystem::path target_;
  bool existed_ = false;
  std::string kept_;
  std::optional<InFlight> removedIfInterrupted_;
};

}  // namespace

InterruptionsDeferred::InterruptionsDeferred() {
  installRemovalAtInterruption();
  ++deferring;
}

InterruptionsDeferred::~InterruptionsDeferred() {
  if (--deferring == 0)
    if (const int signal = deferredSignal.exchange(0)) removeInFlightAndDie(signal);
}

void FileBatch::commit() {
  const InterruptionsDeferred deferred;
  // Each file replaced so far is put back where a later one's rename fails (another user's
  // file in a sticky folder, refused beforehand now; a folder made in its place during the run).
  std::vector<std::unique_ptr<KeptFile>> kept;
  for (size_t i = 0; i + 1 < staged_.size(); ++i) kept.push_back(std::make_unique<KeptFile>(staged_[i]->target));
  for (size_t i = 0; i < staged_.size(); ++i) {
    Staged& staged = *staged_[i];
    if (std::rename(staged.temporary.c_str(), staged.target.c_str()) != 0) {
      const std::string reason = std::strerror(errno);
      std::string replaced;
      for (size_t before = 0; before < i; ++before)
        if (!kept[before]->putBack()) replaced += "; " + staged_[before]->path + " was saved all the same";
      throw Error(staged.path + ": cannot write: renaming " + staged.temporary + " onto it failed (" + reason + ")" +
                  replaced);
    }
    staged.renamed = true;
  }
}

void writeAtomically(const std::string& path, const std::function<void(std::ostream&)>& write) {
  FileBatch batch;
  batch.add(path, write);
  batch.commit();
}

void requireWritable(const std::string& path) {
  requireFileName(path);
  if (isSpecialFile(path)) {
    struct stat special {};
    if (stat(path.c_str(), &special) == 0 && S_ISSOCK(special.st_mode))
      throw Error(path + ": cannot write: it is a socket");
    // A pipe is asked, not opened: its reader takes an open and close for the end of what it
    // reads, and then nothing reads the write after the run, which waited for one for ever.
    if (S_ISFIFO(special.st_mode) ? access(path.c_str(), W_OK) != 0
                                  : !std::ofstream(path, std::ios::binary | std::ios::app))
      throw Error(path + ": cannot write (" + std::strerror(errno) + ")");
    return;
  }
  std::remove(destinationOf(path).temporary.c_str());
}

struct TemporaryFile::RemovedIfInterrupted {
  explicit RemovedIfInterrupted(const std::string& path) : inFlight(path) {}
  InFlight inFlight;
};

TemporaryFile::TemporaryFile(const std::string& suffix) {
  std::error_code error;
  const std::filesystem::path folder = std::filesystem::temp_directory_path(error);
  if (error) throw Error("cannot find a folder for temporary files (" + error.message() + ")");
  const int fd = createUnique(folder, "lloydscope-", suffix, 0600, path_);
  if (fd < 0) throw Error(path_ + ": cannot make a temporary file (" + std::strerror(errno) + ")");
  close(fd);
  removedIfInterrupted_ = std::make_unique<RemovedIfInterrupted>(path_);
}

TemporaryFile::~TemporaryFile() { std::remove(path_.c_str()); }

std::string lowercaseExtension(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

bool sameFile(const std::string& a, const std::string& b) {
  if (a.empty() || b.empty()) return false;
  // weakly_canonical leaves a relative name of no file as it is ("x.off" against "/abs/x.off"),
  // and a link to a file not there yet as the link: a write goes to its target (targetOf),
  // where --record and -o, one through such a link, were both saved, the recording lost.
  const auto resolved = [](const std::string& path) {
    std::error_code ignored;
    std::filesystem::path target = path;
    try {
      target = targetOf(path);
    } catch (const Error&) {  // a loop of links: the input's reader or the writer says so, as such
    }
    return std::filesystem::weakly_canonical(std::filesystem::absolute(target, ignored), ignored);
  };
  return resolved(a) == resolved(b);
}

void makeFolder(const std::string& path) {
  std::error_code error;
  std::filesystem::create_directories(path, error);
  if (!error && !std::filesystem::is_directory(path, error)) error = std::make_error_code(std::errc::not_a_directory);
  if (error) throw Error(path + ": cannot make the folder (" + error.message() + ")");
}

namespace {
// "2 GB", "1 MB", "100 bytes".
std::string sizeText(std::uint64_t bytes) {
  char text[32];
  if (bytes >= 1000000000)
    std::snprintf(text, sizeof text, "%g GB", bytes / 1e9);
  else if (bytes >= 1000000)
    std::snprintf(text, sizeof text, "%g MB", bytes / 1e6);
  else
    std::snprintf(text, sizeof text, "%llu bytes", static_cast<unsigned long long>(bytes));
  return text;
}
}  // namespace

std::string readWhole(std::istream& in, const std::string& path, std::uint64_t mostBytes, const std::string& what) {
  const auto tooLarge = [&] {
    return Error(path + ": larger than " + sizeText(mostBytes) + ", more than " + what + " takes");
  };
  std::error_code ec;
  // A device never ends (/dev/zero) or blocks (a terminal): refused unread. A pipe is read.
  const std::filesystem::file_status status = std::filesystem::status(path, ec);
  if (!ec && (std::filesystem::is_character_file(status) || std::filesystem::is_block_file(status)))
    throw Error(path + ": is a device, not " + what);
  if (std::filesystem::is_regular_file(status) && std::filesystem::file_size(path, ec) > mostBytes && !ec)
    throw tooLarge();
  std::string data;
  char buffer[1 << 16];
  while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {
    data.append(buffer, static_cast<size_t>(in.gcount()));
    if (data.size() > mostBytes) throw tooLarge();
  }
  if (in.bad()) throw Error(path + ": cannot read the file (read error)");
  return data;
}

}  // namespace lloydscope
