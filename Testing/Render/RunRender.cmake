# Driver for the Render.* tests of lct-render (cmake -P). Variables:
#   LCT_RENDER  path of lct-render       LCT_MODE  default | slices | json | error | signal |
#               metric | stdout | compare | image | links | stale | assemble (described where
#               they are run)
#   LCT_OUT     scratch directory        LCT_ARGS  extra arguments, separated by |
#   LCT_EXPECT  (error, metric) phrase stderr (error) or stdout (metric) must contain
#   LCT_EXIT    (error) the exit code expected, default 1 (2 for usage errors)
#   LCT_SETUP   (error) what to put in the way first: dir-in-the-way (a directory named
#               frame_0000.png in LCT_OUT), out-is-file (LCT_OUT a regular file),
#               many-keys=N[:compare] (a keys file of N camera keys, LCT_OUT/many.json)
#   LCT_FSIZE   (error) file-size limit for lct-render, in 512-byte blocks (sh's ulimit -f)
#   LCT_ENV     (error) NAME=VALUE in lct-render's environment
#   LCT_SIGNAL  (signal) the name of the signal that ends the run (PIPE, USR1, ...)
# After an error, no temporary (.*.part) may remain, and nothing at all may be written unless
# LCT_SETUP or LCT_FSIZE made the run fail only after frames were written.
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
  set(out "${out}" PARENT_SCOPE)
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

# A fresh LCT_OUT, then lct_run(dir ...); ends the script (a macro's return() is the caller's)
# when lct-render has no display.
macro(lct_first_run dir)
  file(REMOVE_RECURSE "${LCT_OUT}")
  lct_run("${dir}" ${ARGN})
  if (lct_skipped)
    return()
  endif ()
endmacro()

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
  file(REMOVE_RECURSE "${LCT_OUT}")
  set(command "${LCT_RENDER}" --out "${LCT_OUT}")
  if (LCT_ARGS MATCHES "^assemble")
    set(command "${LCT_RENDER}") # a subcommand takes no --out
  endif ()
  if (LCT_SETUP STREQUAL "dir-in-the-way")
    file(MAKE_DIRECTORY "${LCT_OUT}/frame_0000.png")
  elseif (LCT_SETUP STREQUAL "out-is-file")
    get_filename_component(parent "${LCT_OUT}" DIRECTORY)
    file(MAKE_DIRECTORY "${parent}")
    file(WRITE "${LCT_OUT}" "a file, not a directory\n")
  elseif (LCT_SETUP MATCHES "^many-keys=([0-9]+)(:compare)?$")
    # Written here rather than kept in the repository: it is large and all alike.
    set(n "${CMAKE_MATCH_1}")
    set(compare "${CMAKE_MATCH_2}")
    math(EXPR last "${n} - 1")
    set(json "{\"camera\": {\"keys\": [\n")
    foreach (i RANGE ${last})
      string(APPEND json "{\"time\": ${i}, \"position\": [5, 3, 6], \"focal_point\": [0, 0, 0]},\n")
    endforeach ()
    string(REGEX REPLACE ",\n$" "\n]}}\n" json "${json}")
    file(WRITE "${LCT_OUT}/many.json" "${json}")
    list(APPEND command "${LCT_OUT}/many.json")
    if (compare)
      list(APPEND command --compare)
    endif ()
  endif ()
  if (LCT_FSIZE)
    # The limit applies to lct-render alone, through a shell that then execs it.
    set(command sh -c "ulimit -f ${LCT_FSIZE} && exec \"$0\" \"$@\"" ${command})
  endif ()
  if (LCT_ENV)
    set(command "${CMAKE_COMMAND}" -E env "${LCT_ENV}" ${command})
  endif ()
  execute_process(
    COMMAND ${command} ${LCT_ARGS}
    RESULT_VARIABLE rc
    OUTPUT_VARIABLE out
    ERROR_VARIABLE  err)
  message(STATUS "exit ${rc}, stderr: ${err}")
  if (rc EQUAL 125)
    message(STATUS "LCT_SKIP: no DISPLAY (run under xvfb-run -a)")
    return()
  endif ()
  if (NOT DEFINED LCT_EXIT)
    set(LCT_EXIT 1)
  endif ()
  if (NOT rc STREQUAL "${LCT_EXIT}")
    message(FATAL_ERROR "expected exit code ${LCT_EXIT}, got ${rc}")
  endif ()
  string(FIND "${err}" "${LCT_EXPECT}" at)
  if (at EQUAL -1)
    message(FATAL_ERROR "stderr does not contain \"${LCT_EXPECT}\"")
  endif ()
  if (IS_DIRECTORY "${LCT_OUT}")
    file(GLOB leftovers "${LCT_OUT}/.*")
    if (leftovers)
      message(FATAL_ERROR "temporary files left behind: ${leftovers}")
    endif ()
    if (NOT LCT_SETUP AND NOT LCT_FSIZE)
      file(GLOB written "${LCT_OUT}/*")
      if (written)
        message(FATAL_ERROR "a failed run wrote: ${written}")
      endif ()
    endif ()
  endif ()
  return()
