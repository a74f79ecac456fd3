// Student tasks A1.T4–A1.T5: spring and damper forces (physics contract §2).
// Handout: assignments/a1/handout/T4-spring-force.md, T5-damper-force.md.
#pragma once

#include "jelly/spring.hpp"
#include "jelly/types.hpp"

namespace jelly::a1 {

/// A1.T4 — Force of a spring on its particle a [N].
///   d = x_a − x_b,  u = d / |d|,  f = −ks (|d| − rest_length) u.
/// When |d| < degenerate_length the spring has no direction: return zero (never NaN).
/// The force on b is the negative of the returned value.
Vec3 spring_force(const Vec3& xa, const Vec3& xb, double ks, double rest_length,
                  double degenerate_length);

/// A1.T5 — Force of a damper (along the spring) on its particle a [N].
///   u = (x_a − x_b) / |x_a − x_b|,  f = −kd ((v_a − v_b) · u) u.
/// When |x_a − x_b| < degenerate_length return zero (never NaN).
Vec3 damper_force(const Vec3& xa, const Vec3& xb, const Vec3& va, const Vec3& vb, double kd,
                  double degenerate_length);

}  // namespace jelly::a1
