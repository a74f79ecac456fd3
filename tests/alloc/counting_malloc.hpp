// Counts calls to the C allocator (malloc, calloc, realloc and the aligned forms, which operator
// new and Eigen both end in) while counting is switched on. glibc only; elsewhere available() is
// false and the counts stay zero.
#pragma once

namespace jelly::testing {

bool allocation_counting_available();
void start_counting_allocations();
/// Stops counting and returns the number of allocations since start_counting_allocations().
long stop_counting_allocations();

}  // namespace jelly::testing
