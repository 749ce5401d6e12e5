// radview reads glTF through Debian's libtinygltf. libdraco, which Assimp brings along, exports
// a tinygltf of another version under the same symbol names; a binary that lists libdraco first
// runs that one against radview's headers and corrupts memory on the first file it loads.
// renderer/CMakeLists.txt keeps tinygltf first on the link line; this checks what the dynamic
// linker actually bound.
#include <dlfcn.h>
#include <gtest/gtest.h>

#include <string>

namespace {

TEST(GltfLibrary, TinygltfIsBoundToLibtinygltfNotToAnotherLibrarysCopy) {
  // tinygltf::TinyGLTF::LoadASCIIFromFile(Model*, std::string*, std::string*, const std::string&, unsigned)
  const char* symbol =
      "_ZN8tinygltf8TinyGLTF17LoadASCIIFromFileEPNS_5ModelEPNSt7__cxx1112basic_stringIcSt11char_traitsIcESaIcEEES9_"
      "RKS8_j";
  void* address = dlsym(RTLD_DEFAULT, symbol);
  ASSERT_NE(address, nullptr) << "tinygltf is not linked";
  Dl_info info{};
  ASSERT_NE(dladdr(address, &info), 0);
  EXPECT_NE(std::string(info.dli_fname).find("libtinygltf"), std::string::npos)
      << "tinygltf's loader is bound to " << info.dli_fname;
}

}  // namespace