endif ()

if (LCT_MODE STREQUAL "signal")
  # lct-render ended mid-run by the signal LCT_SIGNAL (a name: PIPE, USR1, ...): PIPE through
  # `| head -n 1`, which leaves after the first line, the others sent with kill once the video's
  # temporary exists. The process must die of that signal and leave no temporary (.*.part).
  # sh runs it (POSIX sh has no PIPESTATUS: the status goes through a file) with no core dumps.
  file(REMOVE_RECURSE "${LCT_OUT}")
  set(status_file "${LCT_OUT}.status")
  file(REMOVE "${status_file}")
  set(script [=[
ulimit -c 0
render=$0 out=$1 keys=$2 sig=$3 status=$4
if [ "$sig" = PIPE ]; then
  { "$render" --out "$out" --frames 1000 --size 64x48 "$keys"; echo $? > "$status"; } | head -n 1
  exit 0
fi
# Without job control sh starts a background command with INT and QUIT ignored: undone, as
# from an interactive shell.
env --default-signal "$render" --out "$out" --frames 1000 --size 64x48 "$keys" > /dev/null &
pid=$!
n=0
while [ $n -lt 1200 ] && kill -0 $pid 2> /dev/null &&
  ! ls -a "$out" 2> /dev/null | grep -q '^\.video\.ogv\..*\.part$'; do
  sleep 0.05
  n=$((n + 1))
done
kill -s "$sig" $pid
wait $pid
echo $? > "$status"
]=])
  execute_process(
    COMMAND sh -c "${script}" "${LCT_RENDER}" "${LCT_OUT}" ${LCT_ARGS} "${LCT_SIGNAL}"
            "${status_file}"
    RESULT_VARIABLE rc
    OUTPUT_VARIABLE out
    ERROR_VARIABLE  err)
  message(STATUS "sh: exit ${rc}\n${out}${err}")
  if (NOT EXISTS "${status_file}")
    message(FATAL_ERROR "the shell running lct-render gave no exit status")
  endif ()
  file(STRINGS "${status_file}" status LIMIT_COUNT 1)
  file(REMOVE "${status_file}")
  if (status EQUAL 125)
    message(STATUS "LCT_SKIP: no DISPLAY (run under xvfb-run -a)")
    return()
  endif ()
  set(died_of "")
  if (status GREATER 128)
    execute_process(COMMAND sh -c "kill -l $0" "${status}" OUTPUT_VARIABLE died_of
      OUTPUT_STRIP_TRAILING_WHITESPACE)
  endif ()
  if (NOT died_of STREQUAL LCT_SIGNAL)
    message(FATAL_ERROR
      "lct-render exited with ${status} (${died_of}), expected to die of SIG${LCT_SIGNAL}")
  endif ()
  file(GLOB leftovers "${LCT_OUT}/.*")
  if (leftovers)
    message(FATAL_ERROR "SIG${LCT_SIGNAL} left temporary files behind: ${leftovers}")
  endif ()
  message(STATUS "SIG${LCT_SIGNAL} ended lct-render (exit ${status}) and left no temporary")
  return()
