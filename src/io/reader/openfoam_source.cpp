// OpenFOAM cases through VTK's reader: the boundary patches (the wall-type ones by default, a
// 2-D case's empty ones, all when none is a wall; --patches picks by name) of a reconstructed
// case or of a decomposed one (processor* directories, --foam-case), every time directory a
// step except the initial conditions in 0/ when solved times exist (--foam-zero-time reads
// them too, as ParaView's Skip Zero Time off), a time directory VTK cannot parse left out
// with a warning naming it, points re-read for time directories that have polyMesh/points
// (moving meshes), and each field's units from its `dimensions` (VTK's "m/s" notation, kept
// on the arrays as UNITS_LABEL). With --field skin-friction the internal mesh is read too,
// the wall patches get the derived stress from it (openfoam_walls.h), and it is dropped.
// Sections: case layout · directories VTK may not parse · units and VTK's warnings ·
// the source · openOpenFoam.
#include "io/reader/vtk_sources.h"

#include "core/errors.h"
#include "io/reader/openfoam_walls.h"

#include <vtkCellData.h>
#include <vtkCompositeDataIterator.h>
#include <vtkCompositeDataSet.h>
#include <vtkDataArray.h>
#include <vtkDataSet.h>
#include <vtkDummyController.h>
#include <vtkInformation.h>
#include <vtkInformationStringKey.h>
#include <vtkOpenFOAMReader.h>
#include <vtkPOpenFOAMReader.h>
#include <vtkPointData.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <regex>
#include <sstream>

namespace flowsurf::io::detail {

namespace {

namespace fs = std::filesystem;

// --- case layout ----------------------------------------------------------------------
// A time directory is named by a number ("0", "0.0005", "1e-05"), as VTK's reader lists them.
bool isTimeName(const std::string& name) {
    if (name.empty()) return false;
    char* end = nullptr;
    std::strtod(name.c_str(), &end);
    return end != name.c_str() && *end == '\0';
}

bool isZeroTime(const std::string& name) { return isTimeName(name) && std::strtod(name.c_str(), nullptr) == 0.0; }

size_t countTimeDirs(const fs::path& dir) {
    std::error_code ec;
    size_t n = 0;
    for (const auto& e : fs::directory_iterator(dir, ec))
        if (e.is_directory(ec) && isTimeName(e.path().filename().string())) ++n;
    return n;
}

// Whether `dir` holds a time directory that is (`zero`) or is not the initial conditions.
bool hasTime(const fs::path& dir, bool zero) {
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(dir, ec)) {
        const std::string name = e.path().filename().string();
        if (e.is_directory(ec) && isTimeName(name) && isZeroTime(name) == zero) return true;
    }
    return false;
}

bool hasMesh(const fs::path& dir) {
    std::error_code ec;
    const fs::path mesh = dir / "constant" / "polyMesh";
    return fs::exists(mesh / "faces", ec) || fs::exists(mesh / "faces.gz", ec);
}

// processor0, processor1, ... (decomposePar's layout) or processorsN (the collated
// format), sorted by number: the first is the one VTK takes the times from.
std::vector<fs::path> processorDirs(const fs::path& dir) {
    static const std::regex name("processors?([0-9]+)(_[0-9]+-[0-9]+)?");
    std::vector<std::pair<long, fs::path>> found;
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(dir, ec)) {
        std::smatch m;
        const std::string n = e.path().filename().string();
        if (e.is_directory(ec) && std::regex_match(n, m, name)) found.emplace_back(std::atol(m[1].str().c_str()), e.path());
    }
    std::sort(found.begin(), found.end());
    std::vector<fs::path> dirs;
    for (auto& f : found) dirs.push_back(f.second);
    return dirs;
}

fs::path caseDir(const std::string& casePath) {
    fs::path dir = fs::path(casePath).parent_path();
    return dir.empty() ? fs::path(".") : dir;
}

