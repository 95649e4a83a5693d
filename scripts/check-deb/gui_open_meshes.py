"""paraview --script: opens two meshes in the GUI before the recorded events click the
macros (paraview_gui_events.xml); also notes whether the plugin was there at start-up."""
import sys

sys.path.insert(0, "/tmp/mobius-check")
from correspondence_views import open_two_meshes  # noqa: E402
from plugin_proxies import check_plugin_proxies  # noqa: E402

with open("/tmp/mobius-check/gui-plugin.txt", "w") as note:
    try:
        note.write(check_plugin_proxies() + " at GUI start-up\n")
    except AssertionError as error:
        note.write(f"FAILED: {error}\n")
open_two_meshes("/tmp/mobius-check")
