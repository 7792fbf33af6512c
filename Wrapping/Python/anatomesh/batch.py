"""``anatomesh batch``: one pipeline over the cases of a CSV manifest.

    anatomesh batch PIPELINE.xml MANIFEST.csv [--jobs N] [--resume] [--output DIR] [--set NAME=VALUE ...]

The manifest's header names pipeline variables (and optionally ``case``, the case's name); each row is a case.
The manifest may be UTF-8 (with or without a byte-order mark) or, with its byte-order mark, UTF-16 or UTF-32.
A case's output folder is DIR/CASE, or DIR/OUTPUT for an ``output`` column; it must lie inside DIR (no ``..``,
no absolute path, unless ``--outputs-anywhere``) and no two cases may share one. Every case runs as its own ``anatomesh run``
process, its progress and messages in CASE_OUTPUT/anatomesh.log, so one failing (or crashing) case never stops
the others. ``--jobs N`` runs N cases at once. ``--resume`` skips a case whose folder holds a complete run marker
(anatomesh-run.json, written last) for the same pipeline and variables. Under ``mpirun -n K`` (mpi4py) the ranks
share the cases, case i on rank i mod K, and rank 0 writes the summary. The summary, DIR/batch_summary.csv and
.html, has every case's status, seconds, log and key figures (label volumes, Hausdorff distance, Table 1's
whole-mesh row, smallest Dice). SIGTERM or SIGINT (Ctrl-C) stops the batch cleanly: every running case's whole
process group is terminated, no case starts after it, and the summary is written with those cases "interrupted"
(``--resume`` runs them again). Exit status: 0 when every case is complete, 1 when any failed, 2 for a mistake in
the command or the manifest (named with its line), 128 + the signal's number when stopped.
"""
import concurrent.futures
import csv
import html
import io
import os
import signal
import subprocess
import sys
import threading
import time

from . import atomic, marker
from .options import variables_of


class ManifestError(Exception):
    pass


class Stop:
    """The batch's stop: the signal that asked for it, and the running cases' processes to end."""
    lock = threading.Lock()
    running = set()
    number = None

    @classmethod
    def request(cls, number, frame=None):
        with cls.lock:
            cls.number = cls.number or number
            for process in cls.running:
                try:
                    os.killpg(process.pid, signal.SIGTERM)  # the case and what it started (TetGen, writers)
                except ProcessLookupError:
                    pass

    @classmethod
    def requested(cls):
        return cls.number is not None


def read_manifest(path, declared):
    """Cases as (name, variables) from the CSV manifest; variables must be declared by the pipeline."""
    try:
        with open(path, "rb") as f:
            raw = f.read()
        rows = list(csv.reader(io.StringIO(_decode(raw), newline="")))
    except OSError as e:
        raise ManifestError("%s: cannot read the manifest: %s" % (path, e.strerror or e))
    except (UnicodeDecodeError, csv.Error) as e:
        raise ManifestError("%s: cannot read the manifest: %s" % (path, e))
    rows = [(n + 1, r) for n, r in enumerate(rows) if any(cell.strip() for cell in r)]
    if len(rows) < 2:
        raise ManifestError("%s: a manifest needs a header of variable names and at least one case" % path)
    header = [h.strip() for h in rows[0][1]]
    unknown = [h for h in header if h != "case" and h not in declared]
    if unknown or len(set(header)) != len(header) or "" in header:
        raise ManifestError("%s:%d: columns must be distinct pipeline variables or 'case'; %s (declared: %s)" % (
            path, rows[0][0], "unknown: " + ", ".join(unknown) if unknown else "empty or repeated names",
            ", ".join(sorted(declared))))
    cases, names = [], set()
    for line, row in rows[1:]:
        if len(row) != len(header):
            raise ManifestError("%s:%d: %d values for %d columns" % (path, line, len(row), len(header)))
        values = dict(zip(header, (cell.strip() for cell in row)))
        name = values.pop("case", "") or "case%03d" % (len(cases) + 1)
        if name in names or os.sep in name or name in (".", ".."):
            raise ManifestError("%s:%d: case name %r is repeated, holds a '%s' or is '.' or '..': each case needs "
                                "a folder of its own" % (path, line, name, os.sep))
        names.add(name)
        cases.append((name, values))
    return cases


def _decode(raw):
    """The manifest's text: a byte-order mark (as spreadsheets write them) says its encoding, else UTF-8."""
    import codecs
    for bom, encoding in ((codecs.BOM_UTF8, "utf-8"), (codecs.BOM_UTF32_LE, "utf-32-le"),
                          (codecs.BOM_UTF32_BE, "utf-32-be"), (codecs.BOM_UTF16_LE, "utf-16-le"),
                          (codecs.BOM_UTF16_BE, "utf-16-be")):
        if raw.startswith(bom):
            return raw[len(bom):].decode(encoding)
    return raw.decode("utf-8")