endif ()

if (LCT_MODE STREQUAL "metric")
  # A slice of a run of very many frames: the metric samples a fixed number of cameras, so this
  # takes the time of one frame (the test's TIMEOUT holds it to that).
  lct_first_run("${LCT_OUT}" ${LCT_ARGS})
  string(FIND "${out}" "${LCT_EXPECT}" at)
  if (at EQUAL -1)
    message(FATAL_ERROR "stdout does not contain \"${LCT_EXPECT}\"")
  endif ()
  return()
endif ()

# The frame rate in the Theora identification header of an .ogv (FRN/FRD after "\x80theora",
# its version, frame and picture sizes and offsets: 22 bytes in), as "FRN/FRD".
function(lct_ogv_rate file out_var)
  file(READ "${file}" hex HEX LIMIT 4096)
  string(FIND "${hex}" "807468656f7261" at)
  if (at EQUAL -1)
    message(FATAL_ERROR "${file}: no Theora identification header")
  endif ()
  math(EXPR at "${at} + 44")
  string(SUBSTRING "${hex}" ${at} 8 frn)
  math(EXPR at "${at} + 8")
  string(SUBSTRING "${hex}" ${at} 8 frd)
  math(EXPR frn "0x${frn}")
  math(EXPR frd "0x${frd}")
  set(${out_var} "${frn}/${frd}" PARENT_SCOPE)
endfunction()

function(lct_contains text phrase what)
  string(FIND "${text}" "${phrase}" at)
  if (at EQUAL -1)
    message(FATAL_ERROR "${what} does not contain \"${phrase}\"")
  endif ()
endfunction()

# Every phrase of LCT_EXPECT (separated by #) in `text`.
function(lct_expect_phrases text what)
  string(REPLACE "#" ";" phrases "${LCT_EXPECT}")
  foreach (phrase IN LISTS phrases)
    lct_contains("${text}" "${phrase}" "${what}")
  endforeach ()
endfunction()

function(lct_same_files a b out_var)
  execute_process(
    COMMAND "${CMAKE_COMMAND}" -E compare_files "${a}" "${b}" RESULT_VARIABLE differ)
  if (differ)
    set(${out_var} FALSE PARENT_SCOPE)
  else ()
    set(${out_var} TRUE PARENT_SCOPE)
  endif ()
endfunction()

if (LCT_MODE STREQUAL "stdout")
  # lct-render LCT_ARGS (no display needed, e.g. --describe): exit 0, every phrase of LCT_EXPECT
  # on stdout, and nothing written (not even the --out directory).
  file(REMOVE_RECURSE "${LCT_OUT}")
  execute_process(
    COMMAND "${LCT_RENDER}" --out "${LCT_OUT}" ${LCT_ARGS}
    RESULT_VARIABLE rc
    OUTPUT_VARIABLE out
    ERROR_VARIABLE  err)
  message(STATUS "exit ${rc}\n${out}${err}")
  if (NOT rc EQUAL 0)
    message(FATAL_ERROR "lct-render ${LCT_ARGS} exited with ${rc}")
  endif ()
  lct_expect_phrases("${out}" stdout)
  if (EXISTS "${LCT_OUT}")
    message(FATAL_ERROR "lct-render ${LCT_ARGS} created ${LCT_OUT}")
  endif ()
  return()
endif ()

