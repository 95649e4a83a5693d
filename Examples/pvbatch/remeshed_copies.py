"""Independently remeshed copies of a mesh, and where points lie on a surface (VTK).

A remeshed copy: the mesh Loop-subdivided once (every vertex moves, three in four are new),
then decimated by vtkQuadricDecimation to the vertex count asked for (each vertex placed
where it best keeps the shape, a little off the original surface). No vertex is one of the
original's, so a map cannot score by snapping to identical vertices. Each vertex's ground
truth is the closest point of the original surface (its triangle and barycentric
coordinates), and it carries through any pose of the original: the posed copy's vertex is
the same barycentric combination of the posed triangle's corners, plus its small offset from
the surface turned by the skinning's rotation there.
"""
import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk, numpy_to_vtkIdTypeArray, vtk_to_numpy
from vtkmodules.vtkCommonCore import reference, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData, vtkStaticCellLocator
from vtkmodules.vtkFiltersCore import vtkQuadricDecimation
from vtkmodules.vtkFiltersModeling import vtkLoopSubdivisionFilter

import skinning


def polydata(points, faces):
    mesh = vtkPolyData()
    vtk_points = vtkPoints()
    vtk_points.SetData(numpy_to_vtk(np.ascontiguousarray(points, dtype=float), deep=1))
    mesh.SetPoints(vtk_points)
    cells = np.hstack([np.full((len(faces), 1), 3), np.asarray(faces)]).astype(np.int64).ravel()
    polys = vtkCellArray()
    polys.SetCells(len(faces), numpy_to_vtkIdTypeArray(cells, deep=1))
    mesh.SetPolys(polys)
    return mesh


def arrays(mesh):
    points = vtk_to_numpy(mesh.GetPoints().GetData()).astype(float)
    cells = vtk_to_numpy(mesh.GetPolys().GetConnectivityArray()).astype(np.int64)
    return points, cells.reshape(-1, 3)


def barycentric(corners, x):
    """Barycentric coordinates of points x in triangles (n x 3 x 3), clipped into the triangle."""
    e1, e2, d = corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0], x - corners[:, 0]
    d11, d12, d22 = (e1 * e1).sum(1), (e1 * e2).sum(1), (e2 * e2).sum(1)
    d1, d2 = (d * e1).sum(1), (d * e2).sum(1)
    det = d11 * d22 - d12 * d12
    v, w = (d22 * d1 - d12 * d2) / det, (d11 * d2 - d12 * d1) / det
    weights = np.clip(np.stack([1 - v - w, v, w], axis=1), 0, None)
    return weights / weights.sum(axis=1, keepdims=True)


class Surface:
    """Closest-point queries on a triangle mesh."""

    def __init__(self, points, faces):
        self.points, self.faces = np.asarray(points, float), np.asarray(faces)
        self.mesh = polydata(self.points, self.faces)
        self.locator = vtkStaticCellLocator()
        self.locator.SetDataSet(self.mesh)
        self.locator.BuildLocator()

    def locate(self, queries):
        """The closest surface point of each query: (triangle indices, barycentric weights)."""
        triangles = np.empty(len(queries), dtype=np.int64)
        closest = np.empty((len(queries), 3))
        point, cell, sub, distance = [0.0, 0.0, 0.0], reference(0), reference(0), reference(0.0)
        for i, x in enumerate(np.asarray(queries, float)):
            self.locator.FindClosestPoint(x, point, cell, sub, distance)
            triangles[i], closest[i] = int(cell), point
        return triangles, barycentric(self.points[self.faces[triangles]], closest)


def interpolate(points, faces, triangles, weights):
    """Points at barycentric locations (triangle, weights) of a mesh."""
    return np.einsum("nk,nkj->nj", weights, np.asarray(points)[np.asarray(faces)[triangles]])


def check_closed_manifold(points, faces, what):
    """An error unless the mesh is one closed, edge-manifold, genus-0 surface whose triangles
    all have area."""
    pairs = np.sort(np.concatenate([faces[:, [0, 1]], faces[:, [1, 2]], faces[:, [2, 0]]]), axis=1)
    _, counts = np.unique(pairs, axis=0, return_counts=True)
    euler = len(points) - len(counts) + len(faces)
    corners = points[faces]
    areas = np.linalg.norm(np.cross(corners[:, 1] - corners[:, 0], corners[:, 2] - corners[:, 0]), axis=1)
    if (counts != 2).any() or euler != 2 or not (areas > 0).all():
        raise ValueError(f"{what}: not a closed genus-0 manifold (edges used other than twice: "
                         f"{(counts != 2).sum()}, Euler characteristic {euler}, "
                         f"degenerate triangles {(areas <= 0).sum()})")


class RemeshedCopy:
    """A remeshed copy of a mesh: `points`, `faces`, and each vertex's closest point on the
    original, as `triangles` and barycentric `weights`, and its `offsets` from it."""

    def __init__(self, points, faces, vertices):
        """About `vertices` vertices."""
        subdivide = vtkLoopSubdivisionFilter()
        subdivide.SetInputData(polydata(points, faces))
        subdivide.SetNumberOfSubdivisions(1)
        decimate = vtkQuadricDecimation()
        decimate.SetInputConnection(subdivide.GetOutputPort())
        decimate.VolumePreservationOn()
        fine_faces = 4 * len(faces)
        decimate.SetTargetReduction(1 - (2 * vertices - 4) / fine_faces)  # F = 2V - 4 (genus 0)
        decimate.Update()
        self.points, self.faces = arrays(decimate.GetOutput())
        check_closed_manifold(self.points, self.faces, "the decimated copy")
        self.triangles, self.weights = Surface(points, faces).locate(self.points)
        self.offsets = self.points - interpolate(points, faces, self.triangles, self.weights)

    def posed(self, original_faces, posed_points, rotations):
        """The copy's points on a posed original (its points, and the skinning's rotation at
        each vertex as unit quaternions)."""
        on_surface = interpolate(posed_points, original_faces, self.triangles, self.weights)
        corner = np.asarray(original_faces)[self.triangles, np.argmax(self.weights, axis=1)]
        return on_surface + skinning.rotate(rotations[corner], self.offsets)
