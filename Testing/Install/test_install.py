"""Install into a staging prefix and use everything from there, as a user would: the
programs (version, man pages, the demo on its installed mesh), the Python package under
python3 and pvpython, the ParaView plugin, and find_package(MobiusRegistration) from a
separate CMake project (Examples/Cxx) built and run against the staged tree."""
import argparse
import glob
import gzip
import os
import shutil
import subprocess
import sys

parser = argparse.ArgumentParser()
for option in ("--cmake", "--build", "--source", "--work", "--python", "--mesh-dir"):
    parser.add_argument(option, required=True)
parser.add_argument("--pvpython")
args = parser.parse_args()

shutil.rmtree(args.work, ignore_errors=True)
os.makedirs(args.work)
prefix = os.path.join(args.work, "prefix")
failures = []


def check(condition, message):
    if not condition:
        failures.append(message)
        print("FAILED:", message)


# Nothing from the build may leak in through the environment: the installed files must
# find each other by themselves.
clean_env = {name: value for name, value in os.environ.items()
             if name not in ("PYTHONPATH", "LD_LIBRARY_PATH", "PV_PLUGIN_PATH", "PV_PLUGIN_CONFIG_FILE")}


def run(command, env=None, cwd=None, timeout=600):
    result = subprocess.run(command, env=env or clean_env, cwd=cwd or args.work, capture_output=True,
                            text=True, errors="replace", timeout=timeout)
    if result.returncode != 0:
        print("$", " ".join(command), "\n", result.stdout[-3000:], result.stderr[-3000:])
    return result


result = run([args.cmake, "--install", args.build, "--prefix", prefix])
if result.returncode != 0:
    sys.exit("cmake --install failed")


def installed(pattern):
    return sorted(glob.glob(os.path.join(prefix, pattern), recursive=True))


# What the install must hold.
for pattern in ("bin/mobius-register", "bin/mobius-benchmark", "share/man/man1/mobius-register.1.gz",
                "share/man/man1/mobius-benchmark.1.gz", "include/MobiusRegistration/vtkSO3Register.h",
                "include/MobiusRegistration/vtkMobiusRegistrationFiltersModule.h",
                "lib*/**/cmake/MobiusRegistration/MobiusRegistrationConfig.cmake",
                "lib*/**/cmake/MobiusRegistration/MobiusRegistration-targets.cmake",
                "lib/python3/dist-packages/mobiusregistration/__init__.py",
                "share/mobius-registration/meshes/cow.off",
                "share/doc/mobius-registration/copyright", "share/doc/mobius-registration/changelog.gz"):
    check(installed(pattern), f"the install has no {pattern}")
check(not installed("**/*Test*"), f"tests were installed: {installed('**/*Test*')[:5]}")


def copyright_paragraphs(path):
    """The paragraphs of a Debian machine-readable copyright file, as {field: value}
    (continuation lines joined with newlines, their leading space and "." lines undone)."""
    paragraphs = []
    for block in open(path, encoding="utf-8").read().strip().split("\n\n"):
        fields, field = {}, None
        for line in block.split("\n"):
            if line.startswith(" "):
                fields[field] += "\n" + ("" if line == " ." else line[1:])
            else:
                field, _, value = line.partition(":")
                fields[field] = value.strip()
        paragraphs.append(fields)
    return paragraphs


# The copyright file (Debian's format 1.0): every Files paragraph names its copyright and a
# licence whose text is given, the project's text is LICENSE's, and each pattern but "*"
# matches an installed file.
header, *paragraphs = copyright_paragraphs(installed("share/doc/mobius-registration/copyright")[0])
check(header.get("Format") == "https://www.debian.org/doc/packaging-manuals/copyright-format/1.0/",
      f"copyright: not in Debian's format 1.0: {header}")
licence_texts = {p["License"].split("\n")[0]: p["License"].partition("\n")[2]
                 for p in paragraphs if "Files" not in p}
