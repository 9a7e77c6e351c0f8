// flowsurf — a dye source as the options give it (no GL): where ink is released, how much
// and when. The point is snapped to the nearest surface point when the dye starts.
#pragma once

#include <glm/glm.hpp>

namespace flowsurf::methods {

// Radius of a source given without one: pixels at the view of the dye's first frame.
inline constexpr float kDyeRadiusPx = 6.0f;

struct DyeSource {
    glm::vec3 point{0.0f};              // object space (snapped to the surface)
    float radius = 0.0f;                // object units; 0: a few pixels at the first frame's view
    glm::vec3 color{0.9f, 0.1f, 0.1f};  // linear RGB 0..1
    int start = 0;                      // first animation frame that emits
    int stop = -1;                      // first frame that no longer emits; -1: --dye-release decides
    bool operator==(const DyeSource&) const = default;
};

// Colours of sources given without one, in order: distinct from every colour map's hues
// at full saturation.
inline constexpr glm::vec3 kDyePalette[] = {{0.95f, 0.1f, 0.1f}, {0.1f, 0.85f, 0.2f}, {0.15f, 0.35f, 1.0f},
                                            {1.0f, 0.85f, 0.0f}, {0.9f, 0.1f, 0.9f},  {0.0f, 0.9f, 0.9f}};

}  // namespace flowsurf::methods
