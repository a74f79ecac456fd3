// The TaskTable slots that take a cube lattice (physics contract §2): the cube kind's part of an
// assignment's task table (TaskTable::kinds), filled by an assignment's bindings and called by
// CubePhysics and the cube's probes.
#pragma once

#include <vector>

#include "jelly/cube.hpp"
#include "jelly/spring.hpp"
#include "jelly/task_table.hpp"

namespace jelly {

/// Spring builders of a cube lattice; null where the assignment has no such task.
struct CubeTasks {
  void (*add_structural_springs)(const CubeLattice&, std::vector<Spring>&) = nullptr;
  void (*add_shear_springs)(const CubeLattice&, std::vector<Spring>&) = nullptr;
  void (*add_bending_springs)(const CubeLattice&, std::vector<Spring>&) = nullptr;
};

/// The table's cube slots, made (all null) on first use.
inline CubeTasks& cube_tasks(TaskTable& t) { return t.kinds.get<CubeTasks>(); }
/// The table's cube slots, all null when the table has none.
inline const CubeTasks& cube_tasks(const TaskTable& t) {
  return t.kinds.get_or_default<CubeTasks>();
}

}  // namespace jelly
