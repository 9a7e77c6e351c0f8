// flowsurf — the typed errors of the library, one base. Every failure a user can cause
// (a bad file, a missing field, a bad option value, no OpenGL) is one of these, with a
// message that names the file, element or option; the library never exits the process.
#pragma once

#include <stdexcept>
#include <string>

namespace flowsurf {

// Base of every error the library reports to a user.
class Error : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// A file cannot be opened, read or written.
class IoError : public Error {
public:
    using Error::Error;
};

// A file was read but its content is malformed, truncated, empty or invalid
// (NaN vectors, out-of-range indices, mismatched array sizes...).
class FormatError : public Error {
public:
    using Error::Error;
};

// A requested vector field / array does not exist.
class FieldError : public Error {
public:
    using Error::Error;
};

// The OpenGL context cannot be created or lacks what we need.
class GlError : public Error {
public:
    using Error::Error;
};

// A shader failed to compile or link.
class ShaderError : public GlError {
public:
    using GlError::GlError;
};

// Invalid parameters or options (image size, grid resolution, unknown names).
class ConfigError : public Error {
public:
    using Error::Error;
};

}  // namespace flowsurf
