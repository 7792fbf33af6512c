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
import contextlib
import os
import re
import sys
import time
import xml.parsers.expat

from . import atomic, catalogue
from . import touched as touched_files

FORMAT_VERSION = "1"

# Property names of earlier versions (British spellings), still read with a warning.
DEPRECATED_PROPERTIES = {
    "FibreArrayName": "FiberArrayName",
    "NeighbourhoodRings": "NeighborhoodRings",
    "NeighbourhoodRadius": "NeighborhoodRadius",
}


class PipelineError(Exception):
    """A problem with a pipeline file or its execution; str() names the file and line."""


class UndeclaredVariableError(PipelineError):
    """--set names a variable the pipeline does not declare (a command-line mistake)."""


class _Node:
    def __init__(self, tag, attrs, line):
        self.tag, self.attrs, self.line, self.children = tag, attrs, line, []


def _parse_xml(path):
    try:
        with open(path, "rb") as f:
            data = f.read()
    except OSError as e:
        raise PipelineError("%s: cannot read the pipeline file: %s" % (path, e.strerror))
    parser = xml.parsers.expat.ParserCreate()
    stack, roots = [], []

    def start(tag, attrs):
        node = _Node(tag, attrs, parser.CurrentLineNumber)
        (stack[-1].children if stack else roots).append(node)
        stack.append(node)

    def end(tag):
        stack.pop()

    parser.StartElementHandler, parser.EndElementHandler = start, end
    try:
        parser.Parse(data, True)
    except xml.parsers.expat.ExpatError as e:
        raise PipelineError("%s:%d: malformed XML: %s" % (path, e.lineno, xml.parsers.expat.ErrorString(e.code)))
    return roots[0]


class Step:
    def __init__(self, name, proxy, line):
        self.name, self.proxy, self.line = name, proxy, line
        self.properties = []  # (Property, [values as strings], line)
        self.inputs = []  # (input property, upstream name, port, line)
        self.algorithm = None


