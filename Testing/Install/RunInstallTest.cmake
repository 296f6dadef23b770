# Install.FindPackage (cmake -P): install the build tree into a scratch prefix, then configure,
# build and run Testing/Install/consumer against that prefix with find_package(vtkLCT).
# Also compiles one translation unit per installed lct/*.h header (each must be self-contained),
# and runs what a user runs from the prefix in a clean environment (env -i: no LD_LIBRARY_PATH,
# no PYTHONPATH but the prefix's, cwd outside the build and the prefix): the installed lct-render
# (--help, an error, and a short render when DISPLAY is set) and the installed Python package.

foreach (var IN ITEMS LCT_BUILD_DIR LCT_WORK_DIR LCT_CONSUMER_SOURCE_DIR LCT_GENERATOR
                      LCT_HEADERS_DESTINATION LCT_INSTALL_BINDIR LCT_INSTALL_LIBDIR)
  if (NOT DEFINED ${var})
    message(FATAL_ERROR "RunInstallTest.cmake: ${var} is not set")
  endif ()
endforeach ()

set(prefix "${LCT_WORK_DIR}/prefix")
set(consumer_build "${LCT_WORK_DIR}/consumer-build")
file(REMOVE_RECURSE "${prefix}" "${consumer_build}")

function (run step)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE result)
  if (NOT result EQUAL 0)
    message(FATAL_ERROR "Install.FindPackage: ${step} failed (${result}): ${ARGN}")
  endif ()
endfunction ()

run("install" "${CMAKE_COMMAND}" --install "${LCT_BUILD_DIR}" --prefix "${prefix}")

# Public headers, including the core under lct/, must be installed.
set(include_dir "${prefix}/${LCT_HEADERS_DESTINATION}")
foreach (header IN ITEMS vtkLCTModule.h vtkLogTransform.h)
  if (NOT EXISTS "${include_dir}/${header}")
    message(FATAL_ERROR "Install.FindPackage: ${include_dir}/${header} was not installed")
  endif ()
endforeach ()
file(GLOB core_headers RELATIVE "${include_dir}" "${include_dir}/lct/*.h")
if (NOT core_headers)
  message(FATAL_ERROR "Install.FindPackage: no core headers under ${include_dir}/lct")
endif ()
set(header_check_dir "${LCT_WORK_DIR}/header-check")
file(REMOVE_RECURSE "${header_check_dir}")
foreach (header IN LISTS core_headers)
  get_filename_component(name "${header}" NAME_WE)
  file(WRITE "${header_check_dir}/Include_${name}.cxx" "#include \"${header}\"\n")
endforeach ()

run("configure consumer"
  "${CMAKE_COMMAND}" -S "${LCT_CONSUMER_SOURCE_DIR}" -B "${consumer_build}"
  -G "${LCT_GENERATOR}"
  "-DCMAKE_BUILD_TYPE=${LCT_BUILD_TYPE}"
  "-DCMAKE_C_COMPILER=${LCT_C_COMPILER}"
  "-DCMAKE_CXX_COMPILER=${LCT_CXX_COMPILER}"
  "-DCMAKE_PREFIX_PATH=${prefix}"
  "-DLCT_CONSUMER_HEADER_CHECK_DIR=${header_check_dir}")
run("build consumer" "${CMAKE_COMMAND}" --build "${consumer_build}" -j2)

# The consumer must link against the installed library, not the build tree's.
file(READ "${consumer_build}/vtkLCT_DIR.txt" found_dir)
string(STRIP "${found_dir}" found_dir)
file(REAL_PATH "${found_dir}" found_dir)
file(REAL_PATH "${prefix}" real_prefix)
string(FIND "${found_dir}" "${real_prefix}/" position)
if (NOT position EQUAL 0)
  message(FATAL_ERROR "Install.FindPackage: vtkLCT was found in ${found_dir}, not under ${prefix}")
endif ()

run("run consumer" "${consumer_build}/consumer")

