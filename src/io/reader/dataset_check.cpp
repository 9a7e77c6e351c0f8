#include "io/reader/checks.h"

#include "core/errors.h"

#include <vtkCell.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkCellType.h>
#include <vtkCellTypes.h>
#include <vtkDataArray.h>
#include <vtkGenericCell.h>
#include <vtkIdTypeArray.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>

#include <cstring>
#include <map>

namespace flowsurf::io::detail {

namespace {

void checkArrays(vtkFieldData* arrays, vtkIdType expected, const char* kind, const std::string& where) {
    for (int i = 0; i < arrays->GetNumberOfArrays(); ++i) {
        vtkAbstractArray* a = arrays->GetAbstractArray(i);
        if (!a || a->GetNumberOfTuples() == expected) continue;
        throw FormatError(where + ": " + kind + " array '" + (a->GetName() ? a->GetName() : "?") + "' has " +
                          std::to_string(a->GetNumberOfTuples()) + " values for " + std::to_string(expected) +
                          " " + kind + "s");
    }
}

// Offsets consistent with the connectivity, every point index in range.
void checkConnectivity(vtkCellArray* cells, vtkIdType points, const char* kind, const std::string& where) {
    if (!cells || cells->GetNumberOfCells() == 0) return;
    if (!cells->IsValid())
        throw FormatError(where + ": the " + std::string(kind) + " offsets are inconsistent with the connectivity");
    double range[2];
    cells->GetConnectivityArray()->GetRange(range, 0);
    if (range[0] < 0 || range[1] >= static_cast<double>(points))
        throw FormatError(where + ": a " + (std::string(kind) == "cell" ? "" : std::string(kind) + " ") +
                          "cell refers to point index " +
                          std::to_string(static_cast<long long>(range[0] < 0 ? range[0] : range[1])) +
                          " (counting from 0) but there are only " + std::to_string(points) + " points");
}

void checkMinimumSize(vtkCellArray* cells, vtkIdType minimum, const char* kind, const std::string& where) {
    for (vtkIdType c = 0; cells && c < cells->GetNumberOfCells(); ++c)
        if (cells->GetCellSize(c) < minimum)
            throw FormatError(where + ": " + kind + " " + std::to_string(c) + " has " +
                              std::to_string(cells->GetCellSize(c)) + " points (at least " +
                              std::to_string(minimum) + " needed)");
}

// How many points a cell type takes: exact for fixed types (asked of a VTK instance),
// a minimum for variable ones; count < 0 for types VTK does not know.
struct CellRule {
    vtkIdType count;
    bool exact;
};
CellRule cellRule(int type) {
    switch (type) {
        case VTK_EMPTY_CELL: return {0, true};
        case VTK_POLY_VERTEX: return {1, false};
        case VTK_POLY_LINE: return {2, false};
        case VTK_TRIANGLE_STRIP: case VTK_POLYGON: return {3, false};
        case VTK_POLYHEDRON: case VTK_CONVEX_POINT_SET: return {4, false};
        case VTK_QUADRATIC_POLYGON: return {6, false};
        default: break;
    }
    if (type < 0 || type >= VTK_NUMBER_OF_CELL_TYPES ||
        std::strcmp(vtkCellTypes::GetClassNameFromTypeId(type), "UnknownClass") == 0)
        return {-1, false};
    auto cell = vtkSmartPointer<vtkCell>::Take(vtkGenericCell::InstantiateCell(type));
    if (!cell || cell->GetCellType() != type) return {-1, false};
    // Higher-order (Lagrange, Bezier) cells start empty: their degree follows the count.
    return cell->GetNumberOfPoints() > 0 ? CellRule{cell->GetNumberOfPoints(), true} : CellRule{1, false};
}

// A polyhedron's face stream: nFaces, then (nPoints, ids...) per face.
void checkPolyhedron(vtkUnstructuredGrid* grid, vtkIdType cell, const std::string& where) {
    vtkIdTypeArray* faces = grid->GetFaces();
    vtkIdTypeArray* locations = grid->GetFaceLocations();
    const std::string what = where + ": polyhedron cell " + std::to_string(cell);
    if (!faces || !locations || locations->GetNumberOfTuples() <= cell)
        throw FormatError(what + " has no faces");
    vtkIdType at = locations->GetValue(cell);
    const vtkIdType size = faces->GetNumberOfTuples(), points = grid->GetNumberOfPoints();
    if (at < 0 || at >= size) throw FormatError(what + " has no faces");
    const vtkIdType nFaces = faces->GetValue(at++);
    for (vtkIdType f = 0; f < nFaces; ++f) {
        if (at >= size) throw FormatError(what + ": the face list is cut short");
        const vtkIdType n = faces->GetValue(at++);
        if (n < 3 || n > size - at) throw FormatError(what + ": face " + std::to_string(f) + " is malformed");
        for (vtkIdType k = 0; k < n; ++k, ++at)
            if (faces->GetValue(at) < 0 || faces->GetValue(at) >= points)
                throw FormatError(what + ": face " + std::to_string(f) + " refers to point index " +
                                  std::to_string(faces->GetValue(at)) + " of " + std::to_string(points));
    }
}

void checkCellTypes(vtkUnstructuredGrid* grid, const std::string& where) {
    vtkUnsignedCharArray* types = grid->GetCellTypesArray();
    vtkCellArray* cells = grid->GetCells();
    const vtkIdType count = grid->GetNumberOfCells();
    if (count == 0) return;
    if (!types || !cells || types->GetNumberOfTuples() != count || cells->GetNumberOfCells() != count)
        throw FormatError(where + ": the cell types do not match the number of cells");
    std::map<int, CellRule> rules;
    for (vtkIdType c = 0; c < count; ++c) {
        const int type = types->GetValue(c);
        auto it = rules.find(type);
        if (it == rules.end()) it = rules.emplace(type, cellRule(type)).first;
        const CellRule rule = it->second;
        const vtkIdType n = cells->GetCellSize(c);
        if (rule.count < 0)
            throw FormatError(where + ": cell " + std::to_string(c) + " has an unknown type " + std::to_string(type));
        if (rule.exact ? n != rule.count : n < rule.count)
            throw FormatError(where + ": cell " + std::to_string(c) + " (" +
                              vtkCellTypes::GetClassNameFromTypeId(type) + ") has " + std::to_string(n) +
                              " points, " + (rule.exact ? "" : "at least ") + std::to_string(rule.count) +
                              " expected");
        if (type == VTK_POLYHEDRON) checkPolyhedron(grid, c, where);
    }
}

}  // namespace

void checkDataSet(vtkDataSet* data, const std::string& where) {
    const vtkIdType points = data->GetNumberOfPoints();
    checkArrays(data->GetPointData(), points, "point", where);
    checkArrays(data->GetCellData(), data->GetNumberOfCells(), "cell", where);
    if (auto* pd = vtkPolyData::SafeDownCast(data)) {
        const std::pair<vtkCellArray*, const char*> parts[] = {
            {pd->GetVerts(), "vertex"}, {pd->GetLines(), "line"}, {pd->GetPolys(), "polygon"}, {pd->GetStrips(), "strip"}};
        const vtkIdType minimum[] = {1, 2, 3, 3};
        for (int i = 0; i < 4; ++i) {
            checkConnectivity(parts[i].first, points, parts[i].second, where);
            checkMinimumSize(parts[i].first, minimum[i], parts[i].second, where);
        }
    } else if (auto* ug = vtkUnstructuredGrid::SafeDownCast(data)) {
        checkConnectivity(ug->GetCells(), points, "cell", where);
        checkCellTypes(ug, where);
    }
}

}  // namespace flowsurf::io::detail
