"""The ``anatomesh`` command.

    anatomesh run PIPELINE.xml [--set NAME=VALUE ...] [--output DIR] [--quiet] [--report [--report-time MS]]
    anatomesh batch PIPELINE.xml MANIFEST.csv [--jobs N] [--resume] [--output DIR] [--set NAME=VALUE ...] [--report]
    anatomesh report DIR [--time MS]   report.html with pictures for a run's output folder
    anatomesh filters            list the filter catalogue (from the plugin's server-manager XML)
    anatomesh --version

Exit status: 0 on success, 1 when the pipeline or its data is wrong (the message names the file
and, for pipeline files, the line), 2 for a command-line mistake. A run writes ``anatomesh-run.json``
in its output folder last: "complete" with its key figures, or "failed" with the error.
"""
import argparse
import math
import os
import re
import sys
import time

from . import adult_volumes, marker
from .options import variables_of


class _Progress:
    """One line per filter on a terminal (\\r-updated), every 25 % otherwise. A filter that runs
    again (once per frame of a time series) is not shown again in a log."""

    def __init__(self, stream):
        self.stream, self.tty = stream, stream.isatty()
        self.current, self.shown, self.start = None, -1, {}
        self.best = {}

    def __call__(self, name, fraction):
        if name is None:  # the end: each filter's time is in the summary's timing table
            if self.tty and self.current:
                self.stream.write("\n")
            self.stream.flush()
            return
        if name != self.current:
            if self.tty and self.current:
                self.stream.write("\n")
            self.current, self.shown = name, -1
        self.start.setdefault(name, time.time())
        step = int(fraction * 100) if self.tty else int(fraction * 4) * 25
        if step == self.shown or (not self.tty and step <= self.best.get(name, -1)):
            return
        self.shown = step
        self.best[name] = max(step, self.best.get(name, -1))
        elapsed = time.time() - self.start[name]
        text = "  %-24s %3d%%  %6.1f s" % (name, step, elapsed)
        if self.tty:
            self.stream.write("\r" + text)
        else:
            self.stream.write(text + "\n")
        self.stream.flush()


CLASS_NAMES = ["air", "lung", "fat", "soft tissue", "contrast blood", "bone"]


# A healthy adult's ECG (the ranges a cardiologist reads against): a QRS above 110 ms is an
# intraventricular conduction delay (Surawicz et al., AHA/ACCF/HRS recommendations for the
# standardization and interpretation of the ECG, part III, JACC 53:976-981, 2009); one below 70 ms
# is rare and narrow for an adult heart.
ECG_NORMAL = {"QRS": (70, 110), "QT": (320, 460)}


def _ecg_reading(table):
    """The ECG's reading from LeadFieldECG's Features table: QRS and QT beside their normal ranges,
    the R-wave progression V1..V6 and the T waves' polarities."""
    fd = table.GetFieldData()
    if fd.GetArray("QRSDuration_ms") is None or table.GetColumnByName("TPolarity") is None:
        return []
    def ranged(name, value):
        low, high = ECG_NORMAL[name]
        return "%s %.0f ms (normal %d-%d%s)" % (name, value, low, high,
                                                "" if low <= value <= high else ", outside")
    rows = {table.GetColumnByName("Lead").GetValue(r): r for r in range(table.GetNumberOfRows())}
    r_wave = table.GetColumnByName("R_mV")
    polarity = table.GetColumnByName("TPolarity")
    progression = " ".join("%.2f" % r_wave.GetValue(rows[v]) for v in ("V1", "V2", "V3", "V4", "V5", "V6")
                           if v in rows)
    upright = [lead for lead in rows if polarity.GetValue(rows[lead]) == "upright"]
    return ["      ECG: %s, %s; R V1..V6 %s mV; T upright in %s" % (
        ranged("QRS", fd.GetArray("QRSDuration_ms").GetValue(0)), ranged("QT", fd.GetArray("QTInterval_ms").GetValue(0)),
        progression, ", ".join(upright) or "no lead")]


