"""The run report: ``report.html`` beside a run's outputs, with pictures rendered off-screen.

``anatomesh report DIR`` (or ``anatomesh run ... --report``) reads what the run wrote (the files that
``anatomesh-run.json`` lists) and draws what it finds: the mesh cut through by region, the remeshed
surface by its distance to the smoothed one, the quality histogram beside the paper's Table 1, the
activation map, the body-surface potential at one time, and the 12 leads on one shared mV scale.
"""
from .page import write_report

__all__ = ["write_report"]
