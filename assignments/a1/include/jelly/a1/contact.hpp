// Student tasks A1.T8–A1.T9: contact and friction forces (physics contract §5).
// Handout: assignments/a1/handout/T8-plane-contact.md, T9-bowl-contact.md.
#pragma once

#include "jelly/terrain.hpp"
#include "jelly/types.hpp"

namespace jelly::a1 {

/// A1.T8 — Contact force on one particle resting on a plane. `f` holds the total force on the
/// particle from every other effect (gravity, springs, dampers, earlier terrains) [N].
/// In contact when φ < ε, N·v < ε, N·f < 0 and outside the hole. Then
///   f_c = −(N·f) N,  f_f = −k_f (−N·f) v_T  (v_T = v − (N·v) N),  f ← f + f_c + f_f.
/// Returns true when the particle was in contact (f was changed).
bool contact_plane(const Plane& plane, const Vec3& x, const Vec3& v, Vec3& f);

/// A1.T9 — Contact force on one particle resting in a bowl: as contact_plane with the bowl's
/// inward normal, φ and extent (see collide_bowl). Returns true when in contact.
bool contact_bowl(const Bowl& bowl, const Vec3& x, const Vec3& v, Vec3& f);

}  // namespace jelly::a1
