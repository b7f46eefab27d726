# sph_set_integrator(TEXT_VAR INTEGRATOR SCENE): the scene text in TEXT_VAR with [numerics]
# integrator = INTEGRATOR (nothing where INTEGRATOR is empty); SCENE names the file in the error.
function(sph_set_integrator text_var integrator scene)
  if(NOT integrator)
    return()
  endif()
  string(REPLACE "\n[numerics]\n" "\n[numerics]\nintegrator = \"${integrator}\"\n" edited
         "${${text_var}}")
  if(edited STREQUAL "${${text_var}}")
    message(FATAL_ERROR "${scene} has no [numerics] table to set the integrator in")
  endif()
  set(${text_var} "${edited}" PARENT_SCOPE)
endfunction()
