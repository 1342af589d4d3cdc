# SPDX-License-Identifier: Apache-2.0
# CTest fixture `package.install`: a fresh `cmake --install` of the build tree into PACKAGE_DIR/prefix, and a
# check that the installed package names no path of the build or source tree (it must be relocatable).
# cmake -D BUILD_DIR=... -D PACKAGE_DIR=... -D SOURCE_DIR=... -P install.cmake
file(REMOVE_RECURSE ${PACKAGE_DIR})
execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${PACKAGE_DIR}/prefix
                RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE output)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "cmake --install ${BUILD_DIR} failed (${result}):\n${output}")
endif()
file(GLOB_RECURSE package_files ${PACKAGE_DIR}/prefix/*.cmake)
if(NOT package_files)
  message(FATAL_ERROR "no CMake package files installed under ${PACKAGE_DIR}/prefix")
endif()
foreach(file IN LISTS package_files)
  file(READ ${file} text)
  foreach(tree IN ITEMS ${BUILD_DIR} ${SOURCE_DIR})
    string(FIND "${text}" "${tree}" at)
    if(NOT at EQUAL -1)
      message(FATAL_ERROR "${file} names ${tree}: the installed package is not relocatable")
    endif()
  endforeach()
endforeach()
list(LENGTH package_files count)
message(STATUS "installed ctab into ${PACKAGE_DIR}/prefix (${count} CMake package files)")