project_licence = open(os.path.join(args.source, "LICENSE"), encoding="utf-8").read()
check(licence_texts.get("BSD-3-Clause", "").strip() in project_licence and
      len(licence_texts.get("BSD-3-Clause", "")) > 1000, "copyright: the BSD-3-Clause text is not LICENSE's")
for files in (p for p in paragraphs if "Files" in p):
    check(files.get("Copyright") and files.get("License") in licence_texts,
          f"copyright: Files {files['Files']}: no Copyright, or a licence without its text")
    check(files["Files"] == "*" or installed(files["Files"].replace("*/", "**/")),
          f"copyright: Files {files['Files']} matches no installed file")

# Every installed binary finds the project's library by a path relative to itself: its
# RUNPATH holds only $ORIGIN-relative entries (no build folder, no absolute prefix), and
# the dynamic linker, with no LD_LIBRARY_PATH, resolves the library to the staged copy.
# A staging prefix is on no system path, so a wrong RPATH shows here as "not found" or as
# the build tree's copy.
library_name = "libvtkMobiusRegistrationFilters.so"
staged_library = installed(f"lib*/**/{library_name}")
check(len(staged_library) == 1, f"installed copies of {library_name}: {staged_library}")


def is_elf(path):
    with open(path, "rb") as f:
        return f.read(4) == b"\x7fELF"


elf_files = [path for path in installed("**/*")
             if os.path.isfile(path) and not os.path.islink(path) and is_elf(path)]
# Two programs, the library, the Python module, and the plugin when built with ParaView
# (pvpython given).
expected_binaries = 5 if args.pvpython else 4
check(len(elf_files) >= expected_binaries,
      f"too few installed binaries (programs, library, Python{', plugin' if args.pvpython else ''}): {elf_files}")
for path in elf_files:
    dynamic = run(["readelf", "-d", path]).stdout
    needs_library = any("(NEEDED)" in line and f"[{library_name}]" in line for line in dynamic.splitlines())
    runpaths = [entry for line in dynamic.splitlines() if "(RUNPATH)" in line or "(RPATH)" in line
                for entry in line.split("[", 1)[1].rstrip("]").split(":") if entry]
    check(all(entry.startswith("$ORIGIN") for entry in runpaths),
          f"{path}: RUNPATH entries not relative to $ORIGIN: {runpaths}")
    if needs_library and staged_library:
        check(runpaths, f"{path} needs {library_name} but has no RUNPATH")
        resolved = [line for line in run(["ldd", path]).stdout.splitlines() if library_name in line]
        check(resolved and os.path.realpath(resolved[0].split("=>")[1].split("(")[0].strip())
              == os.path.realpath(staged_library[0]),
              f"{path}: {library_name} resolves to {resolved}, not to the staged {staged_library[0]}")

# The programs: run from the staged bin, not the build.
program = os.path.join(prefix, "bin", "mobius-register")
result = run([program, "--version"])
check(result.returncode == 0 and result.stdout.startswith("mobius-register "),
      f"mobius-register --version: {result.returncode} {result.stdout!r}")
result = run([os.path.join(prefix, "bin", "mobius-benchmark"), "--help"])
check(result.returncode == 0 and "usage: mobius-benchmark" in result.stdout, "mobius-benchmark --help")
for name, option in (("mobius-register", "resolution"), ("mobius-benchmark", "repeat")):
    page = os.path.join(prefix, "share/man/man1", name + ".1.gz")
    text = gzip.open(page, "rt", encoding="utf-8").read() if os.path.exists(page) else ""
    check(text.startswith(".TH ") and ".SH SYNOPSIS" in text and f"\\-\\-{option}" in text,
          f"{page} is not the program's --help as a man page")
# The demo with no meshes given reads the installed cow (the build's copy is elsewhere);
# the Möbius map at a coarse resolution keeps it quick, and -o leaves out the picture
# (which needs a display).
result = run([program, "--resolution", "64", "--refine", "none", "--quiet", "--json", "-o", "demo"], timeout=600)
check(result.returncode == 0 and os.path.join(prefix, "share/mobius-registration/meshes/cow.off") in result.stdout,
      f"the installed demo did not run on the installed mesh: {result.returncode} {result.stdout[:500]!r}")
