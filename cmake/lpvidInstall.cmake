# Install rules and the CMake package `lpvid` (a library for other
# projects): `cmake --install build --prefix P`, then in another project
# `find_package(lpvid CONFIG REQUIRED)` and link lpvid::core, lpvid::verify or
# lpvid::lib. Kept in its own file, included at the end of the top-level one,
# so that the target definitions there stay as they are: what installing
# needs from those targets is adjusted here, after they exist.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(LPVID_INSTALL_INCLUDEDIR ${CMAKE_INSTALL_INCLUDEDIR}/lpvid)
set(LPVID_INSTALL_CMAKEDIR ${CMAKE_INSTALL_LIBDIR}/cmake/lpvid)

set(LPVID_INSTALL_LIBS lpvid_core lpvid_verify_lib)
if(TARGET lpvid_lib)
  list(APPEND LPVID_INSTALL_LIBS lpvid_lib)
endif()

# Exported names: lpvid::core, lpvid::verify, lpvid::lib. The aliases give a
# project that adds this tree with add_subdirectory the same names.
set_target_properties(lpvid_core PROPERTIES EXPORT_NAME core)
set_target_properties(lpvid_verify_lib PROPERTIES EXPORT_NAME verify)
add_library(lpvid::core ALIAS lpvid_core)
add_library(lpvid::verify ALIAS lpvid_verify_lib)
if(TARGET lpvid_lib)
  set_target_properties(lpvid_lib PROPERTIES EXPORT_NAME lib)
  add_library(lpvid::lib ALIAS lpvid_lib)
endif()

# Headers go to include/lpvid/ in the folders the sources use
# ("model/lpv_model.h", "verify/psd/exact_psd.h"), so one include directory
# serves every library. The top-level file gives the source folders as plain
# paths, which install(EXPORT) rejects: they are kept for the build tree only.
foreach(t ${LPVID_INSTALL_LIBS})
  get_target_property(dirs ${t} INTERFACE_INCLUDE_DIRECTORIES)
  set(wrapped)
  foreach(d ${dirs})
    list(APPEND wrapped "$<BUILD_INTERFACE:${d}>")
  endforeach()
  set_property(TARGET ${t} PROPERTY INTERFACE_INCLUDE_DIRECTORIES
    ${wrapped} "$<INSTALL_INTERFACE:${LPVID_INSTALL_INCLUDEDIR}>")
endforeach()

# lpvid_lib links the solver libraries by the absolute paths find_library gave
# here. An installed package must not carry them (another machine, another
# multiarch folder): in the install interface each becomes lpvid::dep_<name>,
# an imported target that lpvidConfig.cmake finds again with find_library.
# Libraries given by name (gfortran, m) stay names: the compiler driver finds
# them (libgfortran.so lives in GCC's own folder, not on find_library's path).
set(LPVID_CONFIG_FIND_LIBRARIES "")
if(TARGET lpvid_lib)
  get_target_property(links lpvid_lib INTERFACE_LINK_LIBRARIES)
  set(relocatable)
  foreach(item ${links})
    if(IS_ABSOLUTE "${item}")
      get_filename_component(file "${item}" NAME)
      get_filename_component(dir "${item}" DIRECTORY)
      string(REGEX REPLACE "^lib([^.]+)\\..*$" "\\1" stem "${file}")
      list(APPEND relocatable "$<BUILD_INTERFACE:${item}>" "$<INSTALL_INTERFACE:lpvid::dep_${stem}>")
      string(APPEND LPVID_CONFIG_FIND_LIBRARIES "lpvid_find_dep_library(${stem} ${file} \"${dir}\")\n")
    else()
      list(APPEND relocatable "${item}")
    endif()
  endforeach()
  set_property(TARGET lpvid_lib PROPERTY INTERFACE_LINK_LIBRARIES ${relocatable})
endif()

# The certificate format this build reads and writes (verify/certificate/certificate_file.h),
# published as lpvid_CERTIFICATE_FORMAT next to the JSON Schema of the format.
file(STRINGS ${PROJECT_SOURCE_DIR}/verify/certificate/certificate_file.h format_line REGEX "kCertificateFormat = \"")
string(REGEX REPLACE ".*kCertificateFormat = \"([^\"]+)\".*" "\\1" LPVID_CERTIFICATE_FORMAT "${format_line}")

set(LPVID_INSTALL_TARGETS ${LPVID_INSTALL_LIBS} lpvid-verify)
if(TARGET lpvid)
  list(APPEND LPVID_INSTALL_TARGETS lpvid)
endif()
install(TARGETS ${LPVID_INSTALL_TARGETS} EXPORT lpvidTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
  RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/src/ DESTINATION ${LPVID_INSTALL_INCLUDEDIR}
  FILES_MATCHING PATTERN "*.h"
  PATTERN "cli" EXCLUDE)  # the command line's own headers (they need CLI11)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/verify/ DESTINATION ${LPVID_INSTALL_INCLUDEDIR}/verify
  FILES_MATCHING PATTERN "*.h"
  PATTERN "verify_command_line.h" EXCLUDE)  # the program's command line (in no installed library)
install(FILES ${PROJECT_SOURCE_DIR}/docs/certificate.schema.json ${PROJECT_SOURCE_DIR}/docs/certificate_format.md
  DESTINATION ${CMAKE_INSTALL_DATADIR}/lpvid)
# The commands' report schemas (docs/reports.md), for programs that read the reports.
file(GLOB LPVID_REPORT_SCHEMAS ${PROJECT_SOURCE_DIR}/docs/*_report.schema.json)
install(FILES ${LPVID_REPORT_SCHEMAS} ${PROJECT_SOURCE_DIR}/docs/reports.md DESTINATION ${CMAKE_INSTALL_DATADIR}/lpvid)

install(EXPORT lpvidTargets NAMESPACE lpvid:: DESTINATION ${LPVID_INSTALL_CMAKEDIR})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/lpvidConfig.cmake.in
  ${PROJECT_BINARY_DIR}/lpvidConfig.cmake
  INSTALL_DESTINATION ${LPVID_INSTALL_CMAKEDIR}
  PATH_VARS CMAKE_INSTALL_DATADIR)
# 0.x: a minor version may change the API, so only the same minor is compatible.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/lpvidConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/lpvidConfig.cmake ${PROJECT_BINARY_DIR}/lpvidConfigVersion.cmake
  DESTINATION ${LPVID_INSTALL_CMAKEDIR})
