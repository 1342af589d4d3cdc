# SPDX-License-Identifier: Apache-2.0
# Warnings live in a non-exported INTERFACE target, linked PRIVATE by our own targets.
add_library(ctab_warnings INTERFACE)
target_compile_options(ctab_warnings INTERFACE
  -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wsign-conversion -Wnon-virtual-dtor
  -Wold-style-cast -Wcast-align -Woverloaded-virtual -Wnull-dereference -Wdouble-promotion)
if(CTAB_WERROR)
  target_compile_options(ctab_warnings INTERFACE -Werror)
endif()

# ctab_target_warnings(TARGET): our warnings for TARGET's own sources only. Through BUILD_INTERFACE, so that an
# installed static library does not ask its consumers for a ctab_warnings target.
function(ctab_target_warnings target)
  target_link_libraries(${target} PRIVATE $<BUILD_INTERFACE:ctab_warnings>)
endfunction()
