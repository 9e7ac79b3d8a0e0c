# Every dependency is a Debian 12 package (scripts/install_deps.sh installs them).
find_package(Threads REQUIRED)
find_package(Vulkan REQUIRED)
find_package(glslang CONFIG REQUIRED)
find_package(SPIRV-Tools-opt CONFIG REQUIRED)
find_package(embree 3 CONFIG REQUIRED)
find_package(OpenEXR CONFIG REQUIRED)
find_package(nlohmann_json CONFIG REQUIRED)
find_package(CLI11 CONFIG REQUIRED)
find_package(fmt CONFIG REQUIRED)
find_package(meshoptimizer CONFIG REQUIRED)
find_package(TBB CONFIG REQUIRED)
find_package(tinyobjloader CONFIG REQUIRED)
if(TB_BUILD_TESTS)
  find_package(GTest CONFIG REQUIRED)
endif()
if(TB_BUILD_BENCH)
  find_package(benchmark CONFIG REQUIRED)
endif()

# Debian's OpenSubdivConfig.cmake names a static archive the package does not ship,
# so find the headers and the CPU library directly.
find_path(OPENSUBDIV_INCLUDE_DIR opensubdiv/bfr/surface.h REQUIRED)
find_library(OPENSUBDIV_CPU_LIBRARY osdCPU REQUIRED)
add_library(tb_opensubdiv INTERFACE)
target_include_directories(tb_opensubdiv SYSTEM INTERFACE ${OPENSUBDIV_INCLUDE_DIR})
target_link_libraries(tb_opensubdiv INTERFACE ${OPENSUBDIV_CPU_LIBRARY})

find_program(GLSLANG_VALIDATOR glslangValidator REQUIRED)