# ---------------------------------------------------------------------------------------------
# What a user runs from the prefix, in a clean environment: only PATH (and, for rendering, the X
# display) is passed on, so nothing of the build tree or of ctest's environment can help the
# installed files find each other; they must do it through their own RUNPATHs.
set(clean_env env -i PATH=/usr/bin:/bin)
set(elsewhere "${LCT_WORK_DIR}/elsewhere") # the cwd: neither the build tree nor the prefix
file(REMOVE_RECURSE "${elsewhere}")
file(MAKE_DIRECTORY "${elsewhere}")

# run_clean(<step> <expected exit code> <stdout var> <stderr var> <command...>)
function (run_clean step expected out_var err_var)
  execute_process(
    COMMAND           ${clean_env} ${ARGN}
    WORKING_DIRECTORY "${elsewhere}"
    RESULT_VARIABLE   result
    OUTPUT_VARIABLE   out
    ERROR_VARIABLE    err)
  if (NOT result STREQUAL expected)
    message(FATAL_ERROR "Install.FindPackage: ${step}: exit ${result}, expected ${expected}\n"
      "command: ${clean_env} ${ARGN}\nstdout:\n${out}\nstderr:\n${err}")
  endif ()
  set(${out_var} "${out}" PARENT_SCOPE)
  set(${err_var} "${err}" PARENT_SCOPE)
endfunction ()

function (expect_nothing_written step)
  file(GLOB written LIST_DIRECTORIES true "${elsewhere}/*" "${elsewhere}/.*")
  if (written)
    message(FATAL_ERROR "Install.FindPackage: ${step} wrote into its cwd: ${written}")
  endif ()
endfunction ()

set(render "${prefix}/${LCT_INSTALL_BINDIR}/lct-render")
if (LCT_BUILD_EXAMPLES)
  if (NOT EXISTS "${render}")
    message(FATAL_ERROR "Install.FindPackage: ${render} was not installed")
  endif ()

  # The RUNPATH must be relative to the program ($ORIGIN), so that the prefix can be moved.
  find_program(readelf readelf)
  if (readelf)
    execute_process(COMMAND "${readelf}" -d "${render}" OUTPUT_VARIABLE dynamic)
    if (NOT dynamic MATCHES "\\((RUNPATH|RPATH)\\)[^\n]*\\[(\\$ORIGIN[^]\n]*)\\]")
      message(FATAL_ERROR
        "Install.FindPackage: ${render} has no $ORIGIN-relative RUNPATH:\n${dynamic}")
    endif ()
    message(STATUS "Install.FindPackage: lct-render ${CMAKE_MATCH_1} ${CMAKE_MATCH_2}")
  endif ()

  # The dynamic loader must take libvtkLCT from the prefix (not from the build tree).
  run_clean("ldd lct-render" 0 out err ldd "${render}")
  if (out MATCHES "not found")
    message(FATAL_ERROR "Install.FindPackage: installed lct-render misses libraries:\n${out}")
  endif ()
  if (NOT out MATCHES "libvtkLCT[^ \t\n]* => ([^ \t\n]+)")
    message(FATAL_ERROR "Install.FindPackage: ldd shows no libvtkLCT for lct-render:\n${out}")
  endif ()
  file(REAL_PATH "${CMAKE_MATCH_1}" loaded)
  file(REAL_PATH "${prefix}/${LCT_INSTALL_LIBDIR}" real_libdir)
  string(FIND "${loaded}" "${real_libdir}/" position)
  if (NOT position EQUAL 0)
    message(FATAL_ERROR
      "Install.FindPackage: lct-render loads ${loaded}, not one under ${real_libdir}")
  endif ()

  run_clean("lct-render --help" 0 out err "${render}" --help)
  if (NOT out MATCHES "^usage: lct-render ")
    message(FATAL_ERROR "Install.FindPackage: lct-render --help printed no usage:\n${out}${err}")
  endif ()
  expect_nothing_written("lct-render --help")

  # A missing keys file: exit 1 with its message, before any display is needed, nothing written.
  run_clean("lct-render missing.json" 1 out err "${render}" "${elsewhere}/missing.json")
  if (NOT err MATCHES "missing\\.json: cannot open keys file")
    message(FATAL_ERROR "Install.FindPackage: unexpected message for a missing keys file:\n${err}")
  endif ()
  expect_nothing_written("lct-render missing.json")

  # Rendering needs an X server (this VTK has no EGL or OSMesa): only under xvfb-run or a desktop.
  if (DEFINED ENV{DISPLAY} AND NOT "$ENV{DISPLAY}" STREQUAL "")
    set(x_env "DISPLAY=$ENV{DISPLAY}")
    if (DEFINED ENV{XAUTHORITY})
      list(APPEND x_env "XAUTHORITY=$ENV{XAUTHORITY}")
    endif ()
    run_clean("lct-render (render)" 0 out err
      ${x_env} "${render}" --frames 3 --size 64x48 --out rendered)
    foreach (file IN ITEMS frame_0000.png frame_0001.png frame_0002.png video.ogv
                           contact_sheet.png)
      set(file "${elsewhere}/rendered/${file}")
      if (NOT EXISTS "${file}")
        message(FATAL_ERROR "Install.FindPackage: the installed lct-render wrote no ${file}\n"
          "stdout:\n${out}\nstderr:\n${err}")
      endif ()
      file(SIZE "${file}" size)
      if (size EQUAL 0)
        message(FATAL_ERROR "Install.FindPackage: ${file} is empty")
      endif ()
    endforeach ()
    message(STATUS "Install.FindPackage: installed lct-render rendered 3 frames")
  else ()
    message(STATUS "Install.FindPackage: DISPLAY is not set, rendering check skipped "
      "(run ctest under xvfb-run -a, as scripts/test does)")
  endif ()
