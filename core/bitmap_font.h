#pragma once
// A 3 x 5 pixel font for the words and numbers that core draws into its images (the
// difference map's scale, the explain map's legend): digits, A-Z (lower case is drawn
// as upper case) and a little punctuation. Nothing here needs a font file or GL.

#include <string_view>

#include "core/image.h"

namespace rt {

// Draws `text` with its top-left corner at (x, y_top) (rows count from the bottom, as in
// Image), each font pixel `scale` image pixels wide; what falls outside is clipped.
// Characters the font lacks are left blank.
void draw_text(Image& image, int x, int y_top, std::string_view text, int scale,
               const vec3& colour);

// How wide draw_text's text is, in image pixels (4 font pixels a character, the last
// one's spacing included).
int text_width(std::string_view text, int scale);
inline constexpr int kGlyphHeight = 5;  // font pixels

}  // namespace rt
