# Finds radview's dependencies (all Debian 12 packages, installed by install-deps.sh)
# and papers over their packaging quirks, each explained where it is handled below.
find_package(PkgConfig REQUIRED)
find_package(glm CONFIG REQUIRED)
find_package(glfw3 3.3 CONFIG REQUIRED)
find_package(TinyGLTF CONFIG REQUIRED)
find_package(nlohmann_json CONFIG REQUIRED)
find_package(CLI11 CONFIG REQUIRED)
find_package(CGAL REQUIRED)
find_package(Boost 1.74 CONFIG REQUIRED)
find_package(embree 3 CONFIG REQUIRED)
find_package(assimp 5 CONFIG REQUIRED)
find_package(OpenImageIO CONFIG REQUIRED)
find_package(Eigen3 3.3 CONFIG REQUIRED)
# The Python module (app/python), built for Debian's interpreter, whose numpy and scipy the
# packages install (another: -DPython_EXECUTABLE=...); pybind11 through CMake's FindPython.
if(NOT DEFINED Python_EXECUTABLE AND EXISTS /usr/bin/python3)
  set(Python_EXECUTABLE /usr/bin/python3)
endif()
set(PYBIND11_FINDPYTHON ON)
find_package(Python COMPONENTS Interpreter Development.Module REQUIRED)
find_package(pybind11 2.10 CONFIG REQUIRED)
pkg_check_modules(epoxy REQUIRED IMPORTED_TARGET epoxy)
pkg_check_modules(imgui REQUIRED IMPORTED_TARGET imgui)

# OpenImageIO's config names /usr/include/opencv4, which exists only with OpenCV installed;
# CMake refuses a missing include directory, so drop the entries that do not exist.
get_target_property(_oiio_includes OpenImageIO::OpenImageIO INTERFACE_INCLUDE_DIRECTORIES)
set(_oiio_existing "")
foreach(_dir IN LISTS _oiio_includes)
  if(EXISTS "${_dir}" OR _dir MATCHES "^\\$<")
    list(APPEND _oiio_existing "${_dir}")
  endif()
endforeach()
set_target_properties(OpenImageIO::OpenImageIO PROPERTIES INTERFACE_INCLUDE_DIRECTORIES "${_oiio_existing}")

if(RADVIEW_BUILD_TESTS)
  find_package(GTest REQUIRED)
endif()
