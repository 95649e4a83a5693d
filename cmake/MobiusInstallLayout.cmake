# Where an install puts things, decided before any target exists (the targets' build and
# install folders follow it). The build tree uses the same relative layout.

# Debian's python3 and pvpython both import from /usr/lib/python3/dist-packages (not the
# multiarch libdir), so the package goes there for the .deb; other prefixes get a .pth
# hook (MobiusInstall.cmake) so that Debian's python3 finds it there too.
set(mobius_python_destination "lib/python3/dist-packages")

# The demo mesh, installed with the program; mobius-register finds it relative to itself.
set(mobius_mesh_destination "${CMAKE_INSTALL_DATADIR}/mobius-registration/meshes")

# Installed programs find the module's library by a path relative to themselves ($ORIGIN),
# as the plugin (paraview_plugin_build: $ORIGIN/../../..) and the Python extension
# (vtk_module_wrap_python's LIBRARY_DESTINATION) do: any prefix, `cmake --install --prefix`
# and DESTDIR staging keep working, and a staged /usr tree can be tested before it is in
# place. Each target gets only its own path (MobiusInstall.cmake sets the programs' once
# they exist); the library itself needs none.
file(RELATIVE_PATH mobius_bin_to_lib "/prefix/${CMAKE_INSTALL_BINDIR}" "/prefix/${CMAKE_INSTALL_LIBDIR}")
set(mobius_program_install_rpath "$ORIGIN/${mobius_bin_to_lib}")
