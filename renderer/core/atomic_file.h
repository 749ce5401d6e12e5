#pragma once
// Every file radview writes (solutions, images, bench tables) goes through here, so that a
// failed write never costs the user the file that was there: the bytes go to a temporary file
// in the target's folder, which is renamed over the target only once it is complete and on
// disk. rename() within one folder is atomic, so the target is always the old file or the new
// one, never a truncated mix.
#include <cstddef>
#include <string>

namespace radview {

// Writes `bytes` to `path` as above. On any failure (a folder that does not exist or cannot be
// written, a full disk, a file size limit) removes the temporary file and throws
// Error(path, "<what failed>; the existing file is left unchanged") or "...; no file was written".
void writeFileAtomically(const std::string& path, const std::string& bytes);

// The same, for a file written piece by piece as it is made (a large table need not be held
// whole, and the disk starts on it while the rest is computed). Errors as above, each removing
// the temporary file; destroyed before commit(), it removes the temporary file and the target
// is left as it was.
class AtomicFileWriter {
 public:
  explicit AtomicFileWriter(const std::string& path);
  ~AtomicFileWriter();
  AtomicFileWriter(const AtomicFileWriter&) = delete;
  AtomicFileWriter& operator=(const AtomicFileWriter&) = delete;

  void write(const char* data, size_t size);
  // On disk, then renamed over the target.
  void commit();

 private:
  [[noreturn]] void fail(const std::string& what) const;
  [[noreturn]] void abandon(const std::string& what);

  std::string path_, temporary_, outcome_;
  int fd_ = -1;
  size_t written_ = 0;
};

}  // namespace radview
