// Sections: file checks · reader-backed sources · ParaView .pvd collections · openSource (the format table).
#include "io/reader/vtk_sources.h"

#include "core/errors.h"
#include "io/reader/checks.h"
#include "io/reader/parsers.h"
#include "io/reader/sandbox.h"

#include <vtkAlgorithm.h>
#include <vtkExodusIIReader.h>
#include <vtkGenericDataObjectReader.h>
#include <vtkGenericEnSightReader.h>
#include <vtkInformation.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkPolyData.h>
#include <vtkSTLReader.h>
#include <vtkTrivialProducer.h>
#include <vtkStreamingDemandDrivenPipeline.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLDataParser.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <sys/stat.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <system_error>

namespace flowsurf::io::detail {

namespace {

namespace fs = std::filesystem;

std::string lowerExtension(const std::string& path) {
    std::string ext = fs::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext;
}

// --- file checks -------------------------------------------------------------------
// Done before VTK sees the file: VTK reports a missing file as a vague parse error.
void checkReadable(const std::string& path, bool allowEmpty) {
    struct stat st {};
    if (::stat(path.c_str(), &st) != 0)
        throw IoError(path + ": cannot open (" + std::system_category().message(errno) + ")");
    if (S_ISDIR(st.st_mode)) throw IoError(path + ": cannot open (Is a directory)");
    FILE* f = std::fopen(path.c_str(), "rb");
    if (!f) {
        const int error = errno;
        std::string why = std::system_category().message(error);
        const std::string root = error == EACCES ? sandbox::rootExcluding(path) : "";
        if (!root.empty()) why += "; the reader may read only below " + root + ", doc/reader_sandbox.md";
        throw IoError(path + ": cannot open (" + why + ")");
    }
    std::fclose(f);
    if (!allowEmpty && st.st_size == 0) throw FormatError(path + ": the file is empty");
}

// vtkSTLReader reads a truncated binary STL without complaint (fewer triangles).
// Binary STL: 80-byte header, uint32 triangle count, 50 bytes per triangle. A file
// starting with "solid" is ASCII unless its size matches the binary layout exactly.
void checkBinaryStlSize(const std::string& path) {
    std::string head(84, '\0');
    std::ifstream in(path, std::ios::binary);
    head.resize(size_t(in.read(head.data(), 84).gcount()));
    const size_t first = head.find_first_not_of(" \t\r\n");
    if (first != std::string::npos && head.compare(first, 5, "solid") == 0) return;
    if (head.size() < 84)
        throw FormatError(path + ": not an STL file (too short for a binary STL header, no 'solid')");
    uint32_t count = 0;
    for (int i = 3; i >= 0; --i) count = count * 256 + static_cast<unsigned char>(head[80 + i]);
    const uint64_t binarySize = 84 + 50 * uint64_t(count);
    const size_t size = fs::file_size(path);
    if (binarySize > size)
        throw FormatError(path + ": truncated binary STL: the header declares " + std::to_string(count) +
                          " triangles (" + std::to_string(binarySize) + " bytes), the file has " +
                          std::to_string(size) + " bytes");
}

}  // namespace

// --- reader-backed sources ------------------------------------------------------------
AlgorithmSource::AlgorithmSource(vtkAlgorithm* reader, std::string path, std::string format, VtkMessageTrap& trap)
    : StepSource(std::move(path), std::move(format)), reader_(reader), trap_(trap) {
    vtkInformation* info = reader_->GetOutputInformation(0);
    auto key = vtkStreamingDemandDrivenPipeline::TIME_STEPS();
    if (info && info->Has(key)) {
        const double* t = info->Get(key);
        times_.assign(t, t + info->Length(key));
    }
}

vtkSmartPointer<vtkDataObject> AlgorithmSource::readStep(size_t index) {
    VtkMessageTrap::Active active(trap_);
    if (times_.empty()) reader_->Update();
    else reader_->UpdateTimeStep(times_.at(index));
    trap_.throwIfError(path_, "cannot read " + format_);
    afterUpdate(trap_);
    vtkDataObject* out = reader_->GetOutputDataObject(0);
    if (!out) throw FormatError(path_ + ": cannot read " + format_ + ": the reader gave no data");
    vtkSmartPointer<vtkDataObject> copy;
    copy.TakeReference(out->NewInstance());
    copy->ShallowCopy(out);
    adapt(*copy);
    return copy;
}

void readInformation(vtkAlgorithm* reader, const std::string& path, const std::string& format, VtkMessageTrap& trap) {
    reader->UpdateInformation();
    trap.throwIfError(path, "cannot read " + format);
}

namespace {

// How each format is opened: `format` names it in messages; `options` are OpenFOAM's.
using Opener = std::unique_ptr<StepSource> (*)(const std::string& path, const std::string& format,
                                               VtkMessageTrap& trap, const SourceOptions& options);

// A VTK reader of `path`, watched and its header read.
template <class Reader>
vtkSmartPointer<Reader> vtkReader(const std::string& path, const std::string& format, VtkMessageTrap& trap) {
    auto r = vtkSmartPointer<Reader>::New();
    if constexpr (requires { r->SetCaseFileName(""); }) r->SetCaseFileName(path.c_str());
    else r->SetFileName(path.c_str());
    trap.watch(r);
    readInformation(r, path, format, trap);
    return r;
}

template <class Reader>
std::unique_ptr<StepSource> openVtk(const std::string& path, const std::string& format, VtkMessageTrap& trap,
                                    const SourceOptions&) {
    return std::make_unique<AlgorithmSource>(vtkReader<Reader>(path, format, trap), path, format, trap);
}

// Our own parser's surface (PLY, OBJ), handed out as a reader's one step.
template <vtkSmartPointer<vtkPolyData> (*parse)(const std::string&)>
std::unique_ptr<StepSource> openParsed(const std::string& path, const std::string& format, VtkMessageTrap& trap,
                                       const SourceOptions&) {
    auto producer = vtkSmartPointer<vtkTrivialProducer>::New();
    producer->SetOutput(parse(path));
    return std::make_unique<AlgorithmSource>(producer, path, format, trap);
}

std::unique_ptr<StepSource> openStl(const std::string& path, const std::string& format, VtkMessageTrap& trap,
                                    const SourceOptions& options) {
    checkBinaryStlSize(path);
    return openVtk<vtkSTLReader>(path, format, trap, options);
}

std::unique_ptr<StepSource> openLegacy(const std::string& path, const std::string& format, VtkMessageTrap& trap,
                                       const SourceOptions&) {
    checkLegacyFile(path);  // old-layout cell lists VTK would read past their end
    auto r = vtkReader<vtkGenericDataObjectReader>(path, format, trap);
    // The header names the data set type; without one the reader has no output at all.
    vtkDataObject* out = r->GetOutputDataObject(0);
    if (!out) throw FormatError(path + ": not a VTK legacy file (no recognised dataset header)");
    std::string type = out->GetClassName();
    if (type.rfind("vtk", 0) == 0) type = type.substr(3);
    return std::make_unique<AlgorithmSource>(r, path, format + " " + type, trap);
}

std::unique_ptr<StepSource> openExodus(const std::string& path, const std::string& format, VtkMessageTrap& trap,
                                       const SourceOptions&) {
    checkExodusFile(path);  // a truncated file reads as zeros
    auto r = vtkReader<vtkExodusIIReader>(path, format, trap);
    // The reader loads no result variables unless asked.
    r->SetAllArrayStatus(vtkExodusIIReader::NODAL, 1);
    r->SetAllArrayStatus(vtkExodusIIReader::ELEM_BLOCK, 1);
    readInformation(r, path, format, trap);
    return std::make_unique<AlgorithmSource>(r, path, format, trap);
}

// --- ParaView .pvd collections ---------------------------------------------------------
// <VTKFile type="Collection"><Collection><DataSet timestep=".." part=".." file=".."/>...
// Entries with the same timestep are parts of one step (merged like composite blocks).
class PvdSource : public StepSource {
public:
    PvdSource(const std::string& path, const std::string& format, VtkMessageTrap& trap)
        : StepSource(path, format), trap_(trap) {
        auto parser = vtkSmartPointer<vtkXMLDataParser>::New();
        trap.watch(parser);
        parser->SetFileName(path.c_str());
        if (!parser->Parse() || trap.hasError()) {
            trap.throwIfError(path, "cannot parse the .pvd XML");
            throw FormatError(path + ": cannot parse the .pvd XML");
        }
        vtkXMLDataElement* root = parser->GetRootElement();
        vtkXMLDataElement* collection =
            root ? root->FindNestedElementWithName("Collection") : nullptr;
        if (!collection)
            throw FormatError(path + ": not a ParaView collection (no <Collection> element)");
        std::map<double, std::vector<std::string>> files;
        for (int i = 0; i < collection->GetNumberOfNestedElements(); ++i)
            addEntry(collection->GetNestedElement(i), i, files);
        if (files.empty()) throw FormatError(path + ": the collection lists no DataSet entries");
        for (auto& [t, list] : files) {
            times_.push_back(t);
            stepFiles_.push_back(std::move(list));
        }
    }

