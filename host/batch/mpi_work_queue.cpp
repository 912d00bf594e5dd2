#include "batch/mpi_work_queue.hpp"

#include <mpi.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdlib>
#include <condition_variable>
#include <cstdint>
#include <iostream>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>

#include "batch/mesh_queue.hpp"
#include "batch/node_share.hpp"
#include "common/json_text.hpp"
#include "common/user_error.hpp"
#include "launch/failure.hpp"
#include "launch/mpi_session.hpp"

namespace meshparticles {

namespace {

constexpr int kOutcomeTag = 1;     // rank -> 0: its last outcome (empty at first), asking for the next mesh
constexpr int kAssignmentTag = 2;  // 0 -> rank: the mesh's index, or kNoMoreWork
constexpr int kHeartbeatTag = 3;   // rank -> 0, empty, while the rank is alive (running a mesh or not)
constexpr std::int64_t kNoMoreWork = -1;
// OpenMPI's blocking calls spin: a waiting rank would take a core from the
// ranks running meshes (on a node as full as this one, half the machine).
// Waits look every few milliseconds instead; a mesh takes seconds.
constexpr auto kPollInterval = std::chrono::milliseconds(2);

using Clock = std::chrono::steady_clock;
using Seconds = std::chrono::duration<double>;

// How often a living rank says so: often enough that `timeout` of silence
// means it is gone.
Seconds heartbeat_interval(Seconds timeout) { return std::min(Seconds(1), timeout / 5); }

void wait_without_spinning(MPI_Request& request) {
  for (int done = 0; MPI_Test(&request, &done, MPI_STATUS_IGNORE), !done;) std::this_thread::sleep_for(kPollInterval);
}

// A rank other than 0 that has given up on rank 0: MPI_Finalize would wait
// for rank 0 forever, so it leaves without it.
[[noreturn]] void leave_without_rank_zero(int rank, const std::string& why) {
  std::cerr << "meshparticles: rank " << rank << ": " << why << std::endl;
  std::_Exit(1);
}

// Ends every rank: what stops one rank's loop stops the batch, and the
// outputs already written stay valid for a resume.
[[noreturn]] void abort_batch(int rank) {
  const Failure failure = describe_failure(std::current_exception());
  std::cerr << "meshparticles: rank " << rank << ": " << (failure.internal ? "internal error: " : "error: ")
            << failure.message << "\n";
  MPI_Abort(MPI_COMM_WORLD, failure.exit_code);
  std::abort();  // MPI_Abort does not return
}

// What a rank other than 0 does when rank 0 stops answering: gives up.
struct RankZeroSilent : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// A rank other than 0: asks rank 0 for each mesh, sending the last outcome
// along, and tells rank 0 it is alive from a second thread while it runs
// meshes (MPI_THREAD_SERIALIZED: the two threads take turns through mpi_).
class RemoteQueue : public MeshQueue {
 public:
  explicit RemoteQueue(Seconds timeout)
      : timeout_(timeout), beat_every_(heartbeat_interval(timeout)), heartbeat_([this] { beat(); }) {}
  ~RemoteQueue() override {
    {
      const std::lock_guard lock(stop_mutex_);
      stopping_ = true;
    }
    stop_.notify_one();
    heartbeat_.join();
  }

