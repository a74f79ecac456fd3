// Prints the state hash of the course scene after 2 s (through first contact at ≈ 1.4 s, where a
// last-bit difference would grow to millimetres) for the integrators whose update is element-wise.
#include <cstdio>

#include "jelly/a1/task_table.hpp"
#include "jelly/recorder.hpp"
#include "jelly/simulator.hpp"
#include "scenes_in_code.hpp"

int main() {
#if defined(__x86_64__) && defined(__AVX2__)
  if (!__builtin_cpu_supports("avx2")) return 77;
#endif
  using namespace jelly;
  for (IntegratorKind kind : {IntegratorKind::ExplicitEuler, IntegratorKind::RK4,
                              IntegratorKind::SymplecticEuler, IntegratorKind::Midpoint}) {
    Simulator sim(build_world(jelly::testing::course_2023(kind), a1::task_table()), {kind, 0.001});
    sim.run_until(2.0);
    std::printf("%s %016llx\n", std::string(to_string(kind)).c_str(),
                static_cast<unsigned long long>(state_hash(sim.state())));
  }
  return 0;
}
