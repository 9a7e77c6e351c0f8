// CGNS files (HDF5 or ADF) through VTK's vtkCGNSReader: every base and zone, structured
// and unstructured, the solutions at vertices and at cell centres (all arrays enabled: VTK
// loads none unless asked), the times of BaseIterativeData. The surface shown of a volume
// is its wall patches by default (BC type BCWall*, directly or through the BC's family),
// the patches whose BC or family name --patches matches when given, and the volume's
// boundary surface when it has no wall BC; the patches come from cgns_boundaries.h, their
// surfaces with the solution from cgns_walls.h. Surface zones are shown whole. With
// --field skin-friction the wall BCs get the derived stress (skin_friction.h) from the cell
// behind each face that cgns_walls.h finds, the boundary surface of a volume without walls too.
// Sections: the file's kind · the selection · the source · openCgns.
#include "io/reader/vtk_sources.h"

#include "core/errors.h"
#include "io/reader/cgns_boundaries.h"
#include "io/reader/cgns_walls.h"
#include "io/reader/skin_friction.h"
#include "io/reader/vtk_messages.h"

#include <vtkCGNSReader.h>
#include <vtkCellData.h>
#include <vtkCompositeDataSet.h>
#include <vtkDataSet.h>
#include <vtkInformation.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkPolyData.h>

#include <algorithm>
#include <fstream>
#include <map>
#include <optional>
#include <regex>
#include <sstream>

namespace flowsurf::io::detail {

namespace {

// --- the file's kind ----------------------------------------------------------------------
// CGNS lives in an HDF5 file (signature at offset 0, or 512, 1024... after a user block) or
// an ADF one ("ADF Database Version" after a 4-byte tag); neither is no CGNS file, said before libcgns or
// VTK try to parse it.
std::string backendOf(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::string head(4096, '\0');
    head.resize(size_t(in.read(head.data(), std::streamsize(head.size())).gcount()));
    static const std::string hdf5("\x89HDF\r\n\x1a\n", 8);
    for (size_t at = 0; at + hdf5.size() <= head.size(); at = at ? at * 2 : 512)
        if (head.compare(at, hdf5.size(), hdf5) == 0) return "HDF5";
    if (head.size() >= 24 && head.compare(4, 20, "ADF Database Version") == 0) return "ADF";
    throw FormatError(path + ": not a CGNS file (neither an HDF5 nor an ADF file)");
}

// --- the selection ------------------------------------------------------------------------
std::string patchList(const std::vector<CgnsZone>& zones) {
    std::string all;
    for (const auto& z : zones)
        for (const auto& p : z.patches)
            all += (all.empty() ? "" : ", ") + p.name + " (" + p.type + (p.family.empty() ? "" : ", family " + p.family) + ")";
    return all.empty() ? "none" : all;
}

// The patches read of each zone (indices into its patches): --patches' matches on the BC's
// name or its family's, else the walls. Empty everywhere: the volume's boundary is shown.
std::vector<std::vector<size_t>> selectPatches(const std::vector<CgnsZone>& zones, const std::string& path,
                                               const std::string& patches) {
    std::regex select;
    try {
        select = std::regex(patches.empty() ? ".*" : patches);
    } catch (const std::regex_error& e) {
        throw ConfigError("--patches: '" + patches + "' is not a regular expression (" + e.what() + ")");
    }
    std::vector<std::vector<size_t>> kept(zones.size());
    size_t count = 0;
    for (size_t z = 0; z < zones.size(); ++z)
        for (size_t i = 0; i < zones[z].patches.size(); ++i) {
            const CgnsPatch& p = zones[z].patches[i];
            const bool keep = patches.empty() ? isCgnsWallType(p.type)
                                              : std::regex_match(p.name, select) ||
                                                    (!p.family.empty() && std::regex_match(p.family, select));
            if (keep) kept[z].push_back(i), ++count;
        }
    if (count == 0 && !patches.empty())
        throw ConfigError(path + ": --patches '" + patches + "' matches no boundary condition's name or family (BCs: " +
                          patchList(zones) + ")");
    return kept;
}

// The data set of `zone` in vtkCGNSReader's output: base block > zone block (> "Internal").
vtkDataSet* zoneData(vtkMultiBlockDataSet* root, const CgnsZone& zone) {
    auto child = [](vtkMultiBlockDataSet* mb, const std::string& name) -> vtkDataObject* {
        for (unsigned i = 0; mb && i < mb->GetNumberOfBlocks(); ++i)
            if (mb->HasMetaData(i) && mb->GetMetaData(i)->Has(vtkCompositeDataSet::NAME()) &&
                name == mb->GetMetaData(i)->Get(vtkCompositeDataSet::NAME()))
                return mb->GetBlock(i);
        return nullptr;
    };
    vtkDataObject* z = child(vtkMultiBlockDataSet::SafeDownCast(child(root, zone.base)), zone.name);
    if (auto* mb = vtkMultiBlockDataSet::SafeDownCast(z)) z = child(mb, "Internal");
    return vtkDataSet::SafeDownCast(z);
}

// --- the source ------------------------------------------------------------------------------
// Each step: the reader's zones, replaced by the selected patches' surfaces (one block per
// patch, "ZONE/BC" where the file has several zones) and the surface zones.
class CgnsSource final : public AlgorithmSource {
public:
    CgnsSource(vtkAlgorithm* reader, const std::string& path, const std::string& format, VtkMessageTrap& trap,
               std::vector<CgnsZone> zones, std::vector<std::vector<size_t>> selected,
               std::optional<SkinFrictionOptions> skinFriction)
        : AlgorithmSource(reader, path, format, trap), zones_(std::move(zones)), selected_(std::move(selected)),
          skinFriction_(std::move(skinFriction)) {
        for (const auto& s : selected_) patchesShown_ = patchesShown_ || !s.empty();
    }

