"""The defaults agree across the four interfaces. The filters take theirs from the core's
mobius::RegistrationParameters (TestParameterDefaults checks that); here every plugin XML
property's default_values is compared with the getter of a default-constructed filter, the
Python module's DEFAULT_OPTIONS with the filters, and mobius-register's --help "(default X)"
with the same. Paths: MOBIUS_PLUGIN_XML_DIR (Plugin/xml) and MOBIUS_REGISTER (the program)."""
import glob
import os
import re
import subprocess
import sys
import xml.etree.ElementTree as ElementTree

import mobiusregistration
import mobiusregistration.vtkMobiusRegistrationFilters as filters
from mobiusregistration.registration import DEFAULT_OPTIONS

failures = []


def expect_equal(what, actual, expected):
    if isinstance(expected, (list, tuple)):
        same = len(actual) == len(expected) and all(float(a) == float(e) for a, e in zip(actual, expected))
    else:
        same = float(actual) == float(expected)
    if not same:
        failures.append(f"{what}: {actual!r}, expected {expected!r}")


# 1. The plugin's XML against the filters.
xml_dir = os.environ["MOBIUS_PLUGIN_XML_DIR"]
checked = 0
# The XMLs as the plugin is built from them: a template (NAME.xml.in) gets the properties
# the filters share (xml/Shared) where CMake puts them.
# (Shared/LandmarkMode.xml at @MOBIUS_LANDMARK_MODE_PROPERTY@, as Plugin/CMakeLists.txt does).
shared = {}
for snippet in glob.glob(os.path.join(xml_dir, "Shared", "*.xml")):
    name = re.sub(r"([a-z])([A-Z])", r"\1_\2", os.path.basename(snippet)[:-len(".xml")]).upper()
    with open(snippet) as f:
        shared[f"@MOBIUS_{name}_PROPERTY@"] = f.read()
for path in sorted(glob.glob(os.path.join(xml_dir, "*.xml")) + glob.glob(os.path.join(xml_dir, "*.xml.in"))):
    with open(path) as f:
        text = f.read()
    for placeholder, snippet in shared.items():
        text = text.replace(placeholder, snippet)
    if "@MOBIUS_" in text:
        failures.append(f"{os.path.basename(path)}: a placeholder with no Shared snippet")
    for proxy in ElementTree.fromstring(text).iter("SourceProxy"):
        filter_class = getattr(filters, proxy.get("class"), None)
        if filter_class is None:
            failures.append(f"{os.path.basename(path)}: no class {proxy.get('class')}")
            continue
        instance = filter_class()
        for prop in proxy:
            command, defaults = prop.get("command"), prop.get("default_values")
            if not prop.tag.endswith("VectorProperty") or not command or defaults is None:
                continue
            getter = getattr(instance, "Get" + command[len("Set"):], None)
            if getter is None:
                continue  # e.g. a property set through a method with another name
            values = [float(v) for v in defaults.split()]
            actual = getter()
            actual = list(actual) if isinstance(actual, (list, tuple)) else actual
            expect_equal(f"{os.path.basename(path)} {prop.get('name')}", actual,
                         values if len(values) > 1 else values[0])
            checked += 1
# Enough properties compared that a change in how the XML is read cannot pass unnoticed.
if checked < 40:
    failures.append(f"only {checked} XML defaults compared")

# 2. Python's options against the filters.
conformal, registration = filters.vtkSphericalConformalMap(), filters.vtkSO3Register()
refinement = filters.vtkCorrespondenceRefinement()
python_expected = {
    "basis_size": refinement.GetBasisSize(), "polish": refinement.GetGeometricPolish(),
    "both_directions": refinement.GetBothDirections(),
    "resolution": registration.GetResolution(), "smoothing": registration.GetSmoothingTime(),
    "candidates": registration.GetNumberOfCandidates(),
    "candidate_separation": registration.GetCandidateSeparation(),
    "iterations": conformal.GetMaximumNumberOfIterations(),
    "tolerance": conformal.GetConvergenceTolerance(), "fill_holes": conformal.GetFillHoles(),
    "repair": conformal.GetRepair(),
    "keep_largest_component": conformal.GetKeepLargestComponent(),
    "threads": registration.GetNumberOfThreads(),
}
for key, expected in python_expected.items():
    expect_equal(f"DEFAULT_OPTIONS[{key!r}]", DEFAULT_OPTIONS[key], expected)
