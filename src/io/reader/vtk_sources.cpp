// Sections: file checks · reader-backed sources · ParaView .pvd collections · openSource.
#include "io/reader/vtk_sources.h"

#include "core/errors.h"
#include "io/reader/exodus_check.h"
#include "io/reader/legacy_check.h"
#include "io/reader/obj_reader.h"
#include "io/reader/openfoam_source.h"
#include "io/reader/ply_reader.h"
#include "io/reader/sandbox.h"

#include <vtkAlgorithm.h>
#include <vtkExodusIIReader.h>
#include <vtkGenericDataObjectReader.h>
#include <vtkGenericEnSightReader.h>
#include <vtkInformation.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkSTLReader.h>
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
#include <functional>
#include <map>
#include <sstream>
#include <system_error>

namespace flowsurf::io::detail {

namespace {

namespace fs = std::filesystem;

struct FormatEntry {
    const char* extension;
    const char* name;
};
const FormatEntry kFormats[] = {
    {".vtp", "VTK XML PolyData"},    {".vtu", "VTK XML UnstructuredGrid"},
    {".vtk", "VTK legacy"},          {".ply", "Stanford PLY"},
    {".obj", "Wavefront OBJ"},       {".stl", "STL"},
    {".foam", "OpenFOAM case"},      {".e", "Exodus II"},
    {".ex2", "Exodus II"},           {".exo", "Exodus II"},
    {".case", "EnSight case"},       {".pvd", "ParaView data collection (.pvd)"},
};

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
        if (error == EACCES && sandbox::isOutsideReadableRoot(path))
            why += "; the reader may read only below " + sandbox::readableRoot() + ", doc/reader_sandbox.md";
        throw IoError(path + ": cannot open (" + why + ")");
    }
    std::fclose(f);
    if (!allowEmpty && st.st_size == 0) throw FormatError(path + ": the file is empty");
}

std::string fileStart(const std::string& path, size_t bytes) {
    std::string head(bytes, '\0');
    FILE* f = std::fopen(path.c_str(), "rb");
    if (!f) throw IoError(path + ": cannot open (" + std::system_category().message(errno) + ")");
    head.resize(std::fread(head.data(), 1, bytes, f));
    std::fclose(f);
    return head;
}

// vtkSTLReader reads a truncated binary STL without complaint (fewer triangles).
// Binary STL: 80-byte header, uint32 triangle count, 50 bytes per triangle. A file
// starting with "solid" is ASCII unless its size matches the binary layout exactly.
void checkBinaryStlSize(const std::string& path) {
    const std::string head = fileStart(path, 84);
    const size_t size = fs::file_size(path);
    uint32_t count = 0;
    if (head.size() == 84) {
        for (int i = 3; i >= 0; --i) count = count * 256 + static_cast<unsigned char>(head[80 + i]);
    }
    const uint64_t binarySize = 84 + 50 * uint64_t(count);
    size_t first = head.find_first_not_of(" \t\r\n");
    const bool saysSolid = first != std::string::npos && head.compare(first, 5, "solid") == 0;
    if (saysSolid || (head.size() == 84 && binarySize == size)) return;
    if (head.size() < 84)
        throw FormatError(path + ": not an STL file (too short for a binary STL header, no 'solid')");
    if (binarySize > size)
        throw FormatError(path + ": truncated binary STL: the header declares " + std::to_string(count) +
                          " triangles (" + std::to_string(binarySize) + " bytes), the file has " +
                          std::to_string(size) + " bytes");
}

// --- reader-backed sources -----------------------------------------------------------
}  // namespace

// --- reader-backed sources (vtk_sources.h) ---
AlgorithmSource::AlgorithmSource(vtkAlgorithm* reader, std::string path, std::string format, VtkMessageTrap& trap)
    : reader_(reader), path_(std::move(path)), format_(std::move(format)), trap_(trap) {
    vtkInformation* info = reader_->GetOutputInformation(0);
    auto key = vtkStreamingDemandDrivenPipeline::TIME_STEPS();
    if (info && info->Has(key)) {
        const double* t = info->Get(key);
        times_.assign(t, t + info->Length(key));
    }
}

