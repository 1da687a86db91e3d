#include "files.h"

#include "mesh.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>

namespace lloydscope {

namespace {

std::string temporaryOf(const std::string& path) { return path + ".tmp"; }

// Says why "<path>.tmp" could not be made: a missing folder by its name (the user never typed
// the temporary's), else the system's reason.
[[noreturn]] void cannotMake(const std::string& path, const std::string& temporary) {
  const std::string reason = std::strerror(errno);
  const std::filesystem::path folder = std::filesystem::path(path).parent_path();
  std::error_code ignored;
  if (!folder.empty() && !std::filesystem::exists(folder, ignored))
    throw Error(path + ": cannot write: there is no folder " + folder.string());
  throw Error(path + ": cannot write " + temporary + " (" + reason + ")");
}

void requireNotAFolder(const std::string& path) {
  std::error_code ignored;
  if (std::filesystem::is_directory(path, ignored)) throw Error(path + ": cannot write: it is a folder");
}

}  // namespace

void writeAtomically(const std::string& path, const std::function<void(std::ostream&)>& write) {
  requireNotAFolder(path);
  const std::string temporary = temporaryOf(path);
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out) cannotMake(path, temporary);
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
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    const std::string reason = std::strerror(errno);
    std::remove(temporary.c_str());
    throw Error(path + ": cannot write: renaming " + temporary + " onto it failed (" + reason + ")");
  }
}

void requireWritable(const std::string& path) {
  requireNotAFolder(path);
  const std::string temporary = temporaryOf(path);
  std::error_code ignored;
  // writeAtomically's own name: one already there (a run stopped before its rename) stays until then
  const bool there = std::filesystem::exists(temporary, ignored);
  if (!std::ofstream(temporary, std::ios::binary | std::ios::app)) cannotMake(path, temporary);
  if (!there) std::remove(temporary.c_str());
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
