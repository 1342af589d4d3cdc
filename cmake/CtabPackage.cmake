# SPDX-License-Identifier: Apache-2.0
# The installed CMake package `ctab`: libraries, headers and ctabConfig.cmake with namespaced targets ctab::NAME.
#
# A library joins the package in two calls, then the top-level CMakeLists.txt writes the package once:
#
#   ctab_package_component(COMPONENT [OPTIONAL] [REQUIRES COMPONENT...] [LANGUAGES LANG...]
#                          [DEPENDENCIES "PKG ARGS..."...])
#       declares a component of the package. DEPENDENCIES are find_dependency() argument strings that the
#       installed config runs before it loads the component's targets (only when the component is loaded);
#       LANGUAGES are enabled in the consumer first where it has not (FindHDF5 COMPONENTS C needs C).
#       REQUIRES names other components that are loaded first. OPTIONAL components are loaded only when asked
#       for (find_package(ctab COMPONENTS generator)); the others are loaded by a plain find_package(ctab).
#   ctab_install_library(TARGET COMPONENT NAME [INCLUDE_DIR DIR])
#       installs TARGET (its archive/library) into the component's export set as ctab::<EXPORT_NAME> (default:
#       the target name without its ctab_ prefix), and the headers under DIR (default: include/ of the calling
#       directory) into <prefix>/include; adds <prefix>/include to the target's installed include path.
#       Link ctab_warnings as $<BUILD_INTERFACE:ctab_warnings> (ctab_target_warnings()), never plainly: a static
#       library hands PRIVATE links on to its consumers.
#   ctab_install_package()
#       writes ctabConfig.cmake, ctabConfigVersion.cmake (0.2 accepts 0.2.x only: SameMinorVersion while < 1.0)
#       and one ctab-COMPONENT-targets.cmake per component into <prefix>/lib/cmake/ctab. With CTAB_INSTALL=OFF
#       (default under add_subdirectory) nothing is installed.
include_guard(GLOBAL)
include(CMakePackageConfigHelpers)

set(CTAB_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/ctab CACHE STRING "Where ctabConfig.cmake is installed")

function(ctab_package_component component)
  cmake_parse_arguments(PARSE_ARGV 1 arg "OPTIONAL" "" "REQUIRES;LANGUAGES;DEPENDENCIES")
  get_property(known GLOBAL PROPERTY CTAB_PACKAGE_COMPONENTS)
  if(component IN_LIST known)
    message(FATAL_ERROR "ctab_package_component: component '${component}' declared twice")
  endif()
  set_property(GLOBAL APPEND PROPERTY CTAB_PACKAGE_COMPONENTS ${component})
  set_property(GLOBAL PROPERTY CTAB_PACKAGE_${component}_OPTIONAL ${arg_OPTIONAL})
  set_property(GLOBAL PROPERTY CTAB_PACKAGE_${component}_REQUIRES ${arg_REQUIRES})
  set_property(GLOBAL PROPERTY CTAB_PACKAGE_${component}_DEPENDENCIES ${arg_DEPENDENCIES})
  set_property(GLOBAL PROPERTY CTAB_PACKAGE_${component}_LANGUAGES ${arg_LANGUAGES})
endfunction()

