"""The body of the FuzzPipelineXml target: the pipeline-XML parser and validator on any bytes.

Every input must end in a Pipeline (valid) or a PipelineError (a message naming the file and
line); any other exception is a finding (the command line would show a traceback). The package
is imported from the source tree without its wrapped VTK modules: parsing and validation are
plain Python over the server-manager XML.
"""
import glob
import os
import sys
import tempfile
import types

_state = {}


def setup(source):
    package = types.ModuleType("anatomesh")
    package.__path__ = [os.path.join(source, "Wrapping", "Python", "anatomesh")]
    sys.modules["anatomesh"] = package
    from anatomesh import catalogue, pipeline
    _state["pipeline"] = pipeline
    _state["proxies"] = catalogue.load(sorted(glob.glob(os.path.join(source, "Plugins", "*.xml"))))
    folder = tempfile.mkdtemp(prefix="anatomesh-fuzz-", dir="/dev/shm" if os.access("/dev/shm", os.W_OK) else None)
    _state["path"] = os.path.join(folder, "pipeline.xml")
    _state["output"] = os.path.join(folder, "out")
    # Warnings (deprecated property names) go nowhere: the fuzzer's own output stays readable.
    _state["quiet"] = open(os.devnull, "w")


def check(data):
    pipeline = _state["pipeline"]
    with open(_state["path"], "wb") as f:
        f.write(data)
    stderr, sys.stderr = sys.stderr, _state["quiet"]
    try:
        pipeline.Pipeline(_state["path"], variables={"output": _state["output"]}, proxies=_state["proxies"])
    except pipeline.PipelineError:
        pass
    finally:
        sys.stderr = stderr
