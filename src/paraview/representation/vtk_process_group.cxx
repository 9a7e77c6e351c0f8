#include "vtk_process_group.h"

#include "core/errors.h"

#include "vtkCommunicator.h"
#include "vtkMultiProcessController.h"

#include <memory>
#include <numeric>

namespace flowsurf::paraview {

namespace {
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
  std::vector<float> in(values.begin(), values.end());
  check(controller_->AllReduce(in.data(), values.data(), vtkIdType(in.size()), vtkCommunicator::MIN_OP),
    "depth reduction");
}

void VtkProcessGroup::minInPlace(std::span<int32_t> values)
{
  std::vector<int> in(values.begin(), values.end()), out(values.size());
  check(controller_->AllReduce(in.data(), out.data(), vtkIdType(in.size()), vtkCommunicator::MIN_OP),
    "owner reduction");
  std::copy(out.begin(), out.end(), values.begin());
}

void VtkProcessGroup::sumInPlace(std::span<float> values)
{
  std::vector<float> in(values.begin(), values.end());
  check(controller_->AllReduce(in.data(), values.data(), vtkIdType(in.size()), vtkCommunicator::SUM_OP),
    "image merge");
}

std::vector<float> VtkProcessGroup::gather(std::span<const float> values)
{
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

bool VtkProcessGroup::any(bool flag)
{
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
