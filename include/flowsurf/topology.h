// flowsurf — the flow topology of a surface's field (docs/topology.md): its critical points
// and its separation and attachment lines, in the surface's coordinates, as
// Surface::topology() returns them. Plain data the caller owns.
#pragma once

#include <string>
#include <vector>

namespace flowsurf {

struct CriticalPoint {
    float position[3] = {0, 0, 0};  // object space
    std::string type;               // source, sink, saddle, center, repelling_focus, attracting_focus
    int index = 0;                  // Poincaré index: +1, or -1 for a saddle
    float eigenvalues[2][2] = {};   // (re, im) of the fitted Jacobian's eigenvalues, 1/time
};

struct TopologyLine {
    std::string kind;             // separation or attachment
    std::vector<float> points;    // n x 3, object space, in order along the line
    std::vector<float> strength;  // n: |rate across - rate along| x diagonal / 99th-percentile speed
};

struct Topology {
    std::vector<CriticalPoint> criticalPoints;
    std::vector<TopologyLine> lines;
    long eulerCharacteristic = 0;  // of the surface welded at coincident vertices
    long indexSum = 0;             // equals eulerCharacteristic on a closed surface
    bool closed = false;
    std::string field;             // the vector array analysed
    bool fieldReversed = false;    // shown (and analysed) reversed: --reverse-field
};

}  // namespace flowsurf
