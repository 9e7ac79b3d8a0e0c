# Fails when a source, script, shader or document names a file outside the repository:
# the shared folder beside the checkout, or design documents other than docs/.
file(GLOB_RECURSE candidates RELATIVE ${ROOT}
  ${ROOT}/*.h ${ROOT}/*.cpp ${ROOT}/*.glsl ${ROOT}/*.tesc ${ROOT}/*.tese ${ROOT}/*.comp
  ${ROOT}/*.vert ${ROOT}/*.frag ${ROOT}/*.txt ${ROOT}/*.cmake ${ROOT}/*.md ${ROOT}/*.sh
  ${ROOT}/*.py ${ROOT}/*.json ${ROOT}/.ci/run)
set(offenders "")
foreach(path IN LISTS candidates)
  if(path MATCHES "^(build|results|assets)/" OR path MATCHES "check_self_contained.cmake$")
    continue()
  endif()
  file(STRINGS ${ROOT}/${path} lines REGEX "\\.\\./shared|DESIGN\\.md|[^/]STYLE\\.md|^STYLE\\.md")
  foreach(line IN LISTS lines)
    if(path STREQUAL "docs/ARCHITECTURE.md" OR path STREQUAL "docs/STYLE.md")
      if(NOT line MATCHES "\\.\\./shared|DESIGN\\.md")
        continue()  # the two docs link each other by file name
      endif()
    endif()
    if(path STREQUAL "README.md" AND line MATCHES "docs/STYLE\\.md")
      continue()
    endif()
    string(APPEND offenders "${path}: ${line}\n")
  endforeach()
endforeach()
if(offenders)
  message(FATAL_ERROR "files refer outside the repository:\n${offenders}")
endif()
