#include "core/bitmap_font.h"

#include <cstdint>
#include <optional>

namespace rt {
namespace {

// Rows top to bottom, 3 bits each, the leftmost column in the highest bit.
constexpr std::uint16_t glyph(int r0, int r1, int r2, int r3, int r4) {
    return static_cast<std::uint16_t>(r0 << 12 | r1 << 9 | r2 << 6 | r3 << 3 | r4);
}

constexpr std::uint16_t kDigits[10] = {glyph(07, 05, 05, 05, 07), glyph(02, 06, 02, 02, 07),
                                       glyph(07, 01, 07, 04, 07), glyph(07, 01, 07, 01, 07),
                                       glyph(05, 05, 07, 01, 01), glyph(07, 04, 07, 01, 07),
                                       glyph(07, 04, 07, 05, 07), glyph(07, 01, 02, 02, 02),
                                       glyph(07, 05, 07, 05, 07), glyph(07, 05, 07, 01, 07)};

constexpr std::uint16_t kLetters[26] = {
    glyph(02, 05, 07, 05, 05), glyph(06, 05, 06, 05, 06), glyph(03, 04, 04, 04, 03),  // A B C
    glyph(06, 05, 05, 05, 06), glyph(07, 04, 06, 04, 07), glyph(07, 04, 06, 04, 04),  // D E F
    glyph(03, 04, 05, 05, 03), glyph(05, 05, 07, 05, 05), glyph(07, 02, 02, 02, 07),  // G H I
    glyph(01, 01, 01, 05, 02), glyph(05, 05, 06, 05, 05), glyph(04, 04, 04, 04, 07),  // J K L
    glyph(05, 07, 07, 05, 05), glyph(06, 05, 05, 05, 05), glyph(02, 05, 05, 05, 02),  // M N O
    glyph(06, 05, 06, 04, 04), glyph(02, 05, 05, 06, 03), glyph(06, 05, 06, 05, 05),  // P Q R
    glyph(03, 04, 02, 01, 06), glyph(07, 02, 02, 02, 02), glyph(05, 05, 05, 05, 07),  // S T U
    glyph(05, 05, 05, 05, 02), glyph(05, 05, 07, 07, 05), glyph(05, 05, 02, 05, 05),  // V W X
    glyph(05, 05, 02, 02, 02), glyph(07, 01, 02, 04, 07)};                            // Y Z

std::optional<std::uint16_t> glyph_of(char ch) {
    if (ch >= '0' && ch <= '9') return kDigits[ch - '0'];
    if (ch >= 'A' && ch <= 'Z') return kLetters[ch - 'A'];
    if (ch >= 'a' && ch <= 'z') return kLetters[ch - 'a'];
    switch (ch) {
        case '.':
            return glyph(0, 0, 0, 0, 02);
        case ',':
            return glyph(0, 0, 0, 02, 04);
        case ':':
            return glyph(0, 02, 0, 02, 0);
        case '-':
            return glyph(0, 0, 07, 0, 0);
        case '+':
            return glyph(0, 02, 07, 02, 0);
        case '=':
            return glyph(0, 07, 0, 07, 0);
        case '/':
            return glyph(01, 01, 02, 04, 04);
        case '%':
            return glyph(05, 01, 02, 04, 05);
        case '(':
            return glyph(02, 04, 04, 04, 02);
        case ')':
            return glyph(02, 01, 01, 01, 02);
        default:
            return std::nullopt;  // a space, or a character the font lacks
    }
}

}  // namespace

int text_width(std::string_view text, int scale) {
    return 4 * scale * static_cast<int>(text.size());
}

void draw_text(Image& image, int x, int y_top, std::string_view text, int scale,
               const vec3& colour) {
    for (char ch : text) {
        if (const std::optional<std::uint16_t> bits = glyph_of(ch)) {
            for (int row = 0; row < kGlyphHeight; ++row)
                for (int col = 0; col < 3; ++col)
                    if (*bits >> (14 - (row * 3 + col)) & 1)
                        for (int sy = 0; sy < scale; ++sy)
                            for (int sx = 0; sx < scale; ++sx) {
                                const int px = x + col * scale + sx, py = y_top - row * scale - sy;
                                if (px >= 0 && py >= 0 && px < image.width && py < image.height)
                                    image.at(px, py) = colour;
                            }
        }
        x += 4 * scale;
    }
}

}  // namespace rt
