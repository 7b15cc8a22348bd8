# The out-of-tree plugin workflow, end to end (run with cmake -P):
#  1. install the femto build tree to a fresh prefix,
#  2. configure and build examples/custom-integrator against it (find_package(femto)),
#  3. `femto plugins -p <example build>` must list ambient_occlusion, and the
#     installed femto must find its own installed plugins,
#  4. when RENDER is on, render the example scene with it and compare the
#     image mean with the scene's closed form.
# Inputs (-D): FEMTO_BUILD_DIR EXAMPLE_DIR WORK_DIR GENERATOR BUILTIN_PLUGIN RENDER CHECKER
cmake_minimum_required(VERSION 3.22)

include(${CMAKE_CURRENT_LIST_DIR}/sdk_common.cmake)
install_and_build_example()

expect_listed("integrator +ambient_occlusion +ambient occlusion" ambient_occlusion)
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
