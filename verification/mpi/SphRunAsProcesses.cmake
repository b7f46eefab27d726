# cmake -DMPIEXEC=... -DSPH=... -DSCENE=... -DRANKS=N -DEND_TIME=T -DPYTHON=... -DCOMPARE=...
#       -DWORK=... [-DINTEGRATOR=...] -P this
# `mpirun -n N sph run SCENE` writes the run file one process writes, to the bit (every series,
# snapshot and metric but the timings: perf/compare_runs.py), and nothing else: the same files
# in its output directory. The scene is run to END_TIME (a copy of it with that end_time, and
# with [numerics] integrator = INTEGRATOR if given).
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
file(READ ${SCENE} text)
string(REGEX REPLACE "\nend_time = [^\n]*" "\nend_time = ${END_TIME}" text "${text}")
include(${CMAKE_CURRENT_LIST_DIR}/SceneIntegrator.cmake)
sph_set_integrator(text "${INTEGRATOR}" ${SCENE})
get_filename_component(name ${SCENE} NAME)
file(WRITE ${WORK}/${name} "${text}")
execute_process(COMMAND ${SPH} run ${WORK}/${name} --out ${WORK}/one --threads 1
  RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "sph run as one process: exit ${rc}\n${err}")
endif()
execute_process(COMMAND ${MPIEXEC} -n ${RANKS} --oversubscribe ${SPH} run ${WORK}/${name}
  --out ${WORK}/many --threads 1 RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "mpirun -n ${RANKS} sph run: exit ${rc}\n${out}\n${err}")
endif()
if(NOT out MATCHES "${RANKS} processes \\(MPI\\)")
  message(FATAL_ERROR "the summary does not say ${RANKS} processes:\n${out}")
endif()
file(GLOB one RELATIVE ${WORK}/one ${WORK}/one/*)
file(GLOB many RELATIVE ${WORK}/many ${WORK}/many/*)
if(NOT one STREQUAL many)
  message(FATAL_ERROR "one process wrote [${one}], ${RANKS} processes [${many}]")
endif()
file(GLOB h5 RELATIVE ${WORK}/one ${WORK}/one/*.h5)
execute_process(COMMAND ${PYTHON} ${COMPARE} ${WORK}/one/${h5} ${WORK}/many/${h5}
  RESULT_VARIABLE rc OUTPUT_VARIABLE cmp ERROR_VARIABLE cmperr)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "the run files differ: ${cmp}${cmperr}")
endif()
message(STATUS "${RANKS} processes: ${cmp}")
