// The task probes of A2's new slots (jelly/task_probe.hpp): the reference looks implemented, a
// stub-like function (no springs, no impulse, no change) and a missing slot do not.
#include <gtest/gtest.h>

#include "jelly/a2/task_table.hpp"
#include "jelly/cloth_tasks.hpp"
#include "jelly/task_probe.hpp"

namespace jelly {
namespace {

void no_springs(const ClothGrid&, std::vector<Spring>&) {}
Impulse no_impulse_ps(PointBody&, SphereBody&, const ImpulseSettings&) { return Impulse{}; }
Impulse no_impulse_ss(SphereBody&, SphereBody&, const ImpulseSettings&) { return Impulse{}; }
void no_friction(const Impulse&, double, double, double, Vec3&, Vec3&) {}

const char* const kSlots[] = {
    "add_grid_structural_springs", "add_grid_shear_springs", "add_grid_bending_springs",
    "collide_particle_sphere",     "collide_spheres",        "friction_impulse"};

TEST(ClothProbes, TheReferenceLooksImplementedInEveryNewSlot) {
  const TaskTable t = a2::task_table();
  for (const char* slot : kSlots) {
    const TaskStatus st = probe_slot(slot, "A2.Tx", "x", t);
    EXPECT_TRUE(st.implemented) << slot << ": " << st.evidence;
  }
  EXPECT_EQ(probe_slot("add_grid_structural_springs", "A2.T1", "s", t).evidence,
            "12 springs for a 3×3 cloth");
  EXPECT_EQ(probe_slot("add_grid_bending_springs", "A2.T3", "b", t).evidence,
            "6 springs for a 3×3 cloth");
}

TEST(ClothProbes, StubsAndMissingSlotsLookMissing) {
  TaskTable stub;
  cloth_tasks(stub).add_grid_structural_springs = cloth_tasks(stub).add_grid_shear_springs =
      cloth_tasks(stub).add_grid_bending_springs = &no_springs;
  cloth_tasks(stub).collide_particle_sphere = &no_impulse_ps;
  cloth_tasks(stub).collide_spheres = &no_impulse_ss;
  cloth_tasks(stub).friction_impulse = &no_friction;
  for (const char* slot : kSlots) {
    const TaskStatus st = probe_slot(slot, "A2.Tx", "x", stub);
    EXPECT_FALSE(st.implemented) << slot << ": " << st.evidence;
    EXPECT_NE(st.evidence, "function missing from the task table") << slot;
    const TaskStatus none = probe_slot(slot, "A2.Tx", "x", TaskTable{});
    EXPECT_FALSE(none.implemented) << slot;
    EXPECT_EQ(none.evidence, "function missing from the task table") << slot;
  }
  const auto slots = probe_slots();
  for (const char* slot : kSlots)
    EXPECT_NE(std::find(slots.begin(), slots.end(), std::string_view(slot)), slots.end()) << slot;
}

}  // namespace
}  // namespace jelly