if (LCT_MODE STREQUAL "help-example")
  # The complete keys file of `lct-render --help` (from "a complete keys file" to the first
  # empty line), with LCT_PART as its part.vtu: read by --describe, every phrase of LCT_EXPECT.
  file(REMOVE_RECURSE "${LCT_OUT}")
  execute_process(COMMAND "${LCT_RENDER}" --help OUTPUT_VARIABLE help RESULT_VARIABLE rc)
  string(FIND "${help}" "a complete keys file" at)
  if (NOT rc EQUAL 0 OR at EQUAL -1)
    message(FATAL_ERROR "lct-render --help (exit ${rc}) shows no complete keys file")
  endif ()
  string(SUBSTRING "${help}" ${at} -1 help)
  string(FIND "${help}" "\n  {" begin)
  string(FIND "${help}" "\n\n" end)
  math(EXPR length "${end} - ${begin}")
  string(SUBSTRING "${help}" ${begin} ${length} example)
  file(WRITE "${LCT_OUT}/keys.json" "${example}\n")
  file(COPY_FILE "${LCT_PART}" "${LCT_OUT}/part.vtu")
  execute_process(
    COMMAND "${LCT_RENDER}" --describe "${LCT_OUT}/keys.json"
    RESULT_VARIABLE rc
    OUTPUT_VARIABLE out
    ERROR_VARIABLE  err)
  message(STATUS "the example of --help:\n${example}\n--describe: exit ${rc}\n${out}${err}")
  if (NOT rc EQUAL 0)
    message(FATAL_ERROR "the example of lct-render --help does not read: ${err}")
  endif ()
  lct_expect_phrases("${out}" "--describe of the example")
  return()
endif ()

if (LCT_MODE STREQUAL "compare")
  # Two runs, LCT_ARGS into LCT_OUT/a and LCT_ARGS2 into LCT_OUT/b (LCT_ARGS2 unset: one run),
  # then each pair X=Y of LCT_PAIRS (separated by #, paths below LCT_OUT) must be byte-equal
  # (LCT_SAME TRUE) or differ (FALSE). LCT_EXPECT (optional): phrases of the first run's stdout.
  lct_first_run("${LCT_OUT}/a" ${LCT_ARGS})
  if (DEFINED LCT_EXPECT)
    lct_expect_phrases("${out}" stdout)
  endif ()
  if (DEFINED LCT_ARGS2)
    string(REPLACE "|" ";" LCT_ARGS2 "${LCT_ARGS2}")
    lct_run("${LCT_OUT}/b" ${LCT_ARGS2})
  endif ()
  string(REPLACE "#" ";" pairs "${LCT_PAIRS}")
  foreach (pair IN LISTS pairs)
    string(REPLACE "=" ";" pair "${pair}")
    list(GET pair 0 x)
    list(GET pair 1 y)
    foreach (f IN ITEMS "${x}" "${y}")
      if (NOT EXISTS "${LCT_OUT}/${f}")
        message(FATAL_ERROR "missing ${LCT_OUT}/${f}")
      endif ()
    endforeach ()
    lct_same_files("${LCT_OUT}/${x}" "${LCT_OUT}/${y}" same)
    if (NOT same STREQUAL LCT_SAME)
      message(FATAL_ERROR "${x} and ${y}: byte-equal ${same}, expected ${LCT_SAME}")
    endif ()
    message(STATUS "${x} and ${y}: byte-equal ${same}, as expected")
  endforeach ()
  return()
endif ()

if (LCT_MODE STREQUAL "image")
  # lct-render LCT_ARGS, then its frame LCT_FRAME against the baseline LCT_BASELINE with
  # VTK's regression-image comparison (LCT_COMPARE_IMAGE, Testing/Render/CompareImage.cxx).
  lct_first_run("${LCT_OUT}" ${LCT_ARGS})
  execute_process(
    COMMAND "${LCT_COMPARE_IMAGE}" "${LCT_OUT}/${LCT_FRAME}" "${LCT_BASELINE}" "${LCT_OUT}"
    RESULT_VARIABLE rc
    OUTPUT_VARIABLE out
    ERROR_VARIABLE  err)
  message(STATUS "${out}${err}")
  if (NOT rc EQUAL 0)
    message(FATAL_ERROR "${LCT_OUT}/${LCT_FRAME} does not match ${LCT_BASELINE} (see ${LCT_OUT})")
  endif ()
  return()
