#include "io/skeleton_writer.h"

#include "core/errors.h"
#include "io/text_writer.h"

#include <nlohmann/json.hpp>

#include <cstdio>

namespace flowsurf::io {

namespace {

nlohmann::json point3(const glm::vec3& p) { return nlohmann::json::array({p.x, p.y, p.z}); }

}  // namespace

std::string skeletonJson(const skeleton::Skeleton& s, const SkeletonSource& source) {
    nlohmann::json points = nlohmann::json::array();
    for (const skeleton::CriticalPoint& p : s.criticalPoints)
        points.push_back({{"position", point3(p.position)},
                          {"type", skeleton::pointTypeName(p.type)},
                          {"index", p.index},
                          {"eigenvalues", {{p.eigenvalues[0].x, p.eigenvalues[0].y},
                                           {p.eigenvalues[1].x, p.eigenvalues[1].y}}},
                          {"merged_zeros", p.merged}});
    nlohmann::json lines = nlohmann::json::array();
    for (const skeleton::SkeletonLine& l : s.lines) {
        nlohmann::json pts = nlohmann::json::array();
        for (const glm::vec3& p : l.points) pts.push_back(point3(p));
        lines.push_back({{"kind", skeleton::lineKindName(l.kind)},
                         {"points", pts},
                         {"strength", l.strength},
                         {"length", l.length}});
    }
    const skeleton::SkeletonParams& p = source.params;
    nlohmann::json out = {
        {"critical_points", points},
        {"lines", lines},
        {"euler_characteristic", s.eulerCharacteristic},
        {"index_sum", s.indexSum},
        {"closed", s.closed},
        {"parts", s.parts},
        {"vertices", s.weldedVertices},
        {"triangles", s.triangles},
        {"zeros_before_merging", s.zeros},
        {"input", source.input},
        {"field", source.field},
        {"field_reversed", source.fieldReversed},
        {"step", source.step},
        {"time", source.time},
        {"scale", s.scale},
        {"speed_99", s.speed99},
        {"parameters",
         {{"scale", p.scale}, {"cancel_speed", p.cancelSpeed}, {"spiral_ratio", p.spiralRatio},
          {"line_strength", p.lineStrength}, {"line_length", p.lineLength}, {"line_angle", p.lineAngle}}},
    };
    return out.dump(1) + "\n";
}

std::string skeletonCsv(const skeleton::Skeleton& s) {
    std::string out = "record,id,type,index,x,y,z,strength\n";
    char row[256];
    for (size_t i = 0; i < s.criticalPoints.size(); ++i) {
        const skeleton::CriticalPoint& p = s.criticalPoints[i];
        std::snprintf(row, sizeof row, "point,%zu,%s,%d,%.9g,%.9g,%.9g,\n", i, skeleton::pointTypeName(p.type),
                      p.index, double(p.position.x), double(p.position.y), double(p.position.z));
        out += row;
    }
    for (size_t i = 0; i < s.lines.size(); ++i)
        for (size_t k = 0; k < s.lines[i].points.size(); ++k) {
            const glm::vec3& p = s.lines[i].points[k];
            std::snprintf(row, sizeof row, "line,%zu,%s,,%.9g,%.9g,%.9g,%.6g\n", i,
                          skeleton::lineKindName(s.lines[i].kind), double(p.x), double(p.y), double(p.z),
                          double(s.lines[i].strength[k]));
            out += row;
        }
    return out;
}

void writeSkeletonText(const std::string& path, const skeleton::Skeleton& s, const SkeletonSource& source) {
    auto endsWith = [&](const char* ext) {
        const std::string e(ext);
        return path.size() > e.size() && path.compare(path.size() - e.size(), e.size(), e) == 0;
    };
    if (endsWith(".json")) writeTextFile(path, skeletonJson(s, source));
    else if (endsWith(".csv")) writeTextFile(path, skeletonCsv(s));
    else throw ConfigError("-o " + path + ": the topology is written as .json, .csv or .vtp");
}

}  // namespace flowsurf::io
