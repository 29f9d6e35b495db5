# tpc_core_layer(<folder> [DEPENDS <layer>...] [SOURCES <file>...] HEADERS <file>...)
#
# One layer of the core: an object library tpc_<folder> (an interface library
# when it has headers only) whose include path holds its own folder and those
# of the layers it DEPENDS on, nothing else. Each header is also compiled on
# its own in the layer's context (tpc_check_headers), so a header that uses a
# layer its own layer does not declare fails the build, as a source would.
function(tpc_core_layer folder)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "" "DEPENDS;SOURCES;HEADERS")
  set(target "tpc_${folder}")
  list(TRANSFORM arg_DEPENDS PREPEND "tpc_")
  if (arg_SOURCES)
    add_library(${target} OBJECT ${arg_SOURCES} ${arg_HEADERS})
    set(scope PUBLIC)
    set_target_properties(${target} PROPERTIES POSITION_INDEPENDENT_CODE ON CXX_EXTENSIONS OFF)
    target_compile_options(${target} PRIVATE $<$<CXX_COMPILER_ID:GNU,Clang>:-Wall -Wextra>)
  else ()
    add_library(${target} INTERFACE)
    set(scope INTERFACE)
  endif ()
  target_include_directories(${target} ${scope} "$<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}>")
  target_link_libraries(${target} ${scope} tpc_core_flags ${arg_DEPENDS})
  tpc_check_headers(${target} ${arg_HEADERS})
  set(TPC_CORE_LAYERS ${TPC_CORE_LAYERS} ${target} CACHE INTERNAL "The core's layers, lowest first")
  set(TPC_CORE_LAYER_DIRS ${TPC_CORE_LAYER_DIRS} "${CMAKE_CURRENT_SOURCE_DIR}" CACHE INTERNAL "Their folders")
endfunction()

# Compiles each of `headers` alone, with the usage requirements of `target`:
# a header must include what it uses, and only from the layers allowed.
function(tpc_check_headers target)
  if (NOT TPC_CHECK_HEADERS)
    return ()
  endif ()
  set(sources)
  foreach (header IN LISTS ARGN)
    get_filename_component(name "${header}" NAME_WE)
    set(source "${CMAKE_CURRENT_BINARY_DIR}/header-checks/${name}.cxx")
    set(text "#include \"${header}\"\n")
    if (EXISTS "${source}")
      file(READ "${source}" old)
    endif ()
    if (NOT old STREQUAL text)
      file(WRITE "${source}" "${text}")
    endif ()
    list(APPEND sources "${source}")
  endforeach ()
  add_library(${target}_header_checks OBJECT ${sources})
  target_link_libraries(${target}_header_checks PRIVATE ${target})
endfunction()

option(TPC_CHECK_HEADERS "Compile every core header on its own (layer dependencies, self-contained headers)" ON)
set(TPC_CORE_LAYERS "" CACHE INTERNAL "The core's layers, lowest first")
set(TPC_CORE_LAYER_DIRS "" CACHE INTERNAL "Their folders")
