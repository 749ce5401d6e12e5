// The PLY reader (import/ply_file.h): the same small mesh in ASCII and both binary byte
// orders reads to the same values; header variants real writers produce are accepted; every
// kind of damage is refused with a message that names the file and the fault.
#include "import/ply_file.h"

#include "tests/error_message.h"
#include "tests/import/import_files.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace radview {
namespace {

using test::errorOf;
using test::PlyBody;

const char* kHeader =
    "element vertex 3\nproperty float x\nproperty float y\nproperty float z\nproperty uchar red\n"
    "element face 1\nproperty list uchar int vertex_indices\nend_header\n";

PlyFile parse(const std::string& text) { return parsePly(std::vector<char>(text.begin(), text.end()), "t.ply"); }

std::string binaryTriangle(bool bigEndian) {
  PlyBody body(bigEndian);
  const float xyz[3][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0.5f}};
  for (int v = 0; v < 3; ++v) body.put(xyz[v][0]).put(xyz[v][1]).put(xyz[v][2]).put(uint8_t(10 * v + 5));
  body.put(uint8_t(3)).put(int32_t(0)).put(int32_t(1)).put(int32_t(2));
  return std::string("ply\nformat ") + (bigEndian ? "binary_big_endian" : "binary_little_endian") + " 1.0\n" + kHeader +
         body.bytes();
}

void expectTriangle(const PlyFile& ply) {
  ASSERT_EQ(ply.elements.size(), 2u);
  const PlyElement& vertex = *ply.find("vertex");
  EXPECT_EQ(vertex.count, 3u);
  EXPECT_EQ(vertex.find("red")->type, PlyType::UInt8);
  EXPECT_EQ(vertex.find("z")->values, (std::vector<double>{0, 0, 0.5}));
  EXPECT_EQ(vertex.find("red")->values, (std::vector<double>{5, 15, 25}));
  const PlyProperty& list = *ply.find("face")->find("vertex_indices");
  EXPECT_TRUE(list.isList);
  EXPECT_EQ(list.values, (std::vector<double>{0, 1, 2}));
  EXPECT_EQ(list.offsets, (std::vector<uint64_t>{0, 3}));
}

TEST(PlyFile, AsciiAndBothByteOrdersReadTheSame) {
  expectTriangle(parse(std::string("ply\nformat ascii 1.0\n") + kHeader + "0 0 0 5\n1 0 0 15\n0 1 0.5 25\n3 0 1 2\n"));
  expectTriangle(parse(binaryTriangle(false)));
  expectTriangle(parse(binaryTriangle(true)));
}

TEST(PlyFile, HeaderVariantsOfRealWriters) {
  // CR LF and bare CR line ends, tabs and runs of spaces, comments, obj_info, type aliases, no
  // final newline.
  auto crlf = [](std::string text) {
    for (size_t at = text.find('\n'); at != std::string::npos; at = text.find('\n', at + 2)) text.insert(at, "\r");
    return text;
  };
  expectTriangle(parse(crlf(std::string("ply\nformat ascii 1.0\ncomment made by hand\nobj_info x\n") + kHeader +
                            "0 0 0 5\n1 0 0 15\n0 1 0.5 25\n3 0 1 2")));
  std::string binary = binaryTriangle(false);
  const size_t bodyAt = binary.find("end_header\n") + 11;
  std::string header = binary.substr(0, bodyAt), body = binary.substr(bodyAt);
  for (char& c : header)
    if (c == '\n') c = '\r';
  expectTriangle(parse(header + body));
  expectTriangle(
      parse("ply\nformat ascii 1.0\n  element vertex 3\nproperty float32 x\nproperty\tfloat y \nproperty float z\n"
            "property uint8 red\nelement face 1\nproperty list uchar int32 vertex_indices\nend_header\n"
            "0\t0  0 5\n 1 0 0 15\n0 1 0.5 25\n\n3 0 1 2"));
}

TEST(PlyFile, ABareCrHeaderDoesNotEatABodyThatStartsWithLf) {
  PlyBody body(false);
  body.put(uint8_t('\n')).put(uint8_t(7));
  const PlyFile ply =
      parse("ply\rformat binary_little_endian 1.0\relement v 2\rproperty uchar a\rend_header\r" + body.bytes());
  EXPECT_EQ(ply.find("v")->find("a")->values, (std::vector<double>{10, 7}));
}

