#include "files.h"
#include "mesh.h"
#include "test_support.h"

#include <csignal>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <future>
#include <iostream>
#include <sstream>
#include <thread>

#include <fcntl.h>
#include <grp.h>
#include <sys/socket.h>
#include <sys/un.h>
#include <sys/wait.h>
#include <sys/stat.h>
#include <unistd.h>

using namespace lloydscope;

namespace {
bool exists(const std::string& path) { return std::filesystem::exists(path); }

// The Error's text, or "" where `f` threw none.
template <class F>
std::string errorOf(F f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST(Files, RequireWritableSaysWhyBeforehandAndLeavesNothingBehind) {
  const std::string here = test::emptyFolder("writable");
  EXPECT_EQ(errorOf([&] { requireWritable(here + "/fine.off"); }), "");
  EXPECT_TRUE(test::filesIn(here).empty());

  const std::string missing = test::tempPath("no_such_folder") + "/x.off";
  const std::string why = errorOf([&] { requireWritable(missing); });
  // The folder by its name, not the temporary the user never typed ("x.off.tmp (No such file ...)")
  EXPECT_EQ(why, missing + ": cannot write: there is no folder " + test::tempPath("no_such_folder")) << why;

  const std::string folder = test::tempPath("a_folder.off");
  std::filesystem::create_directory(folder);
  EXPECT_EQ(errorOf([&] { requireWritable(folder); }), folder + ": cannot write: it is a folder");
  EXPECT_EQ(errorOf([&] { writeAtomically(folder, [](std::ostream& out) { out << "x"; }); }),
            folder + ": cannot write: it is a folder");
  std::filesystem::remove(folder);
}

TEST(Files, WriteAtomicallyReplacesAFileWholeOrNotAtAll) {
  const std::string here = test::emptyFolder("whole");
  const std::string path = here + "/whole.txt";
  writeAtomically(path, [](std::ostream& out) { out << "first"; });
  EXPECT_EQ(test::readText(path), "first");
  writeAtomically(path, [](std::ostream& out) { out << "second"; });
  EXPECT_EQ(test::readText(path), "second");
  // A writer that fails half-way: the file keeps what it had, and no temporary stays.
  const std::string why = errorOf([&] {
    writeAtomically(path, [](std::ostream& out) {
      out << "thi";
      out.setstate(std::ios::failbit);
    });
  });
  EXPECT_EQ(why.rfind(path + ": cannot write", 0), 0u) << why;
  EXPECT_EQ(test::readText(path), "second");
  EXPECT_EQ(test::filesIn(here), std::vector<std::string>{"whole.txt"});  // no temporary stays
}

// Files saved together are all replaced or none: a second that fails to write leaves the
// first as it was (remesh -o on a full disk replaced the --record file it had saved first).
TEST(Files, ABatchReplacesAllOfItsFilesOrNone) {
  const std::string here = test::emptyFolder("batch");
  const std::string first = here + "/first.txt", second = here + "/second.txt";
  test::writeText(first, "old first");
  test::writeText(second, "old second");
  const std::string why = errorOf([&] {
    FileBatch batch;
    batch.add(first, [](std::ostream& out) { out << "new first"; });
    batch.add(second, [](std::ostream& out) { out.setstate(std::ios::failbit); });
    batch.commit();
  });
  EXPECT_EQ(why.rfind(second + ": cannot write", 0), 0u) << why;
  EXPECT_EQ(test::readText(first), "old first");
  EXPECT_EQ(test::filesIn(here), (std::vector<std::string>{"first.txt", "second.txt"}));  // no temporary stays
  {
    FileBatch batch;  // never committed: nothing replaced either
    batch.add(first, [](std::ostream& out) { out << "new first"; });
  }
  EXPECT_EQ(test::readText(first), "old first");
  EXPECT_EQ(test::filesIn(here), (std::vector<std::string>{"first.txt", "second.txt"}));
  FileBatch batch;
  batch.add(first, [](std::ostream& out) { out << "new first"; });
  batch.add(second, [](std::ostream& out) { out << "new second"; });
  EXPECT_EQ(test::readText(first), "old first");  // until the commit
  batch.commit();
  EXPECT_EQ(test::readText(first), "new first");
  EXPECT_EQ(test::readText(second), "new second");
  EXPECT_EQ(test::filesIn(here), (std::vector<std::string>{"first.txt", "second.txt"}));
}

// Where the second file's rename fails at the commit (here a folder made in its place during the
// run), the first, renamed already, is put back: it stayed replaced, the second not.
TEST(Files, ABatchWhoseSecondRenameFailsPutsTheFirstBack) {
  const std::string here = test::emptyFolder("batch_put_back");
  const std::string first = here + "/first.txt", second = here + "/second.txt", made = here + "/made.txt";
  test::writeText(first, "old first");
  const std::string why = errorOf([&] {
    FileBatch batch;
    batch.add(made, [](std::ostream& out) { out << "new made"; });  // not there before: removed again
    batch.add(first, [](std::ostream& out) { out << "new first"; });
    batch.add(second, [](std::ostream& out) { out << "new second"; });
    std::filesystem::create_directories(second + "/inside");
    batch.commit();
  });
  EXPECT_EQ(why.rfind(second + ": cannot write: renaming ", 0), 0u) << why;
  EXPECT_EQ(why.find("saved all the same"), std::string::npos) << why;  // every file put back
  EXPECT_EQ(test::readText(first), "old first");
  EXPECT_EQ(test::filesIn(here), (std::vector<std::string>{"first.txt", "second.txt"}));  // nothing kept stays
}

// The temporary is a name of its own beside the file: a user's "<name>.tmp" was deleted, and a
// name near the system's limit (255) could not take ".tmp". The file keeps its permissions, and
// a link is written through to its target, not replaced by a file.
TEST(Files, WriteAtomicallyTouchesNoOtherFileAndKeepsLinksAndPermissions) {
  namespace fs = std::filesystem;
  const std::string here = test::emptyFolder("atomic");
  test::writeText(here + "/out.off.tmp", "precious");
  writeAtomically(here + "/out.off", [](std::ostream& out) { out << "mesh"; });
  EXPECT_EQ(test::readText(here + "/out.off.tmp"), "precious");
  EXPECT_EQ(test::filesIn(here), (std::vector<std::string>{"out.off", "out.off.tmp"}));

  const std::string longName = here + "/" + std::string(250, 'n') + ".off";  // 254 characters
  EXPECT_EQ(errorOf([&] { requireWritable(longName); }), "");
  writeAtomically(longName, [](std::ostream& out) { out << "long"; });
  EXPECT_EQ(test::readText(longName), "long");

  fs::create_directory(here + "/real");
  test::writeText(here + "/real/target.off", "old");
  fs::create_symlink("real/target.off", here + "/link.off");
  writeAtomically(here + "/link.off", [](std::ostream& out) { out << "new"; });
  EXPECT_TRUE(fs::is_symlink(here + "/link.off"));
  EXPECT_EQ(test::readText(here + "/real/target.off"), "new");
  // A link to a file not there yet makes the file, and stays a link (it was replaced by it).
  fs::create_symlink("real/later.off", here + "/dangling.off");
  writeAtomically(here + "/dangling.off", [](std::ostream& out) { out << "made"; });
  EXPECT_TRUE(fs::is_symlink(here + "/dangling.off"));
  EXPECT_EQ(test::readText(here + "/real/later.off"), "made");
  // A loop of links is refused, and stays (it was replaced by a file, exit 0).
  fs::create_symlink("loop_b.off", here + "/loop_a.off");
  fs::create_symlink("loop_a.off", here + "/loop_b.off");
  EXPECT_EQ(test::errorOf([&] { writeAtomically(here + "/loop_a.off", [](std::ostream& out) { out << "x"; }); }, "written"),
            here + "/loop_a.off: cannot write: Too many levels of symbolic links");
  EXPECT_TRUE(fs::is_symlink(here + "/loop_a.off"));

  fs::permissions(here + "/out.off", fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
  // While written, the new contents are the owner's alone (they were readable by anyone until
  // the last moment, a private file's too).
  fs::perms whileWritten = fs::perms::unknown;
  writeAtomically(here + "/out.off", [&](std::ostream& out) {
    out << "again";
    for (const auto& entry : fs::directory_iterator(here))
      if (entry.path().filename().string().rfind(".lloydscope-", 0) == 0) whileWritten = entry.status().permissions();
  });
  EXPECT_EQ(whileWritten, fs::perms::owner_read | fs::perms::owner_write);
  EXPECT_EQ(fs::status(here + "/out.off").permissions(), fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read);
  // A new file is readable as any the user makes (mkstemp's own are private).
  EXPECT_NE(fs::status(longName).permissions() & fs::perms::others_read, fs::perms::none);
}

namespace {

// Runs `check` in a child process as a user other than root (root may write anything): as
// nobody where the tests run as root. 0: it held; 1: it did not; 3: there is no other user who
// reaches `folder`. The child ends with _exit: exit() would run the static destructor that
// removes this process's temporary folder.
int exitOfAsAnotherUser(const std::string& folder, const std::function<bool()>& check) {
  const pid_t child = fork();
  if (child < 0) return 1;
  if (child == 0) {
    if (geteuid() == 0 && (setgroups(0, nullptr) != 0 || setgid(65534) != 0 || setuid(65534) != 0)) _exit(3);
    if (access(folder.c_str(), W_OK | X_OK) != 0) _exit(3);
    _exit(check() ? 0 : 1);
  }
  int status = 0;
  if (waitpid(child, &status, 0) != child || !WIFEXITED(status)) return 1;
  return WEXITSTATUS(status);
}

}  // namespace

// A file its owner may not write (read-only) is refused before the run, saying why, and stays
// as it was: its folder let it be replaced, and it was tried after the run, failing with a
// message naming a temporary already gone and no reason.
TEST(Files, AReadOnlyFileIsRefusedBeforehandSayingWhy) {
  namespace fs = std::filesystem;
  const std::string here = test::emptyFolder("read_only"), path = here + "/kept.off";
  fs::permissions(here, fs::perms::all);  // anyone may make files here
  test::writeText(path, "old");
  fs::permissions(path, fs::perms::owner_read | fs::perms::group_read | fs::perms::others_read);
  const std::string refused = path + ": cannot write (Permission denied)";
  const int status = exitOfAsAnotherUser(here, [&] {
    const std::string before = errorOf([&] { requireWritable(path); });
    const std::string after = errorOf([&] { writeAtomically(path, [](std::ostream& out) { out << "new"; }); });
    std::cerr << before << "|" << after << "\n";
    return before == refused && after == refused;
  });
  if (status == 3) GTEST_SKIP() << "no other user to run as who reaches " << here;
  EXPECT_EQ(status, 0);
  EXPECT_EQ(test::readText(path), "old");
  EXPECT_EQ(test::filesIn(here), std::vector<std::string>{"kept.off"});
}

// Another user's file in a folder with the sticky bit (/tmp) may be written but not replaced:
// refused before the run. It was refused at the rename after the run, and `remesh --record A
// -o B` had replaced A by then, B kept: not both or neither.
TEST(Files, AnotherUsersFileInAStickyFolderIsRefusedBeforehand) {
  namespace fs = std::filesystem;
  const std::string here = test::emptyFolder("sticky"), path = here + "/shared.off";
  fs::permissions(here, fs::perms::all | fs::perms::sticky_bit);
  test::writeText(path, "old");
  fs::permissions(path, fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read |
                            fs::perms::group_write | fs::perms::others_read | fs::perms::others_write);
  const std::string refused =
      path + ": cannot write: it is another user's, in a folder where only its owner may replace it";
  const int status = exitOfAsAnotherUser(here, [&] {
    const std::string before = errorOf([&] { requireWritable(path); });
    std::cerr << before << "\n";
    return before == refused;
  });
  if (status == 3 || geteuid() != 0) GTEST_SKIP() << "no other user to run as who reaches " << here;
  EXPECT_EQ(status, 0);
  EXPECT_EQ(test::readText(path), "old");
}

// A link and the file it will make are one file: --record and -o, one through such a link, were
// both saved onto it, the recording lost.
TEST(Files, ALinkToAFileNotThereYetIsThatFile) {
  namespace fs = std::filesystem;
  const std::string here = test::emptyFolder("same_file");
  fs::create_symlink("target.off", here + "/link.off");
  EXPECT_TRUE(sameFile(here + "/link.off", here + "/target.off"));
  EXPECT_FALSE(sameFile(here + "/link.off", here + "/other.off"));
  fs::create_symlink("link.off", here + "/link_to_link.off");
  EXPECT_TRUE(sameFile(here + "/link_to_link.off", here + "/target.off"));
  // A loop of links is no file to compare, not an error of writing: remesh of one as its input
  // said "cannot write" before it was read.
  fs::create_symlink("loop.off", here + "/loop.off");
  EXPECT_EQ(errorOf([&] { EXPECT_FALSE(sameFile(here + "/loop.off", here + "/target.off")); }), "");
}

// A pipe (or a device, or a link to one) is written into, not replaced by a plain file: as root
// `--record /dev/null` replaced /dev/null itself.
TEST(Files, ASpecialFileIsWrittenIntoNotReplaced) {
  namespace fs = std::filesystem;
  const std::string here = test::emptyFolder("special"), fifo = here + "/pipe.off", link = here + "/link.off";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0666), 0);
  fs::create_symlink("pipe.off", link);
  const int reader = open(fifo.c_str(), O_RDONLY | O_NONBLOCK);  // so that writing does not wait
  ASSERT_GE(reader, 0);
  EXPECT_EQ(errorOf([&] { requireWritable(link); }), "");
  writeAtomically(link, [](std::ostream& out) { out << "mesh"; });
  EXPECT_TRUE(fs::is_fifo(fifo));
  EXPECT_TRUE(fs::is_symlink(link));
  char got[16] = {};
  EXPECT_EQ(read(reader, got, sizeof got), 4);
  EXPECT_EQ(std::string(got), "mesh");
  close(reader);
  EXPECT_EQ(test::filesIn(here), (std::vector<std::string>{"link.off", "pipe.off"}));  // no temporary
}

// The check before a run opens no pipe: a reader (`cat pipe.off`) took its open and close for
// the end of what it would read and left, and the write after the run then waited for ever.
TEST(Files, TheCheckBeforeARunLeavesAPipesReaderWaiting) {
  const std::string fifo = test::emptyFolder("pipe_reader") + "/pipe.off";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0666), 0);
  std::promise<std::string> read;
  std::future<std::string> got = read.get_future();
  std::thread reader([&] {
    const int fd = open(fifo.c_str(), O_RDONLY);  // waits for a writer
    std::string text;
    char buffer[16];
    for (ssize_t n; (n = ::read(fd, buffer, sizeof buffer)) > 0;) text.append(buffer, static_cast<size_t>(n));
    close(fd);
    read.set_value(text);
  });
  EXPECT_EQ(errorOf([&] { requireWritable(fifo); }), "");
  if (got.wait_for(std::chrono::milliseconds(300)) == std::future_status::ready) {
    ADD_FAILURE() << "the check ended the reader's stream, before the write, with \"" << got.get() << "\"";
  } else {
    writeAtomically(fifo, [](std::ostream& out) { out << "mesh"; });
    EXPECT_EQ(got.get(), "mesh");
  }
  reader.join();
}