  std::optional<std::size_t> next() override {
    MPI_Request sent, received;
    std::int64_t assignment = kNoMoreWork;
    {
      const std::lock_guard lock(mpi_);
      MPI_Isend(last_outcome_.data(), int(last_outcome_.size()), MPI_CHAR, 0, kOutcomeTag, MPI_COMM_WORLD, &sent);
      MPI_Irecv(&assignment, 1, MPI_INT64_T, 0, kAssignmentTag, MPI_COMM_WORLD, &received);
    }
    // Rank 0's dispatcher answers within milliseconds while it runs: a
    // silence this long means rank 0 is gone, or took this rank for dead
    // and has finished.
    const Clock::time_point deadline = Clock::now() + std::chrono::duration_cast<Clock::duration>(timeout_);
    if (!wait_until(sent, deadline) || !wait_until(received, deadline)) {
      const std::lock_guard lock(mpi_);
      if (received != MPI_REQUEST_NULL) {
        MPI_Cancel(&received);
        MPI_Wait(&received, MPI_STATUS_IGNORE);  // a cancelled receive completes at once
      }
      if (sent != MPI_REQUEST_NULL) MPI_Request_free(&sent);
      throw RankZeroSilent("rank 0 has not answered for " + std::to_string(int(timeout_.count())) +
                           " s; this rank stops (its finished outputs stay; run the batch again for the rest)");
    }
    last_outcome_.clear();
    if (assignment == kNoMoreWork) return std::nullopt;
    return std::size_t(assignment);
  }
  void finished(std::size_t index, const MeshOutcome& outcome) override {
    last_outcome_ = json_text({{"index", index}, {"row", outcome.row}, {"reused", outcome.reused}});
  }

 private:
  bool wait_until(MPI_Request& request, Clock::time_point deadline) {
    for (;;) {
      int done = 0;
      {
        const std::lock_guard lock(mpi_);
        MPI_Test(&request, &done, MPI_STATUS_IGNORE);
      }
      if (done) return true;
      if (Clock::now() > deadline) return false;
      std::this_thread::sleep_for(kPollInterval);
    }
  }

  // The heartbeat thread: an empty message to rank 0 every beat_every_, one
  // at a time, until the queue is destroyed.
  void beat() {
    MPI_Request pending = MPI_REQUEST_NULL;
    std::unique_lock stop_lock(stop_mutex_);
    while (!stop_.wait_for(stop_lock, beat_every_, [this] { return stopping_; })) {
      const std::lock_guard lock(mpi_);
      int done = 1;
      if (pending != MPI_REQUEST_NULL) MPI_Test(&pending, &done, MPI_STATUS_IGNORE);
      if (done) MPI_Isend(nullptr, 0, MPI_CHAR, 0, kHeartbeatTag, MPI_COMM_WORLD, &pending);
    }
    const std::lock_guard lock(mpi_);
    if (pending != MPI_REQUEST_NULL) MPI_Request_free(&pending);  // delivered or not, nobody waits for it
  }

