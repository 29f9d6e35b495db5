#!/usr/bin/env python3
"""The speed benchmark: this filter (1 and 2 threads) vs VTK's recipe
(vtkSampleFunction -> vtkFlyingEdges3D) vs OpenVDB (mesh -> level set ->
level-set CSG -> volumeToMesh), at the same finest cell size, on four scenes
and three epsilons. Every run is its own process (tpc_benchmark), so its peak
memory is its own. Prints, side by side: seconds, peak memory, triangles, grid
cells, whether components and genus are right; then the ratios and how time
grows from epsilon to epsilon/2.

    python3 Testing/Benchmarks/run_benchmark.py            # the full run (~30 min)
    python3 Testing/Benchmarks/run_benchmark.py --quick    # 1/64 and 1/128 only
    python3 Testing/Benchmarks/run_benchmark.py --limits   # memory budget and abort latency
    python3 Testing/Benchmarks/run_benchmark.py --ranks    # 1 vs 2 MPI ranks
    python3 Testing/Benchmarks/run_benchmark.py --errors [--before OLD/tpc_benchmark]
        # issue 17: triangles, certified and measured error vs OpenVDB
    python3 Testing/Benchmarks/run_benchmark.py --compare OLD/tpc_benchmark [--geometry-only]
        # this build's filter vs another build's, interleaved: seconds and
        # whether the outputs are identical (a refactoring keeps them; with
        # --geometry-only, everything but the certified errors)
    ... --scenes plate-ellipsoids --epsilons 64,128        # a subset

The filter runs first; the others get its surface-cell edge as their spacing.
"""
import argparse
import json
import os
import platform
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
SCENES = ["armadillo", "turbine", "armadillo-cavities", "plate-ellipsoids"]
# Untimed scenes that --compare also checks: the demo's two and a mesh Boolean.
CHECK_SCENES = ["demo-csg", "couplingdown", "joint-minus-knot"]
METHODS = [("tpc", 1), ("tpc", 2), ("vtk", 2), ("vdb", 2)]
LABEL = {("tpc", 1): "filter, 1 thread", ("tpc", 2): "filter, 2 threads",
         ("vtk", 2): "VTK sample+FE, 2 thr", ("vdb", 2): "OpenVDB, 2 threads"}


# The memory budget the README documents: a run's peak memory grows by at
# most this much over what the inputs take, for MaximumNumberOfCells = N.
BUDGET_BASE_MIB = 100
BUDGET_BYTES_PER_CELL = 800
LIMITS = [1_000_000, 2_500_000, 5_000_000, 10_000_000]


def budget_mib(max_cells):
    return BUDGET_BASE_MIB + BUDGET_BYTES_PER_CELL * max_cells / 2**20


# Abort requests at these fractions of the progress bar: inputs [0, 0.1],
# subdivision [0.1, 0.85], extraction [0.85, 0.95], grid output [0.95, 1].
ABORT_POINTS = [("inputs", 0.01), ("subdivision", 0.3), ("subdivision", 0.8), ("extraction", 0.9),
                ("grid output", 0.96)]


def run(program, meshes, method, scene, epsilon, threads, cell_size, timeout, max_cells=None, abort_at=None,
        fingerprint=False, adaptivity=None, measure=False, decimate=False):
    cmd = [program, "--method", method, "--scene", scene, "--epsilon", repr(epsilon),
           "--threads", str(threads), "--meshes", meshes]
    if fingerprint:
        cmd += ["--fingerprint", "geometry" if fingerprint == "geometry" else "1"]
    if adaptivity:
        cmd += ["--adaptivity", repr(adaptivity)]
    if measure:
        cmd += ["--measure", "1"]
    if decimate:
        cmd += ["--decimate", "1"]
    if cell_size:
        cmd += ["--cell-size", repr(cell_size)]
    if max_cells:
        cmd += ["--max-cells", str(max_cells)]
    if abort_at:
        cmd += ["--abort-at", repr(abort_at)]
    env = dict(os.environ, VTK_SMP_BACKEND_IN_USE="STDThread")
    try:
        done = subprocess.run(cmd, capture_output=True, text=True, env=env, timeout=timeout)
    except subprocess.TimeoutExpired:
        return {"error": f"stopped after {timeout} s", "timeout": timeout}
    lines = [line for line in done.stdout.splitlines() if line.startswith("{")]
    if done.returncode != 0 or not lines:
        why = (done.stderr.strip().splitlines() or [""])[-1][:50]
        return {"error": f"exit {done.returncode} {why}".strip()}
    return json.loads(lines[-1])


