#include "smc/mpi/mpi_runs.h"

#include <mpi.h>

#include <csignal>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace smcbip::smc::mpi {
namespace {

enum Tag : int { kWork = 1, kStop = 2, kResult = 3 };

/// A message's bytes, written and read in order (the ranks share one architecture).
class Bytes {
 public:
  Bytes() = default;
  explicit Bytes(std::vector<char> data) : data_(std::move(data)) {}

  template <class T>
  void put(const T& value) {
    const char* raw = reinterpret_cast<const char*>(&value);
    data_.insert(data_.end(), raw, raw + sizeof(T));
  }
  void put_text(const std::string& text) {
    put<std::uint64_t>(text.size());
    data_.insert(data_.end(), text.begin(), text.end());
  }
  template <class T>
  T get() {
    T value;
    need(sizeof(T));
    std::memcpy(&value, data_.data() + at_, sizeof(T));
    at_ += sizeof(T);
    return value;
  }
  std::string get_text() {
    const auto size = get<std::uint64_t>();
    need(size);
    std::string text(data_.data() + at_, size);
    at_ += size;
    return text;
  }
  const std::vector<char>& data() const { return data_; }

 private:
  void need(std::size_t n) const {
    if (at_ + n > data_.size()) throw std::runtime_error("a truncated message between ranks");
  }
  std::vector<char> data_;
  std::size_t at_ = 0;
};

void send(const Bytes& bytes, int to, Tag tag) {
  MPI_Send(bytes.data().data(), static_cast<int>(bytes.data().size()), MPI_CHAR, to, tag,
           MPI_COMM_WORLD);
}

/// Set by SIGTERM and SIGINT: the launcher ends the job (a rank failed, or it was stopped).
volatile std::sig_atomic_t ending = 0;

extern "C" void note_ending(int) { ending = 1; }

/// Polls `ready` until it holds (true) or the job ends (false).
template <class Ready>
bool poll_until(Ready ready) {
  for (;;) {
    if (ready()) return true;
    if (ending) return false;
    std::this_thread::yield();
  }
}

/// Waits for a message from `from` (or any rank) with `tag` (or any), polling so as not to miss
/// the end of the job; false if the job ends. It keeps its core busy, as MPI's blocking calls
/// do: sleeping between polls delayed the hand-out enough to cost a fifth of the throughput.
bool wait_for(int from, int tag, MPI_Status& status) {
  return poll_until([&] {
    int arrived = 0;
    MPI_Iprobe(from, tag, MPI_COMM_WORLD, &arrived, &status);
    return arrived != 0;
  });
}

/// The next message from `from` (or any rank) with `tag` (or any); its sender and tag.
Bytes receive(int from, int tag, MPI_Status& status) {
  MPI_Probe(from, tag, MPI_COMM_WORLD, &status);
  int count = 0;
  MPI_Get_count(&status, MPI_CHAR, &count);
  std::vector<char> data(static_cast<std::size_t>(count));
  MPI_Recv(data.data(), count, MPI_CHAR, status.MPI_SOURCE, status.MPI_TAG, MPI_COMM_WORLD,
           MPI_STATUS_IGNORE);
  return Bytes(std::move(data));
}

/// The message `status` announced (wait_for), received without blocking so that a sender that
/// dies halfway through a long message cannot hold rank 0; nullopt if the job ends meanwhile.
std::optional<Bytes> receive_announced(const MPI_Status& status) {
  int count = 0;
  MPI_Get_count(&status, MPI_CHAR, &count);
  std::vector<char> data(static_cast<std::size_t>(count));
  MPI_Request request;
  MPI_Irecv(data.data(), count, MPI_CHAR, status.MPI_SOURCE, status.MPI_TAG, MPI_COMM_WORLD,
            &request);
  const bool received = poll_until([&] {
    int complete = 0;
    MPI_Test(&request, &complete, MPI_STATUS_IGNORE);
    return complete != 0;
  });
  if (!received) return std::nullopt;
  return Bytes(std::move(data));
}

/// A batch's outcomes as a worker made them: the runs made, then, if one failed, why.
struct Batch {
  std::uint64_t first = 0;
  std::vector<RunOutcomes> runs;
  std::string failure;  // the run after the last made could not be made: why
  int rank = 0;
};

void put_run(Bytes& out, const RunOutcomes& run) {
  out.put<std::uint64_t>(run.points.size());
  for (const Outcome& o : run.points) {
    out.put(static_cast<std::uint8_t>(o.verdict));
    out.put(o.value);
  }
  out.put(static_cast<std::uint8_t>(run.end));
  out.put(static_cast<std::uint8_t>(run.trace_cut));
  out.put_text(run.failure);
  out.put_text(run.trace);
}

RunOutcomes get_run(Bytes& in) {
  RunOutcomes run;
  run.points.resize(in.get<std::uint64_t>());
  for (Outcome& o : run.points) {
    o.verdict = static_cast<monitors::Verdict>(in.get<std::uint8_t>());
    o.value = in.get<double>();
  }
  run.end = static_cast<engines::RunEnd>(in.get<std::uint8_t>());
  run.trace_cut = in.get<std::uint8_t>() != 0;
  run.failure = in.get_text();
  run.trace = in.get_text();
  return run;
}

Batch get_batch(Bytes& in, int rank) {
  Batch batch;
  batch.rank = rank;
  batch.first = in.get<std::uint64_t>();
  const auto made = in.get<std::uint64_t>();
  for (std::uint64_t k = 0; k < made; ++k) batch.runs.push_back(get_run(in));
  batch.failure = in.get_text();
  return batch;
}

}  // namespace

