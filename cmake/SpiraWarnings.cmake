# Warnings are errors in Spira's own code. Third-party headers come in through imported
# targets, whose include directories CMake marks as SYSTEM, so their warnings stay silent.
function(spira_target_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor
                                           -Woverloaded-virtual -Wno-unused-parameter -Werror)
endfunction()
