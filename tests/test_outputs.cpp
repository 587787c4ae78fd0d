// Output helpers that need no device: the pixel grid a solve's --samples are stratified over.

#include <gtest/gtest.h>

#include "render/renderer.h"
#include "util/error.h"

namespace rad {
namespace {

TEST(PixelGrid, TheSquarestGridTheCountFills) {
    struct Case {
        int samples, across, down;
    };
    for (const Case c : {Case{1, 1, 1}, Case{4, 2, 2}, Case{16, 4, 4}, Case{256, 16, 16}, Case{8, 4, 2},
                         Case{12, 4, 3}, Case{7, 7, 1}, Case{2, 2, 1}, Case{36, 6, 6}, Case{200, 20, 10}}) {
        const PixelGrid g = pixelGrid(c.samples);
        EXPECT_EQ(g.across, c.across) << c.samples;
        EXPECT_EQ(g.down, c.down) << c.samples;
        EXPECT_EQ(g.across * g.down, c.samples);
    }
    EXPECT_THROW(pixelGrid(0), InputError);
}

}  // namespace
}  // namespace rad
