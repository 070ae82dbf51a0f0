#pragma once
// A labelled contact sheet: images in a grid, each with a caption above it, on the CPU (the
// gallery of shading models, `specula gallery`). Labels use stb_easy_font's segment glyphs.
#include <string>
#include <vector>

#include "core/ImageIO.h"

namespace specula::render {

struct SheetTile {
    std::string label;
    ImageRGBA8 image;
};

/// Tiles of any size in rows of `columns`, each cell as large as the largest tile, with a
/// caption band above each tile. Dark grey background, white text.
ImageRGBA8 makeContactSheet(const std::vector<SheetTile>& tiles, int columns);

/// Draws `text` with its top-left corner at (x, y), each font pixel `scale` × `scale` image
/// pixels; clipped to the image. Returns the width drawn, in image pixels.
int drawText(ImageRGBA8& image, int x, int y, const std::string& text, int scale, const uint8_t rgba[4]);

} // namespace specula::render
