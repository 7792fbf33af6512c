"""`anatomesh state FILE.pvsm`: a ParaView state that holds Anatomesh proxies, checked and loaded.

ParaView's own LoadState drops every proxy whose definition it lacks with a log line and goes on
(exit 0): a state saved with the plugin and opened without it silently loses its pipeline. Here the
state's Anatomesh proxies are listed from the file itself, the plugin is loaded (ANATOMESH_PLUGIN,
else by name from ParaView's plugin list, where the install puts it), and a state that needs a
proxy the plugin does not define, or a plugin ParaView cannot load, is an error naming both. Then
the state is loaded in pvbatch and every source it registers updated (or opened in the GUI)."""
import json
import os
import shutil
import subprocess
import sys
import xml.etree.ElementTree as ET

PLUGIN_NAME = "Anatomesh"
# Exit codes of the pvbatch side (state_load.py).
PLUGIN_MISSING = 3
PROXIES_LOST = 4


class StateError(Exception):
    pass


def read_state(path):
    """The state's Anatomesh proxy types [(group, type)] and the names it registers as sources."""
    try:
        root = ET.parse(path).getroot()
    except ET.ParseError as e:
        raise StateError("%s: not a ParaView state: %s" % (path, e))
    except OSError as e:
        raise StateError("%s: %s" % (path, e.strerror or e))
    state = root if root.tag == "ServerManagerState" else root.find("ServerManagerState")
    if state is None:
        raise StateError("%s: not a ParaView state: no ServerManagerState element (root <%s>)" % (path, root.tag))
    ours = sorted({(p.get("group"), p.get("type")) for p in state.iter("Proxy")
                   if (p.get("type") or "").startswith(PLUGIN_NAME)})
    sources = []
    for collection in state.iter("ProxyCollection"):
        if collection.get("name") == "sources":
            sources += [item.get("name") for item in collection.iter("Item")]
    return ours, sources


def _pvbatch():
    exe = os.environ.get("PVBATCH") or shutil.which("pvbatch")
    if not exe:
        raise StateError("pvbatch not found: ParaView (Debian's paraview package) is needed to load a state")
    return exe


def load(path, plugin=None):
    """Loads the state in pvbatch; returns the lines it printed about each source. Raises StateError
    naming the plugin when ParaView cannot rebuild the state's Anatomesh proxies."""
    ours, sources = read_state(path)
    plugin = plugin or os.environ.get("ANATOMESH_PLUGIN") or ""
    script = os.path.join(os.path.dirname(os.path.abspath(__file__)), "state_load.py")
    needed = json.dumps({"proxies": ours, "sources": sources, "plugin": plugin, "name": PLUGIN_NAME})
    child = subprocess.run([_pvbatch(), "--force-offscreen-rendering", script, os.path.abspath(path), needed],
                           capture_output=True, text=True)
    lines = [line[len("STATE: "):] for line in child.stdout.splitlines() if line.startswith("STATE: ")]
    if child.returncode in (PLUGIN_MISSING, PROXIES_LOST):
        raise StateError("%s: %s" % (path, " ".join(lines)))
    if child.returncode != 0:
        tail = (child.stderr or child.stdout).strip().splitlines()[-3:]
        raise StateError("%s: pvbatch failed (exit %d): %s" % (path, child.returncode, " | ".join(tail)))
    return lines


def main(args):
    try:
        lines = load(args.state, args.plugin)
    except StateError as e:
        sys.stderr.write("anatomesh: error: %s\n" % e)
        return 1
    for line in lines:
        print(line)
    if args.open:
        paraview = shutil.which("paraview")
        if not paraview:
            sys.stderr.write("anatomesh: error: the ParaView GUI (paraview) is not installed\n")
            return 1
        plugin = args.plugin or os.environ.get("ANATOMESH_PLUGIN") or PLUGIN_NAME
        os.execv(paraview, [paraview, "--plugins=" + plugin, "--state=" + os.path.abspath(args.state)])
    return 0
