#!/usr/bin/env bash
# The installed tree as its users meet it: `cmake --install`, then
#  - a C++ project (Examples/Cxx) found with find_package(TopologyPreserving),
#    built and run on two CGAL meshes;
#  - the plugin loaded by pvpython from PV_PLUGIN_PATH;
#  - the Python package and tpcontour from the installed folders.
# Usage: TestInstalledTree.sh <build dir> <source dir> <CGAL data/meshes> <pvpython> <plugin dir under lib>
set -euo pipefail
build=$1 source=$2 meshes=$3 pvpython=$4 plugins=$5
prefix="$build/test-install"
consumer="$build/test-consumer"
rm -rf "$prefix" "$consumer"
cmake --install "$build" --prefix "$prefix" > /dev/null

cmake -S "$source/Examples/Cxx" -B "$consumer" -DCMAKE_PREFIX_PATH="$prefix" > "$build/test-consumer.log"
cmake --build "$consumer" > /dev/null
out=$("$consumer/MeshBoolean" "$meshes/joint.off" "$meshes/knot1.off" difference 0.03125 0.0158 0.0442 0.0271)
echo "installed-package example: $out"
[[ $out == "components 1 genus 9 guaranteed 1"* ]]

PV_PLUGIN_PATH="$prefix/lib/$plugins/TopologyPreservingContour" "$pvpython" -c "
from paraview.simple import TopologyPreservingContour
f = TopologyPreservingContour(ImplicitFunction='Sphere')
f.UpdatePipeline()
genus = f.GetDataInformation(0).DataInformation.GetFieldDataInformation().GetArrayInformation('Genus').GetComponentRange(0)[0]
assert genus == 0, genus
print('installed plugin: loaded from PV_PLUGIN_PATH, sphere of genus', int(genus))
"
"$pvpython" -c "
import sys; sys.path.insert(0, '$prefix/lib/python3/site-packages')
from topologypreserving import vtkTopologyPreservingContour, vtkOFFReader
print('installed Python package: imports')
"
# (Its whole help first: grep -q stops reading at the first match, and with
# pipefail a help longer than one pipe write would then fail on SIGPIPE.)
help=$("$prefix/bin/tpcontour" --help)
grep -q -- "--operation" <<< "$help"
echo "installed tpcontour: runs"
