"""Pipeline XML files: parse, validate against the catalogue, and run.

Format (version 1)::

    <AnatomeshPipeline version="1">
      <Variable name="output" default="out"/>            <!-- ${output}, overridable -->
      <Filter name="phantom" type="ThoraxPhantomSource">
        <Property name="Spacing" value="2 2 2"/>
      </Filter>
      <Filter name="save" type="ImageWriter">              <!-- writers run after the rest -->
        <Input from="phantom" port="Labels"/>              <!-- port: name or index -->
        <Property name="FileName" value="${output}/labels.nii.gz"/>
      </Filter>
      <Output from="phantom" port="CT" file="${output}/ct.vti"/>  <!-- any VTK XML file -->
    </AnatomeshPipeline>

``type`` names a proxy of the catalogue (the plugin's server-manager XML); properties are
checked against it (name, type, number of values, boolean and range domains) before anything
runs. ``${name}`` is replaced by a variable (``output`` always exists, default "out"): its default, or the value given to ``run`` (the
command line's ``--set name=value``; ``--output DIR`` sets ``output``). Every problem is a
PipelineError naming the file and line.
"""
import os
import sys

from .errors import PipelineError, UndeclaredVariableError  # noqa: F401 (the module's errors, as pl.PipelineError)
from .parsing import ParsedPipeline
from .watch import WRITING, Watcher, message_body  # noqa: F401 (WRITING: the outputs' stage name)
from .writers import write_time_series, write_vtk_xml


