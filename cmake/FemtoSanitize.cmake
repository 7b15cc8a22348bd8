# FEMTO_SANITIZE=address (AddressSanitizer + UndefinedBehaviorSanitizer) or
# thread (ThreadSanitizer): every target, the plugins included, is built
# instrumented; `make sanitize` / `make sanitize-thread` build and run the
# unit tests so. ASan and TSan cannot share a process, hence two builds.
set(FEMTO_SANITIZE "" CACHE STRING "Build with sanitizers: address (ASan+UBSan) or thread (TSan); empty: none")
if(FEMTO_SANITIZE STREQUAL "address")
  # -fno-sanitize-recover: a UB finding fails the test instead of scrolling by.
  set(FEMTO_SANITIZE_FLAGS -fsanitize=address,undefined -fno-sanitize-recover=undefined -fno-omit-frame-pointer)
elseif(FEMTO_SANITIZE STREQUAL "thread")
  set(FEMTO_SANITIZE_FLAGS -fsanitize=thread -fno-omit-frame-pointer)
elseif(NOT FEMTO_SANITIZE STREQUAL "")
  message(FATAL_ERROR "FEMTO_SANITIZE is \"${FEMTO_SANITIZE}\": use address, thread or leave it empty")
endif()
if(FEMTO_SANITIZE_FLAGS)
  add_compile_options(${FEMTO_SANITIZE_FLAGS} -g)
  add_link_options(${FEMTO_SANITIZE_FLAGS})
endif()

# FEMTO_FUZZ: the libFuzzer target over the scene loader (tests/fuzz), run by
# tools/fuzz/run_scene_fuzzer.sh. Needs clang; instruments everything for
# coverage (fuzzer-no-link) with ASan + UBSan.
option(FEMTO_FUZZ "Build the libFuzzer scene-loader target (clang only)" OFF)
if(FEMTO_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "FEMTO_FUZZ needs clang (-DCMAKE_CXX_COMPILER=clang++), not ${CMAKE_CXX_COMPILER_ID}")
  endif()
  add_compile_options(-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=undefined -g)
  add_link_options(-fsanitize=address,undefined)
endif()
