"""pvbatch side of `anatomesh state` (paraview_state.py): load the Anatomesh plugin, check that it
defines every Anatomesh proxy the state holds, load the state and update each source it registers.
Lines starting "STATE: " are for the command; exit 3: the plugin or a proxy definition is missing,
4: the state loaded but lost sources."""
import json
import sys

from paraview import servermanager as sm
from paraview.simple import GetSources, LoadDistributedPlugin, LoadPlugin, LoadState


def say(text):
    print("STATE: " + text)
    sys.stdout.flush()


def load_plugin(plugin, name):
    """None, or why the plugin could not be loaded."""
    try:
        if plugin:
            LoadPlugin(plugin, remote=False, ns={})
        else:
            LoadDistributedPlugin(name, remote=False, ns={})
    except Exception as e:  # ParaView raises RuntimeError with its own words
        return str(e).strip() or type(e).__name__
    return None


def main():
    path, needed = sys.argv[1], json.loads(sys.argv[2])
    name, plugin = needed["name"], needed["plugin"]
    proxies = [tuple(p) for p in needed["proxies"]]
    if proxies:
        why = load_plugin(plugin, name)
        if why:
            say("needs the %s ParaView plugin for %d proxy type(s) (%s), which ParaView cannot load (%s): install "
                "Anatomesh (its plugin is then in ParaView's plugin list) or set ANATOMESH_PLUGIN to its %s.so"
                % (name, len(proxies), ", ".join(t for _, t in proxies), why or "not found", name))
            sys.exit(3)
        definitions = sm.ProxyManager().SMProxyManager.GetProxyDefinitionManager()
        missing = [t for g, t in proxies if not definitions.HasDefinition(g, t)]
        if missing:
            say("needs %s, which the %s plugin loaded here (%s) does not define: the state comes from another "
                "version of the plugin" % (", ".join(missing), name, plugin or name))
            sys.exit(3)
    LoadState(path)
    loaded = {key[0]: source for key, source in GetSources().items()}
    lost = [s for s in needed["sources"] if s not in loaded]
    if lost:
        say("the state loaded without its source(s) %s" % ", ".join(lost))
        sys.exit(4)
    for label in sorted(loaded):
        source = loaded[label]
        source.UpdatePipeline()
        info = source.GetDataInformation()
        say("%s (%s): %d points, %d cells" % (label, source.GetXMLName(), info.GetNumberOfPoints(),
                                            info.GetNumberOfCells()))


main()