endif ()

if (LCT_MODE STREQUAL "planted")
  # Temporaries under names one can foresee (.NAME.PID.part; the PID is the shell's, which
  # execs lct-render): links to a victim file and a FIFO put there first were written through
  # (the victim overwritten, the final names turned into links to it) or hung the run. The run
  # must create its temporaries new, leave the victim and the planted files alone, and finish.
  file(REMOVE_RECURSE "${LCT_OUT}")
  file(MAKE_DIRECTORY "${LCT_OUT}/out")
  file(WRITE "${LCT_OUT}/victim.txt" "precious\n")
  set(out "${LCT_OUT}/out")
  set(plant "ln -s '${LCT_OUT}/victim.txt' \"${out}/.frame_0000.png.$$.part\" && ln -s '${LCT_OUT}/victim.txt' \"${out}/.video.ogv.$$.part\" && mkfifo \"${out}/.contact_sheet.png.$$.part\" && exec \"$0\" \"$@\"")
  execute_process(
    COMMAND sh -c "${plant}" "${LCT_RENDER}" --out "${out}" --frames 2 --size 32x24 ${LCT_ARGS}
    TIMEOUT 90
    RESULT_VARIABLE rc
    OUTPUT_VARIABLE stdout
    ERROR_VARIABLE  err)
  message(STATUS "exit ${rc}\n${stdout}${err}")
  if (rc EQUAL 125)
    message(STATUS "LCT_SKIP: no DISPLAY (run under xvfb-run -a)")
    return()
  endif ()
  if (NOT rc EQUAL 0)
    message(FATAL_ERROR "lct-render exited with ${rc} (a timeout: it hung on the planted FIFO)")
  endif ()
  file(READ "${LCT_OUT}/victim.txt" victim)
  if (NOT victim STREQUAL "precious\n")
    message(FATAL_ERROR "the victim file was written through a planted link")
  endif ()
  foreach (f frame_0000.png frame_0001.png video.ogv contact_sheet.png)
    if (IS_SYMLINK "${out}/${f}" OR NOT EXISTS "${out}/${f}")
      message(FATAL_ERROR "${f} is missing or a link")
    endif ()
  endforeach ()
  file(GLOB planted "${out}/.*.part")
  list(LENGTH planted n)
  if (NOT n EQUAL 3)
    message(FATAL_ERROR "the planted files are not all there, or a temporary was left: ${planted}")
  endif ()
  return()
endif ()

