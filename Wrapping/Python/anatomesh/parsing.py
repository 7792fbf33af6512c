"""Pipeline XML files parsed and validated: variables (with arithmetic), filters and their
properties against the catalogue, connections, and the files they read and write (see
anatomesh.pipeline for the format)."""
import os
import re
import sys
import xml.parsers.expat

from . import catalogue
from . import touched as touched_files
from .errors import PipelineError, UndeclaredVariableError

FORMAT_VERSION = "1"

# Property names of earlier versions (British spellings), still read with a warning.
DEPRECATED_PROPERTIES = {
    "FibreArrayName": "FiberArrayName",
    "NeighbourhoodRings": "NeighborhoodRings",
    "NeighbourhoodRadius": "NeighborhoodRadius",
}


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


class ParsedPipeline:
    """A parsed and validated pipeline file: its variables, steps and outputs, every property and
    connection checked against the catalogue, every file against every other."""

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
