"""ParaView macro: the whole Moebius registration pipeline on two loaded meshes.

Add it with Macros -> Import new macro... (the plugin must be loaded: Tools -> Manage
Plugins, or PV_PLUGIN_PATH). Open two meshes, select the one to map from (the source),
and click the macro: it builds
    Spherical Conformal Map -> Mobius Center   (for each mesh)
    SO3 Register (Source, Target) -> Dense Correspondence (Source, Target)
and shows the source mesh placed on the target surface. The target is
the other mesh without an input in the pipeline; if the selected mesh is not one of the two,
the first loaded mesh is the source.
"""
from paraview.simple import (
    ColorBy, GetActiveSource, GetActiveViewOrCreate, GetSources, Hide, Render, SetActiveSource, Show)


def loaded_meshes():
    """Pipeline objects with no input (readers, sources), in the order they were made."""
    roots = [proxy for key, proxy in sorted(GetSources().items(), key=lambda item: int(item[0][1]))
             if "Input" not in proxy.ListProperties()]
    if len(roots) != 2:
        raise RuntimeError("Mobius registration macro: load exactly two meshes first "
                           f"(found {len(roots)} readers or sources)")
    active = GetActiveSource()
    if active is roots[1]:
        roots.reverse()
    return roots


def build_pipeline():
    source, target = loaded_meshes()
    centered = []
    for mesh in (source, target):
        conformal = SphericalConformalMap(Input=mesh)  # noqa: F821 (from the plugin)
        centered.append(MobiusCenter(Input=conformal))  # noqa: F821
    aligned = SO3Register(Source=centered[0], Target=centered[1])  # noqa: F821
    # The Möbius map refined spectrally (from every candidate rotation): the accurate map.
    correspondence = RefineCorrespondence(Source=aligned, Target=centered[1])  # noqa: F821

    # In the active view: the source's connectivity placed on the target surface, colored by
    # the target triangle each source vertex landed in.
    view = GetActiveViewOrCreate("RenderView")
    for mesh in (source, target):
        Hide(mesh, view)
    display = Show(correspondence, view)
    ColorBy(display, ("POINTS", "TargetCellId"))
    view.ResetCamera()
    Render(view)
    SetActiveSource(correspondence)
    return correspondence


build_pipeline()
