// Output helpers that need no device: the pixel grid a solve's --samples are stratified over,
// and the VTK XML writer (a small grid written and read back field by field).

#include <sstream>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "formfactor/surface_view_factors.h"
#include "io/vtu_file.h"
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

// The text between `<tag ...>` and the next `</DataArray>` after it.
std::string arrayText(const std::string& xml, const std::string& opening) {
    const std::size_t at = xml.find(opening);
    if (at == std::string::npos) return "<missing>";
    const std::size_t begin = xml.find('>', at) + 1, end = xml.find("</DataArray>", begin);
    return xml.substr(begin, end - begin);
}

TEST(Vtu, TwoTrianglesSharingAnEdge) {
    VtuGrid grid;
    grid.points = {{0.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, {1.0, 2.5, 0.0}, {0.0, 2.5, -1e-7}};
    grid.triangles = {{0, 1, 2}, {0, 2, 3}};
    grid.cellData.push_back({"radiosity", 3, false, {1, 2, 3, 0.125, 0.5, 1e20}});
    grid.cellData.push_back({"surface", 1, true, {4, 7}});
    grid.comments.push_back("surface 4: a--b-");
    std::ostringstream out;
    writeVtu(out, grid);
    const std::string xml = out.str();
    EXPECT_EQ(xml.rfind("<?xml version=\"1.0\"?>\n", 0), 0u);
    EXPECT_NE(xml.find("<!-- surface 4: a- -b-  -->"), std::string::npos) << xml;  // no "--" inside a comment
    EXPECT_NE(xml.find("<Piece NumberOfPoints=\"4\" NumberOfCells=\"2\">"), std::string::npos);
    EXPECT_EQ(arrayText(xml, "Name=\"radiosity\" NumberOfComponents=\"3\""), "\n1 2 3\n0.125 0.5 1e+20\n");
    EXPECT_EQ(arrayText(xml, "<DataArray type=\"Int32\" Name=\"surface\""), "\n4\n7\n");
    EXPECT_EQ(arrayText(xml, "Name=\"Points\""), "\n0 0 0\n1 0 0\n1 2.5 0\n0 2.5 -1e-07\n");
    EXPECT_EQ(arrayText(xml, "Name=\"connectivity\""), "\n0 1 2\n0 2 3\n");
    EXPECT_EQ(arrayText(xml, "Name=\"offsets\""), "\n3 6\n");
    EXPECT_EQ(arrayText(xml, "Name=\"types\""), "\n5 5\n");  // VTK_TRIANGLE
    EXPECT_NE(xml.find("</VTKFile>\n"), std::string::npos);
    // An array that does not match the cells is a bug, not a file.
    grid.cellData.push_back({"area", 1, false, {1.0}});
    std::ostringstream bad;
    EXPECT_THROW(writeVtu(bad, grid), std::logic_error);
}

// Rays lost on black backs: a line per surface while few lose them, then one line that says how
// many and names the three that lose most, largest first. 0.1 % exactly is not reported.
TEST(BlackBackWarnings, OneLineEachForAFewThenOneForMany) {
    const std::vector<std::string> names{"a", "b", "c", "d", "e"};
    const auto few = blackBackWarnings(names, {0.2, 0.001, 0.0, 0.0105, 0.0}, "lost");
    ASSERT_EQ(few.size(), 2u);
    EXPECT_EQ(few[0].rfind("20 % of the rays from 'a' stop on the back of a single-sided face", 0), 0u) << few[0];
    EXPECT_EQ(few[1].rfind("1.05 % of the rays from 'd'", 0), 0u) << few[1];
    EXPECT_NE(few[0].find(": lost; a face whose back should count must be double-sided"), std::string::npos) << few[0];
    const auto many = blackBackWarnings(names, {0.2, 0.5, 0.002, 0.3, 0.0}, "lost");
    ASSERT_EQ(many.size(), 1u);
    EXPECT_EQ(many[0].rfind("4 surfaces lose more than 0.1 % of their rays on the back of a single-sided face", 0), 0u)
        << many[0];
    EXPECT_NE(many[0].find("the most 'b' 50 %, 'd' 30 %, 'a' 20 %: lost;"), std::string::npos) << many[0];
    EXPECT_TRUE(blackBackWarnings(names, {0.001, 0.0, 0.0, 0.0, 0.0}, "lost").empty());
}

}  // namespace
}  // namespace rad
