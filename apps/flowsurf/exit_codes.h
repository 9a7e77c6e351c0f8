// flowsurf — distinct exit codes of the command-line program, one per error type.
#pragma once

namespace flowsurf::app {

enum ExitCode : int {
    kOk = 0,
    kInternal = 1,    // unexpected error (a bug)
    kUsage = 2,       // bad command line or option value (ConfigError, CLI11 errors)
    kIo = 3,          // cannot open, read or write a file (IoError)
    kFormat = 4,      // malformed, truncated, empty or invalid data (FormatError)
    kField = 5,       // requested vector field missing (FieldError)
    kGl = 6,          // no usable OpenGL 4.5 context, shader failure (GlError)
};

}  // namespace flowsurf::app
