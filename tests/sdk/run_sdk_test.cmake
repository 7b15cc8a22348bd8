# The out-of-tree plugin workflow, end to end (run with cmake -P):
#  1. install the femto build tree to a fresh prefix,
#  2. configure and build examples/custom-integrator against it (find_package(femto)),
#  3. `femto plugins -p <example build>` must list ambient_occlusion, and the
#     installed femto must find its own installed plugins,
#  4. when RENDER is on, render the example scene with it and compare the
#     image mean with the scene's closed form.
# Inputs (-D): FEMTO_BUILD_DIR EXAMPLE_DIR WORK_DIR GENERATOR BUILTIN_PLUGIN RENDER CHECKER
cmake_minimum_required(VERSION 3.22)

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

set(prefix ${WORK_DIR}/prefix)
set(example_build ${WORK_DIR}/example-build)
file(REMOVE_RECURSE ${WORK_DIR})

run(COMMAND ${CMAKE_COMMAND} --install ${FEMTO_BUILD_DIR} --prefix ${prefix})
run(COMMAND ${CMAKE_COMMAND} -S ${EXAMPLE_DIR} -B ${example_build} -G ${GENERATOR}
    -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH=${prefix})
run(COMMAND ${CMAKE_COMMAND} --build ${example_build})

set(femto ${prefix}/bin/femto)
run(COMMAND ${femto} plugins -p ${example_build} OUTPUT_VARIABLE listing)
if(NOT listing MATCHES "integrator +ambient_occlusion +ambient occlusion")
  message(FATAL_ERROR "`femto plugins -p ${example_build}` does not list ambient_occlusion:\n${listing}")
endif()
if(BUILTIN_PLUGIN AND NOT listing MATCHES "[a-z]+ +${BUILTIN_PLUGIN} ")
  message(FATAL_ERROR "the installed femto does not find its installed plugin ${BUILTIN_PLUGIN}:\n${listing}")
endif()
message(STATUS "femto plugins lists the out-of-tree plugin")

if(RENDER)
  set(image ${WORK_DIR}/ambient_occlusion.exr)
  run(COMMAND ${femto} render ${EXAMPLE_DIR}/scene.xml -p ${example_build} -o ${image} --strict --no-progress
      --seed 1 -D spp=4 -D max_distance=2)
  # AO = (h/d)^2 = 0.25; 4 pixel samples x 4 occlusion rays per pixel (see scene.xml).
  run(COMMAND ${CHECKER} ${image} 0.25 16 OUTPUT_VARIABLE check)
  message(STATUS "rendered with the out-of-tree integrator: ${check}")
else()
  message(STATUS "render step skipped: this build lacks the plugins the example scene needs")
endif()
