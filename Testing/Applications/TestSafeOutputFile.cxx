// SafeOutputFile, PublishOutputs and TemporaryFileRegistry on their own: what is planted at
// a name is never followed, a name that appeared is never replaced without `replace`, a
// failed group is taken back, and a signal removes the temporaries.
// Usage: TestSafeOutputFile WORK_FOLDER (emptied first)
#include "PublishOutputs.h"
#include "SafeOutputFile.h"
#include "TemporaryFileRegistry.h"

#include <chrono>
#include <csignal>
#include <dirent.h>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <set>
#include <sstream>
#include <string>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

namespace
{
int Failures = 0;
std::string Work;

void Check(bool condition, const std::string& what)
{
  if (!condition)
  {
    std::printf("FAILED: %s\n", what.c_str());
    ++Failures;
  }
}

std::string At(const std::string& name)
{
  return Work + "/" + name;
}

std::string Read(const std::string& path)
{
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

void Put(const std::string& path, const std::string& text)
{
  std::ofstream(path) << text;
}

bool Exists(const std::string& path)
{
  struct stat information;
  return lstat(path.c_str(), &information) == 0;
}

// Files in the work folder whose name holds ".partial-".
int Temporaries()
{
  int count = 0;
  DIR* folder = opendir(Work.c_str());
  while (const dirent* entry = folder ? readdir(folder) : nullptr)
  {
    count += std::string(entry->d_name).find(".partial-") != std::string::npos;
  }
  if (folder)
  {
    closedir(folder);
  }
  return count;
}

// A finished temporary for `path` holding `text`.
bool Finished(SafeOutputFile& file, const std::string& text)
{
  std::string error;
  return file.Open(error) && file.Write(text, error) && file.Close(error);
}

// Runs `body` in a child process; its wait status.
int InChild(const std::function<void()>& body)
{
  const pid_t child = fork();
  if (child == 0)
  {
    body();
    _exit(0);
  }
  int status = 0;
  waitpid(child, &status, 0);
  return status;
}

void NamesAreFreshAndUnpredictable()
{
  std::set<std::string> names;
  for (int i = 0; i < 1000; ++i)
  {
    names.insert(TemporaryName(At("out.vtp")));
  }
  Check(names.size() == 1000, "1000 temporary names, all different");
  const std::string name = *names.begin();
  Check(name.rfind(At("out.vtp.partial-"), 0) == 0 && name.size() == At("out.vtp.partial-").size() + 12,
    "the temporary is out.vtp.partial- and 12 characters in the output's folder: " + name);
  // A file name at the file system's limit still gets a temporary in the same folder.
  const std::string longName = At(std::string(250, 'n') + ".csv");
  const std::string shorter = TemporaryName(longName);
  Check(shorter.rfind(Work + "/", 0) == 0 && shorter.size() - Work.size() - 1 <= 255,
    "a temporary for a 254-character name fits the limit: " + shorter);
}

void PlantedNamesAreNeverFollowed()
{
  Put(At("victim"), "precious");
  symlink(At("victim").c_str(), At("link").c_str());
  Check(CreateExclusive(At("link")) < 0, "a symbolic link is not opened");
  symlink(At("nowhere").c_str(), At("dangling").c_str());
  Check(CreateExclusive(At("dangling")) < 0 && !Exists(At("nowhere")),
    "a dangling symbolic link is not followed to create its target");
  mkdir(At("folder").c_str(), 0755);
  Check(CreateExclusive(At("folder")) < 0, "a folder is not opened");
  Check(Read(At("victim")) == "precious", "the file a link points to is untouched");
}

void NothingIsReplacedThatAppeared()
{
  SafeOutputFile mesh(At("a.vtp")), csv(At("a.csv"));
  Check(Finished(mesh, "mesh") && Finished(csv, "csv"), "two temporaries written");
  Put(At("a.csv"), "the user's"); // appears while the program runs
  std::string error;
  Check(!PublishOutputs({ &mesh, &csv }, false, error), "publishing over a new file fails");
  Check(error.find("a.csv") != std::string::npos && error.find("exists already") != std::string::npos,
    "the message names the file that appeared: " + error);
  Check(Read(At("a.csv")) == "the user's", "the file that appeared is intact");
  Check(!Exists(At("a.vtp")), "the output already placed is taken back");
}

void ReplacingPutsTheOldFilesBack()
{
  Put(At("b.vtp"), "old mesh");
  mkdir(At("b.csv").c_str(), 0755); // the CSV cannot follow
  SafeOutputFile mesh(At("b.vtp")), csv(At("b.csv"));
  Check(Finished(mesh, "new mesh") && Finished(csv, "new csv"), "two temporaries written");
  std::string error;
  Check(!PublishOutputs({ &mesh, &csv }, true, error), "replacing a folder fails");
  Check(Read(At("b.vtp")) == "old mesh", "the replaced mesh is back: " + Read(At("b.vtp")));
  rmdir(At("b.csv").c_str());
  SafeOutputFile mesh2(At("b.vtp")), csv2(At("b.csv"));
  Check(Finished(mesh2, "new mesh") && Finished(csv2, "new csv"), "two temporaries written");
  Check(PublishOutputs({ &mesh2, &csv2 }, true, error), "replacing: " + error);
  Check(Read(At("b.vtp")) == "new mesh" && Read(At("b.csv")) == "new csv", "both replaced");
  // The failed group's CSV, never moved, waits for its object; no second name is left.
  Check(Temporaries() == 1, "replacing leaves no second name behind: " + std::to_string(Temporaries()));
  // Only regular files are replaced: a link stays, and so does the file it points to.
  Put(At("target"), "kept");
  symlink(At("target").c_str(), At("h.vtp").c_str());
  SafeOutputFile linked(At("h.vtp"));
  Check(Finished(linked, "new"), "a temporary written");
  Check(!PublishOutputs({ &linked }, true, error) && error.find("not a regular file") != std::string::npos,
    "a link is not replaced: " + error);
  Check(Read(At("target")) == "kept" && Exists(At("h.vtp")), "the link and its file stay");
}

void ReplaceFileKeepsTheOldOneOnFailure()
{
  Put(At("i.csv"), "old");
  std::string error;
  Check(ReplaceFile(At("i.csv"), "new", error) && Read(At("i.csv")) == "new", "ReplaceFile: " + error);
  const int status = InChild([]() {
    signal(SIGXFSZ, SIG_IGN);
    const rlimit limit{ 10, 10 };
    setrlimit(RLIMIT_FSIZE, &limit);
    std::string error;
    _exit(ReplaceFile(At("i.csv"), std::string(100, 'x'), error) ? 3 : 0);
  });
  Check(WIFEXITED(status) && WEXITSTATUS(status) == 0, "ReplaceFile fails under a size limit");
  Check(Read(At("i.csv")) == "new" && Temporaries() == 0, "a failed ReplaceFile leaves the old file");
}

void WriteErrorsAreReported()
{
  // A file size limit (its signal ignored) stands for a full disk: write fails with EFBIG.
  const int status = InChild([]() {
    signal(SIGXFSZ, SIG_IGN);
    const rlimit limit{ 10, 10 };
    setrlimit(RLIMIT_FSIZE, &limit);
    SafeOutputFile file(At("g.csv"));
    std::string error;
    const bool opened = file.Open(error);
    const std::string temporary = file.TemporaryPath();
    const bool failed = opened && !file.Write(std::string(100, 'x'), error);
    const bool named = error.find("g.csv: cannot write the file (File too large)") != std::string::npos;
    _exit(!opened ? 3 : !failed ? 4 : !named ? 5 : Exists(temporary) ? 6 : 0);
  });
  Check(WIFEXITED(status) && WEXITSTATUS(status) == 0,
    "a failed write is reported and its temporary removed: status " + std::to_string(status));
  Check(Temporaries() == 0 && !Exists(At("g.csv")), "a failed write leaves nothing");
}

void SignalsRemoveTemporaries()
{
  for (int signal : { SIGINT, SIGTERM, SIGHUP, SIGXFSZ })
  {
    const int status = InChild([signal]() {
      SafeOutputFile file(At("d.vtp"));
      std::string error;
      file.Open(error);
      file.Write("half", 4, error);
      raise(signal);
    });
    Check(WIFSIGNALED(status) && WTERMSIG(status) == signal,
      "signal " + std::to_string(signal) + " still ends the program by that signal");
    Check(Temporaries() == 0, "signal " + std::to_string(signal) + " leaves no temporary");
  }
  // Sent to the process while the writing thread holds it: another thread takes it,
  // passes it on, and it waits until the renames are done.
  const int status = InChild([]() {
    std::thread idle([]() { std::this_thread::sleep_for(std::chrono::seconds(5)); });
    idle.detach();
    SafeOutputFile file(At("e.vtp"));
    std::string error;
    file.Open(error);
    {
      SignalsHeld held;
      kill(getpid(), SIGTERM);
      std::this_thread::sleep_for(std::chrono::milliseconds(200));
      if (!Exists(file.TemporaryPath()))
      {
        _exit(3); // removed while held
      }
    }
    std::this_thread::sleep_for(std::chrono::seconds(2));
    _exit(4); // not ended by the signal
  });
  Check(WIFSIGNALED(status) && WTERMSIG(status) == SIGTERM,
    "a held SIGTERM ends the program after the hold, status " + std::to_string(status));
  Check(Temporaries() == 0, "a held SIGTERM leaves no temporary");
  // Ignored by whoever started the program: stays ignored.
  const int ignored = InChild([]() {
    signal(SIGHUP, SIG_IGN);
    SafeOutputFile file(At("f.vtp"));
    std::string error;
    file.Open(error);
    raise(SIGHUP);
  });
  Check(WIFEXITED(ignored) && WEXITSTATUS(ignored) == 0, "an ignored SIGHUP stays ignored");
}
}

int main(int argc, char* argv[])
{
  if (argc != 2)
  {
    std::fprintf(stderr, "usage: TestSafeOutputFile WORK_FOLDER\n");
    return 2;
  }
  Work = argv[1];
  std::system(("rm -rf '" + Work + "' && mkdir -p '" + Work + "'").c_str());
  NamesAreFreshAndUnpredictable();
  PlantedNamesAreNeverFollowed();
  NothingIsReplacedThatAppeared();
  ReplacingPutsTheOldFilesBack();
  WriteErrorsAreReported();
  ReplaceFileKeepsTheOldOneOnFailure();
  SignalsRemoveTemporaries();
  Check(Temporaries() == 0, "no temporary left at the end");
  std::printf("%d failed\n", Failures);
  return Failures ? 1 : 0;
}
