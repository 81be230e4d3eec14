# Code generation for the CPU.
#
# ARGINE_NATIVE (default ON): -march=native for every target, so that the compiler may use
# what the building machine's CPU has (AVX2 here: the time-step criteria run four points per
# instruction instead of two; about 10 % fewer instructions per point update, doc/scaling.md).
# (On an AVX-512 CPU the compiler may use AVX-512 as well.)
# Turn it OFF for a binary that must run on other CPUs than the one that builds it.
#
# -ffp-contract=off in every build: no a * b + c is fused into one rounding (FMA), so a
# native build computes the same bits as a portable one, and results do not depend on the
# machine that compiled them (the benchmark's fingerprints are the same either way).
#
# ARGINE_NATIVE_EXCLUDE: flags after -march=native that take something away again, e.g.
# "-mno-avx512f" for valgrind 3.19, which stops at the first AVX-512 instruction
# (scripts/count_instructions.sh builds so on a CPU with AVX-512).
set(ARGINE_NATIVE_EXCLUDE "" CACHE STRING "Flags after -march=native, e.g. -mno-avx512f")
include(CheckCXXCompilerFlag)
if(ARGINE_NATIVE)
  check_cxx_compiler_flag("-march=native" ARGINE_COMPILER_HAS_MARCH_NATIVE)
  if(ARGINE_COMPILER_HAS_MARCH_NATIVE)
    separate_arguments(exclude UNIX_COMMAND "${ARGINE_NATIVE_EXCLUDE}")
    add_compile_options(-march=native ${exclude})
  else()
    message(STATUS "ARGINE_NATIVE: the compiler does not take -march=native; portable code")
  endif()
endif()
add_compile_options(-ffp-contract=off)
