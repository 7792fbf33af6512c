"""The run marker: ``anatomesh-run.json`` in a run's output folder, written last.

A complete run says so (status "complete", with the pipeline, its variables, the files written, the seconds
and the key figures of its outputs); a failed run leaves status "failed" and the error beside whatever partial
outputs it made; a run in progress has no marker (the old one is removed when a run starts). ``anatomesh batch
--resume`` trusts only a complete marker whose pipeline and variables are the case's.
"""
import json
import os

from . import atomic

NAME = "anatomesh-run.json"


def path(folder):
    return os.path.join(folder, NAME)


def clear(folder):
    try:
        os.remove(path(folder))
    except FileNotFoundError:
        pass


def _write(folder, record):
    """Write the marker atomically; on an error (a full disk) no temporary file stays behind."""
    os.makedirs(folder, exist_ok=True)
    atomic.write_text(path(folder), json.dumps(record, indent=1, sort_keys=True))


def write_complete(folder, pipeline, variables, written, data, seconds, stages=None, warnings=None):
    """stages: seconds per filter (and for writing the outputs), as the run's timing table lists them. The
    allocator's settings the run had (GLIBC_TUNABLES, see the anatomesh command) go with its seconds; the
    run's warnings ("filter: text"), each once, with its figures."""
    unique = list(dict.fromkeys(warnings or []))
    _write(folder, {"status": "complete", "pipeline": os.path.abspath(pipeline), "variables": variables,
                    "files": written, "seconds": round(seconds, 3), "stage_seconds": stages or {},
                    "glibc_tunables": os.environ.get("GLIBC_TUNABLES", ""), "figures": figures(data),
                    "warnings": unique})


def write_failed(folder, pipeline, variables, message):
    """Best effort: the error that failed the run matters more than its marker (which a full disk or a
    read-only folder may refuse too)."""
    try:
        _write(folder, {"status": "failed", "pipeline": os.path.abspath(pipeline), "variables": variables,
                        "error": message})
    except OSError:
        pass


def read(folder, warn=None):
    """The folder's marker, or None when it has none or it is malformed (not JSON, not an object, a field
    of the wrong type: a marker hand-edited or written by something else). A malformed marker is then
    'not complete', and warn (if given) is called with a message naming it."""
    try:
        with open(path(folder), "rb") as f:
            record = json.loads(f.read().decode("utf-8"))
    except FileNotFoundError:
        return None
    except (OSError, ValueError) as e:
        problem = getattr(e, "strerror", None) or str(e)
    else:
        problem = malformed(record)
        if problem is None:
            return record
    if warn is not None:
        warn("%s: ignored, it is malformed (%s); the case counts as not complete" % (path(folder), problem))
    return None


def _number(x):
    return isinstance(x, (int, float)) and not isinstance(x, bool) and x == x and abs(x) != float("inf")


def malformed(record):
    """What is wrong with a marker's content, or None."""
    if not isinstance(record, dict):
        return "a JSON %s, not an object" % type(record).__name__
    checks = (("status", lambda v: v in ("complete", "failed"), "'complete' or 'failed'"),
              ("pipeline", lambda v: isinstance(v, str), "a path"),
              ("variables", lambda v: isinstance(v, dict) and all(isinstance(x, str) for x in v.values()),
               "an object of texts"),
              ("seconds", _number, "a number"),
              ("files", lambda v: isinstance(v, list) and all(isinstance(x, str) for x in v), "a list of paths"),
              ("stage_seconds", lambda v: isinstance(v, dict) and all(_number(x) for x in v.values()),
               "an object of numbers"),
              ("figures", lambda v: isinstance(v, dict) and all(isinstance(x, dict) for x in v.values()),
               "an object of objects"),
              ("warnings", lambda v: isinstance(v, list) and all(isinstance(x, str) for x in v), "a list of texts"),
              ("error", lambda v: isinstance(v, str), "a text"))
    for key, good, what in checks:
        if key in record and not good(record[key]):
            return "%r should be %s" % (key, what)
    for key in ("status", "pipeline", "variables"):
        if key not in record:
            return "no %r" % key
    if record["status"] == "complete" and "seconds" not in record:
        return "no 'seconds'"
    return None


def _figure(value):
    """A figure rounded to 4 decimals; a whole number (a count) as an integer."""
    x = round(float(value), 4)
    return int(x) if x.is_integer() and abs(x) < 2**53 else x


def figures(data):
    """Key figures of a run's outputs: each label map's volumes (cm3), the surface's Hausdorff distance, the
    mesh quality table's whole-mesh row, the smallest Dice, the ECG's QRS, QT and T polarities."""
    out = {}
    for file, obj in sorted(data.items()):
        if obj is None:
            continue
        name = os.path.basename(file)
        if obj.IsA("vtkImageData"):
            scalars = obj.GetPointData().GetScalars()
            if scalars is None or scalars.GetName() != "Labels":
                continue
            from vtkmodules.util.numpy_support import vtk_to_numpy
            import numpy as np
            values, counts = np.unique(vtk_to_numpy(scalars), return_counts=True)
            sx, sy, sz = obj.GetSpacing()
            out[name] = {"label %d cm3" % v: round(float(c) * sx * sy * sz / 1000.0, 3)
                         for v, c in zip(values.tolist(), counts.tolist()) if v != 0}
        elif obj.IsA("vtkPolyData"):
            h = obj.GetFieldData().GetArray("Hausdorff")
            if h is not None:
                out[name] = {"Hausdorff mm": round(h.GetValue(0), 4), "triangles": obj.GetNumberOfCells()}
        elif obj.IsA("vtkTable"):
            columns = {obj.GetColumnName(c): obj.GetColumn(c) for c in range(obj.GetNumberOfColumns())}
            if "MeanQuality" in columns and "Region" in columns:
                for r in range(obj.GetNumberOfRows()):
                    if columns["Region"].GetValue(r) == -1:
                        out[name] = {k: _figure(columns[c].GetValue(r)) for k, c in (
                            ("tetrahedra", "ne"), ("mean Q", "MeanQuality"), ("worst Q", "MaximumQuality"),
                            ("smallest dihedral", "MinimumDihedralAngle"))}
            elif "TPolarity" in columns and "Lead" in columns:
                ecg = {k: round(float(obj.GetFieldData().GetArray(a).GetValue(0)), 1)
                       for k, a in (("QRS ms", "QRSDuration_ms"), ("QT ms", "QTInterval_ms"))
                       if obj.GetFieldData().GetArray(a) is not None}
                for r in range(obj.GetNumberOfRows()):
                    lead = columns["Lead"].GetValue(r)
                    ecg["R %s mV" % lead] = round(float(columns["R_mV"].GetValue(r)), 3)
                    if "S_mV" in columns:
                        ecg["S %s mV" % lead] = round(float(columns["S_mV"].GetValue(r)), 3)
                    ecg["T %s" % lead] = columns["TPolarity"].GetValue(r)
                out[name] = ecg
            elif "Dice" in columns and "Label" in columns:
                dice = [columns["Dice"].GetValue(r) for r in range(obj.GetNumberOfRows())
                        if columns["Label"].GetValue(r) > 0]
                if dice:
                    out[name] = {"smallest Dice": round(min(dice), 4)}
    return out
