# ccache where present (scripts/install_deps.sh installs it; a machine without it builds the
# same, only slower). base_dir = the source tree and hash_dir = false make the cache's keys
# relative to it, so another clone of the repository (CI's fresh clone, a worktree) reuses
# what this one compiled. TB_CCACHE=OFF turns it off.
option(TB_CCACHE "Compile through ccache when it is installed" ON)
if(TB_CCACHE AND NOT CMAKE_CXX_COMPILER_LAUNCHER)
  find_program(TB_CCACHE_PROGRAM ccache)
  if(TB_CCACHE_PROGRAM)
    set(_tb_launcher ${TB_CCACHE_PROGRAM} base_dir=${PROJECT_SOURCE_DIR} hash_dir=false)
    set(CMAKE_C_COMPILER_LAUNCHER ${_tb_launcher})
    set(CMAKE_CXX_COMPILER_LAUNCHER ${_tb_launcher})
  endif()
endif()
