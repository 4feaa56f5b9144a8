# cmake -DBUILD_DIR=... -DSCRATCH=... -DEXAMPLES=... -DDATA=... -DVTK_DIR=... -DGENERATOR=...
#       [-DPYTHON=... -DPY_DEST=...] -DLIBDIR=... -DBINDIR=... -DWITH_CLI=0|1
#       [-DPLUGIN=QuadCover.so -DPLUGIN_DIR=lib/paraview-5.11/plugins/QuadCover -DPVPYTHON=...]
#       -P TestInstall.cmake
function(run what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if (NOT rc EQUAL 0)
    message(FATAL_ERROR "${what} failed (${rc}):\n${out}\n${err}")
  endif ()
  set(last_output "${out}" PARENT_SCOPE)
endfunction()

file(REMOVE_RECURSE "${SCRATCH}")
set(prefix "${SCRATCH}/prefix")
run("cmake --install" "${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${prefix}")
foreach (header vtkQuadCoverSolver.h vtkQuadCoverArrayNames.h vtkQuadCoverReader.h)
  if (NOT EXISTS "${prefix}/include/quadcover/${header}")
    message(FATAL_ERROR "${header} is not installed")
  endif ()
endforeach ()
if (EXISTS "${prefix}/include/quadcover/vtkQuadCoverEigen.h")
  message(FATAL_ERROR "the private header vtkQuadCoverEigen.h is installed")
endif ()

run("configure the examples" "${CMAKE_COMMAND}" -S "${EXAMPLES}" -B "${SCRATCH}/examples"
  -G "${GENERATOR}" -DCMAKE_BUILD_TYPE=Release "-DCMAKE_PREFIX_PATH=${prefix}"
  "-DVTK_DIR=${VTK_DIR}")
run("build the examples" "${CMAKE_COMMAND}" --build "${SCRATCH}/examples" -j 2)

# The C++ example: a sphere becomes a closed all-quad mesh with 8 valence-3 vertices.
run("the C++ example" "${SCRATCH}/examples/remesh" "${DATA}/sphere.obj" "${SCRATCH}/sphere.obj"
  600)
if (NOT last_output MATCHES "8 irregular inner vertices.*Euler characteristic 2")
  message(FATAL_ERROR "unexpected figures from the C++ example: ${last_output}")
endif ()

# The installed command line finds its libraries without help.
if (WITH_CLI)
  run("the installed command line" "${prefix}/${BINDIR}/quadcover" "${DATA}/sphere.obj"
    -o "${SCRATCH}/cli.vtp" --target-quad-count 600 --stats "${SCRATCH}/cli.json")
  file(READ "${SCRATCH}/cli.json" stats)
  if (NOT stats MATCHES "\"euler_characteristic\": 2")
    message(FATAL_ERROR "unexpected statistics from the installed command line: ${stats}")
  endif ()
endif ()

# The Python example from the installed package.
if (PYTHON AND PY_DEST)
  run("the Python example" "${CMAKE_COMMAND}" -E env "PYTHONPATH=${prefix}/${PY_DEST}"
    "${PYTHON}" "${EXAMPLES}/Python/remesh.py" "${DATA}/sphere.obj" "${SCRATCH}/py.obj"
    --quads 600)
  if (NOT last_output MATCHES "8 irregular inner vertices.*Euler characteristic 2")
    message(FATAL_ERROR "unexpected figures from the Python example: ${last_output}")
  endif ()
endif ()
# The installed plugin finds the installed libraries without help.
if (PLUGIN AND PVPYTHON)
  set(plugin "${prefix}/${PLUGIN_DIR}/${PLUGIN}")
  if (NOT EXISTS "${plugin}")
    message(FATAL_ERROR "the ParaView plugin is not installed as ${plugin}")
  endif ()
  run("the installed plugin" "${PVPYTHON}" -c "
from paraview.simple import *
from paraview import servermanager
LoadPlugin('${plugin}', remote=False, ns=globals())
q = QuadCoverRemesh(Input=Triangulate(Input=Sphere(ThetaResolution=32, PhiResolution=32)))
q.TargetQuadCount = 300
print('Euler characteristic', servermanager.Fetch(q).GetFieldData().GetArray('EulerCharacteristic').GetValue(0))
")
  if (NOT last_output MATCHES "Euler characteristic 2")
    message(FATAL_ERROR "unexpected output of the installed plugin: ${last_output}")
  endif ()
endif ()
message(STATUS "installed QuadCover: the examples build and run")
