// Writes the test cases of cgns_cases.h into a folder, for the command-line tests and the
// manual's picture: box.cgns (HDF5), box_adf.cgns (ADF), series.cgns, blocks.cgns,
// nobc.cgns, each with its expected surface as NAME.expected.vtk (series: one per step), and
// couette.cgns, couette_novelocity.cgns (a linear shear for --field skin-friction, and none).
// With --fuzz-seeds: the fuzz corpus's CGNS seeds instead (fuzz/cgns/, read by
// fuzz/make_seeds.py): the small valid files and their hostile variants (cut short, counts
// beyond the file), each on its own.
#include "cgns_cases.h"

#include <cstdio>
#include <exception>
#include <fstream>
#include <iterator>
#include <string>

namespace c = flowsurf::testing_cgns;

namespace {

void writeFuzzSeeds(const std::string& d) {
    c::writeUnstructuredBox(d + "box_hdf5.cgns", c::Backend::Hdf5);
    c::writeUnstructuredBox(d + "box_adf.cgns", c::Backend::Adf);
    c::writeStructuredBlocks(d + "blocks_adf.cgns", c::Backend::Adf);
    c::writeUnstructuredSeries(d + "series_adf.cgns", c::Backend::Adf);
    for (const char* backend : {"hdf5", "adf"}) {
        const std::string good = d + "box_" + backend + ".cgns";
        std::ifstream in(good, std::ios::binary);
        const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        std::ofstream(d + "regress_cut_" + backend + ".cgns", std::ios::binary) << bytes.substr(0, bytes.size() / 2);
        const struct {
            const char* name;
            const char* node;
            std::vector<int> values;
        } bombs[] = {{"zone", "/Base/Fluid", {0x7fffffff, 16, 0}},
                     {"section", "/Base/Fluid/floor/ElementRange", {25, 2000000000}},
                     {"bc", "/Base/Fluid/ZoneBC/floor/PointRange", {25, 2000000000}}};
        for (const auto& bomb : bombs) {
            const std::string path = d + "regress_bomb_" + bomb.name + "_" + backend + ".cgns";
            std::ofstream(path, std::ios::binary) << bytes;
            c::overwriteNode(path, bomb.node, bomb.values);
        }
    }
}

}  // namespace

int main(int argc, char** argv) {
    const bool fuzz = argc == 3 && std::string(argv[2]) == "--fuzz-seeds";
    if (argc != 2 && !fuzz) {
        std::fprintf(stderr, "usage: %s FOLDER [--fuzz-seeds]\n", argv[0]);
        return 2;
    }
    const std::string d = std::string(argv[1]) + "/";
    try {
        if (fuzz) {
            writeFuzzSeeds(d);
            return 0;
        }
        c::writeUnstructuredBox(d + "box.cgns", c::Backend::Hdf5, d + "box.expected.vtk");
        c::writeUnstructuredBox(d + "box_adf.cgns", c::Backend::Adf);
        c::writeUnstructuredSeries(d + "series.cgns", c::Backend::Hdf5, d + "series.expected_%d.vtk");
        c::writeStructuredBlocks(d + "blocks.cgns", c::Backend::Hdf5, d + "blocks.expected.vtk");
        c::writeBoxWithoutBcs(d + "nobc.cgns", c::Backend::Adf, d + "nobc.expected.vtk");
        c::writeCouetteBox(d + "couette.cgns", c::Backend::Hdf5, c::CouetteVelocity::Vertex, false);
        c::writeCouetteBox(d + "couette_novelocity.cgns", c::Backend::Hdf5, c::CouetteVelocity::None, false);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "%s\n", e.what());
        return 1;
    }
    return 0;
}
