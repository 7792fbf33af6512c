"""The report's 3-D pictures: the mesh cut through by region, the surface by its distance to the
input, the activation map and the body-surface potential. Each takes the data read from the run
and writes one PNG (render.save_png). The views look from the front (-y, where the phantom's
chest electrodes are) with z up, and cut away the front half where the inside matters."""
import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkLookupTable, vtkVariant
from vtkmodules.vtkCommonDataModel import vtkPlane
from vtkmodules.vtkFiltersExtraction import vtkExtractGeometry
from vtkmodules.vtkFiltersGeometry import vtkDataSetSurfaceFilter

from . import render

# Distinct colours for regions (a qualitative palette), repeated beyond its length.
PALETTE = [(0.90, 0.62, 0.45), (0.99, 0.85, 0.55), (0.96, 0.96, 0.86), (0.78, 0.84, 0.95), (0.85, 0.25, 0.20),
           (0.60, 0.10, 0.10), (0.95, 0.55, 0.60), (0.30, 0.45, 0.85), (0.55, 0.75, 0.95), (0.40, 0.70, 0.35),
           (0.65, 0.45, 0.80), (0.95, 0.75, 0.20), (0.25, 0.70, 0.70), (0.70, 0.70, 0.70), (0.45, 0.30, 0.60),
           (0.80, 0.50, 0.15), (0.20, 0.50, 0.30), (0.90, 0.40, 0.70), (0.35, 0.35, 0.35), (0.60, 0.80, 0.40)]
VIEW, UP = (0.0, 1.0, 0.0), (0.0, 0.0, 1.0)
LEGEND_LIMIT = 24  # more regions than this: colours without a legend


def _back_half(data):
    """The cells behind the plane through the centre facing the camera (boundary cells kept, so the
    cut shows whole cells)."""
    b = data.GetBounds()
    plane = vtkPlane()
    plane.SetOrigin(0.5 * (b[0] + b[1]), 0.5 * (b[2] + b[3]), 0.5 * (b[4] + b[5]))
    plane.SetNormal(-VIEW[0], -VIEW[1], -VIEW[2])
    cut = vtkExtractGeometry()
    cut.SetInputData(data)
    cut.SetImplicitFunction(plane)
    cut.ExtractInsideOn()
    cut.ExtractBoundaryCellsOn()
    cut.Update()
    return cut.GetOutput()


def _surface_of(data):
    f = vtkDataSetSurfaceFilter()
    f.SetInputData(data)
    f.Update()
    return f.GetOutput()


def region_lookup(values, names=None):
    """A categorical lookup table: one colour per region value, annotated with its name."""
    lut = vtkLookupTable()
    lut.IndexedLookupOn()
    lut.SetNumberOfTableValues(len(values))
    for i, v in enumerate(values):
        lut.SetTableValue(i, *PALETTE[i % len(PALETTE)], 1.0)
        name = names[v] if names and 0 <= v < len(names) else ""
        lut.SetAnnotation(vtkVariant(int(v)), ("%d %s" % (v, name)).strip())
    return lut


def _ramp(lo, hi, hue=(0.667, 0.0), saturation=(1.0, 1.0), value=(1.0, 1.0)):
    lut = vtkLookupTable()
    lut.SetRange(lo, hi if hi > lo else lo + 1e-9)
    lut.SetHueRange(*hue)
    lut.SetSaturationRange(*saturation)
    lut.SetValueRange(*value)
    lut.Build()
    return lut


def mesh_by_region(mesh, path, names=None, array="Region"):
    """The tetrahedral mesh's back half, its cut face showing the regions and their elements."""
    values = np.unique(vtk_to_numpy(mesh.GetCellData().GetArray(array))).astype(int).tolist()
    lut = region_lookup(values, names)
    half = _surface_of(_back_half(mesh))
    props = [render.actor(half, lut, array, cells=True, edges=half.GetNumberOfCells() < 400000)]
    if len(values) <= LEGEND_LIMIT:
        props.append(render.swatches([(lut.GetAnnotation(i), PALETTE[i % len(PALETTE)]) for i in range(len(values))]))
    render.save_png(path, props, "Mesh: %d tetrahedra, %d regions (cut through the middle)" % (
        mesh.GetNumberOfCells(), len(values)), VIEW, UP, zoom=1.25)


def surface_by_distance(surface, path, tolerance=None):
    """The remeshed surface's back half, each triangle coloured by its largest distance to the input."""
    d = vtk_to_numpy(surface.GetCellData().GetArray("HausdorffDistance"))
    top = max(float(d.max()) if d.size else 0.0, tolerance or 0.0)
    lut = _ramp(0.0, top)
    half = _back_half(surface)
    title = "Remeshed surface: distance to its input, largest %.3f mm" % (float(d.max()) if d.size else 0.0)
    if tolerance:
        title += " (tolerance %g mm)" % tolerance
    edges = half.GetNumberOfCells() < 40000  # denser edges would hide the colours
    render.save_png(path, [render.actor(half, lut, "HausdorffDistance", cells=True, edges=edges),
                           render.legend(lut, "mm")], title, VIEW, UP)


def activation_map(heart, path, array="ActivationTime"):
    """The heart's surface coloured by activation (or repolarisation) time (red first, blue last)."""
    t = vtk_to_numpy(heart.GetPointData().GetArray(array))
    active = t[t >= 0] if t.size else t
    lo, hi = (float(active.min()), float(active.max())) if active.size else (0.0, 1.0)
    lut = _ramp(lo, hi, hue=(0.0, 0.667))
    lut.SetBelowRangeColor(0.6, 0.6, 0.6, 1.0)  # never activated (-1)
    lut.UseBelowRangeColorOn()
    surface = _surface_of(heart)
    what = "Activation" if array == "ActivationTime" else "Repolarisation"
    render.save_png(path, [render.actor(surface, lut, array, cells=False), render.legend(lut, "ms")],
                    "%s time: %.0f to %.0f ms, %d of %d nodes activated" % (
                        what, lo, hi, active.size, t.size), VIEW, UP)


def body_surface_potential(body, path, time):
    """The torso's surface potential at one time, on a symmetric blue-white-red scale."""
    phi = vtk_to_numpy(body.GetPointData().GetArray("Potential"))
    top = float(np.abs(phi).max()) if phi.size else 1.0
    lut = vtkLookupTable()
    lut.SetNumberOfTableValues(256)
    lut.SetRange(-top, top if top > 0 else 1.0)
    for i in range(256):
        s = i / 255.0 * 2.0 - 1.0  # -1 blue, 0 white, 1 red
        r, g, b = (1.0, 1.0 - s, 1.0 - s) if s > 0 else (1.0 + s, 1.0 + s, 1.0)
        lut.SetTableValue(i, r, g, b, 1.0)
    render.save_png(path, [render.actor(body, lut, "Potential", cells=False), render.legend(lut, "mV")],
                    "Body-surface potential at %g ms (range %.3g to %.3g mV)" % (
                        time, float(phi.min()) if phi.size else 0, float(phi.max()) if phi.size else 0), VIEW, UP)
