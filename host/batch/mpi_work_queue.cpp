#include "batch/mpi_work_queue.hpp"

#include <mpi.h>

#include <chrono>
#include <cstdint>
#include <iostream>
#include <stdexcept>
#include <thread>

#include "batch/failure.hpp"
#include "batch/mesh_queue.hpp"
#include "batch/node_share.hpp"
#include "common/user_error.hpp"

namespace meshparticles {

namespace {

constexpr int kOutcomeTag = 1;     // rank -> 0: its last outcome (empty at first), asking for the next mesh
constexpr int kAssignmentTag = 2;  // 0 -> rank: the mesh's index, or kNoMoreWork
constexpr std::int64_t kNoMoreWork = -1;
// OpenMPI's blocking calls spin: a waiting rank would take a core from the
// ranks running meshes (on a node as full as this one, half the machine).
// Waits look every few milliseconds instead; a mesh takes seconds.
constexpr auto kPollInterval = std::chrono::milliseconds(2);

class MpiSession {
 public:
  MpiSession() {
    int provided = 0;
    // Rank 0 calls MPI from its dispatcher thread while the main thread runs
    // meshes, and from the main thread only before and after: serialized.
    MPI_Init_thread(nullptr, nullptr, MPI_THREAD_SERIALIZED, &provided);
    if (provided < MPI_THREAD_SERIALIZED) {
      MPI_Finalize();
      throw std::runtime_error("the MPI library does not allow MPI calls from a second thread");
    }
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &size);
    MPI_Comm node;
    MPI_Comm_split_type(MPI_COMM_WORLD, MPI_COMM_TYPE_SHARED, rank, MPI_INFO_NULL, &node);
    MPI_Comm_rank(node, &node_rank);
    MPI_Comm_size(node, &node_size);
    MPI_Comm_free(&node);
  }
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;
  ~MpiSession() { MPI_Finalize(); }

  int rank = 0, size = 1, node_rank = 0, node_size = 1;
};

void wait_without_spinning(MPI_Request& request) {
  for (int done = 0; MPI_Test(&request, &done, MPI_STATUS_IGNORE), !done;) std::this_thread::sleep_for(kPollInterval);
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

// A rank other than 0: asks rank 0 for each mesh, sending the last outcome along.
class RemoteQueue : public MeshQueue {
 public:
  std::optional<std::size_t> next() override {
    MPI_Request sent, received;
    std::int64_t assignment = kNoMoreWork;
    MPI_Isend(last_outcome_.data(), int(last_outcome_.size()), MPI_CHAR, 0, kOutcomeTag, MPI_COMM_WORLD, &sent);
    MPI_Irecv(&assignment, 1, MPI_INT64_T, 0, kAssignmentTag, MPI_COMM_WORLD, &received);
    wait_without_spinning(sent);
    wait_without_spinning(received);
    last_outcome_.clear();
    if (assignment == kNoMoreWork) return std::nullopt;
    return std::size_t(assignment);
  }
  void finished(std::size_t index, const MeshOutcome& outcome) override {
    last_outcome_ = nlohmann::json{{"index", index}, {"row", outcome.row}, {"reused", outcome.reused}}.dump();
  }

 private:
  std::string last_outcome_;
};

// Rank 0's second thread: records each outcome the other ranks send and
// answers with the next mesh from the queue rank 0 also works through,
// until every other rank has been told there is none left.
void dispatch(LedgerQueue& queue, int other_ranks) {
  while (other_ranks > 0) {
    int arrived = 0;
    MPI_Status status;
    MPI_Iprobe(MPI_ANY_SOURCE, kOutcomeTag, MPI_COMM_WORLD, &arrived, &status);
    if (!arrived) {
      std::this_thread::sleep_for(kPollInterval);
      continue;
    }
    int length = 0;
    MPI_Get_count(&status, MPI_CHAR, &length);
    std::string message(std::size_t(length), '\0');
    MPI_Recv(message.data(), length, MPI_CHAR, status.MPI_SOURCE, kOutcomeTag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    if (!message.empty()) {
      const nlohmann::json outcome = nlohmann::json::parse(message);
      queue.finished(outcome.at("index").get<std::size_t>(), {outcome.at("row"), outcome.at("reused").get<bool>()});
    }
    const std::optional<std::size_t> item = queue.next();
    const std::int64_t assignment = item ? std::int64_t(*item) : kNoMoreWork;
    MPI_Send(&assignment, 1, MPI_INT64_T, status.MPI_SOURCE, kAssignmentTag, MPI_COMM_WORLD);
    if (!item) --other_ranks;
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
    plan = plan_batch(own);
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
  MpiSession mpi;
  const std::optional<BatchPlan> plan = plan_on_every_rank(request, mpi);
  if (!plan) return 0;
  int exit_code = 0;
  if (mpi.rank == 0) {
    try {
      BatchLedger ledger(*plan);
      LedgerQueue queue(biggest_first_order(*plan), ledger);
      std::thread dispatcher([&queue, &mpi] {
        try {
          dispatch(queue, mpi.size - 1);
        } catch (...) {
          abort_batch(mpi.rank);
        }
      });
      try {
        work_through(*plan, queue);
      } catch (...) {
        abort_batch(mpi.rank);  // before the joinable dispatcher is destroyed
      }
      dispatcher.join();
      exit_code = ledger.finish();
    } catch (...) {
      abort_batch(mpi.rank);
    }
  } else {
    try {
      RemoteQueue queue;
      work_through(*plan, queue);
    } catch (...) {
      abort_batch(mpi.rank);
    }
  }
  MPI_Request all_done;
  MPI_Ibarrier(MPI_COMM_WORLD, &all_done);
  wait_without_spinning(all_done);
  return exit_code;
}

}  // namespace meshparticles
