#include "shading/ContactSheet.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

// stb_easy_font is header-only with static functions: no implementation define needed. It
// leaves some of its tables and parameters unused in this translation unit.
#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wsign-compare"
#endif
#include <stb/stb_easy_font.h>
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif

namespace specula::render {
namespace {

constexpr int kLabelScale = 2;
constexpr int kPadding = 6;
constexpr int kLabelHeight = 12 * kLabelScale + 2 * kPadding; // stb_easy_font glyphs are ~12 units tall

void fillRect(ImageRGBA8& image, int x0, int y0, int x1, int y1, const uint8_t rgba[4])
{
    x0 = std::max(x0, 0), y0 = std::max(y0, 0);
    x1 = std::min(x1, image.width), y1 = std::min(y1, image.height);
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) std::memcpy(&image.pixels[(size_t(y) * size_t(image.width) + size_t(x)) * 4], rgba, 4);
}

} // namespace

int drawText(ImageRGBA8& image, int x, int y, const std::string& text, int scale, const uint8_t rgba[4])
{
    // stb_easy_font emits axis-aligned quads (4 vertices of x, y, z floats and 4 colour bytes).
    struct Vertex {
        float x, y, z;
        unsigned char color[4];
    };
    std::vector<Vertex> vertices(text.size() * 70 * 4 + 4); // at most ~70 segments a glyph
    std::string mutableText = text;
    const int quads = stb_easy_font_print(0.0f, 0.0f, mutableText.data(), nullptr, vertices.data(),
                                          int(vertices.size() * sizeof(Vertex)));
    for (int q = 0; q < quads; ++q) {
        const Vertex* v = &vertices[size_t(q) * 4];
        const float minX = std::min({v[0].x, v[1].x, v[2].x, v[3].x}), maxX = std::max({v[0].x, v[1].x, v[2].x, v[3].x});
        const float minY = std::min({v[0].y, v[1].y, v[2].y, v[3].y}), maxY = std::max({v[0].y, v[1].y, v[2].y, v[3].y});
        fillRect(image, x + int(std::lround(minX * float(scale))), y + int(std::lround(minY * float(scale))),
                 x + int(std::lround(maxX * float(scale))), y + int(std::lround(maxY * float(scale))), rgba);
    }
    return stb_easy_font_width(mutableText.data()) * scale;
}

ImageRGBA8 makeContactSheet(const std::vector<SheetTile>& tiles, int columns)
{
    columns = std::max(1, std::min(columns, int(tiles.size())));
    int cellWidth = 0, cellHeight = 0;
    for (const SheetTile& t : tiles) cellWidth = std::max(cellWidth, t.image.width), cellHeight = std::max(cellHeight, t.image.height);
    const int rows = (int(tiles.size()) + columns - 1) / columns;
    ImageRGBA8 sheet;
    sheet.width = columns * (cellWidth + kPadding) + kPadding;
    sheet.height = rows * (cellHeight + kLabelHeight + kPadding) + kPadding;
    sheet.pixels.resize(size_t(sheet.width) * size_t(sheet.height) * 4);
    const uint8_t background[4] = {32, 32, 32, 255}, white[4] = {240, 240, 240, 255};
    fillRect(sheet, 0, 0, sheet.width, sheet.height, background);
    // One caption size for the whole sheet: full size when every caption fits its tile, else
    // half size for all (mixed sizes read as emphasis that is not there); cut at the edge.
    const int captionWidth = cellWidth - kPadding;
    int scale = kLabelScale;
    for (const SheetTile& t : tiles) {
        std::string text = t.label;
        if (stb_easy_font_width(text.data()) * kLabelScale > captionWidth) scale = 1;
    }
    for (size_t i = 0; i < tiles.size(); ++i) {
        const int x0 = kPadding + int(i % size_t(columns)) * (cellWidth + kPadding);
        const int y0 = kPadding + int(i / size_t(columns)) * (cellHeight + kLabelHeight + kPadding);
        ImageRGBA8 caption;
        caption.width = captionWidth;
        caption.height = kLabelHeight - kPadding;
        caption.pixels.assign(size_t(caption.width) * size_t(caption.height) * 4, 0);
        fillRect(caption, 0, 0, caption.width, caption.height, background);
        drawText(caption, 0, scale == kLabelScale ? 0 : 6, tiles[i].label, scale, white);
        for (int y = 0; y < caption.height; ++y)
            std::memcpy(&sheet.pixels[(size_t(y0 + kPadding + y) * size_t(sheet.width) + size_t(x0 + kPadding)) * 4],
                        &caption.pixels[size_t(y) * size_t(caption.width) * 4], size_t(caption.width) * 4);
        const ImageRGBA8& image = tiles[i].image;
        for (int y = 0; y < image.height; ++y)
            std::memcpy(&sheet.pixels[(size_t(y0 + kLabelHeight + y) * size_t(sheet.width) + size_t(x0)) * 4],
                        &image.pixels[size_t(y) * size_t(image.width) * 4], size_t(image.width) * 4);
    }
    return sheet;
}

} // namespace specula::render
