#include "evolve/mpi_evaluator.h"

#include <mpi.h>

#include <atomic>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <type_traits>
#include <vector>

namespace walkers::mpi {
namespace {

// the messages between rank 0 and the others
enum Tag : int { kTask = 1, kResult = 2, kStop = 3, kStopped = 4 };

// how long a rank waits between looks for a message: far below an evaluation
constexpr auto kPollInterval = std::chrono::microseconds(500);

Session* g_session = nullptr;
std::atomic<bool> g_rank_failed{false};
// --rank-timeout of the command's evaluator; also bounds the wait for a
// rank's answer to stop
std::atomic<double> g_rank_timeout_s{300.0};
// rank 0 calls MPI from several threads (MPI_THREAD_SERIALIZED): one at a time
std::mutex g_mpi;
// sends to a rank that did not take them in time: MPI may still read them
// until the job is aborted (guarded by g_mpi)
std::vector<std::unique_ptr<std::string>> g_abandoned_sends;

using Clock = std::chrono::steady_clock;

// Bytes of plain values and strings, written and read in the same order.
class Packer {
 public:
  template <typename T>
  void operator()(const T& value) {
    static_assert(std::is_trivially_copyable_v<T>);
    bytes_.append(reinterpret_cast<const char*>(&value), sizeof(T));
  }
  void operator()(const std::string& text) {
    (*this)(static_cast<std::uint64_t>(text.size()));
    bytes_ += text;
  }
  const std::string& bytes() const { return bytes_; }

 private:
  std::string bytes_;
};

class Unpacker {
 public:
  explicit Unpacker(const std::vector<char>& bytes) : bytes_(bytes) {}
  template <typename T>
  void operator()(T& value) {
    static_assert(std::is_trivially_copyable_v<T>);
    Need(sizeof(T));
    std::memcpy(&value, bytes_.data() + at_, sizeof(T));
    at_ += sizeof(T);
  }
  void operator()(std::string& text) {
    std::uint64_t size = 0;
    (*this)(size);
    Need(size);
    text.assign(bytes_.data() + at_, size);
    at_ += size;
  }

 private:
  void Need(std::size_t n) const {
    if (at_ + n > bytes_.size()) throw std::runtime_error("MPI: a message is shorter than its content");
  }
  const std::vector<char>& bytes_;
  std::size_t at_ = 0;
};

// Every field of a result, the one list both directions use.
template <typename Archive, typename Result>
void ResultFields(Archive& a, Result& r) {
  a(r.outcome), a(r.reason), a(r.fitness), a(r.distance), a(r.leg_length), a(r.footsteps);
  a(r.trunk_contact_fraction), a(r.gait), a(r.sim_time), a(r.wall_ms), a(r.integrator), a(r.integrator_stats);
  a(r.max_weld_drift), a(r.preset);
}

// the ranks run the same program on the same kind of machine: settings and
// genomes travel as their bytes
static_assert(std::is_trivially_copyable_v<EvaluationSettings>);
static_assert(std::is_trivially_copyable_v<Genome>);

std::vector<char> Receive(const MPI_Status& status) {
  int count = 0;
  MPI_Get_count(&status, MPI_BYTE, &count);
  std::vector<char> bytes(static_cast<std::size_t>(count));
  MPI_Recv(bytes.data(), count, MPI_BYTE, status.MPI_SOURCE, status.MPI_TAG, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  return bytes;
}

// the other ranks' sends to rank 0, which is always polling for them
void Send(const std::string& bytes, int rank, Tag tag) {
  MPI_Send(bytes.data(), static_cast<int>(bytes.size()), MPI_BYTE, rank, tag, MPI_COMM_WORLD);
}

std::string NotAnsweredMessage(int rank, double timeout_s) {
  return "MPI rank " + std::to_string(rank) + " has not answered for " + std::to_string(static_cast<long>(timeout_s)) +
         " s (--rank-timeout): it has hung or its node is lost";
}

Clock::time_point After(double seconds) {
  return Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds));
}

// Rank 0: calls `ready` under g_mpi every kPollInterval until it says yes
// (true) or `deadline` passes (false).
template <typename Ready>
bool PollUntil(Clock::time_point deadline, Ready ready) {
  for (;;) {
    {
      std::lock_guard<std::mutex> lock(g_mpi);
      if (ready()) return true;
    }
    if (Clock::now() > deadline) return false;
    std::this_thread::sleep_for(kPollInterval);
  }
}

// Rank 0: sends `bytes` to `rank` and returns whether it took them by
// `deadline`. A task is too large for MPI's eager protocol, so a blocking
// send to a stopped rank would never return, holding g_mpi; the send is
// started, then polled.
bool SendBefore(std::string bytes, int rank, Tag tag, Clock::time_point deadline) {
  auto buffer = std::make_unique<std::string>(std::move(bytes));
  MPI_Request request;
  {
    std::lock_guard<std::mutex> lock(g_mpi);
    MPI_Isend(buffer->data(), static_cast<int>(buffer->size()), MPI_BYTE, rank, tag, MPI_COMM_WORLD, &request);
  }
  const bool taken = PollUntil(deadline, [&] {
    int done = 0;
    MPI_Test(&request, &done, MPI_STATUS_IGNORE);
    return done != 0;
  });
  if (!taken) {
    std::lock_guard<std::mutex> lock(g_mpi);
    g_abandoned_sends.push_back(std::move(buffer));
  }
  return taken;
}

// Rank 0: waits until `deadline` for a message from `rank` with `tag` and
// returns its bytes, or nothing if none came in time.
std::optional<std::vector<char>> AwaitMessage(int rank, Tag tag, Clock::time_point deadline) {
  std::optional<std::vector<char>> bytes;
  PollUntil(deadline, [&] {
    int arrived = 0;
    MPI_Status status;
    MPI_Iprobe(rank, tag, MPI_COMM_WORLD, &arrived, &status);
    if (arrived) bytes = Receive(status);
    return arrived != 0;
  });
  return bytes;
}

// Rank 0's slot for `rank`: sends it the task and waits for its answer.
void EvaluateOnRank(int rank, double timeout_s, const EvaluationTask& task) {
  if (g_rank_failed) throw std::runtime_error("MPI: the job is ending after a rank failed");
  Packer out;
  out(task.preset->name), out(*task.settings), out(*task.genome);
  const Clock::time_point deadline = After(timeout_s);
  std::optional<std::vector<char>> bytes;
  if (SendBefore(out.bytes(), rank, kTask, deadline)) bytes = AwaitMessage(rank, kResult, deadline);
  if (!bytes) {
    g_rank_failed = true;
    throw std::runtime_error(NotAnsweredMessage(rank, timeout_s) +
                             "; the job ends. Resume it with --resume: the last complete generation of every run "
                             "is on disk");
  }
  Unpacker in(*bytes);
  ResultFields(in, *task.result);
}

}  // namespace