class Pipeline:
    """A parsed and validated pipeline file."""

    def __init__(self, path, variables=None, proxies=None):
        self.path = path
        self.proxies = proxies or catalogue.load()
        self.variables = {}
        self.steps = []
        self.outputs = []  # (upstream name, port, file, line)
        self._given = dict(variables or {})
        self._parse()

    # -- parsing -------------------------------------------------------------------------------
    def _error(self, line, message):
        return PipelineError("%s:%d: %s" % (self.path, line, message))

    def _expand(self, text, line):
        def repl(m):
            name = m.group(1)
            if name not in self.variables:
                raise self._error(line, "unknown variable ${%s} (defined: %s)" % (
                    name, ", ".join(sorted(self.variables)) or "none"))
            return self.variables[name]
        text = re.sub(r"\$\{([A-Za-z_][A-Za-z0-9_]*)\}", repl, text)
        return re.sub(r"\$\(([^()]*(?:\([^()]*\)[^()]*)*)\)", lambda m: self._arithmetic(m.group(1), line), text)

    def _arithmetic(self, expression, line):
        """$(EXPRESSION): numbers, + - * /, parentheses, min() and max(), after the variables are expanded
        ("$(0.5 * ${spacing})"), so that defaults follow each other. The value as the shortest text that reads
        back to it."""
        import ast
        import operator
        ops = {ast.Add: operator.add, ast.Sub: operator.sub, ast.Mult: operator.mul, ast.Div: operator.truediv,
               ast.USub: operator.neg, ast.UAdd: operator.pos}

        def value(node):
            if isinstance(node, ast.Expression):
                return value(node.body)
            if isinstance(node, ast.Constant) and isinstance(node.value, (int, float)) \
                    and not isinstance(node.value, bool):
                return node.value
            if isinstance(node, ast.BinOp) and type(node.op) in ops:
                return ops[type(node.op)](value(node.left), value(node.right))
            if isinstance(node, ast.UnaryOp) and type(node.op) in ops:
                return ops[type(node.op)](value(node.operand))
            if isinstance(node, ast.Call) and isinstance(node.func, ast.Name) and node.func.id in ("min", "max") \
                    and node.args and not node.keywords:
                return {"min": min, "max": max}[node.func.id](value(a) for a in node.args)
            raise ValueError("only numbers, + - * /, parentheses, min() and max()")
        try:
            result = value(ast.parse(expression.strip(), mode="eval"))
        except (SyntaxError, ValueError, ZeroDivisionError, OverflowError) as e:
            raise self._error(line, "cannot compute $(%s): %s" % (expression, e)) from None
        if isinstance(result, float) and result.is_integer() and abs(result) < 2**53:
            result = int(result)
        return repr(result)

    def _parse(self):
        root = _parse_xml(self.path)
        if root.tag != "AnatomeshPipeline":
            raise self._error(root.line, "the root element must be <AnatomeshPipeline>, not <%s>" % root.tag)
        version = root.attrs.get("version")
        if version != FORMAT_VERSION:
            raise self._error(root.line, "unsupported pipeline format version %r (this Anatomesh reads %s)"
                              % (version, FORMAT_VERSION))
        # "output" always exists (the command line's --output); a pipeline may give it a default.
        # "pipeline_dir" is the pipeline file's folder, so defaults can name files beside it whatever
        # the current folder ("${pipeline_dir}/data/ct.nii.gz"); defaults may use the variables above them.
        self.variables["pipeline_dir"] = os.path.dirname(os.path.abspath(self.path))
        self.variables["output"] = self._given.get("output", "out")
        for node in root.children:
            if node.tag == "Variable":
                name = node.attrs.get("name")
                if not name or not re.match(r"^[A-Za-z_][A-Za-z0-9_]*$", name):
                    raise self._error(node.line, "a <Variable> needs a name made of letters, digits and _")
                if name in self._given:
                    self.variables[name] = self._given[name]
                else:
                    self.variables[name] = self._expand(node.attrs.get("default", ""), node.line)
        unknown = set(self._given) - set(self.variables)
        if unknown:
            raise UndeclaredVariableError("%s: --set names variables the pipeline does not declare: %s (declared: %s)" % (
                self.path, ", ".join(sorted(unknown)), ", ".join(sorted(self.variables)) or "none"))
        names = {}
        for node in root.children:
            if node.tag == "Variable":
                continue
            if node.tag == "Filter":
                step = self._parse_filter(node)
                if step.name in names:
                    raise self._error(node.line, "filter name %r is used twice" % step.name)
                names[step.name] = step
                self.steps.append(step)
            elif node.tag == "Output":
                for key in ("from", "file"):
                    if key not in node.attrs:
                        raise self._error(node.line, "<Output> needs a %r attribute" % key)
                self.outputs.append((node.attrs["from"], node.attrs.get("port", "0"),
                                     self._expand(node.attrs["file"], node.line), node.line))
            else:
                raise self._error(node.line, "unknown element <%s> (expected Variable, Filter or Output)" % node.tag)
        self._check_connections(names)

    def _parse_filter(self, node):
        name, kind = node.attrs.get("name"), node.attrs.get("type")
        if not name or not kind:
            raise self._error(node.line, "a <Filter> needs 'name' and 'type' attributes")
        if kind not in self.proxies:
            raise self._error(node.line, "unknown filter type %r (known: %s)" % (kind, ", ".join(sorted(self.proxies))))
        proxy = self.proxies[kind]
        step = Step(name, proxy, node.line)
        for child in node.children:
            if child.tag == "Property":
                pname = child.attrs.get("name")
                if pname in DEPRECATED_PROPERTIES and pname not in proxy.properties:
                    new = DEPRECATED_PROPERTIES[pname]
                    sys.stderr.write("%s:%d: warning: property %r is deprecated; use %r\n" % (
                        self.path, child.line, pname, new))
                    pname = new
                if pname not in proxy.properties or proxy.properties[pname].kind == "input":
                    known = [p for p in proxy.properties if proxy.properties[p].kind != "input"]
                    raise self._error(child.line, "filter %r (%s) has no property %r (properties: %s)" % (
                        name, kind, pname, ", ".join(known)))
                if "value" not in child.attrs:
                    raise self._error(child.line, "property %r needs a 'value' attribute" % pname)
                prop = proxy.properties[pname]
                value = self._expand(child.attrs["value"], child.line)
                values = [value] if prop.kind == "string" and prop.number_of_elements == 1 else value.split()
                self._check_value(step, prop, values, child.line)
                for earlier, _, earlier_line in step.properties:
                    if earlier.name == prop.name:
                        raise self._error(child.line, "property %r of filter %r is set twice (first at line %d)" % (
                            prop.name, name, earlier_line))
                step.properties.append((prop, values, child.line))
            elif child.tag == "Input":
                inputs = proxy.inputs
                if not inputs:
                    raise self._error(child.line, "filter %r (%s) takes no input" % (name, kind))
                iname = child.attrs.get("name", inputs[0].name)
                match = [p for p in inputs if p.name == iname]
                if not match:
                    raise self._error(child.line, "filter %r has no input %r" % (name, iname))
                if "from" not in child.attrs:
                    raise self._error(child.line, "<Input> needs a 'from' attribute")
                step.inputs.append((match[0], child.attrs["from"], child.attrs.get("port", "0"), child.line))
            else:
                raise self._error(child.line, "unknown element <%s> in a <Filter> (expected Property or Input)"
                                  % child.tag)
        return step

    def _check_value(self, step, prop, values, line):
        where = "property %r of filter %r" % (prop.name, step.name)
        if prop.kind == "string":
            if prop.number_of_elements and len(values) != prop.number_of_elements and not prop.repeat_command:
                raise self._error(line, "%s needs %d value(s), got %d" % (where, prop.number_of_elements, len(values)))
            return
        if prop.repeat_command:
            if len(values) % prop.per_command:
                raise self._error(line, "%s takes groups of %d values, got %d" % (where, prop.per_command, len(values)))
        elif len(values) != prop.number_of_elements:
            raise self._error(line, "%s needs %d value(s), got %d" % (where, prop.number_of_elements, len(values)))
        conv = int if prop.kind == "int" else float
        for i, v in enumerate(values):
            if prop.enumeration and v in prop.enumeration:
                values[i] = str(prop.enumeration[v])
                continue
            try:
                number = conv(v)
            except ValueError:
                raise self._error(line, "%s must be %s, got %r" % (
                    where, "an integer" if conv is int else "a number", v))
            if conv is float and number != number:
                raise self._error(line, "%s is NaN" % where)
            if conv is float and abs(number) == float("inf"):
                raise self._error(line, "%s must be finite, got %r" % (where, v))
            if conv is int and not -2**31 <= number < 2**31:
                raise self._error(line, "%s is out of an integer's range (%d to %d), got %s" % (
                    where, -2**31, 2**31 - 1, v))
            if prop.boolean and number not in (0, 1):
                raise self._error(line, "%s is a boolean (0 or 1), got %r" % (where, v))
            if prop.enumeration and number not in prop.enumeration.values():
                raise self._error(line, "%s must be one of %s, got %r" % (where, ", ".join(prop.enumeration), v))
            if prop.range:
                lo, hi = prop.range
                k = i if lo is None or i < len(lo) else 0
                if lo is not None and number < lo[min(k, len(lo) - 1)]:
                    raise self._error(line, "%s must be >= %s, got %s" % (where, lo[min(k, len(lo) - 1)], v))
                if hi is not None and number > hi[min(k, len(hi) - 1)]:
                    raise self._error(line, "%s must be <= %s, got %s" % (where, hi[min(k, len(hi) - 1)], v))

    def _port_index(self, step, port, line):
        if re.fullmatch(r"[0-9]+", port):
            count = max(1, len(step.proxy.output_ports))
            if int(port) >= count:
                raise self._error(line, "filter %r (%s) has %d output port(s), so no port %s (ports: %s)" % (
                    step.name, step.proxy.name, count, port, ", ".join(step.proxy.output_ports) or "0"))
            return int(port)
        if port in step.proxy.output_ports:
            return step.proxy.output_ports[port]
        raise self._error(line, "filter %r (%s) has no output port %r (ports: %s)" % (
            step.name, step.proxy.name, port, ", ".join(step.proxy.output_ports) or "0"))

    def _check_connections(self, names):
        for step in self.steps:
            for prop, upstream, port, line in step.inputs:
                if upstream not in names:
                    raise self._error(line, "input of %r comes from %r, which is not a filter of this pipeline"
                                      % (step.name, upstream))
                if names[upstream].proxy.is_writer:
                    raise self._error(line, "input of %r comes from writer %r, which has no output"
                                      % (step.name, upstream))
                self._port_index(names[upstream], port, line)
        for upstream, port, _, line in self.outputs:
            if upstream not in names:
                raise self._error(line, "<Output> from %r, which is not a filter of this pipeline" % upstream)
            self._port_index(names[upstream], port, line)
        # Cycles: depth-first search over the input edges, with a stack of its own (a chain of
        # thousands of filters listed from its end would exhaust Python's).
        state = {}
        for first in self.steps:
            if first.name in state:
                continue
            state[first.name] = 1
            path, stack = [first.name], [iter(first.inputs)]
            while stack:
                for _, upstream, _, line in stack[-1]:
                    if state.get(upstream) == 1:
                        raise self._error(line, "the pipeline has a cycle: %s" % " -> ".join(path + [upstream]))
                    if upstream not in state:
                        state[upstream] = 1
                        path.append(upstream)
                        stack.append(iter(names[upstream].inputs))
                        break
                else:
                    state[path.pop()] = 2
                    stack.pop()
        self._check_files()
        for step in self.steps:
            missing = [p.name for p in step.proxy.inputs
                       if not p.optional and p.name not in [i[0].name for i in step.inputs]]
            if missing:
                raise self._error(step.line, "filter %r (%s) needs its input %s connected" % (
                    step.name, step.proxy.name, ", ".join(missing)))
            if step.proxy.is_writer and not any(
                    p.name == "FileName" and values and values[0] for p, values, _ in step.properties):
                raise self._error(step.line, "writer %r (%s) needs its FileName property" % (
                    step.name, step.proxy.name))

    def _files(self):
        """(read, written): the files the pipeline reads (readers' file names) and writes (writers'
        and <Output>s'), each as (path, line)."""
        read, written = [], []
        for step in self.steps:
            for prop, values, line in step.properties:
                if prop.kind == "string" and prop.name.endswith("FileName") and values and values[0]:
                    (written if step.proxy.is_writer else read).append((values[0], line))
        written += [(path, line) for _, _, path, line in self.outputs]
        return read, written

    def _check_files(self):
        """Every file the pipeline reads exists and is a regular file (or a DICOM folder); no output may
        overwrite a file the pipeline reads (by path, however written, or by inode), the files each reader and
        writer touches besides its own (a detached header's data file, sidecar tables, a series' frames)
        included; and no two outputs may go to one file."""
        def key(path):
            real = os.path.realpath(path)
            try:
                st = os.stat(real)
                return real, (st.st_dev, st.st_ino)
            except OSError:
                return real, None

        read, written = self._files()
        for path, line in read:  # a missing input stops the run before anything is computed or written
            problem = touched_files.unreadable(path)
            if problem:
                raise self._error(line, "input file %s %s" % (path, problem))
        inputs = [(t, path, line, key(t)) for path, line in read for t in touched_files.paths(path, False)]
        seen = {}
        for path, line in written:
            pattern = touched_files.series_pattern(path)
            own = touched_files.paths(path, True)
            for target in own + touched_files.sidecars(path):
                real, inode = key(target)
                for t, ipath, iline, (ireal, iinode) in inputs:
                    if real == ireal or (inode is not None and inode == iinode) or (
                            pattern and pattern.match(ireal)):
                        raise self._error(line, "output %s would overwrite the input %s (line %d)%s" % (
                            path, ipath, iline, "" if t == ipath else ", whose data is in %s" % t))
                if target not in own:
                    continue
                if real in seen:
                    raise self._error(line, "two outputs go to %s (the other at line %d)" % (target, seen[real]))
                seen[real] = line

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
        algorithms = self.build()
        errors = []
        watcher = _Watcher(errors, progress)
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
                    watcher.warnings.append("%s: %s" % (step.name if step else path, _message_body(text)))
                    sys.stderr.write("anatomesh: warning: %s: %s\n" % (step.name if step else path, _message_body(text)))
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