if DEFAULT_OPTIONS["transform"] != ["rotation", "reflection", "both"][registration.GetTransformMode()]:
    failures.append(f"DEFAULT_OPTIONS['transform'] {DEFAULT_OPTIONS['transform']!r}")
if DEFAULT_OPTIONS["candidate"] is not None or refinement.GetCandidate() != -1:
    failures.append("the refinement's candidate is chosen by default in one interface, not the other")

# 3. mobius-register's --help against the same.
help_text = subprocess.run([os.environ["MOBIUS_REGISTER"], "--help"], capture_output=True,
                           text=True, check=True).stdout
cli_expected = {
    "--iterations": python_expected["iterations"], "--tolerance": python_expected["tolerance"],
    "--resolution": python_expected["resolution"], "--smoothing": python_expected["smoothing"],
    "--candidates": python_expected["candidates"], "--basis-size": python_expected["basis_size"],
    "--candidate-separation": python_expected["candidate_separation"],
    "--threads": python_expected["threads"],
    "--degree": filters.vtkMobiusCenter().GetDegree(),
}
for option, expected in cli_expected.items():
    # The option's help runs from its line to the next option's.
    match = re.search(rf"^  {re.escape(option)} .*?\(default ([-+0-9.e]+)\)", help_text, re.M | re.S)
    if not match:
        failures.append(f"--help gives no default for {option}")
    else:
        expect_equal(f"--help {option}", float(match.group(1)), expected)
for option, word in (("--transform", DEFAULT_OPTIONS["transform"]),
                     ("--refine", "spectral" if DEFAULT_OPTIONS["refine"] else "none"),
                     ("--output-geometry", ["target", "source"][refinement.GetOutputGeometry()])):
    if not re.search(rf"^  {re.escape(option)} .*?\(default {word}\)", help_text, re.M | re.S):
        failures.append(f"--help {option}: default is not {word}")

# 4. One validation: a value out of range is refused by mobius-register, register() and
# vtkMobiusRegistration in the same words (mobius::CheckRegistrationParameters), each
# naming the parameter its own way.
from mobiusregistration import register  # noqa: E402
refused = 0
for option, keyword, prop, value in (("--basis-size", "basis_size", "BasisSize", 1),
                                     ("--candidates", "candidates", "NumberOfCandidates", 65),
                                     ("--candidate-separation", "candidate_separation",
                                      "CandidateSeparation", 200),
                                     ("--resolution", "resolution", "Resolution", 6),
                                     ("--threads", "threads", "NumberOfThreads", 1025),
                                     ("--iterations", "iterations", "MaximumNumberOfIterations", 0),
                                     ("--tolerance", "tolerance", "ConvergenceTolerance", 0),
                                     ("--smoothing", "smoothing", "SmoothingTime", 2)):
    # The meshes need not exist: options are checked first.
    cli = subprocess.run([os.environ["MOBIUS_REGISTER"], "a.off", "b.off", "-o", "never", option, str(value)],
                         capture_output=True, text=True)
    cli_words = re.fullmatch(rf"mobius-register: {re.escape(option)} needs (.+), not {value}\n", cli.stderr)
    try:
        register("a.off", "b.off", **{keyword: value})
        python_words = None
    except ValueError as error:
        python_words = re.fullmatch(rf"{keyword} must be (.+), got {value}", str(error))
    whole = filters.vtkMobiusRegistration()
    getattr(whole, "Set" + prop)(value)
    filter_words = re.fullmatch(rf"{prop} must be (.+) \(it is {value}\)", whole.CheckParameters())
    if cli.returncode != 2 or not cli_words or not python_words or not filter_words:
        failures.append(f"{option} {value}: {cli.returncode} {cli.stderr!r}, Python {python_words}, "
                        f"filter {whole.CheckParameters()!r}")
    elif not cli_words.group(1) == python_words.group(1) == filter_words.group(1):
        failures.append(f"{option} {value}: the interfaces disagree: {cli_words.group(1)!r}, "
                        f"{python_words.group(1)!r}, {filter_words.group(1)!r}")
    else:
        refused += 1
    getattr(whole, "Set" + prop)(getattr(filters.vtkMobiusRegistration(), "Get" + prop)())
    if whole.CheckParameters():
        failures.append(f"{prop}: its default refused: {whole.CheckParameters()!r}")

print(f"{checked} XML defaults, {len(python_expected) + 2} Python options, "
      f"{len(cli_expected) + 3} command-line options compared; {refused} values refused alike")
for failure in failures:
    print("FAIL:", failure)
sys.exit(1 if failures else 0)
