#pragma once
/// Runs independent jobs on a few threads: the one place that starts worker
/// threads for a loop over jobs. Its users:
///   - parallel_for: the bound windows and effect candidates of diagnose/
///     (diagnose/diagnose.cc, diagnose/effect_ranking.cc), and the chunks of
///     rows of one Bareiss elimination step (verify/psd/psd_bareiss.cc);
///   - parallel_for_with_scratch: the primes of the multi-modular PSD decision,
///     one residue matrix per worker (verify/psd/psd_modular.cc);
///   - default_thread_count: the default thread counts of lpvid diagnose
///     (cli/diagnose_command.cc) and of the exact PSD decision
///     (verify/psd/psd_internal.h, resolve_threads).
///
/// Job i writes only its own result slot, so the results are in the same
/// order, and the same numbers, as a sequential run: nothing a job computes
/// depends on which thread ran it or when. Shared backends that are not
/// thread-safe serialise themselves (solvers/sdp_solver.cc holds one
/// process-wide mutex around every SDP solve: CSDP keeps static work arrays
/// and the OpenBLAS thread count is process state).

#include <cstddef>
#include <functional>
#include <vector>

namespace lpvid {

/// std::thread::hardware_concurrency(), at least 1.
unsigned default_thread_count();

/// True on a thread that runs jobs of a parallel_for with several workers:
/// the cores are taken, so the structured barrier's default (its helper
/// thread, lmi/delta_form_barrier.h) stays on one thread there.
bool inside_parallel_jobs();

namespace parallel_detail {

/// The number of workers that run `count` jobs with at most `threads` at
/// once: min(threads, count), and 1 for the sequential run (threads ≤ 1 or
/// count ≤ 1; 0 when count is 0).
std::size_t worker_count(std::size_t count, unsigned threads);

/// Calls job(w, i) for i = 0 … count − 1 on worker_count(count, threads)
/// workers w = 0, 1, …; worker 0 is the calling thread, the others are
/// threads started here and joined before it returns. Jobs are handed out in
/// index order. Sequential run: in order on the calling thread, a throwing
/// job ends the loop. Else, if jobs throw, every job still runs, every thread
/// is joined and the exception of the lowest job index is rethrown (as a
/// sequential run would throw first).
void run_jobs(std::size_t count, unsigned threads, const std::function<void(std::size_t, std::size_t)>& job);

}  // namespace parallel_detail

/// Calls job(0) … job(count − 1), at most `threads` at once (threads ≤ 1:
/// in order on the calling thread). Jobs are handed out in index order. If
/// jobs throw, every thread is joined and the exception of the lowest job
/// index is rethrown (as a sequential run would throw first).
void parallel_for(std::size_t count, unsigned threads, const std::function<void(std::size_t)>& job);

/// parallel_for with one default-constructed Scratch per worker: job(i, s)
/// gets the scratch of the worker that runs job i, reused (not cleared) by
/// that worker's later jobs and never seen by another worker at the same
/// time. For working memory that should be allocated once per worker, not
/// once per job (the residue matrices of verify/psd/psd_modular.cc). Same
/// order, thread counts and exceptions as parallel_for.
template <typename Scratch, typename Job>
void parallel_for_with_scratch(std::size_t count, unsigned threads, Job&& job) {
  std::vector<Scratch> scratch(parallel_detail::worker_count(count, threads));
  parallel_detail::run_jobs(count, threads,
                            [&](std::size_t worker, std::size_t i) { job(i, scratch[worker]); });
}

}  // namespace lpvid
