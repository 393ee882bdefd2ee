// hedge tour, run as ./run runs it: the contact sheet, the edited meshes, the table.
#include <set>
#include <sstream>
#include <string>

#include "cli_fixture.h"

namespace {

using namespace cli_test;

TEST_F(HedgeCli, TourWritesTheContactSheetAndEveryEditedMesh) {
  const fs::path out = tmp("out");
  const Result r = run({"tour", data("spot_control_mesh.obj"), "--out", out.string(), "--panel", "160"});
  ASSERT_EQ(r.code, 0) << r.err;
  const std::string sheet = read_text(out / "spot_control_mesh_tour.png");
  ASSERT_GT(sheet.size(), 24u);
  EXPECT_EQ(sheet.compare(0, 8, "\x89PNG\r\n\x1a\n"), 0);
  for (const char* stage :
       {"_catmull_clark.obj", "_split.obj", "_loop.obj", "_smooth.obj", "_decimated.obj", "_fractured.obj",
        "_solid_fractured.obj", "_hole.obj", "_filled.obj", "_patch.obj"}) {
    const fs::path mesh = out / (std::string("spot_control_mesh") + stage);
    EXPECT_TRUE(fs::exists(mesh)) << mesh;
    const Result v = run({"validate", mesh.string()});
    EXPECT_EQ(v.code, 0) << mesh << ": " << v.out << v.err;
  }
  // The table: a header and one row per stage, every one valid.
  EXPECT_NE(r.out.find("stage"), std::string::npos);
  for (const char* stage : {"loaded", "Catmull-Clark", "split all faces", "Loop subdivision", "smoothed",
                            "decimated to 732 faces", "glass fracture", "solid fracture: ", "faces removed",
                            "hole filled", "detached one-ring"})
    EXPECT_NE(r.out.find(stage), std::string::npos) << stage;
  EXPECT_EQ(r.out.find(" NO "), std::string::npos) << r.out;
  // The split stage: 180 faces of 4.4 corners on average become 732 triangles.
  EXPECT_NE(r.out.find("732"), std::string::npos) << r.out;
  // The solid stage: closed pieces pushed apart from the remaining object. Unpushed, each cap corner
  // of a piece would lie on one of the remaining object's or a neighbour's; pushed, no position of
  // the view repeats.
  const std::size_t at = r.out.find("solid fracture: ");
  ASSERT_NE(at, std::string::npos);
  const int pieces = std::stoi(r.out.substr(at + 16));
  EXPECT_GE(pieces, 2);
  const fs::path view = out / "spot_control_mesh_solid_fractured.obj";
  const json info = run_json({"info", view.string(), "--json"});
  EXPECT_TRUE(info["is_closed"].get<bool>());
  EXPECT_GE(info["components"].get<int>(), pieces + 1);  // the remaining object may fall apart too
  std::istringstream obj(read_text(view));
  std::set<std::string> positions;
  std::size_t vertices = 0, repeated = 0;
  for (std::string line; std::getline(obj, line);)
    if (line.rfind("v ", 0) == 0) {
      ++vertices;
      repeated += !positions.insert(line).second;
    }
  EXPECT_EQ(vertices, info["vertices"].get<std::size_t>());
  EXPECT_EQ(repeated, 0u);
}

TEST_F(HedgeCli, TourSkipsTheSubdivisionsALargeMeshCannotAfford) {
  // spot's 180 faces have 732 corners: one Catmull-Clark step (732 quads) and the 1-to-3 split
  // (732 triangles) fit under 1000 faces; two steps (2928) and Loop after the split (2928) do not.
  const Result r =
      run({"tour", data("spot_control_mesh.obj"), "--out", tmp("out").string(), "--max-faces", "1000"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("Catmull-Clark, 1 step"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("Loop subdivision                   skipped"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("split all faces (1-to-3)"), std::string::npos);
  EXPECT_FALSE(fs::exists(tmp("out") / "spot_control_mesh_loop.obj"));
  // Without Loop's mesh, decimation and fracture take the 732 triangles of the split: a quarter is 183 faces,
  // and collapses remove two at a time.
  EXPECT_NE(r.out.find("decimated to 182 faces"), std::string::npos) << r.out;
  EXPECT_TRUE(fs::exists(tmp("out") / "spot_control_mesh_fractured.obj"));
  EXPECT_TRUE(fs::exists(tmp("out") / "spot_control_mesh_tour.png"));
}

// An open mesh cannot be broken as a solid: the tour skips that stage, saying why, and goes on.
TEST_F(HedgeCli, TourSkipsTheSolidFractureOfAnOpenMesh) {
  const Result r = run({"tour", data("three_peaks.off"), "--out", tmp("out").string(), "--panel", "96"});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("solid fracture                     skipped: the mesh is open"), std::string::npos)
      << r.out;
  EXPECT_FALSE(fs::exists(tmp("out") / "three_peaks_solid_fractured.obj"));
  EXPECT_NE(r.out.find("glass fracture"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("hole filled"), std::string::npos) << r.out;
}

TEST_F(HedgeCli, TourOfAMeshWithoutFacesIsADataError) {
  write_text(tmp("points.obj"), "v 0 0 0\nv 1 0 0\n");
  expect_data_error({"tour", tmp("points.obj").string(), "--out", tmp("out").string()}, "no faces");
  EXPECT_FALSE(fs::exists(tmp("out") / "points_tour.png"));
}

}  // namespace
