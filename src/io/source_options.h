// flowsurf — how a file made of parts is read (OpenFOAM cases, CGNS files): plain data, so
// that the frame loop's options can name what they ask the readers for without the readers.
#pragma once

#include <string>

namespace flowsurf::io {

struct SourceOptions {
    std::string patches;            // boundary patches to read: a regular expression on the name (CGNS: or the
                                    // family); empty: the walls (OpenFOAM's wall-type patches, CGNS's
                                    // BCWall* BCs), all patches when none is a wall
    std::string foamCase = "auto";  // auto | reconstructed | decomposed (processor* directories)
    bool zeroTime = false;          // also read 0/ (initial conditions) when solved time directories exist
    // The derived wall field `skin-friction` (--field skin-friction), computed where the volume is read
    // (io/reader/skin_friction.h): OpenFOAM's internal mesh is read for it, a volume file's boundary is its wall.
    bool skinFriction = false;
    double viscosity = 0.0;         // kinematic, m²/s, for skin-friction; 0: the case's own, else a relative magnitude
};

}  // namespace flowsurf::io
