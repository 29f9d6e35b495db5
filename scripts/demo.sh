#!/usr/bin/env bash
# Sets everything up, then contours a CSG of implicit primitives and remeshes
# a real CAD mesh with guaranteed topology: writes demo-output/{csg,mesh}-
# grid.htg, {csg,mesh}-surface.vtp, surface.png, report.txt and prints the
# topology report.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
VTK_SMP_BACKEND_IN_USE=STDThread xvfb-run -a \
  pvpython scripts/demo.py build/lib/python3/site-packages demo-output
