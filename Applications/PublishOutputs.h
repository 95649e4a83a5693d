// Moves a group of finished SafeOutputFiles into place: all of them or none.
//   - Without `replace`, a file is never put over anything, not even over a file that
//     appeared after the program checked (renameat2 with RENAME_NOREPLACE, or link and
//     unlink where the file system lacks it): of concurrent runs on one output, one wins.
//   - With `replace`, each output is replaced in one step (rename), the old file kept under
//     a second name (a hard link) until the whole group is in place, and put back if a
//     later file cannot follow. Only a regular file is replaced, never a folder, a link
//     or a device.
//   - SIGINT, SIGTERM and SIGHUP wait until the group is in place or taken back.
#ifndef PublishOutputs_h
#define PublishOutputs_h

#include "SafeOutputFile.h"

#include <string>
#include <vector>

bool PublishOutputs(const std::vector<SafeOutputFile*>& files, bool replace, std::string& error);

/// Writes `bytes` to `path` through a temporary file and replaces what was there in one
/// step (mobius-score's files): a failure leaves the old file as it was. What is not a
/// regular file (a device such as /dev/stdout, a link) is written through instead.
bool ReplaceFile(const std::string& path, const std::string& bytes, std::string& error);

/// Renames `from` to `to` unless something exists at `to` (errno EEXIST then).
bool RenameWithoutReplacing(const std::string& from, const std::string& to);

#endif
