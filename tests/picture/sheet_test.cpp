#include "picture/sheet.h"

#include <gtest/gtest.h>

#include "hedge/error.h"

namespace hedge::picture {
namespace {

TEST(ContactSheet, CellsInRowsWithCaptions) {
  std::vector<Panel> panels;
  const Rgb colours[] = {{255, 0, 0}, {0, 255, 0}, {0, 0, 255}};
  for (const Rgb& c : colours) panels.push_back({Image(100, 80, c), "panel"});
  const Image one_row = contact_sheet(panels);
  EXPECT_EQ(one_row.width(), 300);
  const int caption = one_row.height() - 80;
  EXPECT_GT(caption, 10);
  EXPECT_EQ(one_row.at(50, 40), colours[0]);
  EXPECT_EQ(one_row.at(150, 40), colours[1]);
  EXPECT_EQ(one_row.at(250, 40), colours[2]);
  int ink = 0;  // the captions
  for (int y = 80; y < one_row.height(); ++y)
    for (int x = 0; x < 300; ++x) ink += one_row.at(x, y).r < 128;
  EXPECT_GT(ink, 30);

  const Image two_rows = contact_sheet(panels, 2);
  EXPECT_EQ(two_rows.width(), 200);
  EXPECT_EQ(two_rows.height(), 2 * (80 + caption));
  EXPECT_EQ(two_rows.at(50, 80 + caption + 40), colours[2]);
  EXPECT_EQ(two_rows.at(150, 80 + caption + 40), (Rgb{255, 255, 255}));  // an empty cell
}

TEST(ContactSheet, RefusesNothingAndTooMuch) {
  EXPECT_THROW(contact_sheet({}), InvalidInputError);
  std::vector<Panel> wide;
  for (int i = 0; i < 5; ++i) wide.push_back({Image(4000, 10), "x"});
  EXPECT_THROW(contact_sheet(wide), InvalidInputError);
}

TEST(ContactSheet, TheSizeIsCheckedBeforeAnyPanelIsDrawnWithTheRealSize) {
  // 200 panels of 2000x2000 in one row: 400000 pixels wide (the message once said "16385x1").
  try {
    check_contact_sheet(200, 2000, 2000, 0);
    FAIL() << "no error";
  } catch (const InvalidInputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("would be 400000x2036 pixels"), std::string::npos) << what;
    EXPECT_EQ(what.find("16385x1"), std::string::npos) << what;
  }
  // Within the sides but past the pixels: 8 x 8 cells of 2000x2000 (16000x16288).
  EXPECT_THROW(check_contact_sheet(64, 2000, 2000, 8), InvalidInputError);
  int w = 0, h = 0;
  check_contact_sheet(4, 100, 80, 2, &w, &h);
  EXPECT_EQ(w, 200);
  EXPECT_EQ(h, 2 * (80 + 22));
  EXPECT_THROW(check_contact_sheet(0, 100, 80, 2), InvalidInputError);
}

}  // namespace
}  // namespace hedge::picture