WRITING = "(outputs)"


class _Watcher:
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
            self.errors.append((name, _message_body(message) or message))

        error_cb.CallDataType = "string0"
        algorithm.AddObserver("ErrorEvent", error_cb)

        def warning_cb(obj, event, data=None):
            # One plain line naming the filter (VTK would print its file, line and object address); kept
            # for the run's marker and report.
            text = _message_body(str(data) if data is not None else "")
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


def _message_body(message):
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


def _make_parent(path, pipeline, line):
    folder = os.path.dirname(os.path.abspath(path))
    try:
        os.makedirs(folder, exist_ok=True)
    except OSError as e:
        raise pipeline._error(line, "cannot create folder %s: %s" % (folder, e.strerror))


def _write_csv(table, path):
    """A vtkTable as comma-separated values with a header row, written atomically."""
    if table is None or not table.IsA("vtkTable"):
        raise PipelineError("%s: .csv takes a table, got %s" % (path, table.GetClassName() if table else "nothing"))
    columns = [table.GetColumn(c) for c in range(table.GetNumberOfColumns())]
    with atomic.replacing(path) as tmp:
        with open(tmp, "w", encoding="utf-8") as f:
            f.write(",".join(c.GetName() for c in columns) + "\n")
            for r in range(table.GetNumberOfRows()):
                f.write(",".join("%.10g" % c.GetTuple1(r) if c.IsNumeric() else str(c.GetValue(r))
                                 for c in columns) + "\n")


