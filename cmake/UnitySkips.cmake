# Files kept out of the unity build (TB_UNITY_BUILD, top-level CMakeLists.txt): each has a
# file-local name (anonymous namespace or static) that another file of its library also
# defines, so the two cannot share one translation unit. Paths are relative to the source root.
set(TB_UNITY_SKIP
  core/tess/triangle_domain.cpp
  core/gpu/tess_capture.cpp
  techniques/gregory_acc/gregory_stencils.cpp
  harness/lod/factor_policy.cpp
)
foreach(path IN LISTS TB_UNITY_SKIP)
  # The directory whose CMakeLists.txt lists the file: the nearest one above it.
  get_filename_component(dir ${PROJECT_SOURCE_DIR}/${path} DIRECTORY)
  while(NOT EXISTS ${dir}/CMakeLists.txt)
    get_filename_component(dir ${dir} DIRECTORY)
  endwhile()
  set_source_files_properties(${PROJECT_SOURCE_DIR}/${path} DIRECTORY ${dir}
    PROPERTIES SKIP_UNITY_BUILD_INCLUSION ON)
endforeach()
# Libraries built file by file: their files share many file-local names.
foreach(target tb_measures)
  if(TARGET ${target})
    set_target_properties(${target} PROPERTIES UNITY_BUILD OFF)
  endif()
endforeach()