def _describe(data):
    """One line about a data object, plus a volume table for label maps (each organ beside its adult
    range, and the tissue classes read from the scan) and the named points of a landmark set."""
    lines = []
    if data is None:
        return lines
    if data.IsA("vtkImageData"):
        dims, spacing = data.GetDimensions(), data.GetSpacing()
        lines.append("      image %dx%dx%d, spacing %g x %g x %g mm" % (dims + spacing))
        scalars = data.GetPointData().GetScalars()
        if scalars is not None and scalars.GetName() == "Labels":
            import numpy as np
            from vtkmodules.util.numpy_support import vtk_to_numpy
            counts = np.bincount(vtk_to_numpy(scalars).astype(np.int64).ravel())
            names = data.GetFieldData().GetAbstractArray("LabelNames")
            voxel = spacing[0] * spacing[1] * spacing[2]
            for label in np.nonzero(counts)[0]:
                if label == 0:
                    continue
                name = names.GetValue(int(label)) if names is not None and label < names.GetNumberOfValues() else ""
                cm3 = counts[label] * voxel / 1000.0
                lines.append("        label %3d %-22s %12.1f cm3%s" % (label, name, cm3, adult_volumes.remark(name, cm3)))
            classes = data.GetFieldData().GetArray("TissueClasses")
            if classes is not None and classes.GetNumberOfComponents() == 6:
                found = ["%s %.0f+-%.0f HU" % (CLASS_NAMES[c], classes.GetComponent(c, 1), classes.GetComponent(c, 2))
                         for c in range(min(6, classes.GetNumberOfTuples())) if classes.GetComponent(c, 4)]
                lines.append("      tissue classes read from the scan: " + ", ".join(found))
            table = data.GetFieldData().GetArray("PatientTable")
            if table is not None and table.GetValue(0) > 0:
                lines.append("      patient table left out of the body: %.1f cm3" % (table.GetValue(0) / 1000.0))
    elif data.IsA("vtkTable"):
        lines.extend(_ecg_reading(data))
        columns = [data.GetColumn(c) for c in range(data.GetNumberOfColumns())]
        widths = [max(len(c.GetName()), 8) for c in columns]
        lines.append("      " + " ".join("%*s" % (w, c.GetName()) for w, c in zip(widths, columns)))
        rows = data.GetNumberOfRows()
        def row(r):
            return "      " + " ".join("%*.6g" % (w, c.GetTuple1(r)) if c.IsNumeric() else "%*s" % (w, c.GetValue(r))
                                       for w, c in zip(widths, columns))
        if rows <= 24:
            lines.extend(row(r) for r in range(rows))
        else:  # a time series (ECG leads): its ends and each column's range
            lines.extend(row(r) for r in range(3))
            lines.append("      ... (%d rows)" % rows)
            lines.extend(row(r) for r in range(rows - 3, rows))
            lines.append("      " + " ".join("%*s" % (w, "%.3g..%.3g" % c.GetRange() if c.IsNumeric() else "")
                                           for w, c in zip(widths, columns)) + "   (min..max)")
    elif data.IsA("vtkDataSet"):
        lines.append("      %s: %d points, %d cells" % (data.GetClassName(), data.GetNumberOfPoints(),
                                                       data.GetNumberOfCells()))
        named = data.GetPointData().GetAbstractArray("Name")
        if named is not None and named.GetNumberOfValues() == data.GetNumberOfPoints() <= 32:
            for i in range(data.GetNumberOfPoints()):
                lines.append("        %-18s (%.1f, %.1f, %.1f) mm" % ((named.GetValue(i),) + data.GetPoint(i)))
        hausdorff = data.GetFieldData().GetArray("Hausdorff")
        if hausdorff is not None and data.IsA("vtkPolyData"):
            lines.append("      two-sided Hausdorff distance to its input surface: %.3f mm" % hausdorff.GetValue(0))
    return lines


def _summary(paths, data, out):
    out.write("Wrote %d file(s):\n" % len(paths))
    series = {}
    for p in paths:  # frames of a time series (NAME_NNNN.vtu beside NAME.pvd) on one line
        m = re.match(r"(.*)_(\d{4})(\.vt[upi])$", p)
        if m and (m.group(1) + ".pvd") in paths:
            series.setdefault(m.group(1) + ".pvd", []).append(p)
    framed = {f for frames in series.values() for f in frames}
    for p in paths:
        if p in framed:
            continue
        if p in series:
            frames = series[p]
            size = sum(os.path.getsize(f) for f in frames if os.path.exists(f))
            out.write("  %-60s %10.1f kB  (time series: %d frames, %s .. %s)\n" % (
                p, size / 1024.0, len(frames), os.path.basename(frames[0]), os.path.basename(frames[-1])))
            for line in _describe(data.get(p)):
                out.write(line + "\n")
            continue
        size = os.path.getsize(p) if os.path.exists(p) else 0
        out.write("  %-60s %10.1f kB\n" % (p, size / 1024.0))
        for line in _describe(data.get(p)):
            out.write(line + "\n")


