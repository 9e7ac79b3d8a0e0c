# `cmake --install build/release --prefix P`: the tessbench executable, what it reads at run
# time (the bundled assets and camera paths), and the SDK an out-of-tree technique builds
# against (docs/PLUGINS.md):
#   P/bin/tessbench
#   P/share/tessbench/assets/...            found beside the binary at run time
#   P/share/tessbench/shaders/common/*.glsl the GLSL a plug-in's shaders include (and the
#                                           layout/*.h they include)
#   P/include/tessbench/<path>.h            the plug-in headers and what they include, no more
#   P/lib/cmake/tessbench/                  tessbenchConfig.cmake: tessbench::sdk,
#                                           tessbench_add_plugin()
# Nothing installed names the build tree, so P can be moved.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(TB_INSTALL_INCLUDEDIR ${CMAKE_INSTALL_INCLUDEDIR}/tessbench)
set(TB_INSTALL_SHADERDIR ${CMAKE_INSTALL_DATADIR}/tessbench/shaders)
set(TB_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/tessbench)

# The plug-in headers (techniques/plugin.h and its include closure; tests/sdk checks the
# list is closed) plus the triangulation a triangle technique wants.
set(TB_SDK_HEADERS
  techniques/plugin.h
  techniques/technique.h
  techniques/batch_eval.h
  techniques/counting_scalar.h
  techniques/simulation.h
  techniques/constraint_solver.h
  techniques/wave_field.h
  core/gpu/patch_program_desc.h
  core/gpu/compute_program_desc.h
  shaders/common/layout/bindings.h
  core/mesh/mesh.h
  core/mesh/vec.h
  core/mesh/triangulate.h
  core/tess/tessellator.h)
foreach(header IN LISTS TB_SDK_HEADERS)
  get_filename_component(dir ${header} DIRECTORY)
  install(FILES ${PROJECT_SOURCE_DIR}/${header} DESTINATION ${TB_INSTALL_INCLUDEDIR}/${dir})
endforeach()

install(TARGETS tessbench RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/assets/ DESTINATION ${CMAKE_INSTALL_DATADIR}/tessbench/assets)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/shaders/common/ DESTINATION ${TB_INSTALL_SHADERDIR}/common
        FILES_MATCHING PATTERN "*.glsl" PATTERN "*.h")

configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/tessbenchConfig.cmake.in
  ${PROJECT_BINARY_DIR}/tessbenchConfig.cmake
  INSTALL_DESTINATION ${TB_INSTALL_CMAKEDIR}
  PATH_VARS TB_INSTALL_INCLUDEDIR TB_INSTALL_SHADERDIR CMAKE_INSTALL_BINDIR)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/tessbenchConfigVersion.cmake
  COMPATIBILITY ExactVersion)
install(FILES ${PROJECT_BINARY_DIR}/tessbenchConfig.cmake
              ${PROJECT_BINARY_DIR}/tessbenchConfigVersion.cmake
              ${PROJECT_SOURCE_DIR}/cmake/tessbenchPlugin.cmake
        DESTINATION ${TB_INSTALL_CMAKEDIR})
