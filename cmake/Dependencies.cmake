# Every dependency is a Debian 12 package (scripts/install_deps.sh installs them).
# The ground layers' dependencies (core/mesh, core/tess, the camera-path and tessellate-CLI
# libraries) come first; a fuzz build (TB_FUZZ, cmake/Fuzz.cmake) finds only those.
find_package(Threads REQUIRED)
find_package(nlohmann_json CONFIG REQUIRED)
find_package(CLI11 CONFIG REQUIRED)
find_package(meshoptimizer CONFIG REQUIRED)
find_package(tinyobjloader CONFIG REQUIRED)
find_package(TinyGLTF CONFIG REQUIRED)

# tb_tinyobjloader, what tb_mesh links: Debian's shared library, or in a fuzz build the
# same version compiled from its header (/usr/include) with the fuzz flags, so that ASan
# checks its reads and libFuzzer's coverage reaches into its parser.
if(TB_FUZZ)
  set(TB_TINYOBJ_SOURCE ${CMAKE_BINARY_DIR}/generated/tinyobjloader_impl.cpp)
  file(CONFIGURE OUTPUT ${TB_TINYOBJ_SOURCE}
    CONTENT "#define TINYOBJLOADER_IMPLEMENTATION\n#include <tiny_obj_loader.h>\n")
  add_library(tb_tinyobjloader STATIC ${TB_TINYOBJ_SOURCE})
else()
  add_library(tb_tinyobjloader INTERFACE)
  target_link_libraries(tb_tinyobjloader INTERFACE tinyobjloader::tinyobjloader)
endif()

# tb_tinygltf, the glTF reader's parser: Debian's libtinygltf-dev shared library, or in a fuzz
# build its header compiled with the fuzz flags (as tb_tinyobjloader). Debian has no stb
# headers for it, and tessbench never decodes images: the fuzz build leaves stb out.
if(TB_FUZZ)
  set(TB_TINYGLTF_SOURCE ${CMAKE_BINARY_DIR}/generated/tinygltf_impl.cpp)
  file(CONFIGURE OUTPUT ${TB_TINYGLTF_SOURCE}
    CONTENT "#define TINYGLTF_IMPLEMENTATION\n#include <tiny_gltf.h>\n")
  add_library(tb_tinygltf STATIC ${TB_TINYGLTF_SOURCE})
  target_compile_definitions(tb_tinygltf PUBLIC TINYGLTF_NO_STB_IMAGE TINYGLTF_NO_STB_IMAGE_WRITE
    TINYGLTF_NO_EXTERNAL_IMAGE)
else()
  add_library(tb_tinygltf INTERFACE)
  target_link_libraries(tb_tinygltf INTERFACE TinyGLTF::TinyGLTF)
endif()

if(NOT TB_FUZZ)
  find_package(Vulkan REQUIRED)
  find_package(glslang CONFIG REQUIRED)
  find_package(SPIRV-Tools-opt CONFIG REQUIRED)
  find_package(embree 3 CONFIG REQUIRED)
  find_package(OpenEXR CONFIG REQUIRED)
  find_package(fmt CONFIG REQUIRED)
  find_package(TBB CONFIG REQUIRED)
  find_package(PNG REQUIRED)  # CMake's FindPNG: the pictures' PNG files (libpng-dev)
  find_package(SQLite3 REQUIRED)  # CMake's FindSQLite3: the history database (libsqlite3-dev)
  # The tests and benchmarks need GoogleTest and Google Benchmark, which README command 1
  # (scripts/install_deps.sh --run) does not install: without them this configure builds
  # tessbench and says so; scripts/test.sh installs them first.
  if(TB_BUILD_TESTS)
    find_package(GTest CONFIG QUIET)
    if(NOT GTest_FOUND)
      message(STATUS "GoogleTest not installed: tests not configured (scripts/install_deps.sh)")
      set(TB_BUILD_TESTS OFF)
    endif()
  endif()
  if(TB_BUILD_BENCH)
    find_package(benchmark CONFIG QUIET)
    if(NOT benchmark_FOUND)
      message(STATUS "Google Benchmark not installed: benchmarks not configured (scripts/install_deps.sh)")
      set(TB_BUILD_BENCH OFF)
    endif()
  endif()

  # Debian's OpenSubdivConfig.cmake names a static archive the package does not ship,
  # so find the headers and the CPU library directly.
  find_path(OPENSUBDIV_INCLUDE_DIR opensubdiv/bfr/surface.h REQUIRED)
  find_library(OPENSUBDIV_CPU_LIBRARY osdCPU REQUIRED)
  add_library(tb_opensubdiv INTERFACE)
  target_include_directories(tb_opensubdiv SYSTEM INTERFACE ${OPENSUBDIV_INCLUDE_DIR})
  target_link_libraries(tb_opensubdiv INTERFACE ${OPENSUBDIV_CPU_LIBRARY})

  find_program(GLSLANG_VALIDATOR glslangValidator REQUIRED)
endif()
