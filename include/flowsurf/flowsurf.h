// flowsurf — dense, animated flow textures on triangle-mesh surfaces (ISA and IBFVS
// [Laramee et al. 2004], hybrid physical/device-space LIC [Weiskopf & Ertl 2004]).
// The one header a C++ consumer includes; it pulls in no OpenGL, EGL or VTK header.
//
//   errors.h    typed exceptions (IoError, FormatError, FieldError, ConfigError, GlError)
//   surface.h   Surface: from arrays or read from a file; time series; its arrays out per step
//   renderer.h  Renderer: options by name, camera, frames, images into caller memory
//   image.h     writePng: 8-bit RGB or 16-bit gray PNG
//
// Link with find_package(flowsurf CONFIG REQUIRED) and flowsurf::flowsurf, or
// pkg-config flowsurf.
#pragma once

#include <flowsurf/errors.h>
#include <flowsurf/image.h>
#include <flowsurf/renderer.h>
#include <flowsurf/surface.h>
#include <flowsurf/topology.h>

#define FLOWSURF_VERSION_MAJOR 0
#define FLOWSURF_VERSION_MINOR 1
#define FLOWSURF_VERSION_PATCH 0
