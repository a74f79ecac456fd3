// Student tasks A2.T4–A2.T5: the force of one spring and of its damper (cloth contract §2, which
// is physics contract §2). The framework applies them to every spring of the cloth.
// Handout: assignments/a2/handout/T4-spring-force.md, T5-damper-force.md.
#pragma once

#include "jelly/types.hpp"

namespace jelly::a2 {

/// A2.T4 — Hooke's force on particle a of a spring a–b: f = −ks (|d| − rest) d/|d|, d = x_a − x_b.
/// Zero when |d| < degenerate_length (or |d| = 0): such a spring has no direction.
Vec3 spring_force(const Vec3& xa, const Vec3& xb, double ks, double rest_length,
                  double degenerate_length);

/// A2.T5 — The damper's force on particle a: f = −kd ((v_a − v_b)·u) u, u = d/|d|.
/// Zero when |d| < degenerate_length (or |d| = 0).
Vec3 damper_force(const Vec3& xa, const Vec3& xb, const Vec3& va, const Vec3& vb, double kd,
                  double degenerate_length);

}  // namespace jelly::a2