def case_folders(work, output, anywhere=False):
    """Each case's output folder: the manifest's 'output' (relative to --output) or --output/CASE. Every
    folder lies inside --output unless 'anywhere' (the user's --outputs-anywhere), and no two cases share
    one. Returns an error message, or None."""
    root = os.path.realpath(output)
    folders = {}
    for name, variables in work:
        given = variables.get("output")
        variables["output"] = os.path.join(output, given if given else name)
        real = os.path.realpath(variables["output"])
        if not anywhere and real != root and not real.startswith(root + os.sep):
            return "case %r: output %r lies outside --output %s (give --outputs-anywhere to allow it)" % (
                name, given, output)
        if real == root:
            return "case %r: output %r is --output itself; each case needs a folder of its own" % (name, given)
        inside = [other for path, other in folders.items()
                  if path == real or path.startswith(real + os.sep) or real.startswith(path + os.sep)]
        if inside:
            return "cases %r and %r write into one folder, %s" % (inside[0], name, variables["output"])
        folders[real] = name
    return None


def run_case(pipeline, name, variables, resume, report=False):
    """Runs one case in its own process; returns its summary row."""
    folder = variables["output"]
    row = {"case": name, "output": folder, "log": os.path.join(folder, "anatomesh.log"),
           "variables": {k: v for k, v in variables.items() if k != "output"}}
    done = marker.read(folder, warn=lambda text: sys.stderr.write("anatomesh: warning: %s\n" % text)) \
        if resume else None
    if done and done.get("status") == "complete" and done.get("pipeline") == os.path.abspath(pipeline) and all(
            done.get("variables", {}).get(k) == v for k, v in variables.items()):
        row.update(status="skipped (complete)", exit=0, seconds=done.get("seconds", 0.0),
                   figures=done.get("figures", {}))
        report_path = os.path.join(folder, "report.html")
        if report and not os.path.isfile(report_path):  # complete before reports were asked for
            with open(row["log"], "a") as log:
                subprocess.call([sys.executable, "-m", "anatomesh.cli", "report", folder], stdout=log,
                                stderr=subprocess.STDOUT)
        if report and os.path.isfile(report_path):
            row["report"] = report_path
        return row
    if Stop.requested():
        row.update(status="interrupted", exit="", seconds=0.0, figures={}, error="not started: the batch was stopped")
        return row
    os.makedirs(folder, exist_ok=True)
    command = [sys.executable, "-m", "anatomesh.cli", "run", pipeline]
    for k, v in variables.items():
        command += ["--set", "%s=%s" % (k, v)]
    if report:
        command.append("--report")
    t0 = time.time()
    with open(row["log"], "w") as log:
        # Its own process group, so that a stop ends it and everything it started.
        process = subprocess.Popen(command, stdout=log, stderr=subprocess.STDOUT, start_new_session=True)
        with Stop.lock:
            Stop.running.add(process)
            stopped = Stop.requested()
        if stopped:
            Stop.request(Stop.number)
        code = process.wait()
        with Stop.lock:
            Stop.running.discard(process)
    done = marker.read(folder) or {}
    ok = code == 0 and done.get("status") == "complete"
    status = "complete" if ok else ("interrupted" if Stop.requested() else "failed")
    row.update(status=status, exit=code, seconds=round(time.time() - t0, 2), figures=done.get("figures", {}))
    if ok and report and os.path.isfile(os.path.join(folder, "report.html")):
        row["report"] = os.path.join(folder, "report.html")
    if status == "interrupted":
        row["error"] = "stopped by the batch's signal %d" % Stop.number
    elif not ok:
        row["error"] = done.get("error") or _last_error(row["log"]) or "exit status %d (see the log)" % code
    return row


def _last_error(log):
    """The last 'anatomesh: error:' line of a case's log (a mistake found before the run has no marker)."""
    try:
        with open(log, errors="replace") as f:
            lines = [l.strip() for l in f if l.startswith("anatomesh: error:")]
    except OSError:
        return None
    return lines[-1][len("anatomesh: error:"):].strip() if lines else None


