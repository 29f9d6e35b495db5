"""tpcontour, the command-line program: every input format (and OBJ files
that crash VTK 9.2's reader), a mesh Boolean asked for explicitly, batches of
files (one surface each, a table, the worst exit status), the outputs it
writes, the JSON report, fractions as tolerances, and the exit codes and
messages on bad input.

Usage: pvpython TestCommandLine.py <tpcontour> <folder with data/meshes> <work folder>
"""
import json
import os
import subprocess
import sys

from vtkmodules.vtkCommonTransforms import vtkTransform
from vtkmodules.vtkFiltersCore import vtkAppendPolyData, vtkCleanPolyData
from vtkmodules.vtkFiltersGeneral import vtkTransformPolyDataFilter
from vtkmodules.vtkFiltersSources import vtkCubeSource, vtkSphereSource
from vtkmodules.vtkIOGeometry import vtkOBJWriter, vtkSTLReader, vtkSTLWriter
from vtkmodules.vtkIOPLY import vtkPLYWriter
from vtkmodules.vtkIOXML import (vtkXMLHyperTreeGridReader, vtkXMLPolyDataReader,
                                 vtkXMLPolyDataWriter)

tpcontour, data, work = sys.argv[1:4]
meshes = os.path.join(data, "data", "meshes")
os.makedirs(work, exist_ok=True)
os.chdir(work)
failures = []


def check(condition, what):
    print(("ok   " if condition else "FAIL ") + what, flush=True)
    if not condition:
        failures.append(what)


def run(*args):
    p = subprocess.run([tpcontour, *args], capture_output=True, text=True,
                       env=dict(os.environ, VTK_SMP_BACKEND_IN_USE="STDThread"))
    return p.returncode, p.stdout, p.stderr


def read_off(name):
    # A minimal OFF parser keeps this test independent of the module under test.
    with open(os.path.join(meshes, name)) as f:
        words = f.read().split()
    assert words[0] == "OFF"
    nv, nf = int(words[1]), int(words[2])
    from vtkmodules.vtkCommonCore import vtkPoints
    from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
    points, polys, i = vtkPoints(), vtkCellArray(), 4
    for _ in range(nv):
        points.InsertNextPoint(float(words[i]), float(words[i + 1]), float(words[i + 2]))
        i += 3
    for _ in range(nf):
        n = int(words[i])
        polys.InsertNextCell(n, [int(w) for w in words[i + 1:i + 1 + n]])
        i += 1 + n
    mesh = vtkPolyData()
    mesh.SetPoints(points)
    mesh.SetPolys(polys)
    return mesh


def write(writer, mesh, name):
    writer.SetInputData(mesh)
    if hasattr(writer, "SetDataModeToBinary"):
        writer.SetDataModeToBinary()  # large appended .vtp files are unreadable here (README)
    writer.SetFileName(name)
    writer.Write()
    return name


# --help documents every option and the exit codes.
code, out, _ = run("--help")
check(code == 0 and all(o in out for o in ("--output", "--grid", "--operation", "--batch", "--output-dir",
                                           "--format", "--grids", "--tolerance", "--absolute-tolerance",
                                           "--max-depth", "--threads", "--json", "1/64", "Exit status",
                                           "worst")),
      "--help documents the options")

# Every input format gives knot1's topology (genus 1), guaranteed.
knot = read_off("knot1.off")
inputs = {
    "off": os.path.join(meshes, "knot1.off"),
    "stl": write(vtkSTLWriter(), knot, "knot1.stl"),
    "obj": write(vtkOBJWriter(), knot, "knot1.obj"),
    "ply": write(vtkPLYWriter(), knot, "knot1.ply"),
    "vtp": write(vtkXMLPolyDataWriter(), knot, "knot1.vtp"),
}
for fmt, path in inputs.items():
    code, out, err = run(path, "-t", "0.03125", "--json", "-o", f"out-{fmt}.vtp")
    report = json.loads(out) if code == 0 else {}
    check(code == 0 and report.get("genus") == 1 and report.get("components") == 1
          and report.get("guaranteed") is True and report.get("closed") is True,
          f"{fmt} input: genus 1, guaranteed ({code}, {err.strip()[:200]})")
    reader = vtkXMLPolyDataReader()
    reader.SetFileName(f"out-{fmt}.vtp")
    reader.Update()
    check(reader.GetOutput().GetNumberOfPolys() == report.get("triangles"),
          f"{fmt} input: the written surface has the reported triangles")

