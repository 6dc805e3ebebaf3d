# Code generation of the engine, for every target that links numerics:
#   -fno-math-errno   sqrt and the like need not set errno, so the pair loops vectorise
#                     (measured 11 % less CPU time for fluid_sim; docs/performance.md);
#   -ffp-contract=off no fused multiply-add contractions: a build for x86-64-v3 gives bit for
#                     bit the results of a generic x86-64 build.
# NUMERICS_ARCH picks the instruction set at build time:
#   auto     x86-64-v3 (AVX2, FMA) when the compiler supports it and the building CPU runs it,
#            else the compiler's generic target (the binaries then run on any x86-64);
#   generic  the compiler's generic target;
#   other    passed as -march=<value> (e.g. native, x86-64-v2, skylake-avx512).
include(CheckCXXSourceRuns)

set(NUMERICS_ARCH "auto" CACHE STRING "Instruction set: auto, generic, or a -march value")

function(numerics_select_arch target)
  target_compile_options(${target} PUBLIC "$<$<COMPILE_LANGUAGE:CXX>:-fno-math-errno;-ffp-contract=off>")
  set(march "")
  if(NUMERICS_ARCH STREQUAL "auto")
    if(NOT CMAKE_CROSSCOMPILING AND CMAKE_SYSTEM_PROCESSOR MATCHES "x86_64|AMD64")
      set(CMAKE_REQUIRED_FLAGS "-march=x86-64-v3")
      set(CMAKE_REQUIRED_QUIET ON)
      # Compiled for x86-64-v3 and run here: fails (or faults) where the CPU lacks it.
      check_cxx_source_runs([[
        #include <cmath>
        int main(int argc, char**) {
          if (!__builtin_cpu_supports("avx2") || !__builtin_cpu_supports("fma") ||
              !__builtin_cpu_supports("bmi2"))
            return 1;
          double s = 0;
          for (int i = 0; i < 64; ++i) s += std::sqrt(double(i + argc));
          return s > 0 ? 0 : 1;
        }]] NUMERICS_CPU_RUNS_X86_64_V3)
      if(NUMERICS_CPU_RUNS_X86_64_V3)
        set(march "x86-64-v3")
      endif()
    endif()
  elseif(NOT NUMERICS_ARCH STREQUAL "generic")
    set(march "${NUMERICS_ARCH}")
  endif()
  if(march)
    target_compile_options(${target} PUBLIC $<BUILD_INTERFACE:$<$<COMPILE_LANGUAGE:CXX>:-march=${march}>>)
  endif()
  set(NUMERICS_SELECTED_ARCH "${march}" PARENT_SCOPE)
  if(march)
    message(STATUS "numerics: instruction set -march=${march} (NUMERICS_ARCH=${NUMERICS_ARCH})")
  else()
    message(STATUS "numerics: instruction set generic (NUMERICS_ARCH=${NUMERICS_ARCH})")
  endif()
endfunction()