// A socket, which no file can be written into (its open fails), is refused before the run: the
// pipe's check, which asks rather than opens, let it through to fail after the run.
TEST(Files, ASocketIsRefusedBeforehand) {
  const std::string path = test::emptyFolder("socket") + "/sock.off";
  const int fd = socket(AF_UNIX, SOCK_STREAM, 0);
  ASSERT_GE(fd, 0);
  sockaddr_un address{};
  address.sun_family = AF_UNIX;
  ASSERT_LT(path.size(), sizeof address.sun_path);
  std::strcpy(address.sun_path, path.c_str());
  ASSERT_EQ(bind(fd, reinterpret_cast<const sockaddr*>(&address), sizeof address), 0);
  EXPECT_EQ(errorOf([&] { requireWritable(path); }), path + ": cannot write: it is a socket");
  close(fd);
}

// No name, or one longer than the system takes, is refused before a run, not after it.
TEST(Files, ANameNoFileCanHaveIsRefusedBeforehand) {
  EXPECT_EQ(errorOf([] { requireWritable(""); }), "cannot write a file of no name (an empty name was given)");
  const std::string here = test::emptyFolder("long_names"), name = here + "/" + std::string(300, 'n') + ".off";
  EXPECT_EQ(errorOf([&] { requireWritable(name); }),
            name + ": cannot write: its name is 304 bytes long, more than a file name may be here (255)");
  // A path longer than the system takes was said to be in "no folder ././...", which was there.
  std::string deep = here;
  while (deep.size() < 5000) deep += "/.";
  deep += "/x.off";
  EXPECT_EQ(errorOf([&] { requireWritable(deep); }), deep + ": cannot write (File name too long)");
}

