#include "PublishOutputs.h"

#include "TemporaryFileRegistry.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace
{
// An output put in place, and where the file it replaced waits (empty: there was none).
struct Placed
{
  std::string Path, Aside;
};

// A second name for the regular file at `path`, so that it can come back if the group
// fails; anything else there (a folder, a link, a device) is refused with EPERM. A hard link keeps `path` in place meanwhile; where the file
// system has none, the file is moved aside.
bool KeepAside(const std::string& path, std::string& aside)
{
  struct stat information;
  aside.clear();
  if (lstat(path.c_str(), &information) != 0)
  {
    return errno == ENOENT; // nothing to keep
  }
  if (!S_ISREG(information.st_mode))
  {
    errno = EPERM; // a folder, a link, a device: not ours to replace
    return false;
  }
  for (int attempt = 0; attempt < 100; ++attempt)
  {
    aside = TemporaryName(path);
    if (link(path.c_str(), aside.c_str()) == 0 ||
      (errno != EEXIST && RenameWithoutReplacing(path, aside)))
    {
      return true;
    }
    if (errno != EEXIST)
    {
      return false;
    }
  }
  return false;
}

// The old file back at `output.Path`, or no file where there was none.
void PutBack(const Placed& output)
{
  if (output.Aside.empty())
  {
    unlink(output.Path.c_str());
    return;
  }
  // A rename between two links of one file does nothing: the second name goes then.
  std::rename(output.Aside.c_str(), output.Path.c_str());
  unlink(output.Aside.c_str());
}

void TakeBack(const std::vector<Placed>& placed)
{
  for (auto it = placed.rbegin(); it != placed.rend(); ++it)
  {
    PutBack(*it);
  }
}

std::string NotReplaced(const std::string& path)
{
  if (errno == EPERM)
  {
    return path + ": is not a regular file (a folder, a link or a device): not replaced";
  }
  return path + ": cannot replace the existing file (" + std::strerror(errno) + ")";
}

std::string Problem(const std::string& path, bool replace)
{
  if (!replace && errno == EEXIST)
  {
    return path + ": exists already, created while the program ran (use --force to overwrite)";
  }
  return path + ": cannot move the finished file into place (" + std::strerror(errno) + ")";
}
}

bool RenameWithoutReplacing(const std::string& from, const std::string& to)
{
  if (renameat2(AT_FDCWD, from.c_str(), AT_FDCWD, to.c_str(), RENAME_NOREPLACE) == 0)
  {
    return true;
  }
  if (errno != EINVAL && errno != ENOSYS)
  {
    return false;
  }
  // A file system without RENAME_NOREPLACE: link fails on an existing name just the same.
  if (link(from.c_str(), to.c_str()) != 0)
  {
    return false;
  }
  unlink(from.c_str());
  return true;
}

bool PublishOutputs(const std::vector<SafeOutputFile*>& files, bool replace, std::string& error)
{
  SignalsHeld held;
  std::vector<Placed> placed;
  for (SafeOutputFile* file : files)
  {
    Placed next{ file->Path(), "" };
    if (replace && !KeepAside(next.Path, next.Aside))
    {
      error = NotReplaced(next.Path);
      TakeBack(placed);
      return false;
    }
    const bool moved = replace ? std::rename(file->TemporaryPath().c_str(), next.Path.c_str()) == 0
                               : RenameWithoutReplacing(file->TemporaryPath(), next.Path);
    if (!moved)
    {
      error = Problem(next.Path, replace);
      if (!next.Aside.empty())
      {
        PutBack(next);
      }
      TakeBack(placed);
      return false;
    }
    file->Published();
    placed.push_back(next);
  }
  for (const auto& output : placed)
  {
    if (!output.Aside.empty())
    {
      unlink(output.Aside.c_str());
    }
  }
  return true;
}

namespace
{
// Into what is at `path` already, a device (/dev/stdout) or a link followed as ever.
bool WriteThrough(const std::string& path, const std::string& bytes, std::string& error)
{
  const int descriptor = open(path.c_str(), O_WRONLY | O_TRUNC | O_CLOEXEC);
  const bool written = descriptor >= 0 && WriteAll(descriptor, bytes.data(), bytes.size());
  const int reason = errno;
  if (descriptor >= 0 && close(descriptor) != 0 && written)
  {
    error = path + ": cannot write the file (" + std::strerror(errno) + ")";
    return false;
  }
  if (!written)
  {
    error = path + ": cannot write the file (" + std::strerror(reason) + ")";
  }
  return written;
}
}

bool ReplaceFile(const std::string& path, const std::string& bytes, std::string& error)
{
  struct stat information;
  if (lstat(path.c_str(), &information) == 0 && !S_ISREG(information.st_mode))
  {
    return WriteThrough(path, bytes, error);
  }
  SafeOutputFile file(path);
  return file.Open(error) && file.Write(bytes, error) && file.Close(error) &&
    PublishOutputs({ &file }, true, error);
}