check(os.path.exists(os.path.join(args.work, "demo.vtp")), "the demo wrote no demo.vtp")

# The Python package from the staged dist-packages (a staging prefix is on no default path).
python_env = dict(clean_env, PYTHONPATH=os.path.join(prefix, "lib/python3/dist-packages"))
probe = ("import mobiusregistration, sys; assert mobiusregistration.__file__.startswith(sys.argv[1]), "
         "mobiusregistration.__file__; mobiusregistration.vtkSO3Register(); print('imported')")
interpreters = [args.python] + ([args.pvpython] if args.pvpython else [])
for interpreter in interpreters:
    result = run([interpreter, "-c", probe, prefix], env=python_env)
    check(result.returncode == 0 and "imported" in result.stdout,
          f"{interpreter}: import mobiusregistration from the staged prefix")

# The plugin, loaded by pvpython from the staged plugin directory, runs a filter by name.
if args.pvpython:
    plugins = installed("lib*/**/paraview-5.11/plugins/MobiusRegistration/MobiusRegistration.so")
    check(len(plugins) == 1, f"plugin files: {plugins}")
    # The autoload links (installed for the /usr prefix) must lead to the installed plugin
    # and macro.
    for link in installed("bin/plugins/*"):
        check(plugins and os.path.realpath(link) == os.path.realpath(plugins[0]),
              f"{link} does not lead to the installed plugin")
    macros = [os.path.join(prefix, "share/mobius-registration/macros", name)
              for name in ("MobiusRegistrationPipeline.py", "AddLandmarkPair.py")]
    for macro in macros:
        check(os.path.isfile(macro), f"the install has no ParaView macro {os.path.basename(macro)}")
    for link in installed("bin/Macros/*"):
        check(os.path.realpath(link) in {os.path.realpath(macro) for macro in macros},
              f"{link} does not lead to an installed macro")
    if plugins:
        script = (
            "import sys\n"
            "from paraview.simple import *\n"
            "from paraview import servermanager\n"
            "LoadPlugin(sys.argv[1], remote=False, ns=globals())\n"
            "sphere = Sphere(ThetaResolution=24, PhiResolution=12)\n"
            "conformal = SphericalConformalMap(Input=sphere)\n"
            "conformal.UpdatePipeline()\n"
            "assert servermanager.Fetch(conformal).GetNumberOfPoints() > 0\n"
            "print('plugin ran')\n")
        result = run([args.pvpython, "--force-offscreen-rendering", "-c", script, plugins[0]], env=clean_env)
        check(result.returncode == 0 and "plugin ran" in result.stdout, "pvpython: the staged plugin")

# A separate CMake project finds the staged package and builds the C++ example.
example_build = os.path.join(args.work, "example-build")
result = run([args.cmake, "-S", os.path.join(args.source, "Examples/Cxx"), "-B", example_build,
              f"-DCMAKE_PREFIX_PATH={prefix}", "-DCMAKE_BUILD_TYPE=Release"])
check(result.returncode == 0, "configure Examples/Cxx against the staged install")
if result.returncode == 0:
    result = run([args.cmake, "--build", example_build], timeout=900)
    check(result.returncode == 0, "build Examples/Cxx against the staged install")
    example = os.path.join(example_build, "register_two_meshes")
    if result.returncode == 0:
        result = run(["ldd", example])
        library = [line for line in result.stdout.splitlines() if "MobiusRegistration" in line]
        check(library and prefix in library[0], f"the example does not link the staged library: {library}")
        hand = os.path.join(args.mesh_dir, "hand.off")
        if os.path.exists(hand):
            output = os.path.join(args.work, "example.vtp")
            result = run([example, hand, hand, output])
            check(result.returncode == 0 and os.path.exists(output), "the example built on the install runs")

if failures:
    sys.exit(f"{len(failures)} check(s) failed")
print("install checks passed")