if (LCT_MODE STREQUAL "links")
  # Final names that are symbolic links are written through: frame_0000.png a relative link to
  # a file not there yet, video.ogv an absolute one to an existing file, contact_sheet.png a link
  # to a link. They stay links, and what they lead to is complete. Then `assemble` refuses a FIFO
  # named video.ogv (it replaced it with a file) and leaves it.
  file(REMOVE_RECURSE "${LCT_OUT}")
  set(elsewhere "${LCT_OUT}/elsewhere")
  file(MAKE_DIRECTORY "${elsewhere}")
  file(WRITE "${elsewhere}/video.ogv" "an older video\n")
  file(CREATE_LINK "elsewhere/first.png" "${LCT_OUT}/frame_0000.png" SYMBOLIC)
  file(CREATE_LINK "${elsewhere}/video.ogv" "${LCT_OUT}/video.ogv" SYMBOLIC)
  file(CREATE_LINK "sheet.png" "${elsewhere}/sheet-link" SYMBOLIC)
  file(CREATE_LINK "elsewhere/sheet-link" "${LCT_OUT}/contact_sheet.png" SYMBOLIC)
  lct_run("${LCT_OUT}" --frames 4 --size 64x48 ${LCT_ARGS})
  if (lct_skipped)
    return()
  endif ()
  lct_expect_full("${LCT_OUT}" 4)
  foreach (pair IN ITEMS "frame_0000.png=first.png=89504e47" "video.ogv=video.ogv=4f676753"
      "contact_sheet.png=sheet.png=89504e47")
    string(REPLACE "=" ";" pair "${pair}")
    list(GET pair 0 link)
    list(GET pair 1 target)
    list(GET pair 2 magic)
    if (NOT IS_SYMLINK "${LCT_OUT}/${link}")
      message(FATAL_ERROR "${link} is no longer a symbolic link")
    endif ()
    file(READ "${elsewhere}/${target}" head HEX LIMIT 4)
    if (NOT head STREQUAL magic)
      message(FATAL_ERROR "elsewhere/${target} (through ${link}) starts with ${head}, not ${magic}")
    endif ()
  endforeach ()
  file(GLOB leftovers "${elsewhere}/.*")
  if (leftovers)
    message(FATAL_ERROR "temporary files left behind: ${leftovers}")
  endif ()
  file(REMOVE "${LCT_OUT}/video.ogv")
  execute_process(COMMAND mkfifo "${LCT_OUT}/video.ogv" RESULT_VARIABLE rc)
  if (NOT rc EQUAL 0)
    message(FATAL_ERROR "mkfifo failed")
  endif ()
  execute_process(
    COMMAND "${LCT_RENDER}" assemble "${LCT_OUT}"
    RESULT_VARIABLE rc
    OUTPUT_VARIABLE out
    ERROR_VARIABLE  err)
  message(STATUS "assemble with a FIFO named video.ogv: exit ${rc}\n${out}${err}")
  lct_contains("${err}" "${LCT_OUT}/video.ogv exists and is not a regular file" stderr)
  execute_process(COMMAND test -p "${LCT_OUT}/video.ogv" RESULT_VARIABLE not_fifo)
  file(GLOB leftovers "${LCT_OUT}/.*")
  if (NOT rc EQUAL 1 OR not_fifo OR leftovers)
    message(FATAL_ERROR "assemble did not refuse the FIFO cleanly (exit ${rc}, FIFO kept: "
      "${not_fifo} = 0, temporaries: ${leftovers})")
  endif ()
  message(STATUS "links written through, a FIFO refused")
  return()
endif ()

if (LCT_MODE STREQUAL "stale")
  # A folder of one run (64x64, 4 frames) refuses a run of another size with a message and
  # leaves its frames; frames without a manifest are refused too; --overwrite replaces them.
  lct_first_run("${LCT_OUT}" --frames 4 --size 64x64 ${LCT_ARGS})
  file(SHA256 "${LCT_OUT}/frame_0000.png" before)
  foreach (attempt IN ITEMS manifest no-manifest)
    if (attempt STREQUAL "no-manifest")
      file(REMOVE "${LCT_OUT}/manifest.json")
    endif ()
    execute_process(
      COMMAND "${LCT_RENDER}" --out "${LCT_OUT}" --frames 4 --size 80x48 ${LCT_ARGS}
      RESULT_VARIABLE rc
      ERROR_VARIABLE  err)
    message(STATUS "${attempt}: exit ${rc}, stderr: ${err}")
    if (NOT rc EQUAL 1)
      message(FATAL_ERROR "a run of another size into the folder exited with ${rc}, expected 1")
    endif ()
    if (attempt STREQUAL "manifest")
      set(phrase "it holds another run (size [64,64] there, [80,48] here)")
    else ()
      set(phrase "it holds 4 frame_*.png of a run without a manifest")
    endif ()
    lct_contains("${err}" "${phrase}" stderr)
    lct_contains("${err}" "Use another --out, or --overwrite to remove them first" stderr)
    file(SHA256 "${LCT_OUT}/frame_0000.png" after)
    file(GLOB frames "${LCT_OUT}/frame_*.png")
    list(LENGTH frames n)
    if (NOT after STREQUAL before OR NOT n EQUAL 4)
      message(FATAL_ERROR "the refused run changed the folder's frames")
    endif ()
  endforeach ()
  lct_run("${LCT_OUT}" --frames 2 --size 80x48 --overwrite ${LCT_ARGS})
  lct_contains("${out}" "--overwrite: removed 6 files of an earlier run" "--overwrite's output")
  lct_expect_full("${LCT_OUT}" 2)
  # The PNG's IHDR: width and height (big-endian) at bytes 16..23.
  file(READ "${LCT_OUT}/frame_0001.png" png HEX OFFSET 16 LIMIT 8)
  if (NOT png STREQUAL "0000005000000030")
    message(FATAL_ERROR "frame_0001.png is not 80x48 after --overwrite (IHDR ${png})")
  endif ()
  message(STATUS "a stale folder is refused, then replaced with --overwrite")
  return()
