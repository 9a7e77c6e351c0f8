#include "present/text.h"

#include "core/errors.h"
#include "core/program_dirs.h"

#include <ft2build.h>
#include FT_FREETYPE_H

#include <algorithm>
#include <functional>
#include <iterator>

namespace flowsurf::methods {

namespace {
const char* kFonts[] = {"/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf",
                        "/usr/share/fonts/truetype/dejavu/DejaVuSans-Bold.ttf"};

// The system's font, else the copy a portable tree carries in PREFIX/share/flowsurf/fonts/.
std::vector<std::string> fontFiles() {
    std::vector<std::string> files(std::begin(kFonts), std::end(kFonts));
    for (const auto& dir : core::programDirs())
        files.push_back((dir.parent_path() / "share/flowsurf/fonts/DejaVuSans.ttf").string());
    return files;
}

// Calls `glyph` for each rendered character with its pen position; returns the advance.
int layout(const std::string& text, int sizePx, const std::function<void(FT_GlyphSlot, int)>& glyph) {
    FT_Library lib = nullptr;
    if (FT_Init_FreeType(&lib)) throw IoError("FreeType could not be initialised");
    FT_Face face = nullptr;
    for (const std::string& f : fontFiles())
        if (!FT_New_Face(lib, f.c_str(), 0, &face)) break;
    if (!face) {
        FT_Done_FreeType(lib);
        throw IoError(std::string(kFonts[0]) + ": cannot load the label font (install fonts-dejavu-core)");
    }
    FT_Set_Pixel_Sizes(face, 0, FT_UInt(sizePx));
    int penX = 0;
    for (unsigned char ch : text) {  // labels are ASCII
        if (FT_Load_Char(face, ch, FT_LOAD_RENDER)) continue;
        glyph(face->glyph, penX);
        penX += int(face->glyph->advance.x >> 6);
    }
    FT_Done_Face(face);
    FT_Done_FreeType(lib);
    return penX;
}
}  // namespace

void drawText(RgbImage& image, const std::string& text, int x, int y, int sizePx, const uint8_t color[3]) {
    layout(text, sizePx, [&](FT_GlyphSlot g, int penX) {
        const FT_Bitmap& bm = g->bitmap;
        int left = x + penX + g->bitmap_left, top = y - g->bitmap_top;
        for (unsigned r = 0; r < bm.rows; ++r)
            for (unsigned c = 0; c < bm.width; ++c) {
                int px = left + int(c), py = top + int(r);
                if (px < 0 || py < 0 || px >= image.width || py >= image.height) continue;
                float a = bm.buffer[r * bm.pitch + c] / 255.0f;
                uint8_t* dst = &image.pixels[(size_t(py) * image.width + px) * image.channels];
                // On a transparent RGBA pixel the colour is the text's; coverage goes to alpha.
                const float w = image.channels == 4 && dst[3] == 0 ? 1.0f : a;
                for (int k = 0; k < 3; ++k) dst[k] = uint8_t(dst[k] + w * (float(color[k]) - float(dst[k])) + 0.5f);
                if (image.channels == 4) dst[3] = std::max(dst[3], uint8_t(a * 255.0f + 0.5f));
            }
    });
}

int textWidth(const std::string& text, int sizePx) {
    return layout(text, sizePx, [](FT_GlyphSlot, int) {});
}

}  // namespace flowsurf::methods
