// flowsurf — the library's ProcessGroup (methods/common/process_group.h) over ParaView's
// vtkMultiProcessController (MPI under pvbatch / pvserver with mpiexec): element-wise
// all-reductions (MIN, SUM) and an all-gather of variable-length arrays.
#pragma once

#include "methods/common/process_group.h"

#include <memory>
#include <string>

class vtkMultiProcessController;

namespace flowsurf::paraview {

class VtkProcessGroup : public methods::ProcessGroup {
public:
  explicit VtkProcessGroup(vtkMultiProcessController* controller);
  int rank() const override;
  int size() const override;
  void minInPlace(std::span<float> values) override;
  void minInPlace(std::span<int32_t> values) override;
  void sumInPlace(std::span<float> values) override;
  std::vector<float> gather(std::span<const float> values) override;
  // Non-blocking point-to-point messages of ParaView's MPI controller.
  std::vector<std::vector<uint8_t>> exchange(const std::vector<std::vector<uint8_t>>& sends) override;
  // True on every process if `flag` is true on any (a collective decision).
  bool any(bool flag);
  // Collective: "" when every process that has a value (`has`) holds the same one; else an
  // error naming `what` and the first two processes that differ, the same on every process.
  std::string sameValue(bool has, double value, const std::string& what);

  // CPU time this process's calling thread has spent inside the collectives above (MPI's
  // copies and its polling while waiting for the others), in ms since construction.
  double mpiCpuMs() const { return mpiCpuMs_; }

private:
  vtkMultiProcessController* controller_;
  double mpiCpuMs_ = 0;
};

// The group of this process when ParaView runs on more than one (null otherwise).
std::unique_ptr<VtkProcessGroup> parallelGroup();

}  // namespace flowsurf::paraview
