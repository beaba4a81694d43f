#include "harness/outputs/render/bitmap_text.h"

#include <array>
#include <cstdint>

namespace holebench::render {
namespace {

constexpr int kGlyphWidth = 5;
constexpr int kGlyphHeight = 7;
constexpr int kAdvance = 6;

/// Rows of a glyph, top first; bit 4 is the leftmost column.
using Glyph = std::array<std::uint8_t, kGlyphHeight>;

const Glyph* glyph(char c) {
  static const Glyph digits[10] = {
      {0x0E, 0x11, 0x13, 0x15, 0x19, 0x11, 0x0E},  // 0
      {0x04, 0x0C, 0x04, 0x04, 0x04, 0x04, 0x0E},  // 1
      {0x0E, 0x11, 0x01, 0x02, 0x04, 0x08, 0x1F},  // 2
      {0x1F, 0x02, 0x04, 0x02, 0x01, 0x11, 0x0E},  // 3
      {0x02, 0x06, 0x0A, 0x12, 0x1F, 0x02, 0x02},  // 4
      {0x1F, 0x10, 0x1E, 0x01, 0x01, 0x11, 0x0E},  // 5
      {0x06, 0x08, 0x10, 0x1E, 0x11, 0x11, 0x0E},  // 6
      {0x1F, 0x01, 0x02, 0x04, 0x08, 0x08, 0x08},  // 7
      {0x0E, 0x11, 0x11, 0x0E, 0x11, 0x11, 0x0E},  // 8
      {0x0E, 0x11, 0x11, 0x0F, 0x01, 0x02, 0x0C},  // 9
  };
  static const Glyph dot = {0x00, 0x00, 0x00, 0x00, 0x00, 0x0C, 0x0C};
  static const Glyph minus = {0x00, 0x00, 0x00, 0x1F, 0x00, 0x00, 0x00};
  static const Glyph plus = {0x00, 0x04, 0x04, 0x1F, 0x04, 0x04, 0x00};
  static const Glyph e = {0x00, 0x00, 0x0E, 0x11, 0x1F, 0x10, 0x0E};
  static const Glyph percent = {0x18, 0x19, 0x02, 0x04, 0x08, 0x13, 0x03};
  if (c >= '0' && c <= '9')
    return &digits[c - '0'];
  switch (c) {
    case '.':
      return &dot;
    case '-':
      return &minus;
    case '+':
      return &plus;
    case 'e':
      return &e;
    case '%':
      return &percent;
    default:
      return nullptr;
  }
}

}  // namespace

int text_width(const std::string& text, const TextOptions& options) {
  return static_cast<int>(text.size()) * kAdvance * options.scale;
}

void draw_text(Image& image, int x, int y, const std::string& text, const TextOptions& options) {
  for (std::size_t i = 0; i < text.size(); ++i) {
    const Glyph* g = glyph(text[i]);
    if (!g)
      continue;
    const int left = x + static_cast<int>(i) * kAdvance * options.scale;
    for (int row = 0; row < kGlyphHeight; ++row) {
      for (int column = 0; column < kGlyphWidth; ++column) {
        if (!((*g)[row] & (0x10 >> column)))
          continue;
        for (int sy = 0; sy < options.scale; ++sy) {
          for (int sx = 0; sx < options.scale; ++sx) {
            const int px = left + column * options.scale + sx;
            const int py = y + row * options.scale + sy;
            if (px >= 0 && py >= 0 && px < image.width && py < image.height)
              image.set(px, py, options.colour);
          }
        }
      }
    }
  }
}

}  // namespace holebench::render
