# SPDX-License-Identifier: Apache-2.0
# ctab_hdf5: the HDF5 C library as this build links it (ctab::tables privately, the tests that write HDF5 files).
#
# With CTAB_STATIC_HDF5 (default in our own build) and Debian's archive beside the shared library (libhdf5-dev ships
# both), HDF5 is linked statically: the shared libhdf5 pulls in about 30 further shared libraries for its S3 driver
# (curl, TLS, Kerberos, LDAP), whose loading and relocation took 4.5 ms of every `ctab` process start (`ctab
# --version`: 7.2 -> 3.0 ms, docs/performance.md). The archive's own dependencies are linked as needed, so a program
# that uses none of the S3 driver loads neither curl nor libcrypto. Every target of the tree links HDF5 through
# this one target: one program never holds two copies of the library. Installed packages name HDF5::HDF5 (the
# consumer's find_dependency), never the archive.
include_guard(GLOBAL)

option(CTAB_STATIC_HDF5 "Link HDF5 statically into ctab's programs where the static archive is installed"
       ${CTAB_TOP_LEVEL})

add_library(ctab_hdf5 INTERFACE)
set(_ctab_hdf5_archive "")
if(CTAB_STATIC_HDF5)
  set(_ctab_hdf5_dirs "")
  foreach(_library IN LISTS HDF5_C_LIBRARIES)
    get_filename_component(_directory "${_library}" DIRECTORY)
    list(APPEND _ctab_hdf5_dirs "${_directory}")
  endforeach()
  find_library(CTAB_HDF5_ARCHIVE NAMES libhdf5.a libhdf5_serial.a HINTS ${_ctab_hdf5_dirs} NO_DEFAULT_PATH)
  if(CTAB_HDF5_ARCHIVE)
    set(_ctab_hdf5_archive "${CTAB_HDF5_ARCHIVE}")
  else()
    message(STATUS "ctab: no static HDF5 archive beside ${HDF5_C_LIBRARIES}; linking HDF5 as a shared library")
  endif()
endif()

if(_ctab_hdf5_archive)
  find_package(ZLIB REQUIRED)
  find_package(Threads REQUIRED)
  find_library(CTAB_SZIP_LIBRARY NAMES sz)  # libaec's szip interface (libsz2), HDF5's szip filter
  find_library(CTAB_CURL_LIBRARY NAMES curl)  # the S3 (ROS3) driver's: linked only where a program uses it
  find_library(CTAB_CRYPTO_LIBRARY NAMES crypto)
  target_include_directories(ctab_hdf5 SYSTEM INTERFACE ${HDF5_C_INCLUDE_DIRS})
  target_compile_definitions(ctab_hdf5 INTERFACE ${HDF5_C_DEFINITIONS})
  set(_as_needed "")
  foreach(_library IN ITEMS CTAB_SZIP_LIBRARY CTAB_CURL_LIBRARY CTAB_CRYPTO_LIBRARY)
    if(${_library})
      list(APPEND _as_needed "${${_library}}")
    endif()
  endforeach()
  target_link_libraries(ctab_hdf5 INTERFACE "${_ctab_hdf5_archive}" "-Wl,--push-state,--as-needed" ${_as_needed}
                        "-Wl,--pop-state" ZLIB::ZLIB Threads::Threads ${CMAKE_DL_LIBS} m)
  message(STATUS "ctab: HDF5 linked statically (${_ctab_hdf5_archive})")
else()
  target_link_libraries(ctab_hdf5 INTERFACE HDF5::HDF5)
endif()
