"""Topology preserving contouring (Varadhan et al., SGP 2004) as a VTK filter.

    from topologypreserving import vtkTopologyPreservingContour

Needs ParaView's VTK Python modules (run under pvpython/pvbatch, or put
ParaView's site-packages on sys.path).
"""
from .vtkTopologyPreservingFilters import *  # noqa: F401,F403
