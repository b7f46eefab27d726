# cmake -DMPIEXEC=... -DSPH=... -DSCENE=... -DEND_TIME=T -DSTOP_AT=S -DWRITERS=a -DREADERS=b
#       -DPYTHON=... -DCOMPARE=... -DWORK=... [-DINTEGRATOR=...] -P this
# A checkpoint written by `sph run` on WRITERS processes (stopped at STOP_AT) continues on READERS
# processes (1: plain `sph run --restart`) to END_TIME, and the continued run file is the one an
# uninterrupted one-process run writes, to the bit (perf/compare_runs.py): the checkpoint is one
# process's whatever the count that wrote it.
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
file(READ ${SCENE} text)
string(REGEX REPLACE "\nend_time = [^\n]*" "\nend_time = ${END_TIME}" text "${text}")
include(${CMAKE_CURRENT_LIST_DIR}/SceneIntegrator.cmake)
sph_set_integrator(text "${INTEGRATOR}" ${SCENE})
get_filename_component(name ${SCENE} NAME_WLE)  # the scene name
file(WRITE ${WORK}/${name}.toml "${text}")
function(sph processes)
  if(processes EQUAL 1)
    set(launch)
  else()
    set(launch ${MPIEXEC} -n ${processes} --oversubscribe)
  endif()
  execute_process(COMMAND ${launch} ${SPH} run ${ARGN} --threads 1 --quiet
    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "sph run ${ARGN} on ${processes}: exit ${rc}\n${out}\n${err}")
  endif()
endfunction()
sph(1 ${WORK}/${name}.toml --out ${WORK}/whole)
sph(${WRITERS} ${WORK}/${name}.toml --out ${WORK}/cut --stop-at ${STOP_AT})
if(NOT EXISTS ${WORK}/cut/${name}.checkpoint.h5)
  message(FATAL_ERROR "no checkpoint after --stop-at on ${WRITERS} processes")
endif()
sph(${READERS} --restart ${WORK}/cut/${name}.checkpoint.h5)
execute_process(COMMAND ${PYTHON} ${COMPARE} ${WORK}/whole/${name}.h5 ${WORK}/cut/${name}.h5
  RESULT_VARIABLE rc OUTPUT_VARIABLE cmp ERROR_VARIABLE cmperr)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "written on ${WRITERS}, continued on ${READERS}: the run files differ: "
                      "${cmp}${cmperr}")
endif()
message(STATUS "written on ${WRITERS}, continued on ${READERS}: ${cmp}")
