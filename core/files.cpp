#include "files.h"

#include "mesh.h"

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace lloydscope {

namespace {

// Where a write goes: through a link to its target (renaming onto the link replaced it with a
// file and left the target as it was).
std::filesystem::path targetOf(const std::string& path) {
  std::error_code error;
  if (std::filesystem::is_symlink(path, error)) {
    std::filesystem::path target = std::filesystem::weakly_canonical(path, error);
    if (!error) return target;
  }
  return path;
}

// Says why no file could be made in the target's folder: a missing folder by its name, else the
// system's reason.
[[noreturn]] void cannotMake(const std::string& path, const std::filesystem::path& folder) {
  const std::string reason = std::strerror(errno);
  std::error_code ignored;
  if (!std::filesystem::exists(folder, ignored))
    throw Error(path + ": cannot write: there is no folder " + folder.string());
  throw Error(path + ": cannot write in " + folder.string() + " (" + reason + ")");
}

void requireNotAFolder(const std::string& path) {
  std::error_code ignored;
  if (std::filesystem::is_directory(path, ignored)) throw Error(path + ": cannot write: it is a folder");
}

// A new empty file beside `target`, of a name no other writer takes (made with O_EXCL): a fixed
// "<path>.tmp" deleted a user's file of that name, two runs writing one output shared it, and
// with a name near the system's limit it was too long. It gets the target's permissions, or
// those any new file gets (the umask's).
std::string makeTemporary(const std::string& path, const std::filesystem::path& target) {
  const std::filesystem::path folder = target.has_parent_path() ? target.parent_path() : ".";
  static std::atomic<unsigned> made{0};
  for (;;) {
    const std::string name =
        (folder / (".lloydscope-" + std::to_string(getpid()) + "-" + std::to_string(made++))).string();
    const int fd = open(name.c_str(), O_WRONLY | O_CREAT | O_EXCL, 0666);
    if (fd < 0 && errno == EEXIST) continue;  // another's, left by a run that was killed
    if (fd < 0) cannotMake(path, folder);
    struct stat existing;
    if (stat(target.c_str(), &existing) == 0) fchmod(fd, existing.st_mode & 07777);
    close(fd);
    return name;
  }
}

}  // namespace

void writeAtomically(const std::string& path, const std::function<void(std::ostream&)>& write) {
  requireNotAFolder(path);
  const std::filesystem::path target = targetOf(path);
  const std::string temporary = makeTemporary(path, target);
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out) {
      std::remove(temporary.c_str());
      throw Error(path + ": cannot write " + temporary);
    }
    try {
      write(out);
    } catch (...) {  // out of memory, say: no half-written temporary stays
      out.close();
      std::remove(temporary.c_str());
      throw;
    }
    out.close();
    if (!out) {  // the writer's own failure (the PNG encoder's), or the disk's
      std::remove(temporary.c_str());
      throw Error(path + ": cannot write " + temporary + " (disk full?)");
    }
  }
  if (std::rename(temporary.c_str(), target.c_str()) != 0) {
    const std::string reason = std::strerror(errno);
    std::remove(temporary.c_str());
    throw Error(path + ": cannot write: renaming " + temporary + " onto it failed (" + reason + ")");
  }
}

void requireWritable(const std::string& path) {
  requireNotAFolder(path);
  std::remove(makeTemporary(path, targetOf(path)).c_str());
}

bool sameFile(const std::string& a, const std::string& b) {
  if (a.empty() || b.empty()) return false;
  // weakly_canonical leaves a relative name of no file as it is ("x.off" against "/abs/x.off").
  const auto resolved = [](const std::string& path) {
    std::error_code ignored;
    return std::filesystem::weakly_canonical(std::filesystem::absolute(path, ignored), ignored);
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
  if (std::filesystem::is_regular_file(path, ec) && std::filesystem::file_size(path, ec) > mostBytes && !ec)
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
