# Where an install puts things, decided before any target exists (RPATHs are read when a
# target is created). The build tree uses the same relative layout.

# Debian's python3 and pvpython both import from /usr/lib/python3/dist-packages (not the
# multiarch libdir), so the package goes there for the .deb; other prefixes get a .pth
# hook (MobiusInstall.cmake) so that Debian's python3 finds it there too.
set(mobius_python_destination "lib/python3/dist-packages")

# The demo mesh, installed with the program; mobius-register finds it relative to itself.
set(mobius_mesh_destination "${CMAKE_INSTALL_DATADIR}/mobius-registration/meshes")

# Installed programs and the Python extension find the module's library by a path relative
# to themselves ($ORIGIN), as the plugin does (paraview_plugin_build adds one): any prefix,
# `cmake --install --prefix` and DESTDIR staging keep working, and a staged /usr tree can be
# tested before it is in place. (Under /usr the libdir is on the linker's path anyway.)
file(RELATIVE_PATH mobius_bin_to_lib "/prefix/${CMAKE_INSTALL_BINDIR}" "/prefix/${CMAKE_INSTALL_LIBDIR}")
file(RELATIVE_PATH mobius_python_to_lib "/prefix/${mobius_python_destination}/mobiusregistration"
  "/prefix/${CMAKE_INSTALL_LIBDIR}")
list(APPEND CMAKE_INSTALL_RPATH "$ORIGIN/${mobius_bin_to_lib}" "$ORIGIN/${mobius_python_to_lib}")
list(REMOVE_DUPLICATES CMAKE_INSTALL_RPATH)
