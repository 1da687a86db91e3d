// Saving a file whole or not at all, and finding out before a long run that it cannot be saved.
#pragma once

#include <functional>
#include <ostream>
#include <string>

namespace lloydscope {

// Writes `path` through "<path>.tmp", renamed onto it once complete: a file already there is
// replaced whole or not at all. `write` fills the stream (binary). Throws Error("<path>: cannot
// write ...") saying why.
void writeAtomically(const std::string& path, const std::function<void(std::ostream&)>& write);

// Throws the Error writeAtomically would end with where "<path>.tmp" cannot be made (no such
// folder, no permission) or `path` is a folder: checked before a run that may take minutes.
// Leaves nothing behind.
void requireWritable(const std::string& path);

// Makes the folder `path` and the folders above it where missing. Throws Error("<path>: cannot
// make the folder (why)") where it cannot be made or is a file.
void makeFolder(const std::string& path);

}  // namespace lloydscope
