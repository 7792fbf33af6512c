/**
 * @class   amAtomicFile
 * @brief   Write a file so that readers only ever see the old file or the complete new one.
 *
 * The content goes to a temporary path in the same folder (same extension, so format-sniffing
 * libraries such as ITK still pick the right codec); Commit() flushes it to the disk (fsync, which
 * also reports a write the kernel deferred and then could not make) and renames it over the target,
 * and the destructor removes the temporary when Commit() was never reached (an error, an exception).
 * Writers therefore never leave a half-written file behind. A process killed mid-write cannot
 * run its destructor: its temporary stays until the next writer of the same target, which removes
 * the temporaries of processes that no longer run.
 */
#ifndef amAtomicFile_h
#define amAtomicFile_h

#include "AnatomeshFiltersCoreModule.h" // export macro

#include <string>

class ANATOMESHFILTERSCORE_EXPORT amAtomicFile
{
public:
  explicit amAtomicFile(const std::string& target);
  ~amAtomicFile();
  amAtomicFile(const amAtomicFile&) = delete;
  amAtomicFile& operator=(const amAtomicFile&) = delete;

  /// Where to write the content ("<dir>/.<stem>.tmp<unique><ext>").
  const std::string& TemporaryPath() const { return this->Temporary; }
  const std::string& TargetPath() const { return this->Target; }

  /// Whether the target's folder exists and is writable; otherwise 'why' says what is wrong.
  bool CanWrite(std::string& why) const;

  /// Writes 'bytes' to the temporary with checked system calls (a full disk, a file size limit:
  /// false, 'why' the system's words) and checks its size on the disk afterwards.
  bool WriteTemporary(const std::string& bytes, std::string& why) const;

  /// Flushes the temporary to the disk, renames it over the target and flushes the folder. False
  /// (and 'why' set, with the system's words) if any step fails; the target is then untouched.
  bool Commit(std::string& why);

  /// The extension of a path, lower case, with ".gz" kept as part of it (".nii.gz").
  static std::string Extension(const std::string& path);

private:
  std::string Target;
  std::string Temporary;
  bool Committed = false;
};

#endif
