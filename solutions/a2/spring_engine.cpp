// The A2 reference's fast spring engine: A1's (solutions/a1/spring_engine.cpp), compiled in
// namespace jelly::a2 with A2's spring and damper forces, not copied. A cloth's spring types are
// index offsets too (structural 1 and n, shear n ± 1, bending 2 and 2n), so its dense runs apply.
// Speed: docs/performance.md.
#include "jelly/a2/spring_engine.hpp"
#include "jelly/a2/forces.hpp"

// GCC takes an included .cpp for a header and warns that the engine's class holds types of the
// file's anonymous namespace; here that file is this translation unit's own code.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wsubobject-linkage"
#endif

#define JELLY_SPRING_ENGINE_NAMESPACE a2
#include "../a1/spring_engine.cpp"  // NOLINT(bugprone-suspicious-include): one engine, two uses