# A Boolean of two files: joint − knot1 moved, genus 9 (CGAL's exact corefinement).
move = vtkTransform()
move.Translate(0.0158, 0.0442, 0.0271)
moved = vtkTransformPolyDataFilter()
moved.SetInputData(knot)
moved.SetTransform(move)
moved.Update()
write(vtkXMLPolyDataWriter(), moved.GetOutput(), "knot1-moved.vtp")
code, out, err = run(os.path.join(meshes, "joint.off"), "knot1-moved.vtp", "--operation", "difference",
                     "-t", "0.03125", "--json", "-o", "difference.stl", "-g", "difference.htg")
report = json.loads(out) if code == 0 else {}
check(code == 0 and report.get("genus") == 9 and report.get("components") == 1,
      f"joint - knot1: genus 9 ({code}, {err.strip()[:200]})")
stl = vtkSTLReader()
stl.SetFileName("difference.stl")
stl.Update()
check(stl.GetOutput().GetNumberOfPolys() == report.get("triangles"), "STL output written")
htg = vtkXMLHyperTreeGridReader()
htg.SetFileName("difference.htg")
htg.Update()
check(htg.GetOutput().GetNumberOfCells() == report.get("grid_cells") and report.get("grid_cells", 0) > 0,
      "grid written")

# A tolerance as a fraction is the same run as its decimal value.
code, out, _ = run(inputs["vtp"], "-t", "1/32", "--json", "-o", "fraction.vtp")
fraction = json.loads(out) if code == 0 else {}
decimal = json.loads(run(inputs["vtp"], "-t", "0.03125", "--json", "-o", "decimal.vtp")[1])
check(code == 0 and fraction.get("absolute_tolerance") == decimal["absolute_tolerance"]
      and fraction.get("triangles") == decimal["triangles"], "-t 1/32 is -t 0.03125")

# Threads: every processor by default, on STDThread even where the environment
# names no backend (ParaView's VTK would run on one); --threads sets the
# number (VTK's STDThread runs at most one per processor),
# VTK_SMP_BACKEND_IN_USE=Sequential runs on one; the same surface on any
# number.
no_backend = {k: v for k, v in os.environ.items() if k != "VTK_SMP_BACKEND_IN_USE"}
threaded = {}
for label, args, env in (("default", [], no_backend), ("1", ["--threads", "1"], no_backend),
                         ("3", ["--threads", "3"], no_backend),
                         ("sequential", ["--threads", "3"], dict(no_backend, VTK_SMP_BACKEND_IN_USE="Sequential"))):
    p = subprocess.run([tpcontour, inputs["off"], "-t", "1/32", "--json", "-o", f"threads-{label}.stl", *args],
                       capture_output=True, text=True, env=env)
    threaded[label] = json.loads(p.stdout) if p.returncode == 0 else {}
check(threaded["default"].get("smp_backend") == "STDThread"
      and threaded["default"].get("threads") == os.cpu_count()
      and threaded["1"].get("threads") == 1 and threaded["3"].get("threads") == min(3, os.cpu_count())
      and threaded["sequential"].get("smp_backend") == "Sequential" and threaded["sequential"].get("threads") == 1,
      "threads: " + ", ".join(f"{k} {v.get('smp_backend')} x {v.get('threads')}" for k, v in threaded.items()))
surfaces = {label: open(f"threads-{label}.stl", "rb").read() for label in threaded}
check(len(set(surfaces.values())) == 1 and len(surfaces["3"]) > 1000, "the same surface on one thread, three, every processor and Sequential")
for bad in ("0", "x", "1.5"):
    code, _, err = run(inputs["off"], "--threads", bad)
    check(code == 1 and "--threads needs an integer" in err, f"--threads {bad} is refused")

# Absolute tolerance and the text report.
code, out, _ = run(inputs["vtp"], "--absolute-tolerance", "0.05", "-o", "abs.vtp")
check(code == 0 and "genus                1" in out and "(tolerance 0.05)" in out,
      "--absolute-tolerance and the text report")

# On a terminal (a pseudo-terminal from util-linux's `script`), a progress bar.
p = subprocess.run(["script", "-qec", f"{tpcontour} {inputs['off']} -t 0.015625 -o bar.vtp", "/dev/null"],
                   capture_output=True, text=True, env=dict(os.environ, VTK_SMP_BACKEND_IN_USE="STDThread"))
