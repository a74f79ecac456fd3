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
#
# Every compiler family is named: Apple's clang reports the id "AppleClang", not "Clang", and its
# default is -ffp-contract=on (fuse within an expression), which on Apple silicon (always FMA)
# gives other bits. MSVC: /fp:precise never contracts on x64 unless /arch:AVX2 is added (do not).
# Source files are UTF-8 (°, ×, ² in messages): MSVC reads them as such only with /utf-8.
target_compile_options(jelly_flags INTERFACE
  $<$<CXX_COMPILER_ID:GNU,Clang,AppleClang>:-ffp-contract=off -fno-fast-math -fno-math-errno -fno-trapping-math>
  $<$<CXX_COMPILER_ID:MSVC>:/fp:precise /utf-8>)
# Eigen's own packet code is off on every platform (EIGEN_DONT_VECTORIZE, defined on the Eigen3::Eigen
# target in cmake/JellyDeps.cmake so that every user of Eigen sees it): its SSE2 path rounds other
# bits than its scalar path, and its NEON pmadd fuses multiply-adds on ARM64 whatever the flags say.
if(JELLY_NATIVE)
  if(CMAKE_SYSTEM_PROCESSOR MATCHES "x86_64|AMD64")
    # Wider vectors, same bits: -ffp-contract=off already forbids the compiler's own fusing, and
    # -mno-fma keeps FMA out of any code that asks for it explicitly (intrinsics, a library's
    # packet code). -mno-avx512f keeps the width at AVX2, the widest tests/determinism checks.
    target_compile_options(jelly_flags INTERFACE
      $<$<CXX_COMPILER_ID:GNU,Clang,AppleClang>:-march=native -mno-fma -mno-avx512f>)
  else()
    message(WARNING "JELLY_NATIVE is only tuned for x86-64; ignored on ${CMAKE_SYSTEM_PROCESSOR}")
  endif()
endif()

add_library(jelly_warnings INTERFACE)
add_library(jelly::warnings ALIAS jelly_warnings)
target_compile_options(jelly_warnings INTERFACE
  $<$<CXX_COMPILER_ID:GNU,Clang,AppleClang>:-Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor>
  $<$<AND:$<BOOL:${JELLY_WERROR}>,$<CXX_COMPILER_ID:GNU,Clang,AppleClang>>:-Werror>)

function(jelly_target_defaults target)
  target_link_libraries(${target} PRIVATE jelly::flags jelly::warnings)
endfunction()