// Which layout `--foam-case auto` reads: the decomposed one when processor* directories
// exist and the case folder has no mesh or fewer time directories than processor0 (a
// case run in parallel and not, or only partly, reconstructed); else the reconstructed.
bool readsDecomposed(const std::string& casePath, const std::string& choice) {
    if (choice != "auto" && choice != "reconstructed" && choice != "decomposed")
        throw ConfigError("--foam-case: '" + choice + "' is not one of auto, reconstructed, decomposed");
    if (choice == "reconstructed") return false;
    const fs::path dir = caseDir(casePath);
    const std::vector<fs::path> procs = processorDirs(dir);
    if (choice == "decomposed") {
        if (procs.empty())
            throw ConfigError(casePath + ": --foam-case decomposed: no processor* directories in " + dir.string());
        return true;
    }
    if (procs.empty()) return false;
    return !hasMesh(dir) || countTimeDirs(procs.front()) > countTimeDirs(dir);
}

// --- directories VTK may not parse ---------------------------------------------------
// VTK 9.1's dictionary parser knows few of OpenFOAM's `#` directives: a field with
// `#includeEtc "caseDicts/setConstraintTypes"` (in the 0/ of most tutorials since v3) fails
// the whole step with "Unsupported directive includeEtc". A solver writes its time
// directories plain, with uniform/time; only the others, when a field file holds a
// directive (or is compressed, so it cannot be looked into here), are read once at opening
// to learn whether VTK parses them.

// `#` followed by a letter, not inside a word, as a directive is written (`{#include`
// too); a binary field's bytes may look so, and then cost a read at opening.
bool holdsDirective(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::vector<char> buf(1 << 16);
    char before = '\n';
    bool hash = false;  // the last character was a '#' starting a word
    while (in) {
        in.read(buf.data(), std::streamsize(buf.size()));
        for (std::streamsize i = 0; i < in.gcount(); ++i) {
            const char c = buf[size_t(i)];
            if (hash && std::isalpha(static_cast<unsigned char>(c))) return true;
            hash = c == '#' && !std::isalnum(static_cast<unsigned char>(before)) && before != '_';
            before = c;
        }
    }
    return false;
}

// The time directory of each of `times` (as VTK lists them, by the value of the name; empty
// where none matches).
std::vector<std::string> timeDirNames(const fs::path& dir, const std::vector<double>& times) {
    std::vector<std::string> names(times.size());
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(dir, ec)) {
        const std::string name = e.path().filename().string();
        if (!e.is_directory(ec) || !isTimeName(name)) continue;
        const double value = std::strtod(name.c_str(), nullptr);
        for (size_t i = 0; i < times.size(); ++i)
            if (std::abs(times[i] - value) <= 1e-12 * std::max(1.0, std::abs(value))) names[i] = name;
    }
    return names;
}

bool mayNotParse(const fs::path& timeDir) {
    std::error_code ec;
    if (fs::exists(timeDir / "uniform" / "time", ec)) return false;
    for (const auto& e : fs::directory_iterator(timeDir, ec)) {
        if (!e.is_regular_file(ec)) continue;
        if (e.path().extension() == ".gz" || holdsDirective(e.path())) return true;
    }
    return false;
}

// --- units and VTK's warnings -----------------------------------------------------------

// "U [m/s]" -> "U" with units "m/s" (AddDimensionsToArrayNames' suffix); false when the
// name carries no such suffix.
bool splitUnitsSuffix(const std::string& name, std::string& bare, std::string& units) {
    const size_t open = name.rfind(" [");
    if (open == std::string::npos || open == 0 || name.back() != ']') return false;
    bare = name.substr(0, open);
    units = name.substr(open + 2, name.size() - open - 3);
    return true;
}

