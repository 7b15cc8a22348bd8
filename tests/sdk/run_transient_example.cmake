# The out-of-tree transient integrator, end to end (run with cmake -P):
#  1. install the femto build tree to a fresh prefix and build
#     examples/transient-first-bounce against it (find_package(femto)),
#  2. `femto plugins -p <example build>` must list transient_first_bounce,
#  3. render its scene in both modes, strict, with two emitter pulses, and check
#     every pixel's arrival and total, and the image mean, against the scene's
#     closed form (check_first_bounce.py),
#  4. render 9 tiles on 1 and 2 threads: the volumes must be identical.
# Inputs (-D): FEMTO_BUILD_DIR EXAMPLE_DIR WORK_DIR GENERATOR PYTHON
cmake_minimum_required(VERSION 3.22)

include(${CMAKE_CURRENT_LIST_DIR}/sdk_common.cmake)
install_and_build_example()

expect_listed("integrator +transient_first_bounce +first bounce" transient_first_bounce)

set(spp 16)
# mode, pulse offset and width, window start: the window (100 bins of 0.01)
# holds every arrival (scene.xml: direct 3 to 3.47 + offset, depth 1 to 1.29).
foreach(render "direct;0;0.02;2.9" "direct;0.25;0.05;2.9" "depth;0;0.02;0.95")
  list(GET render 0 mode)
  list(GET render 1 offset)
  list(GET render 2 width)
  list(GET render 3 start)
  set(volume ${WORK_DIR}/${mode}-${offset}.npy)
  run(COMMAND ${femto} render ${EXAMPLE_DIR}/scene.xml -p ${example_build} -o ${volume} --strict --no-progress
      --seed 1 -D mode=${mode} -D spp=${spp} -D pulse_offset=${offset} -D pulse_width=${width} -D start_opl=${start})
  run(COMMAND ${PYTHON} ${CMAKE_CURRENT_LIST_DIR}/check_first_bounce.py ${volume} ${mode} ${spp} ${offset} ${width}
      OUTPUT_VARIABLE check)
  message(STATUS "pulse offset ${offset}, width ${width}: ${check}")
endforeach()

# Deterministic whatever the thread count: 96 x 96 pixels are 9 tiles of 32 x 32, rendered
# on 1 and on 2 threads.
foreach(threads 1 2)
  run(COMMAND ${femto} render ${EXAMPLE_DIR}/scene.xml -p ${example_build} -o ${WORK_DIR}/threads-${threads}.npy
      --strict --no-progress --seed 1 -t ${threads} -D spp=4 -D resolution=96)
endforeach()
run(COMMAND ${CMAKE_COMMAND} -E compare_files ${WORK_DIR}/threads-1.npy ${WORK_DIR}/threads-2.npy)
message(STATUS "the same volume on 1 and 2 threads")
