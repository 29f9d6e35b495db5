# Writes <OUTPUT>: the presets of <INPUT> (a ParaView colour-map presets file)
# as a C++ array of { name, JSON text }, for the plugin to register them.
# Run at build time: cmake -DINPUT=... -DOUTPUT=... -P ColorMapsHeader.cmake
file(READ "${INPUT}" presets)
string(JSON count LENGTH "${presets}")
math(EXPR last "${count} - 1")
set(entries "")
foreach (i RANGE ${last})
  string(JSON preset GET "${presets}" ${i})
  string(JSON name GET "${preset}" Name)
  string(APPEND entries "  { \"${name}\", R\"tpcjson(${preset})tpcjson\" },\n")
endforeach ()
file(WRITE "${OUTPUT}.tmp" "// Generated from ${INPUT} by ColorMapsHeader.cmake: do not edit.
#pragma once

namespace tpc
{
namespace plugin
{
struct ColorMap
{
  const char* Name;
  const char* Text; ///< the preset as JSON
};
const ColorMap ColorMaps[] = {
${entries}};
} // namespace plugin
} // namespace tpc
")
file(COPY_FILE "${OUTPUT}.tmp" "${OUTPUT}" ONLY_IF_DIFFERENT)
file(REMOVE "${OUTPUT}.tmp")
