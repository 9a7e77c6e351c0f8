// Sections: the file · sizes a file can hold · face sections (unstructured) · faces of a
// BC (unstructured, structured) · readCgnsZones (and the time steps' solution pointers).
#include "io/reader/cgns_boundaries.h"

#include "core/errors.h"
#include "io/reader/vtk_messages.h"

#include <cgnslib.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <set>

namespace flowsurf::io::detail {

namespace {

namespace fs = std::filesystem;

// --- the file ------------------------------------------------------------------------
// libcgns keeps its open files in a table of its own: one file, closed on every way out.
class CgnsFile {
public:
    explicit CgnsFile(const std::string& path) : path_(path) {
        if (cg_open(path.c_str(), CG_MODE_READ, &fn_) != CG_OK)
            throw FormatError(path + ": cannot read the CGNS file (libcgns: " + std::string(cg_get_error()) + ")");
    }
    ~CgnsFile() { cg_close(fn_); }
    CgnsFile(const CgnsFile&) = delete;
    CgnsFile& operator=(const CgnsFile&) = delete;

    int fn() const { return fn_; }
    void check(int rc, const std::string& where) const {
        if (rc != CG_OK) throw FormatError(path_ + ": " + where + ": " + cg_get_error());
    }
    [[noreturn]] void fail(const std::string& where, const std::string& what) const {
        throw FormatError(path_ + ": " + where + ": " + what);
    }
    const std::string& path() const { return path_; }

private:
    std::string path_;
    int fn_ = -1;
};

// --- sizes a file can hold ---------------------------------------------------------------
// A count is believed when its items, at 4 bytes each (the smallest CGNS stores them in),
// fit in the files the reader may see: this file and, for linked nodes, the others in its
// folder. Counts beyond that are a damaged or hostile file, refused before any allocation.
uint64_t bytesAvailable(const std::string& path) {
    std::error_code ec;
    uint64_t bytes = 0;
    const fs::path dir = fs::path(path).has_parent_path() ? fs::path(path).parent_path() : fs::path(".");
    for (const auto& e : fs::directory_iterator(dir, ec))
        if (e.is_regular_file(ec)) bytes += e.file_size(ec);
    return std::max<uint64_t>(bytes, fs::file_size(path, ec));
}

struct Limits {
    uint64_t bytes;
    void check(const CgnsFile& f, const std::string& where, const char* what, long long count, int bytesEach) const {
        if (count < 0 || uint64_t(count) * uint64_t(bytesEach) > bytes)
            f.fail(where, std::to_string(count) + " " + what + " cannot be stored in " + std::to_string(bytes) +
                              " bytes (the file and its folder); the file is damaged");
    }
};

// --- face sections (unstructured) -------------------------------------------------------------
bool isFaceType(CGNS_ENUMT(ElementType_t) t) {
    switch (t) {
        case CGNS_ENUMV(TRI_3): case CGNS_ENUMV(TRI_6): case CGNS_ENUMV(TRI_9): case CGNS_ENUMV(TRI_10):
        case CGNS_ENUMV(TRI_12): case CGNS_ENUMV(TRI_15): case CGNS_ENUMV(QUAD_4): case CGNS_ENUMV(QUAD_8):
        case CGNS_ENUMV(QUAD_9): case CGNS_ENUMV(QUAD_12): case CGNS_ENUMV(QUAD_16): case CGNS_ENUMV(QUAD_P4_16):
        case CGNS_ENUMV(QUAD_25): return true;
        default: return false;
    }
}
// The corners a face is drawn by (higher-order nodes follow them in CGNS's numbering).
int cornersOf(CGNS_ENUMT(ElementType_t) t) {
    switch (t) {
        case CGNS_ENUMV(TRI_3): case CGNS_ENUMV(TRI_6): case CGNS_ENUMV(TRI_9): case CGNS_ENUMV(TRI_10):
        case CGNS_ENUMV(TRI_12): case CGNS_ENUMV(TRI_15): return 3;
        default: return 4;
    }
}

// One Elements_t node's faces (elements that are no face: an empty polygon).
struct FaceSection {
    cgsize_t start = 0, end = 0;
    std::vector<vtkIdType> offsets{0}, ids;
};

std::vector<FaceSection> readFaceSections(const CgnsFile& f, int b, int z, const CgnsZone& zone, const Limits& limits,
                                          cgsize_t& maxElement) {
    int sections = 0;
    const std::string where = "zone " + zone.base + "/" + zone.name;
    f.check(cg_nsections(f.fn(), b, z, &sections), where);
    std::vector<FaceSection> out;
    maxElement = 0;
    for (int s = 1; s <= sections; ++s) {
        char name[33] = {};
        CGNS_ENUMT(ElementType_t) type;
        cgsize_t start = 0, end = 0;
        int nbndry = 0, parent = 0;
        f.check(cg_section_read(f.fn(), b, z, s, name, &type, &start, &end, &nbndry, &parent), where);
        const std::string at = where + ", section " + name;
        if (start < 1 || end < start) f.fail(at, "element range " + std::to_string(start) + ".." + std::to_string(end));
        limits.check(f, at, "elements", end - start + 1, 4);
        maxElement = std::max(maxElement, end);
        const bool mixed = type == CGNS_ENUMV(MIXED), ngon = type == CGNS_ENUMV(NGON_n);
        if (!mixed && !ngon && !isFaceType(type)) continue;
        cgsize_t size = 0;
        f.check(cg_ElementDataSize(f.fn(), b, z, s, &size), at);
        limits.check(f, at, "connectivity entries", size, 4);
        const cgsize_t n = end - start + 1;
        std::vector<cgsize_t> conn(static_cast<size_t>(size)), offsets;
        if (mixed || ngon) {
            offsets.resize(size_t(n) + 1);
            f.check(cg_poly_elements_read(f.fn(), b, z, s, conn.data(), offsets.data(), nullptr), at);
        } else {
            f.check(cg_elements_read(f.fn(), b, z, s, conn.data(), nullptr), at);
        }
        FaceSection sec;
        sec.start = start;
        sec.end = end;
        int npe = 0;
        if (!mixed && !ngon) f.check(cg_npe(type, &npe), at);
        for (cgsize_t e = 0; e < n; ++e) {
            cgsize_t first = e * npe, count = npe;
            CGNS_ENUMT(ElementType_t) t = type;
            if (mixed || ngon) {
                first = offsets[size_t(e)];
                count = offsets[size_t(e) + 1] - first;
                if (first < 0 || count < 0 || first + count > size) f.fail(at, "element offsets out of range");
                if (mixed && count > 0) {
                    t = CGNS_ENUMT(ElementType_t)(conn[size_t(first)]);
                    ++first, --count;
                }
            }
            if (first + count > size) f.fail(at, "connectivity shorter than its elements");
            const bool face = ngon ? count >= 3 : isFaceType(t) && count >= cornersOf(t);
            if (face) {
                const cgsize_t corners = ngon ? count : cornersOf(t);
                for (cgsize_t k = 0; k < corners; ++k) {
                    const cgsize_t v = conn[size_t(first + k)];
                    if (v < 1 || v > zone.vertices)
                        f.fail(at, "element " + std::to_string(start + e) + " names vertex " + std::to_string(v) +
                                       " (the zone has " + std::to_string(zone.vertices) + ")");
                    sec.ids.push_back(vtkIdType(v - 1));
                }
            }
            sec.offsets.push_back(vtkIdType(sec.ids.size()));
        }
        out.push_back(std::move(sec));
    }
    std::sort(out.begin(), out.end(), [](const FaceSection& a, const FaceSection& b) { return a.start < b.start; });
    return out;
}

// --- faces of a BC -----------------------------------------------------------------------------
// Element ids (unstructured: FaceCenter, ElementRange/List): the faces of the sections.
// Vertex sets: every face of the sections whose corners all belong to the set.
void unstructuredFaces(const std::vector<cgsize_t>& points, bool range, bool vertices,
                       const std::vector<FaceSection>& sections, CgnsPatch& patch, size_t& missing) {
    auto addFace = [&patch](const FaceSection& s, size_t e) {
        patch.ids.insert(patch.ids.end(), s.ids.begin() + s.offsets[e], s.ids.begin() + s.offsets[e + 1]);
        patch.offsets.push_back(vtkIdType(patch.ids.size()));
    };
    if (vertices) {
        std::set<vtkIdType> in;
        if (range) for (cgsize_t v = points[0]; v <= points[1]; ++v) in.insert(vtkIdType(v - 1));
        else for (cgsize_t v : points) in.insert(vtkIdType(v - 1));
        for (const FaceSection& s : sections)
            for (size_t e = 0; e + 1 < s.offsets.size(); ++e) {
                if (s.offsets[e] == s.offsets[e + 1]) continue;
                const bool all = std::all_of(s.ids.begin() + s.offsets[e], s.ids.begin() + s.offsets[e + 1],
                                             [&in](vtkIdType v) { return in.count(v) > 0; });
                if (all) addFace(s, e);
            }
        return;
    }
    auto element = [&](cgsize_t id) {
        auto it = std::upper_bound(sections.begin(), sections.end(), id,
                                   [](cgsize_t x, const FaceSection& s) { return x < s.start; });
        if (it == sections.begin() || id > std::prev(it)->end) return ++missing, void();
        const FaceSection& s = *std::prev(it);
        const size_t e = size_t(id - s.start);
        if (s.offsets[e] == s.offsets[e + 1]) return ++missing, void();
        addFace(s, e);
    };
    if (range) for (cgsize_t id = points[0]; id <= points[1]; ++id) element(id);
    else for (cgsize_t id : points) element(id);
}

// A structured zone's BC as a range of vertices (or of faces, one less along the face's
// two directions): the quadrilaterals of that face of the block; none for a range that is
// no face (a line, a volume, beyond the block).
void structuredFaces(const std::vector<cgsize_t>& r, bool faceCentred, const CgnsZone& zone, CgnsPatch& patch) {
    cgsize_t lo[3], hi[3];
    int fixed = -1;
    for (int d = 0; d < 3; ++d) {
        lo[d] = std::min(r[size_t(d)], r[size_t(d) + 3]);
        hi[d] = std::max(r[size_t(d)], r[size_t(d) + 3]);
        if (lo[d] == hi[d] && fixed < 0) fixed = d;
    }
    if (fixed < 0) return;
    for (int d = 0; d < 3; ++d)
        if (faceCentred && d != fixed) ++hi[d];
    for (int d = 0; d < 3; ++d)
        if (lo[d] < 1 || hi[d] > zone.size[d]) return;
    const int a = fixed == 0 ? 1 : 0, b = fixed == 2 ? 1 : 2;
    auto id = [&zone](cgsize_t ijk[3]) {
        return vtkIdType((ijk[0] - 1) + zone.size[0] * ((ijk[1] - 1) + vtkIdType(zone.size[1]) * (ijk[2] - 1)));
    };
    cgsize_t p[3];
    p[fixed] = lo[fixed];
    for (cgsize_t ib = lo[b]; ib < hi[b]; ++ib)
        for (cgsize_t ia = lo[a]; ia < hi[a]; ++ia) {
            for (auto [da, db] : {std::pair{0, 0}, {1, 0}, {1, 1}, {0, 1}}) {
                p[a] = ia + da, p[b] = ib + db;
                patch.ids.push_back(id(p));
            }
            patch.offsets.push_back(vtkIdType(patch.ids.size()));
        }
}

// --- readCgnsZones -------------------------------------------------------------------------------
std::string trimmed(const char* s) {
    std::string t(s);
    while (!t.empty() && t.back() == ' ') t.pop_back();
    return t;
}

// Family name -> the BC type of its FamilyBC (when it has one).
std::map<std::string, std::string> familyTypes(const CgnsFile& f, int b, const std::string& base) {
    std::map<std::string, std::string> types;
    int n = 0;
    f.check(cg_nfamilies(f.fn(), b, &n), "base " + base);
    for (int i = 1; i <= n; ++i) {
        char name[33] = {}, bcName[33] = {};
        int nboco = 0, ngeo = 0;
        f.check(cg_family_read(f.fn(), b, i, name, &nboco, &ngeo), "base " + base + ", family " + std::to_string(i));
        CGNS_ENUMT(BCType_t) type;
        if (nboco > 0 && cg_fambc_read(f.fn(), b, i, 1, bcName, &type) == CG_OK) types[trimmed(name)] = cg_BCTypeName(type);
    }
    return types;
}

CgnsPatch readPatch(const CgnsFile& f, int b, int z, int bc, const CgnsZone& zone, int indexDim, const Limits& limits,
                    const std::vector<FaceSection>& sections, cgsize_t maxElement,
                    const std::map<std::string, std::string>& families) {
    char name[33] = {};
    CGNS_ENUMT(BCType_t) type;
    CGNS_ENUMT(PointSetType_t) ptset;
    cgsize_t npnts = 0, normalListSize = 0;
    int normalIndex[3] = {0, 0, 0}, ndataset = 0;
    CGNS_ENUMT(DataType_t) normalType;
    const std::string where = "zone " + zone.base + "/" + zone.name + ", BC " + std::to_string(bc);
    f.check(cg_boco_info(f.fn(), b, z, bc, name, &type, &ptset, &npnts, normalIndex, &normalListSize, &normalType, &ndataset),
            where);
    CgnsPatch patch;
    patch.name = trimmed(name);
    patch.type = cg_BCTypeName(type);
    const std::string at = "zone " + zone.base + "/" + zone.name + ", BC " + patch.name;
    if (cg_goto(f.fn(), b, "Zone_t", z, "ZoneBC_t", 1, "BC_t", bc, "end") == CG_OK) {
        char family[33] = {};
        if (cg_famname_read(family) == CG_OK) patch.family = trimmed(family);
    }
    if (type == CGNS_ENUMV(FamilySpecified))
        if (auto it = families.find(patch.family); it != families.end()) patch.type = it->second;
    CGNS_ENUMT(GridLocation_t) location = CGNS_ENUMV(Vertex);
    f.check(cg_boco_gridlocation_read(f.fn(), b, z, bc, &location), at);
    const bool range = ptset == CGNS_ENUMV(PointRange) || ptset == CGNS_ENUMV(ElementRange);
    const bool list = ptset == CGNS_ENUMV(PointList) || ptset == CGNS_ENUMV(ElementList);
    if (!range && !list) f.fail(at, std::string("point set type ") + cg_PointSetTypeName(ptset) + " is not a range or list");
    if (range && npnts != 2) f.fail(at, "a point range of " + std::to_string(npnts) + " points");
    limits.check(f, at, "points", (long long)npnts * indexDim, 4);
    std::vector<cgsize_t> points(size_t(npnts) * size_t(indexDim));
    f.check(cg_boco_read(f.fn(), b, z, bc, points.data(), nullptr), at);
    if (zone.structured) {
        const bool faceCentred = location != CGNS_ENUMV(Vertex);
        if (range && indexDim == 3) structuredFaces(points, faceCentred, zone, patch);
        return patch;
    }
    const bool vertices = location == CGNS_ENUMV(Vertex) && ptset != CGNS_ENUMV(ElementRange) && ptset != CGNS_ENUMV(ElementList);
    const cgsize_t limit = vertices ? zone.vertices : maxElement;
    for (cgsize_t p : points)
        if (p < 1 || p > limit)
            f.fail(at, std::string(vertices ? "vertex " : "element ") + std::to_string(p) + " out of range 1.." +
                           std::to_string(limit));
    if (range && points[1] < points[0]) f.fail(at, "an empty range");
    size_t missing = 0;
    unstructuredFaces(points, range, vertices, sections, patch, missing);
    if (missing > 0)
        warnOnce(f.path() + ": " + at + ": " + std::to_string(missing) +
                 " of its elements are no faces of a section; the rest is read");
    return patch;
}

// ZoneIterativeData's FlowSolutionPointers name each time step's FlowSolution_t; one that
// names no solution of the zone (a damaged or hand-edited file) is said, since VTK's reader
// then shows another solution for that step without a word. "Null" marks a step without one.
void checkSolutionPointers(const CgnsFile& f, int b, int z, const CgnsZone& zone, const Limits& limits) {
    char name[33] = {};
    if (cg_ziter_read(f.fn(), b, z, name) != CG_OK) return;
    const std::string at = "zone " + zone.base + "/" + zone.name;
    std::set<std::string> solutions;
    int nsols = 0;
    f.check(cg_nsols(f.fn(), b, z, &nsols), at);
    for (int s = 1; s <= nsols; ++s) {
        char sol[33] = {};
        CGNS_ENUMT(GridLocation_t) location;
        f.check(cg_sol_info(f.fn(), b, z, s, sol, &location), at);
        solutions.insert(trimmed(sol));
    }
    f.check(cg_goto(f.fn(), b, "Zone_t", z, "ZoneIterativeData_t", 1, "end"), at);
    int narrays = 0;
    f.check(cg_narrays(&narrays), at + ", ZoneIterativeData");
    for (int a = 1; a <= narrays; ++a) {
        char array[33] = {};
        CGNS_ENUMT(DataType_t) type;
        int dims = 0;
        cgsize_t sizes[12] = {};
        f.check(cg_array_info(a, array, &type, &dims, sizes), at + ", ZoneIterativeData");
        if (trimmed(array) != "FlowSolutionPointers") continue;
        if (type != CGNS_ENUMV(Character) || dims != 2 || sizes[0] < 1)
            f.fail(at, "FlowSolutionPointers is not a list of names");
        limits.check(f, at + ", FlowSolutionPointers", "characters", (long long)sizes[0] * sizes[1], 1);
        std::vector<char> text(size_t(sizes[0]) * size_t(sizes[1]));
        f.check(cg_array_read(a, text.data()), at + ", FlowSolutionPointers");
        for (cgsize_t step = 0; step < sizes[1]; ++step) {
            const std::string pointer = trimmed(std::string(text.data() + step * sizes[0], size_t(sizes[0])).c_str());
            if (pointer != "Null" && !pointer.empty() && !solutions.count(pointer))
                warnOnce(f.path() + ": " + at + ": FlowSolutionPointers names '" + pointer + "' for time step " +
                         std::to_string(step + 1) + ", which the zone does not have; VTK's reader shows another "
                         "solution for that step");
        }
    }
}

}  // namespace

bool isCgnsWallType(const std::string& type) { return type.rfind("BCWall", 0) == 0; }

std::vector<CgnsZone> readCgnsZones(const std::string& path) {
    const CgnsFile f(path);
    const Limits limits{bytesAvailable(path)};
    std::vector<CgnsZone> zones;
    int bases = 0;
    f.check(cg_nbases(f.fn(), &bases), "bases");
    for (int b = 1; b <= bases; ++b) {
        char baseName[33] = {};
        int cellDim = 0, physDim = 0;
        f.check(cg_base_read(f.fn(), b, baseName, &cellDim, &physDim), "base " + std::to_string(b));
        const std::string base = trimmed(baseName);
        if (cellDim < 1 || cellDim > 3 || physDim < 1 || physDim > 3)
            f.fail("base " + base, "cell/physical dimension " + std::to_string(cellDim) + "/" + std::to_string(physDim));
        const auto families = familyTypes(f, b, base);
        int nzones = 0;
        f.check(cg_nzones(f.fn(), b, &nzones), "base " + base);
        for (int z = 1; z <= nzones; ++z) {
            CgnsZone zone;
            zone.base = base;
            zone.cellDim = cellDim;
            CGNS_ENUMT(ZoneType_t) type;
            int indexDim = 0;
            const std::string where = "base " + base + ", zone " + std::to_string(z);
            f.check(cg_zone_type(f.fn(), b, z, &type), where);
            f.check(cg_index_dim(f.fn(), b, z, &indexDim), where);
            if (indexDim < 1 || indexDim > 3) f.fail(where, "index dimension " + std::to_string(indexDim));
            cgsize_t size[9] = {};
            char zoneName[33] = {};
            f.check(cg_zone_read(f.fn(), b, z, zoneName, size), where);
            zone.name = trimmed(zoneName);
            const std::string at = "zone " + base + "/" + zone.name;
            zone.structured = type == CGNS_ENUMV(Structured);
            if (zone.structured) {
                zone.vertices = 1;
                zone.cells = 1;
                for (int d = 0; d < 3; ++d) zone.size[d] = 1;
                for (int d = 0; d < indexDim; ++d) {
                    if (size[d] < 1) f.fail(at, "size " + std::to_string(size[d]));
                    zone.size[d] = int(size[d]);
                    zone.vertices *= vtkIdType(size[d]);
                    zone.cells *= vtkIdType(std::max<cgsize_t>(size[d] - 1, 1));
                    limits.check(f, at, "vertices", zone.vertices, 4 * physDim);  // checked as it grows: no overflow
                }
            } else {
                zone.vertices = vtkIdType(size[0]);
                zone.cells = vtkIdType(size[1]);
                limits.check(f, at, "vertices", zone.vertices, 4 * physDim);
                limits.check(f, at, "cells", zone.cells, 4 * (cellDim + 1));
            }
            // The patches of volume zones: a surface zone is shown whole.
            int nbocos = 0;
            if (cellDim == 3) f.check(cg_nbocos(f.fn(), b, z, &nbocos), at);
            cgsize_t maxElement = 0;
            std::vector<FaceSection> sections;
            if (nbocos > 0 && !zone.structured) sections = readFaceSections(f, b, z, zone, limits, maxElement);
            for (int bc = 1; bc <= nbocos; ++bc) {
                CgnsPatch patch = readPatch(f, b, z, bc, zone, indexDim, limits, sections, maxElement, families);
                if (patch.faceCount() > 0) zone.patches.push_back(std::move(patch));
                else
                    warnOnce(path + ": " + at + ", BC " + patch.name + " (" + patch.type + ") has no faces flowsurf can " +
                             "draw (structured: a point range over one face of the block; unstructured: face elements, " +
                             "or vertices that bound faces of a section); left out");
            }
            checkSolutionPointers(f, b, z, zone, limits);
            zones.push_back(std::move(zone));
        }
    }
    if (zones.empty()) throw FormatError(path + ": the CGNS file holds no zone");
    return zones;
}

}  // namespace flowsurf::io::detail