def machine():
    cpu = "?"
    try:
        with open("/proc/cpuinfo") as f:
            cpu = next(line.split(":", 1)[1].strip() for line in f if line.startswith("model name"))
    except (OSError, StopIteration):
        pass
    mem = os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES") / 2**30
    return f"{cpu}, {os.cpu_count()} cores, {mem:.0f} GiB, {platform.platform()}"


def topology(r):
    if "error" in r:
        return r["error"]
    mark = "right" if r["topology_right"] else "WRONG"
    return f"{mark} ({r['components']} comp, genus {r['genus']}{'' if r['closed_manifold'] else ', open'})"


def table(rows):
    widths = [max(len(str(row[i])) for row in rows) for i in range(len(rows[0]))]
    for n, row in enumerate(rows):
        print("  " + "  ".join(str(c).rjust(w) if i else str(c).ljust(w) for i, (c, w) in enumerate(zip(row, widths))))
        if n == 0:
            print("  " + "  ".join("-" * w for w in widths))


def seconds(r):
    """A run's seconds; a run stopped by the time limit counts as at least the limit."""
    return r.get("seconds") or r.get("timeout")


def ratio(a, b, at_least=False):
    if not a or not b:
        return "-"
    return (">" if at_least else "") + f"{a / b:.2f}"


def limits(a):
    """MaximumNumberOfCells bounds time and memory: armadillo at 1/2048 of its
    diagonal needs tens of millions of cells; each run stops at the limit.
    Prints each run's peak memory next to the documented budget."""
    print("Machine:", machine())
    print(f"\nLimits: armadillo at epsilon 1/2048, 2 threads; budget = {BUDGET_BASE_MIB} MiB + "
          f"{BUDGET_BYTES_PER_CELL} bytes x MaximumNumberOfCells")
    rows = [["MaximumNumberOfCells", "grid cells", "seconds", "peak MiB", "budget MiB", "bytes per cell",
             "within budget"]]
    over = []
    for n in LIMITS:
        r = run(a.program, a.meshes, "tpc", "armadillo", 1.0 / 2048, 2, None, 4 * 3600, max_cells=n)
        if "error" in r:
            rows.append([f"{n:,}", "-", "-", "-", f"{budget_mib(n):.0f}", "-", r["error"]])
            over.append(n)
            continue
        within = r["peak_mib"] <= budget_mib(n) and r["grid_cells"] <= n
        over += [] if within else [n]
        rows.append([f"{n:,}", f"{r['grid_cells']:,}", f"{r['seconds']:.1f}", f"{r['peak_mib']:.0f}",
                     f"{budget_mib(n):.0f}", f"{r['peak_mib'] * 2**20 / r['grid_cells']:.0f}",
                     "yes" if within else "NO"])
    table(rows)

    print("\nAbort: armadillo at epsilon 1/1024, 2 threads; the longest time between two progress reports "
          "(the filter checks Abort at each), then an abort requested at points of each stage")
    r = run(a.program, a.meshes, "tpc", "armadillo", 1.0 / 1024, 2, None, 3600)
    if "error" in r:
        print("  run failed:", r["error"])
        return 1
    print(f"  whole run {r['seconds']:.1f} s, {r['grid_cells']:,} cells; longest gap between progress reports "
          f"{r['longest_progress_gap_s']:.3f} s (from progress {r['longest_progress_gap_at']:.3f})")
    rows = [["stage", "abort at", "seconds to the request", "latency s"]]
    for stage, at in ABORT_POINTS:
        r = run(a.program, a.meshes, "tpc", "armadillo", 1.0 / 1024, 2, None, 3600, abort_at=at)
        ok = "error" not in r
        rows.append([stage, f"{at:.2f}", f"{r['seconds'] - r['abort_latency_s']:.2f}" if ok else "-",
                     f"{r['abort_latency_s']:.3f}" if ok else r["error"]])
    table(rows)
    if over:
        print("\nOver the budget at MaximumNumberOfCells =", over)
        return 1
    return 0


