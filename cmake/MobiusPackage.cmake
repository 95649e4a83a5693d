# `cpack -G DEB` in the build folder: a Debian package of everything `cmake --install`
# puts in place. Configure with -DCMAKE_INSTALL_PREFIX=/usr for it: that is where Debian's
# ParaView and python3 look (the package is laid out exactly as the configured prefix).
set(CPACK_GENERATOR "DEB")
set(CPACK_PACKAGE_NAME "mobius-registration")
set(CPACK_PACKAGE_VERSION "${PROJECT_VERSION}")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
  "Moebius registration of genus-0 surface meshes for VTK and ParaView")
set(CPACK_DEBIAN_PACKAGE_DESCRIPTION
  "Dense correspondence between two genus-0 surface meshes by the method of Baden, Crane
and Kazhdan (Moebius Registration, SGP 2018), refined spectrally: the mobius-register
and mobius-benchmark programs, the VTK filters (C++ headers, CMake package
MobiusRegistration, Python package mobiusregistration) and a ParaView 5.11 plugin
that ParaView loads at start-up.")
set(CPACK_PACKAGE_CONTACT "Moebius Registration for VTK and ParaView developers")
set(CPACK_DEBIAN_PACKAGE_SECTION "science")
set(CPACK_DEBIAN_FILE_NAME "DEB-DEFAULT")
set(CPACK_PACKAGING_INSTALL_PREFIX "${CMAKE_INSTALL_PREFIX}")
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
if (MOBIUS_PARAVIEW)
  set(CPACK_DEBIAN_PACKAGE_DEPENDS
    "paraview (>= 5.11), paraview (<< 5.12), python3-paraview (>= 5.11), python3-numpy")
else ()
  set(CPACK_DEBIAN_PACKAGE_DEPENDS "python3-vtk9, python3-numpy")
endif ()

# Maintainer scripts: CPack's own postinst/postrm run ldconfig for the library; the prerm
# removes the bytecode Python writes on first import, so that removal leaves nothing.
set(mobius_python_package_dir "${CMAKE_INSTALL_PREFIX}/${mobius_python_destination}/mobiusregistration")
configure_file("${CMAKE_CURRENT_LIST_DIR}/debian/prerm.in" "${CMAKE_BINARY_DIR}/debian/prerm" @ONLY
  FILE_PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE GROUP_READ GROUP_EXECUTE WORLD_READ WORLD_EXECUTE)
set(CPACK_DEBIAN_PACKAGE_CONTROL_EXTRA "${CMAKE_BINARY_DIR}/debian/prerm")
set(CPACK_DEBIAN_PACKAGE_CONTROL_STRICT_PERMISSION ON)

install(FILES "${CMAKE_SOURCE_DIR}/README.md" DESTINATION "${CMAKE_INSTALL_DATAROOTDIR}/doc/mobius-registration")
include(CPack)
