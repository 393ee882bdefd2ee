// hedge render, run as a user would: picture sizes, the grid, the half-edge diagram in PNG and SVG,
// and bad input refused with one error line and no file written.
#include <cstdint>
#include <string>

#include "cli_fixture.h"

namespace {

using namespace cli_test;

// Width and height from a PNG file's IHDR chunk; {0, 0} if it is not a PNG.
std::pair<std::uint32_t, std::uint32_t> png_size(const std::string& bytes) {
  if (bytes.size() < 24 || bytes.compare(0, 8, "\x89PNG\r\n\x1a\n") != 0 || bytes.compare(12, 4, "IHDR") != 0)
    return {0, 0};
  auto be32 = [&](std::size_t at) {
    std::uint32_t v = 0;
    for (std::size_t i = 0; i < 4; ++i) v = (v << 8) | static_cast<unsigned char>(bytes[at + i]);
    return v;
  };
  return {be32(16), be32(20)};
}

TEST_F(HedgeCli, RenderWritesAPngOfExactlyTheAskedSize) {
  const fs::path out = tmp("spot.png");
  const Result r = run({"render", data("spot_control_mesh.obj"), "-o", out.string(), "--size", "320x240"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("wrote"), std::string::npos);
  EXPECT_EQ(png_size(read_text(out)), std::make_pair(320u, 240u));
  for (const char* color : {"face", "shard", "curvature", "valence"}) {
    const fs::path p = tmp(std::string(color) + ".png");
    const Result c = run({"render", data("spot_triangulated.obj"), "-o", p.string(), "--size", "64x48",
                          "--color-by", color, "--wireframe", "--shading", "flat", "--view", "front"});
    ASSERT_EQ(c.code, 0) << color << ": " << c.err;
    EXPECT_EQ(png_size(read_text(p)), std::make_pair(64u, 48u)) << color;
  }
}

TEST_F(HedgeCli, RenderGridPutsMeshesSideBySide) {
  const fs::path out = tmp("grid.png");
  const Result r = run({"render", "--grid", data("tet.obj"), data("spot_control_mesh.obj"),
                        data("anchor.off"), "-o", out.string(), "--size", "100x80", "--columns", "2"});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto [w, h] = png_size(read_text(out));
  EXPECT_EQ(w, 200u);
  EXPECT_GT(h, 160u);  // two rows of 80 plus their captions
  EXPECT_LT(h, 260u);
}

TEST_F(HedgeCli, RenderHalfedgeDiagramAsPngAndSvg) {
  const fs::path png = tmp("tet.png"), svg = tmp("tet.svg");
  ASSERT_EQ(run({"render", "--halfedges", data("tet.obj"), "-o", png.string(), "--size", "400x300"}).code, 0);
  EXPECT_EQ(png_size(read_text(png)), std::make_pair(400u, 300u));
  const Result r = run({"render", "--halfedges", data("tet.obj"), "-o", svg.string()});
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string text = read_text(svg);
  EXPECT_EQ(text.rfind("<?xml", 0), 0u);
  std::size_t arrows = 0;
  for (std::size_t at = text.find("class=\"halfedge"); at != std::string::npos;
       at = text.find("class=\"halfedge", at + 1))
    ++arrows;
  EXPECT_EQ(arrows, 12u);  // a tetrahedron has 12 half-edges
  // Too large for a diagram: refused, naming the limit.
  const Result big =
      run({"render", "--halfedges", data("spot_triangulated.obj"), "-o", tmp("big.svg").string()});
  EXPECT_EQ(big.code, 1);
  EXPECT_NE(big.err.find("the limit is 400"), std::string::npos) << big.err;
  EXPECT_FALSE(fs::exists(tmp("big.svg")));
}

TEST_F(HedgeCli, RenderRefusesBadSizesAndOutputsWithoutWriting) {
  const std::string in = data("tet.obj");
  for (const char* size : {"0x0", "100000x100000", "20x", "big", "-5x10"}) {
    const fs::path out = tmp("x.png");
    expect_usage_error({"render", in, "-o", out.string(), "--size", size});
    EXPECT_FALSE(fs::exists(out)) << size;
  }
  expect_usage_error({"render", in, "-o", tmp("x.png").string(), "--view", "sideways"});
  expect_usage_error({"render", in, "-o", tmp("x.png").string(), "--supersample", "9"});
  expect_data_error({"render", in, "-o", tmp("x.jpg").string()}, "x.jpg");
  expect_data_error({"render", in, "-o", tmp("x.svg").string()}, "x.svg");  // SVG is for --halfedges
  expect_data_error({"render", data("missing.obj"), "-o", tmp("x.png").string()}, "missing.obj");
  expect_usage_error({"render", "-o", tmp("x.png").string()});  // no mesh at all
  expect_usage_error({"render", in, "--grid", in, "-o", tmp("x.png").string()});
  expect_usage_error({"render", in, "-o", tmp("x.png").string(), "--eye", "1,2,3"});
  // A mesh without faces: an OBJ with vertices only.
  write_text(tmp("points.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\n");
  expect_data_error({"render", tmp("points.obj").string(), "-o", tmp("x.png").string()}, "no faces");
  // A camera at its own target.
  expect_data_error({"render", in, "-o", tmp("x.png").string(), "--eye", "1,1,1", "--target", "1,1,1"},
                    "eye");
  EXPECT_FALSE(fs::exists(tmp("x.png")));
  EXPECT_FALSE(fs::exists(tmp("x.jpg")));
}

TEST_F(HedgeCli, RenderGridChecksTheSheetBeforeDrawingAnyPanel) {
  // 200 panels of 2000x2000 in one row: drawn for 74 s and 2.3 GB, then refused as "16385x1".
  std::vector<std::string> args = {"render", "-o", tmp("grid.png").string(), "--size", "2000x2000", "--grid"};
  for (int i = 0; i < 200; ++i) args.push_back(data("missing.obj"));  // never read: refused before
  const Result r = run(args);
  EXPECT_EQ(r.code, 1) << r.err;
  EXPECT_NE(r.err.find("would be 400000x2036 pixels"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("16385x1"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("missing.obj"), std::string::npos) << r.err;  // no panel was loaded
  EXPECT_FALSE(fs::exists(tmp("grid.png")));
}

}  // namespace