    std::vector<PatchInfo> patches() const override {
        std::vector<PatchInfo> all;
        for (size_t z = 0; z < zones_.size(); ++z)
            for (size_t i = 0; i < zones_[z].patches.size(); ++i) {
                const CgnsPatch& p = zones_[z].patches[i];
                const bool read = std::find(selected_[z].begin(), selected_[z].end(), i) != selected_[z].end();
                all.push_back({(zones_.size() > 1 ? zones_[z].name + "/" : "") + p.name, p.type, p.family, p.faceCount(), read});
            }
        return all;
    }

protected:
    void adapt(vtkDataObject& step) override {
        auto* root = vtkMultiBlockDataSet::SafeDownCast(&step);
        if (!root) throw FormatError(path() + ": cannot read " + format() + ": the reader gave no zones");
        auto out = vtkSmartPointer<vtkMultiBlockDataSet>::New();
        auto add = [&out](vtkDataObject* block, const std::string& name) {
            const unsigned i = out->GetNumberOfBlocks();
            out->SetBlock(i, block);
            out->GetMetaData(i)->Set(vtkCompositeDataSet::NAME(), name.c_str());
        };
        for (size_t z = 0; z < zones_.size(); ++z) {
            const CgnsZone& zone = zones_[z];
            vtkDataSet* volume = zoneData(root, zone);
            if (!volume) {
                warnOnce(path() + ": zone " + zone.base + "/" + zone.name + ": VTK's CGNS reader gave no data for it; left out");
                continue;
            }
            const std::string prefix = zones_.size() > 1 ? zone.name + "/" : "";
            const std::string where = path() + " (zone " + zone.base + "/" + zone.name + ")";
            if (zone.cellDim < 3 || !patchesShown_) {
                add(wholeZone(volume, zone, where), zones_.size() > 1 ? zone.name : "zone " + zone.name);
                continue;
            }
            if (volume->GetNumberOfPoints() != zone.vertices)
                throw FormatError(where + ": VTK's reader gave " + std::to_string(volume->GetNumberOfPoints()) +
                                  " points, the zone has " + std::to_string(zone.vertices));
            const bool cellArrays = volume->GetCellData()->GetNumberOfArrays() > 0;
            for (size_t i : selected_[z]) {
                const CgnsPatch& patch = zone.patches[i];
                // The cell behind each wall face brings the cell-centred solution to the wall and
                // is where the wall's shear stress is taken; found once, as CGNS moves
                // coordinates over time but keeps the connectivity.
                std::vector<vtkIdType>& cells = wallCells_[{z, i}];
                if ((cellArrays || skinFriction_) && cells.empty()) cells = wallCells(volume, patch);
                static const std::vector<vtkIdType> kNoCells;
                vtkSmartPointer<vtkPolyData> surface = patchSurface(volume, patch, cellArrays ? cells : kNoCells, where);
                if (skinFriction_ && isCgnsWallType(patch.type))
                    addSkinFrictionOnCells(volume, surface, cells, patch.offsets, patch.ids, "BC '" + patch.name + "'",
                                           *skinFriction_, where);
                else if (skinFriction_)
                    addZeroSkinFriction(surface, skinFriction_->viscosity);
                add(surface, prefix + patch.name);
            }
        }
        step.ShallowCopy(out);
    }

private:
    // A zone shown whole: a surface zone as it is (with a zero skin-friction beside walls),
    // a volume without wall BCs as its boundary surface when skin-friction is asked for.
    vtkSmartPointer<vtkDataObject> wholeZone(vtkDataSet* data, const CgnsZone& zone, const std::string& where) const {
        if (!skinFriction_) return data;
        if (zone.cellDim >= 3) return newBoundaryWithSkinFriction(data, *skinFriction_, where);
        vtkSmartPointer<vtkDataSet> copy = vtkSmartPointer<vtkDataSet>::Take(data->NewInstance());
        copy->ShallowCopy(data);
        addZeroSkinFriction(copy, skinFriction_->viscosity);
        return copy;
    }

