# One check of the sweep CLI, chosen by -DCHECK=export|legacy|bad_file|info.
# Inputs: SWEEP (the executable), SWP_DIR (starter files), DATA_DIR (tests/data), OUT (a scratch
# directory owned by this check, emptied first).
cmake_minimum_required(VERSION 3.20)

function(fail)
  string(JOIN "" message ${ARGN})
  message(FATAL_ERROR "cli.${CHECK}: ${message}")
endfunction()

function(expect_equal what actual expected)
  if(NOT actual STREQUAL expected)
    fail("${what}:\n  expected: [${expected}]\n  actual:   [${actual}]")
  endif()
endfunction()

# Counts the lines of FILE that start with PREFIX (e.g. "v ").
function(count_lines file prefix out)
  file(STRINGS ${file} lines REGEX "^${prefix}")
  list(LENGTH lines n)
  set(${out} ${n} PARENT_SCOPE)
endfunction()

# Runs sweep with ARGN (and DISPLAY unset, so the original form never opens a window).
function(run_sweep)
  execute_process(COMMAND ${CMAKE_COMMAND} -E env --unset=DISPLAY --unset=WAYLAND_DISPLAY ${SWEEP} ${ARGN}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  set(rc "${rc}" PARENT_SCOPE)
  set(out "${out}" PARENT_SCOPE)
  set(err "${err}" PARENT_SCOPE)
endfunction()

function(files_in dir out)
  file(GLOB found RELATIVE ${dir} ${dir}/*)
  list(SORT found)
  set(${out} "${found}" PARENT_SCOPE)
endfunction()

# The torus of tor.swp: a 30-step circle swept along a 60-step circle, both closed, so
# 30 x 60 vertices and 2 x 30 x 60 triangles.
function(expect_torus_obj file)
  count_lines(${file} "v " v)
  count_lines(${file} "vn " vn)
  count_lines(${file} "f " f)
  expect_equal("v lines in ${file}" "${v}" 1800)
  expect_equal("vn lines in ${file}" "${vn}" 1800)
  expect_equal("f lines in ${file}" "${f}" 3600)
endfunction()

file(REMOVE_RECURSE ${OUT})
file(MAKE_DIRECTORY ${OUT})

if(CHECK STREQUAL "export")
  run_sweep(export ${SWP_DIR}/tor.swp ${OUT}/tor)
  expect_equal("exit code" "${rc}" 0)
  expect_equal("stderr" "${err}" "")
  expect_equal("stdout" "${out}" "wrote ${OUT}/tor_fbf.obj (1800 vertices, 3600 triangles)\n")
  files_in(${OUT} files)
  expect_equal("files written" "${files}" "tor_fbf.obj")
  expect_torus_obj(${OUT}/tor_fbf.obj)

elseif(CHECK STREQUAL "legacy")
  # `sweep FILE.swp PREFIX` is `sweep export FILE.swp PREFIX` (plus a viewer when there is a display).
  run_sweep(${SWP_DIR}/tor.swp ${OUT}/old)
  expect_equal("exit code" "${rc}" 0)
  run_sweep(export ${SWP_DIR}/tor.swp ${OUT}/new)
  expect_equal("exit code" "${rc}" 0)
  files_in(${OUT} files)
  expect_equal("files written" "${files}" "new_fbf.obj;old_fbf.obj")
  file(READ ${OUT}/old_fbf.obj old_text)
  file(READ ${OUT}/new_fbf.obj new_text)
  # Only the comment line names the command's input the same way; the geometry must be identical.
  string(REGEX REPLACE "^#[^\n]*\n" "" old_text "${old_text}")
  string(REGEX REPLACE "^#[^\n]*\n" "" new_text "${new_text}")
  if(NOT old_text STREQUAL new_text)
    fail("the original form wrote different geometry from `sweep export`")
  endif()
  expect_torus_obj(${OUT}/old_fbf.obj)

elseif(CHECK STREQUAL "bad_file")
  # A valid surface comes before the error, so a half-done export would leave bad_good.obj.
  set(bad ${DATA_DIR}/cli_bad_reference.swp)
  set(message "${bad}:4:13: expected the name of a 2D curve (bez2, bsp2, circ) defined above as profile, found 'missing' (no object has that name)\n")
  run_sweep(export ${bad} ${OUT}/bad)
  if(rc EQUAL 0)
    fail("export of a bad file exited 0")
  endif()
  expect_equal("stderr of export" "${err}" "${message}")
  expect_equal("stdout of export" "${out}" "")
  files_in(${OUT} files)
  expect_equal("files written" "${files}" "")
  run_sweep(info ${bad})
  if(rc EQUAL 0)
    fail("info of a bad file exited 0")
  endif()
  expect_equal("stderr of info" "${err}" "${message}")
  run_sweep(${bad} ${OUT}/legacy)
  if(rc EQUAL 0)
    fail("the original form on a bad file exited 0")
  endif()
  expect_equal("stderr of the original form" "${err}" "${message}")
  files_in(${OUT} files)
  expect_equal("files written" "${files}" "")

elseif(CHECK STREQUAL "info")
  run_sweep(info ${SWP_DIR}/tor.swp)
  expect_equal("exit code" "${rc}" 0)
  expect_equal("stderr" "${err}" "")
  foreach(pattern
      "^${SWP_DIR}/tor.swp: 3 objects\n"
      "circ +profile +line 1 +steps 30 +radius 0.5, 31 samples, closed\n"
      "circ +sweep +line 2 +steps 60 +radius 2, 61 samples, closed\n"
      "gcyl +fbf +line 4 +profile profile, sweep sweep: 1800 vertices, 3600 triangles\n")
    if(NOT out MATCHES "${pattern}")
      fail("info output does not match '${pattern}':\n${out}")
    endif()
  endforeach()
  # wineglass: 26 B-spline points at 8 steps = 23 * 8 + 1 = 185 samples, turned 90 times.
  run_sweep(info ${SWP_DIR}/wineglass.swp)
  expect_equal("exit code" "${rc}" 0)
  foreach(pattern
      "bsp2 +profile +line 1 +steps 8 +26 control points, 185 samples\n"
      "srev +wineglass +line [0-9]+ +steps 90 +profile profile: 16650 vertices, 33120 triangles\n")
    if(NOT out MATCHES "${pattern}")
      fail("info output does not match '${pattern}':\n${out}")
    endif()
  endforeach()
  files_in(${OUT} files)
  expect_equal("files written by info" "${files}" "")

else()
  fail("unknown CHECK '${CHECK}'")
endif()
