// flowsurf — unsteady data over animation frames [L §I, Fig. 11]: a list of time steps
// loaded on demand, the mapping of frames to data time, and linear interpolation between
// neighbouring steps when their topology agrees (else the nearer step is used).
#pragma once

#include "core/mesh.h"

#include <memory>
#include <string>
#include <vector>

namespace flowsurf::core {

// Time steps that can be loaded one at a time (a file series streams; a Dataset in
// memory serves its steps).
class StepProvider {
public:
    virtual ~StepProvider() = default;
    virtual size_t count() const = 0;
    virtual double time(size_t index) const = 0;
    // Loads step `index`; throws IoError/FormatError naming the step.
    virtual SurfaceMesh load(size_t index) = 0;
    // "file.pvd step 3 (t = 0.5)" for messages.
    virtual std::string label(size_t index) const = 0;
    // Bounds for framing the camera: of every step where known, else of the first.
    virtual Bounds bounds() { return load(0).bounds(); }
};

class DatasetSteps final : public StepProvider {
public:
    explicit DatasetSteps(Dataset data) : data_(std::move(data)) {}
    size_t count() const override { return data_.steps.size(); }
    double time(size_t i) const override { return data_.steps[i].time; }
    SurfaceMesh load(size_t i) override { return data_.steps[i].mesh; }
    std::string label(size_t i) const override;
    Bounds bounds() override { return data_.bounds(); }

private:
    Dataset data_;
};

// Frame k -> data time: start + k * perFrame, held at `end`.
struct TimeMapping {
    double start = 0.0, end = 0.0, perFrame = 0.0;
    double at(int frame) const;
};

// Where a data time falls: steps a <= b and the weight of b (0 when a == b).
struct StepBracket {
    size_t a = 0, b = 0;
    double weight = 0.0;
};
StepBracket bracket(const std::vector<double>& times, double t);

// Same vertex count and identical triangles: the meshes can be interpolated.
bool sameTopology(const SurfaceMesh& a, const SurfaceMesh& b);

// (1 - w) a + w b for positions and every field present in both (by name); normals
// are interpolated and renormalised. Requires sameTopology(a, b).
SurfaceMesh interpolate(const SurfaceMesh& a, const SurfaceMesh& b, double w);

}  // namespace flowsurf::core
