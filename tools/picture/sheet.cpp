#include "sheet.h"

#include <algorithm>
#include <cstdint>
#include <string>

#include "canvas.h"
#include "hedge/error.h"
#include "text.h"

namespace hedge::picture {

namespace {

int caption_height(int cell_w) { return int(std::clamp(cell_w / 28.0, 11.0, 18.0) * 2); }

}  // namespace

void check_contact_sheet(std::size_t panels, int cell_w, int cell_h, int columns, int* sheet_width,
                         int* sheet_height) {
  if (panels == 0) throw InvalidInputError("a contact sheet needs at least one picture");
  const std::int64_t n = std::int64_t(std::min<std::size_t>(panels, std::size_t(1) << 40));
  const std::int64_t cols = columns <= 0 ? n : std::min<std::int64_t>(columns, n);
  const std::int64_t rows = (n + cols - 1) / cols;
  const std::int64_t sheet_w = std::int64_t(cell_w) * cols,
                     sheet_h = std::int64_t(cell_h + caption_height(cell_w)) * rows;
  if (sheet_w > kMaxSide || sheet_h > kMaxSide || sheet_w * sheet_h > kMaxPixels) {
    const std::string size = std::to_string(sheet_w) + "x" + std::to_string(sheet_h);
    throw InvalidInputError("a contact sheet of " + std::to_string(n) + " pictures of " +
                            std::to_string(cell_w) + "x" + std::to_string(cell_h) + " in " +
                            std::to_string(rows) + (rows == 1 ? " row" : " rows") + " of " +
                            std::to_string(cols) + " would be " + size + " pixels, beyond the limit of " +
                            std::to_string(kMaxSide) + " pixels a side and " + std::to_string(kMaxPixels) +
                            " in all; use smaller pictures, more or fewer columns, or fewer panels");
  }
  if (sheet_width) *sheet_width = int(sheet_w);
  if (sheet_height) *sheet_height = int(sheet_h);
}

Image contact_sheet(const std::vector<Panel>& panels, int columns, Rgb background) {
  if (panels.empty()) throw InvalidInputError("a contact sheet needs at least one picture");
  int cell_w = 0, cell_h = 0;
  for (const Panel& p : panels) {
    cell_w = std::max(cell_w, p.image.width());
    cell_h = std::max(cell_h, p.image.height());
  }
  const int n = int(panels.size());
  const int cols = columns <= 0 ? n : std::min(columns, n);
  const double px = std::clamp(cell_w / 28.0, 11.0, 18.0);
  const int caption_h = caption_height(cell_w);
  int sheet_w = 0, sheet_h = 0;
  check_contact_sheet(panels.size(), cell_w, cell_h, columns, &sheet_w, &sheet_h);
  Image sheet(sheet_w, sheet_h, background);
  ImageCanvas canvas(sheet);
  const Font& font = Font::standard();
  for (int i = 0; i < n; ++i) {
    const int x = (i % cols) * cell_w, y = (i / cols) * (cell_h + caption_h);
    const Panel& p = panels[std::size_t(i)];
    sheet.paste(p.image, x + (cell_w - p.image.width()) / 2, y + (cell_h - p.image.height()) / 2);
    std::string caption = p.caption;
    while (caption.size() > 3 && font.width(caption, px) > cell_w - 8)
      caption = caption.substr(0, caption.size() - 4) + "...";
    canvas.text({x + cell_w / 2.0, y + cell_h + caption_h / 2.0}, px, caption, Rgb{30, 30, 30});
  }
  return sheet;
}

}  // namespace hedge::picture
