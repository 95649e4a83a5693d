"""Run by the ParaView GUI (paraview --script=...) from gui_screenshot.sh: loads the plugin
and two meshes, runs the macro, and writes a marker file when the views are drawn. The
paths come from the environment (paraview passes no arguments to a script)."""
import os

from paraview.simple import LoadPlugin, OpenDataFile, SetActiveSource

env = os.environ
LoadPlugin(env["MOBIUS_PLUGIN"], remote=False, ns=globals())
source = OpenDataFile(env["MOBIUS_SOURCE"])
target = OpenDataFile(env["MOBIUS_TARGET"])
SetActiveSource(source)
exec(open(env["MOBIUS_MACRO"]).read(), dict(globals()))
with open(env["MOBIUS_DONE"], "w") as done:
    done.write("drawn\n")
