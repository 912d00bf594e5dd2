#pragma once
// Threads kept for the whole process, so that a parallel loop does not start
// and join threads of its own each time: a run on bunny00 at n = 4,096 runs
// about 1,300 loops (a relaxation's pushes, rounds and pairs, the evening's
// sets), starting and joining a thread took 200 us on the 2-core test
// machine, and a loop on 16 threads starts 15.
//
// One caller's work at a time: a loop asked for while another runs (a loop
// inside a loop's work, as correspond's shapes run theirs, or two Python
// threads' calls at once) is refused, and its caller starts threads of its
// own as before. In a forked child, whose copy of the pool has no threads, a
// new pool starts.
#include <functional>

namespace meshparticles {

// Runs share(0) on the calling thread and share(1) .. share(helpers) on the
// pool's threads (started on first use), and returns once all have returned.
// Where the system refuses a thread, the shares past the threads it has are
// not run: each share must take work until none is left, so that any of
// them do all of it. share must not throw. False, with nothing run, where
// the pool is busy with another caller's loop: the caller runs it itself.
bool run_on_worker_pool(unsigned helpers, const std::function<void(unsigned)>& share);

}  // namespace meshparticles
