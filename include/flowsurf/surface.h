// flowsurf — a triangle surface with per-vertex vector fields, steady or a time series,
// built from caller arrays or read from a file, and its arrays out again per time step
// (SurfaceArrays). Cheap to copy (shared, immutable data).
#pragma once

#include <flowsurf/topology.h>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace flowsurf {

namespace detail {
struct SurfaceData;
}

// A per-vertex array exactly as stored (no projection, no sign rule): `components` 1 (a
// scalar: n values; NaN where a patch has none) or 3 (a vector: n x 3, row-major).
struct PointArray {
    std::string name;
    int components = 1;
    std::vector<float> values;
};

// One time step's mesh and per-vertex arrays as read: row-major copies the caller owns.
struct SurfaceArrays {
    double time = 0.0;
    std::vector<float> points;        // n x 3, object space
    std::vector<uint32_t> triangles;  // m x 3, indices into the points (zero-area ones dropped on the way in)
    std::vector<PointArray> arrays;   // the vectors, then the scalars, in the file's order

    size_t pointCount() const { return points.size() / 3; }
    std::vector<std::string> arrayNames() const;
    // The array named `name`; throws FieldError naming the arrays there are.
    const PointArray& array(const std::string& name) const;
};

class Surface {
public:
    // From arrays, copied: `points` n x 3 (object space), `triangles` m x 3 indices into
    // the points, `vectors` n x 3 (the field, named `field`), `normals` n x 3 or null
    // (computed, area-weighted). Throws FormatError naming the first bad element: an
    // index out of range, a NaN/Inf coordinate or vector, no triangles.
    static Surface fromArrays(const float* points, size_t pointCount, const uint32_t* triangles,
                              size_t triangleCount, const float* vectors, const std::string& field = "velocity",
                              const float* normals = nullptr);
    // Any input the command line reads: a file (.vtp .vtu .vtk .ply .obj .stl .foam .e
    // .case .pvd), a file series (surf_%04d.vtp, surf_*.vtp) or builtin:NAME. `field`
    // chooses the vector array (empty: the first one that is not zero everywhere). A
    // series is streamed step by step while rendering. `options`: how the file is read, by
    // the command line's names (readOptionNames(): "patches", "foam-case",
    // "foam-zero-time"). Throws IoError, FormatError, FieldError naming the file,
    // ConfigError naming a bad option.
    static Surface read(const std::string& path, const std::string& field = "",
                        const std::vector<std::pair<std::string, std::string>>& options = {});
    // The options read() takes: those of the command line that say how the input is read.
    static std::vector<std::string> readOptionNames();

    // Another n x 3 per-vertex vector array (copied), e.g. to switch fields later.
    // Throws FormatError (NaN/Inf) or ConfigError (name taken). In-memory surfaces only.
    void addVectors(const std::string& name, const float* vectors);
    // The field to show; throws FieldError if the surface has no such vector array.
    void setField(const std::string& name);

    const std::string& field() const;
    std::vector<std::string> vectorFields() const;
    size_t pointCount() const;      // of the first step
    size_t triangleCount() const;   // of the first step
    size_t stepCount() const;       // 1 for steady data
    std::vector<double> times() const;
    // Axis-aligned bounds over all steps (where known), object space.
    void bounds(float lo[3], float hi[3]) const;
    // Where it came from, for messages: the path, builtin:NAME or "arrays".
    const std::string& source() const;

    // Step `step`'s mesh and point arrays (0: the first; a series whose mesh changes gives
    // each step its own). A streamed series reads the step again on each call. Throws
    // ConfigError for a step out of range (naming the steps there are), else as read().
    SurfaceArrays arrays(size_t step = 0) const;
    // Step `step`'s points (n x 3), triangles (m x 3) or array `name` (n or n x 3, as
    // stored; FieldError naming the arrays there are): arrays(step)'s.
    std::vector<float> points(size_t step = 0) const;
    std::vector<uint32_t> triangles(size_t step = 0) const;
    PointArray pointArray(const std::string& name, size_t step = 0) const;

    // The flow topology of step `step`'s field as the renderer shows it (docs/topology.md):
    // `options` by the command line's names, those a Renderer takes ("reverse-field",
    // "topology-scale", "topology-cancel-speed", "topology-line-strength",
    // "topology-line-length", "topology-parts", "curvature-radius"). Analysed on each call.
    // Throws ConfigError (a step out of range, a bad option), FieldError (a field zero
    // everywhere, no triangles) naming the surface.
    Topology topology(size_t step = 0, const std::vector<std::pair<std::string, std::string>>& options = {}) const;

    // The library's own view of the data (for Renderer).
    const std::shared_ptr<detail::SurfaceData>& data_shared() const { return data_; }

private:
    explicit Surface(std::shared_ptr<detail::SurfaceData> d) : data_(std::move(d)) {}
    std::shared_ptr<detail::SurfaceData> data_;
};

}  // namespace flowsurf
