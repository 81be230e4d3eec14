# ARGINE_FUZZ=ON (scripts/fuzz.sh): every target is compiled with libFuzzer's coverage
# instrumentation and AddressSanitizer + UndefinedBehaviorSanitizer, so a fuzzed input that
# reads out of bounds, overflows or divides by zero anywhere in argine stops the fuzzer.
# Needs Clang (clang++ 14 and libclang-rt-14-dev on Debian 12, installed by scripts/setup.sh).
if(ARGINE_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang")
    message(FATAL_ERROR "ARGINE_FUZZ needs Clang (-DCMAKE_CXX_COMPILER=clang++), "
                        "not ${CMAKE_CXX_COMPILER_ID}")
  endif()
  set(ARGINE_SANITIZE_FLAGS -fsanitize=address,undefined -fno-sanitize-recover=all
                            -fno-omit-frame-pointer)
  add_compile_options(-fsanitize=fuzzer-no-link ${ARGINE_SANITIZE_FLAGS})
  add_link_options(-fsanitize=address,undefined)
endif()
