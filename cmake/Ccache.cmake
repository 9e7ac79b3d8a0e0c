# ccache where present (scripts/install_deps.sh installs it; a machine without it builds the
# same, only slower). base_dir = the source tree and hash_dir = false make the cache's keys
# relative to it, so another clone of the repository (CI's fresh clone, a worktree) reuses
# what this one compiled. TB_CCACHE=OFF turns it off.
option(TB_CCACHE "Compile through ccache when it is installed" ON)
if(TB_CCACHE AND NOT CMAKE_CXX_COMPILER_LAUNCHER)
  find_program(TB_CCACHE_PROGRAM ccache)
  if(TB_CCACHE_PROGRAM)
    # ccache 4.7 (Debian 12) takes its settings from the environment only.
    set(_tb_launcher ${CMAKE_COMMAND} -E env CCACHE_BASEDIR=${PROJECT_SOURCE_DIR}
        CCACHE_NOHASHDIR=1 ${TB_CCACHE_PROGRAM})
    set(CMAKE_C_COMPILER_LAUNCHER ${_tb_launcher})
    set(CMAKE_CXX_COMPILER_LAUNCHER ${_tb_launcher})
  endif()
endif()
