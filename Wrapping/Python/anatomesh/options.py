"""What the run and batch commands read alike from their command lines."""
import sys


def variables_of(items):
    """The --set NAME=VALUE items as a dict, or None (with a message) when one has no '='."""
    variables = {}
    for item in items or []:
        if "=" not in item:
            sys.stderr.write("anatomesh: error: --set takes NAME=VALUE, got %r\n" % item)
            return None
        k, v = item.split("=", 1)
        variables[k] = v
    return variables