def ranks(a):
    """The filter split among MPI ranks (issue 7) next to one rank: armadillo
    and turbine at 1/64 and 1/128, 1 rank x 1 thread, 2 ranks x 1 thread,
    1 rank x 2 threads (the machine has 2 cores)."""
    print("Machine:", machine())
    script = os.path.join(HERE, "ranks_benchmark.py")
    site = os.path.join(HERE, "../../build/lib/python3/site-packages")
    configs = [(1, 1), (2, 1), (1, 2)]
    rows = [["scene", "epsilon"] + [f"{n} rank{'s' if n > 1 else ''} x {t} thr" for n, t in configs] +
            ["2 ranks / 1 rank", "topology (2 ranks)"]]
    failed = False
    for scene, off in (("armadillo", "armadillo.off"), ("turbine", "turbine.off")):
        for d in (64, 128):
            results = []
            for n, threads in configs:
                cmd = ["mpirun", "--allow-run-as-root", "--oversubscribe", "-np", str(n), "pvbatch", "--symmetric",
                       script, site, os.path.join(a.meshes, off), repr(1.0 / d)]
                env = dict(os.environ, VTK_SMP_BACKEND_IN_USE="STDThread", VTK_SMP_MAX_THREADS=str(threads))
                done = subprocess.run(cmd, capture_output=True, text=True, env=env, timeout=3600)
                lines = [line for line in done.stdout.splitlines() if line.startswith("{")]
                results.append(json.loads(lines[-1]) if lines else {"error": f"exit {done.returncode}"})
                print(f"  ran {scene} 1/{d} {n} rank(s) x {threads} thread(s)", file=sys.stderr, flush=True)
            ok = all("error" not in r for r in results)
            failed |= not ok or not results[1].get("guaranteed")
            rows.append([scene, f"1/{d}"] + [f"{r['seconds']:.2f} s" if "error" not in r else r["error"]
                                             for r in results] +
                        [ratio(results[0].get("seconds"), results[1].get("seconds")) if ok else "-",
                         f"{results[1]['components']} comp, genus {results[1]['genus']}"
                         f"{'' if results[1]['guaranteed'] else ' (not guaranteed)'}" if ok else "-"])
    print("\nSeconds (slowest rank), speed-up of 2 ranks over 1 (each with one thread)")
    table(rows)
    return 1 if failed else 0


# Issue 17's table: the certified per-cell error against the cells sized by
# epsilon and OpenVDB, uniform and adaptive.
ERROR_SCENES = ["sphere", "armadillo", "turbine", "couplingdown", "fandisk", "plate-ellipsoids", "demo-csg"]
ERROR_METHODS = [("filter now", "tpc", None), ("filter, Decimate", "decimate", None),
                 ("filter before", "before", None), ("OpenVDB uniform", "vdb", None),
                 ("OpenVDB adaptivity 0.05", "vdb", 0.05)]


def errors(a):
    """Triangles, seconds, the certified bound and the measured two-sided
    Hausdorff distance (sampled on the sphere, CGAL's certified estimate on
    the scenes of one mesh) relative to epsilon, for this build's filter
    (also with Decimate), an earlier build's (--before PROGRAM), and OpenVDB uniform and with
    adaptivity 0.05 at the filter's finest cell size; ratios to OpenVDB
    uniform."""
    print("Machine:", machine())
    scenes = a.scenes.split(",") if a.scenes != ",".join(SCENES) else ERROR_SCENES
    denominators = [int(d) for d in a.epsilons.split(",")]
    rows = [["scene", "epsilon", "method", "triangles", "seconds", "bound/eps", "measured/eps", "uniform/this",
             "topology"]]
    for scene in scenes:
        for d in denominators:
            results = {}
            for label, method, adaptivity in ERROR_METHODS:
                if method == "before" and not a.before:
                    continue
                program = a.before if method == "before" else a.program
                cell = results["filter now"].get("cell_size") if method == "vdb" else None
                results[label] = run(program, a.meshes, "tpc" if method in ("before", "decimate") else method, scene,
                                     1.0 / d, 2, cell, 4 * 3600 if method != "vdb" else a.time_limit,
                                     adaptivity=adaptivity, measure=True, decimate=method == "decimate")
                print(f"  ran {scene:16} 1/{d:<4} {label:24} {results[label].get('seconds', float('nan')):8.2f} s",
                      file=sys.stderr, flush=True)
            uniform = results["OpenVDB uniform"].get("triangles")
            for label, r in results.items():
                bound, measured = r.get("hausdorff_bound_over_eps"), r.get("measured_hausdorff_over_eps")
                rows.append([scene, f"1/{d}", label, r.get("triangles", "-"),
                             f"{r['seconds']:.2f}" if "seconds" in r else "-",
                             f"{bound:.2f}" if bound is not None else "-",
                             f"{measured:.2f}" if measured is not None else "-",
                             ratio(uniform, r.get("triangles")),
                             topology(r) + (", guaranteed" if r.get("guaranteed") else "")])
    table(rows)
    return 0