class Pipeline(ParsedPipeline):
    """A parsed and validated pipeline file (anatomesh.parsing) that builds its VTK algorithms and runs."""

    # -- execution -----------------------------------------------------------------------------
    def build(self):
        """Instantiate and connect the VTK algorithms; returns {name: algorithm}."""
        import anatomesh
        algorithms = {}
        for step in self.steps:
            cls = getattr(anatomesh, step.proxy.class_name, None)
            if cls is None:
                raise self._error(step.line, "class %s of filter type %s is not in this build of Anatomesh"
                                  % (step.proxy.class_name, step.proxy.name))
            algorithm = cls()
            for prop, values, line in step.properties:
                conv = {"int": int, "double": float}.get(prop.kind, str)
                args = [conv(v) for v in values]
                if prop.kind == "string" and prop.number_of_elements == 1:
                    args = [values[0]]
                method = getattr(algorithm, prop.command, None)
                if method is None:
                    raise self._error(line, "%s has no method %s" % (step.proxy.class_name, prop.command))
                try:
                    if prop.repeat_command:
                        if prop.clean_command:
                            getattr(algorithm, prop.clean_command)()
                        k = prop.per_command
                        if prop.set_number_command:
                            getattr(algorithm, prop.set_number_command)(len(args) // k)
                        for i in range(0, len(args), k):
                            if prop.use_index:
                                method(i // k, *args[i:i + k])
                            else:
                                method(*args[i:i + k])
                    else:
                        method(*args)
                except (TypeError, ValueError) as e:
                    raise self._error(line, "cannot set property %r of filter %r: %s" % (prop.name, step.name, e))
            step.algorithm = algorithm
            algorithms[step.name] = algorithm
        by_name = {s.name: s for s in self.steps}
        for step in self.steps:
            for prop, upstream, port, line in step.inputs:
                index = self._port_index(by_name[upstream], port, line)
                step.algorithm.SetInputConnection(prop.port_index, by_name[upstream].algorithm.GetOutputPort(index))
        return algorithms

    def _failure(self, by_name, step, errors, fallback):
        """The error for a failed update of step: named after the filter that reported the first
        error (an upstream one, often), with that filter's line and type."""
        culprit = by_name.get(errors[0][0], step) if errors else step
        message = errors[0][1] if errors else fallback
        # What a filter refuses in its input (a scan where a label map belongs) comes from a file: name it.
        sources = [] if self._reads(culprit) else sorted(set(self._files_upstream(culprit, by_name)))
        if sources and not any(f in message for f in sources):
            message += " (input read from %s)" % ", ".join(sources)
        return self._error(culprit.line, "filter %r (%s) failed: %s" % (culprit.name, culprit.proxy.name, message))

    @staticmethod
    def _reads(step):
        return [values[0] for prop, values, _ in step.properties
                if prop.kind == "string" and prop.name.endswith("FileName") and values and values[0]]

    def _files_upstream(self, step, by_name, seen=None):
        """The files the readers upstream of a step read."""
        seen = set() if seen is None else seen
        for _, upstream, _, _ in step.inputs:
            if upstream in seen or upstream not in by_name:
                continue
            seen.add(upstream)
            up = by_name[upstream]
            yield from self._reads(up) or self._files_upstream(up, by_name, seen)

    def run(self, progress=None, log=None):
        """Build and execute; write every writer and <Output>. Returns a list of written files.
        An output that feeds one filter and nothing else (no writer, no <Output>) is released once
        that filter has run, so the later stages reuse its memory (the surfaces between the label
        map and the remeshing are most of the main job's), unless that filter runs once per frame
        of a time series. build() alone keeps every output."""
        self.build()
        errors = []
        watcher = Watcher(errors, progress)
        for step in self.steps:
            watcher.watch(step.name, step.algorithm)
        by_name = {s.name: s for s in self.steps}
        self._release_single_use(by_name)  # after the watcher: its information requests report like the run's
        written = []
        self.written_data = {}
        self.warnings = watcher.warnings  # every warning of the run, for its marker and report
        self.clock = watcher.clock  # each filter's own execution time, and the <Output> files'
        self.clock.seconds.update((s.name, 0.0) for s in self.steps)
        # The writers and the <Output> VTK XML files run on worker threads while the next filters
        # run: a writer's input is updated here, then the writer takes a copy of it to a worker.
        from anatomesh import amConcurrentXMLWriter
        files = amConcurrentXMLWriter()
        collections = []
        try:
            writers = {}  # file name: the writer step
            for step in self.steps:
                if not step.proxy.is_writer:
                    continue
                algorithm = step.algorithm
                path = algorithm.GetFileName()
                _make_parent(path, self, step.line)
                connection = algorithm.GetInputConnection(0, 0)
                upstream = connection.GetProducer()
                upstream.Update(connection.GetIndex())
                data = upstream.GetOutputDataObject(connection.GetIndex())
                for port in range(1, algorithm.GetNumberOfInputPorts()):  # a second input (openCARP's surfaces)
                    if algorithm.GetNumberOfInputConnections(port) == 1:
                        extra = algorithm.GetInputConnection(port, 0)
                        extra.GetProducer().Update(extra.GetIndex())
                if errors or data is None:
                    raise self._failure(by_name, step, errors, "no input")
                # No Python observer may run on the worker: the writer's time is the queue's.
                algorithm.RemoveAllObservers()
                algorithm.GetExecutive().RemoveAllObservers()
                if not files.QueueWriter(algorithm, path):
                    raise self._writer_failure(writers, files)
                writers[path] = step
                written.append(path)
                self.written_data[path] = data
            for upstream, port, path, line in self.outputs:
                step = by_name[upstream]
                index = self._port_index(step, port, line)
                algorithm = step.algorithm
                algorithm.UpdateInformation()
                algorithm.Update(index)  # returns nothing in VTK 9.2: errors come through the watcher
                if errors or algorithm.GetOutputDataObject(index) is None:
                    raise self._failure(by_name, step, errors, "no output")
                _make_parent(path, self, line)
                if os.path.splitext(path)[1].lower() == ".pvd":
                    def failed():
                        return (errors[0][0] + ": " + errors[0][1]) if errors else None
                    written.extend(write_time_series(algorithm, index, path, failed, watcher.clock, files,
                                                     collections))
                    self.written_data[path] = algorithm.GetOutputDataObject(index)
                    continue
                with watcher.clock.running(WRITING):
                    write_vtk_xml(algorithm.GetOutputDataObject(index), path, files)
                written.append(path)
                self.written_data[path] = algorithm.GetOutputDataObject(index)
            with watcher.clock.running(WRITING):
                finished = files.Finish()
                for i in range(files.GetNumberOfWarnings()):
                    path, _, text = files.GetWarning(i).partition(": ")
                    step = writers.get(path)
                    watcher.warnings.append("%s: %s" % (step.name if step else path, message_body(text)))
                    sys.stderr.write("anatomesh: warning: %s: %s\n" % (step.name if step else path, message_body(text)))
                if not finished:
                    raise self._writer_failure(writers, files, collections)
                for series in collections:
                    series.commit()
        finally:
            # A series not committed (the run failed) leaves no staging folder; the queue is done first.
            if collections:
                files.Finish()
            for series in collections:
                series.discard()
        watcher.finish()
        return written

    def _release_single_use(self, by_name):
        """VTK's release-data flag on each output port whose one consumer is a filter that runs once:
        the executive frees the data after that filter's execution (and would run the producer again
        if asked). A filter whose output has time steps runs once per frame and asks for its inputs
        each time: its inputs are kept."""
        from vtkmodules.vtkCommonExecutionModel import vtkStreamingDemandDrivenPipeline as sddp

        def per_frame(step):
            step.algorithm.UpdateInformation()
            for port in range(step.algorithm.GetNumberOfOutputPorts()):
                info = step.algorithm.GetOutputInformation(port)
                if info.Has(sddp.TIME_STEPS()) or info.Has(sddp.TIME_RANGE()):
                    return True
            return False

        consumers = {}
        for step in self.steps:
            for _, upstream, port, line in step.inputs:
                key = (upstream, self._port_index(by_name[upstream], port, line))
                consumers.setdefault(key, []).append(step)
        for upstream, port, _, line in self.outputs:
            key = (upstream, self._port_index(by_name[upstream], port, line))
            consumers.setdefault(key, []).append(None)
        for (upstream, index), users in consumers.items():
            if len(users) == 1 and users[0] is not None and not users[0].proxy.is_writer and not per_frame(users[0]):
                by_name[upstream].algorithm.GetExecutive().SetReleaseDataFlag(index, 1)

    def _writer_failure(self, writers, files, collections=()):
        """The queue's first failure: named after its writer step when a writer failed (a series' frame by
        its final path)."""
        message = files.GetErrorMessage()
        for series in collections:
            message = series.named(message)
        path, _, why = message.partition(": ")
        step = writers.get(path)
        if step is None:
            return PipelineError(message)
        return self._error(step.line, "filter %r (%s) failed: %s" % (step.name, step.proxy.name, why))


def _make_parent(path, pipeline, line):
    folder = os.path.dirname(os.path.abspath(path))
    try:
        os.makedirs(folder, exist_ok=True)
    except OSError as e:
        raise pipeline._error(line, "cannot create folder %s: %s" % (folder, e.strerror))
