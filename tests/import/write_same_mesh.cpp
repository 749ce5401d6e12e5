// Writes tests/import/same_mesh_formats.h's mesh as float PLY, 8-bit PLY, OBJ and glTF COLOR_0
// into a folder, with what `radview sample` must print at its nodes off the jump: for each file
// a line "FILE x y z B_r B_g B_b" per node. Used by tests/image/import_cli_test.sh.
#include "tests/import/same_mesh_formats.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: write_same_mesh FOLDER\n");
    return 2;
  }
  const std::string folder = argv[1];
  std::filesystem::create_directories(folder);
  const radview::test::SameMesh same;
  auto write = [&](const std::string& name, const std::string& bytes) {
    std::ofstream(folder + "/" + name, std::ios::binary) << bytes;
  };
  write("two_quads_float.ply", same.plyFloatAscii());
  write("two_quads_uchar.ply", same.plyByteBigEndian());
  write("two_quads.obj", same.obj());
  write("two_quads_colour0.gltf", same.gltfColour0());
  std::ofstream expected(folder + "/expected.txt");
  expected.precision(17);
  for (const char* file : {"two_quads_float.ply", "two_quads_uchar.ply", "two_quads.obj", "two_quads_colour0.gltf"})
    for (size_t node : {0, 3, 5, 6}) {
      const radview::Vec3& p = same.positions[node];
      radview::Rgb B = same.B[node];
      if (std::string(file) == "two_quads_uchar.ply")
        for (int k = 0; k < 3; ++k) B[k] = same.fromByte(same.byteOf(std::min(B[k], 1.0)));
      expected << file << ' ' << p.x << ' ' << p.y << ' ' << p.z << ' ' << B.r << ' ' << B.g << ' ' << B.b << '\n';
    }
  return 0;
}
