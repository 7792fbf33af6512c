"""The README's figures, recorded by the tests that check them: with ANATOMESH_FIGURES set to a file,
``record`` appends one JSON line per figure (the test's id, the figure's name, value, unit, and the bar
the test holds it to); ``scripts/figures.py`` runs those tests and gathers the lines into
docs/figures.json. Without the variable it does nothing."""
import json
import os


def record(test, name, value, unit="", bar=None):
    """bar: the number the test holds the figure to, or [low, high] for a range it must lie in (a
    clinical norm, not a regression bar)."""
    path = os.environ.get("ANATOMESH_FIGURES")
    if not path:
        return
    line = {"test": test.id(), "name": name, "value": value, "unit": unit, "bar": bar}
    with open(path, "a") as f:
        f.write(json.dumps(line) + "\n")
