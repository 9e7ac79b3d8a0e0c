# tb_set_warnings(target): our code builds with -Wall -Wextra -Wshadow and no warnings.
# Third-party headers are included as SYSTEM so their warnings do not count.
function(tb_set_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wshadow)
  if(TB_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()
option(TB_WERROR "Treat warnings in tessbench code as errors" OFF)
