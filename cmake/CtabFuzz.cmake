# SPDX-License-Identifier: Apache-2.0
# CTAB_FUZZ: every target of this build with AddressSanitizer, UndefinedBehaviorSanitizer and libFuzzer's coverage
# instrumentation (fuzzer-no-link: the libraries get no main of their own), the fuzz targets of fuzz/ linked with
# libFuzzer. Clang only: GCC has no libFuzzer.
if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
  message(FATAL_ERROR "CTAB_FUZZ needs clang (CXX=clang++ CC=clang); this build uses ${CMAKE_CXX_COMPILER_ID}")
endif()
add_compile_options(-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=undefined
                    -fno-omit-frame-pointer)
add_link_options(-fsanitize=address,undefined)