    std::vector<CgnsZone> zones_;
    std::vector<std::vector<size_t>> selected_;
    bool patchesShown_ = false;
    std::optional<SkinFrictionOptions> skinFriction_;  // set: --field skin-friction
    std::map<std::pair<size_t, size_t>, std::vector<vtkIdType>> wallCells_;  // (zone, patch) -> wallCells()
};

// --field skin-friction's options for this file: the velocity found by name in each zone
// (vtkCGNSReader's combined Velocity), the viscosity only from --viscosity (CGNS states a
// dynamic viscosity and density in ReferenceState only in nondimensional forms that differ from
// solver to solver). Throws FormatError when there is no volume or none of the BCs read is a wall.
SkinFrictionOptions skinFrictionOfCgns(const std::string& path, const std::vector<CgnsZone>& zones,
                                       const std::vector<std::vector<size_t>>& selected, const SourceOptions& options) {
    bool volume = false, wall = false, shown = false;
    for (size_t z = 0; z < zones.size(); ++z) {
        volume = volume || zones[z].cellDim == 3;
        for (size_t i : selected[z]) shown = true, wall = wall || isCgnsWallType(zones[z].patches[i].type);
    }
    if (!volume)
        throw FormatError(path + ": --field skin-friction needs a volume zone with its velocity; this CGNS file holds "
                                 "surface zones only");
    if (shown && !wall)
        throw FormatError(path + ": --field skin-friction: none of the BCs read is a wall (BC type BCWall*; BCs: " +
                          patchList(zones) + "); --patches selects which are read");
    SkinFrictionOptions sf;
    sf.viscosity = options.viscosity;
    sf.warn = warnOnce;
    return sf;
}

}  // namespace

// --- openCgns ----------------------------------------------------------------------------------
std::unique_ptr<StepSource> openCgns(const std::string& path, const std::string& cgnsFormat, VtkMessageTrap& trap,
                                     const SourceOptions& options) {
    const std::string backend = backendOf(path);
    std::vector<CgnsZone> zones = readCgnsZones(path);
    std::vector<std::vector<size_t>> selected = selectPatches(zones, path, options.patches);
    size_t volumes = 0, shown = 0;
    for (size_t z = 0; z < zones.size(); ++z) volumes += zones[z].cellDim == 3, shown += selected[z].size();
    std::string format = cgnsFormat + " (" + backend + ", " + std::to_string(zones.size()) +
                         (zones.size() == 1 ? " zone" : " zones");
    if (volumes > 0)
        format += shown > 0 ? options.patches.empty() ? "; wall patches" : "; patches matching --patches"
                            : "; no wall BC: the volume's boundary surface";
    std::optional<SkinFrictionOptions> skinFriction;
    if (options.skinFriction) {
        skinFriction = skinFrictionOfCgns(path, zones, selected, options);
        std::ostringstream nu;
        nu << options.viscosity;
        format += options.viscosity > 0 ? "; skin-friction: nu = " + nu.str() + " m^2/s from --viscosity"
                                         : "; skin-friction: no viscosity given, relative magnitude";
    }
    format += ")";
    auto r = vtkSmartPointer<vtkCGNSReader>::New();
    r->SetFileName(path.c_str());
    trap.watch(r);
    readInformation(r, path, format, trap);
    // Every base and every solution, at vertices and at cell centres alike (VTK's reader
    // loads one base and no array unless told); the patches are ours (cgns_boundaries.h).
    r->EnableAllBases();
    r->EnableAllFamilies();
    r->EnableAllPointArrays();
    r->EnableAllCellArrays();
    r->LoadBndPatchOff();
    r->LoadMeshOn();
    readInformation(r, path, format, trap);
    return std::make_unique<CgnsSource>(r, path, format, trap, std::move(zones), std::move(selected),
                                        std::move(skinFriction));
}

}  // namespace flowsurf::io::detail