bool launched_with_ranks() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_SIZE"}) {
    if (const char* size = std::getenv(name)) return std::atoi(size) > 1;
  }
  return false;
}

Session::Session(int& argc, char**& argv) {
  MPI_Init(&argc, &argv);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
  if (rank_ == 0) {
    std::signal(SIGTERM, note_ending);
    std::signal(SIGINT, note_ending);
  }
}

Session::~Session() {
  // Once the job is ending its other ranks are gone: finalising would wait for them.
  if (ending) {
    std::cout.flush();
    std::cerr.flush();
    std::_Exit(kEnded);
  }
  MPI_Finalize();
}

std::string MpiRuns::consume(std::size_t points, const std::atomic<bool>* done,
                             const std::function<bool(const RunOutcomes&)>& consume) {
  if (ended_) return "the MPI job was ended before this query";
  std::uint64_t next = 0;
  std::map<std::uint64_t, int> holder;  // the rank each batch out was handed to, by first run
  std::vector<unsigned> outstanding(static_cast<std::size_t>(size_), 0);
  const auto hand_out = [&](int worker) {
    Bytes work;
    work.put(next);
    work.put(batch_);
    for (std::size_t p = 0; p < points; ++p) work.put(static_cast<std::uint8_t>(done[p].load()));
    send(work, worker, kWork);
    holder[next] = worker;
    next += batch_;
    ++outstanding[static_cast<std::size_t>(worker)];
  };
  for (int w = 1; w < size_; ++w) {
    for (unsigned k = 0; k < ahead_; ++k) hand_out(w);
  }
  std::map<std::uint64_t, Batch> arrived;  // by first run
  std::uint64_t i = 0;
  std::string failure;
  for (bool more = true; more;) {
    const auto ready = arrived.find(i - i % batch_);
    if (ready == arrived.end()) {
      MPI_Status status;
      std::optional<Bytes> in;
      if (wait_for(MPI_ANY_SOURCE, kResult, status)) in = receive_announced(status);
      if (!in) {
        ended_ = true;
        return "the MPI job was ended (a rank failed, which the launcher names, or the job was "
               "stopped) while rank 0 waited for run " +
               std::to_string(i) + " from rank " + std::to_string(holder[i - i % batch_]);
      }
      Batch batch = get_batch(*in, status.MPI_SOURCE);
      holder.erase(batch.first);
      --outstanding[static_cast<std::size_t>(batch.rank)];
      arrived.emplace(batch.first, std::move(batch));
      hand_out(status.MPI_SOURCE);
      continue;
    }
    const Batch& batch = ready->second;
    for (; more && i < batch.first + batch.runs.size(); ++i) {
      more = consume(batch.runs[i - batch.first]);
    }
    if (more && i < batch.first + batch_) {  // the batch stopped at a run that failed
      failure = "rank " + std::to_string(batch.rank) + ", run " + std::to_string(i) + ": " +
                batch.failure;
      more = false;
    }
    if (more) arrived.erase(ready);
  }
  // Every rank is told to stop once its outstanding batches are in, so that no message of this
  // query is left for the next one.
  for (int w = 1; w < size_; ++w) {
    for (; outstanding[static_cast<std::size_t>(w)] > 0;
         --outstanding[static_cast<std::size_t>(w)]) {
      MPI_Status status;
      receive(w, kResult, status);
    }
    send(Bytes(), w, kStop);
  }
  return failure;
}

void MpiRuns::serve(std::size_t points, std::atomic<bool>* done,
                    const std::function<void(std::uint64_t, RunOutcomes&)>& produce) {
  RunOutcomes run;
  for (;;) {
    MPI_Status status;
    Bytes in = receive(0, MPI_ANY_TAG, status);
    if (status.MPI_TAG == kStop) return;
    const auto first = in.get<std::uint64_t>();
    const auto count = in.get<std::uint64_t>();
    for (std::size_t p = 0; p < points; ++p) done[p].store(in.get<std::uint8_t>() != 0);
    Bytes out;
    out.put(first);
    std::vector<RunOutcomes> made;
    std::string failure;
    for (std::uint64_t k = 0; k < count; ++k) {
      try {
        produce(first + k, run);
      } catch (const std::exception& e) {
        failure = e.what();
        break;
      }
      made.push_back(run);
    }
    out.put<std::uint64_t>(made.size());
    for (const RunOutcomes& r : made) put_run(out, r);
    out.put_text(failure);
    send(out, 0, kResult);
  }
}

}  // namespace smcbip::smc::mpi
