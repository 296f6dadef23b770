# Install.FindPackage (cmake -P): install the build tree into a scratch prefix, then configure,
# build and run Testing/Install/consumer against that prefix with find_package(vtkLCT).
# Also compiles one translation unit per installed lct/*.h header (each must be self-contained).

foreach (var IN ITEMS LCT_BUILD_DIR LCT_WORK_DIR LCT_CONSUMER_SOURCE_DIR LCT_GENERATOR
                      LCT_HEADERS_DESTINATION)
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

if (LCT_WRAP_PYTHON AND LCT_PYTHON)
  # No ';' in the snippet: CMake would split the argument there.
  set(ENV{PYTHONPATH} "${prefix}/${LCT_PYTHON_MODULE_DESTINATION}")
  run("import installed Python package" "${LCT_PYTHON}" -c "
import vtklct
from vtklct import vtkLogTransform
assert vtklct.__file__.startswith('${prefix}/'), vtklct.__file__
print('installed vtklct OK:', vtkLogTransform().GetClassName(), 'from', vtklct.__file__)
")
endif ()

message(STATUS "Install.FindPackage: OK (prefix ${prefix})")
