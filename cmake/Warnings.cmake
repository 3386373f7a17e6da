# rtview_warnings(TARGET): the project's warning set, errors in CI (RTVIEW_WERROR).
function(rtview_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wconversion
                                           -Wno-sign-conversion
                                           # GCC 12 false positive on std::string concatenation (GCC bug 105329)
                                           -Wno-restrict)
  if(RTVIEW_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()
