// `flowsurf topology INPUT -o OUT.json|.csv|.vtp`: the flow topology of the shown field
// (doc/topology.md), one file per time step with a pattern in -o (out_%04d.json).
#include "commands.h"

#include "core/errors.h"
#include "io/series_reader.h"
#include "io/skeleton_writer.h"
#include "session/scene_setup.h"
#include "session/topology_source.h"

#include <cstdio>
#include <map>

namespace flowsurf::app {

namespace {

bool endsWith(const std::string& s, const std::string& e) {
    return s.size() > e.size() && s.compare(s.size() - e.size(), e.size(), e) == 0;
}

std::string stepName(const std::string& pattern, size_t step) {
    std::vector<char> buf(pattern.size() + 32);
    std::snprintf(buf.data(), buf.size(), pattern.c_str(), int(step));
    return buf.data();
}

void summarise(const std::string& path, const skeleton::Skeleton& s) {
    std::map<std::string, int> types;
    for (const auto& p : s.criticalPoints) ++types[skeleton::pointTypeName(p.type)];
    int kinds[2] = {0, 0};
    for (const auto& l : s.lines) ++kinds[size_t(l.kind)];
    std::string list;
    for (const auto& [name, n] : types) list += (list.empty() ? " (" : ", ") + std::to_string(n) + " " + name;
    if (!list.empty()) list += ")";
    std::printf("%s: %zu critical points%s, %d separation and %d attachment lines; Euler characteristic %ld%s, "
                "index sum %ld\n", path.c_str(), s.criticalPoints.size(), list.c_str(), kinds[0], kinds[1],
                s.eulerCharacteristic, s.closed ? " (closed)" : " (with boundary)", s.indexSum);
}

}  // namespace

int runTopology(const RenderOptions& o) {
    if (o.input.empty()) throw ConfigError("topology: an input file or builtin:NAME is required");
    if (o.output.empty()) throw ConfigError("topology: -o OUT.json, OUT.csv or OUT.vtp is required");
    if (!endsWith(o.output, ".json") && !endsWith(o.output, ".csv") && !endsWith(o.output, ".vtp"))
        throw ConfigError("-o " + o.output + ": the topology is written as .json, .csv or .vtp");
    const bool pattern = o.output.find('%') != std::string::npos;
    std::unique_ptr<core::StepProvider> steps = io::openInput(o.input, session::sourceOptions(o));
    session::TopologySource topology(*steps, o);
    // every step with a pattern (or the one --time-step names), else the one step
    std::vector<size_t> which;
    if (pattern && !o.timeStepGiven)
        for (size_t i = 0; i < topology.count(); ++i) which.push_back(i);
    else
        which.push_back(o.timeStep);
    if (!pattern && !o.timeStepGiven && topology.count() > 1 && !o.quiet)
        std::fprintf(stderr, "flowsurf: %s has %zu time steps: writing step 0 (a pattern such as out_%%04d.json "
                     "writes each, --time-step N another)\n", o.input.c_str(), topology.count());
    // analyse first, so an error writes nothing
    std::vector<const skeleton::Skeleton*> results;
    for (size_t step : which) results.push_back(&topology.at(step));
    for (size_t i = 0; i < which.size(); ++i) {
        const std::string path = pattern ? stepName(o.output, which[i]) : o.output;
        io::SkeletonSource source{o.input, topology.field(), topology.reversed(), which[i], steps->time(which[i]),
                                  topology.params()};
        if (endsWith(path, ".vtp")) io::writeSkeletonVtp(path, *results[i], source);
        else io::writeSkeletonText(path, *results[i], source);
        if (!o.quiet) summarise(path, *results[i]);
    }
    return 0;
}

}  // namespace flowsurf::app
