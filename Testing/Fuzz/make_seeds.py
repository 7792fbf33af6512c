"""Seed corpora for the fuzz targets, made from Anatomesh's own outputs.

    python3 make_seeds.py OUTDIR

writes OUTDIR/<Target>/ for NiftiCheck, MetaImageCheck, NrrdCheck, MeditFormat and PipelineXml:
a small phantom written by ImageWriter in every image form (each input prefixed with the byte
that picks its form in the target), a small tetrahedral mesh and its solution by MeditWriter,
and the example pipelines. Needs the anatomesh Python package.
"""
import glob
import os
import shutil
import struct
import sys
import tempfile

import anatomesh
from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkIntArray, vtkPoints
from vtkmodules.vtkCommonDataModel import VTK_TETRA, vtkUnstructuredGrid


def read(path):
    with open(path, "rb") as f:
        return f.read()


def save(folder, name, data):
    os.makedirs(folder, exist_ok=True)
    with open(os.path.join(folder, name), "wb") as f:
        f.write(data)


def image_seeds(out, work):
    phantom = anatomesh.amThoraxPhantomSource()
    phantom.SetSpacing(24, 24, 24)
    for port, kind in ((0, "ct"), (1, "labels")):
        for ext, compress in ((".nii", False), (".nii.gz", True), (".mha", False), (".mha", True),
                              (".mhd", False), (".nrrd", False), (".nrrd", True), (".nhdr", False)):
            path = os.path.join(work, "%s%s%s" % (kind, "_z" if compress else "", ext))
            writer = anatomesh.amImageWriter()
            writer.SetInputConnection(phantom.GetOutputPort(port))
            writer.SetFileName(path)
            writer.SetUseCompression(compress)
            writer.Write()
            name = os.path.basename(path)
            if ext == ".nii":
                data = read(path)
                save(os.path.join(out, "NiftiCheck"), name, b"\0" + data)
                save(os.path.join(out, "NiftiCheck"), name + ".gzip", b"\2" + data)
                # The same image as a .hdr/.img pair: magic "ni1", voxels from offset 0 of the .img.
                offset = int(struct.unpack("<f", data[108:112])[0])
                header = data[:108] + struct.pack("<f", 0.0) + data[112:344] + b"ni1\0"
                save(os.path.join(out, "NiftiCheck"), name + ".pair", b"\3" + header + data[offset:])
            elif ext == ".nii.gz":
                save(os.path.join(out, "NiftiCheck"), name, b"\1" + read(path))
            elif ext == ".mha":
                save(os.path.join(out, "MetaImageCheck"), name, b"\0" + read(path))
            elif ext == ".nrrd":
                save(os.path.join(out, "NrrdCheck"), name, b"\0" + read(path))
            else:
                # A detached header: the target writes the bytes after the first NUL to image.raw.
                target = "MetaImageCheck" if ext == ".mhd" else "NrrdCheck"
                text = read(path).decode()
                key = "ElementDataFile = " if ext == ".mhd" else "data file: "
                lines = [l if not l.startswith(key) else key + "image.raw" for l in text.splitlines()]
                data_files = [l[len(key):] for l in text.splitlines() if l.startswith(key)]
                raw = read(os.path.join(work, data_files[0])) if data_files else b""
                save(os.path.join(out, target), name, b"\1" + ("\n".join(lines) + "\n").encode() + b"\0" + raw)


def medit_seeds(out, work):
    points = vtkPoints()
    for p in ((0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1), (1, 1, 1)):
        points.InsertNextPoint(p)
    grid = vtkUnstructuredGrid()
    grid.SetPoints(points)
    region = vtkIntArray()
    region.SetName("Region")
    for cell, label in (((0, 1, 2, 3), 1), ((1, 2, 3, 4), 2)):
        grid.InsertNextCell(VTK_TETRA, 4, cell)
        region.InsertNextValue(label)
    grid.GetCellData().AddArray(region)
    for name, components in (("u", 1), ("m", 6)):
        values = vtkDoubleArray()
        values.SetName(name)
        values.SetNumberOfComponents(components)
        for i in range(5 * components):
            values.InsertNextValue(0.25 * i)
        grid.GetPointData().AddArray(values)
    for name in ("u", "m"):
        writer = anatomesh.amMeditWriter()
        writer.SetInputData(grid)
        writer.SetFileName(os.path.join(work, "mesh_%s.mesh" % name))
        writer.SetSolutionArrayName(name)
        writer.Write()
        for ext in (".mesh", ".sol"):
            path = os.path.join(work, "mesh_%s%s" % (name, ext))
            save(os.path.join(out, "MeditFormat"), os.path.basename(path), read(path))


def pipeline_seeds(out, source):
    for path in sorted(glob.glob(os.path.join(source, "Examples", "Pipelines", "*.xml"))):
        save(os.path.join(out, "PipelineXml"), os.path.basename(path), read(path))


def main():
    out = sys.argv[1]
    source = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
    work = tempfile.mkdtemp(prefix="anatomesh-seeds-")
    try:
        image_seeds(out, work)
        medit_seeds(out, work)
        pipeline_seeds(out, source)
    finally:
        shutil.rmtree(work)
    for target in sorted(os.listdir(out)):
        print("%s: %d seeds" % (target, len(os.listdir(os.path.join(out, target)))))


if __name__ == "__main__":
    main()
