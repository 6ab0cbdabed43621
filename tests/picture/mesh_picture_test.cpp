// Pictures read back with Cairo: the size asked for, each cell's colour at
// its centroid's pixel, background in the rectangle's hole, the rectangle's
// boundary line where the layout puts it, inverted cells red, the colour bar
// and title drawn; 3D meshes refused; a failed write leaves the file intact.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cairo.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <string>
#include <vector>

#include "dgwarp/cases/rect_box.hpp"
#include "dgwarp/core/error.hpp"
#include "dgwarp/picture/color_map.hpp"
#include "dgwarp/picture/mesh_picture.hpp"
#include "dgwarp/picture/picture_layout.hpp"
#include "dgwarp/quality/mesh_quality.hpp"
#include "support/picture_test_box.hpp"
#include "support/test_paths.hpp"

using namespace dgwarp;
using dgwarp::test::picture_test_box;

namespace {

struct Pixel {
    int r = 0, g = 0, b = 0;
};

// A PNG read back with Cairo (RGB24 or ARGB32; the alpha is ignored).
struct Image {
    int width = 0, height = 0;
    std::vector<std::uint32_t> argb;  // width × height, row by row
    Pixel at(int x, int y) const {
        const std::uint32_t v = argb[static_cast<std::size_t>(y) * width + x];
        return {static_cast<int>((v >> 16) & 0xff), static_cast<int>((v >> 8) & 0xff), static_cast<int>(v & 0xff)};
    }
    Pixel at(const std::array<double, 2>& p) const {
        return at(static_cast<int>(std::floor(p[0])), static_cast<int>(std::floor(p[1])));
    }
};

Image read_png(const std::filesystem::path& file) {
    std::unique_ptr<cairo_surface_t, decltype(&cairo_surface_destroy)> s(
        cairo_image_surface_create_from_png(file.c_str()), &cairo_surface_destroy);
    EXPECT_EQ(cairo_surface_status(s.get()), CAIRO_STATUS_SUCCESS) << file;
    Image img;
    if (cairo_surface_status(s.get()) != CAIRO_STATUS_SUCCESS) return img;
    img.width = cairo_image_surface_get_width(s.get());
    img.height = cairo_image_surface_get_height(s.get());
    const int stride = cairo_image_surface_get_stride(s.get());
    const unsigned char* data = cairo_image_surface_get_data(s.get());
    for (int y = 0; y < img.height; ++y) {
        const auto* row = reinterpret_cast<const std::uint32_t*>(data + static_cast<std::ptrdiff_t>(y) * stride);
        img.argb.insert(img.argb.end(), row, row + img.width);
    }
    return img;
}

// Cairo turns a colour channel c into the 8-bit value of round(c · 65535) / 256.
Pixel expected_pixel(const Rgb& c) {
    auto channel = [](double v) { return static_cast<int>(v * 65535.0 + 0.5) >> 8; };
    return {channel(c.r), channel(c.g), channel(c.b)};
}

bool same_color(const Pixel& a, const Pixel& b, int tolerance = 1) {
    return std::abs(a.r - b.r) <= tolerance && std::abs(a.g - b.g) <= tolerance && std::abs(a.b - b.b) <= tolerance;
}

std::string text(const Pixel& p) {
    return "(" + std::to_string(p.r) + ", " + std::to_string(p.g) + ", " + std::to_string(p.b) + ")";
}

std::array<double, 2> centroid(const Mesh& mesh, std::size_t cell) {
    std::array<double, 2> c{};
    const auto nodes = mesh.cells.nodes_of(cell);
    for (NodeId n : nodes)
        for (int d = 0; d < 2; ++d) c[d] += mesh.points[2 * n + d] / static_cast<double>(nodes.size());
    return c;
}

// Distance in pixels from the centre of the pixel holding `cell`'s centroid
// to the nearest line through one of its edges: where that is a few pixels,
// neither the cell's edges nor antialiasing reach the pixel.
double clearance_px(const PictureLayout& layout, const Mesh& mesh, std::size_t cell) {
    const auto c = to_pixel(layout, centroid(mesh, cell)[0], centroid(mesh, cell)[1]);
    const double px = std::floor(c[0]) + 0.5, py = std::floor(c[1]) + 0.5;
    const auto nodes = mesh.cells.nodes_of(cell);
    double nearest = INFINITY;
    for (std::size_t k = 0; k < nodes.size(); ++k) {
        const NodeId a = nodes[k], b = nodes[(k + 1) % nodes.size()];
        const auto pa = to_pixel(layout, mesh.points[2 * a], mesh.points[2 * a + 1]);
        const auto pb = to_pixel(layout, mesh.points[2 * b], mesh.points[2 * b + 1]);
        const double ex = pb[0] - pa[0], ey = pb[1] - pa[1];
        nearest = std::min(nearest, std::fabs(ex * (py - pa[1]) - ey * (px - pa[0])) / std::hypot(ex, ey));
    }
    return nearest;
}

constexpr double clear_px = 3.0;

struct Picture {
    Mesh mesh = make_rect_box(picture_test_box);
    std::vector<double> quality = cell_qualities(mesh, cell_orientations(mesh));
    PictureOptions options;
    Picture() {
        options.width = 800;
        options.height = 600;
    }
};

std::string read_bytes(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace

TEST(Picture, CellsShowTheColourOfTheirQuality) {
    Picture p;
    const auto png = test::scratch_dir() / "rect_box.png";
    write_mesh_picture(png, p.mesh, p.quality, p.options);
    const Image img = read_png(png);
    EXPECT_EQ(img.width, 800);
    EXPECT_EQ(img.height, 600);
    ASSERT_EQ(img.argb.size(), 800u * 600u);

    const PictureLayout layout = picture_layout(p.mesh, p.quality, p.options);
    int checked = 0;
    for (std::size_t i = 0; i < p.mesh.cells.size(); ++i) {
        if (clearance_px(layout, p.mesh, i) < clear_px) continue;
        const auto c = centroid(p.mesh, i);
        const Pixel got = img.at(to_pixel(layout, c[0], c[1]));
        const Pixel want = expected_pixel(value_color(p.quality[i]));
        EXPECT_TRUE(same_color(got, want)) << "cell " << i << " quality " << p.quality[i] << ": pixel " << text(got)
                                           << ", colour map " << text(want);
        ++checked;
    }
    EXPECT_GT(checked, 500);  // the outer cells are tens of pixels wide
    // The qualities differ enough for the colours to differ (the check is not vacuous).
    const auto [lo, hi] = std::minmax_element(p.quality.begin(), p.quality.end());
    EXPECT_GT(*hi - *lo, 0.3);
}

TEST(Picture, TheRectangleHoleIsBackgroundAndItsBoundaryIsDrawn) {
    Picture p;
    const auto png = test::scratch_dir() / "rect_box.png";
    write_mesh_picture(png, p.mesh, p.quality, p.options);
    const Image img = read_png(png);
    ASSERT_EQ(img.width, 800);
    const PictureLayout layout = picture_layout(p.mesh, p.quality, p.options);
    const auto centre = to_pixel(layout, 0, 0);
    EXPECT_TRUE(same_color(img.at(centre), expected_pixel(background_color), 0)) << text(img.at(centre));
    // Walking right from the hole's centre, the first drawn pixel is the
    // rectangle's black marker line at x = 1.
    const int row = static_cast<int>(std::floor(centre[1]));
    int x = static_cast<int>(std::floor(centre[0]));
    while (x < img.width && same_color(img.at(x, row), expected_pixel(background_color), 0)) ++x;
    const double wall = to_pixel(layout, 1.0, 0.0)[0];
    EXPECT_NEAR(x + 0.5, wall, 2.0);
    const Pixel line = img.at(static_cast<int>(std::floor(wall)), row);
    EXPECT_LT(line.r + line.g + line.b, 3 * 90) << text(line);
}

TEST(Picture, InvertedCellsAreRed) {
    Picture p;
    std::size_t widest = 0;
    const PictureLayout layout = picture_layout(p.mesh, p.quality, p.options);
    for (std::size_t i = 0; i < p.mesh.cells.size(); ++i)
        if (clearance_px(layout, p.mesh, i) > clearance_px(layout, p.mesh, widest)) widest = i;
    ASSERT_GE(clearance_px(layout, p.mesh, widest), clear_px);
    p.quality[widest] = -0.185;  // the paper's worst DGM cell
    const auto png = test::scratch_dir() / "inverted.png";
    write_mesh_picture(png, p.mesh, p.quality, p.options);
    const Image img = read_png(png);
    const auto c = centroid(p.mesh, widest);
    const Pixel got = img.at(to_pixel(layout, c[0], c[1]));
    EXPECT_TRUE(same_color(got, expected_pixel(inverted_color))) << text(got);
}

TEST(Picture, ColourBarAndTitleAreDrawn) {
    Picture p;
    p.options.title = "Rectangle in a box";
    const auto png = test::scratch_dir() / "titled.png";
    write_mesh_picture(png, p.mesh, p.quality, p.options);
    const Image img = read_png(png);
    const PictureLayout layout = picture_layout(p.mesh, p.quality, p.options);
    // Somewhere right of the plot: the map's ends, its middle and the inverted swatch.
    auto in_bar_band = [&](const Rgb& color) {
        for (int y = 0; y < img.height; ++y)
            for (int x = static_cast<int>(layout.plot[0] + layout.plot[2]) + 1; x < img.width; ++x)
                if (same_color(img.at(x, y), expected_pixel(color), 3)) return true;
        return false;
    };
    EXPECT_TRUE(in_bar_band(value_color(0.02)));
    EXPECT_TRUE(in_bar_band(value_color(0.5)));
    EXPECT_TRUE(in_bar_band(value_color(0.98)));
    EXPECT_TRUE(in_bar_band(inverted_color));
    // Dark text pixels in the title band above the plot.
    int dark = 0;
    for (int y = 0; y < static_cast<int>(layout.plot[1]); ++y)
        for (int x = 0; x < img.width; ++x) dark += img.at(x, y).r < 100 ? 1 : 0;
    EXPECT_GT(dark, 50);
}

TEST(Picture, WithoutValuesCellsArePlainAndThereIsNoColourBar) {
    Picture p;
    const auto png = test::scratch_dir() / "plain.png";
    write_mesh_picture(png, p.mesh, {}, p.options);
    const Image img = read_png(png);
    const PictureLayout layout = picture_layout(p.mesh, {}, p.options);
    EXPECT_FALSE(layout.colorbar);
    for (std::size_t i = 0; i < p.mesh.cells.size(); ++i) {
        if (clearance_px(layout, p.mesh, i) < clear_px) continue;
        const auto c = centroid(p.mesh, i);
        EXPECT_TRUE(same_color(img.at(to_pixel(layout, c[0], c[1])), expected_pixel(plain_cell_color)))
            << "cell " << i;
    }
}

TEST(Picture, ACloseUpShowsTheWindowsCells) {
    Picture p;
    const NodeId corner[] = {0};  // the rectangle's corner (-1, -0.5)
    p.options.window = window_around(p.mesh, corner, 1.0);
    const auto png = test::scratch_dir() / "corner.png";
    write_mesh_picture(png, p.mesh, p.quality, p.options);
    const Image img = read_png(png);
    const PictureLayout layout = picture_layout(p.mesh, p.quality, p.options);
    EXPECT_GT(layout.scale, 500);  // a close-up indeed: 0.17 units across 700 pixels
    int checked = 0;
    for (std::size_t i = 0; i < p.mesh.cells.size(); ++i) {
        const auto c = centroid(p.mesh, i);
        const auto px = to_pixel(layout, c[0], c[1]);
        if (px[0] < layout.plot[0] + 1 || px[0] > layout.plot[0] + layout.plot[2] - 1 || px[1] < layout.plot[1] + 1 ||
            px[1] > layout.plot[1] + layout.plot[3] - 1 || clearance_px(layout, p.mesh, i) < clear_px)
            continue;
        EXPECT_TRUE(same_color(img.at(px), expected_pixel(value_color(p.quality[i])))) << "cell " << i;
        ++checked;
    }
    EXPECT_GE(checked, 3);
}

TEST(Picture, ThreeDMeshesAreRefused) {
    Mesh tet;
    tet.dim = 3;
    tet.points = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
    const NodeId nodes[] = {0, 1, 2, 3};
    tet.cells.push_back(CellType::tetrahedron, nodes);
    const auto png = test::scratch_dir() / "tet.png";
    try {
        write_mesh_picture(png, tet, {});
        ADD_FAILURE() << "a 3D mesh was drawn";
    } catch (const MeshError& e) {
        EXPECT_NE(std::string(e.what()).find("pictures are 2D only"), std::string::npos) << e.what();
    }
    EXPECT_FALSE(std::filesystem::exists(png));
}

TEST(Picture, WrongNumberOfValuesIsAMeshError) {
    Picture p;
    p.quality.pop_back();
    EXPECT_THROW(write_mesh_picture(test::scratch_dir() / "x.png", p.mesh, p.quality, p.options), MeshError);
}

TEST(Picture, AFailedWriteLeavesTheExistingFileIntact) {
    Picture p;
    const auto dir = test::scratch_dir();
    const auto png = dir / "mesh.png";
    write_mesh_picture(png, p.mesh, p.quality, p.options);
    const std::string before = read_bytes(png);
    ASSERT_GT(before.size(), 1000u);

    PictureOptions bad = p.options;
    bad.window = std::array<double, 4>{1, 0, 0, 1};
    EXPECT_THROW(write_mesh_picture(png, p.mesh, p.quality, bad), Error);
    EXPECT_EQ(read_bytes(png), before);

    // Unwritable folder (root may write anywhere, so only checked as a user).
    if (::geteuid() != 0) {
        std::filesystem::permissions(dir, std::filesystem::perms::owner_read | std::filesystem::perms::owner_exec);
        EXPECT_THROW(write_mesh_picture(png, p.mesh, {}, p.options), IoError);
        std::filesystem::permissions(dir, std::filesystem::perms::owner_all);
        EXPECT_EQ(read_bytes(png), before);
    }
    // Failure after the PNG is encoded: the target is a folder, so the
    // temporary file cannot be renamed into place; it is removed.
    const auto folder = dir / "taken.png";
    std::filesystem::create_directory(folder);
    std::ofstream(folder / "keep.txt") << "keep";
    EXPECT_THROW(write_mesh_picture(folder, p.mesh, p.quality, p.options), IoError);
    EXPECT_EQ(read_bytes(folder / "keep.txt"), "keep");
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir), std::filesystem::directory_iterator()), 2)
        << "a temporary file was left behind";
    EXPECT_EQ(read_bytes(png), before);
}

