"""One run of the filter split among the MPI ranks (issue 7): every rank
computes its piece of a CGAL mesh at a relative epsilon; rank 0 prints one
JSON line (wall-clock seconds of the slowest rank, triangles and grid cells
summed, the reported topology). Driven by run_benchmark.py --ranks.

Usage: mpirun -np N pvbatch --symmetric ranks_benchmark.py <site-packages> <mesh.off> <epsilon>
"""
import json
import sys
import time

sys.path.insert(0, sys.argv[1])
from topologypreserving import vtkOFFReader, vtkTopologyPreservingContour  # noqa: E402
from vtkmodules.vtkCommonCore import vtkDoubleArray  # noqa: E402
from vtkmodules.vtkParallelCore import vtkCommunicator, vtkMultiProcessController  # noqa: E402

controller = vtkMultiProcessController.GetGlobalController()
rank, ranks = controller.GetLocalProcessId(), controller.GetNumberOfProcesses()
reader = vtkOFFReader()
reader.SetFileName(sys.argv[2])
reader.Update()
f = vtkTopologyPreservingContour()
f.SetInputConnection(reader.GetOutputPort())
f.SetTolerance(float(sys.argv[3]))
f.SetMaximumDepth(19)
controller.Barrier()
start = time.perf_counter()
f.UpdatePiece(rank, ranks, 0)
seconds = time.perf_counter() - start
mine = [seconds, f.GetSurfaceOutput().GetNumberOfPolys(), f.GetGridOutput().GetNumberOfCells()]
send, sums, maxima = vtkDoubleArray(), vtkDoubleArray(), vtkDoubleArray()
for v in mine:
    send.InsertNextValue(v)
controller.AllReduce(send, sums, vtkCommunicator.SUM_OP)
controller.AllReduce(send, maxima, vtkCommunicator.MAX_OP)
if rank == 0:
    fd = f.GetSurfaceOutput().GetFieldData()
    print(json.dumps({"ranks": ranks, "seconds": maxima.GetValue(0), "triangles": int(sums.GetValue(1)),
                      "grid_cells": int(sums.GetValue(2)),
                      "components": int(fd.GetArray("Components").GetTuple1(0)),
                      "genus": int(fd.GetArray("Genus").GetTuple1(0)),
                      "guaranteed": int(fd.GetArray("TopologyGuaranteed").GetTuple1(0))}), flush=True)
