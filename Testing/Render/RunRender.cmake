# Driver for the Render.* tests of lct-render (cmake -P). Variables:
#   LCT_RENDER  path of lct-render       LCT_MODE  default | slices | json | error
#   LCT_OUT     scratch directory        LCT_ARGS  extra arguments, separated by |
#   LCT_EXPECT  (error) phrase stderr must contain
# Rendering modes print "LCT_SKIP" (the test's SKIP_REGULAR_EXPRESSION) when lct-render exits 125
# (no DISPLAY): cmake -P cannot exit with 125 itself.
cmake_minimum_required(VERSION 3.22)
# add_test would split a ;-list into separate arguments of cmake itself.
string(REPLACE "|" ";" LCT_ARGS "${LCT_ARGS}")

function(lct_run out_dir)
  execute_process(
    COMMAND "${LCT_RENDER}" --out "${out_dir}" ${ARGN}
    RESULT_VARIABLE rc
    OUTPUT_VARIABLE out
    ERROR_VARIABLE  err)
  message(STATUS "lct-render ${ARGN} -> ${rc}\n${out}${err}")
  if (rc EQUAL 125)
    message(STATUS "LCT_SKIP: no DISPLAY (run under xvfb-run -a)")
    set(lct_skipped TRUE PARENT_SCOPE)
    return()
  endif ()
  if (NOT rc EQUAL 0)
    message(FATAL_ERROR "lct-render ${ARGN} exited with ${rc}")
  endif ()
  set(lct_skipped FALSE PARENT_SCOPE)
endfunction()

function(lct_expect_full dir frames)
  math(EXPR last "${frames} - 1")
  foreach (i RANGE ${last})
    string(LENGTH "${i}" len)
    math(EXPR pad "4 - ${len}")
    string(REPEAT "0" ${pad} zeros)
    if (NOT EXISTS "${dir}/frame_${zeros}${i}.png")
      message(FATAL_ERROR "missing ${dir}/frame_${zeros}${i}.png")
    endif ()
  endforeach ()
  foreach (f video.ogv contact_sheet.png)
    if (NOT EXISTS "${dir}/${f}")
      message(FATAL_ERROR "missing ${dir}/${f}")
    endif ()
    file(SIZE "${dir}/${f}" size)
    if (size EQUAL 0)
      message(FATAL_ERROR "${dir}/${f} is empty")
    endif ()
  endforeach ()
  file(GLOB frames_found "${dir}/frame_*.png")
  list(LENGTH frames_found n)
  if (NOT n EQUAL frames)
    message(FATAL_ERROR "${dir}: ${n} frames, expected ${frames}")
  endif ()
  file(GLOB leftovers "${dir}/.*")
  if (leftovers)
    message(FATAL_ERROR "temporary files left behind: ${leftovers}")
  endif ()
endfunction()

if (LCT_MODE STREQUAL "error")
  execute_process(
    COMMAND "${LCT_RENDER}" --out "${LCT_OUT}" ${LCT_ARGS}
    RESULT_VARIABLE rc
    OUTPUT_VARIABLE out
    ERROR_VARIABLE  err)
  message(STATUS "exit ${rc}, stderr: ${err}")
  if (NOT rc EQUAL 1)
    message(FATAL_ERROR "expected exit code 1, got ${rc}")
  endif ()
  string(FIND "${err}" "${LCT_EXPECT}" at)
  if (at EQUAL -1)
    message(FATAL_ERROR "stderr does not contain \"${LCT_EXPECT}\"")
  endif ()
  return()
endif ()

file(REMOVE_RECURSE "${LCT_OUT}")
if (LCT_MODE STREQUAL "default" OR LCT_MODE STREQUAL "json")
  lct_run("${LCT_OUT}" --frames 8 --size 160x90 ${LCT_ARGS})
  if (NOT lct_skipped)
    lct_expect_full("${LCT_OUT}" 8)
  endif ()
elseif (LCT_MODE STREQUAL "slices")
  lct_run("${LCT_OUT}/full" --frames 8 --size 160x90 ${LCT_ARGS})
  if (lct_skipped)
    return()
  endif ()
  lct_run("${LCT_OUT}/sliced" --frames 0:4/8 --size 160x90 ${LCT_ARGS})
  lct_run("${LCT_OUT}/sliced" --frames 4:8/8 --size 160x90 ${LCT_ARGS})
  foreach (f video.ogv contact_sheet.png)
    if (EXISTS "${LCT_OUT}/sliced/${f}")
      message(FATAL_ERROR "a sliced run wrote ${f}")
    endif ()
  endforeach ()
  foreach (i RANGE 7)
    set(name "frame_000${i}.png")
    execute_process(
      COMMAND "${CMAKE_COMMAND}" -E compare_files "${LCT_OUT}/full/${name}" "${LCT_OUT}/sliced/${name}"
      RESULT_VARIABLE differ)
    if (differ)
      message(FATAL_ERROR "${name} of the sliced runs differs from the full run's")
    endif ()
  endforeach ()
  message(STATUS "8 frames of two sliced runs equal the full run's byte for byte")
else ()
  message(FATAL_ERROR "unknown LCT_MODE ${LCT_MODE}")
endif ()