    vtkSmartPointer<vtkDataObject> readStep(size_t index) override {
        const auto& list = stepFiles_.at(index);
        if (list.size() == 1) return readPart(list[0]);
        auto blocks = vtkSmartPointer<vtkMultiBlockDataSet>::New();
        blocks->SetNumberOfBlocks(static_cast<unsigned>(list.size()));
        for (size_t i = 0; i < list.size(); ++i)
            blocks->SetBlock(static_cast<unsigned>(i), readPart(list[i]));
        return blocks;
    }

private:
    void addEntry(vtkXMLDataElement* e, int index,
                  std::map<double, std::vector<std::string>>& files) const {
        if (std::string(e->GetName()) != "DataSet") return;
        const char* file = e->GetAttribute("file");
        if (!file || !*file)
            throw FormatError(path_ + ": DataSet entry " + std::to_string(index) +
                              " has no file attribute");
        double t = 0.0;
        if (const char* ts = e->GetAttribute("timestep")) {
            char* end = nullptr;
            t = std::strtod(ts, &end);
            if (end == ts)
                throw FormatError(path_ + ": DataSet entry " + std::to_string(index) +
                                  " has a timestep that is not a number: '" + ts + "'");
        }
        fs::path p(file);
        if (p.is_relative()) p = fs::path(path_).parent_path() / p;
        files[t].push_back(p.string());
    }

