# Shared by the out-of-tree example tests (run with cmake -P): run a command or
# fail with its output, and install femto to a fresh prefix and build an
# example against it (find_package(femto)).

# run(COMMAND ... [OUTPUT_VARIABLE var]): fails the test with the command's output.
function(run)
  cmake_parse_arguments(R "" "OUTPUT_VARIABLE" "COMMAND" ${ARGN})
  execute_process(COMMAND ${R_COMMAND} RESULT_VARIABLE code OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT code EQUAL 0)
    string(REPLACE ";" " " shown "${R_COMMAND}")
    message(FATAL_ERROR "failed (exit ${code}): ${shown}\n${out}\n${err}")
  endif()
  if(R_OUTPUT_VARIABLE)
    set(${R_OUTPUT_VARIABLE} "${out}${err}" PARENT_SCOPE)
  endif()
endfunction()

# Installs the femto build tree FEMTO_BUILD_DIR to WORK_DIR/prefix and builds
# EXAMPLE_DIR in WORK_DIR/example-build with GENERATOR; sets `femto` (the
# installed executable) and `example_build` in the caller's scope.
function(install_and_build_example)
  set(prefix ${WORK_DIR}/prefix)
  set(build ${WORK_DIR}/example-build)
  file(REMOVE_RECURSE ${WORK_DIR})
  run(COMMAND ${CMAKE_COMMAND} --install ${FEMTO_BUILD_DIR} --prefix ${prefix})
  run(COMMAND ${CMAKE_COMMAND} -S ${EXAMPLE_DIR} -B ${build} -G ${GENERATOR}
      -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH=${prefix})
  run(COMMAND ${CMAKE_COMMAND} --build ${build})
  set(femto ${prefix}/bin/femto PARENT_SCOPE)
  set(example_build ${build} PARENT_SCOPE)
endfunction()

# Fails unless `femto plugins -p <example build>` lists a line matching
# PATTERN (WHAT names it in the message); sets `listing` to the output.
function(expect_listed pattern what)
  run(COMMAND ${femto} plugins -p ${example_build} OUTPUT_VARIABLE out)
  if(NOT out MATCHES "${pattern}")
    message(FATAL_ERROR "`femto plugins -p ${example_build}` does not list ${what}:\n${out}")
  endif()
  set(listing "${out}" PARENT_SCOPE)
endfunction()
