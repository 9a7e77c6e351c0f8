#include "io/reader/parsers.h"

#include "core/errors.h"

#include <vtkCellArray.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <fstream>
#include <string_view>
#include <system_error>
#include <vector>

namespace flowsurf::io::detail {

namespace {

// Splits a line into whitespace-separated words (views into `line`).
std::vector<std::string_view> words(std::string_view line) {
    constexpr std::string_view kSpace = " \t\r";
    std::vector<std::string_view> out;
    for (size_t i = line.find_first_not_of(kSpace); i != std::string_view::npos;) {
        const size_t end = std::min(line.find_first_of(kSpace, i), line.size());
        out.push_back(line.substr(i, end - i));
        i = line.find_first_not_of(kSpace, end);
    }
    return out;
}

bool parseDouble(std::string_view s, double& v) {
    auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    return ec == std::errc() && p == s.data() + s.size();
}

}  // namespace

vtkSmartPointer<vtkPolyData> readObj(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw IoError(path + ": cannot open (" + std::system_category().message(errno) + ")");
    auto points = vtkSmartPointer<vtkPoints>::New();
    auto polys = vtkSmartPointer<vtkCellArray>::New();
    std::vector<vtkIdType> face;
    std::string line;
    for (long lineNo = 1; std::getline(in, line); ++lineNo) {
        const auto w = words(line);
        if (w.empty() || (w[0] != "v" && w[0] != "f")) continue;
        auto bad = [&](const std::string& why) {
            return FormatError(path + ": OBJ line " + std::to_string(lineNo) + ": " + why);
        };
        if (w[0] == "v") {
            double x, y, z;  // an optional w (weight) or colour may follow
            if (w.size() < 4 || !parseDouble(w[1], x) || !parseDouble(w[2], y) || !parseDouble(w[3], z))
                throw bad("a vertex needs three numbers: '" + shown(line) + "'");
            points->InsertNextPoint(x, y, z);
            continue;
        }
        face.clear();
        const long long count = points->GetNumberOfPoints();
        for (size_t k = 1; k < w.size(); ++k) {
            const std::string_view index = w[k].substr(0, w[k].find('/'));
            long long i = 0;
            auto [p, ec] = std::from_chars(index.data(), index.data() + index.size(), i);
            if (ec != std::errc() || p != index.data() + index.size())
                throw bad("'" + shown(w[k]) + "' is not a vertex index");
            // Negative: counted back from the last vertex defined so far (-1 = last).
            const long long zeroBased = i < 0 ? count + i : i - 1;
            if (i == 0 || zeroBased < 0 || zeroBased >= count)
                throw bad("vertex index " + std::to_string(i) + " is out of range (" + std::to_string(count) +
                          " vertices so far)");
            face.push_back(zeroBased);
        }
        if (face.size() < 3) throw bad("a face needs at least 3 vertices");
        polys->InsertNextCell(vtkIdType(face.size()), face.data());
    }
    if (in.bad()) throw IoError(path + ": cannot read (" + std::system_category().message(errno) + ")");
    auto poly = vtkSmartPointer<vtkPolyData>::New();
    poly->SetPoints(points);
    poly->SetPolys(polys);
    return poly;
}

}  // namespace flowsurf::io::detail
