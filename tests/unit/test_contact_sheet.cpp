// The gallery's contact sheet: tiles in a grid under captions of one size.
#include <gtest/gtest.h>

#include <algorithm>

#include "shading/ContactSheet.h"

using namespace specula;

namespace {

ImageRGBA8 tile(int width, int height)
{
    ImageRGBA8 image;
    image.width = width;
    image.height = height;
    image.pixels.assign(size_t(width) * size_t(height) * 4, 0);
    return image;
}

/// Rows [first, last] in which columns [x0, x1) of `sheet` have a caption (white) pixel; {-1, -1} if none.
std::pair<int, int> textRows(const ImageRGBA8& sheet, int x0, int x1, int y1)
{
    int first = -1, last = -1;
    for (int y = 0; y < y1; ++y)
        for (int x = x0; x < x1; ++x)
            if (sheet.pixels[(size_t(y) * size_t(sheet.width) + size_t(x)) * 4] == 240) {
                if (first < 0) first = y;
                last = y;
            }
    return {first, last};
}

} // namespace

TEST(ContactSheet, TilesInAGridWithCaptionsOfOneSize)
{
    // 100 px tiles: "ab" fits at full size, the long label does not, so both are half size.
    const render::SheetTile shortLabel{"ab", tile(100, 40)}, longLabel{"a label far wider than its tile", tile(100, 40)};
    const ImageRGBA8 mixed = render::makeContactSheet({shortLabel, longLabel}, 2);
    const ImageRGBA8 alone = render::makeContactSheet({shortLabel, shortLabel}, 2);
    ASSERT_EQ(mixed.width, alone.width);
    ASSERT_EQ(mixed.height, alone.height);
    EXPECT_EQ(mixed.width, 2 * (100 + 6) + 6);

    const int captionBottom = mixed.height - 40; // the tiles fill the bottom 40 rows
    const auto mixedShort = textRows(mixed, 0, mixed.width / 2, captionBottom);
    const auto mixedLong = textRows(mixed, mixed.width / 2, mixed.width, captionBottom);
    const auto aloneShort = textRows(alone, 0, alone.width / 2, captionBottom);
    ASSERT_GE(mixedShort.first, 0);
    ASSERT_GE(mixedLong.first, 0);
    // Both captions of the mixed sheet at one size (same rows); alone, "ab" is taller.
    EXPECT_EQ(mixedShort, mixedLong);
    EXPECT_GT(aloneShort.second - aloneShort.first, mixedShort.second - mixedShort.first);
}
