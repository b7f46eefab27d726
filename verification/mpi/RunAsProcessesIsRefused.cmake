# cmake -DMPIEXEC=... -DSPH=... -DSCENE=... -DWORK=... -P this
# `mpirun -n 2 sph run SCENE` is refused with exit 2 (bad input) and a message naming the
# processes, before either process writes anything (two would write one run file).
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
execute_process(COMMAND ${MPIEXEC} -n 2 --oversubscribe ${SPH} run ${SCENE} --out ${WORK}/out
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT err MATCHES "sph run as 2 processes \\(mpirun -n 2\\)")
  message(FATAL_ERROR "no message naming the 2 processes; stderr:\n${err}")
endif()
if(rc EQUAL 0)
  message(FATAL_ERROR "mpirun -n 2 sph run exited 0")
endif()
file(GLOB_RECURSE written ${WORK}/out/*)
if(written)
  message(FATAL_ERROR "files written: ${written}")
endif()
