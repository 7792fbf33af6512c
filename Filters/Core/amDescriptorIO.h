/**
 * @file    amDescriptorIO.h
 * @brief   Whole reads and writes on a file descriptor (a pipe to or from a child process):
 *          short transfers are continued and interrupted calls retried.
 */
#ifndef amDescriptorIO_h
#define amDescriptorIO_h

#include "AnatomeshFiltersCoreModule.h" // export macro

#include <cstddef>

namespace amDescriptorIO
{
/// Writes all 'bytes' of 'data'; false when the descriptor fails or closes first.
ANATOMESHFILTERSCORE_EXPORT bool WriteAll(int fd, const void* data, std::size_t bytes);
/// Reads exactly 'bytes' into 'data'; false when the descriptor fails or ends first.
ANATOMESHFILTERSCORE_EXPORT bool ReadAll(int fd, void* data, std::size_t bytes);
}

#endif