vtkSmartPointer<vtkDataObject> AlgorithmSource::readStep(size_t index) {
    VtkMessageTrap::Active active(trap_);
    trap_.clear();
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

namespace {

// A data object read without a VTK reader (PLY, OBJ): one step, already in memory.
class ReadySource : public StepSource {
public:
    ReadySource(vtkSmartPointer<vtkDataObject> data, std::string format)
        : data_(std::move(data)), format_(std::move(format)) {}
    std::string format() const override { return format_; }
    const std::vector<double>& times() const override { return times_; }
    vtkSmartPointer<vtkDataObject> readStep(size_t) override { return data_; }

private:
    vtkSmartPointer<vtkDataObject> data_;
    std::string format_;
    std::vector<double> times_;
};

// Reads the header; `configure` runs after it (array and patch selections need the
// names the header lists), followed by a second header pass.
std::unique_ptr<StepSource> makeSource(vtkAlgorithm* reader, const std::string& path,
                                       const std::string& format, VtkMessageTrap& trap,
                                       const std::function<void()>& configure = {}) {
    trap.watch(reader);
    reader->UpdateInformation();
    trap.throwIfError(path, "cannot read " + format);
    if (configure) {
        configure();
        reader->UpdateInformation();
        trap.throwIfError(path, "cannot read " + format);
    }
    return std::make_unique<AlgorithmSource>(reader, path, format, trap);
}

template <class Reader>
vtkSmartPointer<Reader> readerFor(const std::string& path) {
    auto r = vtkSmartPointer<Reader>::New();
    r->SetFileName(path.c_str());
    return r;
}

std::unique_ptr<StepSource> openLegacy(const std::string& path, VtkMessageTrap& trap) {
    checkLegacyFile(path);  // old-layout cell lists VTK would read past their end
    auto r = readerFor<vtkGenericDataObjectReader>(path);
    trap.watch(r);
    r->UpdateInformation();
    trap.throwIfError(path, "cannot read VTK legacy");
    // The header names the data set type; without one the reader has no output at all.
    vtkDataObject* out = r->GetOutputDataObject(0);
    if (!out) throw FormatError(path + ": not a VTK legacy file (no recognised dataset header)");
    std::string type = out->GetClassName();
    if (type.rfind("vtk", 0) == 0) type = type.substr(3);
    return std::make_unique<AlgorithmSource>(r, path, "VTK legacy " + type, trap);
}

std::unique_ptr<StepSource> openExodus(const std::string& path, VtkMessageTrap& trap) {
    checkExodusFile(path);  // a truncated file reads as zeros
    auto r = readerFor<vtkExodusIIReader>(path);
    return makeSource(r, path, "Exodus II", trap, [&] {
        // The reader loads no result variables unless asked.
        r->SetAllArrayStatus(vtkExodusIIReader::NODAL, 1);
        r->SetAllArrayStatus(vtkExodusIIReader::ELEM_BLOCK, 1);
    });
}

// --- ParaView .pvd collections ---------------------------------------------------------
// <VTKFile type="Collection"><Collection><DataSet timestep=".." part=".." file=".."/>...
// Entries with the same timestep are parts of one step (merged like composite blocks).
class PvdSource : public StepSource {
public:
    PvdSource(const std::string& path, VtkMessageTrap& trap) : path_(path), trap_(trap) {
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
    std::string format() const override { return "ParaView data collection (.pvd)"; }
    const std::vector<double>& times() const override { return times_; }

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

    std::string path_;
    VtkMessageTrap& trap_;
    std::vector<double> times_;
    std::vector<std::vector<std::string>> stepFiles_;
};

}  // namespace

std::string supportedExtensions() {
    std::string s;
    for (const auto& f : kFormats) s.append(s.empty() ? "" : " ").append(f.extension);
    return s;
}

std::string stepLabel(const std::string& path, const StepSource& source, size_t index) {
    if (source.stepCount() <= 1) return path;
    std::ostringstream s;
    s << path << " (time step " << index + 1 << " of " << source.stepCount()
      << ", t = " << source.times()[index] << ")";
    return s.str();
}

// --- openSource ------------------------------------------------------------------------
std::unique_ptr<StepSource> openSource(const std::string& path, VtkMessageTrap& trap, const SourceOptions& options) {
    VtkMessageTrap::Active active(trap);
    const std::string ext = lowerExtension(path);
    const FormatEntry* entry = nullptr;
    for (const auto& f : kFormats)
        if (ext == f.extension) entry = &f;
    // The .foam file is an empty marker in the case folder: only its presence counts.
    checkReadable(path, ext == ".foam");
    if (!entry)
        throw FormatError(path + ": unknown file extension '" + ext +
                          "' (supported: " + supportedExtensions() + ")");
    trap.clear();
    const std::string name = entry->name;
    if (ext == ".vtp" || ext == ".vtu") {
        vtkSmartPointer<vtkAlgorithm> reader;
        if (ext == ".vtp") reader = readerFor<vtkXMLPolyDataReader>(path);
        else reader = readerFor<vtkXMLUnstructuredGridReader>(path);
        return makeSource(reader, path, name, trap);
    }
    if (ext == ".vtk") return openLegacy(path, trap);
    if (ext == ".ply") return std::make_unique<ReadySource>(readPly(path), name);
    if (ext == ".obj") return std::make_unique<ReadySource>(readObj(path), name);
    if (ext == ".stl") {
        checkBinaryStlSize(path);
        return makeSource(readerFor<vtkSTLReader>(path), path, name, trap);
    }
    if (ext == ".foam") return openOpenFoam(path, trap, options);
    if (ext == ".case") {
        auto r = vtkSmartPointer<vtkGenericEnSightReader>::New();
        r->SetCaseFileName(path.c_str());
        return makeSource(r, path, name, trap);
    }
    if (ext == ".pvd") return std::make_unique<PvdSource>(path, trap);
    return openExodus(path, trap);
}

}  // namespace flowsurf::io::detail