// Moves AddDimensionsToArrayNames' " [m/s]" suffix of every array into the array's
// UNITS_LABEL. The arrays are replaced by renamed shallow copies in a copied tree: the
// reader's own output (and its mesh cache) is left as it was. `units` remembers what was
// seen, for steps the reader hands out again without re-reading.
void moveUnitsToLabels(vtkDataObject* data, std::map<std::string, std::string>& units) {
    auto relabel = [&units](vtkFieldData* fd) {
        for (int i = fd->GetNumberOfArrays() - 1; i >= 0; --i) {
            vtkDataArray* a = fd->GetArray(i);
            if (!a || !a->GetName()) continue;
            std::string bare, unit;
            if (splitUnitsSuffix(a->GetName(), bare, unit)) units[bare] = unit;
            else if (auto it = units.find(a->GetName()); it != units.end()) bare = it->first, unit = it->second;
            else continue;
            auto renamed = vtkSmartPointer<vtkDataArray>::Take(a->NewInstance());
            renamed->ShallowCopy(a);
            renamed->SetName(bare.c_str());
            renamed->GetInformation()->Set(vtkDataArray::UNITS_LABEL(), unit.c_str());
            fd->RemoveArray(i);
            fd->AddArray(renamed);
        }
    };
    auto* composite = vtkCompositeDataSet::SafeDownCast(data);
    if (!composite) return;
    auto it = vtkSmartPointer<vtkCompositeDataIterator>::Take(composite->NewIterator());
    it->SkipEmptyNodesOn();
    for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem()) {
        auto* leaf = vtkDataSet::SafeDownCast(it->GetCurrentDataObject());
        if (!leaf) continue;
        auto own = vtkSmartPointer<vtkDataSet>::Take(leaf->NewInstance());
        own->ShallowCopy(leaf);  // own point/cell data objects; the arrays still shared
        relabel(own->GetPointData());
        relabel(own->GetCellData());
        composite->SetDataSet(it, own);
    }
}

// VTK 9.1 reads a field's patches in the order of constant/polyMesh/boundary and stops at
// the first one its file has no entry for (OpenFOAM lets a 0/ file omit constraint patches
// such as `empty`): the field is then missing on that patch and every later one. Said
// once per field and patch, with what the user sees.
void warnMissingPatchEntries(const std::vector<std::string>& warnings, const std::string& path) {
    static const std::regex missing("boundaryField (\\S+) (not found|not a subdictionary) in object (\\S+) at time = (\\S+)");
    std::map<std::pair<std::string, std::string>, std::string> fields;  // (time, patch) -> "U, p"
    for (const auto& w : warnings) {
        std::smatch m;
        if (!std::regex_search(w, m, missing)) continue;
        std::string& list = fields[{m[4].str(), m[1].str()}];
        list += (list.empty() ? "" : ", ") + m[3].str();
    }
    for (const auto& [where, list] : fields)
        warnOnce(path + ": the fields " + list + " of time " + where.first + " have no entry for boundary patch '" +
                 where.second + "' (OpenFOAM allows that for constraint patches such as empty); VTK's reader then "
                 "leaves them out on that patch and on the patches after it in constant/polyMesh/boundary");
}

// --- the source ---------------------------------------------------------------------------

// The reader's steps, with its warnings about patches missing from field files passed on
// and the units moved from the array names to the labels.
class OpenFoamSource final : public AlgorithmSource {
public:
    OpenFoamSource(vtkAlgorithm* reader, const std::string& path, const std::string& format, VtkMessageTrap& trap,
                   std::vector<PatchInfo> patches)
        : AlgorithmSource(reader, path, format, trap), patches_(std::move(patches)) {}

    std::vector<PatchInfo> patches() const override { return patches_; }