def compare(a):
    """This build's filter against another build's (--compare PROGRAM), both
    with 2 threads, runs interleaved (new, old, new, old, ...) so that the
    machine's drift hits both alike: median seconds, their ratio, and whether
    the two outputs are identical (a hash of every point, triangle, grid cell
    and array: tpc_benchmark --fingerprint; with --geometry-only, of all that
    but the certified errors, for a change that moves only those). Returns 1
    if any output differs."""
    print("Machine:", machine())
    scenes = a.scenes.split(",") if a.scenes != ",".join(SCENES) else SCENES + CHECK_SCENES
    denominators = [int(d) for d in ("64,128" if a.quick or a.epsilons == "64,128,256" else a.epsilons).split(",")]
    rows = [["scene", "epsilon", "new s", "old s", "new / old", "triangles", "grid cells", "output"]]
    differ = []
    for scene in scenes:
        for d in denominators:
            runs = {"new": [], "old": []}
            for _ in range(a.repeat):
                for key, program in (("new", a.program), ("old", a.compare)):
                    runs[key].append(run(program, a.meshes, "tpc", scene, 1.0 / d, 2, None, 4 * 3600,
                                         fingerprint="geometry" if a.geometry_only else True))
            print(f"  ran {scene:20} 1/{d:<4} x {a.repeat}", file=sys.stderr, flush=True)
            every = runs["new"] + runs["old"]
            if any("error" in r for r in every):
                rows.append([scene, f"1/{d}", "-", "-", "-", "-", "-",
                             next(r["error"] for r in every if "error" in r)])
                differ.append((scene, d))
                continue
            kind = "geometry" if a.geometry_only else "everything"
            if any(r.get("fingerprint_of", "everything") != kind for r in every):
                rows.append([scene, f"1/{d}", "-", "-", "-", "-", "-",
                             f"a build cannot fingerprint {kind} (tpc_benchmark --fingerprint geometry)"])
                differ.append((scene, d))
                continue
            median = {k: sorted(r["seconds"] for r in v)[len(v) // 2] for k, v in runs.items()}
            same = len({r["fingerprint"] for r in every}) == 1
            differ += [] if same else [(scene, d)]
            new, old = runs["new"][0], runs["old"][0]
            counts = lambda key: str(new[key]) if new[key] == old[key] else f"{new[key]} (old {old[key]})"
            rows.append([scene, f"1/{d}", f"{median['new']:.2f}", f"{median['old']:.2f}",
                         ratio(median["new"], median["old"]), counts("triangles"), counts("grid_cells"),
                         ("same geometry" if a.geometry_only else "identical") if same else "DIFFERENT"])
    print(f"\nThis build vs {a.compare}: 2 threads, median of {a.repeat} interleaved runs each")
    table(rows)
    if differ:
        print("\nOutputs differ (or a run failed) on:", differ)
        return 1
    return 0


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--program", default=os.path.join(HERE, "../../build/bin/tpc_benchmark"))
    parser.add_argument("--meshes", default=os.path.join(HERE, "../../build/Testing/Cxx/cgal/data/meshes"))
    parser.add_argument("--scenes", default=",".join(SCENES))
    parser.add_argument("--epsilons", default="64,128,256", help="denominators: 64 means 1/64 of the diagonal")
    parser.add_argument("--quick", action="store_true", help="epsilons 1/64 and 1/128")
    parser.add_argument("--smoke", action="store_true", help="one small case per method (a test)")
    parser.add_argument("--json", help="also write every run to this file")
    parser.add_argument("--time-limit", type=int, default=900,
                        help="seconds after which a VTK or OpenVDB run is stopped (reported as a lower bound)")
    parser.add_argument("--limits", action="store_true",
                        help="only the limits: memory vs MaximumNumberOfCells, abort latency (~3 min)")
    parser.add_argument("--ranks", action="store_true",
                        help="only the MPI runs: 1 vs 2 ranks under pvbatch (~3 min)")
    parser.add_argument("--compare", metavar="PROGRAM",
                        help="only the filter, against another build's tpc_benchmark: interleaved seconds and "
                             "identical outputs, on the timed scenes and " + ", ".join(CHECK_SCENES))
    parser.add_argument("--repeat", type=int, default=3, help="with --compare: runs of each build per case")
    parser.add_argument("--geometry-only", action="store_true",
                        help="with --compare: outputs count as the same when everything but the certified "
                             "errors is (both builds' tpc_benchmark must know --fingerprint geometry)")
    parser.add_argument("--errors", action="store_true",
                        help="only issue 17's table: triangles, seconds, certified and measured error against "
                             "OpenVDB uniform and adaptive, on " + ", ".join(ERROR_SCENES))
    parser.add_argument("--before", metavar="PROGRAM", help="with --errors: an earlier build's tpc_benchmark")
    a = parser.parse_args()
    if a.geometry_only and not a.compare:
        parser.error("--geometry-only compares two builds: it goes with --compare PROGRAM")
    if a.errors:
        return errors(a)
    if a.compare:
        return compare(a)
    if a.limits:
        return limits(a)
    if a.ranks:
        return ranks(a)
    scenes = a.scenes.split(",")
    denominators = [int(d) for d in ("64,128" if a.quick else a.epsilons).split(",")]
    if a.smoke:
        scenes, denominators = ["plate-ellipsoids"], [16]

    print("Machine:", machine())
    results = {}
    for scene in scenes:
        for d in denominators:
            eps = 1.0 / d
            for method, threads in METHODS:
                cell = results.get((scene, d, "tpc", 1), {}).get("cell_size") if method != "tpc" else None
                limit = 4 * 3600 if method == "tpc" else a.time_limit
                r = run(a.program, a.meshes, method, scene, eps, threads, cell, limit)
                results[(scene, d, method, threads)] = r
                print(f"  ran {scene:20} 1/{d:<4} {LABEL[(method, threads)]:22} "
                      f"{r.get('seconds', float('nan')):8.2f} s", file=sys.stderr, flush=True)

    for scene in scenes:
        print(f"\n{scene}")
        rows = [["epsilon", "method", "seconds", "peak MiB", "triangles", "grid cells", "topology"]]
        for d in denominators:
            for key in METHODS:
                r = results[(scene, d) + key]
                ok = "error" not in r
                rows.append([f"1/{d}", LABEL[key], f"{r['seconds']:.2f}" if ok else "-",
                             f"{r['peak_mib']:.0f}" if ok else "-", r.get("triangles", "-"),
                             r.get("grid_cells", "-"), topology(r)])
        table(rows)

    print("\nRatios (filter with 2 threads vs the others; > 1 means the filter is better)")
    rows = [["scene", "epsilon", "VTK s / filter s", "VDB s / filter s", "VTK tris / filter tris",
             "VDB tris / filter tris", "2-thread speed-up"]]
    for scene in scenes:
        for d in denominators:
            r = {k: results[(scene, d) + k] for k in METHODS}
            s = {k: seconds(v) for k, v in r.items()}
            t = {k: v.get("triangles") for k, v in r.items()}
            rows.append([scene, f"1/{d}", ratio(s[("vtk", 2)], s[("tpc", 2)], "timeout" in r[("vtk", 2)]),
                         ratio(s[("vdb", 2)], s[("tpc", 2)], "timeout" in r[("vdb", 2)]),
                         ratio(t[("vtk", 2)], t[("tpc", 2)]), ratio(t[("vdb", 2)], t[("tpc", 2)]),
                         ratio(s[("tpc", 1)], s[("tpc", 2)])])
    table(rows)

    if len(denominators) > 1:
        print("\nTime growth from epsilon to epsilon/2 (surface-bound ~4x, volume-bound ~8x)")
        rows = [["scene", "step"] + [LABEL[k] for k in METHODS]]
        for scene in scenes:
            for d0, d1 in zip(denominators, denominators[1:]):
                rows.append([scene, f"1/{d0} -> 1/{d1}"] +
                            [ratio(seconds(results[(scene, d1) + k]), seconds(results[(scene, d0) + k]),
                                   "timeout" in results[(scene, d1) + k]) for k in METHODS])
        table(rows)

    if a.json:
        with open(a.json, "w") as f:
            json.dump([dict(v, key=list(k)) for k, v in results.items()], f, indent=1)
    failed = [k for k, v in results.items() if "error" in v and k[2] == "tpc"]
    wrong = [k for k, v in results.items() if k[2] == "tpc" and "error" not in v and not v["topology_right"]]
    if failed or wrong:
        print("\nThe filter failed or was wrong on:", failed + wrong)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
