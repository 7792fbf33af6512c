"""One off-screen VTK view saved as a PNG: props, a title, an optional colour legend, a camera."""
import errno
import os

import vtkmodules.vtkRenderingFreeType  # noqa: F401  (text)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (the render window's implementation)
from vtkmodules.vtkCommonColor import vtkNamedColors
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkCommonCore import vtkPoints, vtkUnsignedCharArray
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
from vtkmodules.vtkRenderingAnnotation import vtkLegendBoxActor, vtkScalarBarActor
from .. import atomic
from vtkmodules.vtkRenderingCore import (vtkActor, vtkDataSetMapper, vtkRenderWindow, vtkRenderer, vtkTextActor,
                                         vtkWindowToImageFilter)

SIZE = (1100, 720)
SIDE = 0.22  # the legend's share of the width, beside the view (never over the data)


def actor(data, lookup=None, array=None, cells=True, edges=False):
    """An actor for a data set, coloured through lookup by the named cell (or point) array."""
    mapper = vtkDataSetMapper()
    mapper.SetInputData(data)
    if lookup is not None and array is not None:
        mapper.SetLookupTable(lookup)
        mapper.SetUseLookupTableScalarRange(True)
        if cells:
            mapper.SetScalarModeToUseCellFieldData()
        else:
            mapper.SetScalarModeToUsePointFieldData()
        mapper.SelectColorArray(array)
        mapper.ScalarVisibilityOn()
    else:
        mapper.ScalarVisibilityOff()
    a = vtkActor()
    a.SetMapper(mapper)
    if edges:
        a.GetProperty().EdgeVisibilityOn()
        a.GetProperty().SetEdgeColor(0.15, 0.15, 0.15)
        a.GetProperty().SetLineWidth(0.5)
    return a


def legend(lookup, title, labels=6):
    bar = vtkScalarBarActor()
    bar.SetLookupTable(lookup)
    bar.SetTitle(title)
    bar.SetNumberOfLabels(labels)
    bar.UnconstrainedFontSizeOn()
    bar.SetLabelFormat("%-#.3g")
    bar.SetPosition(0.1, 0.06)
    bar.SetWidth(0.5)
    bar.SetHeight(0.82)
    for prop in (bar.GetTitleTextProperty(), bar.GetLabelTextProperty(), bar.GetAnnotationTextProperty()):
        prop.SetColor(0.1, 0.1, 0.1)
        prop.ShadowOff()
        prop.ItalicOff()
        prop.SetFontSize(16)
        prop.BoldOff()
    return bar


def swatches(entries):
    """A legend of (name, (r, g, b)) entries: one coloured square each."""
    box = vtkLegendBoxActor()
    box.SetNumberOfEntries(len(entries))
    points = vtkPoints()
    for xy in ((0, 0), (1, 0), (1, 1), (0, 1)):
        points.InsertNextPoint(xy[0], xy[1], 0)
    for i, (name, rgb) in enumerate(entries):
        # The square's own colour (cell scalars); the entry colour is the text's, dark to be read.
        square = vtkPolyData()
        cells = vtkCellArray()
        cells.InsertNextCell(4, [0, 1, 2, 3])
        square.SetPoints(points)
        square.SetPolys(cells)
        colour = vtkUnsignedCharArray()
        colour.SetNumberOfComponents(3)
        colour.InsertNextTuple3(*(int(round(255 * c)) for c in rgb))
        square.GetCellData().SetScalars(colour)
        box.SetEntry(i, square, name, (0.1, 0.1, 0.1))
    box.BorderOff()
    box.GetEntryTextProperty().SetColor(0.1, 0.1, 0.1)
    box.GetEntryTextProperty().ShadowOff()
    box.GetPositionCoordinate().SetCoordinateSystemToNormalizedViewport()
    box.GetPositionCoordinate().SetValue(0.02, 0.94 - min(0.88, 0.045 * len(entries)))
    box.GetPosition2Coordinate().SetCoordinateSystemToNormalizedViewport()
    box.GetPosition2Coordinate().SetValue(0.96, min(0.88, 0.045 * len(entries)))
    return box


def save_png(path, props, title, view=(0.0, -1.0, 0.0), up=(0.0, 0.0, 1.0), zoom=1.0):
    """Render props looking along view (from the -view side), up as given; the PNG is written under a
    temporary name and renamed, so a failed write leaves no partial picture."""
    white = vtkNamedColors().GetColor3d("White")
    renderer, side = vtkRenderer(), vtkRenderer()
    renderer.SetBackground(white)
    side.SetBackground(white)
    renderer.SetViewport(0.0, 0.0, 1.0 - SIDE, 1.0)
    side.SetViewport(1.0 - SIDE, 0.0, 1.0, 1.0)
    for p in props:
        if p.IsA("vtkScalarBarActor") or p.IsA("vtkLegendBoxActor"):
            side.AddViewProp(p)
        else:
            renderer.AddActor(p)
    text = vtkTextActor()
    text.SetInput(title)
    text.GetTextProperty().SetFontSize(20)
    text.GetTextProperty().SetColor(0.1, 0.1, 0.1)
    text.SetDisplayPosition(12, SIZE[1] - 34)
    renderer.AddViewProp(text)
    camera = renderer.GetActiveCamera()
    camera.SetFocalPoint(0, 0, 0)
    camera.SetPosition(-view[0], -view[1], -view[2])
    camera.SetViewUp(*up)
    renderer.ResetCamera()
    camera.Zoom(zoom)
    window = vtkRenderWindow()
    window.SetOffScreenRendering(1)
    window.SetSize(*SIZE)
    window.AddRenderer(renderer)
    window.AddRenderer(side)
    window.Render()
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.ReadFrontBufferOff()
    grab.Update()
    writer = vtkPNGWriter()
    writer.SetInputData(grab.GetOutput())
    window.Finalize()
    with atomic.replacing(path) as tmp:
        writer.SetFileName(tmp)
        writer.Write()
        if writer.GetErrorCode() != 0 or not os.path.isfile(tmp) or os.path.getsize(tmp) == 0:
            raise OSError(errno.EIO, "could not write the picture (a full disk?)", path)
