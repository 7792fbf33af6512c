#!/usr/bin/python3
"""The anatomesh Python package without import cycles: every module's imports of the package's own
modules (at the top or inside a function alike) form a graph with no cycle. Prints a cycle found
and exits 1; exits 0 when there is none. Usage: scripts/check-import-cycles.py
"""
import ast
import os
import sys

PACKAGE = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "Wrapping", "Python", "anatomesh")


def module_name(path):
    rel = os.path.relpath(path, PACKAGE)[:-3].replace(os.sep, ".")
    return rel[:-len(".__init__")] if rel.endswith(".__init__") else ("" if rel == "__init__" else rel)


def resolve(current, is_package, level, name):
    """The package module an import names (relative imports resolved), or None outside the package."""
    if level == 0:
        if name == "anatomesh" or name.startswith("anatomesh."):
            return name[len("anatomesh."):] if name != "anatomesh" else ""
        return None
    parts = current.split(".") if current else []
    if not is_package:
        parts = parts[:-1]
    parts = parts[:len(parts) - (level - 1)] if level > 1 else parts
    return ".".join(parts + ([name] if name else []))


def graph():
    edges = {}
    modules = set()
    for folder, _, names in os.walk(PACKAGE):
        for n in names:
            if n.endswith(".py"):
                modules.add(module_name(os.path.join(folder, n)))
    for folder, _, names in os.walk(PACKAGE):
        for n in sorted(names):
            if not n.endswith(".py"):
                continue
            path = os.path.join(folder, n)
            me = module_name(path)
            is_package = n == "__init__.py"
            with open(path) as f:
                tree = ast.parse(f.read(), path)
            targets = set()
            for node in ast.walk(tree):
                if isinstance(node, ast.ImportFrom):
                    base = resolve(me, is_package, node.level, node.module or "")
                    if base is None:
                        continue
                    for alias in node.names:  # "from . import cli" names a module
                        sub = (base + "." if base else "") + alias.name
                        targets.add(sub if sub in modules else base)
                elif isinstance(node, ast.Import):
                    for alias in node.names:
                        t = resolve(me, is_package, 0, alias.name)
                        if t is not None:
                            targets.add(t)
            # A module importing its own package's __init__ (for the compiled classes) is not a cycle
            # through the package's modules.
            edges[me] = sorted(t for t in targets if t in modules and t != me and t != "")
    return edges


def find_cycle(edges):
    state, stack = {}, []

    def visit(m):
        state[m] = 1
        stack.append(m)
        for t in edges.get(m, []):
            if state.get(t) == 1:
                return stack[stack.index(t):] + [t]
            if t not in state:
                found = visit(t)
                if found:
                    return found
        state[m] = 2
        stack.pop()
        return None

    for m in sorted(edges):
        if m not in state:
            found = visit(m)
            if found:
                return found
    return None


if __name__ == "__main__":
    edges = graph()
    cycle = find_cycle(edges)
    if cycle:
        print("import cycle: " + " -> ".join(cycle))
        sys.exit(1)
    print("%d modules, no import cycle" % len(edges))
