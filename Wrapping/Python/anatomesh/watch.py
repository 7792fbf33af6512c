"""What a run watches: each algorithm's errors, warnings and progress, and each stage's own time."""
import contextlib
import re
import sys
import time

WRITING = "(outputs)"


class Watcher:
    """Collects VTK errors, reports progress of each algorithm and times each one's own execution."""

    def __init__(self, errors, progress):
        self.errors, self.progress, self.last = errors, progress, {}
        self.warnings = []  # "filter: text", in the order they came
        self.clock = StageClock()

    def watch(self, name, algorithm):
        algorithm.AddObserver("StartEvent", lambda obj, event: self.clock.start(name))
        algorithm.AddObserver("EndEvent", lambda obj, event: self.clock.stop(name))
        def error_cb(obj, event, data=None):
            message = str(data) if data is not None else "(its message is not valid text)"
            self.errors.append((name, message_body(message) or message))

        error_cb.CallDataType = "string0"
        algorithm.AddObserver("ErrorEvent", error_cb)

        def warning_cb(obj, event, data=None):
            # One plain line naming the filter (VTK would print its file, line and object address); kept
            # for the run's marker and report.
            text = message_body(str(data) if data is not None else "")
            self.warnings.append("%s: %s" % (name, text))
            sys.stderr.write("anatomesh: warning: %s: %s\n" % (name, text))

        warning_cb.CallDataType = "string0"
        algorithm.AddObserver("WarningEvent", warning_cb)
        # The executive reports wrong connections (a port that does not exist, a data type the
        # filter does not take): a failure of this filter too.
        algorithm.GetExecutive().AddObserver("ErrorEvent", error_cb)
        if self.progress:
            def progress_cb(obj, event):
                self.progress(name, obj.GetProgress())
            algorithm.AddObserver("ProgressEvent", progress_cb)

    def finish(self):
        if self.progress:
            self.progress(None, 1.0)


def message_body(message):
    """VTK's text "ERROR: In file, line N\\nclass (0x..): message" as its message alone."""
    lines = message.strip().splitlines()
    # The message is everything after the "class (0x...): " prefix, its own lines included (a DICOM
    # folder's list of series).
    for i, line in enumerate(lines):
        m = re.match(r"^\w+ \(0x[0-9a-f]+\): ", line)
        if m:
            return "\n".join([line[m.end():]] + lines[i + 1:]).strip()
    if lines and re.match(r"^(ERROR|Warning): In .*, line \d+$", lines[0]):
        lines = lines[1:]
    return "\n".join(lines).strip()


class StageClock:
    """Wall seconds per stage, each stage's own: a stage that starts while another runs (an upstream
    filter updated from inside a filter) pauses the other's clock until it ends. The process's CPU
    seconds (all its threads) are counted the same way, so cpu / seconds tells how many cores a stage
    kept busy (the output files' worker threads add to whichever stage runs while they write)."""

    def __init__(self):
        self.seconds, self.cpu, self.runs, self.stack = {}, {}, {}, []

    @staticmethod
    def _now():
        return time.perf_counter(), time.process_time()

    def _add(self, name, now, since):
        self.seconds[name] = self.seconds.get(name, 0.0) + now[0] - since[0]
        self.cpu[name] = self.cpu.get(name, 0.0) + now[1] - since[1]

    def start(self, name):
        now = self._now()
        self.runs[name] = self.runs.get(name, 0) + 1
        if self.stack:
            outer, since = self.stack[-1]
            self._add(outer, now, since)
        self.stack.append((name, now))

    def stop(self, name):
        now = self._now()
        if not self.stack or self.stack[-1][0] != name:
            return  # an end without its start (an observer added mid-run): nothing to count
        _, since = self.stack.pop()
        self._add(name, now, since)
        if self.stack:
            self.stack[-1] = (self.stack[-1][0], now)

    @contextlib.contextmanager
    def running(self, name):
        self.start(name)
        try:
            yield
        finally:
            self.stop(name)