    // Reads once each time directory below `timeRoot` (the case folder or processor0)
    // that VTK may not parse, and leaves out those it does not, each named in a warning
    // with VTK's reason; throws FormatError with the reasons when none is left.
    void dropUnparsedTimes(const fs::path& timeRoot) {
        if (times_.empty()) return;
        const std::vector<std::string> names = timeDirNames(timeRoot, times_);
        const std::string prefix = path() + ": cannot read " + format() + ": ";
        std::vector<double> kept;
        std::vector<std::string> failures;
        for (size_t i = 0; i < times_.size(); ++i) {
            if (!names[i].empty() && mayNotParse(timeRoot / names[i])) {
                try {
                    readStep(i);
                } catch (const FormatError& e) {
                    std::string why = e.what();
                    if (why.rfind(prefix, 0) == 0) why = why.substr(prefix.size());
                    failures.push_back("time directory " + names[i] + ": " + why);
                    continue;
                }
            }
            kept.push_back(times_[i]);
        }
        if (kept.empty()) {
            std::string all;
            for (const auto& f : failures) all += (all.empty() ? "" : "; ") + f;
            throw FormatError(path() + ": VTK's OpenFOAM reader cannot parse any time directory (" + all + ")");
        }
        for (const auto& f : failures)
            warnOnce(path() + ": left out " + f + " (VTK 9.1's OpenFOAM reader cannot parse it; the other times are read)");
        times_ = std::move(kept);
    }

    // Derive skin-friction on the wall patches of every step (the internal mesh is read).
    void deriveSkinFriction(FoamWalls walls) { walls_ = std::move(walls); }

protected:
    void afterUpdate(VtkMessageTrap& trap) override { warnMissingPatchEntries(trap.warnings(), path()); }
    void adapt(vtkDataObject& step) override {
        moveUnitsToLabels(&step, units_);
        if (walls_) addFoamSkinFriction(step, *walls_, path());
    }

private:
    std::vector<PatchInfo> patches_;  // every boundary patch, with its type and whether it is read
    std::map<std::string, std::string> units_;
    std::optional<FoamWalls> walls_;
};

// Which patches a case shows without --patches: a 2-D case (one cell deep, its front and back
// of type `empty`) its empty patches, the plane of the flow (its walls are strips one cell
// deep) unless the wall stress is asked for; else its wall-type patches; all when it has
// neither.
enum class DefaultPatches { Plane, Walls, All };

DefaultPatches defaultPatches(const std::vector<PatchInfo>& all, bool wallStress) {
    auto any = [&](auto pred) { return std::any_of(all.begin(), all.end(), [&](const PatchInfo& p) { return pred(p.type); }); };
    if (!wallStress && any([](const std::string& t) { return t == "empty"; })) return DefaultPatches::Plane;
    if (any([](const std::string& t) { return isFoamWallType(t); })) return DefaultPatches::Walls;
    return DefaultPatches::All;
}

bool readByDefault(DefaultPatches rule, const std::string& type) {
    return rule == DefaultPatches::Plane ? type == "empty" : rule == DefaultPatches::Walls ? isFoamWallType(type) : true;
}

// Boundary patches only: the surface to show is the walls, not the volume. --patches
// matches the patch's own name (VTK lists boundary patches as "patch/NAME"); without it the
// wall-type patches are read, as a CGNS file's wall BCs, and all patches when none is a wall
// (or the boundary file gives no types). `volume`: the internal mesh too (for skin-friction,
// dropped after). `meshDirs`: the constant/polyMesh folders read (the case's, or each
// processor's), for the types and face counts. Returns every patch, marked read or not.
std::vector<PatchInfo> selectPatches(vtkOpenFOAMReader* r, const std::string& path, const std::string& patches, bool volume,
                                     const std::vector<fs::path>& meshDirs) {
    std::regex select;
    try {
        select = std::regex(patches.empty() ? ".*" : patches);
    } catch (const std::regex_error& e) {
        throw ConfigError("--patches: '" + patches + "' is not a regular expression (" + e.what() + ")");
    }
    const std::map<std::string, std::string> types = meshDirs.empty() ? std::map<std::string, std::string>{}
                                                                      : readPatchTypes(meshDirs.front());
    std::map<std::string, size_t> faces;
    for (const fs::path& dir : meshDirs)
        for (const auto& [name, n] : readPatchFaceCounts(dir)) faces[name] += n;
    std::vector<PatchInfo> all;
    std::vector<std::string> arrays;  // VTK's names, in `all`'s order
    for (int i = 0; i < r->GetNumberOfPatchArrays(); ++i) {
        const std::string name = r->GetPatchArrayName(i);
        r->SetPatchArrayStatus(name.c_str(), volume && name == "internalMesh" ? 1 : 0);
        // Patch groups ("group/wall", from inGroups) name patches listed on their own too.
        if (name == "internalMesh" || name.rfind("lagrangian", 0) == 0 || name.rfind("group/", 0) == 0) continue;
        const std::string bare = name.rfind("patch/", 0) == 0 ? name.substr(6) : name;
        const auto type = types.find(bare);
        const auto count = faces.find(bare);
        all.push_back({bare, type == types.end() ? "?" : type->second, "", count == faces.end() ? 0 : count->second, false});
        arrays.push_back(name);
    }
    const DefaultPatches rule = defaultPatches(all, volume);
    std::string list;
    int kept = 0;
    for (size_t i = 0; i < all.size(); ++i) {
        list += (list.empty() ? "" : ", ") + all[i].name;
        all[i].read = patches.empty() && rule != DefaultPatches::All ? readByDefault(rule, all[i].type)
                                                                    : std::regex_match(all[i].name, select);
        kept += all[i].read;
        if (all[i].read) r->SetPatchArrayStatus(arrays[i].c_str(), 1);
    }
    if (kept == 0)
        throw ConfigError(path + ": --patches '" + patches + "' matches no boundary patch (patches: " + list + ")");
    return all;
}

