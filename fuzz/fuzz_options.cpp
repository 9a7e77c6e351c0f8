// The option value parsers: --size, vectors, colours, numbers, and every row of the
// option table through setOption. Input: option index byte, then the value text.
#include "core/errors.h"
#include "session/options/options.h"

#include <string>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (size == 0) return 0;
    namespace s = flowsurf::session;
    const std::string text(reinterpret_cast<const char*>(data) + 1, size - 1);
    const auto& table = s::renderOptionTable();
    try {
        switch (data[0] % 5) {
            case 0: s::parseSize(text); break;
            case 1: s::parseVec3(text, "--up"); break;
            case 2: s::parseColor(text); break;
            case 3: s::parseFloat(text, "--alpha"); break;
            default: {
                s::RenderOptions o;
                s::setOption(o, table[(data[0] / 5) % table.size()].name, text);
                s::validateRenderOptions(o);
            }
        }
    } catch (const flowsurf::Error&) {
    }
    return 0;
}
