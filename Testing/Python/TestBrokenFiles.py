"""tpcontour on the broken and odd STL files of Debian's openscad-testing-data
(OpenSCAD's own import tests: empty, unparseable, invalid, open,
self-intersecting and degenerate meshes). Each gets its defined outcome:
exit 1 with one message naming the file and what is wrong, or a closed
manifold surface (exit 0 when guaranteed, 2 when the input violates the
method's assumptions). Never a crash, never silence.

Usage: pvpython TestBrokenFiles.py <tpcontour> <work folder>
"""
import glob
import os
import subprocess
import sys

from vtkmodules.vtkIOXML import vtkXMLPolyDataReader

from TopologyChecks import measure

tpcontour, work = sys.argv[1:3]
# The folders of openscad-testing-data only: where Debian's openscad is
# installed too, /usr/share/openscad/examples holds OpenSCAD's example STLs.
root = "/usr/share/openscad"
folders = ("testdata", "regression")
os.makedirs(work, exist_ok=True)
failures = []


def check(condition, what):
    print(("ok   " if condition else "FAIL ") + what, flush=True)
    if not condition:
        failures.append(what)


# File name -> (exit code, text the message must contain).
READABLE = (0, "")
OPEN = (1, "is not a closed surface")
SELF_INTERSECTING = (2, "violates the method's assumptions")
expected = {
    "stl-export-expected.stl": READABLE,
    "cube.stl": READABLE,
    "cube2.stl": READABLE,
    "import.stl": READABLE,
    "import_bin.stl": READABLE,
    "import_bin_solid.stl": READABLE,
    "issue1580-back-to-back.stl": (0, "degenerate triangles dropped"),
    "issue1580-back-to-back2.stl": OPEN,
    "issue1580-zero-area-triangle.stl": OPEN,
    "issue945f.stl": OPEN,
    "adns2610_dev_circuit_inv.stl": OPEN,
    "issue945e.stl": SELF_INTERSECTING,
    "bad-stl-pcbvicebar.stl": SELF_INTERSECTING,
    "bad-stl-tardis.stl": SELF_INTERSECTING,
    "bad-stl-wing.stl": SELF_INTERSECTING,
    "empty.stl": (1, "Premature EOF"),
    "empty2.stl": (1, "holds no triangles"),
    "invalidvertex.stl": (1, "line 89"),
    "toomanyvertices.stl": (1, "Parse error"),
    "unparseable.stl": (1, "Parse error"),
}

files = sorted(f for folder in folders for f in glob.glob(os.path.join(root, folder, "**", "*.stl"), recursive=True))
if not files:
    sys.exit(f"no STL files under {root}: install Debian's openscad-testing-data (scripts/setup.sh does)")
check(sorted(os.path.basename(f) for f in files) == sorted(expected),
      f"the package holds the {len(expected)} files this test knows")

for path in files:
    name = os.path.basename(path)
    if name not in expected:
        continue
    code, text = expected[name]
    out = os.path.join(work, name.replace(".stl", ".vtp"))
    if os.path.exists(out):
        os.remove(out)
    p = subprocess.run([tpcontour, "--quiet" if code == 1 else "--json", path, "-o", out],
                       capture_output=True, text=True, timeout=600,
                       env=dict(os.environ, VTK_SMP_BACKEND_IN_USE="STDThread"))
    check(p.returncode == code, f"{name}: exit {p.returncode} (expected {code})")
    if code == 1:
        lines = [line for line in p.stderr.splitlines() if line.strip()]
        check(len(lines) == 1 and lines[0].startswith("tpcontour: ") and name in lines[0] and text in lines[0],
              f"{name}: one message naming the file and saying '{text}': {p.stderr.strip()!r}")
        check(not os.path.exists(out), f"{name}: no output written")
        continue
    check(text in p.stderr, f"{name}: the warnings say '{text}'")
    reader = vtkXMLPolyDataReader()
    reader.SetFileName(out)
    reader.Update()
    surface = reader.GetOutput()
    m = measure(surface)
    check(surface.GetNumberOfCells() > 0 and m["boundary"] == 0 and m["nonmanifold"] == 0,
          f"{name}: a closed manifold surface ({surface.GetNumberOfCells()} triangles)")

print(f"{len(failures)} failure(s)")
sys.exit(1 if failures else 0)