def stage_seconds(pipeline, total):
    """Seconds of each filter's own execution in pipeline order, then the <Output> files' writing
    and the rest of the run (building the pipeline, Python), adding up to the run's total."""
    from .watch import WRITING
    seconds = pipeline.clock.seconds
    stages = {s.name: round(seconds.get(s.name, 0.0), 3) for s in pipeline.steps}
    stages[WRITING] = round(seconds.get(WRITING, 0.0), 3)
    stages["(other)"] = round(max(0.0, total - sum(seconds.values())), 3)
    return stages


def _timing(pipeline, stages, out):
    """The timing table: seconds per filter, its share of the run, and how often it ran (a filter
    feeding a time series runs once per frame)."""
    total = sum(stages.values())
    types = {s.name: s.proxy.name for s in pipeline.steps}
    runs, cpu = pipeline.clock.runs, pipeline.clock.cpu
    out.write("Seconds per filter (its own execution; cores: CPU seconds of all threads per second):\n")
    for name, seconds in stages.items():
        times = runs.get(name, 0)
        cores = "%5.2f" % (cpu[name] / seconds) if name in cpu and seconds >= 0.05 else ""
        out.write("  %-24s %-24s %8.1f s %5.1f %%  %5s%s\n" % (
            name, types.get(name, ""), seconds, 100.0 * seconds / total if total else 0.0, cores,
            "  (%d runs)" % times if times > 1 else ""))
    all_cpu = sum(cpu.values())
    out.write("  %-24s %-24s %8.1f s          %5.2f\n" % ("total", "", total, all_cpu / total if total else 0.0))


def _version():
    from vtkmodules.vtkCommonCore import vtkVersion
    from . import __version__
    return "anatomesh %s (VTK %s)" % (__version__, vtkVersion.GetVTKVersion())


def _run(args):
    from . import pipeline as pl
    variables = variables_of(args.set)
    if variables is None:
        return 2
    if args.output:
        variables["output"] = args.output
    try:
        p = pl.Pipeline(args.pipeline, variables)
    except pl.UndeclaredVariableError as e:
        sys.stderr.write("anatomesh: error: %s\n" % e)
        return 2
    except pl.PipelineError as e:
        sys.stderr.write("anatomesh: error: %s\n" % e)
        if variables.get("output") and os.path.isdir(variables["output"]):
            marker.write_failed(variables["output"], args.pipeline, variables, str(e))
        return 1
    folder = p.variables["output"]
    marker.clear(folder)  # a run in progress, or one that fails, is never taken for a complete one
    if not args.quiet:
        sys.stderr.write("Running %s (%d filters)\n" % (args.pipeline, len(p.steps)))
    t0 = time.time()
    try:
        written = p.run(progress=None if args.quiet else _Progress(sys.stderr))
    except pl.PipelineError as e:
        sys.stderr.write("anatomesh: error: %s\n" % e)
        if os.path.isdir(folder):
            marker.write_failed(folder, args.pipeline, p.variables, str(e))
        return 1
    total = time.time() - t0
    stages = stage_seconds(p, total)
    marker.write_complete(folder, args.pipeline, p.variables, written, p.written_data, total, stages,
                          getattr(p, "warnings", []))
    if not args.quiet:
        _summary(written, p.written_data, sys.stdout)
        _timing(p, stages, sys.stdout)
        sys.stdout.write("Done in %.1f s.\n" % (time.time() - t0))
    if args.report:
        return _write_report(folder, args.report_time, args.quiet)
    return 0


def _write_report(folder, at, quiet):
    from .report import write_report
    if at is not None and not math.isfinite(at):
        sys.stderr.write("anatomesh: error: the report's time must be a number of ms, got %s\n" % at)
        return 2
    t0 = time.time()
    path, notes = write_report(folder, at)
    for note in notes:
        sys.stderr.write("anatomesh: warning: report: %s\n" % note)
    if not quiet:
        sys.stdout.write("Report: %s (%.1f s)\n" % (path, time.time() - t0))
    return 0


def _report(args):
    from . import marker as m
    if not os.path.isdir(args.folder):
        sys.stderr.write("anatomesh: error: %s: not a folder\n" % args.folder)
        return 1
    record = m.read(args.folder, warn=lambda text: sys.stderr.write("anatomesh: warning: %s\n" % text))
    if record is None:
        sys.stderr.write("anatomesh: warning: %s has no %s%s: reporting on every file in it\n" % (
            args.folder, "usable " if os.path.lexists(m.path(args.folder)) else "", m.NAME))
    elif record.get("status") != "complete":
        sys.stderr.write("anatomesh: warning: %s: the run did not complete (%s)\n" % (
            args.folder, record.get("error", record.get("status"))))
    return _write_report(args.folder, args.time, False)