frames = [f for f in p.stdout.replace("\r", "\n").split("\n") if f.startswith("[") and "%" in f]
check(p.returncode == 0 and len(frames) > 3 and "#" in frames[-1] and "genus                1" in p.stdout,
      f"progress bar on a terminal ({len(frames)} frames)")
code, out, err = run(inputs["off"], "-t", "0.015625", "-o", "nobar.vtp")
check(code == 0 and "%" not in err, "no progress bar when standard error is not a terminal")

# Issue 14: OpenSCAD's sliver tetrahedron (testdata/scad/3D/issues/issue1089.scad
# as OpenSCAD writes it to STL): 20 long, 1.5e-6 thick. Guaranteed - one
# component, genus 0, embedded, a proven bound - at every tolerance; merging
# points with equal coordinates (vtkCleanPolyData, tolerance 0) keeps them
# all (in double precision: STL's floats would merge points of its two
# sheets, 1e-6 apart at coordinates near 10).
facets = [((-0.249434, -9.94681, 7.66848), (-0.503165, -0.666568, 3.81975), (-0.503165, 8.89648, 0.896037)),
          ((-0.503165, 8.89648, 0.896037), (-0.503165, -10.2296, 6.74347), (-0.249434, -9.94681, 7.66848)),
          ((-0.249434, -9.94681, 7.66848), (-0.503165, -10.2296, 6.74347), (-0.503165, -0.666568, 3.81975)),
          ((-0.503165, -0.666568, 3.81975), (-0.503165, -10.2296, 6.74347), (-0.503165, 8.89648, 0.896037))]
with open("sliver.stl", "w") as f:
    f.write("solid sliver\n")
    for facet in facets:
        f.write("facet normal 0 0 0\nouter loop\n")
        f.writelines(f"vertex {x} {y} {z}\n" for x, y, z in facet)
        f.write("endloop\nendfacet\n")
    f.write("endsolid sliver\n")
for t in ("0.03125", "0.015625", "0.0078125"):
    code, out, err = run("sliver.stl", "-t", t, "--json", "-o", "sliver-out.vtp")
    report = json.loads(out) if code in (0, 2) else {}
    check(code == 0 and report.get("components") == 1 and report.get("genus") == 0
          and report.get("embedded") is True and report.get("outward") is True
          and report.get("hausdorff_bound") is not None,
          f"sliver tetrahedron at {t}: guaranteed, one component, genus 0, embedded ({code}, {err.strip()[:200]})")
    reader = vtkXMLPolyDataReader()
    reader.SetFileName("sliver-out.vtp")
    merged = vtkCleanPolyData()
    merged.SetInputConnection(reader.GetOutputPort())
    merged.SetTolerance(0.0)
    merged.Update()
    check(merged.GetOutput().GetNumberOfPolys() == report.get("triangles")
          and merged.GetOutput().GetNumberOfPoints() == report.get("triangles", 0) // 2 + 2,
          f"sliver tetrahedron at {t}: once points are merged, V = F/2 + 2 (a sphere, no coincident points)")

# The guarantee cannot hold: a self-intersecting mesh (two overlapping spheres) -> exit 2.
a, b = vtkSphereSource(), vtkSphereSource()
b.SetCenter(0.3, 0.1, 0.05)
both = vtkAppendPolyData()
both.AddInputConnection(a.GetOutputPort())
both.AddInputConnection(b.GetOutputPort())
both.Update()
write(vtkSTLWriter(), both.GetOutput(), "crossing.stl")
code, out, err = run("crossing.stl", "-t", "0.03125")
check(code == 2 and "TopologyGuaranteed   0" in out and "self-intersecting" in err,
      f"no guarantee: exit 2 with the reason ({code})")

# Bad input: a clear message and exit 1.
open_sphere = vtkSphereSource()
open_sphere.SetEndTheta(300)
open_sphere.Update()
write(vtkSTLWriter(), open_sphere.GetOutput(), "open.stl")
for args, message in ((["missing.stl"], "no such file"),
                      (["open.stl"], "not a closed surface"),
                      (["knot1.vtp", "--operation", "xor"], "--operation must be"),
                      (["knot1.vtp", "--tolerance", "-1"], "positive number"),
                      (["knot1.vtp", "-o", "out.obj"], "--output must end in"),
                      (["notes.txt"], "no such file"),
                      ([], "no input file")):
    code, _, err = run(*args)
    check(code == 1 and message in err, f"{' '.join(args) or '(no arguments)'}: exit 1, says '{message}'")

