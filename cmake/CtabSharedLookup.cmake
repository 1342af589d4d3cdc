# SPDX-License-Identifier: Apache-2.0
# ctab_shared_lookup(TARGET OUTPUT_NAME SOURCE...): a shared library of the lookup's C API for C programs, dlopen
# and the Python module: libOUTPUT_NAME.so.SOVERSION (SONAME), VERSION the project's.
#
# It links the C++ runtime statically (-static-libstdc++ -static-libgcc) and exports only the ctab_* C symbols
# (cmake/ctab_lookup.map), so that a C linker alone links it and a program's own C++ runtime never meets its copy.
# SOVERSION: MAJOR.MINOR while the major version is 0 (a 0.x minor release may change the ABI, as
# ctabConfigVersion.cmake's SameMinorVersion says), MAJOR from 1.0 on.
include_guard(GLOBAL)

if(PROJECT_VERSION_MAJOR EQUAL 0)
  set(CTAB_SOVERSION ${PROJECT_VERSION_MAJOR}.${PROJECT_VERSION_MINOR})
else()
  set(CTAB_SOVERSION ${PROJECT_VERSION_MAJOR})
endif()

function(ctab_shared_lookup target output_name)
  add_library(${target} SHARED ${ARGN})
  set_target_properties(${target} PROPERTIES OUTPUT_NAME ${output_name} VERSION ${PROJECT_VERSION}
                        SOVERSION ${CTAB_SOVERSION} LIBRARY_OUTPUT_DIRECTORY ${PROJECT_BINARY_DIR}/lib
                        CXX_VISIBILITY_PRESET hidden VISIBILITY_INLINES_HIDDEN ON
                        LINK_DEPENDS ${PROJECT_SOURCE_DIR}/cmake/ctab_lookup.map)
  target_link_options(${target} PRIVATE -static-libstdc++ -static-libgcc
                      -Wl,--version-script=${PROJECT_SOURCE_DIR}/cmake/ctab_lookup.map)
  # Every symbol resolved at link time; not under a sanitizer, whose runtime the loading program provides.
  if(NOT CMAKE_CXX_FLAGS MATCHES "-fsanitize")
    target_link_options(${target} PRIVATE -Wl,--no-undefined)
  endif()
  target_include_directories(${target} PUBLIC $<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/lookup/include>)
  ctab_target_warnings(${target})
endfunction()