TEST(PlyFile, DamageIsRefusedWithTheFault) {
  EXPECT_EQ(errorOf([] { parse("PLX\n"); }), "t.ply: not a PLY file (the first line is not \"ply\")");
  EXPECT_EQ(errorOf([] { parse("ply\nformat ascii 1.0\nelement vertex 1\n"); }),
            "t.ply: the header has no end_header line");
  EXPECT_EQ(errorOf([] { parse("ply\nformat ascii 2.0\nend_header\n"); }),
            "t.ply: line 2: PLY version 2.0 (radview reads 1.0)");
  EXPECT_EQ(errorOf([] { parse("ply\nformat ascii 1.0\nelement v 1\nproperty quad x\nend_header\n1\n"); }),
            "t.ply: line 4: unknown property type \"quad\"");
  EXPECT_EQ(errorOf([] { parse("ply\nformat ascii 1.0\nproperty float x\nend_header\n"); }),
            "t.ply: line 3: a property before any element");
  EXPECT_EQ(errorOf([] { parse("ply\nformat ascii 1.0\nelement v 1\nproperty list float int x\nend_header\n"); }),
            "t.ply: line 4: list x: its count type float is not an integer type");

  // Counts that lie: more entries than the bytes can hold is refused before any allocation,
  // and no count passes radview's limit.
  EXPECT_EQ(errorOf([] {
              parse(
                  "ply\nformat binary_little_endian 1.0\nelement v 1000\nproperty double x\n"
                  "end_header\n12345678");
            }),
            "t.ply: the header declares 1000 v entries, more than the 8 bytes after the header can hold (a "
            "truncated file or a wrong count)");
  EXPECT_EQ(errorOf([] { parse("ply\nformat ascii 1.0\nelement v 4000000000000\nproperty double x\nend_header\n"); }),
            "t.ply: 4000000000000 v entries, more than radview's limit of 16000000");
  std::string truncated = binaryTriangle(false);
  truncated.resize(truncated.size() - 2);
  EXPECT_EQ(errorOf([&] { parse(truncated); }),
            "t.ply: face 0: its vertex_indices list of 3 items runs past the end of the file");
  // The lists' items are past the minimum the counts check: an element after them starves.
  PlyBody starved(false);
  starved.put(uint8_t(2)).put(int32_t(0)).put(int32_t(1)).put(uint8_t(7));
  EXPECT_EQ(errorOf([&] {
              parse(
                  "ply\nformat binary_little_endian 1.0\nelement f 1\nproperty list uchar int i\nelement e 2\n"
                  "property uchar a\nend_header\n" +
                  starved.bytes());
            }),
            "t.ply: the body ends inside e 1 (the file is truncated, or a count is wrong)");
  EXPECT_EQ(errorOf([] { parse(binaryTriangle(false) + "\x01\x02"); }),
            "t.ply: 2 bytes follow the last element the header declares (a count is wrong)");
  PlyBody longList(false);
  longList.put(uint8_t(200)).put(int32_t(0));
  EXPECT_EQ(errorOf([&] {
              parse("ply\nformat binary_little_endian 1.0\nelement f 1\nproperty list uchar int i\nend_header\n" +
                    longList.bytes());
            }),
            "t.ply: f 0: its i list of 200 items runs past the end of the file");
  PlyBody negative(false);
  negative.put(int8_t(-1)).put(int32_t(0));
  EXPECT_EQ(errorOf([&] {
              parse("ply\nformat binary_little_endian 1.0\nelement f 1\nproperty list char int i\nend_header\n" +
                    negative.bytes());
            }),
            "t.ply: f 0: its i list has a negative count");

  const std::string ascii = std::string("ply\nformat ascii 1.0\n") + kHeader;
  EXPECT_EQ(errorOf([&] { parse(ascii + "0 0 0 5\n1 0 0 15\n0 1 0.5\n3 0 1 2\n"); }),
            "t.ply: line 13: vertex 2 has 3 values, too few for the header's properties");
  const std::string rest = "1 0 0 15\n0 1 0.5 25\n3 0 1 2\n";
  EXPECT_EQ(errorOf([&] { parse(ascii + "0 0 0 5 9\n" + rest); }),
            "t.ply: line 11: vertex 0 has 5 values where the header's properties take 4");
  EXPECT_EQ(errorOf([&] { parse(ascii + "0 0 zero 5\n" + rest); }),
            "t.ply: line 11: vertex 0: z \"zero\" is not a number");
  EXPECT_EQ(errorOf([&] { parse(ascii + "0 0 0 5.5\n" + rest); }),
            "t.ply: line 11: vertex 0: red \"5.5\" is not an integer");
  EXPECT_EQ(errorOf([&] { parse(ascii + "0 0 0 256\n" + rest); }),
            "t.ply: line 11: vertex 0: red 256 does not fit in uchar");
  EXPECT_EQ(errorOf([&] { parse(ascii + "0 0 0 5\n1 0 0 15\n0 1 0.5 25\n"); }),
            "t.ply: the file ends before face 0 (of 1 the header declares)");
  EXPECT_EQ(errorOf([&] { parse(ascii + "0 0 0 5\n1 0 0 15\n0 1 0.5 25\n4 0 1 2\n"); }),
            "t.ply: line 14: face 0: its vertex_indices list of 4 items is longer than the line");
  EXPECT_EQ(errorOf([&] { parse(ascii + "0 0 0 5\n1 0 0 15\n0 1 0.5 25\n3 0 1 2\n3 0 1 2\n"); }),
            "t.ply: line 15: text after the last element the header declares (a count is wrong)");
}

TEST(PlyFile, NonFiniteFloatsAreReadForTheMeshToRefuse) {
  const PlyFile ply = parse("ply\nformat ascii 1.0\nelement v 2\nproperty float x\nend_header\nnan\ninf\n");
  const std::vector<double>& x = ply.find("v")->find("x")->values;
  EXPECT_TRUE(std::isnan(x[0]));
  EXPECT_TRUE(std::isinf(x[1]));
}

}  // namespace
}  // namespace radview