def _filters(args):
    from . import catalogue
    for name, proxy in sorted(catalogue.load().items()):
        print("%-24s %-8s %s" % (name, proxy.group, proxy.short_help))
        if args.verbose:
            for prop in proxy.properties.values():
                if prop.kind != "input":
                    print("    %-28s %-6s x%d default=%s" % (prop.name, prop.kind, prop.number_of_elements,
                                                          " ".join(prop.defaults or [])))
    return 0


def main(argv=None):
    parser = argparse.ArgumentParser(prog="anatomesh", description="CT/MRI scan to simulation-ready mesh.")
    parser.add_argument("--version", action="version", version=_version())
    sub = parser.add_subparsers(dest="command")
    run = sub.add_parser("run", help="run a pipeline XML file")
    run.add_argument("pipeline", help="pipeline XML file")
    run.add_argument("--set", action="append", metavar="NAME=VALUE", help="set a pipeline variable")
    run.add_argument("--output", metavar="DIR", help="output folder (sets the variable 'output')")
    run.add_argument("--quiet", action="store_true", help="no progress or summary")
    run.add_argument("--report", action="store_true", help="write report.html with pictures beside the outputs")
    run.add_argument("--report-time", type=float, metavar="MS",
                     help="time of the body-surface picture (default: when the leads are largest)")
    rep = sub.add_parser("report", help="write report.html for a run's output folder")
    rep.add_argument("folder", help="a run's output folder")
    rep.add_argument("--time", type=float, metavar="MS",
                     help="time of the body-surface picture (default: when the leads are largest)")
    bat = sub.add_parser("batch", help="run a pipeline once per row of a CSV manifest")
    bat.add_argument("pipeline", help="pipeline XML file")
    bat.add_argument("manifest", help="CSV file: a header of pipeline variables (and 'case'), one row per case")
    bat.add_argument("--jobs", type=int, default=1, metavar="N", help="cases run at once on this machine")
    bat.add_argument("--resume", action="store_true", help="skip cases whose outputs are complete")
    bat.add_argument("--output", metavar="DIR", default="batch",
                     help="folder of the summary, and of each case's output when the manifest has no 'output'")
    bat.add_argument("--set", action="append", metavar="NAME=VALUE", help="a variable for every case")
    bat.add_argument("--outputs-anywhere", action="store_true",
                     help="let the manifest's output column name folders outside --output (absolute paths, ..)")
    bat.add_argument("--report", action="store_true", help="each case writes its report.html")
    st = sub.add_parser("state", help="check and load a ParaView state (.pvsm) that holds Anatomesh filters")
    st.add_argument("state", help="ParaView state file (.pvsm)")
    st.add_argument("--plugin", metavar="SO", help="the plugin's library (default: ANATOMESH_PLUGIN, else by name "
                    "from ParaView's plugin list)")
    st.add_argument("--open", action="store_true", help="then open it in the ParaView GUI with the plugin")
    flt = sub.add_parser("filters", help="list the filter catalogue")
    flt.add_argument("--verbose", "-v", action="store_true", help="show properties")
    args = parser.parse_args(argv)
    if not sys.stderr.isatty():
        # In a log, VTK's own messages (from filters inside filters) as plain text, without the
        # terminal colour codes of its logger.
        from vtkmodules.vtkCommonCore import vtkLogger, vtkOutputWindow
        vtkLogger.SetStderrVerbosity(vtkLogger.VERBOSITY_OFF)
        vtkOutputWindow.GetInstance().SetDisplayModeToAlwaysStdErr()
    try:
        if args.command == "run":
            return _run(args)
        if args.command == "batch":
            from . import batch
            return batch.main(args)
        if args.command == "filters":
            return _filters(args)
        if args.command == "state":
            from . import paraview_state
            return paraview_state.main(args)
        if args.command == "report":
            return _report(args)
    except OSError as e:
        # A folder that cannot be made or written (a file in its place, read-only, full): the path
        # and the system's words, not a traceback.
        where = e.filename if e.filename is not None else "output"
        sys.stderr.write("anatomesh: error: %s: %s\n" % (where, e.strerror or e))
        return 1
    except KeyboardInterrupt:
        sys.stderr.write("anatomesh: interrupted\n")
        return 130
    parser.print_help()
    return 2


if __name__ == "__main__":
    sys.exit(main())
