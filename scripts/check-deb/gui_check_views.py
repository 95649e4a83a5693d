"""A check macro, put in the test user's ~/.config/ParaView/Macros and clicked in the GUI
after the installed MobiusRegistrationPipeline macro: writes what it finds to
/tmp/mobius-check/gui-result.txt ("ok ..." or "FAILED ...")."""
import sys
import traceback

sys.path.insert(0, "/tmp/mobius-check")
result = "FAILED: the check did not finish\n"
try:
    from correspondence_views import check_views
    plugin = open("/tmp/mobius-check/gui-plugin.txt").read()
    if plugin.startswith("FAILED"):
        result = plugin
    else:
        result = "ok: " + plugin + "ok: Macros -> MobiusRegistrationPipeline: " + \
            check_views("/tmp/mobius-check/gui-macro.png") + "\n"
except Exception:
    result = "FAILED: " + traceback.format_exc()
with open("/tmp/mobius-check/gui-result.txt", "w") as out:
    out.write(result)
