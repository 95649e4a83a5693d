# What `cmake --install` (and the .deb) adds beyond the targets' own install rules: man
# pages, the demo mesh, the CMake package configuration, the Python hooks, and the
# ParaView plugin's autoload link.

# The installed programs find the module's library relative to themselves.
set_property(TARGET mobius-register mobius-benchmark PROPERTY INSTALL_RPATH "${mobius_program_install_rpath}")

# Man pages, rendered from each program's --help at build time and installed gzipped
# (-n: no name or time stamp in the .gz, so that rebuilding gives the same bytes).
find_program(MOBIUS_GZIP gzip REQUIRED)
foreach (program IN ITEMS mobius-register mobius-benchmark)
  set(summary_mobius-register "dense correspondence between two genus-0 surface meshes")
  set(summary_mobius-benchmark "per-stage time, quality figures and memory of the registration pipeline")
  set(man_page "${CMAKE_BINARY_DIR}/${CMAKE_INSTALL_MANDIR}/man1/${program}.1")
  add_custom_command(
    OUTPUT  "${man_page}" "${man_page}.gz"
    COMMAND "${CMAKE_COMMAND}" -E make_directory "${CMAKE_BINARY_DIR}/${CMAKE_INSTALL_MANDIR}/man1"
    COMMAND "${Python3_EXECUTABLE}" "${CMAKE_CURRENT_LIST_DIR}/help_to_man.py"
            "$<TARGET_FILE:${program}>" "${program}" "${summary_${program}}" "${man_page}"
    COMMAND "${MOBIUS_GZIP}" -9 -n -f -k "${man_page}"
    DEPENDS "${program}" "${CMAKE_CURRENT_LIST_DIR}/help_to_man.py"
    COMMENT "Man page of ${program} from its --help"
    VERBATIM)
  add_custom_target("${program}-man" ALL DEPENDS "${man_page}.gz")
  install(FILES "${man_page}.gz" DESTINATION "${CMAKE_INSTALL_MANDIR}/man1")
endforeach ()

# The demo's mesh (CGAL's cow, CC0): `mobius-register` with no meshes runs on it.
if (EXISTS "${MOBIUS_MESH_DIR}/cow.off")
  install(FILES "${MOBIUS_MESH_DIR}/cow.off" DESTINATION "${mobius_mesh_destination}")
endif ()

# find_package(MobiusRegistration): the config next to the targets file and the module
# properties file that vtk_module_build writes (in the build tree and the install tree).
set(mobius_cmake_destination "${CMAKE_INSTALL_LIBDIR}/cmake/MobiusRegistration")
set(mobius_vtk_link_components CommonCore CommonDataModel CommonExecutionModel CommonMath
  FiltersCore IOGeometry IOLegacy IOPLY IOXML ParallelCore)
include(CMakePackageConfigHelpers)
configure_file("${CMAKE_CURRENT_LIST_DIR}/MobiusRegistrationConfig.cmake.in"
  "${CMAKE_BINARY_DIR}/${mobius_cmake_destination}/MobiusRegistrationConfig.cmake" @ONLY)
write_basic_package_version_file(
  "${CMAKE_BINARY_DIR}/${mobius_cmake_destination}/MobiusRegistrationConfigVersion.cmake"
  COMPATIBILITY SameMinorVersion)
install(FILES
  "${CMAKE_BINARY_DIR}/${mobius_cmake_destination}/MobiusRegistrationConfig.cmake"
  "${CMAKE_BINARY_DIR}/${mobius_cmake_destination}/MobiusRegistrationConfigVersion.cmake"
  DESTINATION "${mobius_cmake_destination}")

# Outside /usr, Debian's python3 searches <prefix>/lib/python3.X/dist-packages (for
# /usr/local) rather than lib/python3/dist-packages: a .pth file there adds the package's
# folder, by a path relative to the .pth, so that any prefix keeps working.
if (NOT CMAKE_INSTALL_PREFIX STREQUAL "/usr")
  set(mobius_site_destination
    "lib/python${Python3_VERSION_MAJOR}.${Python3_VERSION_MINOR}/dist-packages")
  file(RELATIVE_PATH mobius_site_to_package "/prefix/${mobius_site_destination}"
    "/prefix/${mobius_python_destination}")
  file(WRITE "${CMAKE_BINARY_DIR}/CMakeFiles/mobiusregistration.pth" "${mobius_site_to_package}\n")
  install(FILES "${CMAKE_BINARY_DIR}/CMakeFiles/mobiusregistration.pth"
    DESTINATION "${mobius_site_destination}")
