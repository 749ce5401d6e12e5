// Atomic writes: a write that fails part way (a real one: the process's file size limit,
// RLIMIT_FSIZE, stops it) throws an Error naming the file, leaves the file that was there byte
// for byte, and leaves no temporary file behind. Tests run as root here, so permissions cannot
// make a write fail; the size limit can.
#include "core/atomic_file.h"

#include "core/error.h"
#include "core/image.h"
#include "mesh/solution_file.h"

#include <gtest/gtest.h>
#include <sys/resource.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <iterator>

namespace radview {
namespace {

namespace fs = std::filesystem;

// While alive, writes that would take a file past `bytes` fail with EFBIG (SIGXFSZ, which
// would kill the process, is ignored); the destructor restores both.
class FileSizeLimit {
 public:
  explicit FileSizeLimit(rlim_t bytes) {
    previousHandler_ = std::signal(SIGXFSZ, SIG_IGN);
    getrlimit(RLIMIT_FSIZE, &previous_);
    rlimit limit = previous_;
    limit.rlim_cur = bytes;
    EXPECT_EQ(setrlimit(RLIMIT_FSIZE, &limit), 0);
  }
  ~FileSizeLimit() {
    setrlimit(RLIMIT_FSIZE, &previous_);
    std::signal(SIGXFSZ, previousHandler_);
  }