// How skin-friction is derived on this case: the wall patches from the boundary file of
// the mesh read (`meshRoot`: the case or processor0), the viscosity given or the case's.
FoamWalls foamWalls(vtkOpenFOAMReader* r, const std::string& path, const fs::path& meshRoot, const SourceOptions& options,
                    bool warn = true) {
    bool velocity = false, volume = false;
    for (int i = 0; i < r->GetNumberOfCellArrays(); ++i) velocity = velocity || std::string(r->GetCellArrayName(i)) == "U";
    for (int i = 0; i < r->GetNumberOfPatchArrays(); ++i) volume = volume || std::string(r->GetPatchArrayName(i)) == "internalMesh";
    if (!volume) throw FormatError(path + ": --field skin-friction: the case has no internal mesh");
    if (!velocity)
        throw FieldError(path + ": --field skin-friction needs the velocity field U in the time directories; the case has none");
    FoamWalls walls;
    walls.types = readPatchTypes(meshRoot / "constant" / "polyMesh");
    walls.options.velocity = "U";
    walls.options.wallVelocity = "U";          // the patch's own value: a moving wall's velocity, zero at rest
    walls.options.turbulentViscosity = "nut";  // wall functions' ν_t on the wall face
    walls.options.warn = warnOnce;
    std::string from = "--viscosity";
    walls.options.viscosity = options.viscosity > 0 ? options.viscosity : readCaseViscosity(caseDir(path), from);
    std::ostringstream nu;
    nu << walls.options.viscosity;
    walls.described = walls.options.viscosity > 0 ? "nu = " + nu.str() + " m^2/s from " + from
                                                  : "no viscosity known, relative magnitude";
    if (warn && walls.options.viscosity <= 0)
        warnOnce(path + ": --field skin-friction: no viscosity (--viscosity, or nu in constant/transportProperties or "
                 "physicalProperties): the direction and a relative magnitude (the wall velocity gradient, 1/s)");
    return walls;
}

}  // namespace

// --- openOpenFoam -------------------------------------------------------------------------
namespace {

vtkSmartPointer<vtkOpenFOAMReader> newReader(bool decomposed) {
    if (!decomposed) return vtkSmartPointer<vtkOpenFOAMReader>::New();
    // One reader per processor directory, appended patch by patch; VTK's parallel
    // reader wants a controller even in one process.
    auto p = vtkSmartPointer<vtkPOpenFOAMReader>::New();
    p->SetController(vtkSmartPointer<vtkDummyController>::New());
    p->SetCaseType(vtkPOpenFOAMReader::DECOMPOSED_CASE);
    return p;
}

}  // namespace