# --fill-holes (the filter's FillHoles) closes the open sphere and says so.
code, out, err = run("open.stl", "--fill-holes", "-t", "1/32", "--json", "-o", "filled.vtp")
report = json.loads(out) if code == 0 else {}
check(code == 0 and report.get("components") == 1 and report.get("genus") == 0 and "holes filled" in err,
      f"--fill-holes: the open sphere closed, genus 0, the repair reported ({code}, {err.strip()[:200]})")

# Several inputs are combined only when asked: without --operation or --batch, exit 1.
code, _, err = run("knot1.vtp", "knot1.stl")
check(code == 1 and "--operation" in err and "--batch" in err,
      f"two inputs without --operation or --batch: exit 1, names both ({err.strip()[:200]})")
for args, message in ((["--batch", "knot1.vtp", "-o", "x.vtp"], "--batch writes one surface per input"),
                      (["--batch", "knot1.vtp", "knot1.stl", "--operation", "union"], "--batch writes one"),
                      (["knot1.vtp", "--grids"], "belong to --batch"),
                      (["--batch", "knot1.vtp", "--format", "obj"], "--format must be vtp or stl"),
                      (["knot1.vtp", "-t", "1/0"], "positive number or fraction"),
                      (["knot1.vtp", "-t", "1/"], "positive number or fraction"),
                      ([work], "is a folder: --batch")):
    code, _, err = run(*args)
    check(code == 1 and message in err, f"{' '.join(args)}: exit 1, says '{message}' ({err.strip()[:200]})")

# VTK's own vtkOBJWriter writes a cube's texture coordinates with face
# indices past the last "vt" line; VTK 9.2's OBJ reader then corrupts the
# heap (exit 134). tpcontour reads the geometry: the cube, guaranteed.
cube_source = vtkCubeSource()
cube_source.Update()
write(vtkOBJWriter(), cube_source.GetOutput(), "textured-cube.obj")
with open("textured-cube.obj") as f:
    lines = f.read().splitlines()
texture_lines = sum(1 for line in lines if line.startswith("vt "))
texture_refs = [int(corner.split("/")[1]) for line in lines if line.startswith("f ") for corner in line.split()[1:]]
check(max(texture_refs) > texture_lines,
      f"the cube's OBJ names texture coordinate {max(texture_refs)} of {texture_lines} (the case that crashed)")
code, out, err = run("textured-cube.obj", "-t", "1/16", "--json", "-o", "textured-cube.vtp")
report = json.loads(out) if code == 0 else {}
check(code == 0 and report.get("components") == 1 and report.get("genus") == 0 and report.get("guaranteed"),
      f"vtkOBJWriter's textured cube: read, one component, genus 0, guaranteed ({code}, {err.strip()[:200]})")
# --split-creases (the filter's SplitCreases): the same cube, its points split
# along its edges (more points, SurfacePointId mapping them back to the
# unsplit surface's), the same triangles.
code, out, err = run("textured-cube.obj", "-t", "1/16", "--split-creases", "-q", "-o", "split-cube.vtp")
plain, split = vtkXMLPolyDataReader(), vtkXMLPolyDataReader()
plain.SetFileName("textured-cube.vtp")
split.SetFileName("split-cube.vtp")
plain.Update()
split.Update()
ids = split.GetOutput().GetPointData().GetArray("SurfacePointId") if code == 0 else None
check(ids is not None and plain.GetOutput().GetPointData().GetArray("SurfacePointId") is None
      and split.GetOutput().GetNumberOfPolys() == plain.GetOutput().GetNumberOfPolys()
      and split.GetOutput().GetNumberOfPoints() > plain.GetOutput().GetNumberOfPoints()
      and max(ids.GetValue(i) for i in range(ids.GetNumberOfTuples())) + 1 == plain.GetOutput().GetNumberOfPoints(),
      f"--split-creases: the cube's points split along its edges ({code}, {err.strip()[:200]})")
