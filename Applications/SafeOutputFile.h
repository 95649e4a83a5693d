// One output file, written to a temporary file in its own folder and moved into place by
// PublishOutputs only once it is complete.
//   - The temporary is created fresh (O_CREAT|O_EXCL|O_NOFOLLOW): nothing planted at its
//     name, a symbolic link or a folder, is ever followed, written or renamed into place;
//     its name ends in random characters, so it cannot be planted in advance either.
//   - Every write and the close are checked; a failure is one message naming the output.
//   - The temporary is removed when the object goes without having been published, and
//     (TemporaryFileRegistry) when SIGINT, SIGTERM, SIGHUP or SIGXFSZ ends the program.
#ifndef SafeOutputFile_h
#define SafeOutputFile_h

#include <cstddef>
#include <string>

class SafeOutputFile
{
public:
  explicit SafeOutputFile(std::string path);
  ~SafeOutputFile();
  SafeOutputFile(const SafeOutputFile&) = delete;
  SafeOutputFile& operator=(const SafeOutputFile&) = delete;

  /// Creates the temporary file.
  bool Open(std::string& error);
  /// Writes all of `data`, or fails.
  bool Write(const char* data, std::size_t size, std::string& error);
  bool Write(const std::string& data, std::string& error);
  /// Closes the temporary file; a complete file is then ready for PublishOutputs.
  bool Close(std::string& error);

  /// Where the file goes, and where it is until then.
  const std::string& Path() const { return this->Final; }
  const std::string& TemporaryPath() const { return this->Temporary; }
  /// Called by PublishOutputs once the temporary has been renamed: nothing to remove.
  void Published();

private:
  void Discard();

  std::string Final, Temporary;
  int Descriptor = -1;
  int Slot = -1;
};

/// `path` followed by ".partial-" and 12 random letters or digits, in the same folder (a
/// shorter name if the file name would grow past the file system's limit).
std::string TemporaryName(const std::string& path);
/// Writes all of `data` to `descriptor` (short writes continued, EINTR retried); false with
/// errno set otherwise.
bool WriteAll(int descriptor, const char* data, std::size_t size);
/// Creates the file `path` for writing; fails (-1, errno set) if anything exists there,
/// a symbolic link included.
int CreateExclusive(const std::string& path);

#endif
