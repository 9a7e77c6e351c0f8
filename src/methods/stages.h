// flowsurf — the stages a method's timer names (FlowMethod::timer, gl::StageTimer), one row
// each: what the renderers time, the benchmark's columns, the viewer's panel and --stats
// and Renderer::stageMs report are these names.
#pragma once

#include <array>
#include <string_view>

namespace flowsurf::methods {

enum class Stage {
    VelocityImage, SeedTextures, VelocityLevels, AdvectionMesh, TextureAdvection, ParticleTracing, SolidNoise,
    Overlay, EdgeMask, ContrastTexture, ContrastColour, TileExchange, TileReturn
};

inline constexpr std::array<std::pair<Stage, const char*>, 13> kStageNames{{
    {Stage::VelocityImage, "velocity image"},        // ISA: the surface's velocities in image space
    {Stage::SeedTextures, "seed textures"},          // the hybrid's surface pass
    {Stage::VelocityLevels, "velocity levels"},      // the hybrid, unsteady data: one per time level
    {Stage::AdvectionMesh, "advection mesh"},        // ISA
    {Stage::TextureAdvection, "texture advection"},  // ISA and IBFVS, with the noise blend
    {Stage::ParticleTracing, "particle tracing"},    // the hybrid
    {Stage::SolidNoise, "solid noise"},              // the hybrid
    {Stage::Overlay, "overlay"},
    {Stage::EdgeMask, "edge mask"},                  // IBFVS --edge-mask
    {Stage::ContrastTexture, "contrast (texture)"},  // --enhance-contrast
    {Stage::ContrastColour, "contrast (colour)"},
    {Stage::TileExchange, "tile exchange"},          // split over processes (ParaView under MPI)
    {Stage::TileReturn, "tile return"},
}};

constexpr const char* stageName(Stage s) {
    for (const auto& [stage, name] : kStageNames)
        if (stage == s) return name;
    return "";
}

// True for the stages that move tiles between processes (the exchange and the return) rather
// than compute the image: FLOWSURF_RANK_STATS sums the others as the compute stages.
constexpr bool isExchangeStage(std::string_view name) {
    return name == stageName(Stage::TileExchange) || name == stageName(Stage::TileReturn);
}

// True if the timer's stage `name` is a row of the table.
constexpr bool isStageName(std::string_view name) {
    for (const auto& [stage, n] : kStageNames)
        if (name == n) return true;
    return false;
}

}  // namespace flowsurf::methods