def _finish(files):
    """Wait for the files queued; a failure (a full disk, say) is an error naming the file."""
    if not files.Finish():
        raise PipelineError(files.GetErrorMessage())


class _Series:
    """A time series' frames, written into a staging folder beside the .pvd (.STEM.tmpPID.frames) and
    moved into place with the .pvd written last by commit(): a failed run leaves the old series (frames and
    .pvd) as it was. discard() removes the staging folder of a series not committed."""

    def __init__(self, folder, stem, path):
        atomic.remove_stale(folder, re.compile(r"^\.%s\.tmp(\d+)\.frames$" % re.escape(stem)))
        self.folder, self.path, self.names, self.text = folder, path, [], None
        self.staging = os.path.join(folder, ".%s.tmp%d.frames" % (stem, os.getpid()))
        self.discard()  # this process's own, from an earlier series of the same name
        try:
            os.mkdir(self.staging)
        except OSError as e:
            raise OSError(e.errno, e.strerror, path) from None

    def named(self, message):
        """A message about a staged frame, naming the series and the frame."""
        prefix = self.staging + os.sep
        if message.startswith(prefix):
            frame, _, why = message[len(prefix):].partition(": ")
            return "%s: frame %s: %s" % (self.path, frame, why)
        return message.replace(prefix, self.folder + os.sep)

    def commit(self):
        try:
            for name in self.names:
                os.replace(os.path.join(self.staging, name), os.path.join(self.folder, name))
        except OSError as e:
            raise OSError(e.errno, e.strerror, self.path) from None
        atomic.write_text(self.path, self.text)
        self.discard()

    def discard(self):
        import shutil
        shutil.rmtree(self.staging, ignore_errors=True)


