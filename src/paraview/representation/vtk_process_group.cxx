#include "vtk_process_group.h"

#include "clock_ms.h"
#include "parallel/process_group.h"

#include "core/errors.h"

#include "vtkMPI.h"  // mpi.h, and the MPI_Comm behind ParaView's controller
#include "vtkMPICommunicator.h"
#include "vtkMPIController.h"
#include "vtkMultiProcessController.h"

#include <algorithm>
#include <chrono>
#include <memory>
#include <numeric>
#include <span>
#include <string>
#include <thread>

namespace flowsurf::paraview {

namespace {
// Adds the calling thread's CPU time over its lifetime to `total` (ms).
class ThreadCpu
{
public:
  explicit ThreadCpu(double& total)
    : total_(total)
    , start_(clockMs(CLOCK_THREAD_CPUTIME_ID))
  {
  }
  ~ThreadCpu() { total_ += clockMs(CLOCK_THREAD_CPUTIME_ID) - start_; }
  ThreadCpu(const ThreadCpu&) = delete;
  ThreadCpu& operator=(const ThreadCpu&) = delete;

private:
  double& total_;
  double start_;
};

void check(int mpiResult, const char* what)
{
  if (mpiResult != MPI_SUCCESS)
  {
    throw Error(std::string("FlowSurf: the parallel ") + what + " between ParaView's processes failed");
  }
}

// Completes `requests` (MPI's non-blocking calls, which Open MPI progresses only inside MPI
// calls: each poll moves them on). `nap`: between polls, once the wait outlasts kSpin, the
// process sleeps kNap, lending its core to the processes that share it. Only where the
// node has more processes than cores (VtkProcessGroup's oversubscribed_): there a process
// that spins while it waits for the group's slowest takes the core from the very process
// it waits for. On a core of its own a process spins, as MPI does: a nap would delay each
// step of a large message's transfer (measured: 2 ranks on 2 cores, ISA at 1M, 1024², 3–5 %
// slower per render with naps).
constexpr std::chrono::microseconds kSpin{ 100 };
constexpr std::chrono::microseconds kNap{ 50 };

void waitAll(std::span<MPI_Request> requests, bool nap, const char* what)
{
  const auto start = std::chrono::steady_clock::now();
  for (;;)
  {
    int done = 0;
    check(MPI_Testall(int(requests.size()), requests.data(), &done, MPI_STATUSES_IGNORE), what);
    if (done)
    {
      return;
    }
    if (nap && std::chrono::steady_clock::now() - start > kSpin)
    {
      std::this_thread::sleep_for(kNap);
    }
  }
}

// The number of processes of `comm` on this node (collective).
int processesOnThisNode(MPI_Comm comm)
{
  MPI_Comm node = MPI_COMM_NULL;
  check(MPI_Comm_split_type(comm, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &node), "split by node");
  int n = 1;
  MPI_Comm_size(node, &n);
  MPI_Comm_free(&node);
  return n;
}
}  // namespace

VtkProcessGroup::VtkProcessGroup(vtkMPIController* controller)
  : controller_(controller)
  , comm_(*vtkMPICommunicator::SafeDownCast(controller->GetCommunicator())->GetMPIComm()->GetHandle())
  , oversubscribed_(unsigned(processesOnThisNode(comm_)) > std::max(1u, std::thread::hardware_concurrency()))
{
}

void VtkProcessGroup::wait(MPI_Request request, const char* what)
{
  waitAll({ &request, 1 }, oversubscribed_, what);
}

int VtkProcessGroup::rank() const
{
  return controller_->GetLocalProcessId();
}

int VtkProcessGroup::size() const
{
  return controller_->GetNumberOfProcesses();
}

void VtkProcessGroup::minInPlace(std::span<float> values)
{
  const ThreadCpu cpu(mpiCpuMs_);
  MPI_Request r = MPI_REQUEST_NULL;
  check(MPI_Iallreduce(MPI_IN_PLACE, values.data(), int(values.size()), MPI_FLOAT, MPI_MIN, comm_, &r),
    "depth reduction");
  wait(r, "depth reduction");
}

void VtkProcessGroup::minInPlace(std::span<int32_t> values)
{
  const ThreadCpu cpu(mpiCpuMs_);
  MPI_Request r = MPI_REQUEST_NULL;
  check(MPI_Iallreduce(MPI_IN_PLACE, values.data(), int(values.size()), MPI_INT32_T, MPI_MIN, comm_, &r),
    "owner reduction");
  wait(r, "owner reduction");
}

void VtkProcessGroup::sumInPlace(std::span<float> values)
{
  const ThreadCpu cpu(mpiCpuMs_);
  MPI_Request r = MPI_REQUEST_NULL;
  check(MPI_Iallreduce(MPI_IN_PLACE, values.data(), int(values.size()), MPI_FLOAT, MPI_SUM, comm_, &r),
    "image merge");
  wait(r, "image merge");
}

std::vector<int> VtkProcessGroup::allGatherInts(std::span<const int> mine, const char* what)
{
  std::vector<int> all(mine.size() * size_t(this->size()));
  MPI_Request r = MPI_REQUEST_NULL;
  check(MPI_Iallgather(mine.data(), int(mine.size()), MPI_INT, all.data(), int(mine.size()), MPI_INT, comm_, &r),
    what);
  wait(r, what);
  return all;
}

std::vector<float> VtkProcessGroup::gather(std::span<const float> values)
{
  const ThreadCpu cpu(mpiCpuMs_);
  const int mine = int(values.size());
  std::vector<int> lengths = allGatherInts({ &mine, 1 }, "gather of lengths"), offsets(lengths.size(), 0);
  std::partial_sum(lengths.begin(), lengths.end() - 1, offsets.begin() + 1);
  std::vector<float> all(size_t(offsets.back()) + size_t(lengths.back()));
  MPI_Request r = MPI_REQUEST_NULL;
  check(MPI_Iallgatherv(values.data(), mine, MPI_FLOAT, all.data(), lengths.data(), offsets.data(), MPI_FLOAT,
          comm_, &r),
    "gather of statistics");
  wait(r, "gather of statistics");
  return all;
}

std::vector<std::vector<uint8_t>> VtkProcessGroup::exchange(const std::vector<std::vector<uint8_t>>& sends)
{
  const ThreadCpu cpu(mpiCpuMs_);
  const int n = this->size(), me = this->rank();
  if (int(sends.size()) != n)
  {
    throw Error("FlowSurf: a tile exchange was given " + std::to_string(sends.size()) + " messages for " +
      std::to_string(n) + " processes");
  }
  // Every process's message lengths (a P x P matrix), then the messages themselves.
  std::vector<int> mine(static_cast<size_t>(n));
  for (int q = 0; q < n; ++q)
  {
    mine[size_t(q)] = q == me ? 0 : int(sends[size_t(q)].size());
  }
  const std::vector<int> all = allGatherInts(mine, "gather of message lengths");
  constexpr int kTag = 7841;
  std::vector<std::vector<uint8_t>> received(static_cast<size_t>(n));
  std::vector<MPI_Request> requests;
  requests.reserve(2 * static_cast<size_t>(n));
  for (int q = 0; q < n; ++q)
  {
    const int length = all[size_t(q) * size_t(n) + size_t(me)];
    if (q == me || length == 0)
    {
      continue;
    }
    received[size_t(q)].resize(size_t(length));
    requests.push_back(MPI_REQUEST_NULL);
    check(MPI_Irecv(received[size_t(q)].data(), length, MPI_BYTE, q, kTag, comm_, &requests.back()),
      "tile exchange (receive)");
  }
  for (int q = 0; q < n; ++q)
  {
    if (q == me || sends[size_t(q)].empty())
    {
      continue;
    }
    requests.push_back(MPI_REQUEST_NULL);
    check(MPI_Isend(sends[size_t(q)].data(), int(sends[size_t(q)].size()), MPI_BYTE, q, kTag, comm_,
            &requests.back()),
      "tile exchange (send)");
  }
  waitAll(requests, oversubscribed_, "tile exchange");
  return received;
}

std::string VtkProcessGroup::sameValue(bool has, double value, const std::string& what)
{
  const ThreadCpu cpu(mpiCpuMs_);
  const int n = this->size();
  const double mine[2] = { has ? 1.0 : 0.0, value };
  std::vector<double> all(2 * static_cast<size_t>(n));
  MPI_Request r = MPI_REQUEST_NULL;
  check(MPI_Iallgather(mine, 2, MPI_DOUBLE, all.data(), 2, MPI_DOUBLE, comm_, &r), "gather of values");
  wait(r, "gather of values");
  int first = -1;
  for (int q = 0; q < n; ++q)
  {
    if (all[2 * size_t(q)] == 0.0)
    {
      continue;
    }
    if (first < 0)
    {
      first = q;
    }
    else if (all[2 * size_t(q) + 1] != all[2 * size_t(first) + 1])
    {
      auto text = [](double v) {
        std::string s = std::to_string(v);
        return s.erase(s.find_last_not_of('0') + 1);
      };
      return "FlowSurf: " + what + " differ between the processes: " + text(all[2 * size_t(first) + 1]) +
        " on process " + std::to_string(first) + ", " + text(all[2 * size_t(q) + 1]) + " on process " +
        std::to_string(q) + " of " + std::to_string(n);
    }
  }
  return {};
}

bool VtkProcessGroup::any(bool flag)
{
  const ThreadCpu cpu(mpiCpuMs_);
  int value = flag ? 1 : 0;
  MPI_Request r = MPI_REQUEST_NULL;
  check(MPI_Iallreduce(MPI_IN_PLACE, &value, 1, MPI_INT, MPI_MAX, comm_, &r), "decision");
  wait(r, "decision");
  return value != 0;
}

std::unique_ptr<VtkProcessGroup> parallelGroup()
{
  // ParaView's processes are MPI's when there are more than one (pvbatch, pvserver).
  // Collective (the constructor): made by a mapper's first render, on every process at once.
  auto* c = vtkMPIController::SafeDownCast(vtkMultiProcessController::GetGlobalController());
  if (!c || c->GetNumberOfProcesses() < 2)
  {
    return nullptr;
  }
  return std::make_unique<VtkProcessGroup>(c);
}

}  // namespace flowsurf::paraview
