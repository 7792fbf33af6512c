"""Anatomesh: CT/MRI scan -> conforming multi-region tetrahedral mesh -> cardiac simulation.

Every filter is a VTK algorithm (class names start with ``am``) usable in ordinary VTK Python
pipelines::

    import anatomesh
    src = anatomesh.amThoraxPhantomSource()
    src.SetSpacing(2, 2, 2)
    src.Update()
    labels = src.GetOutput(1)

``anatomesh.pipeline`` runs pipeline XML files (also the ``anatomesh`` command), and
``anatomesh.catalogue`` reads the filter catalogue (the ParaView server-manager XML).
"""
import importlib as _importlib
import os as _os
import pkgutil as _pkgutil

# The wrapped modules import ParaView's (or VTK's) vtkmodules themselves.
__version__ = "0.1.0"

_here = _os.path.dirname(__file__)
for _info in sorted(_pkgutil.iter_modules([_here]), key=lambda m: m.name):
    if _info.name.startswith("Anatomesh"):
        _module = _importlib.import_module("." + _info.name, __name__)
        for _name in dir(_module):
            if _name.startswith("am"):
                globals()[_name] = getattr(_module, _name)
del _info, _module, _name
