// The grader's one worker pool: a batch's submissions, the mutants, a submission's cases and its
// compiler runs all go through parallel_for.
#pragma once

#include <cstddef>
#include <functional>

namespace jelly::grade {

/// The number of workers `jobs` asks for: `jobs` when positive, else one per core (at least one).
int worker_count(int jobs);

/// Calls body(0) ... body(count - 1), each exactly once, on worker_count(jobs) threads at most
/// (never more than `count`; when no thread can be started, on the caller's); indices are handed
/// out in increasing order as workers come free, so the first ones start first. Returns when every
/// call has returned.
///
/// Exceptions: a body should catch what it can explain (each call site turns a failure into its
/// own item's result: a failed test, a student's "grader error" row, a compiler message). One that
/// escapes never ends the process (an exception leaving a std::thread would call std::terminate):
/// the worker records it and goes on with the next index, every other index still runs, and after
/// all have finished the exception of the lowest index that threw is rethrown here, on the
/// caller's thread, where the command's own error handling reports it.
void parallel_for(std::size_t count, int jobs, const std::function<void(std::size_t)>& body);

}  // namespace jelly::grade
