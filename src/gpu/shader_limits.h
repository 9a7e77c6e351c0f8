// flowsurf — the sizes and thresholds that C++ and GLSL both read: shader_interface.cpp
// writes each as a `#define` of its GLSL name (in parentheses), the C++ of the stage that
// owns it uses the constant. Kept here, beside gpu_bindings.h, so that the interface
// depends on no stage above it.
#pragma once

namespace flowsurf::methods {

// Work group of the dye's band passes (DYE_GROUP; their binding points are in gpu_bindings.h).
inline constexpr int kDyeGroup = 256;
// Concentration (and premultiplied channel) below which a voxel's dye is cleared
// (DYE_VISIBLE): a quarter of an 8-bit gray level, never shown. A brick whose voxels all
// lie below it holds no dye: the step's flag (which bricks to advect next) and what the
// processes of a divided band send each other (dye/dye_shared.h) rest on that.
inline constexpr float kDyeVisible = 1.0f / 1024.0f;

// visibility_raster.comp's work group, in triangles (VIS_RASTER_GROUP; the passes' binding
// points are in gpu_bindings.h).
inline constexpr int kVisRasterGroup = 64;
// The occlusion step's screen cells (VisibilityBuffer::dropOccluded), in pixels a side
// (VIS_OCCLUDER_CELL).
inline constexpr int kVisOccluderCellPx = 8;

// PercentileRange's histogram (present/percentile_range.h): bins over [0, 1], a bin 1/512
// of the value range (HISTOGRAM_BINS); pixels per side of a work group's block (HISTOGRAM_TILE).
inline constexpr int kHistogramBins = 512;
inline constexpr int kHistogramTilePx = 32;

// The most time levels a frame of unsteady data carries (MAX_LEVELS; raster/time_levels.h).
inline constexpr int kMaxTimeLevels = 9;

}  // namespace flowsurf::methods
