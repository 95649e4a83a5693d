#include "SafeOutputFile.h"

#include "TemporaryFileRegistry.h"

#include <cerrno>
#include <climits>
#include <cstring>
#include <fcntl.h>
#include <random>
#include <sys/random.h>
#include <unistd.h>

namespace
{
std::string RandomLetters(int count)
{
  static const char Alphabet[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789";
  unsigned char bytes[64];
  if (getrandom(bytes, count, 0) != count)
  {
    std::random_device device; // the kernel's generator too, through another door
    for (int i = 0; i < count; ++i)
    {
      bytes[i] = static_cast<unsigned char>(device());
    }
  }
  std::string letters;
  for (int i = 0; i < count; ++i)
  {
    letters += Alphabet[bytes[i] % (sizeof(Alphabet) - 1)];
  }
  return letters;
}

std::string Problem(const std::string& path, const char* what)
{
  return path + ": " + what + " (" + std::strerror(errno) + ")";
}
}

std::string TemporaryName(const std::string& path)
{
  const auto slash = path.find_last_of('/');
  const std::string folder = slash == std::string::npos ? "" : path.substr(0, slash + 1);
  std::string name = slash == std::string::npos ? path : path.substr(slash + 1);
  const std::string suffix = ".partial-" + RandomLetters(12);
  if (name.size() + suffix.size() > NAME_MAX)
  {
    name = ".mobius"; // the long name is not needed: the temporary is only ours
  }
  return folder + name + suffix;
}

int CreateExclusive(const std::string& path)
{
  return open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
}

SafeOutputFile::SafeOutputFile(std::string path)
  : Final(std::move(path))
{
}

SafeOutputFile::~SafeOutputFile()
{
  this->Discard();
}

bool SafeOutputFile::Open(std::string& error)
{
  // A name that exists (unlikely with 71 random bits, or planted) is skipped, never opened.
  for (int attempt = 0; attempt < 100; ++attempt)
  {
    this->Temporary = TemporaryName(this->Final);
    // Registered before it exists: a signal right after the creation still removes it.
    this->Slot = RegisterTemporaryFile(this->Temporary);
    if (this->Slot < 0)
    {
      errno = ENAMETOOLONG;
      break;
    }
    this->Descriptor = CreateExclusive(this->Temporary);
    if (this->Descriptor >= 0)
    {
      return true;
    }
    const int reason = errno;
    ForgetTemporaryFile(this->Slot);
    this->Slot = -1;
    errno = reason;
    if (errno != EEXIST)
    {
      break;
    }
  }
  error = Problem(this->Final, "cannot create the file");
  this->Temporary.clear();
  return false;
}

bool WriteAll(int descriptor, const char* data, std::size_t size)
{
  while (size > 0)
  {
    const ssize_t written = write(descriptor, data, size);
    if (written < 0 && errno == EINTR)
    {
      continue;
    }
    if (written <= 0)
    {
      errno = written == 0 ? EIO : errno;
      return false;
    }
    data += written;
    size -= static_cast<std::size_t>(written);
  }
  return true;
}

bool SafeOutputFile::Write(const char* data, std::size_t size, std::string& error)
{
  if (!WriteAll(this->Descriptor, data, size))
  {
    error = Problem(this->Final, "cannot write the file");
    this->Discard();
    return false;
  }
  return true;
}

bool SafeOutputFile::Write(const std::string& data, std::string& error)
{
  return this->Write(data.data(), data.size(), error);
}

bool SafeOutputFile::Close(std::string& error)
{
  // Linux releases the descriptor even when close fails: never close twice.
  const int descriptor = this->Descriptor;
  this->Descriptor = -1;
  if (close(descriptor) != 0)
  {
    error = Problem(this->Final, "cannot write the file");
    this->Discard();
    return false;
  }
  return true;
}

void SafeOutputFile::Published()
{
  ForgetTemporaryFile(this->Slot);
  this->Slot = -1;
  this->Temporary.clear();
}

void SafeOutputFile::Discard()
{
  if (this->Descriptor >= 0)
  {
    close(this->Descriptor);
    this->Descriptor = -1;
  }
  if (!this->Temporary.empty())
  {
    unlink(this->Temporary.c_str());
    this->Temporary.clear();
  }
  ForgetTemporaryFile(this->Slot);
  this->Slot = -1;
}
