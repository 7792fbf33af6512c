"""What a run wrote, found by content: the tetrahedral mesh, the remeshed surface, the quality,
Dice and ECG tables, and the heart's and the torso's time series."""
import csv
import glob
import os
import re
import xml.etree.ElementTree as ET

from vtkmodules.vtkIOXML import vtkXMLPolyDataReader, vtkXMLUnstructuredGridReader

from .. import marker


class ReadError(Exception):
    """An output of the run that cannot be read (truncated, corrupt)."""


# The units the CSV tables' headers carry ("Volume_mm3", "Time_ms", "I_mV"; anatomesh.writers).
UNITS = ("mm3", "mm2", "deg", "ms", "mV")


def base(header):
    """A CSV column's name without its unit: "Volume_mm3" -> "Volume"."""
    for unit in UNITS:
        if header.endswith("_" + unit):
            return header[:-len(unit) - 1]
    return header


def read_xml(path):
    """A .vtp or .vtu file's data; ReadError (with VTK's first message) when it cannot be read."""
    reader = vtkXMLPolyDataReader() if path.endswith(".vtp") else vtkXMLUnstructuredGridReader()
    messages = []

    def keep(caller, event, data=None):
        lines = str(data or "").strip().splitlines()
        messages.append(re.sub(r"^\w+ \(0x[0-9a-f]+\): ", "", lines[-1]) if lines else event)
    keep.CallDataType = "string0"  # the message comes as the call data
    for obj in (reader, reader.GetExecutive()):
        obj.AddObserver("ErrorEvent", keep)
    reader.SetFileName(path)
    reader.Update()
    if messages:
        raise ReadError("%s cannot be read: %s" % (path, messages[0]))
    return reader.GetOutput()


def series(pvd):
    """A .pvd's frames: (time, absolute path), in time order."""
    root = ET.parse(pvd).getroot()
    folder = os.path.dirname(pvd)
    frames = []
    for d in root.iter("DataSet"):
        if d.get("file"):
            try:
                t = float(d.get("timestep", "0"))
            except ValueError:
                raise ValueError("timestep %r is not a number" % d.get("timestep")) from None
            frames.append((t, os.path.join(folder, d.get("file"))))
    return sorted(frames)


def table(path):
    """A CSV as its header and rows of strings."""
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    return (rows[0], rows[1:]) if rows else ([], [])


def files_of(folder):
    """The files the run's marker lists (those still there), or every file of the folder."""
    record = marker.read(folder)
    listed = record.get("files") if record else None
    if listed:
        # Listed where the run wrote them; a folder moved since holds them at the same relative place.
        written_to = os.path.abspath(record.get("variables", {}).get("output", folder))
        here = os.path.abspath(folder)
        moved = [os.path.join(here, os.path.relpath(p, written_to)) if p.startswith(written_to + os.sep) else p
                 for p in listed]
        return record, [p for p in moved if os.path.isfile(p)]
    return record, sorted(p for p in glob.glob(os.path.join(folder, "*")) if os.path.isfile(p))


def find(folder):
    """A dict of what was found: 'record' (the marker, or None), the paths under 'mesh',
    'surface', 'quality', 'dice', 'ecg', 'ecg_features', 'heart', 'body' (each absent when the run made none),
    the mesh's and the surface's data under 'mesh_data' and 'surface_data', and under
    'unreadable' what could not be read and why."""
    record, files = files_of(folder)
    found = {"record": record, "unreadable": []}
    framed = set()
    for pvd in (p for p in files if p.endswith(".pvd")):
        try:
            frames = series(pvd)
        except (ET.ParseError, OSError, ValueError) as e:
            found["unreadable"].append("%s cannot be read: %s" % (pvd, e))
            continue
        framed.update(f for _, f in frames)
        if frames and frames[-1][1].endswith(".vtu"):
            found.setdefault("heart", pvd)
        elif frames and frames[-1][1].endswith(".vtp"):
            found.setdefault("body", pvd)
    best = -1
    for p in files:
        if p in framed:
            continue
        try:
            if p.endswith(".vtu"):
                data = read_xml(p)
                if data.GetCellData().GetArray("Region") is not None and data.GetNumberOfCells() > best:
                    best, found["mesh"], found["mesh_data"] = data.GetNumberOfCells(), p, data
            elif p.endswith(".vtp") and "surface" not in found:
                data = read_xml(p)
                if data.GetFieldData().GetArray("Hausdorff") is not None:
                    found["surface"], found["surface_data"] = p, data
            elif p.endswith(".csv"):
                head, _ = table(p)
                if "MeanQuality" in head and "Region" in head:
                    found.setdefault("quality", p)
                elif "Dice" in head and "Label" in head:
                    found.setdefault("dice", p)
                elif [base(h) for h in head[:2]] == ["Time", "I"]:
                    found.setdefault("ecg", p)
                elif "TPolarity" in head and "Lead" in head:
                    found.setdefault("ecg_features", p)
        except (ReadError, UnicodeDecodeError, csv.Error) as e:
            found["unreadable"].append(str(e) if isinstance(e, ReadError) else "%s cannot be read: %s" % (p, e))
    return found


def label_names(data):
    """The names of the labels (index = label) in a data set's field data "LabelNames": a string
    array, or as written to files for other readers, its UTF-8 text one name a line (UInt8)."""
    array = data.GetFieldData().GetAbstractArray("LabelNames") if data is not None else None
    if array is None:
        return []
    if array.IsA("vtkStringArray"):
        return [array.GetValue(i) for i in range(array.GetNumberOfValues())]
    return bytes(int(array.GetValue(i)) for i in range(array.GetNumberOfValues())).decode("utf-8", "replace").split("\n")
