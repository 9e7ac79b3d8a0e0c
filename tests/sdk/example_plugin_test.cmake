# Run by ctest (tests/sdk/CMakeLists.txt) with BUILD_DIR, SOURCE_DIR, SCRATCH_DIR, PYTHON and
# GENERATOR. Each step stops the test with its output when it fails.
function(step what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${what} failed (${rc}):\n${out}\n${err}")
  endif()
  message(STATUS "${what}: ok")
endfunction()

file(REMOVE_RECURSE ${SCRATCH_DIR})
file(MAKE_DIRECTORY ${SCRATCH_DIR})
set(installed ${SCRATCH_DIR}/installed)
set(prefix ${SCRATCH_DIR}/prefix)

step("install" ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${installed})
# Relocatable: the tree works after a move, and no installed text file names the build or
# source tree.
file(RENAME ${installed} ${prefix})
file(GLOB_RECURSE text_files ${prefix}/*.cmake ${prefix}/*.h ${prefix}/*.glsl)
foreach(file IN LISTS text_files)
  file(READ ${file} content)
  foreach(tree ${BUILD_DIR} ${SOURCE_DIR} ${installed})
    string(FIND "${content}" "${tree}" at)
    if(NOT at EQUAL -1)
      message(FATAL_ERROR "${file} names ${tree}: the installed tree is not relocatable")
    endif()
  endforeach()
endforeach()
# The moved binary reads its own share/tessbench/assets, not the source tree's.
file(COPY ${SOURCE_DIR}/assets/opensubdiv/catmark_cube.obj DESTINATION ${prefix}/share/tessbench/assets/sdk_probe)
execute_process(COMMAND ${prefix}/bin/tessbench list assets OUTPUT_VARIABLE assets RESULT_VARIABLE rc)
string(FIND "${assets}" "sdk_probe/catmark_cube" at)
if(NOT rc EQUAL 0 OR at EQUAL -1)
  message(FATAL_ERROR "the installed tessbench does not list its own assets:\n${assets}")
endif()
file(REMOVE_RECURSE ${prefix}/share/tessbench/assets/sdk_probe)
execute_process(COMMAND ${prefix}/bin/tessbench --version OUTPUT_VARIABLE version)
message(STATUS "installed: ${version}")

# The example, copied outside the source tree, configured with the prefix alone.
file(COPY ${SOURCE_DIR}/examples/plugin/ DESTINATION ${SCRATCH_DIR}/plugin_src)
step("configure examples/plugin" ${CMAKE_COMMAND} -S ${SCRATCH_DIR}/plugin_src
     -B ${SCRATCH_DIR}/plugin_build -G ${GENERATOR} -DCMAKE_BUILD_TYPE=Release
     -DCMAKE_PREFIX_PATH=${prefix})
step("build examples/plugin" ${CMAKE_COMMAND} --build ${SCRATCH_DIR}/plugin_build)

set(plugin ${SCRATCH_DIR}/plugin_build/flat_plugin.so)
step("run flat on catmark_cube" ${prefix}/bin/tessbench --plugin ${plugin} run --quiet
     --technique flat --asset catmark_cube --out ${SCRATCH_DIR}/results --run-id flat)
step("check the records" ${PYTHON} ${SOURCE_DIR}/tests/sdk/check_plugin_results.py
     ${SCRATCH_DIR}/results/flat/results.json)