# --decimate (the filter's Decimate, CertifiedDecimation.h): knot1 at 1/64,
# the same topology, still guaranteed and within the tolerance, on at least
# 4 times fewer triangles (measured 2 232 -> 274).
code, out, err = run(os.path.join(meshes, "knot1.off"), "-t", "1/64", "--json", "-o", "knot1-plain.vtp")
plain_report = json.loads(out) if code == 0 else {}
code, out, err = run(os.path.join(meshes, "knot1.off"), "-t", "1/64", "--decimate", "--json", "-o", "knot1-decimated.vtp")
decimated = json.loads(out) if code == 0 else {}
check(code == 0 and decimated.get("guaranteed") and decimated.get("genus") == 1 and decimated.get("components") == 1
      and decimated.get("hausdorff_bound", 1e9) <= decimated.get("absolute_tolerance", 0) * (1 + 1e-9)
      and 4 * decimated.get("triangles", 1e9) < plain_report.get("triangles", 0),
      f"--decimate: knot1 guaranteed, genus 1, within the tolerance, {plain_report.get('triangles')} -> "
      f"{decimated.get('triangles')} triangles ({code}, {err.strip()[:200]})")
with open("bad-reference.obj", "w") as f:
    f.write("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 2 4\nf 1/1 3/1 9/1\nf 2 3 4\n")
code, _, err = run("bad-reference.obj")
check(code == 1 and "line 7" in err and "vertex 9" in err,
      f"an OBJ face naming a missing vertex: exit 1, names the line ({err.strip()[:200]})")

# --batch: one surface per input (a folder stands for its meshes), a table,
# the worst exit status; a file that fails does not stop the batch.
os.makedirs("batch", exist_ok=True)
for name in ("knot1.off", "textured-cube.obj", "crossing.stl", "open.stl"):
    src = inputs["off"] if name == "knot1.off" else name
    with open(src, "rb") as f_in, open(os.path.join("batch", name), "wb") as f_out:
        f_out.write(f_in.read())
code, out, err = run("--batch", "batch", "-t", "1/32", "--output-dir", "batch-out", "--grids", "--format", "stl")
rows = {line.split()[0]: line.split() for line in out.splitlines() if line.startswith("batch/")}
check(code == 1 and sorted(rows) == sorted(f"batch/{n}" for n in ("knot1.off", "textured-cube.obj",
                                                                  "crossing.stl", "open.stl")),
      f"a batch of a folder: exit 1 (one input failed), one row per file ({code}, {out.strip()[-300:]})")
check([rows.get(f"batch/{n}", [None, None])[1] for n in ("knot1.off", "textured-cube.obj", "crossing.stl",
                                                          "open.stl")] == ["0", "0", "2", "1"],
      "the table gives each input its own exit status")
check(rows.get("batch/knot1.off", [""] * 6)[3:6] == ["1", "1", "yes"],
      "the table gives knot1 one component, genus 1, guaranteed")
check("4 inputs: 2 guaranteed, 1 without the guarantee, 1 failed; exit status 1" in out,
      "the table's summary counts each outcome")
check("not a closed surface" in err, "the failed input's message goes to standard error")
check(all(os.path.exists(os.path.join("batch-out", f"{stem}-tpc.{ext}"))
          for stem in ("knot1", "textured-cube", "crossing") for ext in ("stl", "htg"))
      and not os.path.exists(os.path.join("batch-out", "open-tpc.stl")),
      "each readable input's surface and grid written to --output-dir")
code, out, _ = run("--batch", "--json", "-q", "batch/knot1.off", "batch/crossing.stl", "-t", "1/32",
                   "--output-dir", "batch-json")
reports = json.loads(out) if out.strip().startswith("[") else []
check(code == 2 and [r.get("exit_status") for r in reports] == [0, 2] and reports[0].get("genus") == 1
      and reports[0].get("surface") == os.path.join("batch-json", "knot1-tpc.vtp"),
      f"a batch without failures but one unguaranteed: exit 2, JSON array of reports ({code})")
code, out, _ = run("--batch", "-q", "batch/knot1.off", "-t", "1/32", "--output-dir", "batch-good")
check(code == 0 and "1 input: 1 guaranteed" in out, "a batch of guaranteed inputs: exit 0")
os.makedirs("other", exist_ok=True)
write(vtkSTLWriter(), knot, os.path.join("other", "knot1.stl"))
code, _, err = run("--batch", "batch/knot1.off", "other/knot1.stl")
check(code == 1 and "both be written to knot1-tpc.vtp" in err,
      f"a batch whose inputs share a name: exit 1 before any run ({err.strip()[:200]})")

if failures:
    sys.exit(f"{len(failures)} check(s) failed")
print("all command-line checks passed")
