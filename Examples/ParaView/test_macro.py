"""Runs the macro as the GUI would: two meshes loaded, the source selected."""
import sys

from paraview.simple import GetActiveSource, LoadPlugin, OpenDataFile, SetActiveSource
from paraview import servermanager

plugin, mesh, macro = sys.argv[1:4]
LoadPlugin(plugin, remote=False, ns=globals())
source = OpenDataFile(mesh)
target = OpenDataFile(mesh)
SetActiveSource(source)
exec(open(macro).read(), dict(globals()))
correspondence = GetActiveSource()
assert correspondence.GetXMLName() == "RefineCorrespondence", correspondence.GetXMLName()
result = servermanager.Fetch(correspondence)
assert result.GetPointData().GetArray("MappedPoints") is not None
assert result.GetNumberOfPoints() == servermanager.Fetch(source).GetNumberOfPoints()
print("the macro built the pipeline; error",
      servermanager.Fetch(correspondence.Source).GetFieldData().GetArray("RegistrationError").GetValue(0))
