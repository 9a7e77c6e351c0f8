// flowsurf — a pre-check for EnSight Gold cases (private to src/io). VTK 9.1's EnSight
// readers trust every count: a `coordinates` or element count beyond the file makes them
// allocate for it and loop past the end of the file (an `nsided` block forever), so a
// 1 KB file held the reader until its timeout. Each count is checked against the bytes
// and lines the file has left before VTK sees the case.
#pragma once

#include <string>

namespace flowsurf::io::detail {

// Reads the .case file: a `number of steps` larger than the case file could list is
// refused; then every geometry file of `model:` (each step's file for a wildcard name,
// the one file of a single-file set) is walked, part by part: `coordinates`, `block`
// and element counts (ASCII: lines, C binary: bytes; ids as the header declares) must
// fit in what is left of the file. Throws FormatError naming the file, the part and the
// count. EnSight 6, Fortran binary and files that are missing or that the walk does
// not understand are left to VTK, which reports them.
void checkEnSightCase(const std::string& casePath);

}  // namespace flowsurf::io::detail