def write_time_series(algorithm, port, path, error=lambda: None, clock=None, files=None, collections=None):
    """Write every time step an algorithm's output port advertises as NAME_NNNN.vtu (or .vtp/.vti)
    beside a ParaView collection NAME.pvd; without time steps, one file. The frames are staged and moved
    into place with the .pvd written last (see _Series), so a failed run never leaves a collection naming
    missing files, nor new frames under an old collection. Returns the paths written.
    With 'files' (an amConcurrentXMLWriter) the frames are queued there, and the series (a _Series) is
    appended to 'collections', to commit once the queue is finished (or discard after a failure)."""
    from vtkmodules.vtkCommonExecutionModel import vtkStreamingDemandDrivenPipeline as sddp
    algorithm.UpdateInformation()
    info = algorithm.GetOutputInformation(port)
    times = list(info.Get(sddp.TIME_STEPS())) if info.Has(sddp.TIME_STEPS()) else [None]
    folder = os.path.dirname(os.path.abspath(path))
    stem = os.path.splitext(os.path.basename(path))[0]
    exts = {"vtkUnstructuredGrid": ".vtu", "vtkPolyData": ".vtp", "vtkImageData": ".vti"}
    entries, written = [], []
    series = _Series(folder, stem, path)
    if collections is not None:
        collections.append(series)
    try:
        for k, t in enumerate(times):
            if t is None:
                algorithm.Update(port)
            else:
                algorithm.UpdateTimeStep(t)
            data = algorithm.GetOutputDataObject(port)
            message = error()
            if message or data is None:
                raise PipelineError("%s: time step %s failed: %s" % (path, t, message or "no output"))
            ext = exts.get(data.GetClassName())
            if ext is None:
                raise PipelineError("%s: cannot write a %s as a time series" % (path, data.GetClassName()))
            name = "%s_%04d%s" % (stem, k, ext)
            with (clock or StageClock()).running(WRITING):
                try:
                    write_vtk_xml(data, os.path.join(series.staging, name), files)
                except PipelineError as e:
                    raise PipelineError(series.named(str(e))) from None
            series.names.append(name)
            written.append(os.path.join(folder, name))
            entries.append('    <DataSet timestep="%r" part="0" file="%s"/>' % (0.0 if t is None else t, name))
        series.text = ('<?xml version="1.0"?>\n<VTKFile type="Collection" version="0.1">\n  <Collection>\n'
                       + "\n".join(entries) + "\n  </Collection>\n</VTKFile>\n")
        written.append(path)
        if files is None:
            series.commit()
    finally:
        if files is None:
            series.discard()
    return written