def write_summary(folder, rows):
    """batch_summary.csv and batch_summary.html: one row per case, one column per key figure."""
    figure_columns = []
    for row in rows:
        for file, values in row["figures"].items():
            for key in values:
                if (file, key) not in figure_columns:
                    figure_columns.append((file, key))
    variables = []  # every variable a case was run with, in the manifest's order
    for row in rows:
        variables += [k for k in row.get("variables", {}) if k not in variables]
    head = ["case"] + variables + ["status", "exit", "seconds", "output", "log", "error"] + (
        ["report"] if any("report" in r for r in rows) else [])
    table = [head + ["%s: %s" % c for c in figure_columns]]
    for row in rows:
        cells = dict(row, **row.get("variables", {}))
        table.append([cells.get(h, "") for h in head] +
                     [_plain(row["figures"].get(f, {}).get(k, "")) for f, k in figure_columns])
    os.makedirs(folder, exist_ok=True)
    text = io.StringIO()
    csv.writer(text).writerows(table)
    atomic.write_text(os.path.join(folder, "batch_summary.csv"), text.getvalue())
    failed = sum(1 for r in rows if r["status"] in ("failed", "interrupted"))
    page = ["<!DOCTYPE html><html><head><meta charset='utf-8'><title>Anatomesh batch</title>"
            "<style>td,th{border:1px solid #bbb;padding:2px 6px}table{border-collapse:collapse}"
            ".failed{background:#fdd}</style></head><body>\n",
            "<h1>Anatomesh batch: %d cases, %d failed or interrupted</h1>\n<table>\n" % (len(rows), failed),
            "<tr>" + "".join("<th>%s</th>" % html.escape(str(h)) for h in table[0]) + "</tr>\n"]
    for row, cells in zip(rows, table[1:]):
        cls = " class='failed'" if row["status"] in ("failed", "interrupted") else ""
        page.append("<tr%s>" % cls + "".join(_cell(h, c, folder) for h, c in zip(table[0], cells)) + "</tr>\n")
    page.append("</table></body></html>\n")
    atomic.write_text(os.path.join(folder, "batch_summary.html"), "".join(page))


def _plain(value):
    """A figure as it reads: a count as an integer (939123, not 939123.0)."""
    return int(value) if isinstance(value, float) and value.is_integer() and abs(value) < 2**53 else value


def _cell(column, value, folder):
    """A summary cell; a case's report, folder and log are links (relative to the summary, so the folder can
    move)."""
    if column in ("report", "output", "log") and value:
        target = os.path.relpath(value, folder)
        text = "report" if column == "report" else target
        return "<td><a href='%s'>%s</a></td>" % (html.escape(target, quote=True), html.escape(text))
    return "<td>%s</td>" % html.escape(str(value))


def _mpi():
    """(communicator, rank, size) under mpirun with mpi4py, else (None, 0, 1)."""
    if int(os.environ.get("OMPI_COMM_WORLD_SIZE", os.environ.get("PMI_SIZE", "1"))) <= 1:
        return None, 0, 1
    from mpi4py import MPI
    comm = MPI.COMM_WORLD
    return comm, comm.Get_rank(), comm.Get_size()


def main(args):
    from . import pipeline as pl
    given = variables_of(args.set)
    if given is None:
        return 2
    if args.jobs < 1:
        sys.stderr.write("anatomesh: error: --jobs must be at least 1\n")
        return 2
    try:
        declared = set(pl.Pipeline(args.pipeline, given).variables)
        cases = read_manifest(args.manifest, declared)
    except (pl.PipelineError, ManifestError) as e:
        sys.stderr.write("anatomesh: error: %s\n" % e)
        return 2
    work = []
    for name, values in cases:
        variables = dict(given)
        variables.update(values)
        work.append((name, variables))
    problem = case_folders(work, args.output, args.outputs_anywhere)
    if problem:
        sys.stderr.write("anatomesh: error: %s: %s\n" % (args.manifest, problem))
        return 2
    comm, rank, size = _mpi()
    mine = [(i, w) for i, w in enumerate(work) if i % size == rank]
    previous = {number: signal.signal(number, Stop.request) for number in (signal.SIGTERM, signal.SIGINT)}
    results = {}
    with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
        futures = {pool.submit(run_case, args.pipeline, name, variables, args.resume, args.report): i
                   for i, (name, variables) in mine}
        for future in concurrent.futures.as_completed(futures):
            row = future.result()
            results[futures[future]] = row
            sys.stderr.write("  %-24s %-20s %8.1f s  %s\n" % (row["case"], row["status"], row["seconds"],
                                                            row.get("error", "")))
    if comm is not None:
        gathered = comm.gather(results, root=0)
        if rank == 0:
            for part in gathered:
                results.update(part)
        failed = comm.bcast(sum(1 for r in results.values() if r["status"] in ("failed", "interrupted"))
                            if rank == 0 else None, root=0)
    else:
        failed = sum(1 for r in results.values() if r["status"] in ("failed", "interrupted"))
    for number, handler in previous.items():
        signal.signal(number, handler)
    if rank == 0:
        rows = [results[i] for i in sorted(results)]
        write_summary(args.output, rows)
        interrupted = sum(r["status"] == "interrupted" for r in rows)
        sys.stdout.write("%d cases: %d complete, %d skipped, %d failed, %d interrupted; summary in %s\n" % (
            len(rows), sum(r["status"] == "complete" for r in rows), sum(r["status"].startswith("skipped")
                                                                         for r in rows),
            sum(r["status"] == "failed" for r in rows), interrupted, os.path.join(args.output, "batch_summary.csv")))
    if Stop.requested():
        return 128 + Stop.number
    return 1 if failed else 0