bool LaunchedByLauncher() {
  // Open MPI's mpirun, PMIx (srun --mpi=pmix, mpirun), PMI-1/2 (srun, MPICH)
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_RANK", "PMI_SIZE"}) {
    if (std::getenv(name)) return true;
  }
  return false;
}

Session::Session(int* argc, char*** argv) {
  int provided = 0;
  MPI_Init_thread(argc, argv, MPI_THREAD_SERIALIZED, &provided);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
  if (provided < MPI_THREAD_SERIALIZED && size_ > 1) {
    if (rank_ == 0) std::fprintf(stderr, "walkers: error: this MPI library does not support MPI_THREAD_SERIALIZED\n");
    MPI_Abort(MPI_COMM_WORLD, 1);
  }
  g_session = this;
}

int Session::Finish(int status) {
  if (finished_ || rank_ != 0) return status;
  finished_ = true;
  if (g_rank_failed) {
    std::fflush(stderr);
    MPI_Abort(MPI_COMM_WORLD, status == 0 ? 1 : status);  // a hung rank would never take a stop
  }
  // Every rank answers the stop before MPI_Finalize, which waits for all of
  // them: one that hung after its last evaluation would otherwise hold the
  // job forever.
  const double timeout_s = g_rank_timeout_s;
  const Clock::time_point deadline = After(timeout_s);
  for (int r = 1; r < size_; ++r) {
    if (!SendBefore("", r, kStop, deadline) || !AwaitMessage(r, kStopped, deadline)) {
      std::fprintf(stderr, "walkers: error: %s when told to stop%s; the job is aborted\n",
                   NotAnsweredMessage(r, timeout_s).c_str(), status == 0 ? " (the work is done, every file complete)" : "");
      std::fflush(stderr);
      MPI_Abort(MPI_COMM_WORLD, status == 0 ? 1 : status);
    }
  }
  return status;
}

Session::~Session() {
  Finish(0);
  g_session = nullptr;
  MPI_Finalize();
}

Session* CurrentSession() { return g_session; }

void ServeEvaluations() {
  for (;;) {
    int arrived = 0;
    MPI_Status status;
    MPI_Iprobe(0, MPI_ANY_TAG, MPI_COMM_WORLD, &arrived, &status);
    if (!arrived) {
      std::this_thread::sleep_for(kPollInterval);
      continue;
    }
    const std::vector<char> bytes = Receive(status);
    if (status.MPI_TAG == kStop) {
      Send("", 0, kStopped);
      return;
    }
    std::string preset_name;
    EvaluationSettings settings;
    Genome genome;
    Unpacker in(bytes);
    in(preset_name), in(settings), in(genome);
    EvaluationResult result = Evaluate(genome, PresetByName(preset_name), settings);
    Packer out;
    ResultFields(out, result);
    Send(out.bytes(), 0, kResult);
  }
}

std::unique_ptr<Evaluator> MakeMpiEvaluator(int threads, double rank_timeout_s) {
  g_rank_timeout_s = rank_timeout_s;
  std::vector<SlotEvaluator::Slot> slots;
  for (int t = 0; t < threads; ++t) {
    slots.push_back([](const EvaluationTask& task) {
      *task.result = Evaluate(*task.genome, *task.preset, *task.settings);
    });
  }
  for (int rank = 1; rank < g_session->size(); ++rank) {
    slots.push_back([rank, rank_timeout_s](const EvaluationTask& task) { EvaluateOnRank(rank, rank_timeout_s, task); });
  }
  return std::make_unique<SlotEvaluator>(std::move(slots));
}

bool RankFailed() { return g_rank_failed; }

}  // namespace walkers::mpi