std::string foamSkinFrictionNote(const std::string& path, const SourceOptions& options) {
    VtkMessageTrap trap;
    SourceOptions with = options;
    with.skinFriction = true;
    try {
        const bool decomposed = readsDecomposed(path, options.foamCase);
        vtkSmartPointer<vtkOpenFOAMReader> r = newReader(decomposed);
        r->SetFileName(path.c_str());
        trap.watch(r);
        readInformation(r, path, "OpenFOAM case", trap);
        const FoamWalls walls = foamWalls(r, path, decomposed ? processorDirs(caseDir(path)).front() : caseDir(path), with, false);
        std::string names;
        for (const auto& [name, type] : walls.types)
            if (isFoamWallType(type)) names += (names.empty() ? "" : ", ") + name;
        return "from U in the cells next to the wall patches" + (names.empty() ? std::string() : " (" + names + ")") +
               "; " + walls.described;
    } catch (const Error& e) {
        return std::string("not available: ") + e.what();
    }
}

std::unique_ptr<StepSource> openOpenFoam(const std::string& path, const std::string& caseFormat, VtkMessageTrap& trap,
                                         const SourceOptions& options) {
    std::string format = caseFormat;
    const bool readsDecomposedLayout = readsDecomposed(path, options.foamCase);
    vtkSmartPointer<vtkOpenFOAMReader> r = newReader(readsDecomposedLayout);
    if (readsDecomposedLayout)
        format += " (decomposed, " + std::to_string(processorDirs(caseDir(path)).size()) + " processor directories)";
    r->SetFileName(path.c_str());
    // The initial conditions in 0/ are no result: skipped, as ParaView does, when a solver
    // wrote later times; a case with only 0/ (a mesh, a moving-mesh set-up) is that step.
    const fs::path timeRoot = readsDecomposedLayout ? processorDirs(caseDir(path)).front() : caseDir(path);
    const bool skipZero = !options.zeroTime && hasTime(timeRoot, false);
    r->SetSkipZeroTime(skipZero);
    if (skipZero && hasTime(timeRoot, true)) format += " (initial conditions 0/ skipped)";
    r->ListTimeStepsByControlDictOff();
    // Units travel as " [m/s]" name suffixes; the source moves them to UNITS_LABEL.
    r->AddDimensionsToArrayNamesOn();
    // Moving meshes: the mesh stays cached and only the points of a time directory with
    // polyMesh/points are re-read (VTK compares the points' time instance per step).
    r->CacheMeshOn();
    trap.watch(r);
    readInformation(r, path, format, trap);
    std::vector<fs::path> meshDirs;
    for (const fs::path& root : readsDecomposedLayout ? processorDirs(caseDir(path)) : std::vector<fs::path>{caseDir(path)})
        meshDirs.push_back(root / "constant" / "polyMesh");
    std::vector<PatchInfo> patches = selectPatches(r, path, options.patches, options.skinFriction, meshDirs);
    if (options.patches.empty()) {
        const DefaultPatches rule = defaultPatches(patches, options.skinFriction);
        format += rule == DefaultPatches::Plane ? " (2-D: the empty patches, the plane of the flow)"
                  : rule == DefaultPatches::Walls ? " (wall patches)"
                                                  : " (no wall patch: all patches)";
    }
    // Polyhedra kept whole: a wall face then has one owner cell, whose centre is the mean of its points.
    if (options.skinFriction) r->DecomposePolyhedraOff();
    r->EnableAllCellArrays();
    r->EnableAllPointArrays();
    r->DisableAllLagrangianArrays();
    readInformation(r, path, format, trap);
    std::optional<FoamWalls> walls;
    if (options.skinFriction) {
        walls = foamWalls(r, path, readsDecomposedLayout ? timeRoot : caseDir(path), options);
        format += " (skin-friction: " + walls->described + ")";
    }
    auto source = std::make_unique<OpenFoamSource>(r, path, format, trap, std::move(patches));
    if (walls) source->deriveSkinFriction(*walls);
    source->dropUnparsedTimes(timeRoot);
    return source;
}

}  // namespace flowsurf::io::detail