endif ()

if (MOBIUS_PARAVIEW)
  # The macros (plain paraview.simple Python), for Macros -> Import new macro...: the
  # correspondence view, and landmark pairs from point selections.
  set(mobius_macro_destination "${CMAKE_INSTALL_DATADIR}/mobius-registration/macros")
  set(mobius_macros MobiusRegistrationPipeline.py AddLandmarkPair.py)
  foreach (macro IN LISTS mobius_macros)
    install(FILES "${PROJECT_SOURCE_DIR}/Examples/ParaView/${macro}"
      DESTINATION "${mobius_macro_destination}")
  endforeach ()

  # Debian's ParaView 5.11 loads, at start-up and without any environment variable, every
  # plugin in <directory of the executable>/plugins (vtkPVPluginLoader's search path:
  # PV_PLUGIN_PATH, then /usr/bin/plugins for /usr/bin/paraview, pvpython and pvbatch).
  # It reads no other plugin list: the paraview.plugins.xml in its plugin directory is
  # never loaded (no /usr/bin/paraview.conf). So the plugin stays in ParaView's plugin
  # directory and a relative link in bin/plugins makes ParaView load it.
  # Its Macros menu likewise lists every file in <directory of the executable>/Macros
  # (pqPythonMacroSupervisor: <app dir>/Macros, <app dir>/../Macros, the user's
  # ~/.config/ParaView/Macros and PV_MACRO_PATH), so a link in bin/Macros puts each macro
  # in the menu of every user.
  # AUTO: the links for the /usr prefix (where Debian's ParaView is), decided again
  # whenever the prefix changes.
  set(MOBIUS_PARAVIEW_AUTOLOAD "AUTO" CACHE STRING
    "Install links in <prefix>/bin/plugins and <prefix>/bin/Macros so that a ParaView in the same prefix loads the plugin at start-up and lists the macro: AUTO (for /usr), ON or OFF")
  set_property(CACHE MOBIUS_PARAVIEW_AUTOLOAD PROPERTY STRINGS AUTO ON OFF)
  set(mobius_autoload "${MOBIUS_PARAVIEW_AUTOLOAD}")
  if (mobius_autoload STREQUAL "AUTO")
    set(mobius_autoload OFF)
    if (CMAKE_INSTALL_PREFIX STREQUAL "/usr")
      set(mobius_autoload ON)
    endif ()
  endif ()
  if (mobius_autoload)
    # A relative symbolic link <prefix>/<link_dir>/<name> to <prefix>/<target>.
    function (mobius_install_relative_link link_dir target)
      get_filename_component(name "${target}" NAME)
      file(RELATIVE_PATH relative "/prefix/${link_dir}" "/prefix/${target}")
      set(link "${CMAKE_BINARY_DIR}/CMakeFiles/links/${link_dir}/${name}")
      get_filename_component(link_parent "${link}" DIRECTORY)
      file(MAKE_DIRECTORY "${link_parent}")
      file(CREATE_LINK "${relative}" "${link}" SYMBOLIC)
      install(FILES "${link}" DESTINATION "${link_dir}")
    endfunction ()
    mobius_install_relative_link("${CMAKE_INSTALL_BINDIR}/plugins"
      "${CMAKE_INSTALL_LIBDIR}/paraview-5.11/plugins/MobiusRegistration/MobiusRegistration.so")
    foreach (macro IN LISTS mobius_macros)
      mobius_install_relative_link("${CMAKE_INSTALL_BINDIR}/Macros"
        "${mobius_macro_destination}/${macro}")
    endforeach ()
    # Lintian flags folders in /usr/bin; these two are where ParaView looks (the file says why).
    install(FILES "${CMAKE_CURRENT_LIST_DIR}/debian/lintian-overrides"
      DESTINATION "${CMAKE_INSTALL_DATAROOTDIR}/lintian/overrides" RENAME mobius-registration)
  endif ()
endif ()

include("${CMAKE_CURRENT_LIST_DIR}/MobiusPackage.cmake")
