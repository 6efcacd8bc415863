#pragma once
/// Runs independent jobs on a few threads (the bound windows of diagnose/bound_windows.h).
///
/// Job i writes only its own result slot, so the results are in the same
/// order, and the same numbers, as a sequential run: nothing a job computes
/// depends on which thread ran it or when. Shared backends that are not
/// thread-safe serialise themselves (solvers/sdp_solver.cc holds one
/// process-wide mutex around every SDP solve: CSDP keeps static work arrays
/// and the OpenBLAS thread count is process state).

#include <cstddef>
#include <functional>

namespace lpvid {

/// std::thread::hardware_concurrency(), at least 1.
unsigned default_thread_count();

/// Calls job(0) … job(count − 1), at most `threads` at once (threads ≤ 1:
/// in order on the calling thread). Jobs are handed out in index order. If
/// jobs throw, every thread is joined and the exception of the lowest job
/// index is rethrown (as a sequential run would throw first).
void parallel_for(std::size_t count, unsigned threads, const std::function<void(std::size_t)>& job);

}  // namespace lpvid