endif ()

if (LCT_WRAP_PYTHON AND LCT_PYTHON)
  # A user's script: import the package from the prefix, interpolate two transforms with both
  # classes, and check that the library mapped into the process is the prefix's.
  set(python_path "${prefix}/${LCT_PYTHON_MODULE_DESTINATION}")
  set(python_check "${LCT_WORK_DIR}/check_installed_python.py")
  file(WRITE "${python_check}" [=[
import math
import os
import sys

import vtklct
from vtklct import vtkLogTransform, vtkTransformInterpolatorLCT
from vtkmodules.vtkCommonTransforms import vtkTransform

prefix = os.path.realpath(sys.argv[1]) + os.sep


def from_prefix(name):
    return os.path.realpath(name).startswith(prefix)


assert from_prefix(vtklct.__file__), vtklct.__file__
with open("/proc/self/maps") as maps:
    libraries = {line.split()[-1] for line in maps if "libvtkLCT" in line}
assert libraries and all(from_prefix(name) for name in libraries), libraries

a = vtkTransform()
b = vtkTransform()
b.Translate(4, 0, 0)
b.RotateZ(90)
# Halfway: a 45-degree turn and half the translation.
c = math.cos(math.radians(45))
expected = [[c, -c, 0, 2], [c, c, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]

la, lb, half = vtkLogTransform(), vtkLogTransform(), vtkLogTransform()
la.SetTransform(a)
lb.SetTransform(b)
assert half.Interpolate(la, lb, 0.5) == 1

path = vtkTransformInterpolatorLCT()
assert path.AddTransform(0.0, a) == 1 and path.AddTransform(1.0, b) == 1
out = vtkTransform()
assert path.InterpolateTransform(0.5, out) == 1

for name, m in (("vtkLogTransform", half.GetMatrix()), ("vtkTransformInterpolatorLCT",
                                                         out.GetMatrix())):
    error = max(abs(m.GetElement(i, j) - expected[i][j]) for i in range(4) for j in range(4))
    assert error < 1e-12, (name, error, str(m))
print("installed vtklct", vtklct.__version__, "OK from", vtklct.__file__)
]=])
  run_clean("installed Python package" 0 out err
    "PYTHONPATH=${python_path}" "${LCT_PYTHON}" "${python_check}" "${prefix}")
  message(STATUS "Install.FindPackage: ${out}")
endif ()

message(STATUS "Install.FindPackage: OK (prefix ${prefix})")
