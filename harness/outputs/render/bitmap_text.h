// Short labels drawn into images with a built-in 5x7 pixel font: digits, capital letters,
// '.', '-', '+', '%', '_', '/', '(', ')', ',', ':' and space (other characters are skipped as
// spaces), for the numbers of a colour bar and the captions of panels; no font file is
// needed. Small letters are drawn as capitals, except 'e', which keeps a small glyph for the
// exponents of numbers: write captions in capitals.
#pragma once

#include "harness/outputs/render/image.h"

#include <string>

namespace holebench::render {

struct TextOptions {
  int scale = 2;        ///< pixels per font pixel
  Rgb colour{0, 0, 0};  ///< linear RGB
};

/// The width in pixels of `text` (6 font pixels per character, times the scale).
int text_width(const std::string& text, const TextOptions& options = {});

/// `text` in capitals, as captions are written (a small 'e' would draw as the exponent's).
std::string capitals(std::string text);

/// Draws `text` with its top-left corner at (x, y); pixels outside the image are skipped.
void draw_text(Image& image, int x, int y, const std::string& text,
               const TextOptions& options = {});

}  // namespace holebench::render
