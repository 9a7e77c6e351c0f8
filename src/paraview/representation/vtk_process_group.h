// flowsurf — the library's ProcessGroup (parallel/process_group.h) over the MPI
// communicator of ParaView's vtkMPIController (pvbatch / pvserver under mpiexec):
// element-wise all-reductions (MIN, SUM), all-gathers and point-to-point messages, each
// MPI's non-blocking call completed by a wait that, where the node has more processes than
// cores, naps once it outlasts a short spin (a process waiting for the slowest lends its
// core to the processes that share it).
#pragma once

#include "parallel/process_group.h"

#include "vtkMPI.h"  // MPI_Comm

#include <memory>
#include <string>

class vtkMPIController;

namespace flowsurf::paraview {

class VtkProcessGroup : public methods::ProcessGroup {
public:
  // Collective over the controller's processes (counts those that share this node).
  explicit VtkProcessGroup(vtkMPIController* controller);
  int rank() const override;
  int size() const override;
  void minInPlace(std::span<float> values) override;
  void minInPlace(std::span<int32_t> values) override;
  void sumInPlace(std::span<float> values) override;
  std::vector<float> gather(std::span<const float> values) override;
  // Non-blocking point-to-point messages.
  std::vector<std::vector<uint8_t>> exchange(const std::vector<std::vector<uint8_t>>& sends) override;
  // True on every process if `flag` is true on any (a collective decision).
  bool any(bool flag);
  // Collective: "" when every process that has a value (`has`) holds the same one; else an
  // error naming `what` and the first two processes that differ, the same on every process.
  std::string sameValue(bool has, double value, const std::string& what);

  // CPU time this process's calling thread has spent inside the collectives above (MPI's
  // copies and its polling while waiting for the others; not the naps), in ms since
  // construction.
  // Whether this node runs more of the group's processes than it has cores (the waits nap).
  bool oversubscribed() const { return oversubscribed_; }
  double mpiCpuMs() const { return mpiCpuMs_; }

private:
  std::vector<int> allGatherInts(std::span<const int> mine, const char* what);
  void wait(MPI_Request request, const char* what);

  vtkMPIController* controller_;
  MPI_Comm comm_;
  bool oversubscribed_;
  double mpiCpuMs_ = 0;
};

// The group of this process when ParaView runs on more than one (MPI's; null otherwise).
std::unique_ptr<VtkProcessGroup> parallelGroup();

}  // namespace flowsurf::paraview
