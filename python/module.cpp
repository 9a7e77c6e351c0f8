// flowsurf._flowsurf — the Python binding of the public C++ library (pybind11 + numpy).
// numpy arrays in (any dtype, any strides: converted), numpy arrays out; rendering
// releases the GIL. The keyword layer, mesh adapters and PNG encoding are in
// flowsurf/__init__.py.
#include <cmath>
#include <flowsurf/flowsurf.h>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <string>

namespace py = pybind11;
using namespace flowsurf;

namespace {

using FloatArray = py::array_t<float, py::array::c_style | py::array::forcecast>;
using IndexArray = py::array_t<int64_t, py::array::c_style | py::array::forcecast>;

// (n, 3) or raise ValueError naming the argument.
void needRows3(const py::array& a, const char* name) {
    if (a.ndim() != 2 || a.shape(1) != 3)
        throw py::value_error(std::string(name) + " must have shape (n, 3), got " + std::string(py::str(a.attr("shape"))));
}

Surface makeSurface(py::object points, py::object triangles, py::object vectors, py::object normals,
                    const std::string& field) {
    FloatArray p = FloatArray::ensure(points), v = FloatArray::ensure(vectors);
    IndexArray t = IndexArray::ensure(triangles);
    if (!p || !v || !t) throw py::value_error("points, triangles and vectors must be numeric arrays");
    needRows3(p, "points");
    needRows3(t, "triangles");
    needRows3(v, "vectors");
    const size_t n = size_t(p.shape(0)), m = size_t(t.shape(0));
    if (size_t(v.shape(0)) != n)
        throw py::value_error("vectors has " + std::to_string(v.shape(0)) + " rows, points " + std::to_string(n));
    std::vector<uint32_t> tri(m * 3);
    const int64_t* ti = t.data();
    for (size_t i = 0; i < m * 3; ++i) {
        if (ti[i] < 0 || size_t(ti[i]) >= n)
            throw FormatError("triangles: triangle " + std::to_string(i / 3) + " has index " + std::to_string(ti[i]) +
                              ", out of range for " + std::to_string(n) + " points");
        tri[i] = uint32_t(ti[i]);
    }
    FloatArray nrm;
    if (!normals.is_none()) {
        nrm = FloatArray::ensure(normals);
        if (!nrm) throw py::value_error("normals must be a numeric array");
        needRows3(nrm, "normals");
        if (size_t(nrm.shape(0)) != n) throw py::value_error("normals must have one row per point");
    }
    py::gil_scoped_release release;
    return Surface::fromArrays(p.data(), n, tri.data(), m, v.data(), field, normals.is_none() ? nullptr : nrm.data());
}

py::array_t<uint8_t> image(const Renderer& r) {
    py::array_t<uint8_t> out({r.height(), r.width(), 3});
    uint8_t* data = out.mutable_data();
    py::gil_scoped_release release;
    r.readImage(data);
    return out;
}

py::array_t<float> flowTexture(const Renderer& r) {
    py::array_t<float> out({r.height(), r.width()});
    float* data = out.mutable_data();
    py::gil_scoped_release release;
    r.readFlowTexture(data);
    return out;
}

// A read-only numpy array over `values` (moved into the capsule that owns them).
template <typename T>
py::array readOnly(std::vector<T> values, std::vector<py::ssize_t> shape) {
    auto* owned = new std::vector<T>(std::move(values));
    py::capsule free(owned, [](void* p) { delete static_cast<std::vector<T>*>(p); });
    py::array_t<T> a(shape, owned->data(), free);
    a.attr("setflags")(py::arg("write") = false);
    return a;  // moved: C++20 moves a local into its base class on return
}

// A Python step index as the library's; a negative one is refused as the library refuses
// one too large.
size_t stepIndex(const Surface& s, int64_t step) {
    if (step >= 0) return size_t(step);
    const size_t n = s.stepCount();
    throw ConfigError(s.source() + ": step " + std::to_string(step) + " is out of range (" +
                      (n == 1 ? "the surface has one step, 0" : "steps 0.." + std::to_string(n - 1)) + ")");
}

SurfaceArrays stepArrays(const Surface& s, int64_t step) {
    const size_t index = stepIndex(s, step);
    py::gil_scoped_release release;
    return s.arrays(index);
}

// (n,) for a scalar, (n, 3) for a vector.
py::array arrayOf(PointArray v) {
    const auto c = py::ssize_t(v.components);
    if (c == 1) return readOnly(std::move(v.values), {py::ssize_t(v.values.size())});
    return readOnly(std::move(v.values), {py::ssize_t(v.values.size()) / c, c});
}

// Errors: what a user can cause maps to Python's own kinds.
void bindErrors(py::module_& m) {
    static py::exception<FormatError> formatError(m, "FormatError", PyExc_ValueError);
    static py::exception<FieldError> fieldError(m, "FieldError", PyExc_ValueError);
    static py::exception<GlError> glError(m, "GlError", PyExc_RuntimeError);
    py::register_exception_translator([](std::exception_ptr p) {
        try {
            if (p) std::rethrow_exception(p);
        } catch (const FormatError& e) {
            formatError(e.what());
        } catch (const FieldError& e) {
            fieldError(e.what());
        } catch (const IoError& e) {
            PyErr_SetString(PyExc_OSError, e.what());
        } catch (const ConfigError& e) {
            PyErr_SetString(PyExc_ValueError, e.what());
        } catch (const GlError& e) {
            glError(e.what());
        }
    });
}

// Surface (from arrays or read from a file) and read()'s options.
void bindSurface(py::module_& m) {
    py::class_<Surface>(m, "Surface")
        .def(py::init(&makeSurface), py::arg("points"), py::arg("triangles"), py::arg("vectors"),
             py::arg("normals") = py::none(), py::arg("field") = "velocity",
             "A surface from arrays: points (n,3), triangles (m,3) indices, vectors (n,3); copied")
        .def("add_vectors",
             [](Surface& s, const std::string& name, py::object vectors) {
                 FloatArray v = FloatArray::ensure(vectors);
                 if (!v) throw py::value_error("vectors must be a numeric array");
                 needRows3(v, "vectors");
                 if (size_t(v.shape(0)) != s.pointCount()) throw py::value_error("vectors must have one row per point");
                 s.addVectors(name, v.data());
             },
             py::arg("name"), py::arg("vectors"))
        .def("set_field", &Surface::setField, py::arg("name"))
        .def("points",
             [](const Surface& s, int64_t step) {
                 SurfaceArrays a = stepArrays(s, step);
                 const auto n = py::ssize_t(a.pointCount());
                 return readOnly(std::move(a.points), {n, 3});
             },
             py::arg("step") = 0, "The points of time step `step` (0: the first), (n, 3) float32, read-only")
        .def("triangles",
             [](const Surface& s, int64_t step) {
                 const SurfaceArrays a = stepArrays(s, step);
                 return readOnly(std::vector<int64_t>(a.triangles.begin(), a.triangles.end()),
                                 {py::ssize_t(a.triangles.size() / 3), 3});
             },
             py::arg("step") = 0, "The triangles of time step `step`, (m, 3) int64 point indices, read-only")
        .def("point_array",
             [](const Surface& s, const std::string& name, int64_t step) {
                 const size_t index = stepIndex(s, step);
                 PointArray v;
                 {
                     py::gil_scoped_release release;
                     v = s.pointArray(name, index);
                 }
                 return arrayOf(std::move(v));
             },
             py::arg("name"), py::arg("step") = 0,
             "The per-point array `name` of time step `step` exactly as stored: (n,) float32 for a scalar, (n, 3) "
             "for a vector, read-only")
        .def("point_arrays", [](const Surface& s, int64_t step) { return stepArrays(s, step).arrayNames(); },
             py::arg("step") = 0, "The names of the per-point arrays of time step `step`")
        .def_property_readonly("field", &Surface::field)
        .def_property_readonly("fields", &Surface::vectorFields)
        .def_property_readonly("point_count", &Surface::pointCount)
        .def_property_readonly("triangle_count", &Surface::triangleCount)
        .def_property_readonly("times", &Surface::times)
        .def_property_readonly("source", &Surface::source)
        .def_property_readonly("bounds",
                               [](const Surface& s) {
                                   float lo[3], hi[3];
                                   s.bounds(lo, hi);
                                   return py::make_tuple(py::make_tuple(lo[0], lo[1], lo[2]),
                                                         py::make_tuple(hi[0], hi[1], hi[2]));
                               })
        .def("__repr__", [](const Surface& s) {
            return "<flowsurf.Surface " + s.source() + ": " + std::to_string(s.pointCount()) + " points, " +
                   std::to_string(s.triangleCount()) + " triangles, field '" + s.field() + "', " +
                   std::to_string(s.stepCount()) + " step(s)>";
        });
    m.def("_read", &Surface::read, py::arg("path"), py::arg("field") = "",
          py::arg("options") = std::vector<std::pair<std::string, std::string>>{},
          py::call_guard<py::gil_scoped_release>(),
          "Read a surface: any format the command line reads, a file series, or builtin:NAME");
    m.def("read_option_names", &Surface::readOptionNames, "The options of read(): how the input is read");
    m.def("_topology",
          [](const Surface& s, int64_t step, const std::vector<std::pair<std::string, std::string>>& options) {
              const size_t index = stepIndex(s, step);
              Topology t;
              {
                  py::gil_scoped_release release;
                  t = s.topology(index, options);
              }
              std::vector<float> positions;
              std::vector<int64_t> indices;
              py::list types;
              for (const CriticalPoint& p : t.criticalPoints) {
                  positions.insert(positions.end(), p.position, p.position + 3);
                  indices.push_back(p.index);
                  types.append(p.type);
              }
              py::list lines;
              for (TopologyLine& l : t.lines) {
                  py::dict line;
                  line["kind"] = l.kind;
                  const auto n = py::ssize_t(l.points.size() / 3);
                  line["points"] = readOnly(std::move(l.points), {n, 3});
                  line["strength"] = readOnly(std::move(l.strength), {n});
                  lines.append(line);
              }
              py::dict out;
              const auto k = py::ssize_t(indices.size());
              out["positions"] = readOnly(std::move(positions), {k, 3});
              out["types"] = types;
              out["index"] = readOnly(std::move(indices), {k});
              out["lines"] = lines;
              out["euler_characteristic"] = t.eulerCharacteristic;
              out["index_sum"] = t.indexSum;
              out["closed"] = t.closed;
              out["field"] = t.field;
              out["field_reversed"] = t.fieldReversed;
              return out;
          },
          py::arg("surface"), py::arg("step") = 0,
          py::arg("options") = std::vector<std::pair<std::string, std::string>>{},
          "The flow topology of time step `step` (see flowsurf.topology)");
}

// The quality of the last frames: metrics by the JSON report's names; None where not
// measured (NaN).
py::dict qualityDict(const Renderer& r) {
    Quality q;
    {
        py::gil_scoped_release release;
        q = r.quality();
    }
    auto named = [](const QualityMetrics& metrics) {
        py::dict d;
        for (const auto& [name, value] : metrics.named())
            d[py::str(name)] = std::isnan(value) ? py::object(py::none()) : py::object(py::float_(value));
        return d;
    };
    return py::dict(py::arg("frames") = q.frames, py::arg("median") = named(q.median), py::arg("worst") = named(q.worst));
}

py::dict cameraDict(const Renderer& r) {
    const CameraView c = r.camera();
    return py::dict(py::arg("eye") = py::make_tuple(c.eye[0], c.eye[1], c.eye[2]),
                    py::arg("target") = py::make_tuple(c.target[0], c.target[1], c.target[2]),
                    py::arg("up") = py::make_tuple(c.up[0], c.up[1], c.up[2]), py::arg("fov") = c.fovDeg);
}

// The renderer (flowsurf/__init__.py's Renderer wraps it with keywords).
void bindRenderer(py::module_& m) {
    py::class_<Renderer>(m, "_Renderer")
        .def(py::init([]() { return std::make_unique<Renderer>(); }), py::call_guard<py::gil_scoped_release>())
        .def("set", &Renderer::set)
        .def("get", &Renderer::get)
        .def("add_dye", &Renderer::addDye, py::arg("point"), py::arg("radius") = 0.0f, py::arg("color") = "")
        .def("render", &Renderer::render, py::call_guard<py::gil_scoped_release>())
        .def("begin", &Renderer::begin, py::call_guard<py::gil_scoped_release>())
        .def("advance", &Renderer::advance, py::call_guard<py::gil_scoped_release>())
        .def("image", &image)
        .def("flow_texture", &flowTexture)
        .def("stage_ms", [](const Renderer& r) {
            py::dict d;
            for (const auto& [stage, ms] : r.stageMs()) d[py::str(stage)] = ms;
            return d;
        })
        .def("camera", &cameraDict)
        .def_property_readonly("frame", &Renderer::frame)
        .def_property_readonly("time", &Renderer::time)
        .def_property_readonly("width", &Renderer::width)
        .def_property_readonly("height", &Renderer::height)
        .def("gl_renderer", &Renderer::glRenderer)
        .def("set_quality_every", &Renderer::setQualityEvery)
        .def("quality", &qualityDict);
}

// The option table as the keyword layer reads it.
void bindOptions(py::module_& m) {
    m.def("option_names", &Renderer::optionNames, "The render options a Renderer takes, in --help order");
    const auto rows = [](const std::vector<OptionInfo>& info) {
        py::list rows;
        for (const OptionInfo& o : info)
            rows.append(py::dict(py::arg("name") = o.name, py::arg("group") = o.group, py::arg("help") = o.help,
                                 py::arg("kind") = o.kind, py::arg("min") = o.min, py::arg("max") = o.max,
                                 py::arg("choices") = o.choices, py::arg("default") = o.defaultValue,
                                 py::arg("separator") = o.separator, py::arg("methods") = o.methods));
        return rows;
    };
    m.def("option_info", [rows] { return rows(Renderer::optionInfo()); },
          "The render options described (name, group, help, kind, min, max, choices, default, separator, "
          "methods: those whose images it changes), in --help order");
    m.def("read_option_info", [rows] { return rows(Renderer::readOptionInfo()); },
          "The options of read() described as option_info() describes the render options");
}

// Writers of what Python renders: MP4 (Animation) and PNG.
void bindWriters(py::module_& m) {
    py::class_<VideoWriter>(m, "_VideoWriter")
        .def(py::init<const std::string&, int, int, int, int>(), py::arg("path"), py::arg("width"), py::arg("height"),
             py::arg("fps") = 30, py::arg("crf") = 18)
        .def("add_frame",
             [](VideoWriter& w, py::array_t<uint8_t, py::array::c_style | py::array::forcecast> rgb) {
                 if (rgb.ndim() != 3 || rgb.shape(2) != 3 || rgb.shape(0) != w.height() || rgb.shape(1) != w.width())
                     throw py::value_error("frame must have shape (" + std::to_string(w.height()) + ", " +
                                           std::to_string(w.width()) + ", 3), got " +
                                           std::string(py::str(rgb.attr("shape"))));
                 const uint8_t* data = rgb.data();
                 py::gil_scoped_release release;
                 w.addFrame(data);
             })
        .def("finish", &VideoWriter::finish, py::call_guard<py::gil_scoped_release>());
    m.def("_write_png", [](const std::string& path, py::array_t<uint8_t, py::array::c_style | py::array::forcecast> rgb) {
        if (rgb.ndim() != 3 || rgb.shape(2) != 3) throw py::value_error("image must have shape (h, w, 3)");
        writePng(path, int(rgb.shape(1)), int(rgb.shape(0)), rgb.data());
    });
}

}  // namespace

PYBIND11_MODULE(_flowsurf, m) {
    m.doc() = "flowsurf: dense, animated flow textures on triangle-mesh surfaces (C++ core)";
    bindErrors(m);
    bindSurface(m);
    bindRenderer(m);
    bindOptions(m);
    bindWriters(m);
}