def _plain_field_data(data):
    """A shallow copy whose field data other readers take too (meshio reads no String arrays and no empty
    ones): text arrays become UTF-8 bytes (UInt8, one line per value; bytes(array).decode() gives the text),
    empty arrays are left out."""
    from vtkmodules.vtkCommonCore import vtkStringArray, vtkUnsignedCharArray
    fields = data.GetFieldData()
    if fields is None:
        return data
    if all(fields.GetAbstractArray(i).GetNumberOfTuples() > 0 and not fields.GetAbstractArray(i).IsA("vtkStringArray")
           for i in range(fields.GetNumberOfArrays())):
        return data
    copy = data.NewInstance()
    copy.ShallowCopy(data)
    plain = copy.GetFieldData().NewInstance()
    for i in range(fields.GetNumberOfArrays()):
        array = fields.GetAbstractArray(i)
        if array.GetNumberOfTuples() == 0:
            continue
        if isinstance(array, vtkStringArray):
            text = "\n".join(array.GetValue(k) for k in range(array.GetNumberOfValues())).encode("utf-8")
            import numpy as np
            from vtkmodules.util.numpy_support import numpy_to_vtk
            encoded = numpy_to_vtk(np.frombuffer(text, dtype=np.uint8), deep=1,
                                   array_type=vtkUnsignedCharArray().GetDataType())
            encoded.SetName(array.GetName())
            plain.AddArray(encoded)
        else:
            plain.AddArray(array)
    copy.SetFieldData(plain)
    return copy