function(ctab_install_library target)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "COMPONENT;INCLUDE_DIR" "")
  get_property(known GLOBAL PROPERTY CTAB_PACKAGE_COMPONENTS)
  if(NOT arg_COMPONENT OR NOT arg_COMPONENT IN_LIST known)
    message(FATAL_ERROR "ctab_install_library(${target}): COMPONENT '${arg_COMPONENT}' is not declared "
                        "(ctab_package_component)")
  endif()
  if(NOT arg_INCLUDE_DIR)
    set(arg_INCLUDE_DIR ${CMAKE_CURRENT_SOURCE_DIR}/include)
  endif()
  get_target_property(export_name ${target} EXPORT_NAME)
  if(NOT export_name)
    string(REGEX REPLACE "^ctab_" "" export_name ${target})
    set_target_properties(${target} PROPERTIES EXPORT_NAME ${export_name})
  endif()
  set_property(GLOBAL APPEND PROPERTY CTAB_PACKAGE_${arg_COMPONENT}_TARGETS ${target})
  set_property(GLOBAL APPEND PROPERTY CTAB_PACKAGE_TARGETS ${target})
  target_include_directories(${target} PUBLIC $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  if(NOT CTAB_INSTALL)
    return()
  endif()
  install(TARGETS ${target} EXPORT ctab-${arg_COMPONENT}-targets
          ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
          RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
  install(DIRECTORY ${arg_INCLUDE_DIR}/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
          FILES_MATCHING PATTERN "*.hpp" PATTERN "*.h")
endfunction()

function(ctab_install_package)
  if(NOT CTAB_INSTALL)
    return()
  endif()
  get_property(components GLOBAL PROPERTY CTAB_PACKAGE_COMPONENTS)
  set(blocks "")
  foreach(component IN LISTS components)
    get_property(optional GLOBAL PROPERTY CTAB_PACKAGE_${component}_OPTIONAL)
    get_property(requires GLOBAL PROPERTY CTAB_PACKAGE_${component}_REQUIRES)
    get_property(dependencies GLOBAL PROPERTY CTAB_PACKAGE_${component}_DEPENDENCIES)
    get_property(languages GLOBAL PROPERTY CTAB_PACKAGE_${component}_LANGUAGES)
    get_property(targets GLOBAL PROPERTY CTAB_PACKAGE_${component}_TARGETS)
    if(NOT targets)
      message(FATAL_ERROR "ctab package component '${component}' has no installed library")
    endif()
    foreach(target IN LISTS targets)
      get_target_property(links ${target} LINK_LIBRARIES)
      if("ctab_warnings" IN_LIST links)
        message(FATAL_ERROR "${target} links ctab_warnings plainly; use ctab_target_warnings(${target}) so that "
                            "the installed package does not ask for it")
      endif()
    endforeach()
    install(EXPORT ctab-${component}-targets NAMESPACE ctab:: DESTINATION ${CTAB_INSTALL_CMAKEDIR})
    # The per-component part of ctabConfig.cmake: its requirements, then its find_dependency() calls.
    string(APPEND blocks "set(_ctab_${component}_optional ${optional})\n"
                         "set(_ctab_${component}_requires ${requires})\n"
                         "macro(_ctab_load_${component})\n")
    foreach(language IN LISTS languages)
      string(APPEND blocks "  get_property(_ctab_enabled GLOBAL PROPERTY ENABLED_LANGUAGES)\n"
                           "  if(NOT ${language} IN_LIST _ctab_enabled)\n    enable_language(${language})\n  endif()\n")
    endforeach()
    foreach(dependency IN LISTS dependencies)
      string(APPEND blocks "  find_dependency(${dependency})\n")
    endforeach()
    string(APPEND blocks "endmacro()\n")
  endforeach()
  set(CTAB_PACKAGE_COMPONENT_LIST "${components}")
  set(CTAB_PACKAGE_COMPONENT_BLOCKS "${blocks}")
  configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/ctabConfig.cmake.in
                                ${PROJECT_BINARY_DIR}/package/ctabConfig.cmake
                                INSTALL_DESTINATION ${CTAB_INSTALL_CMAKEDIR})
  write_basic_package_version_file(${PROJECT_BINARY_DIR}/package/ctabConfigVersion.cmake
                                   COMPATIBILITY SameMinorVersion)
  install(FILES ${PROJECT_BINARY_DIR}/package/ctabConfig.cmake ${PROJECT_BINARY_DIR}/package/ctabConfigVersion.cmake
          DESTINATION ${CTAB_INSTALL_CMAKEDIR})
endfunction()

# ctab_install_pkg_config(NAME TARGET DESCRIPTION): <libdir>/pkgconfig/NAME.pc for the shared library TARGET,
# relocatable (paths relative to the .pc file, so that `cmake --install build --prefix P` works for any P).
function(ctab_install_pkg_config name target description)
  if(NOT CTAB_INSTALL)
    return()
  endif()
  file(RELATIVE_PATH to_prefix /root/${CMAKE_INSTALL_LIBDIR}/pkgconfig /root)
  string(REGEX REPLACE "/$" "" to_prefix "${to_prefix}")
  get_target_property(library ${target} OUTPUT_NAME)
  set(pc ${PROJECT_BINARY_DIR}/package/${name}.pc)
  file(WRITE ${pc}
       "prefix=\${pcfiledir}/${to_prefix}\nlibdir=\${prefix}/${CMAKE_INSTALL_LIBDIR}\n"
       "includedir=\${prefix}/${CMAKE_INSTALL_INCLUDEDIR}\n\n"
       "Name: ${name}\nDescription: ctab ${PROJECT_VERSION}: ${description}\nVersion: ${PROJECT_VERSION}\n"
       "Cflags: -I\${includedir}\nLibs: -L\${libdir} -l${library}\n")
  install(FILES ${pc} DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
endfunction()
