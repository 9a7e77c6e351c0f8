#include <flowsurf/surface.h>

#include "api/surface_data.h"
#include "core/errors.h"
#include "io/series_reader.h"
#include "raster/surface_gpu.h"
#include "session/options/options.h"
#include "session/scene_setup.h"
#include "session/topology_source.h"

#include <algorithm>
#include <cmath>

namespace flowsurf {

namespace detail {

namespace {

// The steps of a dataset shared between renderers (no copy per renderer).
class SharedSteps final : public core::StepProvider {
public:
    explicit SharedSteps(std::shared_ptr<const core::Dataset> d) : data_(std::move(d)) {}
    size_t count() const override { return data_->steps.size(); }
    double time(size_t i) const override { return data_->steps[i].time; }
    core::SurfaceMesh load(size_t i) override { return data_->steps[i].mesh; }
    std::string label(size_t i) const override {
        return data_->steps.size() > 1 ? data_->source + " step " + std::to_string(i) : data_->source;
    }
    core::Bounds bounds() override { return data_->bounds(); }

private:
    std::shared_ptr<const core::Dataset> data_;
};

}  // namespace

std::unique_ptr<core::StepProvider> SurfaceData::provider() const {
    if (dataset) return std::make_unique<SharedSteps>(dataset);
    return io::openInput(source, read);
}

}  // namespace detail

namespace {

std::shared_ptr<detail::SurfaceData> describe(std::shared_ptr<detail::SurfaceData> d, core::StepProvider& steps,
                                              const std::string& field) {
    const core::SurfaceMesh first = steps.load(0);
    d->field = methods::selectField(first, field, steps.label(0));
    d->fields.clear();
    for (const auto& f : first.fields) d->fields.push_back(f.name);
    d->points = first.vertexCount();
    d->triangles = first.triangleCount();
    d->times.clear();
    for (size_t i = 0; i < steps.count(); ++i) d->times.push_back(steps.time(i));
    d->bounds = steps.bounds();
    return d;
}

const core::SurfaceMesh& onlyMesh(const detail::SurfaceData& d, const char* what) {
    if (!d.dataset || d.dataset->steps.size() != 1)
        throw ConfigError(std::string(what) + ": only for a surface built from arrays or a one-step file");
    return d.dataset->steps.front().mesh;
}

}  // namespace

Surface Surface::fromArrays(const float* points, size_t pointCount, const uint32_t* triangles, size_t triangleCount,
                            const float* vectors, const std::string& field, const float* normals) {
    if (!points || !triangles || !vectors) throw ConfigError("Surface: points, triangles and vectors are required");
    if (field.empty()) throw ConfigError("Surface: the field needs a name");
    if (pointCount == 0) throw FormatError("arrays: the surface has no points");
    if (triangleCount == 0) throw FormatError("arrays: the surface has no triangles");
    core::SurfaceMesh m;
    m.positions.resize(pointCount);
    std::copy_n(points, pointCount * 3, &m.positions[0].x);
    m.triangles.resize(triangleCount);
    for (size_t t = 0; t < triangleCount; ++t)
        m.triangles[t] = glm::uvec3(triangles[3 * t], triangles[3 * t + 1], triangles[3 * t + 2]);
    core::VectorField f{field, std::vector<glm::vec3>(pointCount)};
    std::copy_n(vectors, pointCount * 3, &f.values[0].x);
    m.fields.push_back(std::move(f));
    if (normals) {
        m.normals.resize(pointCount);
        std::copy_n(normals, pointCount * 3, &m.normals[0].x);
        for (size_t i = 0; i < pointCount; ++i) {
            const glm::vec3& n = m.normals[i];
            if (!std::isfinite(n.x) || !std::isfinite(n.y) || !std::isfinite(n.z) || glm::length(n) == 0.0f)
                throw FormatError("arrays: normal " + std::to_string(i) + " is zero or not finite");
            m.normals[i] = glm::normalize(n);
        }
    }
    core::validateMesh(m, "arrays");  // indices, NaN/Inf, sizes: names the element
    if (m.normals.empty()) m.normals = core::computeVertexNormals(m.positions, m.triangles);
    auto data = std::make_shared<core::Dataset>();
    data->source = "arrays";
    data->steps.push_back({0.0, std::move(m)});
    auto d = std::make_shared<detail::SurfaceData>();
    d->source = "arrays";
    d->dataset = data;
    detail::SharedSteps steps(data);
    return Surface(describe(d, steps, field));
}

std::vector<std::string> Surface::readOptionNames() {
    std::vector<std::string> names;
    for (const auto& spec : session::renderOptionTable())
        if (spec.takes(session::FrontEnd::Read)) names.push_back(spec.name);
    return names;
}

Surface Surface::read(const std::string& path, const std::string& field,
                      const std::vector<std::pair<std::string, std::string>>& options) {
    session::RenderOptions o;
    const std::vector<std::string> allowed = readOptionNames();
    for (const auto& [name, value] : options) {
        if (std::find(allowed.begin(), allowed.end(), name) == allowed.end())
            throw ConfigError("Surface::read: '" + name + "' is not an option of reading (" +
                              [&] {
                                  std::string list;
                                  for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + a;
                                  return list;
                              }() + ")");
        session::setOption(o, name, value);
    }
    o.field = field;  // a field derived where the file is read (skin-friction) must reach the reader
    auto d = std::make_shared<detail::SurfaceData>();
    d->source = path;
    d->read = session::sourceOptions(o);
    std::unique_ptr<core::StepProvider> steps = io::openInput(path, d->read);
    if (steps->count() == 1) {  // read once, shared by every render
        auto data = std::make_shared<core::Dataset>();
        data->source = path;
        data->steps.push_back({steps->time(0), steps->load(0)});
        d->dataset = data;
        detail::SharedSteps shared(data);
        return Surface(describe(d, shared, field));
    }
    return Surface(describe(d, *steps, field));
}

void Surface::addVectors(const std::string& name, const float* vectors) {
    const core::SurfaceMesh& old = onlyMesh(*data_, "addVectors");
    if (old.findField(name)) throw ConfigError("addVectors: the surface already has an array '" + name + "'");
    core::SurfaceMesh m = old;
    core::VectorField f{name, std::vector<glm::vec3>(m.vertexCount())};
    std::copy_n(vectors, m.vertexCount() * 3, &f.values[0].x);
    m.fields.push_back(std::move(f));
    core::validateMesh(m, data_->source);
    auto data = std::make_shared<core::Dataset>(*data_->dataset);
    data->steps.front().mesh = std::move(m);
    auto d = std::make_shared<detail::SurfaceData>(*data_);
    d->dataset = data;
    d->fields.push_back(name);
    data_ = d;  // copies of this Surface keep the old data
}

void Surface::setField(const std::string& name) {
    if (std::find(data_->fields.begin(), data_->fields.end(), name) == data_->fields.end()) {
        std::string list;
        for (const auto& f : data_->fields) list += (list.empty() ? "" : ", ") + f;
        throw FieldError(data_->source + ": no vector field '" + name + "' (has: " + list + ")");
    }
    auto d = std::make_shared<detail::SurfaceData>(*data_);
    d->field = name;
    data_ = d;
}

const std::string& Surface::field() const { return data_->field; }
std::vector<std::string> Surface::vectorFields() const { return data_->fields; }
size_t Surface::pointCount() const { return data_->points; }
size_t Surface::triangleCount() const { return data_->triangles; }
size_t Surface::stepCount() const { return data_->times.size(); }
std::vector<double> Surface::times() const { return data_->times; }
const std::string& Surface::source() const { return data_->source; }

std::vector<std::string> SurfaceArrays::arrayNames() const {
    std::vector<std::string> names;
    for (const auto& a : arrays) names.push_back(a.name);
    return names;
}

const PointArray& SurfaceArrays::array(const std::string& name) const {
    for (const auto& a : arrays)
        if (a.name == name) return a;
    std::string list;
    for (const auto& a : arrays) list += (list.empty() ? "" : ", ") + a.name;
    throw FieldError("no point array '" + name + "' (has: " + (list.empty() ? "none" : list) + ")");
}

SurfaceArrays Surface::arrays(size_t step) const {
    const size_t count = data_->times.size();
    if (step >= count)
        throw ConfigError(data_->source + ": step " + std::to_string(step) + " is out of range (" +
                          (count == 1 ? "the surface has one step, 0" : "steps 0.." + std::to_string(count - 1)) + ")");
    const core::SurfaceMesh m = data_->provider()->load(step);
    SurfaceArrays out;
    out.time = data_->times[step];
    out.points.resize(m.positions.size() * 3);
    std::copy_n(reinterpret_cast<const float*>(m.positions.data()), out.points.size(), out.points.data());
    out.triangles.resize(m.triangles.size() * 3);
    std::copy_n(reinterpret_cast<const uint32_t*>(m.triangles.data()), out.triangles.size(), out.triangles.data());
    for (const auto& f : m.fields) {
        PointArray a{f.name, 3, std::vector<float>(f.values.size() * 3)};
        std::copy_n(reinterpret_cast<const float*>(f.values.data()), a.values.size(), a.values.data());
        out.arrays.push_back(std::move(a));
    }
    for (const auto& f : m.scalars) out.arrays.push_back({f.name, 1, f.values});
    return out;
}

std::vector<float> Surface::points(size_t step) const { return arrays(step).points; }
std::vector<uint32_t> Surface::triangles(size_t step) const { return arrays(step).triangles; }

PointArray Surface::pointArray(const std::string& name, size_t step) const {
    SurfaceArrays a = arrays(step);
    try {
        return a.array(name);
    } catch (const FieldError& e) {
        throw FieldError(data_->source + (stepCount() > 1 ? " step " + std::to_string(step) : "") +
                         ": " + e.what());
    }
}

Topology Surface::topology(size_t step, const std::vector<std::pair<std::string, std::string>>& options) const {
    session::RenderOptions o;
    o.field = data_->field;
    for (const auto& [name, value] : options) {
        const session::OptionSpec* spec = session::findOption(name);
        if (!spec || !spec->takes(session::FrontEnd::Renderer))
            throw ConfigError("topology: unknown option '" + name + "' (it takes the Renderer's options, e.g. "
                              "topology-scale, reverse-field)");
        session::setOption(o, name, value);
    }
    const size_t count = data_->times.size();
    if (step >= count)
        throw ConfigError(data_->source + ": step " + std::to_string(step) + " is out of range (" +
                          (count == 1 ? "the surface has one step, 0" : "steps 0.." + std::to_string(count - 1)) + ")");
    std::unique_ptr<core::StepProvider> steps = data_->provider();
    session::TopologySource source(*steps, o);
    const skeleton::Skeleton& s = source.at(step);
    Topology out;
    for (const skeleton::CriticalPoint& p : s.criticalPoints) {
        CriticalPoint c;
        for (int a = 0; a < 3; ++a) c.position[a] = p.position[a];
        c.type = skeleton::pointTypeName(p.type);
        c.index = p.index;
        for (int k = 0; k < 2; ++k) {
            c.eigenvalues[k][0] = p.eigenvalues[k].x;
            c.eigenvalues[k][1] = p.eigenvalues[k].y;
        }
        out.criticalPoints.push_back(std::move(c));
    }
    for (const skeleton::SkeletonLine& l : s.lines) {
        TopologyLine t;
        t.kind = skeleton::lineKindName(l.kind);
        for (const glm::vec3& p : l.points) t.points.insert(t.points.end(), {p.x, p.y, p.z});
        t.strength = l.strength;
        out.lines.push_back(std::move(t));
    }
    out.eulerCharacteristic = s.eulerCharacteristic;
    out.indexSum = s.indexSum;
    out.closed = s.closed;
    out.field = source.field();
    out.fieldReversed = source.reversed();
    return out;
}

void Surface::bounds(float lo[3], float hi[3]) const {
    for (int a = 0; a < 3; ++a) {
        lo[a] = data_->bounds.lo[a];
        hi[a] = data_->bounds.hi[a];
    }
}

}  // namespace flowsurf
