# Unity builds (TB_UNITY_BUILD, top-level CMakeLists.txt) for the libraries and tessbench, not
# the tests: most of a file's compile time is parsing the same heavy headers (fmt,
# nlohmann-json, CLI11, Vulkan, OpenSubdiv), so batches of a target's files are compiled as one
# translation unit. Our own batches rather than CMake's UNITY_BUILD: CMake 3.25 writes each
# file's absolute path into the batch, so a second clone (CI's) could never reuse ccache's
# objects; these batches include each file by its path from the source root.
#
# File-local names (anonymous namespaces, `static`) must be unique within a library. A file
# that cannot share a batch is listed here, by its path from the source root; a whole target
# built file by file is in TB_UNITY_OFF_TARGETS. Files with their own compile definitions or
# options stay out by themselves.
set(TB_UNITY_SKIP
  core/tess/triangle_domain.cpp
  core/gpu/tess_capture.cpp
  techniques/gregory_acc/gregory_stencils.cpp
  harness/lod/factor_policy.cpp
  # Test files whose file-local helpers share a name with another file of their executable.
  tests/measures/cracks_test.cpp
  tests/measures/culling_test.cpp
  tests/measures/edge_pattern_cracks_test.cpp
  tests/measures/factor_policy_test.cpp
  tests/measures/mixed_domain_test.cpp
  tests/measures/pn_cracks_test.cpp
  tests/measures/screen_metrics_test.cpp
  tests/measures/watertight_variants_test.cpp
  tests/suite/scenario_file_test.cpp
  tests/techniques/gregory_acc_osd_test.cpp
  tests/techniques/gregory_acc_test.cpp
  tests/techniques/gregory_crease_test.cpp
  tests/techniques/patch_bounds_test.cpp
)
set(TB_UNITY_OFF_TARGETS tb_measures)
set(TB_UNITY_BATCH_SIZE 16)

function(tb_write_unity_batch target index content out_var)
  set(path ${CMAKE_BINARY_DIR}/unity/${target}_${index}.cpp)
  # Rewritten only when its content changes, so a re-configure rebuilds nothing.
  file(CONFIGURE OUTPUT ${path} CONTENT "// Unity batch of ${target} (cmake/Unity.cmake).\n${content}")
  set(${out_var} ${path} PARENT_SCOPE)
endfunction()

function(tb_unity_build target)
  get_target_property(dir ${target} SOURCE_DIR)
  get_target_property(sources ${target} SOURCES)
  set(batched "")
  set(batches "")
  set(content "")
  set(count 0)
  set(index 0)
  foreach(source IN LISTS sources)
    if(NOT source MATCHES "\\.cpp$")
      continue()
    endif()
    get_filename_component(absolute ${source} ABSOLUTE BASE_DIR ${dir})
    file(RELATIVE_PATH relative ${PROJECT_SOURCE_DIR} ${absolute})
    get_source_file_property(defs ${absolute} DIRECTORY ${dir} COMPILE_DEFINITIONS)
    get_source_file_property(opts ${absolute} DIRECTORY ${dir} COMPILE_OPTIONS)
    get_source_file_property(incs ${absolute} DIRECTORY ${dir} INCLUDE_DIRECTORIES)
    if(relative MATCHES "^\\.\\./" OR relative MATCHES "^build/" OR relative IN_LIST TB_UNITY_SKIP
       OR defs OR opts OR incs)
      continue()
    endif()
    string(APPEND content "#include \"${relative}\"\n")
    list(APPEND batched ${absolute})
    math(EXPR count "${count} + 1")
    if(count EQUAL TB_UNITY_BATCH_SIZE)
      tb_write_unity_batch(${target} ${index} "${content}" path)
      list(APPEND batches ${path})
      set(content "")
      set(count 0)
      math(EXPR index "${index} + 1")
    endif()
  endforeach()
  if(count GREATER 0)
    tb_write_unity_batch(${target} ${index} "${content}" path)
    list(APPEND batches ${path})
  endif()
  if(batched)
    set_source_files_properties(${batched} DIRECTORY ${dir} PROPERTIES HEADER_FILE_ONLY ON)
    target_sources(${target} PRIVATE ${batches})
  endif()
endfunction()

# Every library and executable defined so far (the layers and the CLI), in each folder.
function(tb_unity_build_all dir)
  get_property(targets DIRECTORY ${dir} PROPERTY BUILDSYSTEM_TARGETS)
  foreach(target IN LISTS targets)
    get_target_property(type ${target} TYPE)
    if((type STREQUAL "STATIC_LIBRARY" OR type STREQUAL "EXECUTABLE")
       AND NOT target IN_LIST TB_UNITY_OFF_TARGETS)
      tb_unity_build(${target})
    endif()
  endforeach()
  get_property(children DIRECTORY ${dir} PROPERTY SUBDIRECTORIES)
  foreach(child IN LISTS children)
    tb_unity_build_all(${child})
  endforeach()
endfunction()
