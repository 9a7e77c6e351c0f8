#include "core/time_series.h"

#include "core/errors.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace flowsurf::core {

std::string DatasetSteps::label(size_t i) const {
    std::ostringstream s;
    s << data_.source << " step " << i << " (t = " << data_.steps[i].time << ")";
    return s.str();
}

double TimeMapping::at(int frame) const {
    double t = start + double(frame) * perFrame;
    return perFrame >= 0.0 ? std::min(t, end) : std::max(t, end);
}

StepBracket bracket(const std::vector<double>& times, double t) {
    FLOWSURF_CHECK(!times.empty());
    if (t <= times.front()) return {0, 0, 0.0};
    if (t >= times.back()) return {times.size() - 1, times.size() - 1, 0.0};
    size_t b = size_t(std::upper_bound(times.begin(), times.end(), t) - times.begin());
    size_t a = b - 1;
    double span = times[b] - times[a];
    double w = span > 0.0 ? (t - times[a]) / span : 0.0;
    if (w <= 0.0) return {a, a, 0.0};
    return {a, b, w};
}

bool sameTopology(const SurfaceMesh& a, const SurfaceMesh& b) {
    return a.positions.size() == b.positions.size() && a.triangles == b.triangles;
}

SurfaceMesh interpolate(const SurfaceMesh& a, const SurfaceMesh& b, double w) {
    FLOWSURF_CHECK(sameTopology(a, b));
    const float wf = float(w);
    SurfaceMesh m;
    m.triangles = a.triangles;
    m.units = a.units;
    m.positions.resize(a.positions.size());
    m.normals.resize(a.positions.size());
    for (size_t i = 0; i < a.positions.size(); ++i) {
        m.positions[i] = glm::mix(a.positions[i], b.positions[i], wf);
        glm::vec3 n = glm::mix(a.normals[i], b.normals[i], wf);
        float l = glm::length(n);
        m.normals[i] = l > 0.0f ? n / l : a.normals[i];
    }
    for (const auto& fa : a.fields)
        if (const VectorField* fb = b.findField(fa.name)) {
            VectorField f{fa.name, std::vector<glm::vec3>(fa.values.size())};
            for (size_t i = 0; i < fa.values.size(); ++i) f.values[i] = glm::mix(fa.values[i], fb->values[i], wf);
            m.fields.push_back(std::move(f));
        }
    for (const auto& sa : a.scalars)
        if (const ScalarField* sb = b.findScalar(sa.name)) {
            ScalarField f{sa.name, std::vector<float>(sa.values.size())};
            for (size_t i = 0; i < sa.values.size(); ++i) f.values[i] = sa.values[i] + wf * (sb->values[i] - sa.values[i]);
            m.scalars.push_back(std::move(f));
        }
    return m;
}

}  // namespace flowsurf::core