TEST(Picture, AMissingFolderIsAnIoError) {
    Picture p;
    EXPECT_THROW(write_mesh_picture(test::scratch_dir() / "none" / "x.png", p.mesh, p.quality, p.options), IoError);
}

TEST(Picture, ADeepCloseUpStillDrawsTheCellsAroundANode) {
    // A window a millionth of the cells' size: the cells reach far beyond
    // what Cairo's fixed-point coordinates hold, so they must be clipped first.
    Picture p;
    const NodeId corner[] = {0};  // the rectangle's corner (-1, -0.5)
    p.options.window = window_around(p.mesh, corner, 1e-5);
    const auto png = test::scratch_dir() / "deep.png";
    write_mesh_picture(png, p.mesh, p.quality, p.options);
    const Image img = read_png(png);
    const PictureLayout layout = picture_layout(p.mesh, p.quality, p.options);
    ASSERT_GT(layout.scale, 1e8);
    const auto at_node = to_pixel(layout, p.mesh.points[0], p.mesh.points[1]);
    int checked = 0;
    for (std::size_t i = 0; i < p.mesh.cells.size(); ++i) {
        const auto nodes = p.mesh.cells.nodes_of(i);
        if (std::find(nodes.begin(), nodes.end(), NodeId{0}) == nodes.end()) continue;
        // Near its corner a cell is a wedge; its centroid's direction lies inside it.
        const auto c = centroid(p.mesh, i);
        const double dx = c[0] - p.mesh.points[0], dy = c[1] - p.mesh.points[1];
        const double r = 150.0 / std::hypot(dx, dy);
        const std::array<double, 2> probe = {at_node[0] + r * dx, at_node[1] - r * dy};
        EXPECT_TRUE(same_color(img.at(probe), expected_pixel(value_color(p.quality[i])))) << "cell " << i;
        ++checked;
    }
    EXPECT_EQ(checked, 2);  // the O-grid's corner node has two cells
    // Towards the hole (up and right of the corner): background.
    EXPECT_TRUE(same_color(img.at({at_node[0] + 150, at_node[1] - 150}), expected_pixel(background_color), 0));
}
