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