    // A listed file is read with its own reader; errors name the .pvd and the file.
    vtkSmartPointer<vtkDataObject> readPart(const std::string& file) {
        if (lowerExtension(file) == ".pvd")
            throw FormatError(path_ + ": nested collection " + file + " is not supported");
        try {
            return openSource(file, trap_)->readStep(0);
        } catch (const IoError& e) {
            throw IoError(path_ + ": " + e.what());
        } catch (const FormatError& e) {
            throw FormatError(path_ + ": " + e.what());
        }
    }

    VtkMessageTrap& trap_;
    std::vector<std::vector<std::string>> stepFiles_;
};

std::unique_ptr<StepSource> openPvd(const std::string& path, const std::string& format, VtkMessageTrap& trap,
                                    const SourceOptions&) {
    return std::make_unique<PvdSource>(path, format, trap);
}

// --- openSource ------------------------------------------------------------------------
struct Format {
    const char* extension;
    const char* name;
    Opener open;
    bool surfaceOnly = false;  // cannot hold a volume (skin-friction)
};
const Format kFormats[] = {
    {".vtp", "VTK XML PolyData", openVtk<vtkXMLPolyDataReader>, true},
    {".vtu", "VTK XML UnstructuredGrid", openVtk<vtkXMLUnstructuredGridReader>},
    {".vtk", "VTK legacy", openLegacy},
    {".ply", "Stanford PLY", openParsed<readPly>, true},
    {".obj", "Wavefront OBJ", openParsed<readObj>, true},
    {".stl", "STL", openStl, true},
    {".foam", "OpenFOAM case", openOpenFoam},
    {".e", "Exodus II", openExodus},
    {".ex2", "Exodus II", openExodus},
    {".exo", "Exodus II", openExodus},
    {".case", "EnSight case", openVtk<vtkGenericEnSightReader>},
    {".cgns", "CGNS", openCgns},
    {".pvd", "ParaView data collection (.pvd)", openPvd},
};

}  // namespace

std::unique_ptr<StepSource> openSource(const std::string& path, VtkMessageTrap& trap, const SourceOptions& options) {
    VtkMessageTrap::Active active(trap);
    const std::string ext = lowerExtension(path);
    const Format* format = nullptr;
    std::string supported;
    for (const auto& f : kFormats) {
        if (ext == f.extension) format = &f;
        supported.append(supported.empty() ? "" : " ").append(f.extension);
    }
    // The .foam file is an empty marker in the case folder: only its presence counts.
    checkReadable(path, ext == ".foam");
    if (!format) throw FormatError(path + ": unknown file extension '" + ext + "' (supported: " + supported + ")");
    if (options.skinFriction && format->surfaceOnly)
        throw FormatError(path + ": --field skin-friction needs a volume mesh with its velocity (an OpenFOAM case, a "
                                 ".vtu/.vtk volume, EnSight or Exodus volume parts); " + format->name +
                          " holds a surface only");
    std::unique_ptr<StepSource> source = format->open(path, format->name, trap, options);
    // OpenFOAM cases and CGNS files know their walls and take the stress on them themselves.
    if (options.skinFriction && ext != ".foam" && ext != ".cgns") return withSkinFriction(std::move(source), options);
    return source;
}

}  // namespace flowsurf::io::detail
