#include "core/atomic_file.h"

#include "core/error.h"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <filesystem>

namespace radview {

namespace {

namespace fs = std::filesystem;

// A name in the target's folder that no other write (another thread, another radview process)
// can be using: hidden, with the process id and a per-process counter, and the target's own
// extension last so that tools which go by the extension still recognise the file.
fs::path temporaryFor(const fs::path& target) {
  static std::atomic<unsigned long> counter{0};
  const std::string name = "." + target.filename().string() + "." + std::to_string(long(getpid())) + "-" +
                           std::to_string(++counter) + ".part" + target.extension().string();
  return target.parent_path() / name;
}

std::string errnoText(int error) { return std::strerror(error); }

}  // namespace

void writeFileAtomically(const std::string& path, const std::string& bytes) {
  const fs::path target(path);
  std::error_code ec;
  const bool existed = fs::exists(target, ec);
  const std::string outcome = existed ? "; the existing file is left unchanged" : "; no file was written";
  auto fail = [&](const std::string& what) { throw Error(path, what + outcome); };

  const fs::path folder = target.parent_path().empty() ? fs::path(".") : target.parent_path();
  if (!fs::is_directory(folder, ec)) fail("the folder " + folder.string() + " does not exist");
  if (fs::is_directory(target, ec)) fail("is a folder");

  const fs::path temporary = temporaryFor(target);
  // O_EXCL: never write into a file that someone else made under the same name.
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  if (fd < 0) fail("cannot create a file in " + folder.string() + ": " + errnoText(errno));
  // From here on, every failure removes the temporary file before it throws.
  auto abandon = [&](const std::string& what) {
    ::close(fd);
    ::unlink(temporary.c_str());
    fail(what);
  };
  size_t written = 0;
  while (written < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + written, bytes.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0)
      abandon("writing failed after " + std::to_string(written) + " of " + std::to_string(bytes.size()) +
              " bytes: " + (n < 0 ? errnoText(errno) : std::string("no more bytes accepted")));
    written += size_t(n);
  }
  // On disk before the rename, so that a crash cannot leave the new name on missing data.
  if (::fsync(fd) != 0) abandon("writing failed: " + errnoText(errno));
  if (::close(fd) != 0) {
    const int error = errno;
    ::unlink(temporary.c_str());
    fail("writing failed: " + errnoText(error));
  }
  if (::rename(temporary.c_str(), target.c_str()) != 0) {
    const int error = errno;
    ::unlink(temporary.c_str());
    fail("cannot replace the file: " + errnoText(error));
  }
}

}  // namespace radview