// Interrupted while writing (Ctrl+C), the run leaves no temporary behind, and the file as it was.
TEST(Files, AnInterruptedWriteLeavesNoTemporary) {
  const std::string here = test::emptyFolder("interrupted"), path = here + "/out.off";
  test::writeText(path, "old");
  EXPECT_EXIT(writeAtomically(path, [](std::ostream& out) {
                out << "half" << std::flush;
                std::raise(SIGINT);
              }),
              ::testing::KilledBySignal(SIGINT), "");
  EXPECT_EQ(test::filesIn(here), std::vector<std::string>{"out.off"});
  EXPECT_EQ(test::readText(path), "old");
}

// A batch of many files (a picture sequence: one per iteration) interrupted before it commits
// leaves none of its temporaries behind: the run kept the names of four at most, and Ctrl+C in
// a sequence of 40 pictures left 36 hidden files of 400 KB each.
TEST(Files, AnInterruptedBatchOfManyFilesLeavesNoTemporary) {
  const std::string here = test::emptyFolder("interrupted_batch");
  test::writeText(here + "/pic_0.png", "old");
  EXPECT_EXIT(
      {
        FileBatch batch;
        for (int i = 0; i < 40; ++i)
          batch.add(here + "/pic_" + std::to_string(i) + ".png", [](std::ostream& out) { out << "new"; });
        std::raise(SIGINT);
      },
      ::testing::KilledBySignal(SIGINT), "");
  EXPECT_EQ(test::filesIn(here), std::vector<std::string>{"pic_0.png"});
  EXPECT_EQ(test::readText(here + "/pic_0.png"), "old");
}

