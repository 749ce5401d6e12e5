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

AtomicFileWriter::AtomicFileWriter(const std::string& path) : path_(path) {
  const fs::path target(path);
  std::error_code ec;
  outcome_ = fs::exists(target, ec) ? "; the existing file is left unchanged" : "; no file was written";
  const fs::path folder = target.parent_path().empty() ? fs::path(".") : target.parent_path();
  if (!fs::is_directory(folder, ec)) fail("the folder " + folder.string() + " does not exist");
  if (fs::is_directory(target, ec)) fail("is a folder");
  temporary_ = temporaryFor(target).string();
  // O_EXCL: never write into a file that someone else made under the same name.
  fd_ = ::open(temporary_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
  if (fd_ < 0) fail("cannot create a file in " + folder.string() + ": " + errnoText(errno));
}

AtomicFileWriter::~AtomicFileWriter() {
  if (fd_ >= 0) {
    ::close(fd_);
    ::unlink(temporary_.c_str());
  }
}

void AtomicFileWriter::fail(const std::string& what) const { throw Error(path_, what + outcome_); }

// Every failure once the temporary file exists removes it before it throws.
void AtomicFileWriter::abandon(const std::string& what) {
  ::close(fd_);
  ::unlink(temporary_.c_str());
  fd_ = -1;
  fail(what);
}

void AtomicFileWriter::write(const char* data, size_t size) {
  RADVIEW_CHECK(fd_ >= 0);
  const size_t wanted = written_ + size;
  for (size_t done = 0; done < size;) {
    const ssize_t n = ::write(fd_, data + done, size - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0)
      abandon("writing failed after " + std::to_string(written_) + " of " + std::to_string(wanted) +
              " bytes: " + (n < 0 ? errnoText(errno) : std::string("no more bytes accepted")));
    done += size_t(n);
    written_ += size_t(n);
  }
  // The disk starts on these bytes now, so that commit()'s sync finds little left to do.
  ::sync_file_range(fd_, off_t(wanted - size), off_t(size), SYNC_FILE_RANGE_WRITE);
}

void AtomicFileWriter::commit() {
  RADVIEW_CHECK(fd_ >= 0);
  // On disk before the rename, so that a crash cannot leave the new name on missing data.
  if (::fsync(fd_) != 0) abandon("writing failed: " + errnoText(errno));
  const int fd = fd_;
  fd_ = -1;
  if (::close(fd) != 0) {
    const int error = errno;
    ::unlink(temporary_.c_str());
    fail("writing failed: " + errnoText(error));
  }
  if (::rename(temporary_.c_str(), path_.c_str()) != 0) {
    const int error = errno;
    ::unlink(temporary_.c_str());
    fail("cannot replace the file: " + errnoText(error));
  }
}

void writeFileAtomically(const std::string& path, const std::string& bytes) {
  AtomicFileWriter file(path);
  file.write(bytes.data(), bytes.size());
  file.commit();
}

}  // namespace radview
