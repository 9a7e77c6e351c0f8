// Sections: case dictionaries · addFoamSkinFriction.
#include "io/reader/openfoam_walls.h"

#include "core/errors.h"

#include <vtkCompositeDataIterator.h>
#include <vtkCompositeDataSet.h>
#include <vtkDataSet.h>
#include <vtkInformation.h>
#include <vtkPolyData.h>

#include <fstream>
#include <regex>

namespace flowsurf::io::detail {

namespace fs = std::filesystem;

namespace {

// A dictionary's text without // and /* */ comments (enough for the few plain entries read
// here; a file over 4 MiB, a binary mesh file's data, is cut there: the entries read come first).
std::string dictionaryText(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) return {};
    std::string text(size_t(4) << 20, '\0');
    text.resize(size_t(in.read(text.data(), std::streamsize(text.size())).gcount()));
    static const std::regex comments(R"(//[^\n]*|/\*[\s\S]*?\*/)");
    return std::regex_replace(text, comments, " ");
}

}  // namespace

// --- case dictionaries -------------------------------------------------------------------
namespace {

// The word after `key` in each patch entry of `meshDir`/boundary, by patch name.
std::map<std::string, std::string> readPatchEntries(const fs::path& meshDir, const std::string& key) {
    std::map<std::string, std::string> values;
    const std::string text = dictionaryText(meshDir / "boundary");
    // After the FoamFile header: N ( name { type T; ... } ... ); patch dictionaries hold no braces.
    const size_t list = text.find('(', text.find("FoamFile") == std::string::npos ? 0 : text.find('}') + 1);
    if (list == std::string::npos) return values;
    static const std::regex entry(R"(([A-Za-z_][\w.:\-]*)\s*\{([^{}]*)\})");
    const std::regex value("(?:^|[;\\s])" + key + R"(\s+(\w+)\s*;)");
    for (auto it = std::sregex_iterator(text.begin() + std::ptrdiff_t(list), text.end(), entry);
         it != std::sregex_iterator(); ++it) {
        std::smatch t;
        const std::string body = (*it)[2].str();
        if (std::regex_search(body, t, value)) values[(*it)[1].str()] = t[1].str();
    }
    return values;
}

}  // namespace

std::map<std::string, std::string> readPatchTypes(const fs::path& meshDir) { return readPatchEntries(meshDir, "type"); }

std::map<std::string, size_t> readPatchFaceCounts(const fs::path& meshDir) {
    std::map<std::string, size_t> counts;
    for (const auto& [name, n] : readPatchEntries(meshDir, "nFaces"))
        if (n.find_first_not_of("0123456789") == std::string::npos && n.size() < 19) counts[name] = std::stoull(n);
    return counts;
}

double readCaseViscosity(const fs::path& caseDir, std::string& from) {
    static const std::regex nu(R"((?:^|[;\s{])nu\s+(?:nu\s+)?(?:\[[^\]]*\]\s*)?([-+0-9.eE]+)\s*;)");
    for (const char* name : {"transportProperties", "physicalProperties"}) {
        const fs::path file = caseDir / "constant" / name;
        const std::string text = dictionaryText(file);
        std::smatch m;
        if (!std::regex_search(text, m, nu)) continue;
        const std::string number = m[1].str();  // strtod's end points into it: kept alive
        char* end = nullptr;
        const double value = std::strtod(number.c_str(), &end);
        if (*end == '\0' && value > 0) {
            from = (fs::path("constant") / name).string();
            return value;
        }
    }
    return 0.0;
}

bool isFoamWallType(const std::string& type) { return type == "wall" || type.find("Wall") != std::string::npos; }

// --- addFoamSkinFriction ---------------------------------------------------------------------
void addFoamSkinFriction(vtkDataObject& step, const FoamWalls& walls, const std::string& where) {
    auto* composite = vtkCompositeDataSet::SafeDownCast(&step);
    if (!composite) throw FormatError(where + ": --field skin-friction: VTK's OpenFOAM reader gave no blocks");
    vtkDataSet* volume = nullptr;
    std::vector<vtkPolyData*> wallPatches, otherPatches;
    std::vector<std::string> wallNames;
    auto it = vtkSmartPointer<vtkCompositeDataIterator>::Take(composite->NewIterator());
    it->SkipEmptyNodesOn();
    for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem()) {
        auto* ds = vtkDataSet::SafeDownCast(it->GetCurrentDataObject());
        const std::string name = it->HasCurrentMetaData() && it->GetCurrentMetaData()->Has(vtkCompositeDataSet::NAME())
                                     ? it->GetCurrentMetaData()->Get(vtkCompositeDataSet::NAME())
                                     : "";
        if (!ds) continue;
        if (name == "internalMesh") {
            volume = ds;
            continue;
        }
        auto* patch = vtkPolyData::SafeDownCast(ds);
        if (!patch) continue;
        const auto type = walls.types.find(name);
        // Without the boundary file every patch is taken as a wall.
        const bool wall = walls.types.empty() || (type != walls.types.end() && isFoamWallType(type->second));
        (wall ? wallPatches : otherPatches).push_back(patch);
        if (wall) wallNames.push_back("patch '" + name + "'");
    }
    if (!volume || volume->GetNumberOfCells() == 0)
        throw FormatError(where + ": --field skin-friction: the case has no internal mesh to take the wall gradient in");
    if (wallPatches.empty())
        throw FormatError(where + ": --field skin-friction: none of the patches read is a wall (type wall in "
                                  "constant/polyMesh/boundary); --patches selects which are read");
    addSkinFriction(volume, wallPatches, wallNames, walls.options, where);
    for (vtkPolyData* p : otherPatches) addZeroSkinFriction(p, walls.options.viscosity);
    // The surface is the patches: the volume goes before the surface stages see it.
    for (it->InitTraversal(); !it->IsDoneWithTraversal(); it->GoToNextItem())
        if (it->GetCurrentDataObject() == volume) {
            composite->SetDataSet(it, nullptr);
            break;
        }
}

}  // namespace flowsurf::io::detail