def write_vtk_xml(data, path, files=None):
    """Write a data object to a VTK XML file (.vti, .vtp, .vtu, .vtm), or a table to .csv, atomically.
    A .vti, .vtp or .vtu goes through amConcurrentXMLWriter (its format settings are the project's
    one copy): queued on 'files' when given (written on a worker thread, done when files.Finish()
    returns), else written before this returns."""
    holds = {".vti": "vtkImageData", ".vtp": "vtkPolyData", ".vtu": "vtkUnstructuredGrid",
             ".vtm": "vtkMultiBlockDataSet"}
    ext = os.path.splitext(path)[1].lower()
    if ext == ".csv":
        _write_csv(data, path)
        return
    if ext not in holds:
        raise PipelineError("%s: unknown output extension %r (use %s)" % (path, ext, ", ".join(sorted(holds))))
    if not data.IsA(holds[ext]):
        fits = [e for e, kind in sorted(holds.items()) if data.IsA(kind)]
        raise PipelineError("%s: a %s file holds a %s, but this output is a %s%s" % (
            path, ext, holds[ext], data.GetClassName(), " (use %s)" % fits[0] if fits else ""))
    if ext != ".vtm":
        from anatomesh import amConcurrentXMLWriter
        queue = files if files is not None else amConcurrentXMLWriter()
        if not queue.Write(_plain_field_data(data), path):
            raise PipelineError(queue.GetErrorMessage())
        if files is None:
            _finish(queue)
        return
    from vtkmodules.vtkIOXML import vtkXMLMultiBlockDataWriter
    writer = vtkXMLMultiBlockDataWriter()
    # As amConcurrentXMLWriter writes: inline base64 (Debian 12's expat breaks VTK 9.2's reading of
    # appended data), zlib's fastest level.
    writer.SetDataModeToBinary()
    writer.SetCompressorTypeToZLib()
    writer.SetCompressionLevel(1)
    writer.SetInputData(data)
    _write_multiblock(writer, path)


def _write_multiblock(writer, path):
    """VTK writes a .vtm's blocks into a folder named after it, which the .vtm names: both are written in a
    temporary folder beside the target, then the blocks' folder and the .vtm are moved into place."""
    import shutil
    import tempfile
    folder, base = os.path.split(os.path.abspath(path))
    stem = os.path.splitext(base)[0]
    try:
        work = tempfile.mkdtemp(prefix=".%s.tmp%d_" % (stem, os.getpid()), dir=folder)
    except OSError as e:
        raise OSError(e.errno, e.strerror, path) from None
    try:
        writer.SetFileName(os.path.join(work, base))
        if not writer.Write() or writer.GetErrorCode() or not os.path.exists(os.path.join(work, base)):
            raise PipelineError("%s: the VTK XML writer failed (a full disk, or no %s data)" % (
                path, writer.GetInput().GetClassName()))
        blocks, target = os.path.join(work, stem), os.path.join(folder, stem)
        if os.path.isdir(blocks):
            if os.path.isdir(target):
                os.rename(target, os.path.join(work, "old"))
            os.rename(blocks, target)
        with atomic.replacing(path) as tmp:
            os.rename(os.path.join(work, base), tmp)
    except OSError as e:
        raise OSError(e.errno, e.strerror, path) from None
    finally:
        shutil.rmtree(work, ignore_errors=True)
