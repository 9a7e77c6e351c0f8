#include "vtk_process_group.h"

#include "clock_ms.h"

#include "core/errors.h"

#include "vtkCommunicator.h"
#include "vtkMPICommunicator.h"
#include "vtkMPIController.h"
#include "vtkMultiProcessController.h"

#include <memory>
#include <numeric>
#include <string>

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

void check(int ok, const char* what)
{
  if (!ok)
  {
    throw Error(std::string("FlowSurf: the parallel ") + what + " between ParaView's processes failed");
  }
}
}  // namespace

VtkProcessGroup::VtkProcessGroup(vtkMultiProcessController* controller)
  : controller_(controller)
{
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
  std::vector<float> in(values.begin(), values.end());
  check(controller_->AllReduce(in.data(), values.data(), vtkIdType(in.size()), vtkCommunicator::MIN_OP),
    "depth reduction");
}

void VtkProcessGroup::minInPlace(std::span<int32_t> values)
{
  const ThreadCpu cpu(mpiCpuMs_);
  std::vector<int> in(values.begin(), values.end()), out(values.size());
  check(controller_->AllReduce(in.data(), out.data(), vtkIdType(in.size()), vtkCommunicator::MIN_OP),
    "owner reduction");
  std::copy(out.begin(), out.end(), values.begin());
}

void VtkProcessGroup::sumInPlace(std::span<float> values)
{
  const ThreadCpu cpu(mpiCpuMs_);
  std::vector<float> in(values.begin(), values.end());
  check(controller_->AllReduce(in.data(), values.data(), vtkIdType(in.size()), vtkCommunicator::SUM_OP),
    "image merge");
}

std::vector<float> VtkProcessGroup::gather(std::span<const float> values)
{
  const ThreadCpu cpu(mpiCpuMs_);
  const int n = this->size();
  vtkIdType mine = vtkIdType(values.size());
  std::vector<vtkIdType> lengths(static_cast<size_t>(n)), offsets(static_cast<size_t>(n), 0);
  check(controller_->AllGather(&mine, lengths.data(), 1), "gather of lengths");
  std::partial_sum(lengths.begin(), lengths.end() - 1, offsets.begin() + 1);
  std::vector<float> all(size_t(offsets.back() + lengths.back()));
  check(controller_->AllGatherV(values.data(), all.data(), mine, lengths.data(), offsets.data()),
    "gather of statistics");
  return all;
}

std::vector<std::vector<uint8_t>> VtkProcessGroup::exchange(const std::vector<std::vector<uint8_t>>& sends)
{
  const ThreadCpu cpu(mpiCpuMs_);
  auto* mpi = vtkMPIController::SafeDownCast(controller_);
  if (!mpi)
  {
    throw Error("FlowSurf: the tiled parallel mode needs ParaView's MPI controller; set FlowSurfParallel to "
                "replicate");
  }
  const int n = this->size(), me = this->rank();
  if (int(sends.size()) != n)
  {
    throw Error("FlowSurf: a tile exchange was given " + std::to_string(sends.size()) + " messages for " +
      std::to_string(n) + " processes");
  }
  // Every process's message lengths (a P x P matrix), then the messages themselves.
  std::vector<int> mine(static_cast<size_t>(n)), all(static_cast<size_t>(n) * static_cast<size_t>(n));
  for (int q = 0; q < n; ++q)
  {
    mine[size_t(q)] = q == me ? 0 : int(sends[size_t(q)].size());
  }
  check(controller_->AllGather(mine.data(), all.data(), n), "gather of message lengths");
  constexpr int kTag = 7841;
  std::vector<std::vector<uint8_t>> received(static_cast<size_t>(n));
  std::vector<vtkMPICommunicator::Request> requests;
  requests.reserve(2 * static_cast<size_t>(n));
  for (int q = 0; q < n; ++q)
  {
    const int length = all[size_t(q) * size_t(n) + size_t(me)];
    if (q == me || length == 0)
    {
      continue;
    }
    received[size_t(q)].resize(size_t(length));
    requests.emplace_back();
    check(mpi->NoBlockReceive(reinterpret_cast<char*>(received[size_t(q)].data()), length, q, kTag,
            requests.back()),
      "tile exchange (receive)");
  }
  for (int q = 0; q < n; ++q)
  {
    if (q == me || sends[size_t(q)].empty())
    {
      continue;
    }
    requests.emplace_back();
    check(mpi->NoBlockSend(reinterpret_cast<const char*>(sends[size_t(q)].data()), int(sends[size_t(q)].size()), q,
            kTag, requests.back()),
      "tile exchange (send)");
  }
  for (auto& r : requests)
  {
    r.Wait();
  }
  return received;
}

std::string VtkProcessGroup::sameValue(bool has, double value, const std::string& what)
{
  const ThreadCpu cpu(mpiCpuMs_);
  const int n = this->size();
  const double mine[2] = { has ? 1.0 : 0.0, value };
  std::vector<double> all(2 * static_cast<size_t>(n));
  check(controller_->AllGather(mine, all.data(), 2), "gather of values");
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
  int in = flag ? 1 : 0, out = 0;
  check(controller_->AllReduce(&in, &out, 1, vtkCommunicator::MAX_OP), "decision");
  return out != 0;
}

std::unique_ptr<VtkProcessGroup> parallelGroup()
{
  vtkMultiProcessController* c = vtkMultiProcessController::GetGlobalController();
  if (!c || c->GetNumberOfProcesses() < 2)
  {
    return nullptr;
  }
  return std::make_unique<VtkProcessGroup>(c);
}

}  // namespace flowsurf::paraview