// Ctrl+C while a batch commits waits for its renames: between two, it left the first file
// replaced, the second old, and the second name that would have put the first back removed.
// The run ends by the signal once they are done.
TEST(Files, AnInterruptionWaitsForTheRenamesOfABatch) {
  EXPECT_EXIT(
      {
        {
          const InterruptionsDeferred deferred;
          std::raise(SIGINT);
          std::fprintf(stderr, "renamed\n");
        }
        std::_Exit(0);
      },
      ::testing::KilledBySignal(SIGINT), "renamed");
}

// A signal the run was started to ignore (SIGHUP under nohup) stays ignored: the handler that
// removes the temporaries took it over, and `nohup lloydscope ...` ended when its terminal closed.
TEST(Files, AnIgnoredHangupStaysIgnored) {
  const std::string style = GTEST_FLAG_GET(death_test_style);
  GTEST_FLAG_SET(death_test_style, "threadsafe");  // a child of its own, the handlers not yet set
  EXPECT_EXIT(
      {
        std::signal(SIGHUP, SIG_IGN);
        const TemporaryFile file(".x");
        std::raise(SIGHUP);
        std::_Exit(0);
      },
      ::testing::ExitedWithCode(0), "");
  GTEST_FLAG_SET(death_test_style, style);
}

// A temporary file of the system's folder goes with its owner, at an error or a Ctrl+C: `bench
// --lloyd-step` left /tmp/lloydscope-<pid>-0.lsrec behind at each.
TEST(Files, ATemporaryFileGoesEvenWhenTheRunIsInterrupted) {
  const std::string here = test::emptyFolder("temporary_files");
  const char* before = std::getenv("TMPDIR");
  const std::string kept = before ? before : "";
  setenv("TMPDIR", here.c_str(), 1);
  {
    const TemporaryFile file(".lsrec");
    EXPECT_EQ(test::filesIn(here).size(), 1u);
    EXPECT_EQ(file.path().substr(file.path().size() - 6), ".lsrec");
  }
  EXPECT_TRUE(test::filesIn(here).empty());
  EXPECT_EXIT(
      {
        const TemporaryFile file(".lsrec");
        std::raise(SIGINT);
      },
      ::testing::KilledBySignal(SIGINT), "");
  EXPECT_TRUE(test::filesIn(here).empty());
  if (before) setenv("TMPDIR", kept.c_str(), 1); else unsetenv("TMPDIR");
}