endif ()

if (LCT_MODE STREQUAL "assemble")
  # Two slices of one run (with --fps 12) into LCT_OUT/sliced: assemble refuses while a slice
  # is missing (writing nothing), then makes the contact sheet equal to a full run's, and a
  # video at the run's 12 fps, or at assemble's --fps 30.
  lct_first_run("${LCT_OUT}/full" --frames 8 --size 160x90 --fps 12 ${LCT_ARGS})
  lct_ogv_rate("${LCT_OUT}/full/video.ogv" rate)
  if (NOT rate STREQUAL "12/1")
    message(FATAL_ERROR "video.ogv of --fps 12 has the frame rate ${rate}")
  endif ()
  lct_contains("${out}" ", ETA " "the progress lines")
  lct_run("${LCT_OUT}/sliced" --frames 0:4/8 --size 160x90 --fps 12 ${LCT_ARGS})
  execute_process(
    COMMAND "${LCT_RENDER}" assemble "${LCT_OUT}/sliced"
    RESULT_VARIABLE rc
    ERROR_VARIABLE  err)
  message(STATUS "assemble with a slice missing: exit ${rc}, ${err}")
  string(FIND "${err}" "lacks 4 of 8 frames (frame_0004.png, frame_0005.png" at)
  if (NOT rc EQUAL 1 OR at EQUAL -1 OR EXISTS "${LCT_OUT}/sliced/video.ogv" OR
      EXISTS "${LCT_OUT}/sliced/contact_sheet.png")
    message(FATAL_ERROR "assemble did not refuse an incomplete run cleanly")
  endif ()
  lct_run("${LCT_OUT}/sliced" --frames 4:8/8 --size 160x90 --fps 12 ${LCT_ARGS})
  lct_contains("${out}" "holds all 8 frames of the run: `lct-render assemble" "the last slice's output")
  foreach (fps IN ITEMS "" 30)
    if (fps)
      set(args --fps ${fps})
      set(expected "${fps}/1")
    else ()
      set(args "")
      set(expected "12/1")
    endif ()
    execute_process(
      COMMAND "${LCT_RENDER}" assemble "${LCT_OUT}/sliced" ${args}
      RESULT_VARIABLE rc
      OUTPUT_VARIABLE out
      ERROR_VARIABLE  err)
    message(STATUS "assemble ${args}: exit ${rc}\n${out}${err}")
    if (NOT rc EQUAL 0)
      message(FATAL_ERROR "assemble exited with ${rc}")
    endif ()
    lct_expect_full("${LCT_OUT}/sliced" 8)
    lct_same_files("${LCT_OUT}/full/contact_sheet.png" "${LCT_OUT}/sliced/contact_sheet.png" same)
    if (NOT same)
      message(FATAL_ERROR "the assembled contact sheet differs from the full run's")
    endif ()
    lct_ogv_rate("${LCT_OUT}/sliced/video.ogv" rate)
    if (NOT rate STREQUAL expected)
      message(FATAL_ERROR "assembled video.ogv has the frame rate ${rate}, expected ${expected}")
    endif ()
  endforeach ()
  message(STATUS "two slices assembled: the full run's contact sheet, a complete video")
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
