#pragma once
// Every file radview writes (solutions, images, bench tables) goes through here, so that a
// failed write never costs the user the file that was there: the bytes go to a temporary file
// in the target's folder, which is renamed over the target only once it is complete and on
// disk. rename() within one folder is atomic, so the target is always the old file or the new
// one, never a truncated mix.
#include <string>

namespace radview {

// Writes `bytes` to `path` as above. On any failure (a folder that does not exist or cannot be
// written, a full disk, a file size limit) removes the temporary file and throws
// Error(path, "<what failed>; the existing file is left unchanged") or "...; no file was written".
void writeFileAtomically(const std::string& path, const std::string& bytes);

}  // namespace radview