TEST(Files, MakeFolderMakesTheFoldersAboveAndRefusesAFile) {
  const std::string top = test::tempPath("made");
  EXPECT_EQ(errorOf([&] { makeFolder(top + "/inner"); }), "");
  EXPECT_TRUE(std::filesystem::is_directory(top + "/inner"));
  EXPECT_EQ(errorOf([&] { makeFolder(top + "/inner"); }), "");  // already there
  const std::string file = top + "/a_file";
  test::writeText(file, "x");
  const std::string why = errorOf([&] { makeFolder(file); });
  EXPECT_EQ(why.rfind(file + ": cannot make the folder (", 0), 0u) << why;
  std::filesystem::remove_all(top);
}

// A file is read whole up to a size: a larger one is refused before it is read, and a stream
// that never ends (a link to /dev/zero, read as a mesh, grew until memory ran out) once it
// passes the size; a device (/dev/zero by its own name: 4 GB were read before the refusal) is
// refused unread.
TEST(Files, ReadWholeStopsAtItsSize) {
  const std::string path = test::tempPath("hundred.off");
  test::writeText(path, std::string(100, 'x'));
  std::ifstream file(path, std::ios::binary);
  EXPECT_EQ(errorOf([&] { readWhole(file, path, 99, "a mesh file"); }), path + ": larger than 99 bytes, more than a mesh file takes");
  EXPECT_EQ(file.tellg(), 0);  // refused by its size, unread
  EXPECT_EQ(readWhole(file, path, 100, "a mesh file"), std::string(100, 'x'));
  std::ifstream zero("/dev/zero", std::ios::binary);
  EXPECT_EQ(errorOf([&] { readWhole(zero, "z.off", 1000000, "a mesh file"); }),
            "z.off: larger than 1 MB, more than a mesh file takes");
  std::ifstream device("/dev/zero", std::ios::binary);
  EXPECT_EQ(errorOf([&] { readWhole(device, "/dev/zero", 1000000, "a mesh file"); }),
            "/dev/zero: is a device, not a mesh file");
  EXPECT_EQ(device.tellg(), 0);  // unread
  std::istringstream small("abc");
  EXPECT_EQ(readWhole(small, "s.off", 3, "a mesh file"), "abc");
}
