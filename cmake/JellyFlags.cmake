# Compiler flags in one place.
#
# Determinism: every target that computes simulation state is compiled with -ffp-contract=off and
# never with fast-math, so that a student's machine, the grader and CI produce the same bits for the
# same scene (GCC contracts a*b+c into an FMA by default as soon as the target has FMA).
# -fno-math-errno and -fno-trapping-math change no result (no reassociation, no contraction); they
# let sqrt inline and let loops with a select vectorise. The
# function jelly_target_defaults() applies this to a target; every simulation target calls it.

add_library(jelly_flags INTERFACE)
add_library(jelly::flags ALIAS jelly_flags)
target_compile_options(jelly_flags INTERFACE
  $<$<CXX_COMPILER_ID:GNU,Clang>:-ffp-contract=off -fno-fast-math -fno-math-errno -fno-trapping-math>
  $<$<CXX_COMPILER_ID:MSVC>:/fp:precise>)
if(JELLY_NATIVE)
  if(CMAKE_SYSTEM_PROCESSOR MATCHES "x86_64|AMD64")
    # Wider vectors, same bits: -ffp-contract=off already forbids the compiler's own fusing, and
    # -mno-fma keeps Eigen's explicit packet code (pmadd) from fusing multiply-adds either. Eigen
    # refuses AVX-512 without FMA, so the width stops at AVX2.
    target_compile_options(jelly_flags INTERFACE
      $<$<CXX_COMPILER_ID:GNU,Clang>:-march=native -mno-fma -mno-avx512f>)
  else()
    message(WARNING "JELLY_NATIVE is only tuned for x86-64; ignored on ${CMAKE_SYSTEM_PROCESSOR}")
  endif()
endif()

add_library(jelly_warnings INTERFACE)
add_library(jelly::warnings ALIAS jelly_warnings)
target_compile_options(jelly_warnings INTERFACE
  $<$<CXX_COMPILER_ID:GNU,Clang>:-Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor>
  $<$<AND:$<BOOL:${JELLY_WERROR}>,$<CXX_COMPILER_ID:GNU,Clang>>:-Werror>)

function(jelly_target_defaults target)
  target_link_libraries(${target} PRIVATE jelly::flags jelly::warnings)
endfunction()
