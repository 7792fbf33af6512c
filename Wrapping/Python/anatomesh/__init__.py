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
``anatomesh.keep_freed_memory()``, called first, gives a script the allocator setting the command
starts with (large arrays reused from filter to filter instead of mapped afresh: see
``anatomesh.allocator``).
"""
# The wrapped modules import ParaView's (or VTK's) vtkmodules themselves.
from .AnatomeshFiltersCleaning import amMorphologyCleaning
from .AnatomeshFiltersSegmentation import (
    amCardiacLandmarks, amIntensityClassifier, amLabelOverlap, amSnakeSegmentation, amTorsoSegmentation)
from .AnatomeshFiltersSimulation import (
    amFitzHughNagumoSolver,
    amHeartSolver,
    amLeadFieldECG,
    amReactionEikonalSolver,
    amTorsoPotential,
    amVentricularFibres,
)
from .AnatomeshFiltersSources import amSeedPointsSource, amSyntheticAtlasSource, amThoraxPhantomSource
from .AnatomeshFiltersSurface import (
    amCurvatureMetric,
    amLabelSurface,
    amMetricRemeshing,
    amSurfaceDistance,
    amSurfaceSmoothing,
)
from .AnatomeshFiltersVolume import amLabelMapTetrahedralize, amMeshQuality, amTetrahedralize
from .AnatomeshIOImage import amImageReader, amImageWriter
from .AnatomeshIOMesh import (
    amConcurrentXMLWriter,
    amGmshWriter,
    amMeditReader,
    amMeditWriter,
    amOpenCARPReader,
    amOpenCARPWriter,
    amXdmfWriter,
)
from .allocator import keep_freed_memory

__version__ = "0.2.0"

__all__ = [
    "amCardiacLandmarks",
    "amConcurrentXMLWriter",
    "amCurvatureMetric",
    "amFitzHughNagumoSolver",
    "amHeartSolver",
    "amGmshWriter",
    "amImageReader",
    "amImageWriter",
    "amIntensityClassifier",
    "amLabelMapTetrahedralize",
    "amLabelOverlap",
    "amLabelSurface",
    "amLeadFieldECG",
    "amMeditReader",
    "amMeditWriter",
    "amMeshQuality",
    "amMetricRemeshing",
    "amMorphologyCleaning",
    "amOpenCARPReader",
    "amOpenCARPWriter",
    "amReactionEikonalSolver",
    "amSeedPointsSource",
    "amSnakeSegmentation",
    "amSurfaceDistance",
    "amSurfaceSmoothing",
    "amSyntheticAtlasSource",
    "amTetrahedralize",
    "amThoraxPhantomSource",
    "amTorsoPotential",
    "amTorsoSegmentation",
    "amVentricularFibres",
    "amXdmfWriter",
    "keep_freed_memory",
]
