"""report.html: the run's pictures and tables on one page, written last and atomically."""
import html
import os

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy

from .. import atomic
from . import charts, collect, scenes, tables
from .display import x_display

STYLE = """body{font-family:sans-serif;max-width:1000px;margin:2em auto;color:#222}
table{border-collapse:collapse;margin:1em 0}td,th{border:1px solid #ccc;padding:3px 8px;text-align:right}
th{background:#eef}caption{text-align:left;font-weight:bold;padding:4px 0}img{max-width:100%;border:1px solid #ddd}
figure{margin:1.5em 0}figcaption{color:#555}.note{color:#a33}"""


def _ecg(path):
    head, rows = collect.table(path)
    values = np.array([[float(c) for c in r] for r in rows]) if rows else np.zeros((0, len(head)))
    return values[:, 0], {collect.base(name): values[:, i] for i, name in enumerate(head) if i > 0}


def _last_frame(found, key, notes):
    """The last frame of a time series, or None (with a note when it cannot be read)."""
    if key not in found:
        return None
    frames = collect.series(found[key])
    try:
        return collect.read_xml(frames[-1][1]) if frames else None
    except collect.ReadError as e:
        notes.append(str(e))
        return None


def _default_time(heart, ecg):
    """The body-surface picture's time when none is given: half the heart activated (the median
    activation time of its nodes), else when the leads are largest together."""
    if heart is not None:
        times = heart.GetPointData().GetArray("ActivationTime")
        if times is not None:
            t = vtk_to_numpy(times)
            if (t >= 0).any():
                return float(np.median(t[t >= 0]))
    if ecg is not None and ecg[1] and ecg[0].size:
        return float(ecg[0][int(np.argmax(sum(np.abs(v) for v in ecg[1].values())))])
    return None


def _tolerance(found):
    """The run's remeshing tolerance (its "tolerance" variable, mm), or None."""
    text = (found.get("record") or {}).get("variables", {}).get("tolerance")
    try:
        return float(text) if text else None
    except ValueError:
        return None