 private:
  rlimit previous_{};
  void (*previousHandler_)(int) = nullptr;
};

std::string contents(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

class AtomicFileTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("radview_atomic_file_test_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path path(const std::string& name) const { return dir_ / name; }
  // Every file in the folder, so a left-over temporary shows.
  std::vector<std::string> files() const {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(dir_)) names.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  }
  // The message of the Error `write` throws, or "" when it throws none.
  template <typename Write>
  static std::string errorOf(Write write) {
    try {
      write();
    } catch (const Error& e) {
      return e.what();
    }
    return "";
  }

  fs::path dir_;
};

TEST_F(AtomicFileTest, WritesANewFileAndReplacesAnOldOne) {
  writeFileAtomically(path("a.txt").string(), "first");
  EXPECT_EQ(contents(path("a.txt")), "first");
  writeFileAtomically(path("a.txt").string(), "second, longer");
  EXPECT_EQ(contents(path("a.txt")), "second, longer");
  EXPECT_EQ(files(), std::vector<std::string>{"a.txt"});
}

TEST_F(AtomicFileTest, AFailedWriteLeavesTheOldFileAndNoTemporary) {
  const std::string old = "the old file's bytes";
  std::ofstream(path("a.bin"), std::ios::binary) << old;
  const std::string message = errorOf([&] {
    FileSizeLimit limit(4096);
    writeFileAtomically(path("a.bin").string(), std::string(100000, 'x'));
  });
  EXPECT_NE(message.find(path("a.bin").string() + ": writing failed after 4096 of 100000 bytes"), std::string::npos)
      << message;
  EXPECT_NE(message.find("the existing file is left unchanged"), std::string::npos) << message;
  EXPECT_EQ(contents(path("a.bin")), old);
  EXPECT_EQ(files(), std::vector<std::string>{"a.bin"});
}

// A file written piece by piece appears whole at commit, and only then; a writer given up
// before it (an exception on the way) leaves the old file and no temporary; a piece that fails
// part way says how far the file got.
TEST_F(AtomicFileTest, AStreamedFileAppearsWholeAtCommitOrNotAtAll) {
  std::ofstream(path("s.npy"), std::ios::binary) << "old";
  {
    AtomicFileWriter file(path("s.npy").string());
    file.write("abc", 3);
    file.write("defg", 4);
    EXPECT_EQ(contents(path("s.npy")), "old");
  }
  EXPECT_EQ(contents(path("s.npy")), "old");
  EXPECT_EQ(files(), std::vector<std::string>{"s.npy"});
  {
    AtomicFileWriter file(path("s.npy").string());
    file.write("abc", 3);
    file.write("defg", 4);
    file.commit();
  }
  EXPECT_EQ(contents(path("s.npy")), "abcdefg");
  EXPECT_EQ(files(), std::vector<std::string>{"s.npy"});
  const std::string message = errorOf([&] {
    FileSizeLimit limit(4096);
    AtomicFileWriter file(path("s.npy").string());
    file.write(std::string(3000, 'x').data(), 3000);
    file.write(std::string(3000, 'y').data(), 3000);
  });
  EXPECT_NE(message.find("s.npy: writing failed after 4096 of 6000 bytes"), std::string::npos) << message;
  EXPECT_EQ(contents(path("s.npy")), "abcdefg");
  EXPECT_EQ(files(), std::vector<std::string>{"s.npy"});
}

TEST_F(AtomicFileTest, AFailedWriteOfANewFileLeavesNothing) {
  const std::string message = errorOf([&] {
    FileSizeLimit limit(10);
    writeFileAtomically(path("new.bin").string(), std::string(1000, 'x'));
  });
  EXPECT_NE(message.find("new.bin: writing failed"), std::string::npos) << message;
  EXPECT_NE(message.find("no file was written"), std::string::npos) << message;
  EXPECT_TRUE(files().empty());
}

TEST_F(AtomicFileTest, AMissingFolderOrAFolderAsTargetIsRefused) {
  const std::string missing = errorOf([&] { writeFileAtomically(path("no/such/x.txt").string(), "x"); });
  EXPECT_NE(
      missing.find("no/such/x.txt: the folder " + path("no/such").string() + " does not exist; no file was written"),
      std::string::npos)
      << missing;
  fs::create_directory(path("folder"));
  const std::string folder = errorOf([&] { writeFileAtomically(path("folder").string(), "x"); });
  EXPECT_NE(folder.find("folder: is a folder"), std::string::npos) << folder;
  EXPECT_EQ(files(), std::vector<std::string>{"folder"});
}

TEST_F(AtomicFileTest, AFailedPngWriteLeavesTheOldImage) {
  Image small{4, 4, std::vector<uint8_t>(64, 200)};
  writePng(small, path("shot.png").string());
  const std::string old = contents(path("shot.png"));
  // Noise does not compress, so the PNG is far larger than the limit.
  Image large{256, 256, std::vector<uint8_t>(256 * 256 * 4)};
  uint32_t state = 1;
  for (size_t i = 0; i < large.rgba.size(); ++i)  // opaque: PNG keeps colour unassociated with alpha
    large.rgba[i] = i % 4 == 3 ? 255 : uint8_t((state = state * 1664525u + 1013904223u) >> 24);
  const std::string message = errorOf([&] {
    FileSizeLimit limit(old.size() + 1000);
    writePng(large, path("shot.png").string());
  });
  EXPECT_NE(message.find("shot.png: writing failed"), std::string::npos) << message;
  EXPECT_NE(message.find("the existing file is left unchanged"), std::string::npos) << message;
  EXPECT_EQ(contents(path("shot.png")), old);
  EXPECT_EQ(files(), std::vector<std::string>{"shot.png"});
  writePng(large, path("shot.png").string());  // without the limit it works, and is read back whole
  EXPECT_EQ(readImage(path("shot.png").string()).rgba, large.rgba);
}

TEST_F(AtomicFileTest, AFailedSolutionWriteLeavesTheOldSolution) {
  RadiosityMesh mesh;
  mesh.materials = {{"white", Rgb(0.5), Rgb(1.0)}};
  for (int i = 0; i < 64; ++i)
    for (int j = 0; j < 64; ++j) mesh.nodes.push_back({Vec3(i, j, 0), Rgb(0.01 * (i + j))});
  for (uint32_t i = 0; i + 1 < 64; ++i)
    for (uint32_t j = 0; j + 1 < 64; ++j) {
      Element e;
      e.corners = {64 * i + j, 64 * (i + 1) + j, 64 * (i + 1) + j + 1, 64 * i + j + 1};
      mesh.elements.push_back(e);
    }
  writeSolution(mesh, path("s.glb").string());
  const std::string old = contents(path("s.glb"));
  for (Node& n : mesh.nodes) n.B = n.B * 2.0;
  const std::string message = errorOf([&] {
    FileSizeLimit limit(old.size() / 2);
    writeSolution(mesh, path("s.glb").string());
  });
  EXPECT_NE(message.find("s.glb: writing failed"), std::string::npos) << message;
  EXPECT_NE(message.find("the existing file is left unchanged"), std::string::npos) << message;
  EXPECT_EQ(contents(path("s.glb")), old);
  EXPECT_EQ(files(), std::vector<std::string>{"s.glb"});
}

}  // namespace
}  // namespace radview
