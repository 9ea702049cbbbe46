# cmake -DSWEEP=... -DADMESH=... -DSWP=file.swp -DOUT=dir -P admesh_checks_stl.cmake
cmake_policy(SET CMP0057 NEW)  # if(IN_LIST) in a -P script
# Every STL of the file passes Debian's admesh with no degenerate facet (a triangle of zero area),
# and every STL that sweep calls closed (no warning that its surface is open, non-manifold or
# not consistently oriented) with nothing to repair: one part, no facet removed, added or
# reversed, no edge fixed, none disconnected.
file(REMOVE_RECURSE ${OUT})
file(MAKE_DIRECTORY ${OUT})
execute_process(COMMAND ${SWEEP} export ${SWP} ${OUT}/out --format stl RESULT_VARIABLE rc OUTPUT_VARIABLE out
                ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "sweep export failed (${rc}): ${err}")
endif()
string(REGEX MATCHALL "wrote [^ ]+\\.stl \\([0-9]+ vertices, [0-9]+ triangles" lines "${out}")
foreach(line ${lines})
  string(REGEX MATCH "wrote ([^ ]+\\.stl) \\([0-9]+ vertices, ([0-9]+) triangles" _ "${line}")
  set(path ${CMAKE_MATCH_1})
  set(triangles ${CMAKE_MATCH_2})
  if(triangles LESS 4)  # admesh 0.98 reads a binary STL of fewer facets as "an empty file"
    message(STATUS "admesh: ${path} skipped (${triangles} triangles)")
    continue()
  endif()
  execute_process(COMMAND ${ADMESH} ${path} RESULT_VARIABLE arc OUTPUT_VARIABLE aout ERROR_VARIABLE aerr)
  if(NOT arc EQUAL 0)
    message(FATAL_ERROR "admesh could not read ${path} (${arc}): ${aerr}")
  endif()
  # admesh's "NAME :  ORIGINAL" lines (the first number is what it found before repairing).
  set(expected "Degenerate facets")
  string(REGEX REPLACE "^.*/out_|\\.stl$" "" surface "${path}")
  if(NOT err MATCHES "surface '${surface}' (is open|has [0-9]+ non-manifold|is not consistently oriented)")
    list(APPEND expected "Edges fixed" "Facets removed" "Facets added" "Facets reversed" "Backwards edges"
         "Total disconnected facets")
    string(REGEX MATCH "Number of parts +: +([0-9]+)" _ "${aout}")
    if(NOT CMAKE_MATCH_1 EQUAL 1)
      message(FATAL_ERROR "admesh found ${CMAKE_MATCH_1} parts in ${path}, which sweep calls closed:\n${aout}")
    endif()
  endif()
  foreach(name ${expected})
    string(REGEX MATCH "${name} +: +([0-9]+)" _ "${aout}")
    if(NOT "${CMAKE_MATCH_1}" STREQUAL "0")
      message(FATAL_ERROR "admesh: ${name} ${CMAKE_MATCH_1} in ${path}:\n${aout}")
    endif()
  endforeach()
  message(STATUS "admesh: ${path} needs nothing")
endforeach()
