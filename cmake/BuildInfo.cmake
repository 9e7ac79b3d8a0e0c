# Generates build_info.h with the git sha, compiler and build type. The sha is
# re-read at every build (the custom target always runs) but the header is only
# rewritten when it changes, so an unchanged tree does not rebuild.
set(TB_BUILD_INFO_DIR ${CMAKE_BINARY_DIR}/generated)
add_custom_target(tb_build_info ALL
  COMMAND ${CMAKE_COMMAND}
    -DSOURCE_DIR=${CMAKE_SOURCE_DIR}
    -DOUTPUT=${TB_BUILD_INFO_DIR}/tb_build_info.h
    "-DCOMPILER=${CMAKE_CXX_COMPILER_ID} ${CMAKE_CXX_COMPILER_VERSION}"
    -DBUILD_TYPE=${CMAKE_BUILD_TYPE}
    -DVERSION=${PROJECT_VERSION}
    -P ${CMAKE_SOURCE_DIR}/cmake/WriteBuildInfo.cmake
  BYPRODUCTS ${TB_BUILD_INFO_DIR}/tb_build_info.h
  COMMENT "Reading git sha"
  VERBATIM)
add_library(tb_build_info_headers INTERFACE)
target_include_directories(tb_build_info_headers INTERFACE ${TB_BUILD_INFO_DIR})
add_dependencies(tb_build_info_headers tb_build_info)
