# `cpack -G DEB` in the build folder: a Debian package of everything `cmake --install`
# puts in place. Configure with -DCMAKE_INSTALL_PREFIX=/usr for it: that is where Debian's
# ParaView and python3 look (the package is laid out exactly as the configured prefix).
set(CPACK_GENERATOR "DEB")
set(CPACK_PACKAGE_NAME "mobius-registration")
set(CPACK_PACKAGE_VERSION "${PROJECT_VERSION}")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
  "Moebius registration of genus-0 surface meshes for VTK and ParaView")
set(CPACK_DEBIAN_PACKAGE_DESCRIPTION
  "Dense correspondence between two genus-0 surface meshes by the method of
Baden, Crane and Kazhdan (Moebius Registration, SGP 2018), refined
spectrally: the mobius-register and mobius-benchmark programs, the VTK
filters (C++ headers, CMake package MobiusRegistration, Python package
mobiusregistration), a ParaView 5.11 plugin that ParaView loads at start-up
and a macro in ParaView's Macros menu that shows the correspondence.")
# The address the project's commits are made under; set MOBIUS_DEB_MAINTAINER for a package
# that someone maintains.
set(MOBIUS_DEB_MAINTAINER "Mobius Team <team@mobius.invalid>" CACHE STRING
  "Maintainer field of the Debian package: Name <address>")
set(CPACK_PACKAGE_CONTACT "${MOBIUS_DEB_MAINTAINER}")
set(CPACK_DEBIAN_PACKAGE_MAINTAINER "${MOBIUS_DEB_MAINTAINER}")
set(CPACK_DEBIAN_PACKAGE_SECTION "science")
set(CPACK_DEBIAN_FILE_NAME "DEB-DEFAULT")
set(CPACK_PACKAGING_INSTALL_PREFIX "${CMAKE_INSTALL_PREFIX}")
# Symbol tables out of the programs, libraries, plugin and Python extension (Debian policy).
set(CPACK_STRIP_FILES ON)
if (NOT CMAKE_INSTALL_PREFIX STREQUAL "/usr")
  message(STATUS "cpack -G DEB will lay the package out under ${CMAKE_INSTALL_PREFIX}; "
    "configure with -DCMAKE_INSTALL_PREFIX=/usr for a package Debian's ParaView and python3 find")
endif ()

# Shared-library dependencies (ParaView's VTK, FFTW, libstdc++) from dpkg-shlibdeps; the
# rest by hand: ParaView itself for the plugin and pvpython, its Python modules and numpy
# for the Python package (which imports vtkmodules).
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# Our own libraries, which the programs, plugin and Python module link, are in the package:
# dpkg-shlibdeps finds them in the build tree.
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS_PRIVATE_DIRS "${CMAKE_BINARY_DIR}/${CMAKE_INSTALL_LIBDIR}")
# The Python extension is built for this python3 (its C API), so the package needs that
# minor version.
math(EXPR mobius_next_python_minor "${Python3_VERSION_MINOR} + 1")
set(mobius_python_depends "python3 (>= ${Python3_VERSION_MAJOR}.${Python3_VERSION_MINOR}), python3 (<< ${Python3_VERSION_MAJOR}.${mobius_next_python_minor})")
if (MOBIUS_PARAVIEW)
  set(CPACK_DEBIAN_PACKAGE_DEPENDS
    "paraview (>= 5.11), paraview (<< 5.12), python3-paraview (>= 5.11), ${mobius_python_depends}, python3-numpy")
else ()
  set(CPACK_DEBIAN_PACKAGE_DEPENDS "python3-vtk9, ${mobius_python_depends}, python3-numpy")
endif ()

# Maintainer scripts. The shared library is in the linker's directories, so its cache is
# refreshed by dpkg's ldconfig trigger (triggers), not by calls in postinst/postrm (which
# CPack would generate unless the package has its own: they only end here). The prerm
# removes the bytecode Python writes on first import, so that removal leaves nothing.
set(mobius_python_package_dir "${CMAKE_INSTALL_PREFIX}/${mobius_python_destination}/mobiusregistration")
set(mobius_control_files)
foreach (script IN ITEMS prerm postinst postrm triggers)
  configure_file("${CMAKE_CURRENT_LIST_DIR}/debian/${script}.in" "${CMAKE_BINARY_DIR}/debian/${script}" @ONLY
    FILE_PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE GROUP_READ GROUP_EXECUTE WORLD_READ WORLD_EXECUTE)
  list(APPEND mobius_control_files "${CMAKE_BINARY_DIR}/debian/${script}")
endforeach ()
file(CHMOD "${CMAKE_BINARY_DIR}/debian/triggers" PERMISSIONS OWNER_READ OWNER_WRITE GROUP_READ WORLD_READ)
set(CPACK_DEBIAN_PACKAGE_CONTROL_EXTRA "${mobius_control_files}")
set(CPACK_DEBIAN_PACKAGE_CONTROL_STRICT_PERMISSION ON)

# Debian's documentation files: the copyright, in Debian's machine-readable format, its
# notice and licence text taken from LICENSE (one place for them), and the changelog
# (gzipped, reproducibly).
set(mobius_doc_destination "${CMAKE_INSTALL_DATAROOTDIR}/doc/mobius-registration")
file(READ "${CMAKE_SOURCE_DIR}/LICENSE" mobius_licence)
if (NOT mobius_licence MATCHES "\nCopyright \\(c\\) ([^\n]+)\n\n(.+)$")
  message(FATAL_ERROR "${CMAKE_SOURCE_DIR}/LICENSE has no 'Copyright (c) YEAR, HOLDER' line before its text")
endif ()
string(REPLACE ", " " " mobius_copyright "${CMAKE_MATCH_1}")
# The licence text as a field's continuation lines: each indented, an empty line as " .".
string(STRIP "${CMAKE_MATCH_2}" mobius_licence_text)
string(REGEX REPLACE "\n\n" "\n.\n" mobius_licence_text "${mobius_licence_text}")
string(REGEX REPLACE "\n" "\n " mobius_licence_text " ${mobius_licence_text}")
set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS "${CMAKE_SOURCE_DIR}/LICENSE")
configure_file("${CMAKE_CURRENT_LIST_DIR}/debian/copyright.in" "${CMAKE_BINARY_DIR}/debian/copyright" @ONLY)
configure_file("${CMAKE_CURRENT_LIST_DIR}/debian/changelog.in" "${CMAKE_BINARY_DIR}/debian/changelog" @ONLY)
execute_process(COMMAND "${MOBIUS_GZIP}" -9 -n -f -k "${CMAKE_BINARY_DIR}/debian/changelog"
  RESULT_VARIABLE mobius_gzip_failed)
if (mobius_gzip_failed)
  message(FATAL_ERROR "gzip could not compress ${CMAKE_BINARY_DIR}/debian/changelog")
endif ()
install(FILES "${CMAKE_BINARY_DIR}/debian/copyright" "${CMAKE_BINARY_DIR}/debian/changelog.gz"
  DESTINATION "${mobius_doc_destination}")
install(FILES "${CMAKE_SOURCE_DIR}/README.md" DESTINATION "${mobius_doc_destination}")
include(CPack)
