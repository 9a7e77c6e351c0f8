// Shared by the test_io_*.cpp unit tests: a fresh folder per test and small files.
#pragma once

#include "core/errors.h"
#include "io/dataset_reader.h"

#include <gtest/gtest.h>

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkFloatArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <stdlib.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace flowsurf::testing_io {

namespace fs = std::filesystem;

// ::testing::TempDir()/flowsurf_io_SUITE_TEST_PID, removed at the end of the test.
class ScratchDir {
public:
    ScratchDir() {
        const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
        path_ = fs::path(::testing::TempDir()) /
                ("flowsurf_io_" + std::string(test->test_suite_name()) + "_" + test->name() + "_" +
                 std::to_string(::getpid()));
        fs::remove_all(path_);
        fs::create_directories(path_);
    }
    ~ScratchDir() {
        std::error_code ec;
        fs::remove_all(path_, ec);
    }
    std::string file(const std::string& name) const { return (path_ / name).string(); }
    const fs::path& path() const { return path_; }
    // Names of everything in the folder (to check that no temporary is left behind).
    std::vector<std::string> list() const {
        std::vector<std::string> names;
        for (const auto& e : fs::directory_iterator(path_)) names.push_back(e.path().filename().string());
        std::sort(names.begin(), names.end());
        return names;
    }

private:
    fs::path path_;
};

inline void writeText(const std::string& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
}

inline std::string readBytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Sets an environment variable for the scope.
class ScopedEnv {
public:
    ScopedEnv(const char* name, const std::string& value) : name_(name) { setenv(name, value.c_str(), 1); }
    ~ScopedEnv() { unsetenv(name_); }
    ScopedEnv(const ScopedEnv&) = delete;
    ScopedEnv& operator=(const ScopedEnv&) = delete;

private:
    const char* name_;
};

// The FormatError's message when reading `path`; a hang, another type or no error say so
// instead.
inline std::string formatErrorOf(const std::string& path) {
    try {
        io::readDataset(path);
    } catch (const FormatError& e) {
        return e.what();
    } catch (const std::exception& e) {
        return std::string("wrong type: ") + e.what();
    }
    return "no exception";
}

// CPU seconds used by this process's children that have ended (the reader processes).
inline double childCpuSeconds() {
    rusage u{};
    getrusage(RUSAGE_CHILDREN, &u);
    return double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) + 1e-6 * double(u.ru_utime.tv_usec + u.ru_stime.tv_usec);
}

// How long `read` took: wall-clock seconds, and CPU seconds of the reader processes.
struct Took {
    double wall = 0, cpu = 0;
};
template <class Read>
Took timed(Read read) {
    const double cpu = childCpuSeconds();
    const auto start = std::chrono::steady_clock::now();
    read();
    return {std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), childCpuSeconds() - cpu};
}

inline vtkSmartPointer<vtkFloatArray> makeArray(const char* name, int components) {
    auto a = vtkSmartPointer<vtkFloatArray>::New();
    a->SetName(name);
    a->SetNumberOfComponents(components);
    return a;
}

// A flat nx × ny grid of unit quads in z = 0, point (i, j) at (i, j, 0), with
//   point "U" = (1, 0.5 x, 0), point scalar "p" = x,
//   cell "cellVec" = (cell index, 0, 2), cell scalar "cellId" = cell index.
// Cells are quads (or split into two triangles each with `triangles`).
inline vtkSmartPointer<vtkPolyData> makeGrid(int nx, int ny, bool triangles = false) {
    auto points = vtkSmartPointer<vtkPoints>::New();
    auto u = makeArray("U", 3);
    auto p = makeArray("p", 1);
    for (int j = 0; j <= ny; ++j)
        for (int i = 0; i <= nx; ++i) {
            points->InsertNextPoint(i, j, 0);
            u->InsertNextTuple3(1, 0.5 * i, 0);
            p->InsertNextTuple1(i);
        }
    auto polys = vtkSmartPointer<vtkCellArray>::New();
    auto cellVec = makeArray("cellVec", 3);
    auto cellId = makeArray("cellId", 1);
    auto id = [nx](int i, int j) { return vtkIdType(j * (nx + 1) + i); };
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i) {
            vtkIdType q[4] = {id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)};
            if (triangles) {
                vtkIdType a[3] = {q[0], q[1], q[2]}, b[3] = {q[0], q[2], q[3]};
                polys->InsertNextCell(3, a);
                polys->InsertNextCell(3, b);
            } else {
                polys->InsertNextCell(4, q);
            }
        }
    for (vtkIdType c = 0; c < polys->GetNumberOfCells(); ++c) {
        cellVec->InsertNextTuple3(double(c), 0, 2);
        cellId->InsertNextTuple1(double(c));
    }
    auto grid = vtkSmartPointer<vtkPolyData>::New();
    grid->SetPoints(points);
    grid->SetPolys(polys);
    grid->GetPointData()->AddArray(u);
    grid->GetPointData()->AddArray(p);
    grid->GetCellData()->AddArray(cellVec);
    grid->GetCellData()->AddArray(cellId);
    return grid;
}

// Runs readDataset and checks the exception type and that the message names `mustName`.
template <class Error>
inline void expectReadError(const std::string& path, const std::string& mustName,
                     const std::string& mustSay = "") {
    SCOPED_TRACE(path);
    try {
        io::readDataset(path);
        ADD_FAILURE() << "no exception";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find(mustName), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find(mustSay), std::string::npos) << e.what();
    } catch (const std::exception& e) {
        ADD_FAILURE() << "wrong exception type: " << e.what();
    }
}

}  // namespace flowsurf::testing_io
