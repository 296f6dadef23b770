/**
 * @file OutputFile.h
 * @brief Writing an output file whole or not at all, without replacing what is not a file.
 *
 * The tools and vtkMotionCodecLCT write a temporary beside the output and rename it over the
 * output when complete, so a failed write never leaves a partial file under the final name.
 * Renaming over a symbolic link would turn the link into a regular file, and over a FIFO or a
 * device (as root: /dev/stdout) replace it; a temporary under a name one can foresee is opened
 * through whatever was put there (a FIFO hangs the writer, a link writes into another file).
 */
#ifndef lct_OutputFile_h
#define lct_OutputFile_h

#include "vtkLCTModule.h"

#include <filesystem>
#include <string>

namespace lct
{

/// The file that writing `name` replaces: `name`, or where its symbolic links lead (a chain of
/// more than 40 is left as it is, and then is not a regular file).
VTKLCT_EXPORT std::filesystem::path outputTarget(const std::filesystem::path& name);

/// "NAME exists and is not a regular file" (with " (a link to TARGET)" after NAME when a link
/// leads there) when outputTarget(name) is a directory, a FIFO, a device or a socket, which a
/// write must not replace; else "".
VTKLCT_EXPORT std::string notARegularFile(const std::filesystem::path& name);

/// A new, empty file beside `target` (an outputTarget) to write it under a temporary name:
/// created exclusively (never through a link, a FIFO or anything put in its place) under a name
/// no one can foresee, ".NAME.PID.RANDOM.part", NAME shortened to fit the file system's name
/// limit. Returns its descriptor (close-on-exec) and sets `temporary`; -1, with `why`, when it
/// cannot be created.
VTKLCT_EXPORT int createTemporaryBeside(
  const std::filesystem::path& target, std::string& temporary, std::string& why);

/// Renames `temporary` over `target` (an outputTarget). A target that exists and is not a regular
/// file is refused; one that is keeps its permission bits (and its owner where this process may
/// set it). On failure the temporary is removed and `why` names the cause.
VTKLCT_EXPORT bool replaceWithTemporary(
  const std::string& temporary, const std::filesystem::path& target, std::string& why);

/// Writes `bytes` to outputTarget(name) through a new temporary beside it (created exclusively,
/// under an unforeseeable name: createTemporaryBeside), renamed over it when complete
/// (replaceWithTemporary). False, with `why` naming the
/// cause (and nothing left behind), when the target exists and is not a regular file, or when
/// creating, writing or renaming fails.
VTKLCT_EXPORT bool writeFileAtomically(
  const std::filesystem::path& name, const std::string& bytes, std::string& why);

} // namespace lct

#endif
