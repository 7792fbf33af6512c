/**
 * @class   amDeflate
 * @brief   A file compressed to a gzip file at a chosen zlib level: amImageWriter's .nii.gz,
 *          since ITK's NIfTI writer always compresses at zlib's default level.
 */
#ifndef amDeflate_h
#define amDeflate_h

#include <string>

class amDeflate
{
public:
  /// Compresses 'from' into the gzip file 'to' at 'level' (1 fastest .. 9 smallest). False, with
  /// 'why' set, when either file fails (a short write: a full disk); 'to' may then be partial,
  /// and is the caller's to remove.
  static bool GzipFile(const std::string& from, const std::string& to, int level, std::string& why);
};

#endif
