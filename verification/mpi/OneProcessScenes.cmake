# cmake -DMPIEXEC=... -DSPH=... -DSCENE=... -DWORK=... -P this
# A scene that runs as one process only (particle shifting; velocity Verlet, whose carried rates do
# not migrate: solver/src/mpi/DESIGN-MPI.md) launched as two processes ends in exit 2 naming the
# file and what it has, before any output is written.
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
file(READ ${SCENE} text)
foreach(case "shifting" "integrator")
  if(case STREQUAL "shifting")
    string(REPLACE "\n[physics]\n" "\n[physics]\nshifting = \"lind\"\n" edited "${text}")
    set(named "particle shifting")
  else()
    string(REPLACE "\n[numerics]\n" "\n[numerics]\nintegrator = \"velocity_verlet\"\n" edited
           "${text}")
    set(named "integrator = \"velocity_verlet\"")
  endif()
  if(edited STREQUAL text)
    message(FATAL_ERROR "${SCENE} has no section to add ${case} to")
  endif()
  file(WRITE ${WORK}/${case}.toml "${edited}")
  execute_process(COMMAND ${MPIEXEC} -n 2 --oversubscribe ${SPH} run ${WORK}/${case}.toml
    --out ${WORK}/out_${case} --threads 1 RESULT_VARIABLE rc OUTPUT_VARIABLE out
    ERROR_VARIABLE err)
  if(rc EQUAL 0)
    message(FATAL_ERROR "mpirun -n 2 sph run with ${named}: exit 0, expected a refusal")
  endif()
  string(FIND "${err}" "${WORK}/${case}.toml: a scene with ${named} runs as one process" at)
  if(at LESS 0)
    message(FATAL_ERROR "the refusal does not name the file and ${named}:\n${err}")
  endif()
  file(GLOB written ${WORK}/out_${case}/*)
  if(written)
    message(FATAL_ERROR "a refused run wrote ${written}")
  endif()
  message(STATUS "${case}: refused as two processes")
endforeach()
