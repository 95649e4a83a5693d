"""pvpython with no PV_PLUGIN_PATH and no LoadPlugin: the plugin was loaded at start-up
(its filters are in the server manager's proxy list and in paraview.simple), one of them
runs, and the Python package imports (run by check-deb-in-chroot.sh)."""
import os
import sys

from paraview import servermanager
import paraview.simple as simple

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plugin_proxies import check_plugin_proxies  # noqa: E402

print(check_plugin_proxies())
conformal = simple.SphericalConformalMap(Input=simple.Sphere(ThetaResolution=24, PhiResolution=12))
conformal.UpdatePipeline()
assert servermanager.Fetch(conformal).GetNumberOfPoints() > 0
import mobiusregistration  # noqa: E402 (after ParaView's own modules, as a user would)
print("pvpython: the plugin's filters ran without LoadPlugin; mobiusregistration from", mobiusregistration.__file__)
