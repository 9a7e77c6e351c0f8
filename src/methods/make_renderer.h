// flowsurf — the one place that knows every method: builds a renderer by kind. Kept out
// of common/ so the shared stages do not depend on the methods built on them.
#pragma once

#include "methods/frame.h"

#include <memory>
#include <string>

namespace flowsurf::methods {

// A name of kMethodNames -> Method. Throws ConfigError listing the names.
Method methodFromName(const std::string& name);

// A renderer of `method` for `viewport`. `group`: the processes rendering this view
// together, each with its own piece of the surface (sort-last, process_group.h), for the
// renderer's whole life: where its image stages run is chosen here (image_work.h), so a
// caller whose group changes makes a new renderer; null: this process alone. Throws
// ConfigError (bad parameters, or ones the group's mode cannot render) or GlError (out of
// graphics memory, or any GL error while setting it up).
std::unique_ptr<FlowMethod> makeRenderer(Method method, const MethodParams& params, const core::Viewport& viewport,
                                         ProcessGroup* group = nullptr);

// makeRenderer(methodFromName(name), ...).
std::unique_ptr<FlowMethod> makeMethod(const std::string& name, const MethodParams& params,
                                       const core::Viewport& viewport, ProcessGroup* group = nullptr);

}  // namespace flowsurf::methods
