"""pvbatch (under Xvfb): the installed macro on two meshes makes the correspondence views
(run by check-deb-in-chroot.sh)."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from correspondence_views import MACRO, check_views, open_two_meshes  # noqa: E402
from plugin_proxies import check_plugin_proxies  # noqa: E402

folder = os.path.dirname(os.path.abspath(__file__))
print(check_plugin_proxies())
open_two_meshes(folder)
exec(open(MACRO).read(), {"__name__": "__main__"})
print("pvbatch:", check_views(os.path.join(folder, "pvbatch-macro.png")))