def _pictures(found, heart, names, folder, pictures, notes, time):
    """The 3-D views; each failure is a note, never the end of the report."""
    mesh, surface = found.get("mesh_data"), found.get("surface_data")
    jobs = []
    if mesh is not None:
        jobs.append(("mesh.png", "The mesh cut through the middle, coloured by region: the elements of every region "
                     "meet on their shared faces.", lambda p: scenes.mesh_by_region(mesh, p, names)))
    if surface is not None:
        if surface.GetCellData().GetArray("HausdorffDistance") is not None:
            jobs.append(("surface.png", "The remeshed surface (back half) coloured by each triangle's largest distance "
                         "to the smoothed surface it approximates.",
                         lambda p: scenes.surface_by_distance(surface, p, _tolerance(found))))
        else:
            notes.append("%s has no per-triangle distances (made before they were recorded)." % found["surface"])
    if heart is not None:
        if heart.GetPointData().GetArray("ActivationTime") is not None:
            jobs.append(("activation.png", "Activation time on the heart's surface (grey: never activated).",
                         lambda p: scenes.activation_map(heart, p)))
        if heart.GetPointData().GetArray("RepolarisationTime") is not None:
            jobs.append(("repolarisation.png", "Repolarisation time on the heart's surface: where it is earliest the "
                         "T wave points.", lambda p: scenes.activation_map(heart, p, "RepolarisationTime")))
    frames = collect.series(found["body"]) if "body" in found else []
    if frames:
        at, frame = min(frames, key=lambda f: abs(f[0] - time)) if time is not None else frames[len(frames) // 2]
        try:
            body = collect.read_xml(frame)
            jobs.append(("body_surface.png", "The body-surface potential at %g ms." % at,
                         lambda p, body=body, at=at: scenes.body_surface_potential(body, p, at)))
        except collect.ReadError as e:
            notes.append(str(e))
    if not jobs:
        return
    with x_display() as why:
        if why is not None:
            notes.append("3-D pictures not drawn: %s." % why)
            return
        for name, caption, draw in jobs:
            path = os.path.join(folder, name)
            try:
                draw(path)
                pictures.append((name, caption))
            except Exception as e:  # noqa: BLE001 (a picture that fails is reported on the page)
                notes.append("%s not drawn: %s" % (name, e))


def write_report(folder, time=None):
    """Writes folder/report.html and its pictures in folder/report/; returns (path, notes), the
    notes saying what could not be drawn and why."""
    found = collect.find(folder)
    pictures_dir = os.path.join(folder, "report")
    os.makedirs(pictures_dir, exist_ok=True)
    pictures, notes, sections = [], list(found["unreadable"]), []
    if not any(k in found for k in ("mesh", "surface", "quality", "dice", "ecg", "heart", "body")):
        notes.append("%s holds no mesh, surface, quality, Dice or ECG table, nor time series to report on." % folder)
    ecg = None
    if "ecg" in found:
        try:
            ecg = _ecg(found["ecg"])
        except ValueError as e:  # a table that is not numbers
            notes.append("%s cannot be read: %s" % (found["ecg"], e))
    heart = _last_frame(found, "heart", notes)
    if time is None:
        time = _default_time(heart, ecg)
    mesh = found.get("mesh_data")
    names = collect.label_names(mesh)
    _pictures(found, heart, names, pictures_dir, pictures, notes, time)
    if mesh is not None and mesh.GetCellData().GetArray("Quality") is not None:
        charts.quality_histogram(vtk_to_numpy(mesh.GetCellData().GetArray("Quality")),
                                 os.path.join(pictures_dir, "quality.png"))
        pictures.append(("quality.png", "Element quality: the number of tetrahedra per quality Q (log scales); the "
                         "dashed line is the bar no element may pass."))
    if ecg is not None:
        charts.ecg_leads(ecg[0], ecg[1], os.path.join(pictures_dir, "ecg.png"))
        pictures.append(("ecg.png", "The 12 leads on standard ECG paper (25 mm/s, 10 mm/mV; small squares 40 ms "
                         "and 0.1 mV), the simulated beat repeated at 75 per minute."))
    for key, make in (("quality", tables.quality), ("dice", tables.dice), ("ecg_features", tables.ecg_features)):
        if key in found:
            try:
                sections.append(make(*collect.table(found[key]), names=names))
            except (ValueError, IndexError) as e:  # a table whose rows are not what its header says
                notes.append("%s cannot be read: %s" % (found[key], e))
    if mesh is not None and mesh.GetFieldData().GetArray("RegionVolumes") is not None:
        sections.append(tables.region_volumes(mesh.GetFieldData().GetArray("RegionVolumes"), names))
    if "surface_data" in found:
        array = found["surface_data"].GetFieldData().GetArray("InterfaceHausdorff")
        if array is not None:
            sections.append(tables.interfaces(array, _tolerance(found), names))
    return _write(folder, found.get("record"), pictures, sections, notes), notes


def _write(folder, record, pictures, sections, notes):
    record = record or {}
    title = "Anatomesh run: %s" % os.path.basename(record.get("pipeline", folder))
    out = ["<!DOCTYPE html>", "<html><head><meta charset='utf-8'><title>%s</title>" % html.escape(title),
           "<style>%s</style></head><body>" % STYLE, "<h1>%s</h1>" % html.escape(title)]
    out.append("<p>Status <b>%s</b>, %s s; pipeline %s; output %s.</p>" % (
        html.escape(str(record.get("status", "unknown"))), html.escape(str(record.get("seconds", "?"))),
        html.escape(str(record.get("pipeline", "?"))), html.escape(os.path.abspath(folder))))
    out.extend("<p class='note'>%s</p>" % html.escape(n) for n in notes)
    warnings = record.get("warnings") or []
    if warnings:  # what the run itself said it missed (element bars, Hausdorff bound, volumes, wall holes)
        out.append("<h2>Warnings of the run</h2><ul>")
        out.extend("<li class='note'>%s</li>" % html.escape(str(w)) for w in warnings)
        out.append("</ul>")
    for name, caption in pictures:
        out.append("<figure><img src='report/%s' alt='%s'><figcaption>%s</figcaption></figure>" % (
            html.escape(name), html.escape(caption), html.escape(caption)))
    out.extend(sections)
    out.append(tables.variables(record))
    out.append("</body></html>")
    path = os.path.join(folder, "report.html")
    atomic.write_text(path, "\n".join(out) + "\n")
    return path