  Seconds timeout_, beat_every_;
  std::string last_outcome_;
  std::mutex mpi_;
  std::mutex stop_mutex_;
  std::condition_variable stop_;
  bool stopping_ = false;
  std::thread heartbeat_;  // last: started once the members it reads exist
};

// Rank 0's second thread: records each outcome the other ranks send and
// answers with the next mesh from the queue rank 0 also works through,
// until every other rank has been told there is none left, or is taken for
// dead: not heard from (outcome or heartbeat) for `timeout`. The mesh a
// dead rank was running is recorded as failed, and the batch goes on
// without it (a resume runs that mesh again). Not another rank: a mesh that
// killed its rank (the usual cause is memory) would kill the next one too.
// A rank taken for dead that speaks again is taken back. Until rank 0's own
// meshes are done too, it sends a heartbeat to the ranks waiting for the
// end, so that they can tell a busy rank 0 from a dead one. Returns the
// number of ranks lost.
int dispatch(const BatchPlan& plan, LedgerQueue& queue, int ranks, Seconds timeout,
             const std::atomic<bool>& own_work_done) {
  enum class State { working, done, lost };
  struct Watch {
    State state = State::working;
    std::optional<std::size_t> mesh;  // the one it runs
    Clock::time_point last_heard = Clock::now();
  };
  std::vector<Watch> watch(static_cast<std::size_t>(ranks));
  int unfinished = ranks - 1;  // working ranks
  const auto note = [](const std::string& line) { std::cerr << "meshparticles: " << line << "\n"; };
  const auto beat_every = std::chrono::duration_cast<Clock::duration>(heartbeat_interval(timeout));
  Clock::time_point last_beat = Clock::now();
  while (unfinished > 0 || !own_work_done) {
    int arrived = 0;
    MPI_Status status;
    MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &arrived, &status);
    if (!arrived) {
      for (int r = 1; r < ranks; ++r) {
        Watch& rank = watch[std::size_t(r)];
        if (rank.state != State::working || Clock::now() - rank.last_heard <= timeout) continue;
        rank.state = State::lost;
        --unfinished;
        const std::string silence = "no word from rank " + std::to_string(r) + " for " +
                                    std::to_string(int(timeout.count())) + " s: taken for dead";
        if (!rank.mesh) {
          note(silence + " between meshes");
          continue;
        }
        note(silence + "; its mesh " + plan.items[*rank.mesh].output_name + " is marked failed");
        queue.finished(*rank.mesh, lost_mesh_outcome(plan, *rank.mesh,
                                                     "lost with rank " + std::to_string(r) + " (" + silence +
                                                         "); run the batch again to redo it"));
      }
      if (Clock::now() - last_beat > beat_every) {
        last_beat = Clock::now();
        for (int r = 1; r < ranks; ++r) {
          if (watch[std::size_t(r)].state != State::done) continue;
          MPI_Request sent;
          MPI_Isend(nullptr, 0, MPI_CHAR, r, kHeartbeatTag, MPI_COMM_WORLD, &sent);
          MPI_Request_free(&sent);
        }
      }
      std::this_thread::sleep_for(kPollInterval);
      continue;
    }
    Watch& rank = watch[std::size_t(status.MPI_SOURCE)];
    rank.last_heard = Clock::now();
    if (rank.state == State::lost) {
      rank.state = State::working;
      ++unfinished;
      note("rank " + std::to_string(status.MPI_SOURCE) + " is heard from again: taken back");
    }
    int length = 0;
    MPI_Get_count(&status, MPI_CHAR, &length);
    std::string message(std::size_t(length), '\0');
    MPI_Recv(message.data(), length, MPI_CHAR, status.MPI_SOURCE, status.MPI_TAG, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    if (status.MPI_TAG != kOutcomeTag) continue;  // a heartbeat
    if (!message.empty()) {
      const nlohmann::json outcome = nlohmann::json::parse(message);
      queue.finished(outcome.at("index").get<std::size_t>(), {outcome.at("row"), outcome.at("reused").get<bool>()});
    }
    rank.mesh = queue.next();
    const std::int64_t assignment = rank.mesh ? std::int64_t(*rank.mesh) : kNoMoreWork;
    MPI_Send(&assignment, 1, MPI_INT64_T, status.MPI_SOURCE, kAssignmentTag, MPI_COMM_WORLD);
    if (!rank.mesh) {
      rank.state = State::done;
      --unfinished;
    }
  }
  return int(std::count_if(watch.begin(), watch.end(), [](const Watch& w) { return w.state == State::lost; }));
}

// A rank other than 0, its meshes done: waits, without spinning, for every
// rank to be done (a barrier), or gives up when rank 0 stops sending its
// heartbeat (dead).
void wait_for_the_end(int rank, Seconds timeout) {
  MPI_Request all_done;
  MPI_Ibarrier(MPI_COMM_WORLD, &all_done);
  Clock::time_point last_heard = Clock::now();
  for (int done = 0; MPI_Test(&all_done, &done, MPI_STATUS_IGNORE), !done;) {
    int arrived = 0;
    MPI_Iprobe(0, kHeartbeatTag, MPI_COMM_WORLD, &arrived, MPI_STATUS_IGNORE);
    if (arrived) {
      MPI_Recv(nullptr, 0, MPI_CHAR, 0, kHeartbeatTag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      last_heard = Clock::now();
    } else if (Clock::now() - last_heard > timeout) {
      leave_without_rank_zero(rank, "rank 0 has not been heard from for " + std::to_string(int(timeout.count())) +
                                        " s; this rank stops (its outputs stay; run the batch again for the rest)");
    }
    std::this_thread::sleep_for(kPollInterval);
  }
}

// Plans on every rank (the same inputs give the same plan). A rank that
// cannot tells the others, and all stop instead of waiting for each other:
// rank 0 throws its own error (or names the other rank's), the others
// return nothing, printing their error only when rank 0 had none.
std::optional<BatchPlan> plan_on_every_rank(const BatchRequest& request, const MpiSession& mpi) {
  std::optional<BatchPlan> plan;
  std::exception_ptr error;
  try {
    BatchRequest own = request;
    own.quiet = request.quiet || mpi.rank != 0;  // rank 0's notes are enough
    plan = plan_batch(own, mpi.rank == 0);  // rank 0 writes the summary
    plan->request.quiet = request.quiet;          // each rank prints its meshes' warnings
    share_node(plan->request.run, mpi.node_rank, mpi.node_size);
  } catch (...) {
    error = std::current_exception();
  }
  const int own_code = error ? describe_failure(error).exit_code : 0;
  int worst_code = 0, rank0_code = own_code;
  MPI_Allreduce(&own_code, &worst_code, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  MPI_Bcast(&rank0_code, 1, MPI_INT, 0, MPI_COMM_WORLD);
  if (worst_code == 0) return plan;
  if (mpi.rank == 0) {
    if (error) std::rethrow_exception(error);
    throw UserError("another rank could not plan the batch (its message is above)", worst_code);
  }
  if (error && rank0_code == 0) {
    std::cerr << "meshparticles: rank " << mpi.rank << ": error: " << describe_failure(error).message << "\n";
  }
  return std::nullopt;
}

}  // namespace

int run_batch_across_ranks(const BatchRequest& request) {
  // Rank 0 calls MPI from its dispatcher thread while the main thread runs
  // meshes, and from the main thread only before and after.
  MpiSession mpi(MpiSession::Calls::one_at_a_time);
  const std::optional<BatchPlan> plan = plan_on_every_rank(request, mpi);
  if (!plan) return 0;
  const Seconds timeout(request.rank_timeout_seconds);
  if (mpi.rank == 0) {
    int exit_code = 0, lost = 0;
    try {
      BatchLedger ledger(*plan);
      LedgerQueue queue(biggest_first_order(*plan), ledger);
      std::atomic<bool> own_work_done{false};
      std::thread dispatcher([&] {
        try {
          lost = dispatch(*plan, queue, mpi.size, timeout, own_work_done);
        } catch (...) {
          abort_batch(mpi.rank);
        }
      });
      try {
        work_through(*plan, queue);
      } catch (...) {
        abort_batch(mpi.rank);  // before the joinable dispatcher is destroyed
      }
      own_work_done = true;
      dispatcher.join();
      exit_code = ledger.finish();
    } catch (...) {
      abort_batch(mpi.rank);
    }
    if (lost > 0) {
      // The barrier below would wait for the dead, and MPI_Finalize can hang
      // on them (OpenMPI 4.1, measured): the summary is written, so the
      // job ends here, the waiting ranks with it.
      std::cerr << "meshparticles: " << lost << " rank(s) lost: ending the job with MPI_Abort (the summary is complete)"
                << std::endl;
      MPI_Abort(MPI_COMM_WORLD, exit_code);
    }
    MPI_Request all_done;
    MPI_Ibarrier(MPI_COMM_WORLD, &all_done);
    wait_without_spinning(all_done);
    return exit_code;
  }
  std::string gave_up;
  try {
    RemoteQueue queue(timeout);
    work_through(*plan, queue);
  } catch (const RankZeroSilent& silent) {
    gave_up = silent.what();
  } catch (...) {
    abort_batch(mpi.rank);
  }
  if (!gave_up.empty()) leave_without_rank_zero(mpi.rank, gave_up);
  wait_for_the_end(mpi.rank, timeout);
  return 0;
}

}  // namespace meshparticles
